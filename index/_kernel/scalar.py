"""Single-id entries: one point or one id in, one answer out, strings parsed and built in compiled code.

A lone ``str`` id used to cross the Python codec (:func:`dggs.index._convert.strings.parse_str`,
about 500 ns for a level-17 id on the benchmark machine) before the kernel and again after it;
here the string is read in place by the array codec's own parser (no character objects) and
the answer built as one new string.  Each entry answers a miss (the empty string, NaN, 0) for anything it
cannot take, and the verb then takes its general path, which raises naming the bad value.
Each is the int kernel between that parser and :func:`format_one`.

The verbs call these through their compiled entry points
(:class:`dggs.index._convert.apply.Entry`), which skip numba's type dispatch: numba's
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
from numba.cpython.unicode import PY_UNICODE_1BYTE_KIND, _empty_string, _set_code_point

from .bits import digit_of, face_of, is_valid, level_of
from .codec import _parse_span
from .hierarchy import parent_of
from .points import centre_of, one_point

__all__ = ["centre_str", "format_one", "parent_str", "parse_one", "point_str"]

_ORD_A = 65  # "A"
_ORD_0 = 48  # "0"


@njit(cache=True, nogil=True)
def parse_one(s: str) -> np.uint64:
    """The id of a string id, or 0 if it is not one (the array codec's parser, reading the str in place)."""
    return _parse_span(s, 0, len(s))


@njit(cache=True, nogil=True)
def format_one(cell: int) -> str:
    """The string of a well-formed id (as an integer), or "" if it is not one."""
    c = np.uint64(cell)
    if not is_valid(c):
        return ""
    level = level_of(c)
    out = _empty_string(PY_UNICODE_1BYTE_KIND, level + 1, 1)
    _set_code_point(out, 0, _ORD_A + face_of(c))
    for k in range(1, level + 1):
        _set_code_point(out, k, _ORD_0 + digit_of(c, k))
    return out


@njit(cache=True, nogil=True)
def parent_str(s: str, level: int) -> str:
    """The ancestor of string id ``s`` at ``level`` (-1: one level up), or "" where there is none."""
    return format_one(parent_of(np.int64(parse_one(s)), level))


@njit(cache=True, nogil=True)
def point_str(lat: float, lng: float, level: int) -> str:
    """The string id of the level-``level`` cell holding a point; "" for a point not on the globe."""
    return format_one(np.int64(one_point(lat, lng, level)))


@njit(cache=True, nogil=True)
def centre_str(s: str):
    """The centre (lat, lng) of a string id; NaNs if it is not one."""
    return centre_of(np.int64(parse_one(s)))
