"""Equal area on WGS84, checked with pyproj.Geod; congruence checked through PROJ's isea."""

from __future__ import annotations

import math

import numpy as np
import pyproj
import pytest
from pyproj import Geod

import dggs
from dggs.geometry.authalic import WGS84

GEOD = Geod(ellps="WGS84")
# The WGS84 ellipsoid's area, from pyproj.Geod (not from our code): two hemispheres.
_LONS = np.linspace(-180, 180, 721)[:-1]
ELLIPSOID_AREA = 2 * abs(GEOD.polygon_area_perimeter(_LONS, np.zeros_like(_LONS))[0])


def geodesic_areas(cells, densify):
    b = dggs.cell_to_boundary(cells, densify=densify)
    return np.array([abs(GEOD.polygon_area_perimeter(r[:, 1], r[:, 0])[0]) for r in b])


def test_cell_area_is_ellipsoid_area_over_cell_count():
    for level in range(0, dggs.MAX_LEVEL + 1, 4):
        n = 20 if level == 0 else 120 * 3 ** (level - 1)
        assert dggs.cell_area(level) == pytest.approx(ELLIPSOID_AREA / n, rel=1e-12)
    assert dggs.cell_area(3, "km^2") == pytest.approx(dggs.cell_area(3) / 1e6)
    assert dggs.cell_area(0, "rads^2") == pytest.approx(4 * math.pi / 20)


def special_cells(level):
    """Cells touching face centres, icosahedron vertices, poles and the antimeridian."""
    geo = dggs.geometry.icosahedron.ISEA.geometry if hasattr(dggs, "icosahedron") else None
    from dggs.geometry.icosahedron import ISEA, xyz_to_latlng

    geo = ISEA.geometry
    pts = np.concatenate([geo.centres, geo.vertices])
    beta, lng = xyz_to_latlng(pts)
    lat = WGS84.authalic_to_geodetic_deg(np.degrees(beta))
    # nudge off the exact vertex so each lands in one of the cells around it
    lat = np.clip(lat + 1e-7, -90, 90)
    extra_lat = np.array([90.0, -90.0, 0.0, 45.0])
    extra_lng = np.array([0.0, 0.0, 180.0, -180.0])
    return np.unique(dggs.latlng_to_cell(np.concatenate([lat, extra_lat]), np.concatenate([np.degrees(lng), extra_lng]), level))


@pytest.mark.parametrize("level", [0, 1, 2, 3, 5, 8, 10, 13, 16, 19])
def test_geodesic_area_equals_cell_area(level):
    rng = np.random.default_rng(level)
    lat = np.degrees(np.arcsin(rng.uniform(-1, 1, 30)))
    lng = rng.uniform(-180, 180, 30)
    cells = np.unique(np.concatenate([dggs.latlng_to_cell(lat, lng, level), special_cells(level)]))
    areas = geodesic_areas(cells, densify=256)
    expected = ELLIPSOID_AREA / (20 if level == 0 else 120 * 3 ** (level - 1))
    assert np.abs(areas / expected - 1).max() <= 2e-6


def _vertex_cells(level, per_vertex=4, seed=0):
    """Cells a few cell-widths from each icosahedron vertex and face centre, where the projection bends most."""
    from dggs.geometry.icosahedron import ISEA, xyz_to_latlng

    geo = ISEA.geometry
    beta, lng = xyz_to_latlng(np.concatenate([geo.vertices, geo.centres]))
    lat = WGS84.authalic_to_geodetic_deg(np.degrees(beta))
    rng = np.random.default_rng(seed)
    step = 3 * math.sqrt(dggs.cell_area(level)) / 111_000.0  # about three cell widths, in degrees
    lat = np.repeat(lat, per_vertex) + rng.normal(0.0, step, lat.size * per_vertex)
    lng = np.repeat(np.degrees(lng), per_vertex) + rng.normal(0.0, step, lng.size * per_vertex)
    keep = np.abs(lat) < 89.0  # pole cells: pyproj.Geod's own area error is the larger there at fine levels
    return dggs.latlng_to_cell(lat[keep], (lng[keep] + 180.0) % 360.0 - 180.0, level)


@pytest.mark.parametrize("level", [1, 2, 4, 7, 9, 12, 14, 17, 19])
def test_polygon_default_densify_is_within_1e6(level):
    """Each cell gets its own point count (index/_densify.py); pyproj.Geod measures the result."""
    rng = np.random.default_rng(100 + level)
    lat = np.degrees(np.arcsin(rng.uniform(-0.99, 0.99, 40)))
    lng = rng.uniform(-170, 170, 40)
    cells = np.concatenate([dggs.latlng_to_cell(lat, lng, level), _vertex_cells(level)])
    for c, poly in zip(cells, dggs.cell_to_polygon(cells), strict=True):
        if poly.geom_type != "Polygon":
            continue
        xs, ys = poly.exterior.coords.xy
        area = abs(GEOD.polygon_area_perimeter(np.array(xs), np.array(ys))[0])
        assert area == pytest.approx(dggs.cell_area(c), rel=1e-6), c


