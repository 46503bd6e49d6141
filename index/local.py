"""Positions: a cell's position among its ancestor's descendants, and local (i, j) coordinates around an anchor.

Child positions count a parent's descendants at one level in digit order (as
h3's ``cell_to_child_pos``): the digits below the parent's level read in base
3, the level-1 digit (0-5) in base 6 when the parent is a face.

Local coordinates name the cells of the anchor's chart (its sector of its face
and the sector across that sector's face edge, unfolded into one plane; at
level 0 its face and the three across its edges) by integers (i, j) computed
from their centroids (docs/grid.md, "Local coordinates"): the anchor is (0, 0),
the lattice is the same at every level, and a pair (i, j) names at most one
cell.  Beyond the chart the grid bends and a DistortionError says so.
The kernels are in :mod:`dggs.index._kernel.local`.
"""

from __future__ import annotations

import math
import sys
from typing import Any

import numpy as np

from dggs.errors import DggsValueError, DistortionError, LevelMismatchError

from ._checks import check_level
from ._convert import CELL, VALUE, Kind, Op, apply, apply_pair, cells_in, cells_out, id_name
from ._kernel import hierarchy as kh
from ._kernel import local as kl

__all__ = ["cell_to_child_pos", "child_pos_to_cell", "cell_to_local_ij", "local_ij_to_cell"]


def _child_pos(ids: np.ndarray, parent_level: int) -> np.ndarray:
    out = np.empty(ids.shape[0], dtype=np.int64)
    kl.child_pos(ids.shape[0], ids, parent_level, out)
    if (out < 0).any():
        i = int(np.flatnonzero(out < 0)[0])
        level = int(kh.levels(ids[i : i + 1])[0])
        raise LevelMismatchError(f"parent level {parent_level} is finer than cell {id_name(ids[i])!r} at level {level}")
    return out


