"""cells_to_polygons against the cells' own polygons, summed and unioned (independent of the outline code).

The oracle never sees the outline code: the areas (geodesic on WGS84 by
pyproj.Geod, and in the (lng, lat) plane) are the sums over the cells'
``dggs.cell_to_polygon`` (for mixed levels, over the cells uncompacted to the
finest level), and the shape is compared with GEOS's union of those polygons
(the area of the symmetric difference).  The counts of polygons and holes come
from a brute-force search on the grid, where the outline is not cut at the
antimeridian or a pole; there the tests check what the cut should give.
"""

from __future__ import annotations

import numpy as np
import pytest
import shapely
from hypothesis import example, given, settings
from hypothesis import strategies as st
from pyproj import Geod
from shapely.geometry import MultiPolygon, Polygon

import dggs
from dggs.errors import DggsValueError, InvalidCellError
from dggs.index.dissolve import GLOBE, cells_to_polygons
from tests.strategies import examples, latlngs, special_points

GEOD = Geod(ellps="WGS84")
SPECIAL = special_points()


def _parts(g):
    return list(getattr(g, "geoms", [g]))


def _counts(g, least=0.0):
    """Polygons and holes of ``g``, those of area at most ``least`` left out (GEOS's slivers)."""
    parts = [p for p in _parts(g) if isinstance(p, Polygon) and p.area > least]
    return len(parts), sum(Polygon(h).area > least for p in parts for h in p.interiors)


def _components(cells):
    """(polygons, holes) by brute force on the grid, or (polygons, None) where holes cannot be told so.

    Polygons are the groups of cells joined by shared edges; a hole is a group of cells outside the set,
    joined by shared edges, that the set encloses (a search that stops at the set and gives up, as the
    outside, past n + 50 cells, or the largest) and whose bordering cells are all of one polygon.  Where a gap borders
    several polygons (cells touching at corners round it, or an island in a lake) it is not counted: None.
    """
    ids = {dggs.str_to_int(c) if isinstance(c, str) else int(c) for c in np.atleast_1d(cells).tolist()}

    def flood(start, inside, limit):
        seen, todo, rim = {start}, [start], set()
        while todo and len(seen) <= limit:
            for nb in dggs.edge_neighbors(todo.pop()):
                if (nb in ids) != inside:
                    rim.add(nb)
                elif nb not in seen:
                    seen.add(nb)
                    todo.append(nb)
        return seen, len(seen) <= limit, rim

    label: dict[int, int] = {}
    left = set(ids)
    while left:
        group = flood(next(iter(left)), True, len(ids))[0]
        label.update(dict.fromkeys(group, len(set(label.values()))))
        left -= group
    border = {nb for c in ids for nb in dggs.edge_neighbors(c)} - ids
    gaps, done = [], set()
    for c in sorted(border):
        if c not in done:
            seen, closed, rim = flood(c, False, len(ids) + 50)
            done |= seen
            gaps.append((len(seen) if closed else np.inf, len({label[r] for r in rim})))
    gaps.sort()
    gaps.pop()  # the largest gap is the outside (the ones given up on, or the rest of a small globe)
    gaps = [g for g in gaps if g[0] < np.inf]
    if any(polygons > 1 for _, polygons in gaps):
        return len(set(label.values())), None
    return len(set(label.values())), len(gaps)


def _as(cells, form):
    cells = list(np.atleast_1d(cells).tolist())
    return [dggs.str_to_int(c) for c in cells] if form == "int" else cells


