"""The Split (2:6) hierarchy on a face plane (thesis §6.1.7).

Level 1 splits each face into 6 congruent 30-60-90 triangles (vertex, centre,
edge midpoint); every later level splits each 30-60-90 triangle
``A (30 deg), B (60 deg), C (90 deg)`` into 3 congruent similar ones by
bisecting the 60-degree angle at B (the bisector meets AC at D, a third of
the way from C to A) and halving the remaining 30-30-120 triangle ABD at E,
the midpoint of AB.  The children, in digit order, are::

    0: BCD  (A', B', C') = (B, D, C)
    1: BDE  (A', B', C') = (B, D, E)
    2: ADE  (A', B', C') = (A, D, E)

Consecutive children share an edge.  Every level is the kisrhombille tiling
of a triangular lattice (scaled by 1/sqrt(3) and turned 30 degrees per
level), a reflection tiling: the neighbour across any cell edge is the
cell's mirror image in that edge, across face edges too once the adjacent
face is unfolded into the plane.

All coordinates are in the face frame of :mod:`dggs.geometry.snyder` (unit sphere).
Level-1 digits ``d = 0..5`` number the six triangles clockwise from the face's
reference vertex: triangle ``d`` spans planar azimuths ``60 d .. 60 (d + 1)``
degrees.

The compiled point location (:func:`dggs.geometry.kernel.level1_start`,
``descend``, ``descend4``) reads its tables from here: :data:`CHILD_M`,
:data:`CHILD_T`, :data:`L1_ROWS`, :data:`L1_C` and :func:`jump_table`.

Examples
--------
>>> import numpy as np
>>> a, b, c = cell_vertices(np.zeros(3, dtype=np.intp), np.array([[0], [1], [2]]))
>>> A, B, C = LEVEL1[0]
>>> bool(np.allclose(b, C + (A - C) / 3))  # every child's B' is D, a third of the way from C to A
True
"""

from __future__ import annotations

import math
from functools import lru_cache

import numpy as np

from dggs.geometry.constants import FACE_CIRCUMRADIUS, FACE_INRADIUS, SQRT3

__all__ = [
    "FACE_VERTICES",
    "LEVEL1",
    "level1_triangles",
    "level1_digit",
    "cell_vertices",
    "neighbour_points",
    "EDGE_NORMALS",
    "CHILD_COUNT",
    "CHILD_M",
    "CHILD_T",
    "L1_ROWS",
    "L1_C",
    "jump_table",
    "JUMP_LEVELS",
    "GRID_W",
    "GRID_H",
    "AMBIGUOUS",
]
#: Planar face vertices: vertex k at azimuth 120 k degrees, clockwise from +y.
FACE_VERTICES = np.array(
    [
        [FACE_CIRCUMRADIUS * math.sin(a), FACE_CIRCUMRADIUS * math.cos(a)]
        for a in (0.0, 2 * math.pi / 3, 4 * math.pi / 3)
    ]
)
CHILD_COUNT = 3


def level1_triangles() -> np.ndarray:
    """The six level-1 triangles as a (6, 3, 2) array of (A, B, C) corners."""
    tris = np.empty((6, 3, 2))
    for d in range(6):
        k = d // 2
        vk, vn = FACE_VERTICES[k], FACE_VERTICES[(k + 1) % 3]
        tris[d, 0] = vk if d % 2 == 0 else vn  # A: the face vertex, 30 degrees
        tris[d, 1] = 0.0  # B: the face centre, 60 degrees
        tris[d, 2] = 0.5 * (vk + vn)  # C: the edge midpoint, 90 degrees
    return tris


LEVEL1 = level1_triangles()
LEVEL1.setflags(write=False)

# Canonical triangle: C = (0, 0), A = (sqrt3, 0), B = (0, 1).  The child
# corners D = (1/sqrt3, 0) and E = (sqrt3/2, 1/2).
_CANON = {
    "A": np.array([SQRT3, 0.0]),
    "B": np.array([0.0, 1.0]),
    "C": np.array([0.0, 0.0]),
    "D": np.array([1.0 / SQRT3, 0.0]),
    "E": np.array([SQRT3 / 2, 0.5]),
}
_CHILDREN = ("BDC", "BDE", "ADE")  # (A', B', C') of children 0, 1, 2


def _frame_rows(a: np.ndarray, b: np.ndarray, c: np.ndarray) -> np.ndarray:
    """Rows mapping a 30-60-90 triangle's C->A and C->B directions to +x and +y."""
    return np.stack([(a - c) / np.linalg.norm(a - c), (b - c) / np.linalg.norm(b - c)])


