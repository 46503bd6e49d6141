"""The converter floor: ids and coordinates in any container in, the same kind out.

Verbs reach the kernel only through here: :func:`apply` (and
:func:`apply_pair`, :func:`apply_points`) with an :class:`Op` is the one
path, with the one single-id fast path; :func:`cells_in`, :func:`cells_out`,
:func:`cells_out_flat`, :func:`values_out` and :func:`coords_in` are its
pieces, for verbs whose answer is not one row per id.

The modules: :mod:`.kind` (what came in, and the error naming a bad id),
:mod:`.strings` (the string codec around the compiled one), :mod:`.cells_in`,
:mod:`.cells_out`, :mod:`.values`, :mod:`.coords`, :mod:`.apply`.
"""

from __future__ import annotations

from .apply import CELL, FLAT, ROWS, VALUE, VALUES, Entry, Op, apply, apply_pair, apply_points, lone_id, pair, pair_kind
from .cells_in import cells_in, is_valid_any
from .cells_out import cells_out, cells_out_flat, ids_array
from .coords import as_float_scalar, check_points, coords_in, levels_in, raise_bad_point
from .kind import Kind, as_form, id_name
from .strings import format_int, parse_str
from .values import values_out

__all__ = [
    "CELL", "FLAT", "ROWS", "VALUE", "VALUES", "Entry", "Kind", "Op", "apply", "apply_pair", "apply_points", "as_float_scalar", "as_form",
    "cells_in", "cells_out", "cells_out_flat", "ids_array", "check_points", "coords_in", "format_int", "is_valid_any", "levels_in", "lone_id",
    "id_name", "pair", "pair_kind", "parse_str", "raise_bad_point", "values_out",
]  # fmt: skip
