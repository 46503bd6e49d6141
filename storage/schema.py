"""The SQLite schema of a :class:`~dggs.storage.CellStore`, and checks on it.

One store holds points (or polygon features, one row per cell) binned at one
subdivision level, the *stored level*.  See ``docs/storage.md`` for the full
description; the DDL below is the single source of truth.

Tables
------
``meta``
    ``key``/``value`` pairs: ``schema_version``, ``dggs_version``, ``level``
    (the stored level), ``crs`` (always ``EPSG:4326``: stored coordinates are
    WGS84 geodetic degrees), ``created`` and ``updated`` (ISO 8601 UTC).
``sources``
    One row per ingested input (a file identified by its content hash, or a
    named stream) with the count of input rows committed so far, used to
    resume an interrupted ingest exactly once.
``points``
    The binned rows, clustered on ``cell`` (primary key ``cell, source_id,
    row, part``) so that a descendant (prefix) query is a range scan:
    ``cell >= :c AND cell < :c || '~'``.
``points_pending``
    Rows of recent batches not yet merged into ``points`` (same columns, no
    index or constraint).  Ingest appends each batch here, atomically with the source's
    progress, and moves rows to ``points`` in large sorted chunks, which is
    much faster than inserting small batches into a big index.  Queries read
    both tables; after a completed ingest it is empty.
``all_points``
    A view, ``points UNION ALL points_pending``, for ad-hoc SQL.
``rejects``
    Input rows refused by ``on_error="skip"``, with the reason.
"""

from __future__ import annotations

import re
import sqlite3
from collections.abc import Mapping
from datetime import datetime, timezone
from pathlib import Path

from dggs.errors import DggsValueError, StorageError

__all__ = [
    "SCHEMA_VERSION",
    "CRS",
    "BASE_COLUMNS",
    "POINT_TABLES",
    "SQL_TYPES",
    "create_schema",
    "check_schema",
    "check_column_name",
    "quote",
    "sql_type",
    "now",
]

#: The newest layout this dggs reads: 2 keeps roll-ups, 3 with exact REAL sums (rollup_keep); older dggs refuse them.
SCHEMA_VERSION = 3
BASE_SCHEMA_VERSION = 1  # a new store's: readable by any dggs

#: Coordinate reference system of the stored ``lat``/``lng`` columns.
CRS = "EPSG:4326"

#: Columns every point row has, before any value columns (key columns first).
BASE_COLUMNS = ("cell", "source_id", "row", "part", "lat", "lng")

#: The column order of stores written before the key-first layout.
_OLD_ORDER = ("cell", "lat", "lng", "source_id", "row", "part")

#: The two tables that hold points: merged (indexed) and pending.
POINT_TABLES = ("points", "points_pending")

#: Allowed SQL types of value columns, and the Python types mapping to them.
SQL_TYPES = {"INTEGER": "INTEGER", "REAL": "REAL", "TEXT": "TEXT"}
_PY_TYPES = {int: "INTEGER", float: "REAL", str: "TEXT", bool: "INTEGER"}

_NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")  # used with fullmatch: "$" would let "cell\n" through

# ``points`` is clustered on the cell id (WITHOUT ROWID, primary key led by
# ``cell``): a descendant query reads one contiguous key range, a roll-up
# scans the table in id order, and a row can never be stored twice.
# The key columns come first so that the declared order is the order in the
# record: SQLite 3.40's ``PRAGMA integrity_check`` reads the NOT NULL columns
# of a WITHOUT ROWID table at their declared position and reports "NULL value
# in points.lat" when non-key NOT NULL columns end the table (fixed in later
# SQLite; :func:`upgrade_layout` rebuilds stores made with the old order).
# ``points_pending`` is a plain append-only table without constraints, so
# that committing a batch is cheap and emptying it is a one-step truncate.
DDL = """
CREATE TABLE meta (
    key TEXT PRIMARY KEY,
    value TEXT NOT NULL
);
CREATE TABLE sources (
    id INTEGER PRIMARY KEY,
    key TEXT NOT NULL UNIQUE,
    kind TEXT NOT NULL,
    name TEXT NOT NULL,
    size INTEGER,
    mtime REAL,
    sha256 TEXT,
    params TEXT NOT NULL,
    crs TEXT NOT NULL,
    rows_done INTEGER NOT NULL DEFAULT 0,
    rows_inserted INTEGER NOT NULL DEFAULT 0,
    rows_rejected INTEGER NOT NULL DEFAULT 0,
    complete INTEGER NOT NULL DEFAULT 0,
    started TEXT NOT NULL,
    updated TEXT NOT NULL
);
CREATE TABLE points (
    cell TEXT NOT NULL,
    source_id INTEGER NOT NULL REFERENCES sources(id),
    row INTEGER NOT NULL,
    part INTEGER NOT NULL DEFAULT 0,
    lat REAL NOT NULL,
    lng REAL NOT NULL,
    PRIMARY KEY (cell, source_id, row, part)
) WITHOUT ROWID;
CREATE TABLE points_pending (
    cell TEXT NOT NULL,
    source_id INTEGER NOT NULL,
    row INTEGER NOT NULL,
    part INTEGER NOT NULL DEFAULT 0,
    lat REAL NOT NULL,
    lng REAL NOT NULL
);
CREATE VIEW all_points AS
    SELECT * FROM points UNION ALL SELECT * FROM points_pending;
CREATE TABLE rejects (
    id INTEGER PRIMARY KEY,
    source_id INTEGER NOT NULL REFERENCES sources(id),
    row INTEGER NOT NULL,
    line INTEGER,
    "column" TEXT,
    value TEXT,
    reason TEXT NOT NULL,
    record TEXT
);
CREATE INDEX rejects_source ON rejects(source_id, row);
"""

