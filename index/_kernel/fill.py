"""Polygon fill: the whole descent through the levels for one polygon, depth first, in id order.

Compiled C, libdggs/src/fill.c (through ``dggs._core``).

:func:`descend` walks the hierarchy from the 20 base cells, carrying each
cell's planar corners down (one :func:`dggs.geometry.kernel.child_corners`
a level).  A cell is classified by its footprint: every point of a level-l
cell lies within the arc :data:`RHO` [l] of its footprint centre (below),
which bounds its latitudes and longitudes by an ellipse round that centre in
the lng/lat plane.  The polygon's edges sit in the bucket grid of
:mod:`.polygon`: an ellipse that meets no edge lies wholly inside the polygon
(its centre inside) or wholly outside.  Cells wholly inside are emitted
whole, cells outside dropped, the others descended.  In ``"center"`` mode
every descendant at the target level of a cell ``direct`` levels above it
is tested by its centre, computed exactly as :func:`.points.centres` does,
with the exact crossing parity of :func:`.polygon.parity` (the few centres
within rounding of an edge are flagged for GEOS); in the other modes the
boundary cells at the target level are flagged for the caller's test of
their polygons.  Depth first, children in digit order: the output comes out
sorted.

The footprint bound.  A level-l cell is the image under Snyder's inverse of
a planar triangle that lies within ``d_l`` of its footprint centre (for a
base cell its centroid, for a finer one the middle of its hypotenuse).  The
inverse stretches no planar length by more than its largest scale factor,
1.1633 (Snyder 1992: the icosahedral projection's largest angular
deformation is 17.27 degrees; for an equal-area map the larger scale is
``sqrt((1 + s) / (1 - s))`` with ``s = sin(17.27 / 2)``), so the arc from
that centre to any point of the cell is at most ``rho_l = 1.17 d_l``
(tests/index/kernel/test_kfill.py measures 0.990 of it at worst).  Within
that cap the authalic latitude moves at most ``rho_l`` and the geodetic one
at most :data:`K_LAT` times that (WGS84's largest d(phi)/d(beta) is
1.00449); by the haversine formula, with ``c*`` the cosine of the cap's
largest latitude, ``sin^2(dbeta/2) + c*^2 sin^2(dlng/2) <= sin^2(rho/2)``,
and since ``sin(x/2)`` is concave this gives the ellipse of semi-axes
``K_LAT rho`` (latitude) and ``2 asin(sin(rho/2) / c*)`` (longitude).  A cap
holding a pole (``c* <= sin(rho/2)``) is bounded by its latitudes only, and
never wholly inside.
"""

from __future__ import annotations

from dggs._core import fill_centre as centre
from dggs._core import fill_descend as descend
from dggs._core import fill_ellipse as ellipse
from dggs._core import fill_first_over as first_over
from dggs._core import fill_footprint as footprint
from dggs._core import fill_tables

__all__ = [
    "descend", "first_over", "centre", "footprint", "ellipse", "RHO", "OK", "TOO_MANY", "SURE", "CENTRE", "EDGE",
]

_TABLES = fill_tables()
#: A base cell's planar corners counter-clockwise (dggs.geometry.kernel.FACE_CORNERS_CCW), (3, 2).
_FACE = _TABLES["face"]
#: The six level-1 triangles' corners (A, B, C) (dggs.geometry.kernel.LEVEL1_CORNERS), (6, 3, 2).
_L1 = _TABLES["l1"]

#: The largest scale factor of Snyder's inverse on a face, rounded up (1.1633: module docstring).
K_INV = 1.17
#: The largest ratio of geodetic to authalic latitude change on WGS84 (1.00449), rounded up.
K_LAT = 1.005

#: RHO[l]: the largest arc (radians) from a level-l cell's footprint centre (:func:`footprint`) to its points
#: (libdggs/tools/gen_fill_tables.py computes it from the planar corners).
RHO = _TABLES["rho"]

#: Status of :func:`descend`: done, or stopped by a count over the limit.
OK, TOO_MANY = 0, 1
#: Flags of the cells found: certain, centre on an edge (left to GEOS), boundary cell at the level (left to the caller).
SURE, CENTRE, EDGE = 0, 1, 2
