"""Compiled tracing of a polyline of WGS84 geodesics through the cells of a level.

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
the ellipsoid's normal (:func:`_foot`: one round of Bowring's iteration,
exact to rounding for points within metres of the surface), as sines and
cosines that go straight into the authalic series and Snyder's forward
(:func:`_cell_at`, no trigonometric call).  Anchors
themselves are located from pyproj's (lat, lng) as given, exactly as
:func:`dggs.latlng_to_cell` locates them.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from dggs.geometry import kernel as gk

from . import bits
from .chord import corner_clear as _corner_clear
from .chord import corners6 as _corners6
from .chord import crosses as _crosses
from .grid import _neighbour
from .line_layout import clean, layout
from .points import encode_point, one_point

__all__ = ["RHO_MIN", "cells_at", "clean", "geodetic", "interpolate", "layout", "span_for", "trace"]

_A = 6378137.0
_F = 1.0 / 298.257223563
_B = _A * (1.0 - _F)
_E2 = _F * (2.0 - _F)
_EP2 = _E2 / (1.0 - _E2)
#: The smallest radius of curvature of the WGS84 ellipsoid (metres): the meridian's at the equator, b**2 / a.
RHO_MIN = _B * _B / _A
_STACK = 256
_COS_20 = math.cos(math.radians(20.0))
_ISEA_CENTRES = gk.ISEA_CENTRES
_ISEA_FRAMES = gk.ISEA_FRAMES


def span_for(tol: float) -> float:
    """The longest anchor span (metres) whose interpolated points stay within ``tol`` metres of the geodesic."""
    return float((96.0 * RHO_MIN**3 * tol) ** 0.25)


@njit(cache=True, nogil=True)
def ecef(lat_deg: float, lng_deg: float):
    """Geodetic WGS84 (lat, lng) degrees on the surface -> ECEF metres."""
    phi = math.radians(lat_deg)
    lam = math.radians(lng_deg)
    sp, cp = math.sin(phi), math.cos(phi)
    n = _A / math.sqrt(1.0 - _E2 * sp * sp)
    return n * cp * math.cos(lam), n * cp * math.sin(lam), n * (1.0 - _E2) * sp


@njit(cache=True, nogil=True)
def tangent(lat_deg: float, lng_deg: float, az_deg: float):
    """The unit vector (ECEF) at a point heading at azimuth ``az_deg`` (clockwise from north)."""
    phi = math.radians(lat_deg)
    lam = math.radians(lng_deg)
    al = math.radians(az_deg)
    sp, cp = math.sin(phi), math.cos(phi)
    sl, cl = math.sin(lam), math.cos(lam)
    ca, sa = math.cos(al), math.sin(al)
    return -ca * sp * cl - sa * sl, -ca * sp * sl + sa * cl, ca * cp


@njit(cache=True, nogil=True)
def geodetic(x: float, y: float, z: float):
    """ECEF metres -> geodetic WGS84 (lat, lng) degrees of the foot of the normal (:func:`_foot`'s)."""
    sp, cp, sl, cl = _foot(x, y, z)
    return math.degrees(math.atan2(sp, cp)), math.degrees(math.atan2(sl, cl))


@njit(cache=True, nogil=True)
def _span(lat, lng, az_out, az_in, span, k):
    """Hermite coefficients of span ``k``: A, s * TA, B, s * TB (12 numbers)."""
    s = span[k]
    ax, ay, az = ecef(lat[k], lng[k])
    tax, tay, taz = tangent(lat[k], lng[k], az_out[k])
    bx, by, bz = ecef(lat[k + 1], lng[k + 1])
    tbx, tby, tbz = tangent(lat[k + 1], lng[k + 1], az_in[k + 1])
    return ax, ay, az, s * tax, s * tay, s * taz, bx, by, bz, s * tbx, s * tby, s * tbz


@njit(cache=True, nogil=True)
def _point(c, t: float):
    """ECEF point of the Hermite curve ``c`` (from :func:`_span`) at ``t`` in 0..1."""
    t2 = t * t
    t3 = t2 * t
    h00 = 2.0 * t3 - 3.0 * t2 + 1.0
    h10 = t3 - 2.0 * t2 + t
    h01 = 3.0 * t2 - 2.0 * t3
    h11 = t3 - t2
    x = h00 * c[0] + h10 * c[3] + h01 * c[6] + h11 * c[9]
    y = h00 * c[1] + h10 * c[4] + h01 * c[7] + h11 * c[10]
    z = h00 * c[2] + h10 * c[5] + h01 * c[8] + h11 * c[11]
    return x, y, z


@njit(cache=True, nogil=True)
def _at(c, t: float):
    """(lat, lng) degrees of the Hermite curve ``c`` at ``t`` in 0..1."""
    x, y, z = _point(c, t)
    return geodetic(x, y, z)


@njit(cache=True, nogil=True)
def _foot(x: float, y: float, z: float):
    """Sine and cosine of the geodetic latitude and longitude of an ECEF point near the surface, without trigonometry.

    One round of Bowring's iteration (1976) on tangents from his starting
    reduced latitude, ``tan beta = a z / (b p)``: for points within metres
    of the surface it is exact to rounding (below 5e-16 rad against the
    latitude a point was built from, over a million points within 1 mm of
    the surface; more rounds change nothing).  The longitude's sine and
    cosine are (y, x) over their norm (a pole gives 0 and 1).
    """
    p = math.sqrt(x * x + y * y)
    if p == 0.0:
        return (1.0 if z >= 0.0 else -1.0), 0.0, 0.0, 1.0
    u, v = _A * z, _B * p
    r = math.sqrt(u * u + v * v)
    sb, cb = u / r, v / r
    num = z + _EP2 * _B * sb * sb * sb
    den = p - _E2 * _A * cb * cb * cb
    r = math.sqrt(num * num + den * den)
    return num / r, den / r, y / p, x / p


@njit(cache=True, nogil=True)
def _sample(x: float, y: float, z: float, level: int, hint: int):
    """``(cell, face, fx, fy)``: the cell holding the foot of ECEF point (x, y, z), as :func:`dggs.index._kernel.points.one_point`, and the point in its face's plane.

    The authalic shift is :func:`dggs.geometry.kernel.authalic_sincos`'s
    series on ``sin 2 phi`` and ``cos 2 phi``; the longitude's sine and
    cosine come from (x, y), so no trigonometric function is called.  The
    face is :func:`dggs.geometry.kernel.nearest_face`'s; a point within 20
    degrees of face ``hint``'s centre (the previous point's face) is on that
    face without the search, since every other centre is 41.8 degrees or
    more from it, so 21.8 or more from the point (a margin of 0.011 in the
    dot products against nearest_face's tie bias of at most 7.6e-15).
    """
    sp, cp, sl, cl = _foot(x, y, z)
    sb, cb = gk.authalic_sincos(sp, cp)
    px, py, pz = cb * cl, cb * sl, sb
    face = hint
    if face < 0 or px * _ISEA_CENTRES[face, 0] + py * _ISEA_CENTRES[face, 1] + pz * _ISEA_CENTRES[face, 2] <= _COS_20:
        face = gk.nearest_face(_ISEA_CENTRES, px, py, pz)
    fx, fy = gk.face_forward(_ISEA_FRAMES, face, px, py, pz)
    return encode_point(face, fx, fy, level), face, fx, fy


@njit(cache=True, nogil=True)
def _cell_at(x: float, y: float, z: float, level: int, hint: int):
    """``(cell, face)``: :func:`_sample`'s cell and face."""
    cell, face, _, _ = _sample(x, y, z, level, hint)
    return cell, face


@njit(cache=True, nogil=True)
def _anchor(lat: float, lng: float, level: int):
    """``(cell, face, fx, fy)`` of a polyline's or pyproj's point: the cell as ``latlng_to_cell`` gives it.

    The planar point is :func:`_sample`'s; where its face is not the cell's
    (a point on a face edge, a tie) the face is -1, so that :func:`_clear`
    trusts no planar test from it.
    """
    cell = one_point(lat, lng, level)
    x, y, z = ecef(lat, lng)
    _, face, fx, fy = _sample(x, y, z, level, -1)
    if face != bits.face_of(cell):
        face = -1
    return cell, face, fx, fy


@njit(cache=True, nogil=True)
def interpolate(lat, lng, az_out, az_in, span, k, t, out_lat, out_lng) -> None:
    """``out_lat[i], out_lng[i]``: the interpolated point at fraction ``t[i]`` of span ``k[i]`` (for tests)."""
    for i in range(k.shape[0]):
        c = _span(lat, lng, az_out, az_in, span, k[i])
        out_lat[i], out_lng[i] = _at(c, t[i])


@njit(cache=True, nogil=True)
def cells_at(lat, lng, level, out, chained=False) -> None:
    """``out[i]``: the cell of point ``i`` located as the tracer locates interpolated points (for tests).

    ``chained``: each point's face search starts from the one before's, as along a line.
    """
    hint = -1
    for i in range(lat.shape[0]):
        x, y, z = ecef(lat[i], lng[i])
        out[i], face = _cell_at(x, y, z, level, hint)
        if chained:
            hint = face


@njit(cache=True, nogil=True, inline="always")
def _adjacent(a: np.uint64, b: np.uint64, level: int) -> bool:
    for j in range(3):
        if _neighbour(a, level, j) == b:
            return True
    return False


@njit(cache=True, nogil=True)
def _between(a: np.uint64, b: np.uint64, level: int) -> np.uint64:
    """The one edge neighbour ``a`` and ``b`` have in common, or 0 (none, or two)."""
    found = np.uint64(0)
    for i in range(3):
        x = _neighbour(a, level, i)
        for j in range(3):
            if _neighbour(b, level, j) == x:
                if found != 0:
                    return np.uint64(0)
                found = x
    return found


@njit(cache=True, nogil=True)
def trace(lat, lng, az_out, az_in, span, level, step, corner, out, fix, shortcut=True):
    """The cells along a chain of anchors, into ``out``; returns ``(cells, corner gaps)``, or ``(-1, 0)`` if ``out`` is full.

    Anchor ``k`` is ``(lat[k], lng[k])`` with the geodesic's azimuth
    ``az_out[k]`` leaving it and ``az_in[k]`` arriving (they differ at a
    polyline's vertices); span ``k`` joins anchors ``k`` and ``k + 1`` along
    ``span[k]`` metres.  Each span is sampled every ``step`` metres or less;
    where two consecutive samples' cells share no edge, or share one but
    :func:`dggs.index._kernel.chord.clear` cannot tell from their points in
    the face plane that the line crossed only that edge (it may have passed
    round an end of it, through the cells beyond that corner), the stretch
    between them is bisected until every pair is clear, or the stretch is
    shorter than ``corner`` metres: then a pair sharing no edge (a corner
    between them) is recorded in ``fix`` as the index of the second cell in
    ``out``, for the caller to join around the corner, and a pair sharing
    one is joined across it.  Consecutive cells in ``out`` differ.

    With ``shortcut`` (from level 1), two cells at most a step apart along
    the line whose edge neighbours have exactly one cell in common are
    joined through it without a point located: the cells of a level form a
    bipartite graph, so the line crosses an even number of edges between
    them, and with two it crosses the common neighbour; four or more would
    take it round their shared corner the other way, across cells whose
    angles there sum to 180 degrees or more (that corner has 6, 10 or 12
    cells, or 4 and then two common neighbours).  A straight line cannot,
    but the line's image in the face plane bends (a kink where it crosses
    one of the projection's sector boundaries), so the join is taken only
    where :func:`dggs.index._kernel.chord.corner_clear` finds the chord
    between the two samples farther from their shared corner than that
    bend; otherwise the stretch is bisected.  (A line
    through the corner itself, within the corner length, goes round it the
    shorter way, through the same cell.)
    """
    nfix = 0
    cap = out.shape[0]
    prev, pf, px, py = _anchor(lat[0], lng[0], level)
    out[0] = prev
    n = 1
    sa = np.empty(_STACK, dtype=np.float64)
    sb = np.empty(_STACK, dtype=np.float64)
    ca = np.empty(_STACK, dtype=np.uint64)
    cb = np.empty(_STACK, dtype=np.uint64)
    fa = np.empty(_STACK, dtype=np.int64)
    fb = np.empty(_STACK, dtype=np.int64)
    pa = np.empty((_STACK, 2), dtype=np.float64)
    pb = np.empty((_STACK, 2), dtype=np.float64)
    hint = -1
    kc, kt = np.uint64(0), (0.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    for k in range(lat.shape[0] - 1):
        s = span[k]
        c = _span(lat, lng, az_out, az_in, span, k)
        m = max(1, int(math.ceil(s / step)))
        t0 = 0.0
        for j in range(1, m + 1):
            if j == m:
                t1 = 1.0
                cur, cf, cx, cy = _anchor(lat[k + 1], lng[k + 1], level)
            else:
                t1 = j / m
                x, y, z = _point(c, t1)
                cur, cf, cx, cy = _sample(x, y, z, level, hint)
                hint = cf
            if cur != prev:
                # bisect (t0, prev) .. (t1, cur), emitting every cell after prev up to cur
                sa[0], ca[0], sb[0], cb[0] = t0, prev, t1, cur
                fa[0], pa[0, 0], pa[0, 1], fb[0], pb[0, 0], pb[0, 1] = pf, px, py, cf, cx, cy
                top = 1
                while top > 0:
                    top -= 1
                    x0, x1, c0, c1 = sa[top], sb[top], ca[top], cb[top]
                    if c0 != c1:
                        near = _adjacent(c0, c1, level)
                        ok = False
                        if near and fa[top] >= 0 and fa[top] == fb[top] and bits.face_of(c0) == fa[top] and bits.face_of(c1) == fa[top]:
                            # chord.clear, the last cell's corners kept (the next pair mostly starts there)
                            ta = kt if c0 == kc else _corners6(c0)
                            kc, kt = c1, _corners6(c1)
                            ok = _crosses(ta, kt, pa[top, 0], pa[top, 1], pb[top, 0], pb[top, 1])
                        if not ok:
                            via = np.uint64(0)
                            if not near and shortcut and level > 0 and (x1 - x0) * s <= step:
                                via = _between(c0, c1, level)
                                if via != 0 and not _corner_clear(c0, c1, fa[top], pa[top, 0], pa[top, 1], fb[top], pb[top, 0], pb[top, 1]):
                                    via = np.uint64(0)
                            if via != 0:
                                if n >= cap:
                                    return -1, 0
                                out[n] = via
                                n += 1
                            elif (x1 - x0) * s >= corner and top + 2 <= _STACK:
                                xm = 0.5 * (x0 + x1)
                                x, y, z = _point(c, xm)
                                cm, mf, mx, my = _sample(x, y, z, level, hint)
                                hint = mf
                                # (x0 .. xm) above (xm .. x1): the first half is taken first
                                sa[top + 1], ca[top + 1], sb[top + 1], cb[top + 1] = x0, c0, xm, cm
                                fa[top + 1], pa[top + 1, 0], pa[top + 1, 1] = fa[top], pa[top, 0], pa[top, 1]
                                fb[top + 1], pb[top + 1, 0], pb[top + 1, 1] = mf, mx, my
                                sa[top], ca[top] = xm, cm  # (xm .. x1) keeps its end
                                fa[top], pa[top, 0], pa[top, 1] = mf, mx, my
                                top += 2
                                continue
                            elif not near:
                                if nfix >= fix.shape[0]:
                                    return -1, 0
                                fix[nfix] = n
                                nfix += 1
                    if c1 != out[n - 1]:
                        if n >= cap:
                            return -1, 0
                        out[n] = c1
                        n += 1
                prev, pf, px, py = cur, cf, cx, cy
            else:
                pf, px, py = cf, cx, cy
            t0 = t1
    return n, nfix
