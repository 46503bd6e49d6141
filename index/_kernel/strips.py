"""Compiled grid distances at any range: the fewest mirror lines over the face strips a straight path can take.

Unfold a chain of icosahedron faces ``f0 = face(a), f1, ..., fm = face(b)``
(each across an edge of the one before) into ``a``'s face frame.  Every face of
a level carries the same kisrhombille arrangement, and a face edge is one of
its mirror lines, so the unfolded chain lies in one planar arrangement: the
level's six families of parallel lines extended over the plane
(:func:`dggs.index._kernel.grid_tables._separating_lines`).  If the straight
segment from ``a``'s centroid to the unfolded centroid of ``b`` runs through
exactly those faces (it crosses each shared edge, in order, away from its
ends), the cells it passes through form a path on the sphere that crosses
each separating line once: its length is the number of lines separating the
two centroids.  So each such strip gives the length of a real path, and the
least of them is an upper bound of the distance that is never below it.

That the least is the distance (no shortest path must bend round an
icosahedron vertex, as with lengths on a convex polyhedron) is checked against
breadth-first search over the whole level: every pair at levels 1 to 3, random
sources at levels 4 to 6 and the cells at every vertex at level 6
(tests/index/kernel/test_strip_distance.py).  The chains searched are the
simple ones crossing at most :data:`MAX_STRIP` face edges: 5 miss the optimum
for 0.4 % of the level-3 pairs, 6 never did, and 8 never beat 6 over 600,000
pairs at levels 9, 17 and 28, half of them nearly antipodal.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from dggs.geometry import split26

from .grid_tables import _CHART_OFF, _CHART_ROT, _FACE_ADJ, _FACE_BACK, _centroid, _separating_lines

__all__ = ["MAX_STRIP", "strip_distance"]

#: Most face edges a searched strip crosses.
MAX_STRIP = 6
_FV = np.ascontiguousarray(split26.FACE_VERTICES, dtype=np.float64)  # face corners in a face's own frame
_EPS = 1e-9  # of an edge's length: a crossing this close to an icosahedron vertex does not count


@njit(cache=True, nogil=True)
def _straight(px: float, py: float, bx: float, by: float, edges: np.ndarray, m: int) -> bool:
    """Whether the segment p -> b crosses edges 1..m (rows of ``edges``: x0, y0, x1, y1) in order, inside each."""
    dx, dy = bx - px, by - py
    last = 0.0
    for i in range(1, m + 1):
        x0, y0, x1, y1 = edges[i, 0], edges[i, 1], edges[i, 2], edges[i, 3]
        ex, ey = x1 - x0, y1 - y0
        den = dx * ey - dy * ex
        if den == 0.0:
            return False
        wx, wy = x0 - px, y0 - py
        t = (wx * ey - wy * ex) / den  # along the segment
        u = (wx * dy - wy * dx) / den  # along the edge
        if not (last < t < 1.0) or not (_EPS < u < 1.0 - _EPS):
            return False
        last = t
    return True


@njit(cache=True, nogil=True)
def strip_distance(a: np.uint64, b: np.uint64, level: int) -> int:
    """The fewest separating lines over the straight face strips from ``a`` to ``b`` (level >= 1), or -1 if none.

    See the module doc: each strip counted is a real path of that length.
    """
    fa = np.int64((a >> np.uint64(57)) & np.uint64(31))
    fb = np.int64((b >> np.uint64(57)) & np.uint64(31))
    px, py = _centroid(a, level)
    qx, qy = _centroid(b, level)
    best = -1
    if fa == fb:
        best = _separating_lines(px, py, qx, qy, level)  # the face itself: convex, always straight
    top = MAX_STRIP + 1
    faces = np.empty(top, dtype=np.int64)
    tried = np.zeros(top, dtype=np.int64)  # edges of faces[i] tried so far
    rot = np.empty((top, 2, 2))  # faces[i]'s frame -> a's frame
    off = np.empty((top, 2))
    edges = np.empty((top, 4))  # edges[i]: the edge between faces[i - 1] and faces[i], in a's frame
    faces[0] = fa
    rot[0, 0, 0], rot[0, 0, 1], rot[0, 1, 0], rot[0, 1, 1] = 1.0, 0.0, 0.0, 1.0
    off[0, 0], off[0, 1] = 0.0, 0.0
    depth = 0
    while depth >= 0:
        if tried[depth] == 3 or depth == MAX_STRIP:
            tried[depth] = 0
            depth -= 1
            continue
        j = tried[depth]
        tried[depth] += 1
        f = faces[depth]
        g = _FACE_ADJ[f, j]
        seen = False
        for i in range(depth + 1):
            seen = seen or faces[i] == g
        if seen:
            continue
        r, o = rot[depth], off[depth]
        v0, v1 = _FV[j], _FV[(j + 1) % 3]
        n = depth + 1
        edges[n, 0] = r[0, 0] * v0[0] + r[0, 1] * v0[1] + o[0]
        edges[n, 1] = r[1, 0] * v0[0] + r[1, 1] * v0[1] + o[1]
        edges[n, 2] = r[0, 0] * v1[0] + r[0, 1] * v1[1] + o[0]
        edges[n, 3] = r[1, 0] * v1[0] + r[1, 1] * v1[1] + o[1]
        back = _FACE_BACK[f, j]
        cr, co = _CHART_ROT[g, back], _CHART_OFF[g, back]  # g's frame -> f's frame
        for x in range(2):
            for y in range(2):
                rot[n, x, y] = r[x, 0] * cr[0, y] + r[x, 1] * cr[1, y]
            off[n, x] = r[x, 0] * co[0] + r[x, 1] * co[1] + o[x]
        if g == fb:  # a strip ends here: the path never leaves b's face again
            bx = rot[n, 0, 0] * qx + rot[n, 0, 1] * qy + off[n, 0]
            by = rot[n, 1, 0] * qx + rot[n, 1, 1] * qy + off[n, 1]
            if _straight(px, py, bx, by, edges, n):
                d = _separating_lines(px, py, bx, by, level)
                if best < 0 or d < best:
                    best = d
            continue
        faces[n] = g
        tried[n] = 0
        depth = n
    return best