def _local_ij(anchors: np.ndarray, ids: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    la, lc = kh.levels(anchors), kh.levels(ids)
    if (la != lc).any():
        n = int(np.flatnonzero(la != lc)[0])
        raise LevelMismatchError(
            f"cell {id_name(ids[n])!r} (level {lc[n]}) is not at the level of anchor {id_name(anchors[n])!r} (level {la[n]})"
        )
    i = np.empty(ids.shape[0], dtype=np.int64)
    j = np.empty(ids.shape[0], dtype=np.int64)
    kl.local_ij(ids.shape[0], anchors, ids, i, j)
    if (i == kl.OUT_OF_RANGE).any():
        n = int(np.flatnonzero(i == kl.OUT_OF_RANGE)[0])
        raise DistortionError(
            f"cell {id_name(ids[n])!r} has no local coordinates around anchor {id_name(anchors[n])!r}: the grid bends "
            "between them (the chart is the anchor's sector of its face and the sector across that sector's face edge; "
            "docs/grid.md, \"Local coordinates\")"
        )
    return i, j


def _one_child_pos(cell: int, parent_level: int) -> int | None:
    """A lone id's position, or None (a miss: the general path explains it)."""
    r = int(kl.one_child_pos(cell, parent_level))
    return r if r >= 0 else None


def _one_local_ij(anchor: int, cell: int) -> tuple[float, float]:
    """A lone pair's (i, j), or NaNs (a miss: the general path explains it)."""
    i, j, ok = kl.one_local_ij(anchor, cell)
    return (int(i), int(j)) if ok else (math.nan, math.nan)  # type: ignore[return-value]


_CHILD_POS = Op(many=_child_pos, out=VALUE, one=_one_child_pos)
_LOCAL_IJ = Op(many=_local_ij, out=VALUE, one=_one_local_ij)
_CHILD_CELL = Op(many=lambda ids, pos, level: _child_cells(ids, np.full(ids.shape[0], pos, np.int64), level),
                 out=CELL, one=kl.one_child_cell)
_LOCAL_CELL = Op(many=lambda ids, i, j: _local_cells(ids, np.full(ids.shape[0], i, np.int64), np.full(ids.shape[0], j, np.int64)),
                 out=CELL, one=kl.one_local_cell)


def _ints_in(obj: Any, name: str) -> tuple[np.ndarray, Kind | None]:
    """Integers in any container as a flat int64 array, and their container's kind (None for a scalar).

    Raises
    ------
    DggsValueError
        A value that is not an integer (the message names it).
    """
    pd, pa = sys.modules.get("pandas"), sys.modules.get("pyarrow")
    kind: Kind | None = None
    if pd is not None and isinstance(obj, pd.Series):
        kind, values = Kind("pandas", "int", (len(obj),), index=obj.index, name=obj.name), obj.to_numpy()
    elif pa is not None and isinstance(obj, (pa.Array, pa.ChunkedArray)):
        chunked = isinstance(obj, pa.ChunkedArray)
        kind, values = Kind("arrow", "int", (len(obj),), chunked=chunked), obj.to_numpy(zero_copy_only=False)
    elif isinstance(obj, (list, tuple)):
        values = np.asarray(obj, dtype=object)
        kind = Kind("list", "int", values.shape)
    elif isinstance(obj, np.ndarray):
        values, kind = obj, Kind("numpy", "int", obj.shape)
    else:
        values = np.asarray([obj], dtype=object)
    flat = np.asarray(values).reshape(-1)
    if flat.dtype.kind in "iu":
        return flat.astype(np.int64), kind
    for x in flat.tolist():
        if isinstance(x, bool) or not isinstance(x, (int, np.integer)):
            raise DggsValueError(f"{name} {x!r} must be an integer")
    try:
        return np.array(flat.tolist(), dtype=np.int64), kind
    except OverflowError:
        raise DggsValueError(f"{name} {max(flat.tolist(), key=abs)!r} is out of the 64-bit integer range") from None


def _ids_with_ints(cells: Any, numbers: list[tuple[Any, str]]) -> tuple[np.ndarray, list[np.ndarray], Kind]:
    """Ids and integer arguments broadcast against each other, and the answer's kind (the ids' unless a scalar)."""
    ids, kind = cells_in(cells)
    arrays, shapes = [], []
    shape = kind.shape
    out_kind = kind
    for obj, name in numbers:
        arr, k = _ints_in(obj, name)
        arrays.append(arr)
        shapes.append(() if k is None else k.shape)
        if k is not None:
            try:
                shape = np.broadcast_shapes(shape, k.shape)
            except ValueError:
                raise DggsValueError(f"cannot pair {ids.shape[0]} cells (shape {kind.shape}) with {arr.shape[0]} {name}s") from None
            if out_kind.scalar:
                out_kind = Kind(k.container, kind.form, k.shape, index=k.index, name=k.name, chunked=k.chunked)
    if out_kind.container == "arrow":
        pa = sys.modules["pyarrow"]
        out_kind = Kind("arrow", kind.form, shape, dtype=pa.string() if kind.form == "str" else pa.uint64(), chunked=out_kind.chunked)
    elif out_kind.container == "pandas" and out_kind.dtype is None:
        out_kind = Kind("pandas", kind.form, shape, dtype=np.dtype(object) if kind.form == "str" else np.dtype(np.uint64),
                        index=out_kind.index, name=out_kind.name)
    elif out_kind.shape != shape:
        out_kind = Kind("list" if out_kind.container in ("list", "tuple") else "numpy", kind.form, shape)
    full = [np.ascontiguousarray(np.broadcast_to(ids.reshape(kind.shape), shape)).reshape(-1)]
    for arr, a_shape in zip(arrays, shapes, strict=True):
        full.append(np.ascontiguousarray(np.broadcast_to(arr.reshape(a_shape), shape)).reshape(-1))
    return full[0], full[1:], out_kind


def cell_to_child_pos(cell: Any, parent_level: int) -> Any:
    """The position of each cell among the descendants, at its level, of its ancestor at ``parent_level`` (h3 semantics).

    Descendants are counted in id order (the digit order of
    :func:`dggs.cell_to_children`): the digits below ``parent_level`` read as a
    number in base 3, the level-1 digit (0-5) as a base-6 digit when
    ``parent_level`` is 0.  A cell at ``parent_level`` is at position 0.

    Parameters
    ----------
    cell : str, int or any container of ids
        Cells of either form.
    parent_level : int
        0..the cell's level.

    Returns
    -------
    int or container of int
        In the container that came in.

    Raises
    ------
    InvalidCellError
        A malformed id (the message names it).
    LevelError
        ``parent_level`` is not an integer 0..MAX_LEVEL.
    LevelMismatchError
        ``parent_level`` is finer than a cell (the message names it).

    Examples
    --------
    >>> cell_to_child_pos("C421", 1)
    7
    >>> cell_to_child_pos(["C401", "C5"], 0)
    [37, 5]
    """
    return apply(_CHILD_POS, cell, check_level(parent_level, "parent level"))


def child_pos_to_cell(pos: Any, parent: Any, level: int) -> Any:
    """The descendant of ``parent`` at ``level`` at position ``pos`` (the inverse of :func:`cell_to_child_pos`).

    Parameters
    ----------
    pos : int or container of int
        Positions 0 .. (number of descendants - 1): ``3 ** (level - p)`` below a
        parent at level ``p >= 1``, ``6 * 3 ** (level - 1)`` below a face.
    parent : str, int or any container of ids
        Parents of either form; broadcast against ``pos`` as numpy does.
    level : int
        The descendants' level, at or below every parent's.

    Returns
    -------
    str, int or container of ids
        In the parent's form and container (the positions' container for a single parent).

    Raises
    ------
    InvalidCellError
        A malformed parent id.
    LevelError
        ``level`` is not an integer 0..MAX_LEVEL.
    LevelMismatchError
        A parent is finer than ``level``.
    DggsValueError
        A position that is no integer, or out of range (the message names it and the range).

    Examples
    --------
    >>> child_pos_to_cell(7, "C4", 3)
    'C421'
    >>> child_pos_to_cell([0, 37], "C", 3)
    ['C000', 'C401']
    """
    level = check_level(level)
    one, k = _ints_in(pos, "child position")
    if k is None:  # one position: the parents' container, and a lone parent's compiled entry
        return apply(_CHILD_CELL, parent, int(one[0]), level)
    ids, (positions,), kind = _ids_with_ints(parent, [(pos, "child position")])
    return cells_out(_child_cells(ids, positions, level), kind)


def _child_cells(ids: np.ndarray, positions: np.ndarray, level: int) -> np.ndarray:
    out = np.empty(ids.shape[0], dtype=np.uint64)
    kl.child_pos_cells(ids.shape[0], positions, ids, level, out)
    if not out.all():
        n = int(np.flatnonzero(out == 0)[0])
        p = int(kh.levels(ids[n : n + 1])[0])
        if p > level:
            raise LevelMismatchError(f"level {level} is coarser than parent {id_name(ids[n])!r} at level {p}")
        count = int(kl.child_count(p, level))
        raise DggsValueError(
            f"child position {int(positions[n])} is out of range 0..{count - 1} for parent {id_name(ids[n])!r} at level {level}"
        )
    return out


def cell_to_local_ij(anchor: Any, cell: Any) -> Any:
    """Integer lattice coordinates (i, j) of ``cell`` around ``anchor`` (docs/grid.md, "Local coordinates").

    The anchor is (0, 0).  The cells of the anchor's chart have coordinates, one
    pair per cell: at level 0 the anchor's face and the three across its edges;
    finer, the anchor's 120-degree sector of its face (Snyder's projection is one
    smooth map there; the sectors are the level-1 digit pairs {0, 1}, {2, 3},
    {4, 5}) and the sector across the face edge bounding it, unfolded into the
    anchor's face plane.  Beyond, the projection bends (as h3 refuses across
    pentagons).  :func:`local_ij_to_cell` is the exact inverse.

    Parameters
    ----------
    anchor, cell : str, int or any container of ids
        Cells of one level, of either form; broadcast as numpy does.

    Returns
    -------
    (int, int) or (container, container)
        ``i`` and ``j`` in the container of the first non-scalar argument.

    Raises
    ------
    InvalidCellError
        A malformed id.
    LevelMismatchError
        A cell and its anchor are at different levels.
    DistortionError
        A cell outside the anchor's chart: the grid bends between them (the message names both).

    Examples
    --------
    >>> cell_to_local_ij("C401", "C401")
    (0, 0)
    >>> cell_to_local_ij("C401", ["C402", "C400"])
    ([4, -1], [2, 1])
    >>> cell_to_local_ij("K110121", "K210121")
    Traceback (most recent call last):
    ...
    dggs.errors.DistortionError: cell 'K210121' has no local coordinates around anchor 'K110121': the grid bends between them (the chart is the anchor's sector of its face and the sector across that sector's face edge; docs/grid.md, "Local coordinates")
    """
    return apply_pair(_LOCAL_IJ, anchor, cell)


def local_ij_to_cell(anchor: Any, i: Any, j: Any) -> Any:
    """The cell at lattice coordinates (i, j) around ``anchor`` (the inverse of :func:`cell_to_local_ij`).

    Parameters
    ----------
    anchor : str, int or any container of ids
        Anchor cells of either form.
    i, j : int or container of int
        Coordinates, broadcast against the anchors as numpy does.

    Returns
    -------
    str, int or container of ids
        At the anchor's level, in the anchor's form and container (the coordinates' container for a single anchor).

    Raises
    ------
    InvalidCellError
        A malformed anchor.
    DggsValueError
        Coordinates that are no integers, or that name no cell: not a cell's centroid of the lattice, or outside the
        anchor's chart (the message names them).

    Examples
    --------
    >>> local_ij_to_cell("C401", 4, 2)
    'C402'
    >>> local_ij_to_cell("C401", [0, -1], [0, 1])
    ['C401', 'C400']
    """
    one_i, ki = _ints_in(i, "i")
    one_j, kj = _ints_in(j, "j")
    if ki is None and kj is None:  # one pair: the anchors' container, and a lone anchor's compiled entry
        return apply(_LOCAL_CELL, anchor, int(one_i[0]), int(one_j[0]))
    ids, (ii, jj), kind = _ids_with_ints(anchor, [(i, "i"), (j, "j")])
    return cells_out(_local_cells(ids, ii, jj), kind)


def _local_cells(ids: np.ndarray, ii: np.ndarray, jj: np.ndarray) -> np.ndarray:
    out = np.empty(ids.shape[0], dtype=np.uint64)
    kl.local_cells(ids.shape[0], ids, ii, jj, out)
    if not out.all():
        n = int(np.flatnonzero(out == 0)[0])
        raise DggsValueError(
            f"(i, j) = ({int(ii[n])}, {int(jj[n])}) names no cell around anchor {id_name(ids[n])!r}: not a cell of the "
            "lattice, or outside the anchor's chart (its sector of its face and the sector across that sector's face edge)"
        )
    return out

