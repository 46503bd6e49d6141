"""dggs.Grid: the same Split (2:6) cells on ISEA and on IVEA.

References independent of the IVEA point kernels (index/_kernel/ivea_points.py):
- the planar cell comes from the ISEA path (module-level verbs and Snyder's public projection): a cell is the
  same planar triangle on both grids, so IVEA's centre is ``ivea.Projection().inverse`` of the planar centroid
  and IVEA's corners the inverse of the planar corners;
- a point's cell on IVEA holds the point's IVEA planar position (``ivea.Projection().forward``) in its planar
  triangle, checked by barycentric coordinates;
- areas from ``pyproj.Geod`` against the equal-area cell area.
The round trips (location of the centre, boundary inside) run on both grids, for string and integer ids.
"""

from __future__ import annotations

import doctest
import math

import numpy as np
import pandas as pd
import pyproj
import pytest
import shapely
import shapely.affinity
import shapely.geometry
from hypothesis import example, given, settings

import dggs
import dggs.index.projection as projection_module
from dggs.errors import DggsValueError
from dggs.geometry import ivea, kernel
from dggs.geometry.authalic import WGS84
from dggs.geometry.icosahedron import ISEA
from tests.strategies import cells, examples, latlngs

IVEA = dggs.Grid("IVEA")
ISEA_GRID = dggs.Grid("ISEA")
GRIDS = [ISEA_GRID, IVEA]
GEOD = pyproj.Geod(ellps="WGS84")
R = WGS84.authalic_radius
FRAMES = np.ascontiguousarray(ISEA.geometry.frames)
PINNED = ["A", "Q", "A5", "Q1", "C401", "K1", "T01", "A51111111", "Q122222", "B0000000000", "S3210"]


def angle(lat1, lng1, lat2, lng2):
    a = np.radians([lat1, lng1])
    b = np.radians([lat2, lng2])
    c = math.sin((b[0] - a[0]) / 2) ** 2 + math.cos(a[0]) * math.cos(b[0]) * math.sin((b[1] - a[1]) / 2) ** 2
    return 2 * math.asin(math.sqrt(min(c, 1.0)))


def planar_corners(cell):
    """The cell's planar triangle on its face, from the ISEA grid: corners projected by Snyder's kernel."""
    face = dggs.get_face(cell)
    out = []
    for lat, lng in dggs.cell_to_boundary(cell):
        beta = math.radians(float(WGS84.geodetic_to_authalic_deg(lat)))
        lam = math.radians(lng)
        p = (math.cos(beta) * math.cos(lam), math.cos(beta) * math.sin(lam), math.sin(beta))
        out.append(kernel.face_forward(FRAMES, face, *p))
    return face, np.array(out)


def test_choice_and_errors():
    assert dggs.Grid() == ISEA_GRID == dggs.Grid("isea") and repr(IVEA) == "Grid('IVEA')"
    assert ISEA_GRID.latlng_to_cell is not None and hash(IVEA) == hash(dggs.Grid("ivea"))
    with pytest.raises(DggsValueError, match="projection 'HEALPix' is not one of ISEA, IVEA"):
        dggs.Grid("HEALPix")
    with pytest.raises(DggsValueError, match="projection 3"):
        dggs.Grid(3)  # type: ignore[arg-type]
    with pytest.raises(dggs.CoordinateError, match="latitude 91.0"):
        IVEA.latlng_to_cell(91.0, 0.0, 3)
    with pytest.raises(dggs.InvalidCellError):
        IVEA.cell_to_latlng("Z1")
    with pytest.raises(dggs.LevelError):
        IVEA.latlng_to_cell(0.0, 0.0, 99)


def test_doctests():
    assert doctest.testmod(projection_module).failed == 0
    assert doctest.testmod(ivea).failed == 0


def test_isea_grid_is_the_module_level_verbs():
    lat, lng = np.array([51.05, -33.9, 89.9]), np.array([-114.07, 151.2, 0.0])
    for level in (0, 5, 17):
        assert np.array_equal(ISEA_GRID.latlng_to_cell(lat, lng, level), dggs.latlng_to_cell(lat, lng, level))
    assert ISEA_GRID.cell_to_latlng("C401") == dggs.cell_to_latlng("C401")


