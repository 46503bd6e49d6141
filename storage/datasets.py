"""Several named datasets in one store file: their names, their tables, and the list of them.

A store file holds one *default* dataset under today's table names (``points``, ``sources``, ``meta``, ...;
a file written before datasets existed is exactly that) and any number of *named* datasets, each with its
own level, projection, value columns, sources, rejects and kept roll-ups.  A named dataset's tables are the
default's names behind its name and a slash: ``"land/points"``, ``"land/meta"``, ... (``docs/storage.md``).
The table ``datasets`` lists the named ones; it is made with the first of them and dropped with the last,
so a file that has none is not touched.  A connection opened on a named dataset renames the bare table
names of every statement to the dataset's (:mod:`.scoped`).

Examples
--------
>>> check_dataset_name("land"), table_name("points", "land")
('land', '"land/points"')
"""

from __future__ import annotations

import os
import re
import sqlite3
from typing import Any

from dggs.errors import DggsValueError, StorageError

from .scoped import scoped

__all__ = [
    "DatasetError",
    "REGISTRY",
    "check_dataset_name",
    "table_name",
    "named_datasets",
    "find_dataset",
    "open_dataset",
    "create_dataset",
    "drop_dataset",
    "discard_empty_dataset",
    "describe_datasets",
    "format_datasets",
    "list_datasets",
]

#: The file-level table listing the named datasets (made with the first one).
REGISTRY = "datasets"
_REGISTRY_DDL = (f"CREATE TABLE IF NOT EXISTS {REGISTRY} (name TEXT PRIMARY KEY COLLATE NOCASE, "
                 "created TEXT NOT NULL)")

# A name is a URL path segment (it is the server's collection id) and a table-name prefix: letters, digits,
# "_" and "-", starting with a letter, at most 64 characters.
_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_-]{0,63}")


class DatasetError(DggsValueError):
    """A dataset name is not allowed, or no dataset of that name is in the store."""


def check_dataset_name(name: object) -> str:
    """Validate a dataset name and return it.

    Raises
    ------
    DatasetError
        Naming the value, unless it is letters, digits, ``_`` and ``-`` starting with a letter (64 at most).

    Examples
    --------
    >>> check_dataset_name("rain-2024")
    'rain-2024'
    >>> check_dataset_name("a/b")
    Traceback (most recent call last):
    ...
    dggs.storage.datasets.DatasetError: dataset name 'a/b' is not allowed: ...
    """
    if not isinstance(name, str) or not _NAME.fullmatch(name):
        raise DatasetError(f"dataset name {name!r} is not allowed: use letters, digits, _ and -, "
                           "starting with a letter (64 characters at most)")
    return name


def table_name(table: str, dataset: str | None) -> str:
    """The SQL name of ``table`` of ``dataset`` (None: the default dataset), quoted when it needs to be.

    Examples
    --------
    >>> table_name("points", None), table_name("points", "land")
    ('"points"', '"land/points"')
    """
    return '"' + (table if dataset is None else f"{dataset}/{table}").replace('"', '""') + '"'


def _has_registry(conn: sqlite3.Connection) -> bool:
    return conn.execute("SELECT 1 FROM sqlite_master WHERE type = 'table' AND name = ?", (REGISTRY,)).fetchone() is not None


def named_datasets(conn: sqlite3.Connection) -> list[str]:
    """The names of the file's named datasets, in the order they were made."""
    if not _has_registry(conn):
        return []
    return [name for (name,) in conn.execute(f"SELECT name FROM {REGISTRY} ORDER BY rowid")]


def find_dataset(conn: sqlite3.Connection, name: str) -> str | None:
    """The stored spelling of dataset ``name`` (names ignore case, as SQLite's table names), or None."""
    check_dataset_name(name)
    if not _has_registry(conn):
        return None
    row = conn.execute(f"SELECT name FROM {REGISTRY} WHERE name = ?", (name,)).fetchone()
    return None if row is None else str(row[0])


