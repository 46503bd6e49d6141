"""The grid as a graph: edge neighbours, disks, rings, distances.

Each level is a reflection tiling, so the cell across an edge is the mirror
image of the cell in that edge.  A neighbour is found by mirroring the cell's
planar centroid in the edge and locating the image, carried onto the
adjacent face when it falls off this one.  No lookup tables, any level.
"""

from __future__ import annotations

import numpy as np

from dggs.errors import DggsValueError, LevelMismatchError
from dggs.split26 import face_adjacency, locate, neighbour_points

from . import _geo
from .cellid import FACE_LETTERS, as_id_array, decode, encode

__all__ = ["edge_neighbors", "are_neighbor_cells", "grid_disk", "grid_ring", "grid_distance"]

_LETTERS = np.array(list(FACE_LETTERS))


def _neighbours(ids: np.ndarray) -> np.ndarray:
    """(N, 3) ids of the cells across each edge (corner i to corner i+1)."""
    dec = decode(ids)
    n = len(ids)
    geo = _geo.ORIENTATION.geometry
    out = np.empty((n, 3), dtype=ids.dtype if ids.size else "<U1")
    base = dec.level == 0
    if base.any():
        adj = face_adjacency(geo.face_vertices)
        # base-cell corners run V2, V1, V0 (counter-clockwise): corner edges 0, 1, 2
        # are face edges 1, 0, 2
        out[base] = _LETTERS[adj[dec.face[base]][:, [1, 0, 2]]]
    fine = np.flatnonzero(~base)
    if fine.size == 0:
        return out
    sub = decode(ids[fine])
    pts = _geo.corners(sub)  # (M, 3, 2)
    centre = pts.mean(axis=1)
    for levels in np.unique(sub.level):
        sel = np.flatnonzero(sub.level == levels)
        for i in range(3):
            p, q = pts[sel, i], pts[sel, (i + 1) % 3]
            d = q - p
            t = np.einsum("ij,ij->i", centre[sel] - p, d) / np.einsum("ij,ij->i", d, d)
            foot = p + t[:, None] * d
            mirror = 2.0 * foot - centre[sel]
            face, moved = neighbour_points(sub.face[sel], mirror, geo.face_vertices)
            digits = locate(moved[:, 0], moved[:, 1], int(levels))
            out[fine[sel], i] = encode(face, digits)
    return out


def edge_neighbors(cell) -> np.ndarray:
    """The three cells that share an edge with ``cell``, across face edges too.

    Returns a ``U`` array of 3 ids for one cell, (N, 3) for an array; column
    ``i`` is the cell across the edge from corner ``i`` to corner ``i + 1``
    of :func:`cell_to_boundary`.

    Examples
    --------
    >>> edge_neighbors("C401").tolist()
    ['C411', 'C402', 'C400']
    """
    ids, scalar = as_id_array(cell)
    out = _neighbours(ids)
    return out[0] if scalar else out


def are_neighbor_cells(a, b):
    """Whether cells ``a`` and ``b`` share an edge.

    Examples
    --------
    >>> are_neighbor_cells("C401", "C402"), are_neighbor_cells("C401", "C401")
    (True, False)
    """
    ia, sa = as_id_array(a)
    ib, sb = as_id_array(b)
    decode(ib)
    if ia.shape != ib.shape:
        ia, ib = np.broadcast_arrays(ia, ib)
    res = np.any(_neighbours(ia) == ib[:, None], axis=1)
    return bool(res[0]) if (sa and sb) else res


def _check_k(k) -> int:
    if isinstance(k, bool) or not isinstance(k, (int, np.integer)) or k < 0:
        raise DggsValueError(f"k {k!r} must be a non-negative integer")
    return int(k)


def _rings(cell: str, k: int):
    """Yield successive rings 0..k around one cell (breadth-first)."""
    ids, _ = as_id_array(cell)
    decode(ids)
    ring = np.unique(ids)
    seen = ring
    yield ring
    for _ in range(k):
        nb = np.unique(_neighbours(ring).ravel())
        ring = np.setdiff1d(nb, seen, assume_unique=True)
        seen = np.union1d(seen, ring)
        yield ring


def grid_disk(cell: str, k: int = 1) -> np.ndarray:
    """All cells within ``k`` edge steps of ``cell`` (including it), sorted.

    Examples
    --------
    >>> len(grid_disk("C401", 1)), len(grid_disk("C401", 2))
    (4, 9)
    """
    k = _check_k(k)
    return np.sort(np.concatenate(list(_rings(cell, k))))


def grid_ring(cell: str, k: int = 1) -> np.ndarray:
    """The cells exactly ``k`` edge steps from ``cell``, sorted.

    Examples
    --------
    >>> grid_ring("C401", 1).tolist()
    ['C400', 'C402', 'C411']
    """
    k = _check_k(k)
    *_, last = _rings(cell, k)
    return np.sort(last)


def grid_distance(a: str, b: str, max_steps: int = 10_000) -> int:
    """Number of edge steps on the shortest path between two cells of one level.

    Breadth-first search, so the cost grows with the square of the distance;
    ``max_steps`` bounds it.

    Raises
    ------
    LevelMismatchError
        The cells are at different levels.
    DggsValueError
        The distance exceeds ``max_steps``.

    Examples
    --------
    >>> grid_distance("C401", "C402"), grid_distance("C401", "C401")
    (1, 0)
    """
    ia, _ = as_id_array(a)
    ib, _ = as_id_array(b)
    la, lb = decode(ia).level[0], decode(ib).level[0]
    if la != lb:
        raise LevelMismatchError(f"cells {a!r} (level {la}) and {b!r} (level {lb}) are at different levels")
    target = str(ib[0])
    for step, ring in enumerate(_rings(str(ia[0]), max_steps)):
        if target in set(ring.tolist()) if ring.size < 64 else np.any(ring == target):
            return step
    raise DggsValueError(f"cells {a!r} and {b!r} are more than {max_steps} steps apart")