# --- IVEA against the planar cells of the ISEA grid ---------------------------------------------
@settings(max_examples=examples(60), deadline=None)
@given(cells(max_level=20))
@example("A")
@example("Q1")
@example("A51111111")
@example("Q122222")
@example("T0122222")
def test_ivea_centre_and_corners_are_the_planar_cell_mapped_by_ivea(cell):
    face, corners = planar_corners(cell)
    proj = ivea.Projection()
    cx, cy = corners.mean(axis=0)
    lat, lng = proj.inverse(face, cx * R, cy * R)
    got = IVEA.cell_to_latlng(cell)
    assert angle(got[0], got[1], lat, lng) < 1e-11
    ring = IVEA.cell_to_boundary(cell)
    for (la, lo), (x, y) in zip(ring, corners, strict=True):
        la2, lo2 = proj.inverse(face, x * R, y * R)
        assert angle(la, lo, la2, lo2) < 1e-9  # corners on face edges: a few ulps of the planar slack


@settings(max_examples=examples(100), deadline=None)
@given(latlngs())
@example((90.0, 0.0))
@example((-90.0, 0.0))
@example((0.0, 180.0))
@example((0.0, -180.0))
@example((58.282525588539, 11.25))
@example((26.565051177078, -168.75))
def test_ivea_location_holds_the_points_ivea_position(p):
    lat, lng = p
    proj = ivea.Projection()
    for level in (1, 6, 14):
        cell = IVEA.latlng_to_cell(lat, lng, level)
        face, corners = planar_corners(cell)
        f, x, y = proj.forward(lat, lng)
        if f != face:  # on a face edge or vertex: the point on the cell's own face
            x, y = R * np.array(ivea.face_forward(FRAMES, face, *_unit(lat, lng)))
        a, b, c = corners
        m = np.array([b - a, c - a]).T
        u, v = np.linalg.solve(m, np.array([x / R, y / R]) - a)
        assert min(u, v, 1 - u - v) > -1e-9, (cell, u, v)


def _unit(lat, lng):
    beta = math.radians(float(WGS84.geodetic_to_authalic_deg(lat)))
    lam = math.radians(lng)
    return math.cos(beta) * math.cos(lam), math.cos(beta) * math.sin(lam), math.sin(beta)


# --- round trips on both grids, string and integer ids ---------------------------------------------
@pytest.mark.parametrize("grid", GRIDS, ids=repr)
@settings(max_examples=examples(60), deadline=None)
@given(cells(max_level=25))
@example("A")
@example("Q")
@example("A5")
@example("K1")
@example("B0000000000")
def test_centre_is_located_in_its_cell(grid, cell):
    level = dggs.get_level(cell)
    assert grid.latlng_to_cell(*grid.cell_to_latlng(cell), level) == cell
    as_int = dggs.str_to_int(cell)
    assert grid.latlng_to_cell(*grid.cell_to_latlng(as_int), level, as_int=True) == as_int


@pytest.mark.parametrize("grid", GRIDS, ids=repr)
def test_boundary_points_nudged_inward_locate_in_the_cell(grid):
    for cell in PINNED:
        level = dggs.get_level(cell)
        lat0, lng0 = grid.cell_to_latlng(cell)
        for lat, lng in grid.cell_to_boundary(cell, densify=3):
            if abs(lat) > 89.999:  # a pole corner: every direction is "inward"
                continue
            # 1e-6 of the way to the centre, along the great circle (pyproj.Geod)
            az, _, dist = GEOD.inv(lng, lat, lng0, lat0)
            lng1, lat1, _ = GEOD.fwd(lng, lat, az, dist * 1e-6)
            assert grid.latlng_to_cell(lat1, lng1, level) == cell


# --- areas and polygons --------------------------------------------------------------------------
def test_ivea_polygons_have_the_cell_area():
    for cell in PINNED:
        poly = IVEA.cell_to_polygon(cell)
        assert poly.is_valid
        area, _ = GEOD.geometry_area_perimeter(poly)
        assert abs(area) == pytest.approx(IVEA.cell_area(cell), rel=2e-6), cell  # the default densify aims at 1e-6


def test_ivea_whole_level_tiles_the_globe():
    ids = dggs.cell_to_children(dggs.get_base_cells(), 2)
    polys = IVEA.cell_to_polygon(ids, densify=24)
    total = sum(abs(GEOD.geometry_area_perimeter(p)[0]) for p in polys)
    assert total == pytest.approx(WGS84.area, rel=1e-6)