def open_dataset(conn: sqlite3.Connection, name: str, path: str, may_create: bool, dggs_version: str,
                 stamp: str) -> tuple[str, bool]:
    """Point ``conn`` (a :class:`~.scoped.ScopedConnection`) at dataset ``name``, made first if new and allowed.

    Returns the stored name and whether this call made it.

    Raises
    ------
    DatasetError
        If there is none of that name and it may not be made (a read-only store, or ``create=False``).
    """
    found = find_dataset(conn, name)
    made = False
    if found is None:
        if not may_create:
            have = ", ".join(named_datasets(conn)) or "none"
            raise DatasetError(f"{path} has no dataset {name!r} (named datasets: {have})")
        found = create_dataset(conn, name, dggs_version, stamp)
        made = found == name
    conn.dataset = found  # type: ignore[attr-defined]
    return found, made


def create_dataset(conn: sqlite3.Connection, name: str, dggs_version: str, stamp: str) -> str:
    """Make the tables of a new named dataset and list it, in one transaction; return its stored name.

    Another writer that made it meanwhile wins: its dataset is used.

    Raises
    ------
    StorageError
        If a table of that name exists in the file without being listed (made by hand).
    """
    from .schema import BASE_SCHEMA_VERSION, CRS, DDL

    check_dataset_name(name)
    conn.execute("BEGIN IMMEDIATE")
    try:
        conn.execute(_REGISTRY_DDL)
        found = conn.execute(f"SELECT name FROM {REGISTRY} WHERE name = ?", (name,)).fetchone()
        if found is not None:  # another process made it meanwhile
            conn.execute("COMMIT")
            return str(found[0])
        clash = conn.execute("SELECT name FROM sqlite_master WHERE name LIKE ? ESCAPE '\\'",
                             (name.replace("_", "\\_") + "/%",)).fetchone()
        if clash is not None:
            raise StorageError(f"table {clash[0]!r} is in the store but dataset {name!r} is not listed; "
                               "rename or drop that table")
        for statement in DDL.split(";"):
            if statement.strip():
                conn.execute(scoped(statement, name))
        conn.executemany(
            f"INSERT INTO {table_name('meta', name)} (key, value) VALUES (?, ?)",
            [("schema_version", str(BASE_SCHEMA_VERSION)), ("dggs_version", dggs_version), ("crs", CRS),
             ("created", stamp), ("updated", stamp)],
        )
        conn.execute(f"INSERT INTO {REGISTRY} (name, created) VALUES (?, ?)", (name, stamp))
        conn.execute("COMMIT")
    except BaseException:
        if conn.in_transaction:
            conn.execute("ROLLBACK")
        raise
    return name


def drop_dataset(conn: sqlite3.Connection, name: str) -> None:
    """Drop every table of named dataset ``name`` and unlist it, in one transaction.

    The registry goes with the last dataset, leaving the file as it was before the first.
    """
    conn.execute("BEGIN IMMEDIATE")
    try:
        prefix = name.replace("_", "\\_") + "/%"
        objects = conn.execute("SELECT type, name FROM sqlite_master WHERE name LIKE ? ESCAPE '\\' "
                               "AND type IN ('view', 'table') ORDER BY type = 'table'", (prefix,)).fetchall()
        # the view first, then tables whose rows point at sources before sources itself
        order = {f"{name}/{t}": i for i, t in enumerate(("all_points", "raster_partials", "raster_classes", "rejects",
                                                            "points", "points_pending", "rollups", "sources"))}
        for kind, table in sorted(objects, key=lambda o: order.get(o[1], 50)):
            conn.execute(f"DROP {kind.upper()} {table_name(table.split('/', 1)[1], name)}")
        conn.execute(f"DELETE FROM {REGISTRY} WHERE name = ?", (name,))
        if conn.execute(f"SELECT 1 FROM {REGISTRY} LIMIT 1").fetchone() is None:
            conn.execute(f"DROP TABLE {REGISTRY}")  # the last one: the file is as before the first
        conn.execute("COMMIT")
    except BaseException:
        if conn.in_transaction:
            conn.execute("ROLLBACK")
        raise


def discard_empty_dataset(conn: sqlite3.Connection, name: str) -> bool:
    """Drop named dataset ``name`` if it holds no row, and point ``conn`` back at the default; True if it did.

    For a dataset made for an ingest that failed before storing a row (a source it registered is no data);
    one whose first batches committed stays, to be resumed as any ingest is.
    """
    if any(conn.execute(f"SELECT 1 FROM {table_name(t, name)} LIMIT 1").fetchone()
           for t in ("points", "points_pending")):
        return False
    drop_dataset(conn, name)
    conn.dataset = None  # type: ignore[attr-defined]  # the file's default tables from now on
    return True


