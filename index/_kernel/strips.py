"""Grid distances at any range (compiled C, libdggs/src/strips.c): the fewest mirror lines over the face strips.

Unfold a chain of icosahedron faces ``f0 = face(a), f1, ..., fm = face(b)``
(each across an edge of the one before) into ``a``'s face frame.  Every face of
a level carries the same kisrhombille arrangement, and a face edge is one of
its mirror lines, so the unfolded chain lies in one planar arrangement: the
level's six families of parallel lines extended over the plane.  If the straight
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

from dggs._core import MAX_STRIP, strip_distance

__all__ = ["MAX_STRIP", "strip_distance"]