def check_against_union(cells, densify=0, fine=None):
    """cells_to_polygons(cells) is the union of the polygons of ``fine`` (default: the cells; distinct, disjoint).

    The areas are the sums of the cells' own areas (geodesic, pyproj.Geod, and (lng, lat)); the shape is
    compared with GEOS's union (``union_all``, or ``coverage_union_all`` where the cascaded union lost area,
    as it does for some sets of large cells drawn with straight edges).
    """
    got = cells_to_polygons(cells, densify=densify)
    polys = np.atleast_1d(dggs.cell_to_polygon(cells if fine is None else fine, densify=densify))
    assert got.is_valid, shapely.is_valid_reason(got)
    if got.bounds != GLOBE.bounds:  # pyproj.Geod cannot measure a shell round the whole (lng, lat) rectangle
        geod_cells = sum(abs(GEOD.geometry_area_perimeter(p)[0]) for p in polys)
        assert abs(GEOD.geometry_area_perimeter(got)[0]) == pytest.approx(geod_cells, rel=1e-9)
    plane_cells = float(shapely.area(polys).sum())
    assert got.area == pytest.approx(plane_cells, rel=1e-9)
    union = shapely.union_all(polys)
    if abs(union.area - plane_cells) > 1e-9 * plane_cells:
        try:
            union = shapely.coverage_union_all(polys)
        except shapely.errors.GEOSException:  # a TopologyException on some blobs round a pole (level 4, k 4)
            union = None
    if union is None:  # no GEOS union to compare with: every cell inside the outline, and the same area, suffice
        assert float(shapely.area(shapely.difference(polys, got)).sum()) <= 1e-9 * plane_cells
        union = got
    assert union.area == pytest.approx(plane_cells, rel=1e-9)
    assert shapely.symmetric_difference(got, union).area <= 1e-9 * union.area
    xmin, ymin, xmax, ymax = union.bounds
    if -180.0 < xmin and xmax < 180.0 and -90.0 < ymin and ymax < 90.0:  # not cut: one polygon per component
        polygons, holes = _components(cells if fine is None else fine)
        assert _counts(got)[0] == polygons
        assert holes is None or _counts(got)[1] == holes
    return got


def _disk(lat, lng, level, k):
    return dggs.grid_disk(dggs.latlng_to_cell(lat, lng, level), k)


# -- random blobs, rings, holes ------------------------------------------------------------------------


@settings(max_examples=examples(30), deadline=None)
@given(
    seeds=st.lists(latlngs(), min_size=1, max_size=3),
    level=st.integers(2, 9),
    k=st.integers(0, 4),
    densify=st.sampled_from([0, 2]),
    form=st.sampled_from(["str", "int"]),
)
@example(seeds=[(90.0, 0.0)], level=5, k=3, densify=0, form="str")
@example(seeds=[(-90.0, 0.0)], level=5, k=3, densify=2, form="int")
@example(seeds=[(0.0, 180.0)], level=6, k=4, densify=0, form="int")
@example(seeds=[(45.0, -180.0), (45.0, 179.0)], level=4, k=2, densify=2, form="str")
@example(seeds=[SPECIAL[6]], level=3, k=2, densify=0, form="str")  # an icosahedron vertex
@example(seeds=[(0.0, 174.0), (-87.0, 0.0)], level=4, k=4, densify=0, form="str")  # GEOS: TopologyException
@example(seeds=[(0.0, 174.0), (-87.0, 0.0)], level=4, k=4, densify=2, form="int")
def test_random_blobs(seeds, level, k, densify, form):
    """Seeds grown by grid_disk (overlapping disks: duplicates merged), str and int ids alike."""
    cells = np.unique(np.concatenate([_disk(lat, lng, level, k) for lat, lng in seeds]))
    check_against_union(_as(cells, form), densify)


@settings(max_examples=examples(30), deadline=None)
@given(
    point=latlngs(),
    level=st.integers(3, 8),
    k=st.integers(2, 5),
    drop=st.lists(st.integers(0, 10_000), max_size=12),
    form=st.sampled_from(["str", "int"]),
)
@example(point=(90.0, 0.0), level=4, k=3, drop=[0, 5, 9], form="str")
@example(point=(0.0, -180.0), level=5, k=4, drop=[1, 7, 20], form="int")
def test_blobs_with_holes(point, level, k, drop, form):
    """A disk with cells taken out: holes, holes touching each other or the shell at a corner."""
    cells = list(_disk(*point, level, k))
    for d in sorted({d % len(cells) for d in drop}, reverse=True):
        cells.pop(d)
    if cells:
        check_against_union(_as(cells, form), 0)


