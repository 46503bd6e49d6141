"""Pixels cut along cell edges (dggs.index._pixels): each piece's area against independent oracles (issue 19).

Oracles, none using the face-plane clipping under test:

* geometry: the geodesic area (pyproj.Geod) of the intersection, in lng/lat,
  of the pixel drawn with 2,000 points an edge and the cell drawn with 512
  (``cell_to_polygon``): the chords of both are far below the error checked;
* sampling: the pixel cut into N x N small lat/lng rectangles, each of its
  exact ellipsoidal area (Geod), given to the cell holding its centre
  (``latlng_to_cell``): where lng/lat polygons cannot be intersected (a pole
  inside, the antimeridian), looser, O(1/N) at cell edges.
"""

from __future__ import annotations

import numpy as np
import pyproj
import pytest
import shapely
from hypothesis import example, given, settings
from hypothesis import strategies as st
from shapely.geometry import Polygon

import dggs
from dggs.index._pixels import pixel_pieces
from dggs.raster.grid import TOLERANCE, chord_error, points_per_edge

from ...strategies import examples, special_points

GEOD = pyproj.Geod(ellps="WGS84")


def lat_lng_grid(top, left, d, rows, cols, k):
    """Edge points of rows x cols lat/lng pixels of side d from (top, left), k points an edge."""
    hl = top - np.arange(rows + 1)[:, None] * d + np.zeros((1, cols * k + 1))
    hg = left + np.arange(cols * k + 1)[None, :] * d / k + np.zeros((rows + 1, 1))
    vl = top - np.arange(rows * k + 1)[:, None] * d / k + np.zeros((1, cols + 1))
    vg = left + np.arange(cols + 1)[None, :] * d + np.zeros((rows * k + 1, 1))
    return hl, hg, vl, vg


def rectangle(top, left, d, n=2000, width=None):
    """A lat/lng rectangle d high (and ``width`` wide, default d), n points an edge, clockwise."""
    w = d if width is None else width
    t = np.linspace(0, 1, n, endpoint=False)
    lat = np.concatenate([top + 0 * t, top - d * t, top - d + 0 * t, top - d + d * t])
    lng = np.concatenate([left + w * t, left + w + 0 * t, left + w - w * t, left + 0 * t])
    return lat, lng


def geod_area(lat, lng):
    return abs(GEOD.polygon_area_perimeter(lng, lat)[0])


def geometric_oracle(top, left, d, cells):
    """Geodesic area of each cell's intersection with the lat/lng pixel (no cell across the antimeridian)."""
    lat, lng = rectangle(top, left, d)
    pixel = Polygon(np.column_stack([lng, lat]))
    out = {}
    for cell in cells:
        part = shapely.intersection(dggs.cell_to_polygon(int(cell), densify=512), pixel)
        out[int(cell)] = sum(geod_area(*np.asarray(g.exterior.coords.xy)[::-1]) for g in getattr(part, "geoms", [part])
                             if not g.is_empty)
    return out, geod_area(lat, lng)


def sampling_oracle(top, left, d, level, n=300):
    """Each cell's area of the pixel, from n x n lat/lng sub-rectangles given to the cell of their centre."""
    edges_lat = top - np.arange(n + 1) * d / n
    area_row = np.array([geod_area(*rectangle(edges_lat[i], left, d / n, 50)) for i in range(n)])
    centre_lat = np.repeat((edges_lat[:-1] + edges_lat[1:]) / 2, n)
    centre_lng = np.tile(left + (np.arange(n) + 0.5) * d / n, n)
    centre_lng = (centre_lng + 180.0) % 360.0 - 180.0
    ids = dggs.latlng_to_cell(centre_lat, centre_lng, level, as_int=True)
    out: dict[int, float] = {}
    for cell, a in zip(ids.tolist(), np.repeat(area_row, n).tolist(), strict=True):
        out[cell] = out.get(cell, 0.0) + a
    return out


def one_sector(top, left, d):
    """Whether the pixel's edge lies in one 120-degree sector of one face (Snyder's forward, public API)."""
    from dggs.geometry.snyder import forward

    lat, lng = rectangle(top, left, d, n=50)
    beta = dggs.geometry.authalic.WGS84.geodetic_to_authalic_deg(lat)
    face, x, y = forward(beta, lng)
    sector = np.floor(np.degrees(np.arctan2(x, y)) % 360.0 / 120.0)
    return len(set(zip(face.tolist(), sector.tolist(), strict=True))) == 1


def k_for(top, left, d):
    from rasterio.transform import from_origin

    return points_per_edge(chord_error(None, from_origin(left, top, d, d), 0, 0, 1, 1))


def pieces_of_one(top, left, d, level):
    k = k_for(top, left, d)
    pixel, cell, area, total = pixel_pieces(*lat_lng_grid(top, left, d, 1, 1, k), k, np.ones((1, 1), bool), level)
    assert set(pixel.tolist()) <= {0}
    return dict(zip(cell.tolist(), area.tolist(), strict=True)), float(total[0])


