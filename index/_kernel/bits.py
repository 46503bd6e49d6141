"""The 64-bit integer cell id: its layout's constants (the bit operations are the core's, libdggs/src/bits.h).

Layout, most significant bit first (docs/grid.md, "Integer ids")::

    bit  63      0            (so every id is a positive int64 too)
    bit  62      1            (marker: 0 is never an id, it is the null id)
    bits 61..57  face 0..19
    bits 56..54  level-1 code: 0 = none, 1..6 = digit 0..5
    bits 2(28-k)+1 .. 2(28-k)   level-k code (k = 2..28): 0 = none, 1..3 = digit 0..2

A field of 0 means "no digit", so a cell's id is its parent's with one more
field filled in: numeric order is the string order (depth-first, a parent
right before its descendants), the descendants of ``c`` at level ``l`` are
the integers ``[c, c + 2**shift(l))``, and level, parent and children are
bit operations.  ``MAX_LEVEL = 28``: the deepest level whose digit fits
beside the sign and marker bits.

Examples
--------
>>> int(SHIFTS[0]), int(SHIFTS[1]), int(SHIFTS[2]), int(SHIFTS[MAX_LEVEL])
(57, 54, 52, 0)
"""

from __future__ import annotations

import numpy as np

MAX_LEVEL = 28
MARKER = np.uint64(1 << 62)
FACE_SHIFT = 57
L1_SHIFT = 54
NULL_ID = np.uint64(0)

#: shift(l): the lowest bit of level l's field.
SHIFTS = np.array([FACE_SHIFT, L1_SHIFT] + [2 * (MAX_LEVEL - k) for k in range(2, MAX_LEVEL + 1)], dtype=np.uint64)
SHIFTS.setflags(write=False)
#: The low bit of every 2-bit digit field (levels 2..28): codes 1 and 3 (digits 0 and 2) set it.
DIGIT_LOW_BITS = np.uint64(sum(1 << (2 * j) for j in range(MAX_LEVEL - 1)))

__all__ = ["DIGIT_LOW_BITS", "FACE_SHIFT", "L1_SHIFT", "MARKER", "MAX_LEVEL", "NULL_ID", "SHIFTS"]
