"""The 64-bit integer cell id: layout and bit operations (compiled).

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
"""

from __future__ import annotations

import llvmlite.ir as llvm_ir
import numpy as np
from numba import njit, types
from numba.extending import intrinsic

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
_U1 = np.uint64(1)
_U0 = np.uint64(0)


@njit(cache=True, nogil=True, inline="always")
def shift_of(level: int) -> np.uint64:
    """Lowest bit of level ``level``'s field."""
    if level == 0:
        return np.uint64(FACE_SHIFT)
    if level == 1:
        return np.uint64(L1_SHIFT)
    return np.uint64(2 * (MAX_LEVEL - level))


@intrinsic
def cttz(typingctx, x):
    """Trailing zero bits of a nonzero uint64 (one instruction)."""
    sig = types.uint64(types.uint64)

    def codegen(context, builder, signature, args):
        return builder.cttz(args[0], llvm_ir.Constant(llvm_ir.IntType(1), 1))

    return sig, codegen


_LOW54 = np.uint64((1 << L1_SHIFT) - 1)


@njit(cache=True, nogil=True, inline="always")
def level_of(cell: np.uint64) -> int:
    """Level of a well-formed id: its lowest filled field, by one trailing-zero count."""
    low = cell & _LOW54
    if low:
        return int(MAX_LEVEL - np.int64(cttz(low)) // 2)  # type: ignore[call-arg]
    return 1 if (cell >> np.uint64(L1_SHIFT)) & np.uint64(7) else 0


@njit(cache=True, nogil=True)
def is_valid(cell: np.uint64) -> bool:
    """Whether an integer is a well-formed id (never raises)."""
    if cell >> np.uint64(62) != _U1:  # sign bit clear, marker set
        return False
    if (cell >> np.uint64(FACE_SHIFT)) & np.uint64(31) >= 20:
        return False
    l1 = (cell >> np.uint64(L1_SHIFT)) & np.uint64(7)
    low = cell & np.uint64((1 << L1_SHIFT) - 1)
    if l1 == 0:
        return low == 0
    if l1 == 7:
        return False
    # every empty field must have only empty fields below it
    seen_empty = False
    for k in range(2, MAX_LEVEL + 1):
        code = (low >> np.uint64(2 * (MAX_LEVEL - k))) & np.uint64(3)
        if code == 0:
            seen_empty = True
        elif seen_empty:
            return False
    return True


@njit(cache=True, nogil=True, inline="always")
def face_of(cell: np.uint64) -> int:
    return int((cell >> np.uint64(FACE_SHIFT)) & np.uint64(31))


@njit(cache=True, nogil=True, inline="always")
def digit_of(cell: np.uint64, level: int) -> int:
    """Digit of ``cell`` at ``level`` >= 1 (0..5 at level 1, 0..2 after); -1 where empty."""
    if level == 1:
        return int((cell >> np.uint64(L1_SHIFT)) & np.uint64(7)) - 1
    return int((cell >> np.uint64(2 * (MAX_LEVEL - level))) & np.uint64(3)) - 1



@njit(cache=True, nogil=True, inline="always")
def base_cell(face: int) -> np.uint64:
    return MARKER | (np.uint64(face) << np.uint64(FACE_SHIFT))


@njit(cache=True, nogil=True, inline="always")
def parent_at(cell: np.uint64, level: int) -> np.uint64:
    """Ancestor at ``level`` (no checks): clear every field below it."""
    return cell & ~((_U1 << shift_of(level)) - _U1)


@njit(cache=True, nogil=True, inline="always")
def range_end(cell: np.uint64, level: int) -> np.uint64:
    """One past the last descendant of ``cell`` (at ``level``)."""
    return cell + (_U1 << shift_of(level))
