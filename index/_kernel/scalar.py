"""Single-id entries: one point or one id in, one answer out: compiled C, libdggs/src/codec.c and points.c.

A lone ``str`` id is read in place at its own width (no character objects, no numpy array) by the array
codec's own parser, and the answer built as one new string.  Each entry answers a miss (the empty string,
NaN, 0) for anything it cannot take, and the verb then takes its general path, which raises naming the bad
value.  Each is the int kernel between that parser and :func:`format_one`.

The verbs name these in an :class:`dggs.index._convert.apply.Op`'s entries; :class:`Lone` binds an op's two
entries once, and :func:`lone` (:func:`lone_point` for a point) runs the one that fits a lone ``str`` or ``int``
as one C call, the core's functions called directly, answering None for a miss; :func:`lone_apply` and
:func:`lone_apply_points` are apply's and apply_points' whole fast path (the Op's entries, else the general path
they are given), and :func:`plain_level` check_level's (a plain int level, else the check it is given).

Examples
--------
>>> parse_one("C401") == 0x4000_0000_0000_0000 | (2 << 57) | (5 << 54) | (1 << 52) | (2 << 50)
True
>>> format_one(parse_one("C401")), parent_str("C401", -1), point_str(51.05, -114.07, 9)
('C401', 'C40', 'F200021102')
>>> str_if_valid("C401"), str_if_valid("C4013"), int_if_valid(parse_one("C401")) == parse_one("C401")
('C401', '', True)
>>> lone(Lone(parent_str, None), "C401", (1,)), lone(Lone(parent_str, None), 0x4558, (1,))
('C4', None)
"""

from __future__ import annotations

from dggs._core import (
    Lone,
    centre_str,
    format_one,
    int_if_valid,
    lone,
    lone_apply,
    lone_apply_points,
    lone_point,
    parent_str,
    parse_one,
    plain_level,
    point_str,
    str_if_valid,
)

__all__ = [
    "Lone", "centre_str", "format_one", "int_if_valid", "lone", "lone_apply", "lone_apply_points", "lone_point",
    "parent_str", "parse_one", "plain_level", "point_str", "str_if_valid",
]  # fmt: skip
