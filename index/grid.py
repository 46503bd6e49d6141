"""The grid as a graph: edge neighbours, disks, rings, distances.

Each level is a reflection tiling (thesis §6.1.7, docs/grid.md), so the cell
across an edge is the mirror image of the cell in that edge; its id is the
cell's with one digit replaced (a digit walk on the integer id, in
:mod:`dggs.index._kgrid`).  Disks and rings grow breadth-first, each ring
deduplicated against the two before it.
"""

from __future__ import annotations

import numpy as np

from dggs.errors import DggsValueError, LevelMismatchError, TooManyCellsError

from . import _codec, _kgrid, _khier
from ._convert_in import cells_in, scalar_id
from ._convert_out import cells_out
from .hierarchy import check_max_cells, check_size
from dggs.geometry._parallel import parallel

__all__ = ["edge_neighbors", "are_neighbor_cells", "grid_disk", "grid_ring", "grid_distance"]


def edge_neighbors(cell):
    """The three cells that share an edge with ``cell``, across face edges too.

    Column ``i`` is the cell across the edge from corner ``i`` to corner
    ``i + 1`` of :func:`cell_to_boundary`.  A single id gives a list of 3;
    an array gives shape ``input shape + (3,)``, of the same kind.

    Examples
    --------
    >>> edge_neighbors("C401")
    ['C411', 'C402', 'C400']
    """
    ids, kind = cells_in(cell)
    out = np.empty((ids.shape[0], 3), dtype=np.uint64)
    _kgrid.neighbours(ids, out)
    return cells_out(out, kind, (3,))


def are_neighbor_cells(a, b):
    """Whether cells ``a`` and ``b`` share an edge (element-wise; shapes broadcast as in numpy).

    Raises
    ------
    DggsValueError
        The two shapes do not broadcast (the message names both sizes and shapes).

    Examples
    --------
    >>> are_neighbor_cells("C401", "C402"), are_neighbor_cells("C401", "C401")
    (True, False)
    """
    ia, ka = cells_in(a)
    ib, kb = cells_in(b)
    ia, ib, shape = _pair(ia, ka, ib, kb)
    res = np.empty(ia.shape[0], dtype=bool)
    _kgrid.are_neighbours(ia, ib, res)
    if ka.scalar and kb.scalar:
        return bool(res[0])
    return res.reshape(shape)


def _pair(ia: np.ndarray, ka, ib: np.ndarray, kb) -> tuple[np.ndarray, np.ndarray, tuple[int, ...]]:
    """Two id arrays broadcast against each other (numpy's rules), and the result's shape."""
    sa, sb = (() if ka.scalar else ka.shape), (() if kb.scalar else kb.shape)
    if sa == sb:
        return ia, ib, sa
    try:
        shape = np.broadcast_shapes(sa, sb)
    except ValueError:
        raise DggsValueError(
            f"cannot pair {ia.shape[0]} cells (shape {sa}) with {ib.shape[0]} cells (shape {sb})"
        ) from None
    ia = np.ascontiguousarray(np.broadcast_to(ia.reshape(sa), shape)).reshape(-1)
    ib = np.ascontiguousarray(np.broadcast_to(ib.reshape(sb), shape)).reshape(-1)
    return ia, ib, shape


#: Largest ``k`` (and ``max_steps``) the kernels take; a disk of this radius covers the globe at every level.
_K_LIMIT = 1 << 31


def _check_k(k, name: str = "k") -> int:
    if isinstance(k, (bool, np.bool_)) or not isinstance(k, (int, np.integer)) or k < 0:
        raise DggsValueError(f"{name} {k!r} must be a non-negative integer")
    return int(k)


def _check_radius(k, what: str) -> int:
    k = _check_k(k)
    if k > _K_LIMIT:
        raise TooManyCellsError(f"{what} with k={k} would return more cells than the grid has at any level")
    return k


