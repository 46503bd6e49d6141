"""Local (i, j) coordinates around an anchor: exact inverses, one pair per cell, and the lattice's geometry.

Oracles: brute-force enumeration of every cell of a level; the anchor's range
from the faces' own adjacency (``edge_neighbors`` of the base cells); and the
geometry of the 30-60-90 tiling: a cell's neighbour across an edge is its
mirror image, so their centroids are twice the centroid-to-side distance
apart.  In a right triangle with legs 1 and sqrt(3) those distances are
sqrt(3)/3, 1/3 and sqrt(3)/6 of the short leg, squared in the ratio 12 : 4 : 3; in the
lattice's basis (two axes 120 degrees apart) the squared length of (i, j) is
i^2 + j^2 - i j, so the three neighbours of every cell must sit at exactly
{3, 4, 12} (the level's unit is the same everywhere, the unfolded faces included).
"""

from __future__ import annotations

import numpy as np
import pandas as pd
import pyarrow as pa
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

import dggs
from dggs.errors import DggsValueError, DistortionError, InvalidCellError, LevelMismatchError

from ..strategies import cells, examples, special_points


def all_cells(level):
    return list(dggs.get_base_cells()) if level == 0 else dggs.cell_to_children(list(dggs.get_base_cells()), level)


def region_faces(anchor: str) -> set[str]:
    """The anchor's face and the three across its edges (from the base cells' adjacency)."""
    return {anchor[0], *dggs.edge_neighbors(anchor[0])}