@settings(max_examples=examples(30), deadline=None)
@given(
    point=latlngs(),
    level=st.integers(3, 7),
    seed=st.integers(0, 2**32 - 1),
    density=st.floats(0.3, 0.9),
    densify=st.sampled_from([0, 2]),
    form=st.sampled_from(["str", "int"]),
)
@example(point=(90.0, 180.0), level=3, seed=1, density=0.5, densify=0, form="str")
@example(point=(90.0, 0.8), level=4, seed=7, density=0.6, densify=2, form="int")
@example(point=(-90.0, -121.9), level=5, seed=3, density=0.4, densify=1, form="str")
@example(point=(10.0, 180.0), level=6, seed=5, density=0.5, densify=0, form="int")
def test_sparse_sets_touching_at_corners(point, level, seed, density, densify, form):
    """Random parts of a disk: many cells and holes touching at corners, where the shapes must stay valid."""
    disk = np.asarray(_disk(*point, level, 5))
    keep = disk[np.random.default_rng(seed).random(disk.size) < density]
    if keep.size:
        check_against_union(_as(keep, form), densify)


@pytest.mark.parametrize("lat,lng", SPECIAL[:18])
@pytest.mark.parametrize("form", ["str", "int"])
def test_a_cell_less_its_surroundings_is_one_hole(lat, lng, form):
    """The level-6 cells of the cells round a level-4 cell, less its own: one hole, of the cell's area."""
    c = dggs.latlng_to_cell(lat, lng, 4)
    cells = np.setdiff1d(dggs.uncompact_cells(dggs.grid_disk_vertex(c, 1), 6), dggs.uncompact_cells([c], 6))
    got = check_against_union(_as(cells, form), 1)
    xmin, ymin, xmax, ymax = got.bounds
    if -180.0 < xmin and xmax < 180.0 and -90.0 < ymin and ymax < 90.0:
        assert _counts(got) == (1, 1)
        hole = Polygon(got.interiors[0])
        # one point an edge: the hole's geodesic area is the cell's to the drawing's error, not to 1e-9
        assert abs(GEOD.geometry_area_perimeter(hole)[0]) == pytest.approx(dggs.cell_area(4), rel=1e-3)
    assert not got.covers(dggs.cell_to_polygon(c).representative_point())


def test_single_rings_of_corner_touching_cells():
    for c in ("C4010", "A0", dggs.latlng_to_cell(-89.9, 10, 5)):
        check_against_union(dggs.grid_ring(c, 3), 0)


# -- faces, poles, the antimeridian, the globe ------------------------------------------------------------


@pytest.mark.parametrize("faces", [["A"], ["A", "B", "C", "D", "E"], ["F", "K", "P"], list("KLMNOPQRST")])
def test_whole_faces(faces):
    """Faces as level-0 cells and as their level-2 descendants give the same outline as their union."""
    check_against_union(faces, 3)
    fine = dggs.uncompact_cells(faces, 2)
    check_against_union(fine, 0)


def test_blob_across_the_antimeridian_is_cut_there():
    cells = _disk(10.0, 179.95, 7, 6)
    got = check_against_union(cells, 2)
    assert got.geom_type == "MultiPolygon"
    xmin, _, xmax, _ = got.bounds
    assert xmin == -180.0 and xmax == 180.0


@pytest.mark.parametrize("lat", [90.0, -90.0])
def test_blob_around_a_pole_reaches_it(lat):
    got = check_against_union(_disk(lat, 0.0, 6, 5), 2)
    assert got.geom_type == "Polygon"
    _, ymin, _, ymax = got.bounds
    assert (ymax if lat > 0 else -ymin) == 90.0
    assert got.covers(shapely.Point(12.3, lat))


def test_hole_at_a_pole():
    c = dggs.latlng_to_cell(89.99, 0.0, 5)
    cells = np.setdiff1d(dggs.grid_disk(c, 6), dggs.grid_disk(c, 2))
    got = check_against_union(cells, 0)
    assert not got.covers(shapely.Point(0.0, 90.0))


