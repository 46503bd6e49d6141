"""String <-> 64-bit integer cell id codec: the compiled kernels (numba only, arrays in and out).

The integer layout is in :mod:`dggs.index._kernel.bits`; a string id is a face
letter ``A``..``T``, a level-1 digit ``0``..``5``, then one digit ``0``..``2``
per further level (at most 29 characters).  Strings reach the kernels as 2-D
character codes (a zero-copy ``uint32`` view of a numpy ``U`` array, ``uint8``
for ``S``; trailing NULs mean a shorter id), as Arrow buffers (data, offsets,
validity) or NUL-joined.  Parsers write the null id 0 for an invalid entry and
return the index of the first one (or -1), so callers can raise naming it.
The containers around these kernels, and the pure-Python scalar codec, are
in :mod:`dggs.index._convert.strings`.
"""

from __future__ import annotations

import numpy as np
from numba import njit, types
from numba.cpython.unicode import _get_code_point
from numba.extending import overload

from .bits import FACE_SHIFT, L1_SHIFT, MAX_LEVEL

__all__ = ["MAX_CHARS", "check_ints", "fill_codes", "max_level", "parse_arrow", "parse_codes", "parse_joined", "valid_ints"]

#: Longest string id: a face letter and MAX_LEVEL digits.
MAX_CHARS = MAX_LEVEL + 1
_LOW_BITS = (1 << L1_SHIFT) - 1  # the level-2..28 fields
_DIGIT_LOW = sum(1 << (2 * j) for j in range(MAX_LEVEL - 1))  # low bit of each 2-bit field
_ORD_A = 65  # "A"
_ORD_0 = 48  # "0"

_U0 = np.uint64(0)
_U1 = np.uint64(1)
_U_LOW_BITS = np.uint64(_LOW_BITS)
_U_DIGIT_LOW = np.uint64(_DIGIT_LOW)


# --------------------------------------------------------------------------
# Compiled kernels
# --------------------------------------------------------------------------


def _code_at(buf, j):  # type: ignore[no-untyped-def]
    """Character code ``j`` of ``buf``: an array of codes (any integer dtype) or a str (compiled only)."""
    raise NotImplementedError("compiled code only")


@overload(_code_at, inline="always")
def _code_at_compiled(buf, j):  # type: ignore[no-untyped-def]
    if isinstance(buf, types.UnicodeType):  # read in place: no one-character strings
        return lambda buf, j: np.int64(_get_code_point(buf, j))
    return lambda buf, j: np.int64(buf[j])


@njit(cache=True, nogil=True, inline="always")
def _parse_span(buf, start, end) -> np.uint64:
    """Id of the characters ``buf[start:end]`` (codes of any integer dtype, or a str); 0 if invalid."""
    n = end - start
    if n < 1 or n > MAX_CHARS:
        return _U0
    face = _code_at(buf, start) - _ORD_A
    if face < 0 or face >= 20:
        return _U0
    cell = np.uint64(1 << 62) | (np.uint64(face) << np.uint64(FACE_SHIFT))
    if n == 1:
        return cell
    d = _code_at(buf, start + 1) - _ORD_0
    if d < 0 or d > 5:
        return _U0
    cell |= np.uint64(d + 1) << np.uint64(L1_SHIFT)
    # levels 2..: accumulate base-4 codes (digit + 1), then shift them into place
    acc = _U0
    for j in range(start + 2, end):
        d = _code_at(buf, j) - _ORD_0
        if d < 0 or d > 2:
            return _U0
        acc = (acc << np.uint64(2)) | np.uint64(d + 1)
    return cell | (acc << np.uint64(2 * (MAX_CHARS - n)))


@njit(cache=True, nogil=True)
def parse_codes(codes):
    """Parse a 2-D array of character codes (one id per row, NUL padded).

    Returns ``(ids, first_bad)``: a uint64 array with 0 for every invalid
    row, and the index of the first invalid row or -1.  An empty row is
    invalid; so is a NUL followed by another character.
    """
    n, width = codes.shape
    out = np.empty(n, dtype=np.uint64)
    bad = -1
    for i in range(n):
        row = codes[i]
        end = width
        while end > 0 and row[end - 1] == 0:
            end -= 1
        v = _parse_span(row, 0, end)
        out[i] = v
        if v == _U0 and bad < 0:
            bad = i
    return out, bad


@njit(cache=True, nogil=True)
def parse_arrow(data, offsets, validity, offset: int, n: int):
    """Parse ``n`` Arrow strings starting at element ``offset``.

    ``data`` is the uint8 character buffer, ``offsets`` the int32 or int64
    offsets buffer and ``validity`` the validity bitmap (an empty array when
    there are no nulls).  Nulls are invalid.  Returns ``(ids, first_bad)``.
    """
    out = np.empty(n, dtype=np.uint64)
    bad = -1
    has_validity = validity.shape[0] > 0
    for i in range(n):
        j = offset + i
        if has_validity and not (validity[j >> 3] >> (j & 7)) & 1:
            v = _U0
        else:
            v = _parse_span(data, np.int64(offsets[j]), np.int64(offsets[j + 1]))
        out[i] = v
        if v == _U0 and bad < 0:
            bad = i
    return out, bad


