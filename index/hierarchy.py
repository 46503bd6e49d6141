"""Hierarchy: levels, parents, children, compaction, counts.

Ids carry the hierarchy in their prefixes, so parents are truncations and
children are suffixes: string arithmetic on numpy arrays, no geometry.
"""

from __future__ import annotations

from typing import Iterable

import numpy as np

from dggs.errors import LevelMismatchError

from . import _scalar
from .cellid import FACE_LETTERS, MAX_LEVEL, as_id_array, check_level, decode, levels, valid_mask

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
]


def get_num_cells(level: int) -> int:
    """Number of cells at ``level``: 20 at level 0, ``120 * 3 ** (level - 1)`` after.

    Examples
    --------
    >>> [get_num_cells(l) for l in range(4)]
    [20, 120, 360, 1080]
    """
    level = check_level(level)
    return 20 if level == 0 else 120 * 3 ** (level - 1)


def get_base_cells() -> np.ndarray:
    """The 20 level-0 cells (the icosahedron's faces), ``A`` .. ``T``.

    Examples
    --------
    >>> get_base_cells()[:3].tolist()
    ['A', 'B', 'C']
    """
    return np.array(list(FACE_LETTERS))


def is_valid_cell(cell) -> bool | np.ndarray:
    """Whether ``cell`` is a well-formed cell id.  Never raises.

    Examples
    --------
    >>> is_valid_cell("C401"), is_valid_cell("C6"), is_valid_cell(42)
    (True, False, False)
    """
    if isinstance(cell, str):
        return _scalar.is_valid(cell)
    try:
        arr = np.asarray(cell)
    except Exception:  # noqa: BLE001 - never raise
        return False
    if arr.ndim == 0:
        return False
    if arr.dtype.kind != "U":
        flat = arr.ravel()
        return np.array([isinstance(c, str) and bool(c) and bool(is_valid_cell(c)) for c in flat]).reshape(arr.shape)
    return valid_mask(arr.ravel()).reshape(arr.shape)


def get_level(cell):
    """Level of a cell (``len(id) - 1``).

    Examples
    --------
    >>> get_level("C401")
    3
    """
    if isinstance(cell, str) and _scalar.is_valid(cell):
        return len(cell) - 1
    ids, scalar = as_id_array(cell)
    level = decode(ids).level
    return int(level[0]) if scalar else level


def get_face(cell):
    """Icosahedron face (0..19, PROJ's numbering) of a cell.

    Examples
    --------
    >>> get_face("C401")
    2
    """
    if isinstance(cell, str) and _scalar.is_valid(cell):
        return ord(cell[0]) - 65
    ids, scalar = as_id_array(cell)
    face = decode(ids).face
    return int(face[0]) if scalar else face


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
    if isinstance(cell, str) and _scalar.is_valid(cell) and len(cell) > 1:
        if level is None:
            return cell[:-1]
        if isinstance(level, (int, np.integer)) and not isinstance(level, bool) and 0 <= level < len(cell):
            return cell[: level + 1]
    ids, scalar = as_id_array(cell)
    lv = levels(ids)
    if level is None:
        if ids.size and lv.min() == 0:
            i = int(np.argmin(lv))
            raise LevelMismatchError(f"base cell {str(ids[i])!r} has no parent")
        if ids.size and lv.min() != lv.max():
            out = np.array([c[:-1] for c in ids.tolist()])
        else:
            out = ids.astype(f"<U{int(lv[0]) if ids.size else 1}")
    else:
        level = check_level(level)
        if ids.size and lv.min() < level:
            i = int(np.argmin(lv))
            raise LevelMismatchError(
                f"parent level {level} is finer than cell {str(ids[i])!r} at level {int(lv[i])}"
            )
        out = ids.astype(f"<U{level + 1}")
    return str(out[0]) if scalar else out


def _suffixes(n_digits: int, first_six: bool) -> np.ndarray:
    """All digit suffixes (3^n or 6 * 3^(n-1), n) in depth-first order."""
    if n_digits == 0:
        return np.zeros((1, 0), dtype=np.uint32)
    radices = [6 if (first_six and i == 0) else 3 for i in range(n_digits)]
    grids = np.indices(radices).reshape(n_digits, -1).T
    return grids.astype(np.uint32)


