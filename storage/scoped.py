"""Every table name of the store's SQL goes through here: a named dataset's connection renames the bare ones.

The store's ~90 statements (``storage/`` and the server) name their tables bare: ``points``, ``meta``,
``sources``, ...  A connection opened on a named dataset (:class:`ScopedConnection`, storage/datasets.py)
rewrites those names in each statement to the dataset's, ``"land/points"``, so no statement needs to know
the dataset and none can read another's rows.  Only bare identifiers are renamed, never string literals,
quoted identifiers (value columns are always quoted), comments or a name after a dot (a column qualified
by its table alias); the default dataset's statements pass unchanged.

Examples
--------
>>> print(scoped("SELECT count(*) FROM points WHERE cell >= 'points'", "land"))
SELECT count(*) FROM "land/points" WHERE cell >= 'points'
"""

from __future__ import annotations

import functools
import re
import sqlite3
from typing import Any

__all__ = ["DATASET_TABLES", "scoped", "ScopedConnection", "ScopedCursor"]

#: The names a dataset owns: its tables, its view and its index (schema.DDL, raster_ingest, rollup_keep).
DATASET_TABLES = frozenset({
    "meta", "sources", "points", "points_pending", "all_points", "rejects", "rejects_source",
    "rollups", "raster_partials", "raster_classes",
})

# SQL tokens: string literals, quoted identifiers, comments, then bare words (SQLite's lexical rules,
# https://www.sqlite.org/lang_keywords.html: '...', "...", [...], `...`).
_TOKEN = re.compile(r"""'(?:[^']|'')*'|"(?:[^"]|"")*"|\[[^\]]*\]|`(?:[^`]|``)*`|--[^\n]*|/\*.*?\*/|[A-Za-z_][A-Za-z0-9_]*""",
                    re.DOTALL)


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
    _last: tuple[str, str, str] = ("", "", "")  # the last long statement, its dataset and its rewrite (bulk.py)

    def cursor(self, factory: Any = ScopedCursor) -> Any:  # noqa: D102
        return super().cursor(factory)

    def execute(self, sql: str, parameters: Any = (), /) -> Any:  # noqa: D102
        if self.dataset is not None:
            if len(sql) <= _SHORT:
                sql = _scoped_short(sql, self.dataset)
            elif sql == self._last[0] and self.dataset == self._last[1]:  # a C compare, where the regex over a
                sql = self._last[2]  # long VALUES list (storage/bulk.py repeats one) cost 20 % of an ingest
            else:
                self._last = (sql, self.dataset, _scope(sql, self.dataset))
                sql = self._last[2]
        return super().execute(sql, parameters)

    def executemany(self, sql: str, parameters: Any, /) -> Any:  # noqa: D102
        return super().executemany(sql if self.dataset is None else scoped(sql, self.dataset), parameters)

    def executescript(self, sql: str, /) -> Any:  # noqa: D102
        return super().executescript(scoped(sql, self.dataset))