@pytest.mark.parametrize("level", [0, 1, 2])
@pytest.mark.parametrize("form", ["str", "int"])
def test_whole_globe_is_the_documented_rectangle(level, form):
    cells = dggs.uncompact_cells(dggs.get_base_cells(), level)
    got = cells_to_polygons(_as(cells, form))
    assert got.equals(GLOBE) and got.bounds == (-180.0, -90.0, 180.0, 90.0)
    union = shapely.union_all(np.atleast_1d(dggs.cell_to_polygon(cells, densify=2)))
    assert got.area == pytest.approx(union.area, rel=1e-9) and union.area == pytest.approx(360.0 * 180.0, rel=1e-9)


@pytest.mark.parametrize("lat,lng", [(0.0, 0.0), (90.0, 0.0), (10.0, 180.0)])
def test_globe_less_a_blob(lat, lng):
    """The complement of a blob: the globe's rectangle with one hole (or cut round a pole)."""
    cells = np.setdiff1d(dggs.uncompact_cells(dggs.get_base_cells(), 3), _disk(lat, lng, 3, 1))
    check_against_union(cells, 0)


# -- mixed levels, duplicates -----------------------------------------------------------------------------


@settings(max_examples=examples(20), deadline=None)
@given(point=latlngs(), level=st.integers(3, 7), k=st.integers(2, 6), form=st.sampled_from(["str", "int"]))
@example(point=(90.0, 0.0), level=4, k=6, form="str")
@example(point=(0.0, 180.0), level=5, k=6, form="int")
def test_mixed_levels_equal_the_fine_union(point, level, k, form):
    """A compacted blob (coarse cells beside fine ones) is drawn along the fine cells' edges."""
    fine = _disk(*point, level, k)
    compact = dggs.compact_cells(fine)
    check_against_union(_as(compact, form), 0, fine=fine)


def test_face_beside_fine_cells():
    fine = np.concatenate([dggs.uncompact_cells(["A"], 4), _disk(40.0, 10.0, 4, 3)])
    mixed = np.concatenate([["A"], _disk(40.0, 10.0, 4, 3)])
    check_against_union(mixed, 0, fine=np.unique(fine))


def test_duplicates_and_ancestors_are_merged():
    blob = list(_disk(20.0, 30.0, 6, 3))
    parents = list(np.unique(dggs.cell_to_parent(blob, 5)))
    plain = cells_to_polygons(parents, densify=1)
    noisy = cells_to_polygons(blob + parents + parents[:3], densify=1)
    assert noisy.equals(plain)


# -- containers, errors ------------------------------------------------------------------------------------


def test_every_container_gives_the_same_outline():
    pd = pytest.importorskip("pandas")
    pa = pytest.importorskip("pyarrow")
    cells = _disk(-30.0, 100.0, 6, 3)
    ints = np.array(_as(cells, "int"), dtype=np.uint64)
    want = cells_to_polygons(list(cells))
    for obj in (np.asarray(cells), tuple(cells), ints, ints.astype(np.int64), pd.Series(cells), pa.array(ints),
                pa.chunked_array([pa.array(list(cells))])):
        assert cells_to_polygons(obj).equals(want)
    assert cells_to_polygons("C401").equals(dggs.cell_to_polygon("C401"))


def test_empty_set_is_an_empty_multipolygon():
    got = cells_to_polygons([])
    assert isinstance(got, MultiPolygon) and got.is_empty


@pytest.mark.parametrize("bad", [["C401", "Z1"], ["C4019"], [12345], "X"])
def test_bad_ids_are_named(bad):
    with pytest.raises(InvalidCellError) as err:
        cells_to_polygons(bad)
    assert str(bad[-1] if isinstance(bad, list) else bad) in str(err.value)


@pytest.mark.parametrize("densify", [-1, 1.5, "2", True])
def test_bad_densify(densify):
    with pytest.raises(DggsValueError, match="densify"):
        cells_to_polygons(["C401"], densify=densify)


def test_docstring_examples_run():
    import doctest

    import dggs.index.dissolve

    result = doctest.testmod(dggs.index.dissolve, optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    assert result.attempted >= 8 and result.failed == 0