_REQUIRED = {
    "meta": {"key", "value"},
    "sources": {"id", "key", "rows_done", "complete", "params"},
    "points": set(BASE_COLUMNS),
    "points_pending": set(BASE_COLUMNS),
    "rejects": {"source_id", "row", "reason"},
}


def now() -> str:
    """Return the current UTC time as ISO 8601 text, to the second.

    Examples
    --------
    >>> now().endswith("+00:00")
    True
    """
    return datetime.now(timezone.utc).isoformat(timespec="seconds")


def quote(name: str) -> str:
    """Quote an already validated SQL identifier.

    Examples
    --------
    >>> quote("population")
    '"population"'
    """
    return '"' + name.replace('"', '""') + '"'


def check_column_name(name: object) -> str:
    """Validate the name of a value column and return it.

    Names are plain identifiers (letters, digits, ``_``, not starting with a
    digit) and may not shadow a base column.

    Raises
    ------
    DggsValueError
        If the name is not allowed.

    Examples
    --------
    >>> check_column_name("population")
    'population'
    >>> check_column_name("cell")
    Traceback (most recent call last):
    ...
    dggs.errors.DggsValueError: value column 'cell' clashes with a built-in column ...
    """
    if not isinstance(name, str) or not _NAME.fullmatch(name):
        raise DggsValueError(
            f"value column name {name!r} is not a plain identifier "
            "(letters, digits and _, not starting with a digit)"
        )
    if name.lower() in BASE_COLUMNS:
        raise DggsValueError(
            f"value column {name!r} clashes with a built-in column "
            f"({', '.join(BASE_COLUMNS)}); rename it"
        )
    return name


def sql_type(spec: object) -> str:
    """Normalise a column type given as SQL text or a Python type.

    Raises
    ------
    DggsValueError
        If ``spec`` is not INTEGER, REAL, TEXT (any case) or int, float, str.

    Examples
    --------
    >>> sql_type(int), sql_type("real"), sql_type(str)
    ('INTEGER', 'REAL', 'TEXT')
    """
    if isinstance(spec, type) and spec in _PY_TYPES:
        return _PY_TYPES[spec]
    if isinstance(spec, str) and spec.upper() in SQL_TYPES:
        return SQL_TYPES[spec.upper()]
    raise DggsValueError(f"column type {spec!r} is not one of INTEGER, REAL, TEXT (or int, float, str)")


def create_schema(conn: sqlite3.Connection, dggs_version: str) -> None:
    """Create every table, index and the metadata in an empty database.

    Runs in one transaction: either the whole schema exists afterwards or
    none.  Does nothing if another connection created it first.
    """
    stamp = now()
    conn.execute("BEGIN IMMEDIATE")
    if conn.execute("SELECT count(*) FROM sqlite_master").fetchone()[0]:
        conn.execute("ROLLBACK")  # another process created it meanwhile
        return
    try:
        for statement in DDL.split(";"):
            if statement.strip():
                conn.execute(statement)
        conn.executemany(
            "INSERT INTO meta (key, value) VALUES (?, ?)",
            [
                ("schema_version", str(BASE_SCHEMA_VERSION)),
                ("dggs_version", dggs_version),
                ("crs", CRS),
                ("created", stamp),
                ("updated", stamp),
            ],
        )
        conn.execute("COMMIT")
    except BaseException:
        conn.execute("ROLLBACK")
        raise


