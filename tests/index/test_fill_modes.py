"""polygon_to_cells modes "contains" and "overlaps" against a brute-force scan of every cell's polygon."""

from __future__ import annotations

import numpy as np
import pytest
import shapely
from hypothesis import given, settings
from hypothesis import strategies as st
from shapely.geometry import MultiPolygon, Point, Polygon, box

import dggs
from dggs.errors import DggsValueError

LEVEL = 4
ALL = dggs.cell_to_children(dggs.get_base_cells(), LEVEL)
ALL_POLYS = dggs.cell_to_polygon(ALL)  # the densified polygons, as the modes use them
ALL_LAT, ALL_LNG = dggs.cell_to_latlng(ALL)
shapely.prepare(ALL_POLYS)


def _wrapped(geom):
    """The oracle's target: parts beyond +-180 folded back (as polygon_to_cells reads them)."""
    minx, _, maxx, _ = geom.bounds
    if minx >= -180 and maxx <= 180:
        return geom
    parts = [
        shapely.affinity.translate(geom.intersection(box(-180 + 360 * k, -90, 180 + 360 * k, 90)), xoff=-360 * k)
        for k in (-1, 0, 1)
    ]
    return shapely.union_all([p for p in parts if not p.is_empty])


def oracle(geom, mode):
    target = _wrapped(geom)
    shapely.prepare(target)
    if mode == "contains":
        keep = shapely.contains(target, ALL_POLYS)
    elif mode == "overlaps":
        keep = shapely.intersects(target, ALL_POLYS)
    else:
        keep = shapely.contains_xy(target, ALL_LNG, ALL_LAT)
    return set(ALL[keep].tolist())


def fill(geom, mode, level=LEVEL):
    return set(dggs.polygon_to_cells(geom, level, mode=mode).tolist())


SHAPES = {
    "box": box(-10, -10, 10, 10),
    "disk": Point(40, 30).buffer(12),
    "donut": Point(10, 45).buffer(15).difference(Point(10, 45).buffer(6)),
    "antimeridian_beyond_180": box(170, -20, 195, 5),
    "antimeridian_split": MultiPolygon([box(170, -20, 180, 5), box(-180, -20, -165, 5)]),
    "north_cap": box(-180, 70, 180, 90),
    "south_cap": box(-180, -90, 180, -75),
    "near_north_pole": box(30, 80, 100, 89),
    "near_south_pole": box(-150, -88, 120, -70),
    "thin_sliver": box(0, 0, 40, 0.5),
    "tiny": box(5, 5, 5.5, 5.5),
}


@pytest.mark.parametrize("name", sorted(SHAPES))
@pytest.mark.parametrize("mode", ["contains", "overlaps", "center"])
def test_modes_match_brute_force(name, mode):
    geom = SHAPES[name]
    assert fill(geom, mode) == oracle(geom, mode)


@settings(max_examples=20, deadline=None)
@given(st.floats(-180, 175), st.floats(-89, 80), st.floats(0.5, 60), st.floats(0.5, 30))
def test_random_boxes_match_brute_force(lng0, lat0, w, h):
    geom = box(lng0, lat0, lng0 + w, min(lat0 + h, 90))
    for mode in ("contains", "overlaps"):
        assert fill(geom, mode) == oracle(geom, mode)


@pytest.mark.parametrize("name", sorted(SHAPES))
def test_contains_center_overlaps_nest(name):
    geom = SHAPES[name]
    inner, centre, outer = (fill(geom, m) for m in ("contains", "center", "overlaps"))
    assert inner <= centre <= outer


@pytest.mark.parametrize("name", ["box", "disk", "antimeridian_beyond_180", "north_cap", "near_south_pole"])
def test_overlaps_covers_the_polygon(name):
    geom = _wrapped(SHAPES[name])
    cells = sorted(fill(geom, "overlaps"))
    union = shapely.union_all(dggs.cell_to_polygon(np.array(cells)))
    # the densified cells tile the sphere up to the chords' slivers
    assert geom.difference(union).area < 1e-6 * geom.area


def test_deeper_level_modes_agree_with_own_edge_test():
    geom = Point(-75, 42).buffer(0.4)
    for mode, pred in (("contains", shapely.contains), ("overlaps", shapely.intersects)):
        got = dggs.polygon_to_cells(geom, 12, mode=mode)
        assert len(got) > 0
        assert pred(geom, dggs.cell_to_polygon(got)).all()
    # every overlapping cell's neighbours outside the result do not touch the polygon
    over = set(dggs.polygon_to_cells(geom, 12, mode="overlaps").tolist())
    ring = {n for c in over for n in dggs.edge_neighbors(c)} - over
    assert not shapely.intersects(geom, dggs.cell_to_polygon(np.array(sorted(ring)))).any()


def test_ints_and_strings_agree():
    geom = SHAPES["disk"]
    ints = dggs.polygon_to_cells(geom, LEVEL, mode="overlaps", as_int=True)
    assert ints.dtype == np.uint64
    assert dggs.int_to_str(ints).tolist() == sorted(fill(geom, "overlaps"))


def test_bad_mode_raises():
    with pytest.raises(DggsValueError, match="mode"):
        dggs.polygon_to_cells(box(0, 0, 1, 1), 3, mode="intersects")


def test_empty_polygon_any_mode():
    for mode in ("contains", "overlaps"):
        assert len(dggs.polygon_to_cells(Polygon(), 3, mode=mode)) == 0


def test_max_cells_applies_to_modes():
    with pytest.raises(dggs.TooManyCellsError):
        dggs.polygon_to_cells(box(-10, -10, 10, 10), 12, mode="overlaps", max_cells=1000)
