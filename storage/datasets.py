"""Several named datasets in one store file: their names, their tables, and the list of them.

A store file holds one *default* dataset under today's table names (``points``, ``sources``, ``meta``, ...;
a file written before datasets existed is exactly that) and any number of *named* datasets, each with its
own level, projection, value columns, sources, rejects and kept roll-ups.  A named dataset's tables are the
default's names behind its name and a slash: ``"land/points"``, ``"land/meta"``, ... (the design in
``docs/storage.md``).  The table ``datasets`` lists the named ones; it is made with the first of them, so a
file that has none is not touched.

Every table name of the store's SQL goes through one place, :func:`scoped`: a named dataset's connection
(:class:`ScopedConnection`) rewrites the bare table names of each statement to its own, so the ~90
statements of ``storage/`` and the server read and write the dataset they were opened on without naming it.
Only bare (unquoted) identifiers are rewritten, never string literals, quoted identifiers (value columns are
always quoted) or a name after a dot (a column qualified by its table alias).

Examples
--------
>>> print(scoped("SELECT count(*) FROM points WHERE cell >= 'points'", "land"))
SELECT count(*) FROM "land/points" WHERE cell >= 'points'
>>> check_dataset_name("land")
'land'
"""

from __future__ import annotations

import functools
import re
import sqlite3
from typing import Any

from dggs.errors import DggsValueError, StorageError

__all__ = [
    "DatasetError",
    "DATASET_TABLES",
    "REGISTRY",
    "check_dataset_name",
    "scoped",
    "table_name",
    "ScopedConnection",
    "named_datasets",
    "find_dataset",
    "create_dataset",
    "drop_dataset",
    "describe_datasets",
]

#: The names a dataset owns: its tables, its view and its index (schema.DDL, raster_ingest, rollup_keep).
DATASET_TABLES = frozenset({
    "meta", "sources", "points", "points_pending", "all_points", "rejects", "rejects_source",
    "rollups", "raster_partials", "raster_classes",
})

#: The file-level table listing the named datasets (made with the first one).
REGISTRY = "datasets"
_REGISTRY_DDL = (f"CREATE TABLE IF NOT EXISTS {REGISTRY} (name TEXT PRIMARY KEY COLLATE NOCASE, "
                 "created TEXT NOT NULL)")

# A name is a URL path segment (it is the server's collection id) and a table-name prefix: letters, digits,
# "_" and "-", starting with a letter, at most 64 characters.
_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_-]{0,63}")
# SQL tokens: string literals, quoted identifiers, comments, then bare words (SQLite's lexical rules,
# https://www.sqlite.org/lang_keywords.html: '...', "...", [...], `...`).
_TOKEN = re.compile(r"""'(?:[^']|'')*'|"(?:[^"]|"")*"|\[[^\]]*\]|`(?:[^`]|``)*`|--[^\n]*|/\*.*?\*/|[A-Za-z_][A-Za-z0-9_]*""",
                    re.DOTALL)


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


def scoped(sql: str, dataset: str | None) -> str:
    """``sql`` with each bare dataset table name made ``dataset``'s (unchanged for the default dataset).

    Short statements (the store's, repeated for every batch) are remembered; long ones (a batch's
    ``VALUES`` list) are rewritten each time, not kept.
    """
    if dataset is None:
        return sql
    return _scoped_short(sql, dataset) if len(sql) <= _SHORT else _scope(sql, dataset)


_SHORT = 4096  # characters: the longest statement remembered by _scoped_short


@functools.lru_cache(maxsize=4096)
def _scoped_short(sql: str, dataset: str) -> str:
    return _scope(sql, dataset)


def _scope(sql: str, dataset: str) -> str:
    def swap(match: re.Match[str]) -> str:
        word = match.group(0)
        if word.lower() not in DATASET_TABLES:
            return word
        start = match.start()
        if start and sql[start - 1] == ".":  # alias.column: a column, not a table
            return word
        return '"' + f"{dataset}/{word.lower()}" + '"'

    return _TOKEN.sub(swap, sql)


class ScopedCursor(sqlite3.Cursor):
    """A cursor of a :class:`ScopedConnection`: its statements name the connection's dataset's tables."""

    def execute(self, sql: str, parameters: Any = (), /) -> Any:  # noqa: D102
        return super().execute(scoped(sql, self.connection.dataset), parameters)  # type: ignore[attr-defined]

    def executemany(self, sql: str, parameters: Any, /) -> Any:  # noqa: D102
        return super().executemany(scoped(sql, self.connection.dataset), parameters)  # type: ignore[attr-defined]


class ScopedConnection(sqlite3.Connection):
    """A SQLite connection reading and writing one dataset: :func:`scoped` applied to every statement.

    ``dataset`` is None (the default dataset, statements unchanged) until the store sets it.
    """

    dataset: str | None = None

    def cursor(self, factory: Any = ScopedCursor) -> Any:  # noqa: D102
        return super().cursor(factory)

    def execute(self, sql: str, parameters: Any = (), /) -> Any:  # noqa: D102
        return super().execute(sql if self.dataset is None else scoped(sql, self.dataset), parameters)

    def executemany(self, sql: str, parameters: Any, /) -> Any:  # noqa: D102
        return super().executemany(sql if self.dataset is None else scoped(sql, self.dataset), parameters)

    def executescript(self, sql: str, /) -> Any:  # noqa: D102
        return super().executescript(scoped(sql, self.dataset))


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
