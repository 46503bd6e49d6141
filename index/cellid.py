"""Cell ids: the string form, the 64-bit integer form, and levels.

String ids: a face letter ``A``..``T`` (level 0, PROJ's faces 0..19), a digit
``0``..``5`` for the level-1 triangle, then one digit ``0``..``2`` per further
level; ``"C401"`` is a level-3 cell on face 2.  ``level = len(id) - 1``, the
parent is a prefix, sorting orders cells depth-first.

Integer ids (:mod:`dggs.index._bits`, docs/grid.md): 64 bits with the same
order, the descendants of a cell one integer range, and level, parent and
children bit operations.  Every id is a positive int64, so it fits SQLite,
Parquet, Arrow and DuckDB integer columns as it is.  :func:`str_to_int` and
:func:`int_to_str` convert, losslessly, any container.
"""

from __future__ import annotations

import numpy as np

from dggs.errors import LevelError

from ._bits import MAX_LEVEL
from ._convert import int_to_str, str_to_int

__all__ = ["MAX_LEVEL", "FACE_LETTERS", "check_level", "str_to_int", "int_to_str"]

FACE_LETTERS = "ABCDEFGHIJKLMNOPQRST"


def check_level(level, name: str = "level") -> int:
    """Return ``level`` as an int, or raise :class:`LevelError` naming it.

    Python and numpy integers are accepted; bools, floats and strings are not.

    Examples
    --------
    >>> check_level(np.int64(5))
    5
    """
    if isinstance(level, (bool, np.bool_)) or not isinstance(level, (int, np.integer)):
        raise LevelError(f"{name} {level!r} must be an integer 0..{MAX_LEVEL}")
    if not 0 <= level <= MAX_LEVEL:
        raise LevelError(f"{name} {level!r} is out of range 0..{MAX_LEVEL}")
    return int(level)
