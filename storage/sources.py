"""The ``sources`` table: which inputs a store holds, and how far each got.

A file is identified by its content (SHA-256).  When a file that was
ingested before under the same name has changed:

* if the old content is a prefix of the new one (rows were appended, and the
  old file ended with a newline), the ingest *resumes the same source* after
  the rows it already holds, so only the new rows are stored;
* otherwise it is refused with a :class:`StorageError` naming the change
  (size and modification time, old and new); ``replace=True`` deletes what
  the old version stored and ingests the new one.
"""

from __future__ import annotations

import hashlib
import json
from collections.abc import Mapping
from datetime import datetime, timezone
from pathlib import Path
from typing import Any

from dggs.errors import StorageError

from .connection import Connection
from .rollup_keep import rebuild
from .schema import CRS, now

__all__ = ["file_info", "open_source", "delete_source", "list_sources", "list_rejects"]


def file_info(path: Path, prefix: int | None = None) -> dict[str, Any]:
    """Return size, mtime and SHA-256 of a file (its identity as a source).

    With ``prefix``, also ``prefix_sha256``: the hash of its first
    ``prefix`` bytes (to recognise a file that was appended to).
    """
    digest = hashlib.sha256()
    head = hashlib.sha256() if prefix is not None else None
    seen = 0
    with open(path, "rb") as fh:
        while block := fh.read(1 << 20):
            digest.update(block)
            if head is not None and prefix is not None and seen < prefix:
                head.update(block[: prefix - seen])
            seen += len(block)
    stat = path.stat()
    info: dict[str, Any] = {"size": stat.st_size, "mtime": stat.st_mtime, "sha256": digest.hexdigest()}
    if head is not None:
        info["prefix_sha256"] = head.hexdigest()
    return info


def _ends_with_newline(path: Path, offset: int) -> bool:
    if offset <= 0:
        return True
    with open(path, "rb") as fh:
        fh.seek(offset - 1)
        return fh.read(1) in (b"\n", b"\r")


def _stamp(mtime: Any) -> str:
    try:
        return datetime.fromtimestamp(float(mtime), timezone.utc).isoformat(timespec="seconds")
    except (TypeError, ValueError, OverflowError):
        return "?"


def find_earlier_version(
    store: Connection, kind: str, name: str, path: Path, info: Mapping[str, Any], replace: bool
) -> dict[str, Any]:
    """Settle a file's identity against an earlier source of the same name.

    Returns ``info``, possibly with ``"key"`` (an appended file: resume that
    source's key) set.  With ``replace``, older versions are deleted.

    Raises
    ------
    StorageError
        If the file changed other than by appending (and not ``replace``).
    """
    rows = store.conn.execute(
        "SELECT id, key, size, mtime, sha256 FROM sources WHERE kind = ? AND name = ? AND sha256 != ? "
        "ORDER BY id DESC",
        (kind, name, info["sha256"]),
    ).fetchall()
    if not rows:
        return dict(info)
    if replace:
        for row in rows:
            delete_source(store, row[0])
        return dict(info)
    source_id, key, size, mtime, sha = rows[0]
    size = int(size or 0)
    if size < info["size"] and _ends_with_newline(path, size):
        head = file_info(path, prefix=size)["prefix_sha256"]
        if head == sha:
            return {**info, "key": key, "appended_to": source_id}
    raise StorageError(
        f"{name} changed since it was ingested into {store.path} "
        f"(was {size:,} bytes, modified {_stamp(mtime)}; now {info['size']:,} bytes, modified "
        f"{_stamp(info['mtime'])}; not an append to the old content); pass replace=True "
        "(--replace) to replace the rows of the old version, or rename the file to keep both"
    )


