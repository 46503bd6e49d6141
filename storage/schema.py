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

#: Version of the on-disk layout; bumped on incompatible changes.
SCHEMA_VERSION = 1

#: Coordinate reference system of the stored ``lat``/``lng`` columns.
CRS = "EPSG:4326"

#: Columns every point row has, before any value columns.
BASE_COLUMNS = ("cell", "lat", "lng", "source_id", "row", "part")

#: The two tables that hold points: merged (indexed) and pending.
POINT_TABLES = ("points", "points_pending")

#: Allowed SQL types of value columns, and the Python types mapping to them.
SQL_TYPES = {"INTEGER": "INTEGER", "REAL": "REAL", "TEXT": "TEXT"}
_PY_TYPES = {int: "INTEGER", float: "REAL", str: "TEXT", bool: "INTEGER"}

_NAME = re.compile(r"^[A-Za-z_][A-Za-z0-9_]*$")

# ``points`` is clustered on the cell id (WITHOUT ROWID, primary key led by
# ``cell``): a descendant query reads one contiguous key range, a roll-up
# scans the table in id order, and a row can never be stored twice.
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
    lat REAL NOT NULL,
    lng REAL NOT NULL,
    source_id INTEGER NOT NULL REFERENCES sources(id),
    row INTEGER NOT NULL,
    part INTEGER NOT NULL DEFAULT 0,
    PRIMARY KEY (cell, source_id, row, part)
) WITHOUT ROWID;
CREATE TABLE points_pending (
    cell TEXT NOT NULL,
    lat REAL NOT NULL,
    lng REAL NOT NULL,
    source_id INTEGER NOT NULL,
    row INTEGER NOT NULL,
    part INTEGER NOT NULL DEFAULT 0
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
    if not isinstance(name, str) or not _NAME.match(name):
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

    Examples
    --------
    >>> sql_type(int), sql_type("real"), sql_type(str)
    ('INTEGER', 'REAL', 'TEXT')
    """
    if isinstance(spec, type) and spec in _PY_TYPES:
        return _PY_TYPES[spec]
    if isinstance(spec, str) and spec.upper() in SQL_TYPES:
        return SQL_TYPES[spec.upper()]
    raise DggsValueError(
        f"column type {spec!r} is not one of INTEGER, REAL, TEXT (or int, float, str)"
    )


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
                ("schema_version", str(SCHEMA_VERSION)),
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


def infer_type(values: list, from_text: bool) -> str:
    """Guess the SQL type of a new value column from a batch of raw values.

    Text input (CSV) is ``INTEGER`` if every non-empty value parses as an
    integer, ``REAL`` if every one parses as a number, else ``TEXT``.  Other
    input goes by the Python type.

    Examples
    --------
    >>> infer_type(["1", "", "3"], from_text=True)
    'INTEGER'
    >>> infer_type([1.5, None, 2], from_text=False)
    'REAL'
    >>> infer_type(["a", "1"], from_text=True)
    'TEXT'
    """
    kind = "INTEGER"
    seen = False
    for value in values:
        if value is None or (from_text and isinstance(value, str) and not value.strip()):
            continue
        seen = True
        if isinstance(value, bool):
            continue
        if hasattr(value, "item") and not isinstance(value, (str, bytes)):
            value = value.item()  # numpy scalar
        if isinstance(value, int):
            continue
        if isinstance(value, float):
            kind = "REAL"
            continue
        if from_text and isinstance(value, str):
            try:
                int(value)
                continue
            except ValueError:
                pass
            try:
                float(value)
                kind = "REAL"
                continue
            except ValueError:
                pass
        return "TEXT"
    return kind if seen else "TEXT"


def column_types(conn: sqlite3.Connection) -> dict[str, str]:
    """Return ``{name: SQL type}`` of the value columns of ``points``."""
    return {
        row[1]: row[2].upper()
        for row in conn.execute("PRAGMA table_info(points)")
        if row[1] not in BASE_COLUMNS
    }


def add_columns(conn: sqlite3.Connection, columns: Mapping[str, str]) -> None:
    """Add value columns to both point tables (inside the caller's transaction)."""
    for name, kind in columns.items():
        check_column_name(name)
        for table in POINT_TABLES:
            conn.execute(f"ALTER TABLE {table} ADD COLUMN {quote(name)} {sql_type(kind)}")
    if columns:
        # The view's column list is fixed when it is created: rebuild it.
        conn.execute("DROP VIEW IF EXISTS all_points")
        conn.execute(
            "CREATE VIEW all_points AS "
            "SELECT * FROM points UNION ALL SELECT * FROM points_pending"
        )
