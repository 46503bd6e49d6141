"""A projected raster's block cut cell by cell in the raster's own plane (issue 35), where that holds.

In its CRS a raster's pixels are a regular axis-aligned grid, so, as for
lat/lng rasters (:func:`dggs.index._pixels.latlng_pieces`), each *cell* is
cut against the grid's rows and columns instead of each pixel against the
cells:

* the cells that may meet the block are those holding a sample of its points
  (interior every third of a cell, the boundary every twelfth) and the cells
  two edge steps from them, kept where their drawn ring meets the block (cells
  smaller than the pixels: the descendants of such cells of the level whose
  cells hold about 64 pixels);
* each cell's edges (straight in Snyder's face plane) are densified with
  ``k`` chords, the points put on the globe by the core and taken into the
  CRS by pyproj (one vectorised transform for the block), ``k`` the block's
  from each edge's sagitta in pixel units, so that every chord leaves out at
  most :data:`dggs.raster.grid.TOLERANCE` of any pixel it crosses (a chord's
  sagitta falls as ``1/k²``; the chords through a pixel leave out at most
  ``2/3 s √2`` of it, ``s`` their sagitta, along its diagonal);
* the rings are cut in the plane by the core (``dggs_plane_pieces``: Green's
  theorem in strips), which gives each piece's planar area and centroid;
* each piece's true area is its planar area times the map's inverse areal
  scale ``w`` at its centroid.  ``w`` is measured, not assumed: the
  geodesic area (:class:`pyproj.Geod`, on the ellipsoid the cells' areas are
  of) of small squares of the plane over a 9 x 9 lattice of the block, fitted
  by a polynomial of degree 4 and checked on the 8 x 8 lattice between.  In an
  equal-area CRS (LAEA, EPSG:6933, Albers) ``w`` is a constant and the areas
  are exact; in another (UTM, polar stereographic, mercator) the centroid rule
  errs by the second order, bounded by ``w``'s second derivatives over a
  pixel.  (:meth:`pyproj.Proj.get_factors` would be cheaper but is not the
  ellipsoid's: for Mollweide on WGS84 it says 1 where the ellipsoid's areal
  scale is 0.9966 at 60N, and for web mercator 4.0489 where it is 4.0357.)

The path is refused (``None``: the caller cuts pixel by pixel) where a rule
does not hold, or where it does not pay: cells smaller than
:data:`MIN_CELL_PIXELS` pixels, a rotated grid, a geographic CRS (degrees
of another datum than WGS84's), points the CRS cannot take, ``w`` not fitted
within a tenth of the tolerance or bending more than the tolerance over a
pixel, an edge wanting more than 4,096 chords, or any valid pixel whose
pieces do not add up to it (cells the sample missed, a cell torn by the CRS's
own edge): so a block is cut here only where every pixel is whole.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from dggs.index._bbox_fill import _descendants
from dggs.index._pixels import plane_pieces
from dggs.index._shapes import boundaries
from dggs.index.grid import edge_neighbors
from dggs.index.measure import cell_area
from dggs.index.points import latlng_to_cell
from dggs.raster.grid import TOLERANCE
from dggs.raster.source import Block, RasterSource

__all__ = ["plane_block_pieces", "MIN_CELL_PIXELS", "MOST_CHORDS", "COVER_TOLERANCE"]

#: The fewest pixels a cell must hold for the plane cut: where cells are the pixels' size a cell's ring costs more
#: than the pixels it meets (a UTM raster of 1 km pixels, one thread: level 14, 2.7 pixels a cell, 1.20 s here
#: against 1.82 s pixel by pixel; level 15, 0.89 pixels a cell, 2.32 s against 2.12 s).
MIN_CELL_PIXELS = 2.0
#: Most chords a cell edge may take in the plane (more: the block is cut pixel by pixel).
MOST_CHORDS = 4096
#: How far a valid pixel's pieces may add up from the whole pixel (planar, a fraction of it) before the block is
#: refused: a shared cell edge is one polyline on both sides, so this is rounding; a missed cell is far more.
COVER_TOLERANCE = 1e-7
#: Pixels from the block a ring's point may lie (the core takes 1e15; a point farther is a CRS's blow-up).
_FARTHEST = 1e12
#: Degree of the polynomial ``w`` is fitted by, and the lattice it is sampled on (and checked between).
_DEGREE = 4
_LATTICE = 9
#: Side of the squares ``w`` is measured on (metres): small enough that their mean is ``w`` at their centre to
#: about 1e-9, large enough that their geodesic area keeps 1e-10.
_SQUARE_M = 1000.0


_FACTS: dict[str, tuple[float, float | None]] = {}


def _crs_facts(transformer: Any) -> tuple[float, float | None]:
    """``(metres per CRS unit, the period of x in CRS units or None)``: a cylindrical CRS's world width."""
    key = str(transformer.definition)
    if key not in _FACTS:
        _FACTS[key] = _measure_crs(transformer)
    return _FACTS[key]


