"""polygon_to_cells against a brute-force scan of every cell's centre."""

from __future__ import annotations

import pytest
import shapely
from hypothesis import given, settings
from hypothesis import strategies as st
from shapely.geometry import MultiPolygon, Point, Polygon, box

import dggs
from dggs.errors import DggsValueError, LevelError

LEVEL = 6
ALL = dggs.cell_to_children(dggs.get_base_cells(), LEVEL)
ALL_LAT, ALL_LNG = dggs.cell_to_latlng(ALL)


def brute_force(geom):
    inside = shapely.contains_xy(geom, ALL_LNG, ALL_LAT)
    return set(ALL[inside].tolist())


@settings(max_examples=25)
@given(
    st.floats(-170, 160), st.floats(-80, 70), st.floats(1, 40), st.floats(1, 20)
)
def test_boxes_match_brute_force(lng0, lat0, w, h):
    poly = box(lng0, lat0, min(lng0 + w, 180), min(lat0 + h, 90))
    assert set(dggs.polygon_to_cells(poly, LEVEL).tolist()) == brute_force(poly)


def test_holes_are_respected():
    outer = Point(10, 45).buffer(15)
    hole = Point(10, 45).buffer(6)
    donut = outer.difference(hole)
    got = set(dggs.polygon_to_cells(donut, LEVEL).tolist())
    assert got == brute_force(donut)
    assert got.isdisjoint(brute_force(hole))


def test_antimeridian_both_conventions():
    wide = box(170, -20, 190, 20)  # longitudes beyond 180
    split = MultiPolygon([box(170, -20, 180, 20), box(-180, -20, -170, 20)])
    a = set(dggs.polygon_to_cells(wide, LEVEL).tolist())
    b = set(dggs.polygon_to_cells(split, LEVEL).tolist())
    assert a == b == brute_force(split)
    assert len(a) > 0


def test_polar_cap():
    cap = box(-180, 75, 180, 90)
    assert set(dggs.polygon_to_cells(cap, LEVEL).tolist()) == brute_force(cap)


def test_whole_world_is_every_cell():
    assert len(dggs.polygon_to_cells(box(-180, -90, 180, 90), 3)) == dggs.get_num_cells(3)


def test_bad_input():
    with pytest.raises(DggsValueError, match="Polygon or MultiPolygon, not Point"):
        dggs.polygon_to_cells(Point(0, 0), 3)
    with pytest.raises(DggsValueError, match="not valid"):
        dggs.polygon_to_cells(Polygon([(0, 0), (1, 1), (1, 0), (0, 1)]), 3)
    with pytest.raises(LevelError):
        dggs.polygon_to_cells(box(0, 0, 1, 1), 99)
    assert len(dggs.polygon_to_cells(Polygon(), 3)) == 0
