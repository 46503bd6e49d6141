"""Lat/lng rasters cut cell by cell against the pixel grid (issue 35) against the pixel-by-pixel cut.

The oracles, none using the cylindrical-map cut under test (libdggs/src/pixels_latlng.c):

* the pixel-by-pixel cut (:func:`dggs.index._pixels.pixel_pieces`, each pixel clipped along the cells' edges in
  Snyder's face planes) with 48 points an edge and its arc corrections, far within the bound checked: every
  piece of the two within 2e-5 of its pixel's area (each is within ``TOLERANCE``, 1e-5, of the true piece);
* each pixel's exact ellipsoidal area in closed form (the area between two parallels, Snyder 1987 eq. 3-12,
  written out here): a pixel's pieces add up to it within 1e-6 where the cells round it tile it;
* the cell's area (the ellipsoid's over the cells of the level): a cell wholly under the grid is covered to
  within 1e-6 of it.
Pinned at the poles (corners of cells and cells round a pole), the antimeridian and the icosahedron's vertices.
"""

from __future__ import annotations

import math
from collections import defaultdict

import numpy as np
import pytest
from hypothesis import example, given, reject, settings
from hypothesis import strategies as st

import dggs
from dggs.index._pixels import latlng_pieces, pixel_pieces
from dggs.raster.grid import TOLERANCE

from ..strategies import examples, special_points

A, F = 6378137.0, 1 / 298.257223563  # WGS84
E2 = F * (2 - F)
E = math.sqrt(E2)


#: The coarsest level a pixel side's grid is cut at here: coarser cells' edges want more than the kernel's 4,096
#: chords (block_pieces then cuts pixel by pixel).
COARSEST = {0.01: 4, 0.1: 2, 0.5: 0, 1.0: 0}


def _q(lat: float) -> float:
    s = math.sin(math.radians(lat))
    return (1 - E2) * (s / (1 - E2 * s * s) - math.log((1 - E * s) / (1 + E * s)) / (2 * E))


def band_area(lat0: float, lat1: float, dlng: float) -> float:
    """Exact area (m²) between two parallels over dlng degrees of longitude (Snyder 1987, eq. 3-12)."""
    return abs(A * A * (_q(lat1) - _q(lat0)) / 2 * math.radians(dlng))


def pixel_grid(top: float, left: float, d: float, rows: int, cols: int, k: int) -> tuple[np.ndarray, ...]:
    """Edge points of rows x cols pixels of side d from (top, left) going south, k points an edge."""
    hl = top - np.arange(rows + 1)[:, None] * d + np.zeros((1, cols * k + 1))
    hg = left + np.arange(cols * k + 1)[None, :] * d / k + np.zeros((rows + 1, 1))
    vl = top - np.arange(rows * k + 1)[:, None] * d / k + np.zeros((1, cols + 1))
    vg = left + np.arange(cols + 1)[None, :] * d + np.zeros((rows * k + 1, 1))
    return tuple(np.clip(a, -90.0, 90.0) if i % 2 == 0 else a for i, a in enumerate((hl, hg, vl, vg)))


def pieces_by_pair(pixel: np.ndarray, cell: np.ndarray, area: np.ndarray) -> dict[tuple[int, int], float]:
    out: dict[tuple[int, int], float] = defaultdict(float)
    for p, c, a in zip(pixel.tolist(), cell.tolist(), area.tolist(), strict=True):
        out[(p, c)] += a
    return out


def check_against_pixel_cut(top: float, left: float, d: float, rows: int, cols: int, level: int) -> None:
    top = min(90.0, max(-90.0 + rows * d, top))
    lat_edges = np.clip(top - d * np.arange(rows + 1), -90.0, 90.0)
    valid = np.ones((rows, cols), bool)
    try:
        pixel, cell, area = latlng_pieces(left, d, lat_edges, valid, level, TOLERANCE)
    except RuntimeError as err:  # refused (its documented limits): the raster path cuts such blocks pixel by pixel
        assert "4096 chords" in str(err)
        reject()
    assert (area > 0).all() and (dggs.get_level(cell) == level).all()
    k = 48
    old_pixel, old_cell, old_area, old_total = pixel_pieces(*pixel_grid(top, left, d, rows, cols, k), k, valid, level)
    exact = np.repeat([band_area(lat_edges[r], lat_edges[r + 1], d) for r in range(rows)], cols)
    total = np.bincount(pixel, weights=area, minlength=rows * cols)
    # the pixels' areas: the cells round a pixel tile it, the chords' gaps given back by the arcs
    assert np.all(np.abs(total / exact - 1) < 1e-6), np.max(np.abs(total / exact - 1))
    assert np.all(np.abs(old_total / exact - 1) < 2e-5)  # the oracle itself
    new, old = pieces_by_pair(pixel, cell, area), pieces_by_pair(old_pixel, old_cell, old_area)
    for key in set(new) | set(old):
        diff = abs(new.get(key, 0.0) - old.get(key, 0.0)) / exact[key[0]]
        assert diff < 2 * TOLERANCE, (key[0], dggs.int_to_str(key[1]), new.get(key), old.get(key))