def _measure_crs(transformer: Any) -> tuple[float, float | None]:
    crs = transformer.source_crs
    unit = float(crs.axis_info[0].unit_conversion_factor) if crs.axis_info else 1.0
    lats = np.array([-60.0, 0.0, 60.0])
    east, _ = _to_crs(transformer, np.full(3, 180.0 - 1e-9), lats)
    west, _ = _to_crs(transformer, np.full(3, -180.0 + 1e-9), lats)
    width = east - west
    period = float(width[1]) if np.isfinite(width).all() and np.ptp(width) < 1e-6 * abs(width[1]) else None
    return unit, period


def _to_crs(transformer: Any, lng: np.ndarray, lat: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    from pyproj.enums import TransformDirection

    x, y = transformer.transform(lng, lat, direction=TransformDirection.INVERSE, errcheck=False)
    return np.asarray(x, dtype=np.float64), np.asarray(y, dtype=np.float64)


def _to_wgs84(transformer: Any, x: np.ndarray, y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    lng, lat = transformer.transform(x, y, errcheck=False)
    return np.asarray(lng, dtype=np.float64), np.asarray(lat, dtype=np.float64)


def _monomials(u: np.ndarray, v: np.ndarray) -> np.ndarray:
    return np.stack([u**i * v**j for i in range(_DEGREE + 1) for j in range(_DEGREE + 1 - i)], axis=-1)


class _Weight:
    """The inverse areal scale ``w`` over a block: true m² per planar m², a polynomial in the block's pixels."""

    def __init__(self, coef: np.ndarray, rows: int, cols: int) -> None:
        self.coef, self.rows, self.cols = coef, rows, cols

    def __call__(self, col: np.ndarray, row: np.ndarray) -> np.ndarray:
        u, v = 2.0 * col / self.cols - 1.0, 2.0 * row / self.rows - 1.0
        terms = [(i, j) for i in range(_DEGREE + 1) for j in range(_DEGREE + 1 - i)]  # _monomials' order
        out = np.zeros(np.broadcast(u, v).shape)
        for i in range(_DEGREE, -1, -1):  # Horner's scheme in u of Horner's in v
            inner = np.zeros_like(out)
            for j in range(_DEGREE - i, -1, -1):
                inner = inner * v + self.coef[terms.index((i, j))]
            out = out * u + inner
        return out

    def bend(self, col: np.ndarray, row: np.ndarray) -> np.ndarray:
        """The centroid rule's bound a pixel (fraction of ``w``): ``w``'s second derivatives over a half-diagonal."""
        h = 1e-3 * min(self.rows, self.cols, 8)
        w = self(col, row)
        wcc = (self(col + h, row) - 2 * w + self(col - h, row)) / h**2
        wrr = (self(col, row + h) - 2 * w + self(col, row - h)) / h**2
        wcr = (self(col + h, row + h) - self(col + h, row - h) - self(col - h, row + h) + self(col - h, row - h)) / (
            4 * h**2)
        return np.asarray(0.25 * (np.abs(wcc) + 2 * np.abs(wcr) + np.abs(wrr)) / w)


def _measured_w(transformer: Any, t: Any, row0: int, col0: int, col: np.ndarray, row: np.ndarray, side: float
                ) -> np.ndarray:
    """``w`` at pixel positions: the geodesic area of a square of ``side`` CRS units round each, over its plane area.

    NaN where a square's point cannot be put on the globe.
    """
    from pyproj import Geod

    s = np.linspace(-0.5, 0.5, 5)[:-1]
    du = np.concatenate([s, 0 * s + 0.5, -s, 0 * s - 0.5]) * side  # a square's 16 points, counter-clockwise
    dv = np.concatenate([0 * s - 0.5, s, 0 * s + 0.5, -s]) * side
    x = t.c + t.a * (col0 + col)[:, None] + du
    y = t.f + t.e * (row0 + row)[:, None] + dv
    lng, lat = _to_wgs84(transformer, x.ravel(), y.ravel())
    lng, lat = lng.reshape(x.shape), lat.reshape(x.shape)
    geod = Geod(ellps="WGS84")
    out = np.full(col.shape[0], np.nan)
    for i in range(col.shape[0]):
        if np.isfinite(lng[i]).all() and np.isfinite(lat[i]).all() and (np.abs(lat[i]) <= 90.0).all():
            out[i] = abs(geod.polygon_area_perimeter(lng[i], lat[i])[0]) / side**2
    return out


def _weight(transformer: Any, t: Any, block: Block, unit: float) -> _Weight | None:
    """``w`` fitted over the block (per CRS unit², in m²), or None where the fit or the centroid rule fails."""
    rows, cols = block.shape
    side = _SQUARE_M / unit
    on = np.linspace(0.0, 1.0, _LATTICE)
    between = 0.5 * (on[1:] + on[:-1])
    fit_c, fit_r = (g.ravel() for g in np.meshgrid(on * cols, on * rows))
    chk_c, chk_r = (g.ravel() for g in np.meshgrid(between * cols, between * rows))
    w = _measured_w(transformer, t, block.row, block.col, np.concatenate([fit_c, chk_c]),
                    np.concatenate([fit_r, chk_r]), side)
    if not (np.isfinite(w).all() and (w > 0).all()):
        return None
    n = fit_c.shape[0]
    weight = _Weight(np.zeros(1), rows, cols)
    a = _monomials(2.0 * fit_c / cols - 1.0, 2.0 * fit_r / rows - 1.0)
    weight.coef = np.linalg.lstsq(a, w[:n], rcond=None)[0]
    if not (np.abs(weight(chk_c, chk_r) / w[n:] - 1.0).max() <= 0.1 * TOLERANCE):
        return None
    if not (weight.bend(np.concatenate([fit_c, chk_c]), np.concatenate([fit_r, chk_r])).max() <= TOLERANCE):
        return None
    return weight


def _candidates(transformer: Any, t: Any, block: Block, level: int, cell_px: float) -> np.ndarray | None:
    """The cells holding a sample of the block's points, and those two edge steps from them (uint64, unique)."""
    rows, cols = block.shape
    edge = math.sqrt(4.0 * cell_px / math.sqrt(3.0))  # a cell's edge in pixels (an equilateral triangle)
    inner = max(edge / 3.0, 1e-3)
    rim = max(edge / 12.0, 1e-3)
    ci = np.linspace(0.0, cols, max(2, math.ceil(cols / inner) + 1))
    ri = np.linspace(0.0, rows, max(2, math.ceil(rows / inner) + 1))
    cc, rr = (g.ravel() for g in np.meshgrid(ci, ri))
    cb = np.linspace(0.0, cols, max(2, math.ceil(cols / rim) + 1))
    rb = np.linspace(0.0, rows, max(2, math.ceil(rows / rim) + 1))
    cc = np.concatenate([cc, cb, cb, 0 * rb, 0 * rb + cols])
    rr = np.concatenate([rr, 0 * cb, 0 * cb + rows, rb, rb])
    if cc.shape[0] > 64 * rows * cols + 4096:  # cells far finer than the pixels: the pixel path's job
        return None
    lng, lat = _to_wgs84(transformer, t.c + t.a * (block.col + cc), t.f + t.e * (block.row + rr))
    if not (np.isfinite(lng).all() and np.isfinite(lat).all() and (np.abs(lat) <= 90.0).all()):
        return None
    ids = np.unique(latlng_to_cell(lat, lng, level, as_int=True))
    for _ in range(2):  # two edge steps: round a vertex the line of the block's edge passes near
        ids = np.unique(np.concatenate([ids, edge_neighbors(ids).ravel()]))
    return ids


def _rings(transformer: Any, t: Any, block: Block, ids: np.ndarray, chords: int, period: float | None
           ) -> tuple[np.ndarray, np.ndarray]:
    """(N, 3 chords) column and row coordinates (the block's) of the cells' densified rings."""
    pts = boundaries(ids, chords - 1, max_points=2**62)
    x, y = _to_crs(transformer, pts[..., 1].ravel(), pts[..., 0].ravel())
    x, y = x.reshape(pts.shape[:2]), y.reshape(pts.shape[:2])
    if period is not None:  # a cylindrical CRS: each ring in one piece, nearest the block's middle
        x = x - period * np.round((x - x[:, :1]) / period)
        mid = t.c + t.a * (block.col + 0.5 * block.shape[1])
        x = x - period * np.round((x.mean(axis=1, keepdims=True) - mid) / period)
    return (x - t.c) / t.a - block.col, (y - t.f) / t.e - block.row


def plane_block_pieces(src: RasterSource, transformer: Any, block: Block, level: int) -> tuple[
    np.ndarray, np.ndarray, np.ndarray, bool
] | None:
    """``(pixel, cell, area, False)`` as :func:`dggs.raster.pieces.block_pieces`, cut in the CRS's plane; or None.

    None where the block must be cut pixel by pixel (see the module's notes). A cell's pieces together, in
    pixel order; areas in m² on the ellipsoid.

    Examples
    --------
    >>> from affine import Affine
    >>> from pyproj import Transformer
    >>> from types import SimpleNamespace
    >>> src = SimpleNamespace(transform=Affine(2000.0, 0, 500000.0, 0, -2000.0, 6000000.0))
    >>> utm = Transformer.from_crs("EPSG:32633", "EPSG:4326", always_xy=True)
    >>> block = Block(0, 0, np.zeros((1, 20, 20)), np.ones((20, 20), bool))
    >>> pixel, cell, area, split = plane_block_pieces(src, utm, block, 9)
    >>> sums = np.bincount(pixel, area, minlength=400)
    >>> bool(np.allclose(sums, sums.mean(), rtol=1e-3)), round(float(sums[0]) / 1e6, 3)
    (True, 4.003)
    """
    t = src.transform
    rows, cols = block.shape
    if transformer is None or t.b != 0.0 or t.d != 0.0 or t.a == 0.0 or t.e == 0.0 or not block.valid.any():
        return None
    if transformer.source_crs is None or transformer.source_crs.is_geographic:  # degrees of another datum
        return None
    unit, period = _crs_facts(transformer)
    if period is not None and abs(t.a) * cols >= 0.5 * period:
        return None
    weight = _weight(transformer, t, block, unit)
    if weight is None:
        return None
    pixel_m2 = abs(t.a * t.e)  # CRS units²: w is m² per CRS unit²
    cell_px = float(cell_area(level, unit="m^2")) / (pixel_m2 * float(weight(np.array([cols / 2]),
                                                                               np.array([rows / 2]))[0]))
    if cell_px < MIN_CELL_PIXELS:
        return None
    coarse = level  # cells far smaller than the pixels: found as the descendants of coarser ones (~64 pixels)
    while coarse > 1 and cell_px * float(cell_area(coarse, unit="m^2") / cell_area(level, unit="m^2")) < 64.0:
        coarse -= 1
    ratio = float(cell_area(level, unit="m^2") / cell_area(coarse, unit="m^2"))
    ids = _candidates(transformer, t, block, coarse, cell_px / ratio)
    if ids is None:
        return None
    col, row = _rings(transformer, t, block, ids, 2, period)  # corners and edge midpoints: the sagittas
    good = np.isfinite(col).all(axis=1) & np.isfinite(row).all(axis=1)
    ends = [(0, 2), (2, 4), (4, 0)]
    sag = np.zeros(ids.shape[0])
    for m, (a, b) in zip((1, 3, 5), ends, strict=True):
        sag = np.maximum(sag, np.hypot(col[:, m] - 0.5 * (col[:, a] + col[:, b]),
                                       row[:, m] - 0.5 * (row[:, a] + row[:, b])))
    with np.errstate(invalid="ignore"):
        pad = sag + 1.0
        meets = good & (col.min(axis=1) - pad < cols) & (col.max(axis=1) + pad > 0) & (
            row.min(axis=1) - pad < rows) & (row.max(axis=1) + pad > 0)
    ids, sag = ids[meets], sag[meets] * ratio  # a sagitta goes as the square of the edge: as the area
    if ids.shape[0] == 0:
        return None
    if coarse < level:
        ids = _descendants(ids, level)
    # k chords leave 1/k² of the edge's sagitta s (constant curvature; 1.1 for its change along the edge), and the
    # chords in a pixel leave out at most 2/3 s sqrt(2) of it (parabolic segments along its diagonal)
    chords = max(1, math.ceil(1.1 * math.sqrt(2.0 / 3.0 * math.sqrt(2.0) * float(sag.max()) / TOLERANCE)))
    if chords > MOST_CHORDS:
        return None
    col, row = _rings(transformer, t, block, ids, chords, period)
    if not ((np.abs(col) < _FARTHEST).all() and (np.abs(row) < _FARTHEST).all()):  # NaN too
        return None
    n = col.shape[1]
    pixel, cell, area, cu, cv = plane_pieces(col.ravel(), row.ravel(), np.arange(ids.shape[0] + 1) * n, ids,
                                             block.valid)
    covered = np.bincount(pixel, area, minlength=rows * cols)
    if not (np.abs(covered[block.valid.ravel()] - 1.0) <= COVER_TOLERANCE).all():
        return None
    pr, pc = np.divmod(pixel, cols)
    true = area * pixel_m2 * weight(pc + cu, pr + cv)
    return pixel, cell, true, False
