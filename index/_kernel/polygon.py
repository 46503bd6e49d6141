"""Point- and circle-against-polygon tests for polygon fill: a uniform bucket grid over the polygon's edges.

Compiled C, libdggs/src/polygon.c (through ``dggs._core``).

:func:`build` sorts a polygon's edges (segments in one plane, lng/lat for
polygon fill) into the buckets of a uniform grid over their bounding box,
and records for each bucket the nearest bucket right of it that no edge
meets, and that one's side.
:func:`near` says whether some edge lies within ``r`` of a point (the
point-to-segment distance over the buckets the circle's box overlaps), in a
plane whose x axis may be scaled first (an ellipse is then a circle).
:func:`parity` locates a point by the crossing number of the ray to +x (over
the buckets of the point's row up to such an empty one, each edge counted
once), with the sign of every crossing decided by an orientation whose
rounding error is bounded: a point within that error of an edge is reported
as undecided (-1), never guessed.
So an answer of 1 (inside) or 0 (outside) is the exact one, the same as an
exact point-in-polygon test (GEOS's) gives; only points on or within about
1e-16 of an edge are left to one.  :func:`classify` combines the two for
circles (``hit``: meets the polygon; ``inside``: lies wholly in it), called
as ``classify(n, px, py, r, x0, y0, x1, y1, frame, start, items, empty, hit, inside)``.
"""

from __future__ import annotations

from dggs._core import polygon_build as build
from dggs._core import polygon_classify as classify
from dggs._core import polygon_near as near
from dggs._core import polygon_parity as parity
from dggs._core import polygon_ring_edges as ring_edges

__all__ = ["ring_edges", "build", "near", "parity", "classify", "ORIENT_ERR"]

#: Relative error bound of a 2x2 orientation determinant in doubles: Shewchuk 1997 ("Adaptive precision
#: floating-point arithmetic and fast robust geometric predicates"), ccwerrboundA = (3 + 16 eps) eps with
#: eps = 2**-53 is 3.3e-16; three times that for margin (DGGS_ORIENT_ERR in polygon.h).
ORIENT_ERR = 1e-15
