"""polygon_to_cells on the 177 Natural Earth countries against an independent brute force.

The oracle takes every cell of the level whose centre lies in the country's
bounding box (for a country given beyond 180 degrees, in the box shifted by
a turn) and keeps those whose centre shapely's ``contains_xy`` finds in the
country: the definition of mode ``"center"``, with no descent, footprint or
edge grid.  The countries have islands, holes (South Africa around
Lesotho), parts across the antimeridian (Fiji, Russia, whose edge at
180.00000000000006 leaves a line at -180 when folded back) and a pole
(Antarctica).  The modes ``"contains"`` and ``"overlaps"`` are checked the same
way against shapely's ``contains`` and ``intersects`` on the cells' polygons.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import shapely

import dggs

pyogrio = pytest.importorskip("pyogrio")
SHAPES = Path(pyogrio.__file__).parent / "tests/fixtures/naturalearth_lowres/naturalearth_lowres.shp"
if not SHAPES.exists():  # pragma: no cover - the fixture ships with pyogrio's wheels
    pytest.skip("pyogrio's Natural Earth fixture is not installed", allow_module_level=True)

COUNTRIES = pyogrio.read_dataframe(SHAPES)
NAMES = COUNTRIES["name"].tolist()
GEOMS = list(COUNTRIES.geometry.values)
#: A few countries at level 10: across the antimeridian, a pole, many islands, long and thin.
AT_10 = ["Fiji", "Russia", "Antarctica", "Canada", "Chile", "Indonesia", "Norway", "Lesotho"]

_CELLS: dict[int, tuple[np.ndarray, np.ndarray, np.ndarray]] = {}


def every_cell(level: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """All cells of a level with their centres (lat, lng), cached."""
    if level not in _CELLS:
        cells = np.asarray(dggs.cell_to_children(dggs.get_base_cells(as_int=True), level))
        lat, lng = dggs.cell_to_latlng(cells)
        _CELLS[level] = cells, lat, lng
    return _CELLS[level]


def near_bounds(geom, level: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The cells whose centres lie in the geometry's bounding box, with the longitudes to test them at."""
    cells, lat, lng = every_cell(level)
    minx, miny, maxx, maxy = geom.bounds
    picks = []
    for turn in (-360.0, 0.0, 360.0):
        x = lng + turn
        keep = (x >= minx) & (x <= maxx) & (lat >= miny) & (lat <= maxy)
        picks.append((cells[keep], lat[keep], x[keep]))
    return tuple(np.concatenate(p) for p in zip(*picks, strict=True))  # type: ignore[return-value]


def brute_force(geom, level: int) -> np.ndarray:
    cells, lat, lng = near_bounds(geom, level)
    return np.unique(cells[shapely.contains_xy(geom, lng, lat)])


def check(level: int, names: list[str]) -> None:
    for name in names:
        geom = GEOMS[NAMES.index(name)]
        got = np.asarray(dggs.polygon_to_cells(geom, level, as_int=True))
        want = brute_force(geom, level)
        assert got.tolist() == want.tolist(), (name, level, np.setxor1d(got, want)[:5])


@pytest.mark.parametrize("level", [6, 7, 8])
def test_every_country_at_levels_6_to_8(level):
    check(level, NAMES)


def test_some_countries_at_level_10():
    check(10, AT_10)


def test_the_oracle_sees_the_countries():
    assert sum(len(brute_force(g, 6)) for g in GEOMS) == 8443  # cells of 29,160: the countries cover 29 %
    assert len(brute_force(GEOMS[NAMES.index("Lesotho")], 8)) > 0  # the hole in South Africa, filled apart


def _folded(geom):
    """The country with its parts beyond +-180 moved a turn back (as polygon_to_cells reads it)."""
    minx, _, maxx, _ = geom.bounds
    if minx >= -180 and maxx <= 180:
        return geom
    box = shapely.box
    parts = [shapely.affinity.translate(geom.intersection(box(-180 + 360 * k, -90, 180 + 360 * k, 90)), -360 * k)
             for k in (-1, 0, 1)]
    return shapely.union_all([p for p in parts if not p.is_empty])


@pytest.mark.slow
@pytest.mark.parametrize("level", [4, 5])
def test_every_country_contains_and_overlaps(level):
    cells = every_cell(level)[0]
    tree = shapely.STRtree(dggs.cell_to_polygon(cells))
    for name, geom in zip(NAMES, GEOMS, strict=True):
        target = _folded(geom)
        for mode, predicate in (("contains", "contains"), ("overlaps", "intersects")):
            want = np.sort(cells[tree.query(target, predicate=predicate)])
            got = np.asarray(dggs.polygon_to_cells(geom, level, mode=mode, as_int=True))
            assert got.tolist() == want.tolist(), (name, mode, np.setxor1d(got, want)[:5])