def test_the_default_puts_few_points_on_fine_cells_and_many_only_where_edges_bend():
    from dggs.index._densify import needed_densify
    from dggs.index.ids import str_to_int

    rng = np.random.default_rng(5)
    lat = np.degrees(np.arcsin(rng.uniform(-0.99, 0.99, 500)))
    lng = rng.uniform(-180, 180, 500)
    medians = []
    for level in (8, 12, 17, 22):
        ids = np.asarray(dggs.latlng_to_cell(lat, lng, level, as_int=True), dtype=np.uint64)
        medians.append(float(np.median(needed_densify(ids))))
        vertex = np.asarray(str_to_int(list(_vertex_cells(level))), dtype=np.uint64)
        assert np.median(needed_densify(vertex)) >= medians[-1]  # bends more near the vertices
    assert medians == sorted(medians, reverse=True)  # fewer points the finer the level
    assert medians[-2] <= 8 and medians[-1] <= 1  # against 32 for every cell before


@pytest.mark.parametrize("level", [0, 1, 2, 3])
def test_all_cells_sum_to_the_ellipsoid(level):
    cells = dggs.get_base_cells() if level == 0 else dggs.cell_to_children(dggs.get_base_cells(), level)
    total = math.fsum(geodesic_areas(cells, densify=64))
    assert total == pytest.approx(ELLIPSOID_AREA, rel=2e-6)


def test_corners_through_proj_isea_form_congruent_30_60_90_triangles():
    """Independent check: PROJ's isea maps our cells' edges to straight, congruent triangles."""
    proj = pyproj.Transformer.from_pipeline(f"+proj=isea +R={WGS84.authalic_radius!r}")
    rng = np.random.default_rng(7)
    lat = np.degrees(np.arcsin(rng.uniform(-1, 1, 200)))
    lng = rng.uniform(-180, 180, 200)
    from dggs.geometry.icosahedron import ISEA

    for level in (4, 6, 9, 12):
        cells = dggs.latlng_to_cell(lat, lng, level)
        # PROJ gives points within 5e-6 rad of a face edge to the lower-numbered face
        # (extrapolating its formulas); keep cells well inside one face
        b0 = dggs.cell_to_boundary(cells, densify=7)
        beta = np.radians(WGS84.geodetic_to_authalic_deg(b0[..., 0]))
        lam = np.radians(b0[..., 1])
        xyz = np.stack([np.cos(beta) * np.cos(lam), np.cos(beta) * np.sin(lam), np.sin(beta)], -1)
        dots = np.sort(xyz @ ISEA.geometry.centres.T, axis=-1)
        inner = (dots[..., -1] - dots[..., -2] > 2e-5).all(axis=1)
        assert inner.sum() >= 20
        cells = cells[inner]
        b = dggs.cell_to_boundary(cells, densify=7)  # 3 corners + 7 points per edge
        auth = WGS84.geodetic_to_authalic_deg(b[..., 0])
        x, y = proj.transform(b[..., 1], auth)
        pts = np.stack([x, y], axis=-1).reshape(len(cells), 3, 8, 2)
        corner = pts[:, :, 0]
        # PROJ's net wraps face 14: skip cells it splits across the seam
        span = np.ptp(pts[..., 0].reshape(len(cells), -1), axis=1)
        ok = span < 0.5 * 5 * 7.674e6
        sides = np.linalg.norm(corner - np.roll(corner, -1, axis=1), axis=2)[ok]
        s = np.sort(sides, axis=1)
        assert np.allclose(s[:, 1] / s[:, 0], math.sqrt(3), rtol=1e-7)
        assert np.allclose(s[:, 2] / s[:, 0], 2.0, rtol=1e-7)
        assert np.allclose(s[:, 0], s[:, 0].mean(), rtol=1e-7)  # congruent
        # densified points lie on the straight segments between corners
        start, end = pts[ok][:, :, :1], np.roll(corner[ok], -1, axis=1)[:, :, None]
        d = end - start
        rel = pts[ok] - start
        cross = d[..., 0] * rel[..., 1] - d[..., 1] * rel[..., 0]
        assert np.abs(cross / np.linalg.norm(d, axis=-1)).max() < 1e-3 + 1e-7 * s[:, 0].mean()