@njit(cache=True, nogil=True)
def parse_joined(data, n: int):
    r"""Parse ``n`` ids joined by NUL codes (``"\x00".join(strings)``, as codes of any integer dtype).

    Returns ``(ids, first_bad, pieces)``; ``pieces != n`` means an element held a NUL itself
    (the ids are then meaningless).
    """
    out = np.zeros(n, dtype=np.uint64)
    bad = -1
    i = 0
    start = 0
    m = data.shape[0]
    for j in range(m + 1):
        if j == m or data[j] == 0:
            if i < n:
                v = _parse_span(data, start, j)
                out[i] = v
                if v == _U0 and bad < 0:
                    bad = i
            i += 1
            start = j + 1
    return out, bad, i


@njit(cache=True, nogil=True, inline="always")
def _ok(cell: np.uint64) -> bool:
    """Whether a uint64 is a well-formed id (branch-free, so loops over it vectorize)."""
    l1 = (cell >> np.uint64(L1_SHIFT)) & np.uint64(7)
    low = cell & _U_LOW_BITS
    # one bit per non-empty field of levels 2..28: the filled ones must be the top ones
    m = (low | (low >> _U1)) & _U_DIGIT_LOW
    lsb = m & (~m + _U1)
    return (
        ((cell >> np.uint64(62)) == _U1)  # sign clear, marker set
        & (((cell >> np.uint64(FACE_SHIFT)) & np.uint64(31)) < np.uint64(20))
        & (l1 != np.uint64(7))
        & ((l1 != _U0) | (low == _U0))
        & (m == (_U_DIGIT_LOW & ~(lsb - _U1)))
    )


@njit(cache=True, nogil=True)
def check_ints(ids):
    """Index of the first id of a uint64 array that is not well formed, or -1."""
    ok = True
    for i in range(ids.shape[0]):
        ok &= _ok(ids[i])
    if ok:
        return -1
    for i in range(ids.shape[0]):
        if not _ok(ids[i]):
            return i
    return -1


@njit(cache=True, nogil=True)
def valid_ints(ids):
    """Boolean mask of the well-formed ids of a uint64 array."""
    out = np.empty(ids.shape[0], dtype=np.bool_)
    for i in range(ids.shape[0]):
        out[i] = _ok(ids[i])
    return out


@njit(cache=True, nogil=True)
def max_level(ids):
    """``(deepest level, first bad index)`` of a uint64 array; the null id 0 is allowed.

    The deepest level is -1 when there is no id but nulls.
    """
    ok = True
    none = np.uint64(1 << 63)
    lowest = none  # the lowest bit of the deepest filled field seen
    for i in range(ids.shape[0]):
        c = ids[i]
        ok &= _ok(c) | (c == _U0)
        low = c & _U_LOW_BITS
        m = (low | (low >> _U1)) & _U_DIGIT_LOW
        bit = m & (~m + _U1)
        if m == _U0:
            bit = none if c == _U0 else np.uint64(1 << L1_SHIFT) if (c >> np.uint64(L1_SHIFT)) & np.uint64(7) else np.uint64(1 << FACE_SHIFT)
        lowest = min(lowest, bit)
    if not ok:
        for i in range(ids.shape[0]):
            if ids[i] != _U0 and not _ok(ids[i]):
                return -1, i
    if lowest == none:
        return -1, -1
    if lowest == np.uint64(1 << FACE_SHIFT):
        return 0, -1
    if lowest == np.uint64(1 << L1_SHIFT):
        return 1, -1
    k = MAX_LEVEL
    while lowest > _U1:
        lowest >>= np.uint64(2)
        k -= 1
    return k, -1


@njit(cache=True, nogil=True)
def fill_codes(ids, out) -> None:
    """Characters of valid-or-null ids into the rows of ``out``: an empty field gives a NUL."""
    width = out.shape[1]
    for i in range(ids.shape[0]):
        c = ids[i]
        row = out[i]
        row[0] = _ORD_A + np.int64((c >> np.uint64(FACE_SHIFT)) & np.uint64(31)) if c != _U0 else 0
        if width > 1:
            code = np.int64((c >> np.uint64(L1_SHIFT)) & np.uint64(7))
            row[1] = _ORD_0 - 1 + code if code else 0
        for k in range(2, width):
            code = np.int64((c >> np.uint64(2 * (MAX_LEVEL - k))) & np.uint64(3))
            row[k] = _ORD_0 - 1 + code if code else 0