def check_schema(conn: sqlite3.Connection, path: str | Path) -> bool:
    """Check that a database is a cell store; return False if it is empty.

    Raises
    ------
    StorageError
        Naming the file, if it is not a SQLite database or holds other tables.
    """
    try:
        tables = {
            name
            for (name,) in conn.execute(
                "SELECT name FROM sqlite_master WHERE type IN ('table', 'view')"
            )
        }
    except sqlite3.DatabaseError as exc:
        raise StorageError(f"{path} is not a SQLite database ({exc})") from exc
    if not tables:
        return False
    for table, needed in _REQUIRED.items():
        if table not in tables:
            raise StorageError(
                f"{path} is a SQLite database but not a dggs cell store "
                f"(table {table!r} is missing)"
            )
        have = {row[1] for row in conn.execute(f"PRAGMA table_info({quote(table)})")}
        if not needed <= have:
            missing = ", ".join(sorted(needed - have))
            raise StorageError(
                f"{path} is not a valid dggs cell store "
                f"(table {table!r} lacks column(s) {missing})"
            )
    meta = dict(conn.execute("SELECT key, value FROM meta"))
    version = meta.get("schema_version")
    if version is None or not version.isdigit():
        raise StorageError(f"{path} has no valid schema_version in table meta")
    if int(version) > SCHEMA_VERSION:
        raise StorageError(
            f"{path} uses store schema version {version}, newer than this "
            f"dggs supports ({SCHEMA_VERSION}); upgrade dggs"
        )
    return True


def check_meta(conn: sqlite3.Connection, path: str | Path) -> None:
    """Check the values of table ``meta`` a store relies on (e.g. ``level``).

    Raises
    ------
    StorageError
        Naming the file and the bad value, if ``meta`` was tampered with.
    """
    from dggs.index.ids import MAX_LEVEL

    row = conn.execute("SELECT value FROM meta WHERE key = 'level'").fetchone()
    if row is not None:
        value = row[0]
        if not (isinstance(value, str) and value.isdigit() and int(value) <= MAX_LEVEL):
            raise StorageError(
                f"{path} is damaged: meta.level is {value!r}, not a level 0..{MAX_LEVEL}; "
                "restore the file from a backup or ingest into a new store"
            )


def upgrade_layout(conn: sqlite3.Connection) -> bool:
    """Rebuild point tables made with the old column order (key columns later).

    Stores written before the key-first layout fail ``PRAGMA
    integrity_check`` on SQLite 3.40 (see the DDL); this copies their rows
    into tables with the new order, in one transaction.  Returns True if it
    did.
    """
    info = list(conn.execute("PRAGMA table_info(points)"))
    if tuple(row[1] for row in info[:6]) != _OLD_ORDER:
        return False
    extra = [(row[1], row[2]) for row in info[6:]]
    ddl = {name: text for name, text in _split_ddl().items() if name in POINT_TABLES}
    cols = ", ".join(quote(c) for c in (*BASE_COLUMNS, *(n for n, _ in extra)))
    conn.execute("BEGIN IMMEDIATE")
    try:
        conn.execute("DROP VIEW IF EXISTS all_points")
        for table in POINT_TABLES:
            conn.execute(f"ALTER TABLE {table} RENAME TO old_{table}")
            conn.execute(ddl[table])
            for name, kind in extra:
                conn.execute(f"ALTER TABLE {table} ADD COLUMN {quote(name)} {kind}")
            conn.execute(f"INSERT INTO {table} ({cols}) SELECT {cols} FROM old_{table}")
            conn.execute(f"DROP TABLE old_{table}")
        conn.execute(
            "CREATE VIEW all_points AS SELECT * FROM points UNION ALL SELECT * FROM points_pending"
        )
        conn.execute("COMMIT")
    except BaseException:
        if conn.in_transaction:
            conn.execute("ROLLBACK")
        raise
    return True


def _split_ddl() -> dict[str, str]:
    out = {}
    for statement in DDL.split(";"):
        words = statement.split()
        if len(words) > 2 and words[1] == "TABLE":
            out[words[2]] = statement.strip()
    return out


def column_types(conn: sqlite3.Connection) -> dict[str, str]:
    """Return ``{name: SQL type}`` of the value columns of ``points``."""
    return {
        row[1]: row[2].upper()
        for row in conn.execute("PRAGMA table_info(points)")
        if row[1] not in BASE_COLUMNS
    }


def add_columns(conn: sqlite3.Connection, columns: Mapping[str, str]) -> None:
    """Add value columns to both point tables (inside the caller's transaction).

    Raises
    ------
    DggsValueError
        If a name differs only in case from a stored column (SQLite names ignore case).
    """
    have = {name.lower(): name for name in column_types(conn)}
    for name, kind in columns.items():
        check_column_name(name)
        if name.lower() in have:
            raise DggsValueError(
                f"value column {name!r} differs only in case from the stored column "
                f"{have[name.lower()]!r} (SQLite column names ignore case); use {have[name.lower()]!r}"
            )
        have[name.lower()] = name
        for table in POINT_TABLES:
            conn.execute(f"ALTER TABLE {table} ADD COLUMN {quote(name)} {sql_type(kind)}")
    if columns:
        # The view's column list is fixed when it is created: rebuild it.
        conn.execute("DROP VIEW IF EXISTS all_points")
        conn.execute(
            "CREATE VIEW all_points AS "
            "SELECT * FROM points UNION ALL SELECT * FROM points_pending"
        )
