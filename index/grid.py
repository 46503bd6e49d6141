"""The grid as a graph: edge neighbours, disks, rings, distances.

Each level is a reflection tiling, so the cell across an edge is the mirror
image of the cell in that edge.  A neighbour is found by mirroring the cell's
planar centroid in the edge and locating the image, carried onto the
adjacent face when it falls off this one.  No lookup tables, any level.
"""

from __future__ import annotations

import numpy as np

from dggs.errors import DggsValueError, LevelMismatchError
from dggs.geometry.split26 import face_adjacency, locate, neighbour_points

from . import _geo
from . import _scalar
from .cellid import FACE_LETTERS, as_id_array, decode, encode

__all__ = ["edge_neighbors", "are_neighbor_cells", "grid_disk", "grid_ring", "grid_distance"]

_LETTERS = np.array(list(FACE_LETTERS))


# Edge labels of a 30-60-90 cell (A 30, B 60, C 90 degrees): a = BC, b = CA, c = AB.
_EA, _EB, _EC = 0, 1, 2
# Children (A', B', C'): 0 = (B, D, C), 1 = (B, D, E), 2 = (A, D, E).  For child
# digit c and its edge e: the sibling across it (same edge label on both
# sides), or -1 when the edge lies on the parent's edge _OUTER[c, e].
_SIBLING = np.array([[-1, -1, 1], [2, -1, 0], [1, -1, -1]], dtype=np.int8)
_OUTER = np.array([[_EB, _EA, -1], [-1, _EC, -1], [-1, _EC, _EB]], dtype=np.int8)
# One lookup per step: the sibling digit (0-2), or 3 + the parent's edge label.
_STEP = np.where(_SIBLING >= 0, _SIBLING, 3 + _OUTER).astype(np.int8)
# A cell's neighbour across an edge on its parent's edge is the same child of
# the parent's neighbour there: the neighbour is the mirror image, and mirror
# images carry the same labels (angles fix them).


def _geometric_neighbours(ids: np.ndarray) -> np.ndarray:
    """(N, 3) neighbours by mirroring centroids in each edge (reference method).

    Columns follow the counter-clockwise corners: edge from corner i to i+1.
    Used to build the level-1 table and to test :func:`_neighbours`.
    """
    geo = _geo.ORIENTATION.geometry
    sub = decode(ids)
    pts = _geo.corners(sub)  # (M, 3, 2)
    centre = pts.mean(axis=1)
    out = np.empty((len(ids), 3), dtype=ids.dtype)
    for levels in np.unique(sub.level):
        sel = np.flatnonzero(sub.level == levels)
        for i in range(3):
            p, q = pts[sel, i], pts[sel, (i + 1) % 3]
            d = q - p
            t = np.einsum("ij,ij->i", centre[sel] - p, d) / np.einsum("ij,ij->i", d, d)
            mirror = 2.0 * (p + t[:, None] * d) - centre[sel]
            face, moved = neighbour_points(sub.face[sel], mirror, geo.face_vertices)
            out[sel, i] = encode(face, locate(moved[:, 0], moved[:, 1], int(levels)))
    return out


def _column_labels(ccw: np.ndarray) -> np.ndarray:
    """Edge labels of the corner-order columns: (A, B, C) ccw -> c, a, b; (A, C, B) -> b, a, c."""
    return np.where(ccw[:, None], np.array([_EC, _EA, _EB]), np.array([_EB, _EA, _EC]))


_L1_CCW = None
_L1_TABLE = None


def _level1_tables():
    """Level-1 orientation (6,) and neighbour table (20, 6, 3) -> (face, digit), from geometry."""
    global _L1_CCW, _L1_TABLE
    if _L1_TABLE is None:
        from dggs.geometry.split26 import LEVEL1

        a, b, c = LEVEL1[:, 0], LEVEL1[:, 1], LEVEL1[:, 2]
        ccw = ((b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0])) > 0
        cells = np.array([f"{FACE_LETTERS[f]}{d}" for f in range(20) for d in range(6)])
        nb = _geometric_neighbours(cells).reshape(20, 6, 3)
        labels = _column_labels(np.tile(ccw, 20)).reshape(20, 6, 3)
        table = np.empty((20, 6, 3, 2), dtype=np.intp)
        for f in range(20):
            for d in range(6):
                for col in range(3):
                    other = str(nb[f, d, col])
                    table[f, d, labels[f, d, col]] = (FACE_LETTERS.index(other[0]), int(other[1]))
        _L1_CCW, _L1_TABLE = ccw, table
    return _L1_CCW, _L1_TABLE


