"""Hierarchy: levels, parents, children, compaction, counts.

Integer ids carry the hierarchy in their bits (:mod:`dggs.index._kernel.bits`):
parents clear fields, children fill one, the descendants of a cell are one
integer range.  The compiled kernels are in :mod:`dggs.index._kernel.hierarchy`.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from dggs.errors import LevelMismatchError

from ._checks import MAX_CELLS, check_level, check_max_cells, check_size
from ._convert import CELL, FLAT, VALUE, Entry, Op, apply, id_name, is_valid_any
from ._convert.strings import face_of, level_of
from ._kernel import compact as kc
from ._kernel import hierarchy as kh
from ._kernel import points as kp
from ._kernel import scalar as ks
from ._kernel.bits import FACE_SHIFT, MARKER, MAX_LEVEL
from .ids import FACE_LETTERS

__all__ = [
    "get_level",
    "get_face",
    "is_valid_cell",
    "cell_to_parent",
    "cell_to_children",
    "cell_to_center_child",
    "compact_cells",
    "uncompact_cells",
    "get_num_cells",
    "get_base_cells",
    "MAX_CELLS",
]


def _level_error(ids: np.ndarray, bad: int, message: str) -> LevelMismatchError:
    """The error naming cell ``ids[bad]`` and its level: ``message`` has ``{cell}`` and ``{level}``."""
    level = int(kh.levels(ids[bad : bad + 1])[0])
    return LevelMismatchError(message.format(cell=id_name(ids[bad]), level=level))


def _levels(ids: np.ndarray) -> np.ndarray:
    levels: np.ndarray = kh.levels(ids).astype(np.int64)
    return levels


def _faces(ids: np.ndarray) -> np.ndarray:
    faces: np.ndarray = ((ids >> np.uint64(FACE_SHIFT)) & np.uint64(31)).astype(np.int64)
    return faces


def _parents(ids: np.ndarray, level: int) -> np.ndarray:
    out: np.ndarray
    if level < 0:
        out, bad = kh.parents_up(ids)
        if bad >= 0:
            raise _level_error(ids, bad, "base cell {cell!r} has no parent")
        return out
    out, bad = kh.parents(ids, level)
    if bad >= 0:
        raise _level_error(ids, bad, f"parent level {level} is finer than cell {{cell!r}} at level {{level}}")
    return out


def _children(ids: np.ndarray, level: int, max_cells: int) -> np.ndarray:
    if level < 0:  # one level down: all cells must be of one level
        lo, hi = kh.level_bounds(ids)
        if lo != hi:
            raise LevelMismatchError("cells of mixed levels need an explicit child level")
        level = check_level(lo + 1 if ids.size else 1, "child level")
    total, bad = kh.count_children(ids, level)
    if bad >= 0:
        raise _level_error(ids, bad, f"child level {level} is coarser than cell {{cell!r}} at level {{level}}")
    check_size(total, max_cells, "cell_to_children")
    out = np.empty(total, dtype=np.uint64)
    kh.children(ids, level, out)
    return out


def _center_children(ids: np.ndarray, level: int) -> np.ndarray:
    if level < 0:  # one level down from each cell (a level-28 cell is its own centre child)
        out = np.empty(ids.shape[0], dtype=np.uint64)
        levels = np.asarray(kh.levels(ids))
        for lv in np.unique(levels):
            rows = levels == lv
            out[rows] = _center_children(np.ascontiguousarray(ids[rows]), min(int(lv) + 1, MAX_LEVEL))
        return out
    lo, hi = kh.level_bounds(ids)
    if ids.size and hi > level:
        i = int(np.argmax(kh.levels(ids)))
        raise _level_error(ids, i, f"child level {level} is coarser than cell {{cell!r}} at level {{level}}")
    out = np.empty(ids.shape[0], dtype=np.uint64)
    # The centroid lies inside the cell, so it is located in one of its descendants; a base cell's centre is a
    # corner of all six level-1 triangles and goes to triangle 0 by the level-1 tie rule.
    kp.center_children(ids.shape[0], ids, level, out)
    return out


def _uncompact(ids: np.ndarray, level: int, max_cells: int) -> np.ndarray:
    cover, total, bad = kc.uncompact_prepare(ids, level)
    if bad >= 0:
        raise _level_error(ids, bad, f"cell {{cell!r}} at level {{level}} is finer than level {level}")
    check_size(total, max_cells, "uncompact_cells")
    out = np.empty(total, dtype=np.uint64)
    kh.children(cover, level, out)
    return out


_LEVEL = Op(many=_levels, out=VALUE, one=level_of)
_FACE = Op(many=_faces, out=VALUE, one=face_of)
_PARENT = Op(many=_parents, out=CELL, one_str=Entry(ks.parent_str),
              one_int=Entry(kh.parent_of))
_CHILDREN = Op(many=_children, out=FLAT)
_CENTER_CHILD = Op(many=_center_children, out=CELL)
_COMPACT = Op(many=kc.compact, out=FLAT)
_UNCOMPACT = Op(many=_uncompact, out=FLAT)


def get_num_cells(level: int) -> int:
    """Number of cells at ``level``: 20 at level 0, ``120 * 3 ** (level - 1)`` after.

    Raises
    ------
    LevelError
        ``level`` is not an integer 0..MAX_LEVEL.

    Examples
    --------
    >>> [get_num_cells(l) for l in range(4)]
    [20, 120, 360, 1080]
    """
    level = check_level(level)
    return 20 if level == 0 else 120 * 3 ** (level - 1)


def get_base_cells(as_int: bool = False) -> np.ndarray:
    """The 20 level-0 cells (the icosahedron's faces), ``A`` .. ``T``.

    Examples
    --------
    >>> get_base_cells()[:3].tolist()
    ['A', 'B', 'C']
    >>> int(get_base_cells(as_int=True)[0])
    4611686018427387904
    """
    ids = np.array([int(MARKER) | (f << FACE_SHIFT) for f in range(20)], dtype=np.uint64)
    return ids if as_int else np.array(list(FACE_LETTERS))


def is_valid_cell(cell: Any) -> bool | np.ndarray:
    """Whether ``cell`` is a well-formed id (string or integer).  Never raises.

    Examples
    --------
    >>> is_valid_cell("C401"), is_valid_cell("C6"), is_valid_cell(42)
    (True, False, False)
    """
    valid: bool | np.ndarray = is_valid_any(cell)
    return valid


def get_level(cell: Any) -> Any:
    """Level of a cell (``len(id) - 1`` for a string id).

    Raises
    ------
    InvalidCellError
        A malformed id (the message names it).

    Examples
    --------
    >>> get_level("C401"), get_level(["C", "C4"])
    (3, [0, 1])
    """
    return apply(_LEVEL, cell)


def get_face(cell: Any) -> Any:
    """Icosahedron face (0..19, PROJ's numbering) of a cell.

    Raises
    ------
    InvalidCellError
        A malformed id (the message names it).

    Examples
    --------
    >>> get_face("C401")
    2
    """
    return apply(_FACE, cell)


def cell_to_parent(cell: Any, level: int | None = None) -> Any:
    """The ancestor of a cell at ``level`` (default: one level up).

    Raises
    ------
    InvalidCellError
        A malformed id.
    LevelError
        ``level`` is not None or an integer 0..MAX_LEVEL.
    LevelMismatchError
        ``level`` is finer than the cell, or the cell is a base cell.

    Examples
    --------
    >>> cell_to_parent("C401"), cell_to_parent("C401", 1)
    ('C40', 'C4')
    """
    return apply(_PARENT, cell, -1 if level is None else check_level(level))


def cell_to_children(cell: Any, level: int | None = None, max_cells: int | None = None) -> Any:
    """The descendants of a cell (or of each cell) at ``level`` (default: one level down), in id order.

    3 children per level (6 from a base cell to level 1).  A single id gives
    a list; an array gives one flat array of the same kind, each input
    cell's descendants together, in input order.

    Parameters
    ----------
    max_cells : int, optional
        Refuse to return more cells than this (default :data:`MAX_CELLS`).

    Raises
    ------
    InvalidCellError
        A malformed id (the message names it).
    LevelError
        ``level`` is not None or an integer 0..MAX_LEVEL, or no level is given for cells at MAX_LEVEL.
    LevelMismatchError
        ``level`` is coarser than a cell, or no level is given for cells of mixed levels.
    DggsValueError
        ``max_cells`` is not None or a non-negative integer.
    TooManyCellsError
        The result would exceed ``max_cells``; nothing is allocated.

    Examples
    --------
    >>> cell_to_children("C401")
    ['C4010', 'C4011', 'C4012']
    >>> len(cell_to_children("C", 2))
    18
    """
    limit = check_max_cells(max_cells)
    return apply(_CHILDREN, cell, -1 if level is None else check_level(level, "child level"), limit)


def cell_to_center_child(cell: Any, level: int | None = None) -> Any:
    """The descendant at ``level`` that holds the cell's centre point (default: one level down).

    Raises
    ------
    InvalidCellError
        A malformed id (the message names it).
    LevelError
        ``level`` is not None or an integer 0..MAX_LEVEL.
    LevelMismatchError
        ``level`` is coarser than a cell.

    Examples
    --------
    >>> cell_to_center_child("C401")
    'C4011'
    """
    return apply(_CENTER_CHILD, cell, -1 if level is None else check_level(level, "child level"))


def compact_cells(cells: Any) -> Any:
    """Replace every complete set of siblings by their parent, recursively.

    Duplicates and cells already covered by an ancestor in the input are
    dropped.  The result covers exactly the same area with the fewest cells,
    sorted.  Linear after one sort.

    Raises
    ------
    InvalidCellError
        A malformed id (the message names it).

    Examples
    --------
    >>> compact_cells(["C4010", "C4011", "C4012", "C402"])
    ['C401', 'C402']
    """
    return apply(_COMPACT, cells)


def uncompact_cells(cells: Any, level: int, max_cells: int | None = None) -> Any:
    """Expand cells to their descendants at ``level`` (the inverse of compaction), sorted.

    Raises
    ------
    InvalidCellError
        A malformed id (the message names it).
    LevelError
        ``level`` is not an integer 0..MAX_LEVEL.
    LevelMismatchError
        A cell is finer than ``level``.
    DggsValueError
        ``max_cells`` is not None or a non-negative integer.
    TooManyCellsError
        The result would exceed ``max_cells`` (default :data:`MAX_CELLS`).

    Examples
    --------
    >>> uncompact_cells(["C401", "C4020"], 4)
    ['C4010', 'C4011', 'C4012', 'C4020']
    """
    return apply(_UNCOMPACT, cells, check_level(level), check_max_cells(max_cells))
