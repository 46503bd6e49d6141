"""Hierarchy: levels, parents, children, compaction, counts.

Integer ids carry the hierarchy in their bits (:mod:`dggs.index._bits`):
parents clear fields, children fill one, the descendants of a cell are one
integer range.  The compiled kernels are in :mod:`dggs.index._khier`.
"""

from __future__ import annotations

import numpy as np

from dggs.errors import DggsValueError, LevelMismatchError, TooManyCellsError

from . import _codec, _khier, _kpoints
from ._bits import MAX_LEVEL
from ._convert_in import cells_in, is_valid_any, scalar_id
from ._convert_out import cells_out, cells_out_flat
from .cellid import FACE_LETTERS, check_level

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

#: Default limit on the cells one call may return (400 MB of integer ids).
MAX_CELLS = 50_000_000


def check_max_cells(max_cells) -> int:
    """``max_cells`` as an int (:data:`MAX_CELLS` for None), or :class:`DggsValueError` naming it."""
    if max_cells is None:
        return MAX_CELLS
    if isinstance(max_cells, (bool, np.bool_)) or not isinstance(max_cells, (int, np.integer)) or max_cells < 0:
        raise DggsValueError(f"max_cells {max_cells!r} must be a non-negative integer (or None for {MAX_CELLS:,})")
    return int(max_cells)


def check_size(total: int, max_cells: int | None, what: str) -> None:
    """Raise :class:`TooManyCellsError` before allocating more than ``max_cells`` cells."""
    limit = check_max_cells(max_cells)
    if total > limit:
        raise TooManyCellsError(
            f"{what} would return {total:,} cells, over the limit of {limit:,} (raise max_cells to allow it)"
        )


