"""A polyline's points checked, and its anchors laid out: the plain loops before :mod:`.line_trace` traces it.

Neither locates a point, so the IVEA build (:mod:`.ivea_lines`) shares them as compiled.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

__all__ = ["clean", "layout"]


@njit(cache=True, nogil=True)
def clean(xy):
    """The points without consecutive repeats, checked: ``(-1, points)``, or ``(i, empty)``.

    ``i`` is the index of the first point that is not a finite latitude in
    -90..90 and a finite longitude.
    """
    n = xy.shape[0]
    keep = np.empty(n, dtype=np.bool_)
    count = 0
    for i in range(n):
        la, lo = xy[i, 0], xy[i, 1]
        if not (-90.0 <= la <= 90.0) or not np.isfinite(lo):
            return i, np.empty((0, 2), dtype=np.float64)
        keep[i] = i == 0 or la != xy[i - 1, 0] or lo != xy[i - 1, 1]
        count += keep[i]
    out = np.empty((count, 2), dtype=np.float64)
    j = 0
    for i in range(n):
        if keep[i]:
            out[j, 0], out[j, 1] = xy[i, 0], xy[i, 1]
            j += 1
    return -1, out


@njit(cache=True, nogil=True)
def layout(xy, az12, az21, dist, max_span):
    """Anchor arrays for a polyline's segments cut into spans of at most ``max_span`` metres.

    Returns ``(lat, lng, az_out, az_in, span, at, seg, s)``: the polyline's
    points and their azimuths in place (``az21``, pyproj's back azimuth at
    each end, turned round), and for each anchor between them its index
    ``at``, segment ``seg`` and distance ``s`` from the segment's start, for
    the caller to fill from ``pyproj.Geod.fwd``.
    """
    nseg = dist.shape[0]
    m = np.empty(nseg, dtype=np.int64)
    size = 1
    inner = 0
    for i in range(nseg):
        m[i] = max(1, int(math.ceil(dist[i] / max_span)))
        size += m[i]
        inner += m[i] - 1
    lat, lng = np.empty(size), np.empty(size)
    az_out, az_in, span = np.zeros(size), np.zeros(size), np.zeros(size - 1)
    at = np.empty(inner, dtype=np.int64)
    seg = np.empty(inner, dtype=np.int64)
    s = np.empty(inner)
    k = 0
    r = 0
    for i in range(nseg):
        lat[k], lng[k] = xy[i, 0], xy[i, 1]
        az_out[k] = az12[i]
        step = dist[i] / m[i]
        for j in range(m[i]):
            span[k + j] = step
            if j > 0:
                at[r], seg[r], s[r] = k + j, i, j * step
                r += 1
        k += m[i]
        az_in[k] = az21[i] + 180.0
    lat[k], lng[k] = xy[nseg, 0], xy[nseg, 1]
    return lat, lng, az_out, az_in, span, at, seg, s