def test_ivea_cells_differ_from_isea_cells_but_not_by_much():
    """Same ids, different places: the two maps agree on vertices, centres and edge midpoints only."""
    rng = np.random.default_rng(4)
    lat = np.degrees(np.arcsin(rng.uniform(-1, 1, 5000)))
    lng = rng.uniform(-180, 180, 5000)
    a = IVEA.latlng_to_cell(lat, lng, 8, as_int=True)
    b = ISEA_GRID.latlng_to_cell(lat, lng, 8, as_int=True)
    assert 0.2 < (a != b).mean() < 0.95
    # the parents at level 1 are the same cells on both: the map keeps each natural triangle
    assert np.array_equal(dggs.cell_to_parent(a, 1), dggs.cell_to_parent(b, 1))
    # the face-to-plane maps agree at the face's vertices, centre and edge midpoints (fixed points)
    for f in range(20):
        for p in list(ISEA.geometry.vertices[ISEA.geometry.face_vertices[f]]) + [ISEA.geometry.centres[f]]:
            x1, y1 = ivea.face_forward(FRAMES, f, *p)
            x2, y2 = kernel.face_forward(FRAMES, f, *p)
            assert math.hypot(x1 - x2, y1 - y2) < 1e-14


# --- containers ------------------------------------------------------------------------------------
def test_ivea_gives_back_the_kind_it_was_given():
    s = pd.Series([10.0, 20.0], index=["a", "b"])
    out = IVEA.latlng_to_cell(s, s, 4)
    assert isinstance(out, pd.Series) and list(out.index) == ["a", "b"]
    arr = IVEA.latlng_to_cell(np.array([10.0, 20.0]), np.array([1.0, 2.0]), 4, as_int=True)
    assert arr.dtype == np.uint64
    assert isinstance(IVEA.latlng_to_cell(10.0, 1.0, 4), str)
    lat, lng = IVEA.cell_to_latlng(["C401", "C402"])
    assert isinstance(lat, list) and len(lng) == 2
    assert isinstance(IVEA.cell_to_boundary("C401"), tuple)
    assert IVEA.cell_to_boundary(np.array(["C401", "C402"]), densify=1).shape == (2, 6, 2)
    assert IVEA.cell_to_polygon(np.array(["C401"]))[0].geom_type == "Polygon"


# --- polygon fill ----------------------------------------------------------------------------------
FILL_TARGETS = {
    "box": shapely.geometry.box(-10, -10, 10, 10),
    "antimeridian": shapely.geometry.box(170, -20, 190, 5),
    "polar": shapely.geometry.Polygon([(-180, 70), (180, 70), (180, 90), (-180, 90)]),
    "vertex": shapely.geometry.Point(11.25, 58.2825).buffer(6.0),
}


@pytest.mark.parametrize("name", list(FILL_TARGETS))
def test_ivea_fill_is_the_brute_force_over_every_cell(name):
    """Every level-5 cell tested by its IVEA centre (center), and its IVEA polygon (contains, overlaps)."""
    polygon = FILL_TARGETS[name]
    level = 5
    ids = np.asarray(dggs.cell_to_children(dggs.get_base_cells(as_int=True), level), dtype=np.uint64)
    lat, lng = IVEA.cell_to_latlng(ids)
    target = shapely.union_all([shapely.affinity.translate(polygon, xoff=k * 360.0) for k in (-1, 0, 1)])
    target = target.intersection(shapely.geometry.box(-180, -90, 180, 90))
    centre = set(ids[shapely.contains_xy(target, lng, lat)].tolist())
    got = set(IVEA.polygon_to_cells(polygon, level, as_int=True).tolist())
    assert got == centre and len(got) > 10
    polys = IVEA.cell_to_polygon(ids)
    near = shapely.intersects(target, polys)
    assert set(IVEA.polygon_to_cells(polygon, level, "overlaps", as_int=True).tolist()) == set(ids[near].tolist())
    inside = shapely.contains(target, polys)
    assert set(IVEA.polygon_to_cells(polygon, level, "contains", as_int=True).tolist()) == set(ids[inside].tolist())
    # and not ISEA's cells
    if name == "box":
        assert got != set(dggs.polygon_to_cells(polygon, level, as_int=True).tolist())


def test_fill_projection_checked():
    with pytest.raises(DggsValueError, match="projection 'X'"):
        dggs.polygon_to_cells(shapely.geometry.box(0, 0, 1, 1), 3, projection="X")


def test_ivea_threaded_loops_equal_the_serial_ones():
    from dggs.index._kernel import ivea_points as ki

    rng = np.random.default_rng(3)
    n = 20_000
    lat, lng = np.degrees(np.arcsin(rng.uniform(-1, 1, n))), rng.uniform(-180, 180, n)
    a, b = np.empty(n, np.uint64), np.empty(n, np.uint64)
    ki.locate(1, lat, lng, 14, a)  # the amount of work picks the threads: one, then all
    ki.locate(1 << 30, lat, lng, 14, b)
    assert np.array_equal(a, b)
    one, two = np.empty((n, 6, 2)), np.empty((n, 6, 2))
    ki.boundaries(1, a, 1, one, False)
    ki.boundaries(1 << 30, a, 1, two, False)
    assert np.array_equal(one, two)