def sector_edges(cells_: list[str]) -> list[frozenset[int]]:
    """The icosahedron edge (its two vertex numbers) bounding the 120-degree sector of Snyder's projection that holds
    each cell (level >= 1): the sector between a face's vertices n and n + 1 (``split26.FACE_VERTICES``, at planar
    azimuths 0, 120 and 240 degrees clockwise from +y), found from the cell's planar centroid by azimuth
    (tests.gridref, numpy, independent of the kernel)."""
    from dggs.geometry.icosahedron import ISEA

    from ..gridref import FACES, planar_corners

    fv = ISEA.geometry.face_vertices
    out = []
    for cell, (x, y) in zip(cells_, planar_corners(cells_).mean(axis=1), strict=True):
        t = int((np.degrees(np.arctan2(x, y)) % 360) // 120)
        f = FACES.index(cell[0])
        out.append(frozenset((int(fv[f][t]), int(fv[f][(t + 1) % 3]))))
    return out


def in_chart(anchor: str, cells_: list[str]) -> list[bool]:
    """The cells local (i, j) answers for around ``anchor`` (docs/grid.md, "Local coordinates"): at level 0 the
    anchor's face and the three across its edges; finer, the cells whose sector is bounded by the same icosahedron
    edge as the anchor's (the anchor's sector and its mirror image across that face edge)."""
    if len(anchor) == 1:
        return [c[0] in region_faces(anchor) for c in cells_]
    edge = sector_edges([anchor])[0]
    return [e == edge for e in sector_edges(cells_)]


def split_chart(anchor: str, cells_: list[str]) -> tuple[list[str], list[str]]:
    """(inside, outside) of the anchor's chart, in order."""
    ok = in_chart(anchor, cells_)
    return [c for c, o in zip(cells_, ok, strict=True) if o], [c for c, o in zip(cells_, ok, strict=True) if not o]


def norm(i, j):
    return i * i + j * j - i * j


def special_cells(level: int) -> list[str]:
    lat, lng = zip(*special_points(), strict=True)
    return sorted(set(dggs.latlng_to_cell(list(lat), list(lng), level)))


@pytest.mark.parametrize("level", [0, 1, 2, 3])
def test_exhaustive_round_trip_and_uniqueness(level):
    every = all_cells(level)
    rng = np.random.default_rng(level)
    anchors = sorted(set(special_cells(level)) | set(rng.choice(every, 8).tolist()))
    for anchor in anchors:
        inside, outside = split_chart(anchor, every)
        i, j = dggs.cell_to_local_ij(anchor, inside)
        assert dggs.cell_to_local_ij(anchor, anchor) == (0, 0)
        assert len(set(zip(i, j, strict=True))) == len(inside)  # one pair per cell
        assert dggs.local_ij_to_cell(anchor, i, j) == inside
        ai = dggs.str_to_int(anchor)
        assert dggs.local_ij_to_cell(ai, np.array(i), np.array(j)).tolist() == dggs.str_to_int(inside)
        for c in outside[:: max(1, len(outside) // 10)]:
            with pytest.raises(DistortionError, match=f"{c}.*{anchor}"):
                dggs.cell_to_local_ij(anchor, c)
        # every other integer pair in the box names no cell
        taken = set(zip(i, j, strict=True))
        box = [(a, b) for a in range(min(i) - 2, max(i) + 3, 3) for b in range(min(j) - 2, max(j) + 3, 2) if (a, b) not in taken]
        for a, b in box[:: max(1, len(box) // 25)]:
            with pytest.raises(DggsValueError, match=f"\\({a}, {b}\\)"):
                dggs.local_ij_to_cell(anchor, a, b)


@pytest.mark.parametrize("level", [0, 1, 2, 3])
def test_neighbours_are_mirror_images(level):
    """Every cell's three edge neighbours (within the range) at squared lattice lengths {3, 4, 12}, across face edges too."""
    every = all_cells(level)
    for anchor in special_cells(level)[:6]:
        inside, _ = split_chart(anchor, every)
        ij = dict(zip(inside, zip(*dggs.cell_to_local_ij(anchor, inside), strict=True), strict=True))
        crossings = 0
        for c in inside:
            near = [n for n in dggs.edge_neighbors(c) if n in ij]
            got = {norm(ij[n][0] - ij[c][0], ij[n][1] - ij[c][1]) for n in near}
            crossings += sum(n[0] != c[0] for n in near)
            if level == 0:  # the faces: equilateral triangles, their centroids one step apart
                assert got == {1}
            elif len(near) == 3:
                assert got == {3, 4, 12}, (c, near)
            else:
                assert got <= {3, 4, 12}
        assert crossings > 0  # face edges crossed


@settings(max_examples=examples(100))
@given(anchor=cells(max_level=28), k=st.integers(1, 4), as_int=st.booleans())
@example(anchor="A" + "0" * 28, k=3, as_int=False)
@example(anchor="T5" + "2" * 27, k=3, as_int=True)
@example(anchor="C", k=1, as_int=True)
def test_round_trip_around_any_anchor(anchor, k, as_int):
    """All cells of a disk around the anchor: on the range, exact inverses; off it, refused (their face tells)."""
    disk = dggs.grid_disk(anchor, k)
    inside, outside = split_chart(anchor, disk)
    a = dggs.str_to_int(anchor) if as_int else anchor
    ids = dggs.str_to_int(inside) if as_int else inside
    i, j = dggs.cell_to_local_ij(a, ids)
    assert len(set(zip(i, j, strict=True))) == len(inside)
    assert dggs.local_ij_to_cell(a, i, j) == ids
    for c, n in zip(inside, dggs.edge_neighbors(inside), strict=True):
        for m in n:
            if m in inside:
                di = i[inside.index(m)] - i[inside.index(c)]
                dj = j[inside.index(m)] - j[inside.index(c)]
                assert norm(di, dj) in ({3, 4, 12} if len(anchor) > 1 else {1})
    for c in outside:
        with pytest.raises(DistortionError):
            dggs.cell_to_local_ij(a, dggs.str_to_int(c) if as_int else c)


@pytest.mark.parametrize("level", [5, 17, 28])
def test_special_cells(level):
    """Anchors at poles, the antimeridian, icosahedron vertices and edges: their neighbours and back."""
    for anchor in special_cells(level):
        ring, _ = split_chart(anchor, dggs.grid_disk(anchor, 2))
        i, j = dggs.cell_to_local_ij(anchor, ring)
        assert dggs.local_ij_to_cell(anchor, i, j) == ring
        assert {norm(a, b) for a, b, c in zip(i, j, ring, strict=True) if c in dggs.edge_neighbors(anchor)} <= {3, 4, 12}


def test_containers_and_broadcasting():
    i, j = dggs.cell_to_local_ij(np.array(["C401", "C401"]), np.array(["C402", "C400"]))
    assert isinstance(i, np.ndarray) and i.tolist() == [4, -1] and j.tolist() == [2, 1]
    s = dggs.cell_to_local_ij("C401", pd.Series(["C402", "C400"], index=[7, 8]))
    assert s[0].index.tolist() == [7, 8] and s[0].tolist() == [4, -1]
    assert dggs.cell_to_local_ij("C401", pa.array(["C402"]))[1].to_pylist() == [2]
    out = dggs.local_ij_to_cell(dggs.str_to_int("C401"), pd.Series([4, -1]), pd.Series([2, 1]))
    assert isinstance(out, pd.Series) and out.tolist() == dggs.str_to_int(["C402", "C400"])
    assert dggs.local_ij_to_cell(["C401", "C402"], 0, 0) == ["C401", "C402"]


def test_invalid_inputs():
    with pytest.raises(LevelMismatchError, match="C40"):
        dggs.cell_to_local_ij("C401", "C40")
    with pytest.raises(InvalidCellError, match="Z1"):
        dggs.cell_to_local_ij("Z1", "C4")
    with pytest.raises(DggsValueError, match="'T'"):  # T shares no edge with A
        dggs.cell_to_local_ij("A", "T")
    for bad in (1.5, True, None, "1"):
        with pytest.raises(DggsValueError, match="must be an integer"):
            dggs.local_ij_to_cell("C401", bad, 0)
    with pytest.raises(DggsValueError, match="names no cell"):
        dggs.local_ij_to_cell("C401", 1, 0)
    with pytest.raises(DggsValueError, match="names no cell"):
        dggs.local_ij_to_cell("C401", 10**9, -(10**9))


def _unfolded_centroids(anchor: str, cells_: list[str]) -> np.ndarray:
    """Planar centroids of cells in the anchor's face frame, each adjacent face unfolded into it by the rigid motion
    that fixes the two vertices it shares with the anchor's face (docs/grid.md, "Local coordinates").

    Independent of the kernel: corners from :func:`tests.gridref.planar_corners` (numpy Split(2:6)), the faces'
    vertex ids from the icosahedron, their planar positions from ``split26.FACE_VERTICES``.
    """
    from dggs.geometry.icosahedron import ISEA
    from dggs.geometry.split26 import FACE_VERTICES

    from ..gridref import FACES, planar_corners

    fv = ISEA.geometry.face_vertices
    f = FACES.index(anchor[0])
    centres = planar_corners(cells_).mean(axis=1)
    out = np.empty_like(centres)
    for n, (cell, c) in enumerate(zip(cells_, centres, strict=True)):
        g = FACES.index(cell[0])
        if g == f:
            out[n] = c
            continue
        shared = [v for v in fv[g] if v in fv[f]]
        assert len(shared) == 2, (anchor, cell)  # answered only on a face across an edge
        pf = [FACE_VERTICES[list(fv[f]).index(v)] for v in shared]
        pg = [FACE_VERTICES[list(fv[g]).index(v)] for v in shared]
        (dfx, dfy), (dgx, dgy) = pf[1] - pf[0], pg[1] - pg[0]
        turn = np.arctan2(dfy, dfx) - np.arctan2(dgy, dgx)
        rot = np.array([[np.cos(turn), -np.sin(turn)], [np.sin(turn), np.cos(turn)]])
        out[n] = rot @ (c - pg[0]) + pf[0]
    return out


VERTEX_AND_EDGE_POINTS = special_points()[6:]  # the 12 icosahedron vertices, then the face-edge midpoints


def _anchor(grid, point, offset, level, as_int):
    """The anchor of a drawn example: the issue's two (point (0, 0)) or the cell at point + offset on ``grid``."""
    if point == (0.0, 0.0):  # the two anchors of the issue
        return "K110121" if not as_int else "E222202"
    lat = float(np.clip(point[0] + offset[0], -90, 90))
    return grid.latlng_to_cell(lat, point[1] + offset[1], level)


@settings(max_examples=examples(60), deadline=None)
@given(
    point=st.sampled_from(VERTEX_AND_EDGE_POINTS),
    offset=st.tuples(st.floats(-0.3, 0.3), st.floats(-0.3, 0.3)),
    level=st.integers(1, 13),
    k=st.integers(1, 6),
    as_int=st.booleans(),
)
@example(point=(0.0, 0.0), offset=(0.0, 0.0), level=6, k=8, as_int=False).via("issue 32: K110121")
@example(point=(0.0, 0.0), offset=(0.0, 0.0), level=6, k=8, as_int=True).via("issue 32: E222202")
@example(point=VERTEX_AND_EDGE_POINTS[0], offset=(0.0, 0.0), level=13, k=6, as_int=True)
@example(point=VERTEX_AND_EDGE_POINTS[12], offset=(0.0, 0.0), level=3, k=6, as_int=False)
def test_local_ij_is_one_lattice_wherever_it_answers(point, offset, level, k, as_int):
    """Issue 32 item 4: round anchors at icosahedron vertices and face edges, the (i, j) of every cell that answers
    are one affine map of the cells' centroids in the unfolded face plane, to 1e-9 of a lattice unit (a cell's
    nearest neighbour is sqrt(3) units away), and the other cells are refused with a DggsValueError.

    (Cell centres on the sphere are not an affine image of the chart, anywhere: Snyder's projection is not affine
    within a face, so a fit to geodetic centres leaves a residual growing with the neighbourhood, 0.1-0.9 units at
    radius 5 at level 6; docs/grid.md, "Local coordinates".)
    """
    anchor = _anchor(dggs.Grid("ISEA"), point, offset, level, as_int)
    disk = dggs.grid_disk(anchor, k)
    a = dggs.str_to_int(anchor) if as_int else anchor
    answered, ij = [], []
    for cell in disk:
        try:
            ij.append(dggs.cell_to_local_ij(a, dggs.str_to_int(cell) if as_int else cell))
            answered.append(cell)
        except DistortionError:
            assert not in_chart(anchor, [cell])[0]
    assert anchor in answered and len(answered) >= 3
    xy = _unfolded_centroids(anchor, answered)
    design = np.c_[xy, np.ones(len(answered))]
    target = np.array(ij, dtype=float)
    coef, *_ = np.linalg.lstsq(design, target, rcond=None)
    assert np.abs(design @ coef - target).max() < 1e-9


#: The worst residual of an affine fit of geodetic cell centres to (i, j), in cell sizes (the square root of the
#: anchor's area), over grid_disk(anchor, k <= 5) where local (i, j) answers, per projection. Measured: ISEA 0.142,
#: IVEA 0.169 (every anchor of face C at level 6, all of level 3, anchors near its vertices at levels 8-13; the
#: projections are smooth but not affine within a sector, most near a vertex). Before the chart kept to one sector
#: and its mirror image: ISEA 0.39 at K110121, 0.53 at E222202 (k = 5), 0.28 at the cells on an icosahedron vertex
#: (k = 3); IVEA 0.38 at E222202.
SPHERE_FIT_BOUND = {"ISEA": 0.16, "IVEA": 0.2}


@settings(max_examples=examples(60), deadline=None)
@given(
    point=st.sampled_from(special_points()),
    offset=st.tuples(st.floats(-1.0, 1.0), st.floats(-1.0, 1.0)),
    level=st.integers(3, 13),
    k=st.integers(1, 5),
    as_int=st.booleans(),
    projection=st.sampled_from(["ISEA", "IVEA"]),
)
@example(point=(0.0, 0.0), offset=(0.0, 0.0), level=6, k=5, as_int=False, projection="ISEA").via("issue 32: K110121")
@example(point=(0.0, 0.0), offset=(0.0, 0.0), level=6, k=5, as_int=True, projection="ISEA").via("issue 32: E222202")
@example(point=(0.0, 0.0), offset=(0.0, 0.0), level=6, k=5, as_int=True, projection="IVEA")
@example(point=(90.0, 0.0), offset=(0.0, 0.0), level=9, k=5, as_int=False, projection="ISEA")
@example(point=(0.0, 180.0), offset=(0.0, 0.0), level=13, k=5, as_int=True, projection="IVEA")
@example(point=special_points()[6], offset=(0.0, 0.0), level=8, k=5, as_int=False, projection="ISEA")
def test_local_ij_fits_the_sphere_wherever_it_answers(point, offset, level, k, as_int, projection):
    """Issue 32 item 4: round poles, the antimeridian, icosahedron vertices and face edges, on both projections, the
    (i, j) local coordinates answer for are one affine image of the cells' geodetic centres (in an azimuthal
    equidistant projection at the anchor, from PROJ), to SPHERE_FIT_BOUND cell sizes; the others are refused with a
    DistortionError naming cell and anchor, exactly where the chart oracle (sector edges from tests.gridref) says."""
    import pyproj

    grid = dggs.Grid(projection)
    anchor = _anchor(grid, point, offset, level, as_int)
    disk = dggs.grid_disk(anchor, k)
    a = dggs.str_to_int(anchor) if as_int else anchor
    answered, ij = [], []
    for cell, ok in zip(disk, in_chart(anchor, disk), strict=True):
        c = dggs.str_to_int(cell) if as_int else cell
        if ok:
            ij.append(grid.cell_to_local_ij(a, c))
            answered.append(cell)
            assert grid.local_ij_to_cell(a, *ij[-1]) == c
        else:
            with pytest.raises(DistortionError, match=f"{cell}.*{anchor}"):
                grid.cell_to_local_ij(a, c)
    lat0, lng0 = grid.cell_to_latlng(anchor)
    aeqd = pyproj.Proj(proj="aeqd", lat_0=lat0, lon_0=lng0, ellps="WGS84")
    lat, lng = np.array([grid.cell_to_latlng(c) for c in answered]).T
    xy = np.c_[aeqd(lng, lat)]
    design = np.c_[np.array(ij, dtype=float), np.ones(len(answered))]
    coef, *_ = np.linalg.lstsq(design, xy, rcond=None)
    worst = np.linalg.norm(design @ coef - xy, axis=1).max() / np.sqrt(grid.cell_area(anchor, unit="m^2"))
    assert worst < SPHERE_FIT_BOUND[projection], (anchor, k, worst)