@settings(max_examples=examples(25), deadline=None)
@given(
    st.floats(-89.0, 90.0), st.floats(-180.0, 180.0), st.sampled_from([0.01, 0.1, 0.5, 1.0]), st.integers(1, 4),
    st.integers(1, 5), st.integers(0, 12),
)
@example(90.0, -180.0, 1.0, 3, 5, 4)  # the north pole's row: cells with a corner on it and round it
@example(-87.0, 170.0, 1.0, 3, 5, 5)  # the south pole, across the antimeridian
@example(0.5, 179.5, 0.5, 2, 2, 8)  # the antimeridian at the equator
@example(1.0, -1.0, 0.1, 4, 5, 12)  # cells finer than the pixels
def test_cut_by_cells_matches_the_pixel_cut(top, left, d, rows, cols, level):
    """Every (pixel, cell) piece within 2e-5 of its pixel of the pixel-by-pixel cut's; pixels' sums exact."""
    level = max(level, COARSEST[d])
    check_against_pixel_cut(top, left, d, rows, cols, level)


@pytest.mark.parametrize("lat, lng", special_points()[:6] + special_points()[6:18])
def test_cut_by_cells_at_poles_antimeridian_and_vertices(lat, lng):
    """A 4 x 4 grid of 0.25 degree pixels round each pole, antimeridian point and icosahedron vertex."""
    top = min(90.0, lat + 0.5)
    left = lng - 0.5
    check_against_pixel_cut(top, left, 0.25, 4, 4, 7)


@pytest.mark.parametrize("top, left, d, rows, cols, level", [(30.0, -100.0, 0.001, 10, 10, 18),
                                                             (50.0, 5.0, 0.01, 12, 15, 15)])
def test_cells_the_pixels_size(top, left, d, rows, cols, level):
    """Cells the pixels' size, a cell's corners in most pixels: each piece gets the chords' error of every edge of its
    cell crossing the pixel (docs/raster.md: the worst measured, 1.5e-5 of the pixel, is the first grid's)."""
    check_against_pixel_cut(top, left, d, rows, cols, level)


@pytest.mark.parametrize("west", [-180.0, 0.0, 170.0])
def test_a_global_raster_covers_every_cell_to_its_area(west):
    """A whole 2-degree globe at level 4 (in any turn of longitudes): each cell's pieces add up to its area."""
    d = 2.0
    rows, cols = 90, 180
    lat_edges = 90.0 - d * np.arange(rows + 1)
    pixel, cell, area = latlng_pieces(west, d, lat_edges, np.ones((rows, cols), bool), 4, TOLERANCE)
    cells, inv = np.unique(cell, return_inverse=True)
    sums = np.bincount(inv, weights=area)
    assert cells.size == dggs.get_num_cells(4)
    assert np.max(np.abs(sums / dggs.cell_area(4, "m^2") - 1)) < 1e-6
    # a pixel meets a cell at most once, even where a cell round a pole meets it from both ends of its turn
    assert np.unique(pixel.astype(np.int64) * cells.size + inv).size == pixel.size


@pytest.mark.parametrize("top, d, level", [(90.0, 1.0, 0), (60.0, 0.01, 0), (68.0, 0.01, 4), (90.0, 0.1, 12)])
def test_grids_the_cut_refuses_are_cut_pixel_by_pixel(tmp_path, top, d, level):
    """Level 0 cells (an edge through a pole: the cut read a NaN longitude out of bounds and crashed) and cells far
    coarser than the pixels near a pole (more than 4096 chords an edge): the core refuses, and raster_to_cells
    answers through the pixel-by-pixel cut: every pixel shared out in full, and the shared areas add up to the
    pixels' closed-form areas."""
    from rasterio.transform import from_origin

    from dggs.raster import raster_to_cells

    from .helpers import write

    rows, cols = 3, 4
    lat_edges = np.clip(top - d * np.arange(rows + 1), -90.0, 90.0)
    with pytest.raises(RuntimeError, match="4096 chords"):
        latlng_pieces(0.0, d, lat_edges, np.ones((rows, cols), bool), level, TOLERANCE)
    path = write(tmp_path / "r.tif", np.ones((rows, cols)), crs="EPSG:4326", transform=from_origin(0.0, top, d, d))
    shares = raster_to_cells(path, level, mode="sum", as_str=True)  # each pixel's 1 shared out by area
    assert abs(shares["value"].sum() / (rows * cols) - 1) < 1e-5, shares
    areas = raster_to_cells(path, level, mode="sum", density=True, as_str=True)  # 1 a m^2: the shared areas
    pixels = sum(band_area(lat_edges[r], lat_edges[r + 1], d) for r in range(rows)) * cols
    assert abs(areas["value"].sum() / pixels - 1) < 1e-5, (areas["value"].sum(), pixels)


def test_invalid_pixels_get_no_pieces_and_bad_grids_are_refused():
    lat_edges = np.array([21.0, 20.5, 20.0])
    valid = np.array([[True, False], [False, True]])
    pixel, cell, area = latlng_pieces(30.0, 0.5, lat_edges, valid, 9, TOLERANCE)
    assert set(pixel.tolist()) == {0, 3}
    with pytest.raises(ValueError, match="monotonic"):
        latlng_pieces(30.0, 0.5, np.array([21.0, 21.0, 20.0]), valid, 9, TOLERANCE)
    with pytest.raises(ValueError, match="360"):
        latlng_pieces(30.0, 200.0, lat_edges, valid, 9, TOLERANCE)