def grid_disk(cell, k: int = 1, max_cells: int | None = None):
    """All cells within ``k`` edge steps of ``cell`` (including it), sorted.

    A single id gives a sorted list.  An array of N cells gives shape
    ``input shape + (M,)``: row i is the disk of cell i, sorted, padded
    with ``""`` (or 0 for integer ids) where a disk near an icosahedron
    vertex is smaller than the others.

    Parameters
    ----------
    max_cells : int, optional
        Refuse outputs larger than this (default
        :data:`dggs.index.hierarchy.MAX_CELLS`); checked before allocating.

    Raises
    ------
    TooManyCellsError
        The output would exceed ``max_cells``.

    Examples
    --------
    >>> len(grid_disk("C401", 1)), len(grid_disk("C401", 2))
    (4, 9)
    >>> grid_disk(np.array(["C401", "C402"]), 1).shape
    (2, 4)
    """
    k = _check_radius(k, "grid_disk")
    check_max_cells(max_cells)
    one = scalar_id(cell)
    if one and k <= 64:  # the single-cell path
        disk = _kgrid.disk_of(one, k).tolist()
        if disk:
            return [_codec.format_int(c) for c in disk] if type(cell) is str else disk
    return _rows(cell, k, max_cells, "grid_disk", _kgrid.disk_size_bound(k), _kgrid.disk, _kgrid.disk_serial)


def grid_ring(cell, k: int = 1, max_cells: int | None = None):
    """The cells exactly ``k`` edge steps from ``cell``, sorted.

    Same shapes and padding as :func:`grid_disk`.

    Examples
    --------
    >>> grid_ring("C401", 1)
    ['C400', 'C402', 'C411']
    """
    k = _check_radius(k, "grid_ring")
    check_max_cells(max_cells)
    return _rows(cell, k, max_cells, "grid_ring", _kgrid.ring_size_bound(k), _kgrid.ring, _kgrid.ring_serial)


def _rows(cell, k: int, max_cells, what: str, width: int, threaded, serial):
    """One sorted row of ``width`` per cell, padded with the null id, from a disk or ring kernel."""
    ids, kind = cells_in(cell)
    check_size(ids.shape[0] * width, max_cells, f"{what} with k={k}")
    out = np.empty((ids.shape[0], width), dtype=np.uint64)
    run = threaded if parallel(ids.shape[0] * width) else serial
    run(ids, k, out, np.empty(ids.shape[0], dtype=np.int64))
    return cells_out(out, kind, (width,))


def grid_distance(a, b, max_steps: int = 10_000):
    """Number of edge steps on the shortest path between cells of one level.

    Element-wise for arrays of the same shape, or shapes that broadcast as in
    numpy (one cell against many).

    Raises
    ------
    LevelMismatchError
        The cells are at different levels.
    DggsValueError
        The distance exceeds ``max_steps``, or the shapes do not broadcast.

    Examples
    --------
    >>> grid_distance("C401", "C402"), grid_distance("C401", "C401")
    (1, 0)
    """
    max_steps = min(_check_k(max_steps, "max_steps"), _K_LIMIT)
    ia, ka = cells_in(a)
    ib, kb = cells_in(b)
    ia, ib, shape = _pair(ia, ka, ib, kb)
    la, lb = _khier.levels(ia), _khier.levels(ib)
    if (la != lb).any():
        i = int(np.flatnonzero(la != lb)[0])
        raise LevelMismatchError(
            f"cells {_codec.format_int(int(ia[i]))!r} (level {la[i]}) and "
            f"{_codec.format_int(int(ib[i]))!r} (level {lb[i]}) are at different levels"
        )
    dist = np.empty(ia.shape[0], dtype=np.int64)
    run = _kgrid.distances if parallel(ia.shape[0]) else _kgrid.distances_serial
    run(ia, ib, max_steps, dist)
    if (dist < 0).any():
        i = int(np.flatnonzero(dist < 0)[0])
        raise DggsValueError(
            f"cells {_codec.format_int(int(ia[i]))!r} and {_codec.format_int(int(ib[i]))!r} "
            f"are more than {max_steps} steps apart"
        )
    if ka.scalar and kb.scalar:
        return int(dist[0])
    return dist.reshape(shape)
