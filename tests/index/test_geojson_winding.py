"""cells_to_geojson's rings (oriented by shapely.orient_polygons) against orient() of each polygon, and RFC 7946's winding."""

from __future__ import annotations

import numpy as np
import pytest
import shapely
from hypothesis import example, given, settings
from hypothesis import strategies as st
from shapely.geometry import MultiPolygon, Polygon, mapping, shape
from shapely.geometry.polygon import orient

import dggs

from ..strategies import cells, examples, special_points

#: Cells at the poles, on the antimeridian, at the icosahedron's vertices and edge midpoints.
SPECIAL = sorted({str(dggs.latlng_to_cell(lat, lng, level)) for lat, lng in special_points() for level in (0, 2, 7)})


def _one_by_one(ids: list[str], densify: int) -> list[dict]:
    """Each polygon oriented on its own, counter-clockwise exteriors (shapely.geometry.polygon.orient)."""
    out = []
    for poly in np.asarray(dggs.cell_to_polygon(np.array(ids), densify), dtype=object).reshape(-1):
        fixed = orient(poly, 1.0) if isinstance(poly, Polygon) else MultiPolygon([orient(p, 1.0) for p in poly.geoms])
        out.append(mapping(fixed))
    return out


def _check(ids: list[str], densify: int) -> None:
    ref = _one_by_one(ids, densify)
    for form in (ids, [int(dggs.str_to_int(i)) for i in ids]):
        fc = dggs.cells_to_geojson(form, densify=densify)
        geoms = [f["geometry"] for f in fc["features"]]
        assert geoms == ref
        assert [f["id"] for f in fc["features"]] == list(form)
        for g in geoms:
            for part in getattr(shape(g), "geoms", [shape(g)]):
                assert part.exterior.is_ccw and all(not r.is_ccw for r in part.interiors)


@settings(max_examples=examples(60), deadline=None)
@given(st.lists(cells(max_level=14), min_size=1, max_size=10), st.sampled_from([0, 2, 16]))
@example(["A", "T"], 0)
def test_rings_are_orient_of_each_polygon(ids, densify):
    _check(ids, densify)


@pytest.mark.parametrize("densify", [0, 16])
def test_poles_antimeridian_vertices_and_edges(densify):
    assert any(dggs.cell_to_polygon(c, densify).geom_type == "MultiPolygon" for c in SPECIAL)
    _check(SPECIAL, densify)


def test_clockwise_input_comes_out_counter_clockwise():
    # the oracle's own check: a clockwise ring is turned round by orient() and by shapely.orient_polygons alike
    cw = Polygon([(0, 0), (0, 1), (1, 1), (1, 0)])
    assert not cw.exterior.is_ccw
    assert shapely.orient_polygons(cw, exterior_cw=False).equals_exact(orient(cw, 1.0), 0)
