"""Tables of the grid graph (:mod:`dggs.index._kernel.grid`), built at import from the geometry; compiled C helpers.

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

The C core holds the same arrays as static data (libdggs/src/grid_tables.h,
written from this module by libdggs/tools/gen_grid_tables.py, floats as hex
literals); :func:`chart_distance`, :func:`disk_size_bound` and
:func:`ring_size_bound` are compiled C, libdggs/src/grid_tables.c.

Edge labels of a 30-60-90 cell with corners A (30°), B (60°), C (90°):
``a = BC`` (0), ``b = CA`` (1), ``c = AB`` (2): each label names the corner
the edge does not touch.
"""

from __future__ import annotations

import numpy as np

from dggs._core import chart_distance, disk_size_bound, ring_size_bound  # compiled C, libdggs/src/grid_tables.c
from dggs.geometry import split26
from dggs.geometry.constants import FACE_EDGE, FACE_INRADIUS
from dggs.geometry.icosahedron import ISEA

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


__all__ = ["BASE_ADJ", "BLOCK", "CHART_OFF", "CHART_ROT", "CHILD_FLIP", "COLUMN_LABEL", "FACE_ADJ", "FACE_BACK",
           "FACE_DISTANCE", "L1_CCW", "L1_TABLE", "LEVEL1_CORNERS", "LINE_NORMALS", "STEP", "chart_distance",
           "disk_size_bound", "line_spacings", "ring_size_bound"]