def _neighbours_fine(dec) -> np.ndarray:
    """(N, 3) neighbour ids of cells at one level >= 1, from their digits alone."""
    l1_ccw, l1_table = _level1_tables()
    n, level = dec.face.shape[0], int(dec.level[0])
    digits = dec.digits[:, : level - 1]
    flips = np.count_nonzero((digits == 0) | (digits == 2), axis=1)
    ccw = l1_ccw[dec.l1] ^ (flips % 2 == 1)  # children 0 and 2 are mirror images
    codes = np.empty((n, 3, level), dtype=np.uint8)  # by edge label a, b, c
    faces = np.empty((n, 3), dtype=np.intp)
    for e in (_EA, _EB, _EC):
        new_digits = codes[:, e, 1:]  # walk in place
        new_digits[...] = digits
        face = dec.face.copy()
        l1 = dec.l1.copy()
        edge = np.full(n, e, dtype=np.int8)
        active = None  # None: every row (no gather on the first, widest step)
        for pos in range(level - 2, -1, -1):  # walk up from the last digit
            if active is None:
                step = _STEP[new_digits[:, pos], edge]
                done = step < 3
                new_digits[done, pos] = step[done]
                edge = np.where(done, edge, step - 3)
                active = np.flatnonzero(~done)
                continue
            if active.size == 0:
                break
            step = _STEP[new_digits[active, pos], edge[active]]
            done = step < 3
            new_digits[active[done], pos] = step[done]
            edge[active] = np.where(done, edge[active], step - 3)
            active = active[~done]
        if active is None:
            active = np.arange(n)
        if active.size:  # the edge lies on the level-1 triangle's edge
            nf_nd = l1_table[face[active], l1[active], edge[active]]
            face[active], l1[active] = nf_nd[:, 0], nf_nd[:, 1]
        codes[:, e, 0] = l1
        faces[:, e] = face
    # reorder label columns (a, b, c) into the counter-clockwise corner order
    flip = ~ccw
    codes[flip] = codes[flip][:, [1, 0, 2]]  # (A, C, B) corners: b, a, c
    codes[ccw] = codes[ccw][:, [2, 0, 1]]  # (A, B, C) corners: c, a, b
    faces[flip] = faces[flip][:, [1, 0, 2]]
    faces[ccw] = faces[ccw][:, [2, 0, 1]]
    return encode(faces.ravel(), codes.reshape(n * 3, level)).reshape(n, 3)


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
    if n and dec.level.min() == dec.level.max() and dec.level[0] > 0:
        return _neighbours_fine(dec)  # one level: no regrouping
    for lv in np.unique(dec.level):
        if lv == 0:
            continue
        sel = np.flatnonzero(dec.level == lv)
        sub = type(dec)(dec.face[sel], dec.level[sel], dec.l1[sel], dec.digits[sel])
        out[sel] = _neighbours_fine(sub)
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
    if isinstance(cell, str) and _scalar.is_valid(cell):
        return np.array(_scalar.neighbours(cell))
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


def _disks(ids: np.ndarray, k: int) -> np.ndarray:
    """(N, M) disks of many cells at once, each row sorted, padded with ''.

    Breadth-first over (origin, cell) pairs, all origins together: each ring
    is the neighbours of the last one, less the pairs already seen.
    """
    n = len(ids)
    if k == 0:
        decode(ids)  # validate
    if k == 1:  # the 3 neighbours are distinct and differ from the cell
        return np.sort(np.concatenate([ids[:, None], _neighbours(ids)], axis=1), axis=1)
    origins = [np.arange(n)]
    cells = [ids]
    front_o, front_c = origins[0], ids
    for _ in range(k):
        o = np.repeat(front_o, 3)
        c = _neighbours(front_c).ravel()
        seen_o, seen_c = np.concatenate(origins), np.concatenate(cells)
        all_o = np.concatenate([seen_o, o])
        all_c = np.concatenate([seen_c, c])
        fresh = np.concatenate([np.zeros(seen_o.size, bool), np.ones(o.size, bool)])
        order = np.lexsort((fresh, all_c, all_o))  # by origin, cell; seen pairs (False) first
        all_o, all_c, fresh = all_o[order], all_c[order], fresh[order]
        first = np.ones(all_o.size, bool)
        first[1:] = (all_o[1:] != all_o[:-1]) | (all_c[1:] != all_c[:-1])
        keep = first & fresh
        front_o, front_c = all_o[keep], all_c[keep]
        origins.append(front_o)
        cells.append(front_c)
    all_o, all_c = np.concatenate(origins), np.concatenate(cells)
    order = np.lexsort((all_c, all_o))
    all_o, all_c = all_o[order], all_c[order]
    counts = np.bincount(all_o, minlength=n)
    out = np.full((n, int(counts.max()) if n else 0), "", dtype=ids.dtype)
    starts = np.cumsum(counts) - counts
    out[all_o, np.arange(all_o.size) - np.repeat(starts, counts)] = all_c
    return out


def grid_disk(cell, k: int = 1) -> np.ndarray:
    """All cells within ``k`` edge steps of ``cell`` (including it), sorted.

    For one cell, a 1-d ``U`` array.  For an array of N cells, an (N, M)
    array whose row i is the disk of cell i, sorted and padded with ``""``
    (disks near icosahedron vertices are a little smaller), computed for
    all cells at once.

    Examples
    --------
    >>> len(grid_disk("C401", 1)), len(grid_disk("C401", 2))
    (4, 9)
    >>> grid_disk(["C401", "C402"], 1).shape
    (2, 4)
    """
    k = _check_k(k)
    if isinstance(cell, str) and _scalar.is_valid(cell):
        return np.array(_scalar.disk(cell, k))
    ids, scalar = as_id_array(cell)
    out = _disks(ids, k)  # validates the ids
    if scalar:
        row = out[0]
        return row[row != ""]
    return out


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