def open_source(
    store: Connection,
    key: str,
    kind: str,
    name: str,
    params: dict[str, Any],
    info: Mapping[str, Any],
    replace: bool,
) -> dict[str, Any]:
    """Find or register a source; with ``replace``, forget its rows first.

    A source that has committed no row yet takes the new settings (a
    corrected command is not refused because a wrong one failed).

    Raises
    ------
    StorageError
        If the store is read-only, or the source was ingested before with other settings
        (and ``replace`` is not set).
    """
    if store.readonly:
        raise StorageError(f"{store.path} is open read-only")
    conn = store.conn
    params_json = json.dumps(params, sort_keys=True, default=str)
    key = info.get("key", key)
    found = conn.execute("SELECT id, params, rows_done FROM sources WHERE key = ?", (key,)).fetchone()
    if found and replace:
        delete_source(store, found[0])
        found = None
    stamp = now()
    if found:
        if found[1] != params_json and found[2]:
            raise StorageError(
                f"{name} was ingested into {store.path} before with other settings "
                f"({found[1]}, now {params_json}); pass replace=True to ingest it afresh"
            )
        with store.transaction():
            if found[1] != params_json:
                conn.execute(
                    "UPDATE sources SET params = ?, crs = ?, updated = ? WHERE id = ?",
                    (params_json, str(params.get("crs") or CRS), stamp, found[0]),
                )
            if "appended_to" in info:  # the file grew: resume after its old rows
                conn.execute(
                    "UPDATE sources SET size = ?, mtime = ?, sha256 = ?, key = ?, complete = 0, updated = ? "
                    "WHERE id = ?",
                    (info["size"], info["mtime"], info["sha256"], f"file:{info['sha256']}", stamp, found[0]),
                )
    else:
        with store.transaction():
            conn.execute(
                "INSERT OR IGNORE INTO sources (key, kind, name, size, mtime, sha256, params, crs, started, updated) "
                "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?)",
                (
                    key,
                    kind,
                    name,
                    info.get("size"),
                    info.get("mtime"),
                    info.get("sha256"),
                    params_json,
                    str(params.get("crs") or CRS),
                    stamp,
                    stamp,
                ),
            )
    if "appended_to" in info:
        key = f"file:{info['sha256']}"
    row = conn.execute("SELECT id, rows_done, complete FROM sources WHERE key = ?", (key,)).fetchone()
    return {"id": row[0], "rows_done": row[1], "complete": bool(row[2])}


def delete_source(store: Connection, source: int | str) -> int:
    """Delete a source (by id or name) with all its rows and rejects; return rows deleted.

    Raises
    ------
    StorageError
        If there is no such source in the store.
    """
    conn = store.conn
    row = conn.execute(
        "SELECT id FROM sources WHERE id = ? OR name = ? ORDER BY id DESC LIMIT 1",
        (source if isinstance(source, int) else -1, str(source)),
    ).fetchone()
    if row is None:
        raise StorageError(f"no source {source!r} in {store.path}")
    with store.transaction():
        deleted = 0
        for table in ("points", "points_pending"):
            deleted += conn.execute(f"DELETE FROM {table} WHERE source_id = ?", (row[0],)).rowcount
        conn.execute("DELETE FROM rejects WHERE source_id = ?", (row[0],))
        conn.execute("DELETE FROM sources WHERE id = ?", (row[0],))
        if deleted:
            rebuild(conn)  # kept roll-ups: min and max cannot be taken back, so computed afresh
        store.touch()
    return deleted


def list_sources(store: Connection) -> list[dict[str, Any]]:
    """The ingested sources, one dict each, in the order they were first ingested."""
    return list(
        store.query(
            "SELECT id, kind, name, size, sha256, crs, rows_done, rows_inserted, rows_rejected, "
            "complete, started, updated FROM sources ORDER BY id"
        )
    )


def list_rejects(store: Connection, limit: int | None = None) -> list[dict[str, Any]]:
    """The rejected rows of every source, at most ``limit``, with their value and record decoded from JSON."""
    sql = (
        'SELECT s.name AS source, r.row, r.line, r."column", r.value, r.reason, r.record '
        "FROM rejects r JOIN sources s ON s.id = r.source_id ORDER BY r.source_id, r.row"
    )
    params: list[Any] = []
    if limit is not None:
        params.append(int(limit))
        sql += " LIMIT ?"
    out = []
    for row in store.query(sql, params):
        row["value"] = json.loads(row["value"]) if row["value"] is not None else None
        row["record"] = json.loads(row["record"]) if row["record"] is not None else None
        out.append(row)
    return out