def _child_affines() -> tuple[np.ndarray, np.ndarray]:
    """Per child j, ``p' = M[j] @ p + t[j]``: parent canonical -> child canonical."""
    mats, offs = [], []
    for corners in _CHILDREN:
        a, b, c = (_CANON[k] for k in corners)
        m = SQRT3 * _frame_rows(a, b, c)
        mats.append(m)
        offs.append(-m @ c)
    return np.array(mats), np.array(offs)


CHILD_M, CHILD_T = _child_affines()
# Level-1 triangle d: canonical = (rows @ (p - C)) / inradius_of_cell
L1_ROWS = np.array([_frame_rows(*LEVEL1[d]) / FACE_INRADIUS for d in range(6)])
L1_C = LEVEL1[:, 2].copy()


def level1_digit(x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """Level-1 digit 0..5 of face-frame points (planar azimuth // 60 degrees).

    A point on a dividing ray goes to the triangle clockwise of it; the face
    centre goes to triangle 0.
    """
    az = np.arctan2(x, y)
    az = np.where(az < 0, az + 2 * math.pi, az)
    return np.minimum((az * (3 / math.pi)).astype(np.intp), 5)


def descend_rows(px: np.ndarray, py: np.ndarray, steps: int, rows: np.ndarray, row: int):
    """Exact per-level descent in the canonical frame: writes digit rows ``row..row+steps-1``.

    ``rows`` holds one row of digits per level (shape (levels, N)).  Child 0
    (BCD) lies on C's side of BD (``sqrt3 x + y < 1``); child 2 (ADE) on A's
    side of DE (``sqrt3 x - y > 1``); child 1 (BDE) between them, so it wins
    both of its internal edges.  Returns the point in the last child's
    canonical frame.
    """
    m00, m01, m10, m11 = CHILD_M[:, 0, 0], CHILD_M[:, 0, 1], CHILD_M[:, 1, 0], CHILD_M[:, 1, 1]
    t0, t1 = CHILD_T[:, 0], CHILD_T[:, 1]
    for r in range(row, row + steps):
        sx = SQRT3 * px
        c = np.where(sx + py < 1.0, 0, np.where(sx - py > 1.0, 2, 1)).astype(np.uint8)
        rows[r] = c
        px, py = m00[c] * px + m01[c] * py + t0[c], m10[c] * px + m11[c] * py + t1[c]
    return px, py


# Jump table: K levels in one step.  The canonical triangle's bounding box
# [0, sqrt3] x [0, 1] is cut into a W x H grid; a grid cell that lies wholly
# inside one level-K descendant (checked at its corners pushed outwards by
# _EPS: each descendant's region is convex) stores that descendant's code,
# the others store AMBIGUOUS and their points take the exact descent.
JUMP_LEVELS = 4
GRID_W, GRID_H = 1024, 592
_EPS = 1e-9
AMBIGUOUS = 255


@lru_cache(maxsize=1)
def jump_table():
    """The jump table: :data:`JUMP_LEVELS` levels of descent in one look-up (computed, ~0.5 s; cached).

    Returns
    -------
    table : ndarray of uint8, ((GRID_H + 2) * (GRID_W + 2),)
        Per grid cell (row-major, with a one-cell border), the base-3 code of
        the level-4 descendant that holds the whole grid cell, or
        :data:`AMBIGUOUS`.
    digit_rows : tuple of 4 ndarrays of uint8, (81,)
        The digits of each code, first level first.
    coef : tuple of 6 ndarrays, (81,)
        ``(a00, a01, a10, a11, b0, b1)`` of each code's composite map
        ``p -> A p + b`` from the canonical frame to the descendant's.
    """
    k = JUMP_LEVELS
    codes = np.indices((3,) * k).reshape(k, -1).T.astype(np.uint8)  # (81, K), base-3 order
    # composite affine maps p -> A p + t of each K-digit path
    mats = np.tile(np.eye(2), (len(codes), 1, 1))
    offs = np.zeros((len(codes), 2))
    for j in range(k):
        m, t = CHILD_M[codes[:, j]], CHILD_T[codes[:, j]]
        offs = np.einsum("nij,nj->ni", m, offs) + t
        mats = np.einsum("nij,njk->nik", m, mats)
    xs = np.arange(GRID_W + 1) * (SQRT3 / GRID_W)
    ys = np.arange(GRID_H + 1) * (1.0 / GRID_H)
    gx, gy = np.meshgrid(xs, ys)  # (H+1, W+1) grid nodes

    def node_codes(sx: float, sy: float) -> np.ndarray:
        px, py = (gx + sx * _EPS).ravel(), (gy + sy * _EPS).ravel()
        d = np.empty((k, px.size), dtype=np.uint8)
        descend_rows(px, py, k, d, 0)
        return (3 ** np.arange(k - 1, -1, -1) @ d.astype(np.intp)).reshape(gx.shape)

    ll, lr = node_codes(-1, -1)[:-1, :-1], node_codes(+1, -1)[:-1, 1:]
    ul, ur = node_codes(-1, +1)[1:, :-1], node_codes(+1, +1)[1:, 1:]
    same = (ll == lr) & (ll == ul) & (ll == ur)
    # a border of ambiguous cells catches points off the grid (after clipping)
    table = np.full((GRID_H + 2, GRID_W + 2), AMBIGUOUS, dtype=np.uint8)
    table[1:-1, 1:-1] = np.where(same, ll, AMBIGUOUS)
    digit_rows = tuple(np.ascontiguousarray(codes[:, j]) for j in range(k))
    coef = tuple(np.ascontiguousarray(v) for v in (mats[:, 0, 0], mats[:, 0, 1], mats[:, 1, 0], mats[:, 1, 1], offs[:, 0], offs[:, 1]))
    return table.ravel(), digit_rows, coef


@lru_cache(maxsize=1)
def _inverse_blocks():
    """Inverse (contracting) maps of 1- and K-digit paths: child frame -> parent frame.

    For digits d1..dk (parent to child), ``G = f_d1^-1 o ... o f_dk^-1`` as
    ``(A, b)`` with ``G(p) = A p + b``; index = digits read as a base-3 number.
    """
    inv_m = np.linalg.inv(CHILD_M)
    inv_t = -np.einsum("nij,nj->ni", inv_m, CHILD_T)
    out = {}
    for k in (1, JUMP_LEVELS):
        codes = np.indices((3,) * k).reshape(k, -1).T
        a = np.tile(np.eye(2), (len(codes), 1, 1))
        b = np.zeros((len(codes), 2))
        for j in range(k):  # G = G o g_dj
            g_m, g_t = inv_m[codes[:, j]], inv_t[codes[:, j]]
            b = np.einsum("nij,nj->ni", a, g_t) + b
            a = np.einsum("nij,njk->nik", a, g_m)
        out[k] = (a, b)
    return out


def _compose_contractions(digits: np.ndarray) -> tuple[np.ndarray, ...]:
    """``G = g_d1 o ... o g_dL`` for rows of equal depth: ``(a00, a01, a10, a11, b0, b1)``.

    Four digits at a time from the precomputed blocks, then one at a time.
    """
    n, depth = digits.shape
    blocks = _inverse_blocks()
    a00, a01, a10, a11 = np.ones(n), np.zeros(n), np.zeros(n), np.ones(n)
    b0, b1 = np.zeros(n), np.zeros(n)
    col = 0
    while col < depth:
        k = JUMP_LEVELS if depth - col >= JUMP_LEVELS else 1
        code = np.zeros(n, dtype=np.intp)
        for j in range(k):
            code = code * 3 + digits[:, col + j]
        m, t = blocks[k][0][code], blocks[k][1][code]
        # G = G o g: b += A t, A = A m
        b0, b1 = a00 * t[:, 0] + a01 * t[:, 1] + b0, a10 * t[:, 0] + a11 * t[:, 1] + b1
        a00, a01, a10, a11 = (
            a00 * m[:, 0, 0] + a01 * m[:, 1, 0],
            a00 * m[:, 0, 1] + a01 * m[:, 1, 1],
            a10 * m[:, 0, 0] + a11 * m[:, 1, 0],
            a10 * m[:, 0, 1] + a11 * m[:, 1, 1],
        )
        col += k
    return a00, a01, a10, a11, b0, b1


def cell_vertices(l1: np.ndarray, digits: np.ndarray, levels: np.ndarray | None = None):
    """Face-frame corners ``(A, B, C)`` of cells, each an (N, 2) array.

    Parameters
    ----------
    l1 : (N,) int array
        Level-1 digits 0..5.
    digits : (N, L) int array
        The later digits (0..2), one column per level from 2 on.
    levels : (N,) int array, optional
        Each cell's level, for rows of mixed depth (columns past a row's
        level are ignored).  Default: every row uses all columns.

    Notes
    -----
    The map from the cell's canonical frame back to its level-1 triangle's
    is composed four digits at a time from precomputed contractions, then the
    canonical corners (sqrt3, 0), (0, 1), (0, 0) are carried through it.
    """
    n = l1.shape[0]
    depth = np.full(n, digits.shape[1]) if levels is None else levels - 1
    coef = np.empty((6, n))
    for d in np.unique(depth):
        rows = np.flatnonzero(depth == d)
        coef[:, rows] = _compose_contractions(digits[rows, :d])
    a00, a01, a10, a11, b0, b1 = coef
    # canonical corners A = (sqrt3, 0), B = (0, 1), C = (0, 0) -> level-1 canonical frame
    ca = np.stack([a00 * SQRT3 + b0, a10 * SQRT3 + b1], axis=1)
    cb = np.stack([a01 + b0, a11 + b1], axis=1)
    cc = np.stack([b0, b1], axis=1)
    # level-1 canonical -> face frame: p = C_d + r * rows_d^T p_can
    rows_t = np.swapaxes(L1_ROWS[l1], 1, 2) * (FACE_INRADIUS**2)
    centre = L1_C[l1]
    return tuple(centre + np.einsum("nij,nj->ni", rows_t, v) for v in (ca, cb, cc))


def _face_edge_transforms(face_vertices: np.ndarray):
    """Unfolding maps across face edges, from the icosahedron's topology.

    For face ``f`` and its edge ``k`` (from vertex k to vertex k+1), returns
    the adjacent face ``g`` and the rigid motion ``p -> R @ p + t`` taking
    ``f``'s face frame to ``g``'s, fixed by the two shared vertices.
    """
    nf = face_vertices.shape[0]
    adjacent = np.empty((nf, 3), dtype=np.intp)
    rot = np.empty((nf, 3, 2, 2))
    off = np.empty((nf, 3, 2))
    for f in range(nf):
        for k in range(3):
            a, b = face_vertices[f, k], face_vertices[f, (k + 1) % 3]
            g = next(
                h for h in range(nf) if h != f and a in face_vertices[h] and b in face_vertices[h]
            )
            ia = int(np.flatnonzero(face_vertices[g] == a)[0])
            ib = int(np.flatnonzero(face_vertices[g] == b)[0])
            pa, pb = FACE_VERTICES[k], FACE_VERTICES[(k + 1) % 3]
            qa, qb = FACE_VERTICES[ia], FACE_VERTICES[ib]
            ang = math.atan2(*(qb - qa)[::-1]) - math.atan2(*(pb - pa)[::-1])
            r = np.array([[math.cos(ang), -math.sin(ang)], [math.sin(ang), math.cos(ang)]])
            adjacent[f, k], rot[f, k], off[f, k] = g, r, qa - r @ pa
    return adjacent, rot, off


#: Outward unit normals of the face edges: edge k (vertex k to k+1) faces azimuth 60 + 120 k.
EDGE_NORMALS = np.array(
    [[math.sin(a), math.cos(a)] for a in (math.pi / 3, math.pi, 5 * math.pi / 3)]
)


def neighbour_points(face: np.ndarray, pts: np.ndarray, face_vertices: np.ndarray):
    """Move face-frame points that fell off their face onto the adjacent face.

    ``pts`` (N, 2) are mirror images of cell centres; a point beyond face
    edge k is carried by the unfolding map to the face across that edge.
    Returns the new faces and points.
    """
    adjacent, rot, off = _transforms(face_vertices.astype(np.int64).tobytes(), face_vertices.shape)
    beyond = pts @ EDGE_NORMALS.T - FACE_INRADIUS  # (N, 3): > 0 outside edge k
    k = np.argmax(beyond, axis=1)
    out = beyond[np.arange(len(k)), k] > 0
    face = face.copy()
    pts = pts.copy()
    if out.any():
        f, kk, p = face[out], k[out], pts[out]
        r, t = rot[f, kk], off[f, kk]
        pts[out] = np.einsum("nij,nj->ni", r, p) + t
        face[out] = adjacent[f, kk]
    return face, pts


_TRANSFORM_CACHE: dict = {}


def _transforms(key: bytes, shape):
    if key not in _TRANSFORM_CACHE:
        _TRANSFORM_CACHE[key] = _face_edge_transforms(np.frombuffer(key, dtype=np.int64).reshape(shape))
    return _TRANSFORM_CACHE[key]
