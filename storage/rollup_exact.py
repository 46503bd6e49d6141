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
import struct
from collections.abc import Iterable
from typing import Any

import numpy as np

__all__ = ["INEXACT", "grow", "pack", "unpack", "add", "rounded", "of_values", "of_groups", "register"]

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


_DOUBLE = struct.Struct("<d")


def unpack(blob: bytes) -> list[float]:
    """The doubles of an expansion BLOB."""
    return list(struct.unpack(f"<{len(blob) // 8}d", blob))


def pack(parts: list[float] | None) -> bytes | None:
    """An expansion as a BLOB (None: no values)."""
    return None if parts is None else struct.pack(f"<{len(parts)}d", *parts)


def of_values(values: Iterable[float]) -> bytes | None:
    """The exact sum of ``values`` (finite floats) as a BLOB; None if there are none; INEXACT past the range."""
    parts: list[float] | None = None
    for v in values:
        if parts is None:
            parts = []
        if not grow(parts, float(v) + 0.0):  # + 0.0: -0.0 is stored as 0.0, so it is summed as 0.0
            return INEXACT
    return pack(parts)


def of_groups(values: np.ndarray, counts: np.ndarray) -> tuple[list[bytes | None], list[float | None]]:
    """Exact sums (BLOBs) and their rounded values of consecutive groups of ``counts`` finite floats.

    Groups of one value and of two (Knuth's TwoSum: the rounded sum and its exact error) are done in numpy,
    larger ones by :func:`of_values`; an empty group gives None, None.
    """
    values = values.astype(np.float64) + 0.0  # -0.0 is stored as 0.0, so it is summed as 0.0
    first = np.concatenate([[0], np.cumsum(counts)[:-1]]).astype(np.int64)
    blobs: list[bytes | None] = [None] * counts.shape[0]
    sums: list[float | None] = [None] * counts.shape[0]
    one = np.flatnonzero(counts == 1)
    if one.size:
        x = values[first[one]]
        for i, blob, v in zip(one.tolist(), _bytes(x), x.tolist(), strict=True):
            blobs[i], sums[i] = blob, v
    two = np.flatnonzero(counts == 2)
    if two.size:
        a, b = values[first[two]], values[first[two] + 1]
        with np.errstate(over="ignore", invalid="ignore"):
            total = a + b
            back = total - a
            err = (a - (total - back)) + (b - back)  # TwoSum: a + b == total + err exactly
        finite = np.isfinite(total) & np.isfinite(err)
        lone = _bytes(total)
        pair = _bytes(np.stack([err, total], axis=1).ravel())  # increasing magnitude: |err| <= ulp(total) / 2
        for k, i in enumerate(two.tolist()):
            if not finite[k]:
                blobs[i] = INEXACT
            else:
                blobs[i] = lone[k] if err[k] == 0 else pair[2 * k] + pair[2 * k + 1]
                sums[i] = float(total[k])
    for i in np.flatnonzero(counts > 2).tolist():
        many = of_values(values[first[i] : first[i] + counts[i]].tolist())
        blobs[i], sums[i] = many, rounded(many)
    return blobs, sums


def _bytes(x: np.ndarray) -> list[bytes]:
    """Each double's 8 little-endian bytes."""
    listed: list[bytes] = np.frombuffer(np.ascontiguousarray(x, dtype="<f8").tobytes(), dtype="V8").tolist()
    return listed


def add(a: bytes | None, b: bytes | None) -> bytes | None:
    """The exact sum of two BLOBs (either None: the other)."""
    if a is None or b is None:
        return a if b is None else b
    if a == INEXACT or b == INEXACT:
        return INEXACT
    if len(a) == 8 and len(b) == 8:  # the common case, two doubles: TwoSum (Knuth), exact
        (x,), (y,) = _DOUBLE.unpack(a), _DOUBLE.unpack(b)
        total = x + y
        if not math.isfinite(total):
            return INEXACT
        back = total - x
        err = (x - (total - back)) + (y - back)
        return _DOUBLE.pack(total) if not err else _DOUBLE.pack(err) + _DOUBLE.pack(total)
    parts = unpack(a)
    for x in unpack(b):
        if not grow(parts, x):
            return INEXACT
    return pack(parts)


def rounded(blob: bytes | None) -> float | None:
    """The correctly rounded value of a BLOB (None: none, or INEXACT)."""
    if blob is None or blob == INEXACT:
        return None
    if len(blob) == 8:
        return float(_DOUBLE.unpack(blob)[0])
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
