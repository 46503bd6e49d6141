"""The C core's dissolve (``dggs_cells_to_multi_polygon``, libdggs/src/multipolygon.c) against the cells' own polygons.

The oracle never sees the outline code: the cells' own ``dggs.cell_to_polygon`` (each already cut at the
antimeridian and closed over a pole), whose areas sum to the union's (the cells are disjoint) and each of which
has a point inside the answer (GEOS's union_all of them is no referee: round the South Pole at level 4 it loses
6 % of the area). Sets are disks, annuli (a shell in a hole in
a shell) and random halves of disks (cells touching at corners), centred at random points and pinned at the
poles, the antimeridian and the icosahedron's vertices and edges; the C answer must be valid, shells
counter-clockwise and holes clockwise, with the union's area (symmetric difference ~0).
"""

from __future__ import annotations

import numpy as np
import pytest
import shapely
from hypothesis import example, given, settings
from hypothesis import strategies as st
from shapely.geometry import MultiPolygon, Polygon
from shapely.validation import explain_validity

import dggs
from dggs.index._kernel import dissolve as kd
from tests.strategies import examples, latlngs, special_points

SPECIAL = special_points()


def core_polygons(cells: list[str], densify: int = 0) -> MultiPolygon:
    """The core's answer as shapely polygons (its rings are not closed; shapely closes them)."""
    ids = np.asarray(dggs.str_to_int(cells), np.uint64) if cells else np.zeros(0, np.uint64)
    got = kd.multi_polygon(np.ascontiguousarray(ids), densify, 0)
    assert not isinstance(got, int), got
    xy, ring_sizes, polygon_rings = got
    ends = np.cumsum(ring_sizes)
    rings = [xy[e - s : e] for s, e in zip(ring_sizes, ends, strict=True)]
    polys, k = [], 0
    for c in polygon_rings:
        polys.append(Polygon(rings[k], rings[k + 1 : k + c]))
        k += c
    return MultiPolygon(polys)


def check(cells: list[str]) -> None:
    got = core_polygons(cells)
    polys = dggs.cell_to_polygon(sorted(set(cells)), densify=0)
    assert got.is_valid, explain_validity(got)
    for p in got.geoms:
        assert p.exterior.is_ccw and not any(h.is_ccw for h in p.interiors)
    want = float(np.sum(shapely.area(polys)))  # the cells are disjoint: the union's area is their sum
    assert abs(got.area - want) <= 1e-9 * want
    inside = shapely.point_on_surface(polys)  # each cell's point lies in the answer
    assert bool(np.all(shapely.covers(got, inside)))


@settings(max_examples=examples(60), deadline=None)
@given(latlngs(), st.integers(1, 6), st.integers(0, 3), st.sampled_from(["disk", "annulus", "half"]), st.randoms())
@example((90.0, 0.0), 4, 2, "annulus", __import__("random").Random(0))
@example((-90.0, 0.0), 3, 3, "half", __import__("random").Random(1))
@example((0.0, 180.0), 5, 3, "annulus", __import__("random").Random(2))
@example((45.0, -180.0), 2, 1, "disk", __import__("random").Random(3))
@example(SPECIAL[6], 4, 3, "half", __import__("random").Random(4))  # an icosahedron vertex
@example(SPECIAL[20], 5, 2, "annulus", __import__("random").Random(5))
def test_core_dissolve_is_the_union(point, level, k, shape, rnd) -> None:
    centre = dggs.latlng_to_cell(point[0], point[1], level)
    disk = list(dggs.grid_disk(centre, k + 1))
    if shape == "annulus":
        ring = set(dggs.grid_ring(centre, k)) if k else {centre}
        cells = [c for c in disk if c not in ring]
    elif shape == "half":
        cells = [c for c in disk if rnd.random() < 0.5] or [centre]
    else:
        cells = disk
    check(cells)


def test_core_dissolve_globe_and_empty() -> None:
    """All 20 faces: the window (-180, -90, 180, 90); the globe less a disk: a hole in it; no cells: nothing."""
    globe = core_polygons(list(dggs.get_base_cells()))
    assert globe.equals(shapely.box(-180.0, -90.0, 180.0, 90.0))
    level2 = list(dggs.uncompact_cells(dggs.get_base_cells(), 2))
    gone = set(dggs.grid_disk(dggs.latlng_to_cell(20.0, 30.0, 2), 1))
    check([c for c in level2 if c not in gone])
    assert core_polygons([]).is_empty
    bad = kd.multi_polygon(np.array([0], np.uint64), 0, 0)
    assert bad == 3  # DGGS_E_CELL


@pytest.mark.parametrize(("lat", "lng", "level", "k"), [(90.0, 0.0, 4, 3), (-90.0, 0.0, 4, 3), (89.0, 180.0, 5, 4),
                                                        (0.0, 180.0, 3, 2), (-60.0, -180.0, 4, 2)])  # fmt: skip
def test_core_dissolve_round_poles_and_across_the_antimeridian(lat: float, lng: float, level: int, k: int) -> None:
    """Disks round each pole (closed over it along the window's frame) and across the antimeridian (cut there)."""
    check(list(dggs.grid_disk(dggs.latlng_to_cell(lat, lng, level), k)))