@pytest.mark.parametrize(
    "top, left, d, level",
    [
        (40.3, 10.1, 0.3, 8),  # inside a face
        (32.5, -30.5, 0.5, 7),  # across face edges
        (10.0, 20.0, 0.01, 12),  # small: most of it in one cell
        (0.4, -0.4, 0.8, 9),
        (-55.1, 100.2, 1.0, 6),
        (-57.0, -165.0, 1.0, 5),  # across a sector's edge (a ray to a vertex): Snyder's plane kinks there
        (-18.0, 7.0, 1.0, 6),
    ],
)
def test_each_piece_is_the_geodesic_area_of_pixel_and_cell(top, left, d, level):
    got, total = pieces_of_one(top, left, d, level)
    want, true_total = geometric_oracle(top, left, d, got)
    # extrapolated from k and k / 2 points: 1e-9 where Snyder's plane is smooth, one sector of one face
    assert abs(total / true_total - 1) < (1e-9 if one_sector(top, left, d) else TOLERANCE)
    assert abs(sum(got.values()) - total) < 1e-9 * total
    bound = TOLERANCE + 2e-7  # the documented bound, and the oracle's chords
    for cell, area in got.items():
        assert abs(area - want[cell]) <= bound * true_total, (dggs.int_to_str(cell), area, want[cell])
    # no cell met by the pixel is missing: the cells round the pieces hold no more of it
    around = set(dggs.grid_disk(np.array(list(got), dtype=np.uint64), 1).ravel().tolist()) - set(got) - {0}
    missed, _ = geometric_oracle(top, left, d, around)
    assert sum(missed.values()) <= 2e-7 * true_total


@pytest.mark.parametrize("lat, lng", special_points())
def test_pixels_at_poles_vertices_edges_and_the_antimeridian_match_sampling(lat, lng):
    d = 0.4
    top = max(-90.0 + d, min(90.0, lat + d / 2))
    left = lng - d / 2
    level = 7
    got, total = pieces_of_one(top, left, d, level)
    want = sampling_oracle(top, left, d, level)
    t_lat, t_lng = rectangle(top, left, d)
    assert abs(total / geod_area(t_lat, t_lng) - 1) < TOLERANCE  # across face edges: kinks, no extrapolation
    assert set(got) >= {c for c, a in want.items() if a > 2e-3 * total}  # every cell the pixel covers a bit of
    for cell, area in got.items():
        assert abs(area - want.get(cell, 0.0)) < 4e-3 * total, (dggs.int_to_str(cell), area, want.get(cell))


@settings(max_examples=examples(30), deadline=None)
@given(
    st.floats(-89.0, 89.0), st.floats(-180.0, 179.0), st.sampled_from([0.002, 0.05, 0.3]), st.integers(0, 14),
    st.integers(1, 3), st.integers(1, 3),
)
@example(0.0, 178.96875, 0.05, 0, 1, 1)  # a sliver whose arc correction took all its area: no empty piece
def test_a_grid_of_pixels_shares_out_exactly_its_area(top, left, d, level, rows, cols):
    """Every pixel's pieces add up to its area; neighbouring pixels do not overlap (the cells' sums are the pixels')."""
    top = max(-89.0 + rows * d, top)
    k = k_for(top, left, d)
    grid = lat_lng_grid(top, left, d, rows, cols, k)
    pixel, cell, area, total = pixel_pieces(*grid, k, np.ones((rows, cols), bool), level)
    sums = np.bincount(pixel, weights=area, minlength=rows * cols)
    assert np.allclose(sums, total, rtol=1e-12, atol=0)
    whole = geod_area(*rectangle(top, left, d * rows, 500, width=d * cols))
    assert abs(total.sum() / whole - 1) < TOLERANCE
    assert (dggs.get_level(cell) == level).all() and np.all(np.diff(pixel) >= 0)
    # a pixel's pieces are in distinct cells, each area positive and at most the cell's area
    assert all(len(set(cell[pixel == p].tolist())) == int((pixel == p).sum()) for p in range(rows * cols))
    assert (area > 0).all() and (area <= dggs.cell_area(level, "m^2") + TOLERANCE * total.max()).all()


def test_invalid_pixels_get_no_pieces_and_cells_smaller_than_pixels_are_whole():
    k = k_for(20.0, 30.0, 0.5)
    grid = lat_lng_grid(20.0, 30.0, 0.5, 2, 2, k)
    valid = np.array([[True, False], [False, True]])
    pixel, cell, area, total = pixel_pieces(*grid, k, valid, 12)
    assert set(pixel.tolist()) == {0, 3} and total[1] == total[2] == 0.0
    inner = area[area > 0.999999 * dggs.cell_area(12, "m^2")]
    assert inner.size > 100  # cells far smaller than the pixel: whole, each the cell's exact area
    assert np.allclose(inner, dggs.cell_area(12, "m^2"), rtol=1e-6)
