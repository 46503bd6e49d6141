"""``mode="center"`` of :func:`dggs.raster.raster_to_cells`: the pixel under each cell's centre.

A block's cells are those whose centre falls in one of its pixels: the cells
of a box round the block's outline in longitude and latitude (a polar cap
when the outline goes round a pole, longitudes past 180 across the
antimeridian) are filled by centre, and each centre is put in the raster's
CRS and kept if it lands on a pixel of the block holding data.  Blocks tile
the raster, so every cell comes from exactly one block.
"""

from __future__ import annotations

import functools
import math
from typing import Any

import numpy as np
from shapely.geometry import box

import dggs
from dggs.raster.grid import arc_degrees, lnglat

__all__ = ["centre_values", "outline_box"]


def outline_box(lat: np.ndarray, lng: np.ndarray, margin: float) -> Any:
    """A lng/lat box holding a closed outline (vertices in order), ``margin`` degrees of arc wider.

    Examples
    --------
    >>> outline_box(np.array([0.0, 0.0, 1.0, 1.0]), np.array([179.0, -179.0, -179.0, 179.0]), 0.0).bounds
    (179.0, 0.0, 181.0, 1.0)
    >>> outline_box(np.array([80.0, 80.0, 80.0, 80.0]), np.array([0.0, 90.0, 180.0, -90.0]), 0.0).bounds
    (-180.0, 80.0, 180.0, 90.0)
    """
    ok = np.isfinite(lat) & np.isfinite(lng)
    lat, lng = lat[ok], lng[ok]
    step = (np.diff(np.append(lng, lng[:1])) + 180.0) % 360.0 - 180.0
    low, high = max(-90.0, float(lat.min()) - margin), min(90.0, float(lat.max()) + margin)
    if abs(step.sum()) > 180.0:  # the outline goes round a pole: a cap
        return box(-180.0, low, 180.0, 90.0) if lat.mean() > 0 else box(-180.0, -90.0, 180.0, high)
    unwrapped = lng[0] + np.concatenate([[0.0], np.cumsum(step[:-1])])
    stretch = margin / max(math.cos(math.radians(max(abs(low), abs(high)))), 1e-3)
    west, east = float(unwrapped.min()) - stretch, float(unwrapped.max()) + stretch
    if east - west >= 360.0:
        west, east = -180.0, 180.0
    elif west < -180.0 and east < 180.0:
        west, east = west + 360.0, east + 360.0  # one turn past 180 at most, as polygon_to_cells takes it
    elif west >= 180.0:
        west, east = west - 360.0, east - 360.0  # a block wholly past 180 (a raster laid out 0..360)
    return box(west, low, east, high)


def _widest_pixel(src: Any, transformer: Any, block: Any, ring_lat: np.ndarray, ring_lng: np.ndarray) -> float:
    """Degrees of arc of the widest pixel side: along the outline, and over a 9 x 9 sample of the block's pixels."""
    rows, cols = block.shape
    r = block.row + np.unique(np.linspace(0, rows - 1, min(rows, 9)).astype(np.int64))
    c = block.col + np.unique(np.linspace(0, cols - 1, min(cols, 9)).astype(np.int64))
    rr, cc = np.meshgrid(r.astype(np.float64), c.astype(np.float64), indexing="ij")
    lat, lng = lnglat(transformer, src.transform, cc.reshape(-1, 1) + [0, 1, 1, 0], rr.reshape(-1, 1) + [0, 0, 1, 1])
    sides = arc_degrees(lat, lng, np.roll(lat, -1, axis=1), np.roll(lng, -1, axis=1))
    outline = arc_degrees(ring_lat, ring_lng, np.roll(ring_lat, -1), np.roll(ring_lng, -1))
    return max(sides, outline)


@functools.lru_cache(maxsize=16)
def _from_wgs84(crs_wkt: str) -> Any:
    from pyproj import CRS, Transformer

    return Transformer.from_crs(CRS.from_epsg(4326), CRS.from_wkt(crs_wkt), always_xy=True)


def centre_values(src: Any, transformer: Any, block: Any, level: int) -> tuple[np.ndarray, np.ndarray] | None:
    """The cells whose centre lies on a pixel of ``block`` holding data, and those pixels' values (bands, n)."""
    rows, cols = block.shape
    r0, c0 = float(block.row), float(block.col)
    across, down = np.arange(cols + 1.0), np.arange(rows + 1.0)
    # the block's outline through every pixel corner on it, clockwise from the top-left corner
    ring_c = c0 + np.concatenate([across, np.full(rows, cols), across[::-1][1:], np.zeros(rows - 1)])
    ring_r = r0 + np.concatenate([np.zeros(cols + 1), down[1:], np.full(cols, rows), down[::-1][1:-1]])
    ring_lat, ring_lng = lnglat(transformer, src.transform, ring_c, ring_r)
    if not np.isfinite(ring_lat).any():
        return None
    margin = 2.0 * _widest_pixel(src, transformer, block, ring_lat, ring_lng)
    ids = np.asarray(dggs.polygon_to_cells(outline_box(ring_lat, ring_lng, margin), level, as_int=True))
    if ids.size == 0:
        return None
    lat, lng = dggs.cell_to_latlng(ids)
    if transformer is None:
        x, y = np.asarray(lng, dtype=np.float64), np.asarray(lat, dtype=np.float64)
    else:
        x, y = _from_wgs84(src.crs.to_wkt()).transform(lng, lat, errcheck=False)
        x, y = np.asarray(x, dtype=np.float64), np.asarray(y, dtype=np.float64)
    if src.crs.is_geographic:
        # longitudes of the raster's own turn: a raster laid out 0..360 (or 170..190) holds the centre at -10
        # at 350; a longitude is put in the turn that starts at the block's westernmost corner
        t = src.transform
        west = float(np.nanmin(t.a * ring_c + t.b * ring_r + t.c))
        x = west + np.mod(x - west, 360.0)
    inverse = ~src.transform
    col = np.floor(inverse.a * x + inverse.b * y + inverse.c) - block.col
    row = np.floor(inverse.d * x + inverse.e * y + inverse.f) - block.row
    ok = np.isfinite(col) & np.isfinite(row) & (col >= 0) & (col < cols) & (row >= 0) & (row < rows)
    r, c = row[ok].astype(np.int64), col[ok].astype(np.int64)
    have = block.valid[r, c]
    return ids[ok][have], block.data[:, r[have], c[have]].astype(np.float64)
