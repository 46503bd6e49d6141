"""Single-id entries: one point or one id in, one answer out, strings parsed and built in compiled code.

A lone ``str`` id used to cross the Python codec (:func:`dggs.index._convert.strings.parse_str`,
about 500 ns for a level-17 id on the benchmark machine) before the kernel and again after it;
here the string is read in place (``_get_code_point``, no character objects) and the answer
built as one new string.  Each entry answers a miss (the empty string, NaN, 0) for anything it
cannot take, and the verb then takes its general path, which raises naming the bad value.

The verbs call these through their compiled entry points
(:func:`dggs.index._convert.apply.compiled`), which skip numba's type dispatch: numba's
dispatcher spends about 1 µs choosing the signature for a ``str`` argument.

Examples
--------
>>> parse_one("C401") == 0x4000_0000_0000_0000 | (2 << 57) | (5 << 54) | (1 << 52) | (2 << 50)
True
>>> format_one(parse_one("C401")), parent_str("C401", -1), point_str(51.05, -114.07, 9)
('C401', 'C40', 'F200021102')
"""

from __future__ import annotations

import numpy as np
from numba import njit
from numba.cpython.unicode import PY_UNICODE_1BYTE_KIND, _empty_string, _get_code_point, _set_code_point

from .bits import FACE_SHIFT, L1_SHIFT, MAX_LEVEL, is_valid, level_of
from .points import _one_centre, one_point

__all__ = ["centre_str", "format_one", "parent_str", "parse_one", "point_str"]

_ORD_A = 65  # "A"
_ORD_0 = 48  # "0"
_MARKER = 1 << 62
_FACES = 20


@njit(cache=True, nogil=True)
def parse_one(s: str) -> int:
    """The id of a string id, or 0 if it is not one (the layout of :mod:`.bits`)."""
    n = len(s)
    if n < 1 or n > MAX_LEVEL + 1:
        return 0
    face = _get_code_point(s, 0) - _ORD_A
    if face < 0 or face >= _FACES:
        return 0
    cell = _MARKER | (face << FACE_SHIFT)
    if n == 1:
        return cell
    d = _get_code_point(s, 1) - _ORD_0
    if d < 0 or d > 5:
        return 0
    cell |= (d + 1) << L1_SHIFT
    for k in range(2, n):  # the character of level k
        d = _get_code_point(s, k) - _ORD_0
        if d < 0 or d > 2:
            return 0
        cell |= (d + 1) << (2 * (MAX_LEVEL - k))
    return cell


@njit(cache=True, nogil=True)
def format_one(cell: int) -> str:
    """The string of a well-formed id (as int64), or "" if it is not one."""
    c = np.uint64(cell)
    if not is_valid(c):
        return ""
    level = level_of(c)
    out = _empty_string(PY_UNICODE_1BYTE_KIND, level + 1, 1)
    _set_code_point(out, 0, _ORD_A + (cell >> FACE_SHIFT) % 32)
    if level >= 1:
        _set_code_point(out, 1, _ORD_0 + ((cell >> L1_SHIFT) & 7) - 1)
    for k in range(2, level + 1):
        _set_code_point(out, k, _ORD_0 + ((cell >> (2 * (MAX_LEVEL - k))) & 3) - 1)
    return out


@njit(cache=True, nogil=True)
def parent_str(s: str, level: int) -> str:
    """The ancestor of string id ``s`` at ``level`` (-1: one level up), or "" where there is none.

    A string id's ancestor at level ``l`` is its first ``l + 1`` characters.
    """
    cell = parse_one(s)
    if cell == 0:
        return ""
    lv = len(s) - 1
    if level < 0:
        level = lv - 1
    if level < 0 or level > lv:
        return ""
    return s[: level + 1]



@njit(cache=True, nogil=True)
def point_str(lat: float, lng: float, level: int) -> str:
    """The string id of the level-``level`` cell holding a point; "" for a point not on the globe."""
    cell = one_point(lat, lng, level)
    if cell == 0:
        return ""
    return format_one(np.int64(cell))



@njit(cache=True, nogil=True)
def centre_str(s: str):
    """The centre (lat, lng) of a string id; NaNs if it is not one."""
    cell = parse_one(s)
    if cell == 0:
        return np.nan, np.nan
    return _one_centre(np.uint64(cell))
