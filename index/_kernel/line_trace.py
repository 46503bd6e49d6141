"""Tracing a polyline of WGS84 geodesics through the cells of a level: compiled C, libdggs/src/line_trace.c.

The caller (:func:`dggs.index.paths.line_to_cells`) gives exact geodesic
points, *anchors*, from ``pyproj.Geod`` (one vectorised ``fwd`` call for all
segments) with the geodesic's azimuth at each; this module fills the spans
between anchors, locates the points and bisects the gaps, all in one compiled
loop (:func:`trace`).

Between two anchors A and B a span ``s`` apart, the geodesic ``P(u)``
(parametrised by arc length) is replaced by the cubic Hermite curve in
Earth-centred (ECEF) coordinates that has A's and B's positions and the
geodesic's unit tangents there (times ``s``).  Cubic Hermite interpolation of
a curve with a bounded fourth derivative errs by at most
``s**4 / 384 * max |P''''|`` (the classical remainder).  A geodesic has no
curvature within the surface; its curvature is the normal curvature of the
ellipsoid, at most ``1 / rho`` with ``rho = b**2 / a = 6,335,439 m`` (the
meridian's radius at the equator), and its higher derivatives are ``1 / rho**3``
up to terms in ``e**2`` (on a sphere of radius R, exactly ``|P''''| = 1 / R**3``).
With a factor 4 of margin for those terms:

    |H(u / s) - P(u)| <= s**4 / (96 rho**3)

so a span of at most ``(96 rho**3 tol) ** 0.25`` keeps every interpolated
point within ``tol`` of the geodesic point at the same distance
(:func:`span_for`: 39 km for 0.1 mm, 12.5 km for 1 micrometre).  The bound is
conservative: Hermite's error is mostly along the normal, which the return
to the surface drops; measured against pyproj, points are within 1e-7 m of
the geodesic at 1 micrometre's spans (tests/index/test_paths.py).  The interpolated point, a
hair off the surface, is taken back to geodetic latitude and longitude along
the ellipsoid's normal (one round of Bowring's iteration, exact to rounding
for points within metres of the surface), as sines and cosines that go
straight into the authalic series and Snyder's forward (no trigonometric
call).  Anchors themselves are located from pyproj's (lat, lng) as given,
exactly as :func:`dggs.latlng_to_cell` locates them.

The functions are the C core's (``dggs._core``), bit for bit the numba
kernel's they replace; :mod:`.ivea_lines` is the same tracer on IVEA.
"""

from __future__ import annotations

import math

from dggs._core import cells_at, clean, ecef, geodetic, interpolate, layout, tangent, trace

__all__ = ["RHO_MIN", "cells_at", "clean", "ecef", "geodetic", "interpolate", "layout", "span_for", "tangent", "trace"]

_A = 6378137.0
_F = 1.0 / 298.257223563
_B = _A * (1.0 - _F)
_E2 = _F * (2.0 - _F)
_EP2 = _E2 / (1.0 - _E2)
#: The smallest radius of curvature of the WGS84 ellipsoid (metres): the meridian's at the equator, b**2 / a.
RHO_MIN = _B * _B / _A
#: Depth of the tracer's bisection stack (DGGS_TRACE_STACK in line_trace.h).
_STACK = 256
_COS_20 = math.cos(math.radians(20.0))


def span_for(tol: float) -> float:
    """The longest anchor span (metres) whose interpolated points stay within ``tol`` metres of the geodesic.

    Parameters
    ----------
    tol : float
        The largest distance (metres) allowed between an interpolated point and the geodesic's.

    Returns
    -------
    float
        ``(96 RHO_MIN**3 tol) ** 0.25`` metres.
    """
    return float((96.0 * RHO_MIN**3 * tol) ** 0.25)
