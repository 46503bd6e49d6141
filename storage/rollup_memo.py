"""Roll-up partials remembered per connection, so that coarser roll-ups and exports need no new scan.

A roll-up of a million rows reads every row; an analyst then rolls up to a
coarser level and exports that, reading every row again each time.  The
partials of a roll-up (per cell: rows, and the column's sum, min, max and
non-NULL count) are kept with the state of the file they were read from,
and answer later calls while that state holds (up to :data:`MEMO_CELLS` cells):

* the same level: the very values SQL computed;
* a coarser level: the partials of the finest remembered level regrouped,
  only where that is exact: counts, min and max always; sums and means of
  an INTEGER column when no partial sum can reach 2**53, where SQLite's own
  sum and average are exact too.  A REAL sum or mean regrouped would differ
  from SQL's in its last bits, so those go back to SQL.

The state is the connection object, ``PRAGMA data_version`` (changes when
another connection commits) and ``total_changes`` (this connection's own
writes, through any API).  Only whole-store roll-ups in cell order are kept.
"""

from __future__ import annotations

import sqlite3
from dataclasses import dataclass
from typing import Any

import numpy as np

__all__ = ["Partials", "Memo", "State", "state", "MEMO_CELLS"]

_EXACT = 2**53

#: The most cells a connection remembers partials of, all levels and columns together (about 150 bytes
#: a cell): a server thread rolling up fine levels must not hold millions of them.
MEMO_CELLS = 300_000

#: A file state: the connection object, ``PRAGMA data_version`` and ``total_changes``.
State = tuple[Any, int, int]


@dataclass
class Partials:
    """Per-cell partials of one roll-up, cells in id order."""

    cells: list[str]
    count: list[int]
    total: list[Any]
    low: list[Any]
    high: list[Any]
    valued: list[int]

    def rows(self, stats: tuple[str, ...], integer: bool, limit: int | None) -> list[dict[str, Any]] | None:
        """Rows ``{cell, stats...}`` as SQL gives them, or None if a mean could differ from SQL's ``avg``."""
        n = len(self.cells) if limit is None else min(limit, len(self.cells))
        if "mean" in stats and integer and not self._all_bounded():
            if not all(_bounded(self, i) for i in range(n)):
                return None
        columns = {
            "count": self.count,
            "sum": self.total,
            "min": self.low,
            "max": self.high,
            "mean": [t / v if v else None for t, v in zip(self.total[:n], self.valued[:n], strict=True)]
            if "mean" in stats else [],
        }
        keys = ("cell", *stats)
        picked = [self.cells[:n], *(columns[s][:n] for s in stats)]
        return [dict(zip(keys, row, strict=True)) for row in zip(*picked, strict=True)]

    def regroup(self, level: int, integer: bool) -> Partials | None:
        """The partials of the coarser ``level``; None where a regrouped sum would not be exact."""
        if not integer and any(t is not None for t in self.total):
            sums = False  # REAL sums: counts, min and max only
        else:
            sums = self._all_bounded()
        out = Partials([], [], [], [], [], [])
        if not self.cells:
            return out
        keys = np.array(self.cells).astype(f"<U{level + 1}")  # the coarse cell of each: its id's prefix
        starts = np.flatnonzero(np.concatenate([[True], keys[1:] != keys[:-1]])).tolist()
        for a, b in zip(starts, [*starts[1:], len(self.cells)], strict=True):
            out.cells.append(self.cells[a][: level + 1])
            out.count.append(sum(self.count[a:b]))
            out.valued.append(sum(self.valued[a:b]))
            given = [t for t in self.total[a:b] if t is not None]
            out.total.append(sum(given) if given else None)
            lows = [v for v in self.low[a:b] if v is not None]
            highs = [v for v in self.high[a:b] if v is not None]
            out.low.append(min(lows) if lows else None)
            out.high.append(max(highs) if highs else None)
        if not sums:
            out.total = [_NOT_EXACT] * len(out.cells)
        elif any(t is not None and not -(2**63) <= t < 2**63 for t in out.total):
            return None  # SQL's sum would overflow: let it say so
        return out

    def _all_bounded(self) -> bool:
        """True if every cell's running integer sums stay below 2**53, coarser cells included."""
        values = [v for v in (*self.low, *self.high) if v is not None]
        if not values:
            return True
        if not all(type(v) is int for v in values):
            return False
        return bool(sum(self.valued) * max(max(values), -min(values)) < _EXACT)


class _NotExact:
    """Stands for a sum that regrouping cannot give exactly."""

    def __repr__(self) -> str:
        return "<not exact>"


_NOT_EXACT: Any = _NotExact()


def _bounded(p: Partials, i: int) -> bool:
    """True if every running sum of cell ``i``'s integers stays below 2**53 (so doubles hold it exactly)."""
    if p.valued[i] == 0:
        return True
    if not isinstance(p.low[i], int) or not isinstance(p.high[i], int):
        return False
    return bool(p.valued[i] * max(abs(p.low[i]), abs(p.high[i])) < _EXACT)


def state(conn: sqlite3.Connection) -> State:
    """What the remembered partials are valid for: this connection, others' commits, its own writes."""
    return conn, int(conn.execute("PRAGMA data_version").fetchone()[0]), conn.total_changes


class Memo:
    """Partials by (column, level), valid while :func:`state` is unchanged."""

    def __init__(self) -> None:
        self._state: State | None = None
        self._kept: dict[tuple[str | None, int], Partials] = {}

    def _valid(self, now: State) -> bool:
        if self._state is None or now[0] is not self._state[0] or now[1:] != self._state[1:]:
            self._kept.clear()
            self._state = None
            return False
        return True

    def find(self, now: State, column: str | None, level: int, stats: tuple[str, ...],
             integer: bool) -> Partials | None:
        """Partials that answer ``stats`` at ``level`` exactly, remembered or regrouped, else None."""
        if not self._valid(now):
            return None
        kept = self._kept.get((column, level))
        if kept is not None:
            return kept
        finer = sorted(lv for (c, lv) in self._kept if c == column and lv > level)
        if not finer:
            return None
        regrouped = self._kept[(column, finer[0])].regroup(level, integer)
        if regrouped is None or ({"sum", "mean"} & set(stats) and regrouped.total[:1] == [_NOT_EXACT]):
            return None
        if regrouped.total[:1] != [_NOT_EXACT]:
            self._kept[(column, level)] = regrouped
        return regrouped

    def keep(self, now: State, column: str | None, level: int, partials: Partials) -> None:
        """Remember ``partials``, read in a snapshot no newer than ``now`` described (within :data:`MEMO_CELLS`)."""
        if len(partials.cells) > MEMO_CELLS:
            return
        if not self._valid(now):
            self._state = now
        if sum(len(p.cells) for p in self._kept.values()) + len(partials.cells) > MEMO_CELLS:
            self._kept.clear()
        self._kept[(column, level)] = partials