def cell_to_children(cell, level: int | None = None) -> np.ndarray:
    """The descendants of a cell at ``level`` (default: one level down), in id order.

    Returns a ``U`` array: 3 children per level (6 from a base cell to level 1).

    Raises
    ------
    LevelMismatchError
        ``level`` is coarser than the cell.

    Examples
    --------
    >>> cell_to_children("C401").tolist()
    ['C4010', 'C4011', 'C4012']
    >>> len(cell_to_children("C", 2))
    18
    """
    if isinstance(cell, str) and _scalar.is_valid(cell):
        target = len(cell) if level is None else level
        if isinstance(target, (int, np.integer)) and not isinstance(target, bool) and len(cell) <= target <= MAX_LEVEL:
            return np.array(_scalar.children(cell, int(target)))
    ids, _ = as_id_array(cell)
    if ids.size == 0:
        return np.array([], dtype="<U1")
    cell_levels = levels(ids)
    lo, hi = int(cell_levels.min()), int(cell_levels.max())
    if level is None:
        if lo != hi:
            raise LevelMismatchError("cells of mixed levels need an explicit child level")
        level = lo + 1
    level = check_level(level, "child level")
    if hi > level:
        i = int(np.argmax(cell_levels))
        raise LevelMismatchError(
            f"child level {level} is coarser than cell {str(ids[i])!r} at level {int(cell_levels[i])}"
        )
    parts = []
    unique_levels: Iterable[int]
    if lo == hi:
        order = np.arange(len(ids))
        unique_levels = [lo]
    else:
        order = np.argsort(ids, kind="stable")
        unique_levels = np.unique(cell_levels)
    for lv in unique_levels:
        sel = order if lo == hi else order[cell_levels[order] == lv]
        suffix = _suffixes(level - int(lv), lv == 0)
        suffix = suffix + np.uint32(ord("0"))
        base = ids[sel].astype(f"<U{lv + 1}").view(np.uint32).reshape(len(sel), int(lv) + 1)
        codes = np.empty((len(sel), len(suffix), level + 1), dtype=np.uint32)
        codes[:, :, : lv + 1] = base[:, None, :]
        codes[:, :, lv + 1 :] = suffix[None, :, :]
        parts.append((sel, codes.reshape(-1, level + 1).view(f"<U{level + 1}").ravel()))
    if len(parts) == 1:
        return parts[0][1]
    out = np.concatenate([p[1] for p in parts])
    return np.sort(out)


def cell_to_center_child(cell, level: int | None = None):
    """The descendant at ``level`` that holds the cell's centre point.

    Examples
    --------
    >>> cell_to_center_child("C401")
    'C4011'
    """
    from .points import _planar_centres
    from dggs.geometry.split26 import locate
    from .cellid import encode

    ids, scalar = as_id_array(cell)
    dec = decode(ids)
    if level is None:
        level = int(dec.level.max()) + 1 if ids.size else 1
    level = check_level(level, "child level")
    if ids.size and dec.level.max() > level:
        i = int(np.argmax(dec.level))
        raise LevelMismatchError(
            f"child level {level} is coarser than cell {str(ids[i])!r} at level {int(dec.level[i])}"
        )
    c = _planar_centres(dec)
    out = encode(dec.face, locate(c[:, 0], c[:, 1], level))
    # The centroid lies inside the cell, so it is located in one of its
    # descendants; a base cell's centre is a corner of all six level-1
    # triangles and goes to triangle 0 by the level-1 tie rule.
    return str(out[0]) if scalar else out


def compact_cells(cells) -> np.ndarray:
    """Replace every complete set of siblings by their parent, recursively.

    Duplicates and cells already covered by an ancestor in the input are
    dropped.  The result covers exactly the same area with fewest cells.

    Examples
    --------
    >>> compact_cells(["C4010", "C4011", "C4012", "C402"]).tolist()
    ['C401', 'C402']
    """
    ids, _ = as_id_array(cells)
    if ids.size == 0:
        return np.array([], dtype="<U1")
    dec = decode(ids)
    top = int(dec.level.max())
    by_level = {lv: np.unique(ids[dec.level == lv]).astype(f"<U{lv + 1}") for lv in range(top + 1)}
    for lv in range(top, 0, -1):
        group = by_level[lv]
        if group.size == 0:
            continue
        parents = group.astype(f"<U{lv}")
        uniq, counts = np.unique(parents, return_counts=True)
        full = uniq[counts == (6 if lv == 1 else 3)]
        if full.size:
            by_level[lv] = group[~np.isin(parents, full)]
            by_level[lv - 1] = np.union1d(by_level[lv - 1], full)
    # drop cells already covered by a coarser cell of the input
    for lv in range(1, top + 1):
        for coarse in range(lv):
            if by_level[lv].size and by_level[coarse].size:
                covered = np.isin(by_level[lv].astype(f"<U{coarse + 1}"), by_level[coarse])
                by_level[lv] = by_level[lv][~covered]
    return np.sort(np.concatenate([by_level[lv] for lv in range(top + 1)]))


def uncompact_cells(cells, level: int) -> np.ndarray:
    """Expand cells to their descendants at ``level`` (the inverse of compaction).

    Raises
    ------
    LevelMismatchError
        A cell is finer than ``level``.

    Examples
    --------
    >>> uncompact_cells(["C401", "C4020"], 4).tolist()
    ['C4010', 'C4011', 'C4012', 'C4020']
    """
    level = check_level(level)
    ids, _ = as_id_array(cells)
    if ids.size == 0:
        return np.array([], dtype=f"<U{level + 1}")
    return np.unique(cell_to_children(ids, level))
