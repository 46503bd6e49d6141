"""Tables for the compiled grid graph (:mod:`dggs.index._kernel.grid`), built once at import from the geometry.

Also the largest disks and rings (:func:`disk_size_bound`,
:func:`ring_size_bound`) and the planar charts that give exact distances
(:func:`chart_distance`).

Everything here is derived from :mod:`dggs.geometry.split26` and the ISEA
icosahedron (:data:`dggs.geometry.icosahedron.ISEA`), never typed in:

* :data:`STEP` (3, 3): one step of the digit walk (docs/grid.md, "Neighbours";
  thesis §6.1.7).  For child digit ``c`` and its edge label ``e`` it holds the
  sibling across that edge (0..2; the sibling's edge has the same label), or
  ``3 + L`` when the edge lies on the parent's edge of label ``L``.
* :data:`BLOCK` (3, 64): three steps of that walk at once (three digit fields).
* :data:`CHILD_FLIP` (3,): whether child ``c`` is a mirror image of its parent
  (children 0 and 2 are, so a cell's orientation is its level-1 triangle's XOR
  the parity of its later digits equal to 0 or 2).
* :data:`L1_CCW` (6,): whether level-1 triangle ``d``'s corners A, B, C run
  counter-clockwise.
* :data:`L1_TABLE` (20, 6, 3, 2): the (face, level-1 digit) across edge label
  ``e`` of level-1 triangle ``d`` on face ``f``, by the mirror construction
  (mirror the centroid in the edge, carry it across the face edge with
  ``neighbour_points``, take its level-1 digit).
* :data:`BASE_ADJ` (20, 3): the face across each edge of a level-0 cell, in
  corner order (the corners run counter-clockwise: face vertices 2, 1, 0).
* :data:`COLUMN_LABEL` (2, 3): the edge label of output column ``i`` (the
  edge from corner ``i`` to ``i + 1``) for clockwise (row 0) and
  counter-clockwise (row 1) cells.
* Planar charts for exact distances: :data:`FACE_ADJ`, :data:`FACE_BACK`,
  :data:`CHART_ROT`, :data:`CHART_OFF` (the rigid motion taking face ``g``'s
  frame into the frame of the face across its edge ``k``), and the six line
  families of the Split (2:6) arrangement (:data:`LINE_NORMALS`,
  :func:`line_spacings`).

Numba freezes these arrays into the cached machine code: they depend on the
geometry only, which this module's source pins.

Edge labels of a 30-60-90 cell with corners A (30°), B (60°), C (90°):
``a = BC`` (0), ``b = CA`` (1), ``c = AB`` (2): each label names the corner
the edge does not touch.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from dggs.geometry import split26
from dggs.geometry.constants import FACE_EDGE, FACE_INRADIUS
from dggs.geometry.icosahedron import ISEA

from .bits import MAX_LEVEL

EA, EB, EC = 0, 1, 2
#: The two corners (indices into A, B, C) of each edge label.
_EDGE_CORNERS = ((1, 2), (2, 0), (0, 1))


def _ccw(a: np.ndarray, b: np.ndarray, c: np.ndarray) -> np.ndarray:
    """Whether triangles (..., 2) a, b, c run counter-clockwise."""
    return ((b[..., 0] - a[..., 0]) * (c[..., 1] - a[..., 1]) - (b[..., 1] - a[..., 1]) * (c[..., 0] - a[..., 0])) > 0


def _mirror(p: np.ndarray, q: np.ndarray, x: np.ndarray) -> np.ndarray:
    """Mirror images (N, 2) of points ``x`` in the lines through ``p`` and ``q``."""
    d = q - p
    t = np.einsum("ij,ij->i", x - p, d) / np.einsum("ij,ij->i", d, d)
    return 2.0 * (p + t[:, None] * d) - x


def _on_segment(p: np.ndarray, a: np.ndarray, b: np.ndarray, tol: float = 1e-12) -> bool:
    d = b - a
    t = float(np.dot(p - a, d) / np.dot(d, d))
    return -tol <= t <= 1 + tol and float(np.linalg.norm(a + t * d - p)) < tol


def _child_tables() -> tuple[np.ndarray, np.ndarray]:
    """STEP (3, 3) and CHILD_FLIP (3,) from the children of level-1 triangle 0."""
    parent = split26.LEVEL1[0]
    kids = np.stack(split26.cell_vertices(np.zeros(3, np.intp), np.arange(3)[:, None]), axis=1)  # (3, 3, 2)
    step = np.full((3, 3), -1, dtype=np.int8)
    for c in range(3):
        for e in range(3):
            ends = kids[c, list(_EDGE_CORNERS[e])]
            for s in range(3):  # a sibling holding both ends shares the edge
                if s == c:
                    continue
                hit = [int(np.argmin(np.linalg.norm(kids[s] - p, axis=1))) for p in ends]
                if all(np.allclose(kids[s, h], p, atol=1e-12) for h, p in zip(hit, ends, strict=True)):
                    label = 3 - sum(hit)  # the corner the shared edge misses names its label
                    assert label == e, "a sibling's shared edge keeps its label"
                    step[c, e] = s
            if step[c, e] < 0:
                outer = [L for L in range(3) if all(_on_segment(p, *parent[list(_EDGE_CORNERS[L])]) for p in ends)]
                assert len(outer) == 1
                step[c, e] = 3 + outer[0]
    flip = _ccw(kids[:, 0], kids[:, 1], kids[:, 2]) != _ccw(parent[0], parent[1], parent[2])
    return step, flip


def _block_table(step: np.ndarray) -> np.ndarray:
    """BLOCK (3, 64): three levels of the digit walk in one lookup.

    Index: the entering edge label and the 6 bits of three consecutive digit
    fields (codes 1..3, the deepest in the low bits).  Value: ``64 + new bits``
    when a sibling shares the edge within the block (one field replaced), else
    the edge label on the block's parent (< 3).
    """
    out = np.full((3, 64), -1, dtype=np.int64)
    for e in range(3):
        for bits in range(64):
            codes = [(bits >> 4) & 3, (bits >> 2) & 3, bits & 3]  # shallow .. deep
            if 0 in codes:
                continue
            edge = e
            for pos in (2, 1, 0):
                st = int(step[codes[pos] - 1, edge])
                if st < 3:
                    codes[pos] = st + 1
                    out[e, bits] = 64 + (codes[0] << 4 | codes[1] << 2 | codes[2])
                    break
                edge = st - 3
            else:
                out[e, bits] = edge
    return out


def _face_charts(face_vertices: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """FACE_ADJ (20, 3), and the rigid motions (20, 3, 2, 2), (20, 3, 2) of each face frame into its neighbours'.

    Fitted through :func:`split26.neighbour_points` on three points just beyond each face edge.
    """
    adj = np.empty((20, 3), dtype=np.int64)
    rot = np.empty((20, 3, 2, 2))
    off = np.empty((20, 3, 2))
    fv = split26.FACE_VERTICES
    for f in range(20):
        for k in range(3):
            p, q = fv[k], fv[(k + 1) % 3]
            mid, along = 0.5 * (p + q), (q - p) / np.linalg.norm(q - p)
            pts = mid + np.array([[0.01], [0.05], [0.02]]) * split26.EDGE_NORMALS[k] + np.array([[0.0], [0.1], [-0.1]]) * along
            faces, moved = split26.neighbour_points(np.full(3, f), pts, face_vertices)
            assert (faces == faces[0]).all() and faces[0] != f
            sol = np.linalg.solve(np.c_[pts, np.ones(3)], moved)  # rows: x, y, 1 -> x', y'
            rot[f, k], off[f, k], adj[f, k] = sol[:2].T, sol[2], faces[0]
            assert np.allclose(rot[f, k] @ rot[f, k].T, np.eye(2), atol=1e-9)
    return adj, rot, off


def _level1_table(face_vertices: np.ndarray) -> np.ndarray:
    """(20, 6, 3, 2): (face, level-1 digit) across each edge label, by mirroring centroids."""
    tri = split26.LEVEL1
    centre = tri.mean(axis=1)
    table = np.empty((20, 6, 3, 2), dtype=np.int64)
    for e, (i, j) in enumerate(_EDGE_CORNERS):
        img = _mirror(tri[:, i], tri[:, j], centre)  # (6, 2)
        for f in range(20):
            faces, pts = split26.neighbour_points(np.full(6, f), img, face_vertices)
            table[f, :, e, 0] = faces
            table[f, :, e, 1] = split26.level1_digit(pts[:, 0], pts[:, 1])
    return table


def _base_adjacency(adj: np.ndarray) -> np.ndarray:
    """Faces across the edges of level-0 cells in corner order (corners: face vertices 2, 1, 0)."""
    fv = split26.FACE_VERTICES
    corners = (2, 1, 0)
    assert _ccw(*(fv[c] for c in corners))
    cols = []
    for i in range(3):
        pair = {corners[i], corners[(i + 1) % 3]}
        cols.append(next(k for k in range(3) if {k, (k + 1) % 3} == pair))  # face edge k: vertex k to k + 1
    return np.ascontiguousarray(adj[:, cols])


def _column_labels() -> np.ndarray:
    """Edge label of corner-order column i: corners (A, C, B) when clockwise, (A, B, C) when counter-clockwise."""
    out = np.empty((2, 3), dtype=np.int64)
    for ccw, corners in ((0, (0, 2, 1)), (1, (0, 1, 2))):
        for i in range(3):
            out[ccw, i] = 3 - corners[i] - corners[(i + 1) % 3]  # the corner the edge misses
    return out


def _line_families() -> np.ndarray:
    """(6, 2) unit normals: the face-edge direction families (0..2), then the median families (3..5).

    Level ``l`` is the kisrhombille of a triangular lattice (docs/grid.md), the
    arrangement of six families of parallel lines: three along the face edges
    (the face edges among them) and three along the medians (through the face
    centre).  Spacings: :func:`line_spacings`.
    """
    out = np.empty((6, 2))
    out[:3] = split26.EDGE_NORMALS
    for k in range(3):  # perpendicular to the median through vertex k
        v = split26.FACE_VERTICES[k] / np.linalg.norm(split26.FACE_VERTICES[k])
        out[3 + k] = (v[1], -v[0])
    return out


def line_spacings(max_level: int) -> np.ndarray:
    """(max_level + 1, 2): spacing of the edge-parallel and median-parallel lines per level.

    The lattice shrinks by sqrt 3 and turns 30° per level, so the two sets of
    families swap roles and each gets 3 times denser every second level: edge
    families ``3 r / 3**(l // 2)``, median families ``(E / 2) / 3**((l - 1) // 2)``
    (``r`` the face inradius, ``E`` its edge).  Level 0 uses the face edges only.
    """
    out = np.empty((max_level + 1, 2))
    out[0] = (3 * FACE_INRADIUS, np.inf)
    for lv in range(1, max_level + 1):
        out[lv] = (3 * FACE_INRADIUS / 3 ** (lv // 2), 0.5 * FACE_EDGE / 3 ** ((lv - 1) // 2))
    return out


_FV = ISEA.geometry.face_vertices
STEP, CHILD_FLIP = _child_tables()
BLOCK = _block_table(STEP)
L1_CCW = _ccw(split26.LEVEL1[:, 0], split26.LEVEL1[:, 1], split26.LEVEL1[:, 2])
L1_TABLE = _level1_table(_FV)
FACE_ADJ, CHART_ROT, CHART_OFF = _face_charts(_FV)
BASE_ADJ = _base_adjacency(FACE_ADJ)
COLUMN_LABEL = _column_labels()
LINE_NORMALS = _line_families()
LEVEL1_CORNERS = np.ascontiguousarray(split26.LEVEL1)
#: Index of the face across edge k of face g that is g itself seen from there: FACE_BACK[g, k] = k' with FACE_ADJ[FACE_ADJ[g, k], k'] == g.
FACE_BACK = np.array([[list(FACE_ADJ[FACE_ADJ[g, k]]).index(g) for k in range(3)] for g in range(20)], dtype=np.int64)


def _face_distances(adj: np.ndarray) -> np.ndarray:
    """(20, 20) steps between faces across their edges: the level-0 grid distance (breadth-first search)."""
    out = np.full((20, 20), -1, dtype=np.int64)
    for source in range(20):
        out[source, source] = 0
        front = [source]
        while front:
            nxt = []
            for f in front:
                for g in adj[f]:
                    if out[source, g] < 0:
                        out[source, g] = out[source, f] + 1
                        nxt.append(int(g))
            front = nxt
    return out


#: Steps between the 20 faces (level-0 cells): the dodecahedron graph's distances, 0..5.
FACE_DISTANCE = _face_distances(FACE_ADJ)
for _arr in (STEP, BLOCK, CHILD_FLIP, L1_CCW, L1_TABLE, FACE_ADJ, CHART_ROT, CHART_OFF, BASE_ADJ, COLUMN_LABEL, LINE_NORMALS, FACE_BACK,
             FACE_DISTANCE):
    _arr.setflags(write=False)


# ---------------------------------------------------------------------------
# Disk and ring sizes
# ---------------------------------------------------------------------------
@njit(cache=True, nogil=True)
def ring_size_bound(k: int) -> int:
    """Most cells exactly ``k`` steps from a cell, at any level.

    Away from the icosahedron vertices every level is the truncated
    trihexagonal (4.6.12) graph, whose rings hold 1, 3, 5, 7, 9, 12, 15, ...
    cells: ``12 m + (0, 3, 5, 7, 9)[r]`` for ``k = 5 m + r >= 1`` (period 5, so
    ``2.4 k`` on average, not ``2 k + 1`` past k = 4).  Around the 12 vertices
    (10 cells meet there, not 12) rings are no larger; only level 0 (the
    dodecahedron graph: 1, 3, 6, 6, 3, 1) exceeds it, at k = 2.  Checked for
    every cell and every k at levels 0-8.
    """
    if k == 0:
        return 1
    if k == 2:
        return 6
    m, r = divmod(k, 5)
    return 12 * m + (0, 3, 5, 7, 9)[r]


@njit(cache=True, nogil=True)
def disk_size_bound(k: int) -> int:
    """Most cells within ``k`` steps of a cell, at any level: 1, 4, 10, 16, 25, 37, 52, ...

    The planar 4.6.12 disk is ``1 + 30 m**2 + 6 m + 12 m r + (0, 3, 8, 15, 24)[r]``
    for ``k = 5 m + r``: ``(k + 1)**2`` up to k = 4, then larger (37 > 36 at k = 5,
    about ``1.2 k**2``).  Level 0 has 10 cells within 2 steps (planar: 9).
    Checked for every cell and every k at levels 0-8.
    """
    if k == 2:
        return 10
    m, r = divmod(k, 5)
    return 1 + 30 * m * m + 6 * m + 12 * m * r + (0, 3, 8, 15, 24)[r]


# ---------------------------------------------------------------------------
# Planar charts (compiled): exact distances where the plane proves them
# ---------------------------------------------------------------------------
_FACE_ADJ = FACE_ADJ.astype(np.int64)
_FACE_BACK = FACE_BACK.astype(np.int64)
_CHART_ROT = CHART_ROT.copy()
_CHART_OFF = CHART_OFF.copy()
_LINE_NORMALS = LINE_NORMALS.copy()
_SPACING = line_spacings(MAX_LEVEL)
_L1_CORNERS = LEVEL1_CORNERS.copy()
_R = float(FACE_INRADIUS)
_U3 = np.uint64(3)


@njit(cache=True, nogil=True)
def _centroid(cell: np.uint64, level: int) -> tuple[float, float]:
    """Planar centroid of a cell at level >= 1 in its face frame (D and E per level, thesis §6.1.7)."""
    d1 = np.int64((cell >> np.uint64(54)) & np.uint64(7)) - 1
    ax, ay = _L1_CORNERS[d1, 0, 0], _L1_CORNERS[d1, 0, 1]
    bx, by = _L1_CORNERS[d1, 1, 0], _L1_CORNERS[d1, 1, 1]
    cx, cy = _L1_CORNERS[d1, 2, 0], _L1_CORNERS[d1, 2, 1]
    for lv in range(2, level + 1):
        dig = np.int64((cell >> np.uint64(2 * (MAX_LEVEL - lv))) & _U3) - 1
        dx, dy = cx + (ax - cx) / 3.0, cy + (ay - cy) / 3.0  # D: a third of the way from C to A
        ex, ey = 0.5 * (ax + bx), 0.5 * (ay + by)  # E: the midpoint of AB
        if dig == 0:  # BCD
            ax, ay, bx, by = bx, by, dx, dy
        elif dig == 1:  # BDE
            ax, ay, bx, by, cx, cy = bx, by, dx, dy, ex, ey
        else:  # ADE
            bx, by, cx, cy = dx, dy, ex, ey
    return (ax + bx + cx) / 3.0, (ay + by + cy) / 3.0


@njit(cache=True, nogil=True)
def _separating_lines(px: float, py: float, qx: float, qy: float, level: int) -> int:
    """Lines of the level's planar arrangement between two cell centroids (face-frame chart)."""
    total = 0
    for f in range(6):
        nx, ny = _LINE_NORMALS[f, 0], _LINE_NORMALS[f, 1]
        if f < 3:  # edge families: the face edge r - <p, n> = 0 is a line
            h = _SPACING[level, 0]
            tp, tq = (_R - (px * nx + py * ny)) / h, (_R - (qx * nx + qy * ny)) / h
        else:  # median families: through the face centre
            h = _SPACING[level, 1]
            tp, tq = (px * nx + py * ny) / h, (qx * nx + qy * ny) / h
        total += int(abs(np.int64(math.floor(tp)) - np.int64(math.floor(tq))))
    return total


@njit(cache=True, nogil=True)
def chart_distance(a: np.uint64, b: np.uint64, level: int) -> int:
    """Exact distance from the planar arrangement if ``a``'s chart proves it, else -1.

    The chart is ``a``'s face with its 3 neighbours unfolded: a triangle of
    twice the size whose corners and edge midpoints are the only icosahedron
    vertices it touches.  In the plane the cells are the alcoves of the affine
    reflection group G2~ (the kisrhombille), and the distance between two
    alcoves is the number of mirror lines separating them.  If every cell
    within that many steps of ``a`` lies inside the chart (a disk of radius
    ``rho`` around the centroid), every path from ``a`` shorter than it stays
    in the chart, where the count is a lower bound, and a planar shortest path
    realises it: the count is the distance on the sphere.
    """
    fa = np.int64((a >> np.uint64(57)) & np.uint64(31))
    fb = np.int64((b >> np.uint64(57)) & np.uint64(31))
    px, py = _centroid(a, level)
    qx, qy = _centroid(b, level)
    if fb != fa:
        k = -1
        for j in range(3):
            if _FACE_ADJ[fa, j] == fb:
                k = _FACE_BACK[fa, j]  # b's face edge that borders a's face
        if k < 0:
            return -1
        rot = _CHART_ROT[fb, k]
        off = _CHART_OFF[fb, k]
        qx, qy = rot[0, 0] * qx + rot[0, 1] * qy + off[0], rot[1, 0] * qx + rot[1, 1] * qy + off[1]
    d = _separating_lines(px, py, qx, qy, level)
    short = _R / math.sqrt(3.0) ** (level - 1)  # edge BC of a cell at this level
    # centroids move at most 2/sqrt3 BC per step; a corner is sqrt13/3 BC from the centroid
    rho = (d * 2.0 / math.sqrt(3.0) + math.sqrt(13.0) / 3.0) * short * (1.0 + 1e-9) + 1e-12
    for j in range(3):  # the chart: <p, n_j> >= -2 r
        if px * _LINE_NORMALS[j, 0] + py * _LINE_NORMALS[j, 1] + 2.0 * _R <= rho:
            return -1
    return d
