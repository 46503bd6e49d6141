"""Exact sums of floats that can be added up later: the kept roll-ups' REAL partials.

The sum of a REAL column is the correctly rounded sum of its values
(:mod:`dggs.storage.rollup_columns`): one answer whatever the order of the
rows.  A kept roll-up adds each ingest batch's partials to the old ones, in
another order than the rows', so it must carry the *exact* sum, not a
rounded one.  It is kept as a non-overlapping expansion (Shewchuk 1997,
"Adaptive precision floating-point arithmetic", the ``msum`` of Python's
``math.fsum`` recipe): a few doubles of increasing magnitude whose exact sum
is the exact sum of the values, stored as a BLOB of little-endian float64s
(8 bytes for one value, rarely more than 24).  Adding two is exact;
``math.fsum`` of one is the correctly rounded sum, the very value the rows
give.  A sum past the double range cannot be kept exactly: its BLOB is
:data:`INEXACT`, and such roll-ups are read from the rows.

The SQL functions (registered on every connection of a store, :func:`register`):
``dggs_xadd(a, b)`` adds two BLOBs, ``dggs_xround(a)`` rounds one to a double,
the aggregates ``dggs_xsum(value)`` (values to a BLOB) and ``dggs_xmerge(blob)``
(BLOBs to a BLOB).  NULL means no value.
"""

from __future__ import annotations

import math
import sqlite3
from collections.abc import Iterable
from typing import Any

import numpy as np

__all__ = ["INEXACT", "grow", "pack", "unpack", "add", "rounded", "of_values", "register"]

#: The BLOB of a sum that left the double range: not exact, never served.
INEXACT = b"\x00"


def grow(parts: list[float], x: float) -> bool:
    """Add ``x`` to the expansion ``parts`` in place, exactly; False if a partial sum overflowed."""
    i = 0
    for y in parts:
        if abs(x) < abs(y):
            x, y = y, x
        hi = x + y
        lo = y - (hi - x)
        if lo:
            parts[i] = lo
            i += 1
        x = hi
    parts[i:] = [x]
    return math.isfinite(x)


def unpack(blob: bytes) -> list[float]:
    """The doubles of an expansion BLOB."""
    values: list[float] = np.frombuffer(blob, dtype="<f8").tolist()
    return values


def pack(parts: list[float] | None) -> bytes | None:
    """An expansion as a BLOB (None: no values)."""
    return None if parts is None else np.asarray(parts, dtype="<f8").tobytes()


def of_values(values: Iterable[float]) -> bytes | None:
    """The exact sum of ``values`` (finite floats) as a BLOB; None if there are none; INEXACT past the range."""
    parts: list[float] | None = None
    for v in values:
        if parts is None:
            parts = []
        if not grow(parts, float(v) + 0.0):  # + 0.0: -0.0 is stored as 0.0, so it is summed as 0.0
            return INEXACT
    return pack(parts)


def add(a: bytes | None, b: bytes | None) -> bytes | None:
    """The exact sum of two BLOBs (either None: the other)."""
    if a is None or b is None:
        return a if b is None else b
    if a == INEXACT or b == INEXACT:
        return INEXACT
    parts = unpack(a)
    for x in unpack(b):
        if not grow(parts, x):
            return INEXACT
    return pack(parts)


def rounded(blob: bytes | None) -> float | None:
    """The correctly rounded value of a BLOB (None: none, or INEXACT)."""
    if blob is None or blob == INEXACT:
        return None
    return math.fsum(unpack(blob))


class _Sum:
    """``dggs_xsum(value)``: the exact sum of the non-NULL values as a BLOB."""

    def __init__(self) -> None:
        self.parts: list[float] | None = None
        self.exact = True

    def step(self, value: Any) -> None:
        if value is None or not self.exact:
            return
        if self.parts is None:
            self.parts = []
        self.exact = grow(self.parts, float(value) + 0.0)

    def finalize(self) -> bytes | None:
        return pack(self.parts) if self.exact else INEXACT


class _Merge:
    """``dggs_xmerge(blob)``: the exact sum of BLOBs."""

    def __init__(self) -> None:
        self.total: bytes | None = None

    def step(self, blob: bytes | None) -> None:
        self.total = add(self.total, blob)

    def finalize(self) -> bytes | None:
        return self.total


def register(conn: sqlite3.Connection) -> None:
    """Make the exact-sum functions callable from SQL on ``conn``."""
    conn.create_function("dggs_xadd", 2, add, deterministic=True)
    conn.create_function("dggs_xround", 1, rounded, deterministic=True)
    conn.create_aggregate("dggs_xsum", 1, _Sum)  # type: ignore[arg-type]
    conn.create_aggregate("dggs_xmerge", 1, _Merge)  # type: ignore[arg-type]