def describe_datasets(conn: sqlite3.Connection) -> list[dict[str, Any]]:
    """Each dataset of the file, the default one (``name`` None) first: name, level, projection, rows, columns.

    Reads every dataset by its full table names, whichever dataset ``conn`` is scoped to.
    """
    from .projection import DEFAULT_PROJECTION
    from .rollup_keep import KEPT_KEY
    from .schema import BASE_COLUMNS

    out = []
    for name in [None, *named_datasets(conn)]:
        meta = dict(conn.execute(f"SELECT key, value FROM {table_name('meta', name)}"))
        rows = conn.execute(f"SELECT (SELECT count(*) FROM {table_name('points', name)}) + "
                            f"(SELECT count(*) FROM {table_name('points_pending', name)})").fetchone()[0]
        columns = {row[1]: row[2].upper() for row in conn.execute(f"PRAGMA table_info({table_name('points', name)})")
                   if row[1] not in BASE_COLUMNS}
        level = meta.get("level")
        kept = meta.get(KEPT_KEY) or ""
        out.append({
            "name": name,
            "level": int(level) if level is not None and level.isdigit() else None,
            "projection": meta.get("projection", DEFAULT_PROJECTION),
            "rows": int(rows),
            "columns": columns,
            "rollup_levels": sorted((int(v) for v in kept.split(",") if v), reverse=True),
        })
    return out


def list_datasets(path: str | os.PathLike[str]) -> list[dict[str, Any]]:
    """The datasets of the store file at ``path``, read-only, as :meth:`CellStore.datasets` gives them.

    Raises
    ------
    StorageError
        Naming the file, if it is missing or not a cell store.

    Examples
    --------
    >>> import os, tempfile
    >>> from dggs.storage import CellStore
    >>> path = os.path.join(tempfile.mkdtemp(), "two.db")
    >>> with CellStore(path) as points, CellStore(path, dataset="land") as land:
    ...     _ = points.ingest_points([48.85, 51.5], [2.35, -0.12], 17)
    ...     _ = land.ingest_points([48.85], [2.35], 10, {"frac": [0.5]})
    >>> [(d["name"], d["level"], d["rows"], d["columns"]) for d in list_datasets(path)]
    [(None, 17, 2, {}), ('land', 10, 1, {'frac': 'REAL'})]
    """
    from .failures import translate
    from .readonly import connect
    from .schema import check_schema

    file = os.fspath(path)
    if not os.path.isfile(file):
        raise StorageError(f"no cell store at {file}")
    try:
        conn, _immutable = connect(file, True, 30.0)
    except (sqlite3.Error, OSError) as exc:
        raise translate(exc, file) from exc
    try:
        if not check_schema(conn, file):
            raise StorageError(f"{file} is an empty database, not a cell store")
        return describe_datasets(conn)
    except sqlite3.Error as exc:
        raise translate(exc, file) from exc
    finally:
        conn.close()


def format_datasets(datasets: list[dict[str, Any]]) -> str:
    """One line per dataset (``dggs info``): name (``(default)`` for the default one), level, projection, rows, columns.

    Examples
    --------
    >>> print(format_datasets([{"name": None, "level": 17, "projection": "ISEA", "rows": 1200, "columns": {}},
    ...                        {"name": "land", "level": 10, "projection": "ISEA", "rows": 3,
    ...                         "columns": {"frac": "REAL"}}]))
      (default)  level 17  ISEA  1,200 rows  (no columns)
      land       level 10  ISEA      3 rows  frac REAL
    """
    names = ["(default)" if d["name"] is None else d["name"] for d in datasets]
    levels = ["-" if d["level"] is None else str(d["level"]) for d in datasets]
    rows = [f"{d['rows']:,}" for d in datasets]
    wn, wl, wr = (max(map(len, column)) for column in (names, levels, rows))
    return "\n".join(
        f"  {name.ljust(wn)}  level {level.ljust(wl)}  {d['projection']}  {count.rjust(wr)} rows  "
        + (", ".join(f"{k} {v}" for k, v in d["columns"].items()) or "(no columns)")
        for name, level, count, d in zip(names, levels, rows, datasets, strict=True)
    )