def get_num_cells(level: int) -> int:
    """Number of cells at ``level``: 20 at level 0, ``120 * 3 ** (level - 1)`` after.

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
    ids = np.array([(1 << 62) | (f << 57) for f in range(20)], dtype=np.uint64)
    return ids if as_int else np.array(list(FACE_LETTERS))


def is_valid_cell(cell) -> bool | np.ndarray:
    """Whether ``cell`` is a well-formed id (string or integer).  Never raises.

    Examples
    --------
    >>> is_valid_cell("C401"), is_valid_cell("C6"), is_valid_cell(42)
    (True, False, False)
    """
    return is_valid_any(cell)


def get_level(cell):
    """Level of a cell (``len(id) - 1`` for a string id).

    Examples
    --------
    >>> get_level("C401"), get_level(["C", "C4"]).tolist()
    (3, [0, 1])
    """
    ids, kind = cells_in(cell)
    lv = _khier.levels(ids)
    return int(lv[0]) if kind.scalar else lv.astype(np.int64).reshape(kind.shape)


def get_face(cell):
    """Icosahedron face (0..19, PROJ's numbering) of a cell.

    Examples
    --------
    >>> get_face("C401")
    2
    """
    ids, kind = cells_in(cell)
    face = ((ids >> np.uint64(57)) & np.uint64(31)).astype(np.int64)
    return int(face[0]) if kind.scalar else face.reshape(kind.shape)


def cell_to_parent(cell, level: int | None = None):
    """The ancestor of a cell at ``level`` (default: one level up).

    Raises
    ------
    InvalidCellError
        A malformed id.
    LevelMismatchError
        ``level`` is finer than the cell, or the cell is a base cell.

    Examples
    --------
    >>> cell_to_parent("C401"), cell_to_parent("C401", 1)
    ('C40', 'C4')
    """
    one = scalar_id(cell)
    if one and (level is None or (type(level) is int and 0 <= level <= MAX_LEVEL)):
        parent = _khier.parent_of(one, -1 if level is None else level)
        if parent:
            return _codec.format_int(parent) if type(cell) is str else parent
    ids, kind = cells_in(cell)
    if level is None:
        out, bad = _khier.parents_up(ids)
        if bad >= 0:
            raise LevelMismatchError(f"base cell {_name(ids[bad])!r} has no parent")
    else:
        level = check_level(level)
        out, bad = _khier.parents(ids, level)
        if bad >= 0:
            lv = int(_khier.levels(ids[bad : bad + 1])[0])
            raise LevelMismatchError(f"parent level {level} is finer than cell {_name(ids[bad])!r} at level {lv}")
    return cells_out(out, kind)


def _name(cell) -> str:
    return _codec.format_int(int(cell)) or str(int(cell))


def cell_to_children(cell, level: int | None = None, max_cells: int | None = None):
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
    LevelMismatchError
        ``level`` is coarser than a cell, or no level is given for cells of mixed levels.
    TooManyCellsError
        The result would exceed ``max_cells``; nothing is allocated.

    Examples
    --------
    >>> cell_to_children("C401")
    ['C4010', 'C4011', 'C4012']
    >>> len(cell_to_children("C", 2))
    18
    """
    check_max_cells(max_cells)
    ids, kind = cells_in(cell)
    if level is None:
        lo, hi = _khier.level_bounds(ids)
        if lo != hi:
            raise LevelMismatchError("cells of mixed levels need an explicit child level")
        level = lo + 1 if ids.size else 1
    level = check_level(level, "child level")
    total, bad = _khier.count_children(ids, level)
    if bad >= 0:
        lv = int(_khier.levels(ids[bad : bad + 1])[0])
        raise LevelMismatchError(f"child level {level} is coarser than cell {_name(ids[bad])!r} at level {lv}")
    check_size(total, max_cells, "cell_to_children")
    out = np.empty(total, dtype=np.uint64)
    _khier.children(ids, level, out)
    return cells_out_flat(out, kind)


def cell_to_center_child(cell, level: int | None = None):
    """The descendant at ``level`` that holds the cell's centre point (default: one level down).

    Examples
    --------
    >>> cell_to_center_child("C401")
    'C4011'
    """
    ids, kind = cells_in(cell)
    lo, hi = _khier.level_bounds(ids)
    if level is None:
        level = min(hi + 1, MAX_LEVEL) if ids.size else 1
    level = check_level(level, "child level")
    if ids.size and hi > level:
        i = int(np.argmax(_khier.levels(ids)))
        raise LevelMismatchError(
            f"child level {level} is coarser than cell {_name(ids[i])!r} at level {hi}"
        )
    out = np.empty(ids.shape[0], dtype=np.uint64)
    # The centroid lies inside the cell, so it is located in one of its
    # descendants; a base cell's centre is a corner of all six level-1
    # triangles and goes to triangle 0 by the level-1 tie rule.
    _kpoints.center_children(ids, level, out)
    return cells_out(out, kind)


def compact_cells(cells):
    """Replace every complete set of siblings by their parent, recursively.

    Duplicates and cells already covered by an ancestor in the input are
    dropped.  The result covers exactly the same area with the fewest cells,
    sorted.  Linear after one sort.

    Examples
    --------
    >>> compact_cells(["C4010", "C4011", "C4012", "C402"])
    ['C401', 'C402']
    """
    ids, kind = cells_in(cells)
    return cells_out_flat(_khier.compact(ids), kind)


def uncompact_cells(cells, level: int, max_cells: int | None = None):
    """Expand cells to their descendants at ``level`` (the inverse of compaction), sorted.

    Raises
    ------
    LevelMismatchError
        A cell is finer than ``level``.
    TooManyCellsError
        The result would exceed ``max_cells`` (default :data:`MAX_CELLS`).

    Examples
    --------
    >>> uncompact_cells(["C401", "C4020"], 4)
    ['C4010', 'C4011', 'C4012', 'C4020']
    """
    level = check_level(level)
    check_max_cells(max_cells)
    ids, kind = cells_in(cells)
    cover, total, bad = _khier.uncompact_prepare(ids, level)
    if bad >= 0:
        lv = int(_khier.levels(ids[bad : bad + 1])[0])
        raise LevelMismatchError(f"cell {_name(ids[bad])!r} at level {lv} is finer than level {level}")
    check_size(total, max_cells, "uncompact_cells")
    out = np.empty(total, dtype=np.uint64)
    _khier.children(cover, level, out)
    return cells_out_flat(out, kind)
