"""A block's pixel edges on the globe: the points :func:`dggs.index._pixels.pixel_pieces` cuts along.

A pixel's edges are straight in the raster's CRS and curved in Snyder's face
planes, where the pixels are cut; each is drawn through ``k`` points (chords
between them), transformed to WGS84 with pyproj.  An edge whose midpoint
lies ``s`` off its chord leaves out about ``2/3 s L`` of area (a parabola's
segment, L the edge's length), ``1/k²`` of that with ``k`` points; so
:func:`points_per_edge` measures the sagittas of a sample of the block's
pixels in the face plane and takes the ``k`` that keeps every piece of a
pixel within :data:`TOLERANCE` of the pixel's area.  The pixel's whole area,
with each pair of chords' parabolic segment added where it lies (the kernel's arcs), is closer still.
Pixels wider than the kernel takes are cut into sub-pixels first
(:func:`split_factor`), which changes no area.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from dggs.index._pixels import MAX_PIXEL_DEGREES

__all__ = ["TOLERANCE", "arc_degrees", "lnglat", "chord_error", "tile_chord_errors", "points_per_edge", "split_factor", "edge_grid", "pixel_degrees", "to_wgs84"]

#: The error a piece may have, as a fraction of its pixel's area.  1e-6 cost 3 times the points of 1e-5
#: (a global quarter-degree raster: 28 points an edge instead of 9) for no change a user could see, the
#: pixel's whole area being within about 1e-9 anyway (each pair of chords' parabolic segment added).
TOLERANCE = 1e-5
#: Sample pixels a tile side for the sagittas (raster.py cuts blocks in tiles of 32: one in four).
_SAMPLE = 8

# The 16 points round a pixel whose sagittas are measured, clockwise from its top-left corner, four an edge:
# the corner, then a quarter, half and three quarters along (row and column offsets in pixels).
_T = np.array([0.0, 0.25, 0.5, 0.75])
_DR = np.concatenate([0 * _T, _T, 1 + 0 * _T, 1 - _T])
_DC = np.concatenate([_T, 1 + 0 * _T, 1 - _T, 0 * _T])


def points_per_edge(chord_error: float) -> int:
    """Points per edge keeping every piece within :data:`TOLERANCE`, given the error of one point an edge.

    ``chord_error`` is :func:`chord_error`'s: the area the chords leave out, as a fraction of a pixel's.
    From 2 points up, an even number (the kernel adds each pair of chords' parabolic segment).

    Examples
    --------
    >>> [points_per_edge(e) for e in (1e-6, 1e-5, 3e-5, 1e-1)]
    [1, 1, 2, 100]
    """
    k = max(1, math.ceil(math.sqrt(chord_error / TOLERANCE)))
    return k + (k % 2 if k >= 2 else 0)


def chord_error(transformer: Any, transform: Any, row: int, col: int, rows: int, cols: int) -> float:
    """The largest fraction of a pixel's area its edges' chords leave out, over a sample of the block's pixels.

    ``2/3 sum(s L) / A`` of each sampled pixel with one point an edge, its sagittas ``s`` measured in the
    face planes (:func:`dggs.index._pixels.chord_errors`).  Where no sampled pixel has an edge without a
    kink (a pixel at an icosahedron vertex, alone), pixels a quarter the size are measured: the fraction
    grows as the side (s L / A ~ L), so theirs times 4.
    """
    from dggs.index._pixels import chord_errors

    r = row + np.unique(np.linspace(0, rows - 1, min(rows, _SAMPLE)).astype(np.int64))
    c = col + np.unique(np.linspace(0, cols - 1, min(cols, _SAMPLE)).astype(np.int64))
    rr, cc = np.meshgrid(r.astype(np.float64), c.astype(np.float64), indexing="ij")
    for scale in (1.0, 0.25, 0.0625):
        lat, lng = lnglat(transformer, transform, cc.reshape(-1, 1) + scale * _DC, rr.reshape(-1, 1) + scale * _DR)
        errors = chord_errors(lat, lng)
        if np.isfinite(errors).any():
            return float(np.nanmax(errors)) / scale
    return 0.0


def _samples(start: int, count: int, tile: int) -> tuple[np.ndarray, np.ndarray]:
    """Sampled pixel positions along one axis, :data:`_SAMPLE` a tile (fewer in a short one), and their tiles."""
    pos, which = [], []
    for i, t0 in enumerate(range(0, count, tile)):
        n = min(tile, count - t0)
        at = np.unique(np.linspace(0, n - 1, min(n, _SAMPLE)).astype(np.int64))
        pos.append(start + t0 + at)
        which.append(np.full(at.size, i))
    return np.concatenate(pos), np.concatenate(which)


def tile_chord_errors(transformer: Any, transform: Any, row: int, col: int, rows: int, cols: int, tile: int
                      ) -> np.ndarray:
    """:func:`chord_error` of every ``tile x tile`` tile of a block at once (one kernel call).

    NaN for a tile none of whose sampled pixels has a smooth edge (:func:`chord_error` then measures it finer).

    Examples
    --------
    >>> from affine import Affine
    >>> e = tile_chord_errors(None, Affine(0.01, 0, 5.0, 0, -0.01, 50.0), 0, 0, 40, 70, 32)
    >>> e.shape, bool((e > 0).all() and (e < 1e-4).all())
    ((2, 3), True)
    """
    from dggs.index._pixels import chord_errors

    r, tr = _samples(row, rows, tile)
    c, tc = _samples(col, cols, tile)
    rr, cc = np.meshgrid(r.astype(np.float64), c.astype(np.float64), indexing="ij")
    lat, lng = lnglat(transformer, transform, cc.reshape(-1, 1) + _DC, rr.reshape(-1, 1) + _DR)
    errors = chord_errors(lat, lng)
    which = (tr[:, None] * (tc.max() + 1) + tc[None, :]).ravel()
    out = np.full((tr.max() + 1) * (tc.max() + 1), -np.inf)
    ok = np.isfinite(errors)
    np.maximum.at(out, which[ok], errors[ok])
    return np.where(np.isfinite(out), out, np.nan).reshape(tr.max() + 1, tc.max() + 1)


def split_factor(degrees: float) -> int:
    """Sub-pixels per pixel side so that each is at most half the widest pixel the kernel takes."""
    return max(1, math.ceil(degrees / (0.5 * MAX_PIXEL_DEGREES)))


def to_wgs84(crs: Any) -> Any:
    """A transformer from ``crs`` to WGS84 (lng, lat), or None for WGS84 geographic itself.

    Raises
    ------
    RasterError
        PROJ knows no way from ``crs`` to WGS84 (a local engineering CRS, ``LOCAL_CS``), naming it.
    """
    from pyproj import CRS, Transformer
    from pyproj.exceptions import CRSError, ProjError

    from dggs.raster.source import RasterError

    wgs84 = CRS.from_epsg(4326)
    try:
        if CRS.from_user_input(crs).equals(wgs84, ignore_axis_order=True):
            return None
        return Transformer.from_crs(crs, wgs84, always_xy=True)
    except (ProjError, CRSError) as exc:
        raise RasterError(f"the CRS {_crs_name(crs)!r} has no transformation to WGS84 ({exc}): the raster cannot be "
                          "put on the globe; assign its true CRS first") from None


def _crs_name(crs: Any) -> str:
    return str(getattr(crs, "name", None) or crs)


def _beyond_pole(transformer: Any, transform: Any) -> float:
    """How far past a pole (degrees of latitude) a pixel's corner may lie and be moved onto it; 0 for none.

    A geographic raster whose rows are centred on +-90 (ERA5's layout) has its outer edges half a pixel past
    the poles: the part of those pixels on the globe is kept by putting the corners past a pole on it (at
    most a pixel past it: anything farther is no raster of the globe).
    """
    if transformer is not None and not _geographic_source(transformer):
        return 0.0
    return abs(transform.d) + abs(transform.e)


def _geographic_source(transformer: Any) -> bool:
    try:
        return bool(transformer.source_crs.is_geographic)
    except AttributeError:  # pragma: no cover - pyproj < 3.1
        return False


def lnglat(transformer: Any, transform: Any, cols: np.ndarray, rows: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """WGS84 (lat, lng) of fractional pixel positions; NaN where the CRS cannot be transformed."""
    a, b, c, d, e, f = transform.a, transform.b, transform.c, transform.d, transform.e, transform.f
    x = a * cols + b * rows + c
    y = d * cols + e * rows + f
    reach = _beyond_pole(transformer, transform)
    if reach:
        past = np.abs(y) > 90.0
        if past.any():
            y = np.where(past & (np.abs(y) <= 90.0 + reach), np.clip(y, -90.0, 90.0), y)
    if transformer is not None:
        x, y = transformer.transform(x, y, errcheck=False)
        x, y = np.asarray(x, dtype=np.float64), np.asarray(y, dtype=np.float64)
    bad = ~(np.isfinite(x) & np.isfinite(y)) | (np.abs(y) > 90.0)
    if bad.any():
        x, y = np.where(bad, np.nan, x), np.where(bad, np.nan, y)
    return y, x


def edge_grid(transformer: Any, transform: Any, row: int, col: int, rows: int, cols: int, k: int, s: int = 1) -> tuple[
    np.ndarray, np.ndarray, np.ndarray, np.ndarray
]:
    """``hlat, hlng, vlat, vlng`` of the pixels (rows x cols from (row, col)), each cut into s x s, k points an edge."""
    n_rows, n_cols = rows * s, cols * s
    hr = (row + np.arange(n_rows + 1) / s)[:, None] + np.zeros((1, n_cols * k + 1))
    hc = (col + np.arange(n_cols * k + 1) / (s * k))[None, :] + np.zeros((n_rows + 1, 1))
    vr = (row + np.arange(n_rows * k + 1) / (s * k))[:, None] + np.zeros((1, n_cols + 1))
    vc = (col + np.arange(n_cols + 1) / s)[None, :] + np.zeros((n_rows * k + 1, 1))
    hlat, hlng = lnglat(transformer, transform, hc, hr)
    vlat, vlng = lnglat(transformer, transform, vc, vr)
    return hlat, hlng, vlat, vlng


def arc_degrees(lat1: np.ndarray, lng1: np.ndarray, lat2: np.ndarray, lng2: np.ndarray) -> float:
    """The longest great-circle arc, in degrees, between paired points (NaN pairs skipped; 0 for none).

    Examples
    --------
    >>> arc_degrees(np.array([0.0, 0.0]), np.array([0.0, 10.0]), np.array([1.0, 0.0]), np.array([0.0, 12.0]))
    2.0
    """
    p1, p2 = np.radians(lat1), np.radians(lat2)
    h = np.sin((p2 - p1) / 2) ** 2 + np.cos(p1) * np.cos(p2) * np.sin(np.radians(lng2 - lng1) / 2) ** 2
    with np.errstate(invalid="ignore"):
        out = np.degrees(2 * np.arcsin(np.sqrt(np.clip(h, 0, 1))))
    return float(np.nanmax(out)) if np.isfinite(out).any() else 0.0


def pixel_degrees(hlat: np.ndarray, hlng: np.ndarray, vlat: np.ndarray, vlng: np.ndarray, k: int) -> float:
    """The longest pixel side in degrees of arc (great-circle), over a grid of :func:`edge_grid` (NaN skipped)."""
    arc = arc_degrees
    across = arc(hlat[:, :-k:k], hlng[:, :-k:k], hlat[:, k::k], hlng[:, k::k]) if hlat.shape[1] > k else 0.0
    down = arc(vlat[:-k:k], vlng[:-k:k], vlat[k::k], vlng[k::k]) if vlat.shape[0] > k else 0.0
    return max(across, down)
