"""Single-id entries: one point or one id in, one answer out: compiled C, libdggs/src/codec.c and points.c.

A lone ``str`` id is read in place at its own width (no character objects, no numpy array) by the array
codec's own parser, and the answer built as one new string.  Each entry answers a miss (the empty string,
NaN, 0) for anything it cannot take, and the verb then takes its general path, which raises naming the bad
value.  Each is the int kernel between that parser and :func:`format_one`.

The verbs call these through :class:`dggs.index._convert.apply.Entry`, which calls them directly.

Examples
--------
>>> parse_one("C401") == 0x4000_0000_0000_0000 | (2 << 57) | (5 << 54) | (1 << 52) | (2 << 50)
True
>>> format_one(parse_one("C401")), parent_str("C401", -1), point_str(51.05, -114.07, 9)
('C401', 'C40', 'F200021102')
"""

from __future__ import annotations

from dggs._core import centre_str, format_one, parent_str, parse_one, point_str

__all__ = ["centre_str", "format_one", "parent_str", "parse_one", "point_str"]
