"""Multi-row inserts: as many rows per statement as SQLite's parameter limit allows, up to :data:`MOST`."""

from __future__ import annotations

import sqlite3
import sys
from typing import Any

__all__ = ["insert_many", "max_variables", "MOST"]

#: The most parameters a statement binds.  Debian's SQLite allows 250,000, but a statement that large
#: costs more to prepare than it saves: 1.6M point rows (6 values each) in batches of 100,000 took
#: 2.27 s at 250,000, 1.44-1.82 s at 16,384 and 1.63 s at 4,000; 200,000 roll-up upserts (7 values)
#: 0.90-1.21 s at 250,000 and 0.22 s at 16,384.
MOST = 16_384


def max_variables(conn: sqlite3.Connection) -> int:
    """Return how many ``?`` parameters one statement may hold (SQLite's limit, at most :data:`MOST`)."""
    if sys.version_info < (3, 11):  # no Connection.getlimit: SQLite's historical default
        return 999
    try:
        return min(MOST, int(conn.getlimit(sqlite3.SQLITE_LIMIT_VARIABLE_NUMBER)))
    except sqlite3.Error:
        return 999


def insert_many(
    conn: sqlite3.Connection, head: str, one: str, values: list[Any], width: int, limit: int, tail: str = ""
) -> None:
    """Insert rows of ``width`` flat ``values`` with multi-row ``VALUES`` statements, as few as the limit allows.

    ``tail`` ends every statement (an upsert's ``ON CONFLICT ... DO UPDATE``).

    Twice as fast as ``executemany`` (one statement step per few thousand
    rows), and the GIL is released for the whole step, so the reader thread
    can work meanwhile.
    """
    if not values:
        return
    per = max(1, limit // max(width, 1))
    step = per * width
    full = None
    for start in range(0, len(values), step):
        chunk = values[start : start + step]
        if len(chunk) == step:
            full = full or head + ",".join([one] * per) + tail
            sql = full
        else:
            sql = head + ",".join([one] * (len(chunk) // width)) + tail
        conn.execute(sql, chunk)
