"""Vertices: the cells around each corner, against the geometry (shared corner points)."""

from __future__ import annotations

from collections import Counter, defaultdict

import numpy as np
import pytest

import dggs
from dggs.errors import DggsValueError, InvalidCellError
from dggs.index.vertex import (
    cell_to_vertexes,
    grid_disk_vertex,
    is_valid_vertex,
    vertex_neighbors,
    vertex_to_cells,
    vertex_to_latlng,
)

DECIMALS = 9  # unit-vector coordinates rounded to 1e-9 (6 mm): corners are >= 80 cm apart, computed to ~1e-12


def _xyz(latlng: np.ndarray) -> np.ndarray:
    lat, lng = np.radians(latlng[..., 0]), np.radians(latlng[..., 1])
    return np.stack([np.cos(lat) * np.cos(lng), np.cos(lat) * np.sin(lng), np.sin(lat)], axis=-1)


def geometric_fans(cells: np.ndarray) -> dict[tuple, set[str]]:
    """Rounded corner point -> the cells whose boundary has that corner."""
    corners = np.round(_xyz(dggs.cell_to_boundary(cells)), DECIMALS) + 0.0  # no -0.0
    fans: dict[tuple, set[str]] = defaultdict(set)
    for cell, pts in zip(cells.tolist(), corners, strict=True):
        for p in pts:
            fans[tuple(p)].add(cell)
    return fans


@pytest.mark.parametrize("level", [0, 1, 2, 3])
def test_vertex_neighbors_match_shared_corners_whole_level(level):
    cells = dggs.cell_to_children(dggs.get_base_cells(), level)
    fans = geometric_fans(cells)
    expected = defaultdict(set)
    for members in fans.values():
        for c in members:
            expected[c] |= members - {c}
    got = vertex_neighbors(cells)
    for cell, row in zip(cells.tolist(), got.tolist(), strict=True):
        assert {c for c in row if c} == expected[cell], cell
    sizes = Counter(len(m) for m in fans.values())
    if level == 0:
        assert set(sizes) == {5}
    else:  # level 1: 30-degree corners only at the icosahedron vertices
        assert set(sizes) == ({4, 6, 10} if level == 1 else {4, 6, 10, 12})
        assert sizes[10] == 12  # one per icosahedron vertex


@pytest.mark.parametrize("level", [0, 2, 3])
def test_vertex_ids_name_shared_corners_once(level):
    cells = dggs.cell_to_children(dggs.get_base_cells(), level)
    fans = geometric_fans(cells)
    vids = cell_to_vertexes(cells)
    assert vids.shape == (cells.size, 3)
    corners = np.round(_xyz(dggs.cell_to_boundary(cells)), DECIMALS) + 0.0
    by_point: dict[tuple, set[str]] = defaultdict(set)
    for row, pts in zip(vids.tolist(), corners, strict=True):
        for v, p in zip(row, pts, strict=True):
            by_point[tuple(p)].add(v)
    assert all(len(v) == 1 for v in by_point.values())  # one id per corner point
    assert len(set(vids.ravel().tolist())) == len(fans)  # and one corner point per id
    # V - E + F = 2 on the sphere: E = 3F / 2
    assert len(fans) - 3 * cells.size // 2 + cells.size == 2
    for point, (vid,) in list(by_point.items())[:200]:
        assert set(vertex_to_cells(vid)) == fans[point]
        assert is_valid_vertex(vid)
        np.testing.assert_allclose(_xyz(np.array(vertex_to_latlng(vid))), point, atol=2e-9)


RANDOM = np.random.default_rng(7)


def _random_cells(n: int, level: int) -> list[str]:
    lat = np.degrees(np.arcsin(RANDOM.uniform(-1, 1, n)))
    lng = RANDOM.uniform(-180, 180, n)
    return dggs.latlng_to_cell(lat, lng, level).tolist()


SPECIAL = [
    dggs.latlng_to_cell(90, 0, 12),
    dggs.latlng_to_cell(-90, 0, 12),
    dggs.latlng_to_cell(10, 180, 12),
    dggs.latlng_to_cell(58.2825255885, 11.25, 12),  # an icosahedron vertex
    dggs.latlng_to_cell(58.2825255885, 11.25, 20),
]


@pytest.mark.parametrize("cell", _random_cells(12, 9) + _random_cells(6, 18) + _random_cells(3, 27) + SPECIAL)
def test_vertex_neighbors_match_geometry_deep(cell):
    candidates = np.array(dggs.grid_disk(cell, 8))
    fans = geometric_fans(candidates)
    expected = set().union(*(m for m in fans.values() if cell in m)) - {cell}
    assert set(vertex_neighbors(cell)) == expected
    assert set(dggs.edge_neighbors(cell)) <= expected


@pytest.mark.parametrize("cell", _random_cells(10, 7) + SPECIAL)
def test_vertex_adjacency_is_symmetric(cell):
    for other in vertex_neighbors(cell):
        assert cell in vertex_neighbors(other)


def test_fan_sizes_around_special_points():
    v = cell_to_vertexes(dggs.latlng_to_cell(58.2825255885, 11.25, 5))
    assert sorted(len(vertex_to_cells(x)) for x in v) == [4, 6, 10]
    assert len(vertex_to_cells(cell_to_vertexes("C40120")[0])) in (4, 6, 12)


def test_grid_disk_vertex_rings():
    c = "C40120"
    assert grid_disk_vertex(c, 0) == [c]
    one = grid_disk_vertex(c, 1)
    assert one == sorted([c, *vertex_neighbors(c)])
    two = grid_disk_vertex(c, 2)
    assert set(two) == set(one).union(*(vertex_neighbors(x) for x in one))
    assert set(dggs.grid_disk(c, 2)) <= set(two)


def test_forms_and_arrays():
    cell = "C40120"
    as_int = dggs.str_to_int(cell)
    assert dggs.int_to_str(grid_disk_vertex(as_int, 1)) == grid_disk_vertex(cell, 1)
    assert dggs.int_to_str(vertex_neighbors(as_int)) == vertex_neighbors(cell)
    assert cell_to_vertexes(as_int) == cell_to_vertexes(cell)
    arr = grid_disk_vertex(np.array([cell, "C401"]), 1)
    assert arr.shape == (2, 17)
    assert [x for x in arr[1] if x] == grid_disk_vertex("C401", 1)


def test_errors():
    with pytest.raises(InvalidCellError):
        vertex_neighbors("Z9")
    with pytest.raises(DggsValueError):
        grid_disk_vertex("C401", -1)
    with pytest.raises(dggs.TooManyCellsError):
        grid_disk_vertex("C40120000", 5, max_cells=50)
    for bad in ("C401", "C401:3", "C401:0", 5, "Z1:0"):
        assert not is_valid_vertex(bad)
        with pytest.raises(DggsValueError):
            vertex_to_latlng(bad)


def test_disk_refused_before_any_work(monkeypatch):
    """Issue 17 item 10: a disk whose proven size bound is over max_cells is refused before the first ring.

    The bound is the edge disk of radius 6k (a corner-sharing step crosses at most 6 edges, the
    shorter way around a 12-cell corner), capped by the cells of the level.
    """
    import dggs.index.vertex as vx

    calls = []
    real = vx.kv.disk_row
    monkeypatch.setattr(vx.kv, "disk_row", lambda *a: calls.append(a) or real(*a))
    with pytest.raises(dggs.TooManyCellsError, match=r"k=300.*\d"):
        grid_disk_vertex("C4" + "0" * 27, 300, max_cells=1000)
    assert calls == []


def test_disk_rings_deduplicate_against_last_two_only(monkeypatch):
    """Issue 17 item 10: growing a ring never compares against everything seen (no union over the whole disk)."""
    import dggs.index.vertex as vx

    class NoWholeDiskSets:
        """numpy for vertex.py, without the set operations that would compare against the whole disk."""

        def __getattr__(self, name):
            if name in ("union1d", "setdiff1d", "isin", "in1d"):
                raise AssertionError(f"np.{name} over the disk")
            return getattr(np, name)

    monkeypatch.setattr(vx, "np", NoWholeDiskSets())
    got = grid_disk_vertex("C4012010", 6)
    # expected: breadth-first search over vertex_neighbors, independently of the ring code
    seen = {"C4012010"}
    front = {"C4012010"}
    for _ in range(6):
        front = {n for c in front for n in vertex_neighbors(c)} - seen
        seen |= front
    assert got == sorted(seen)


def test_vertex_verbs_equal_their_frozen_answers():
    """Issue 32 item 6: the corner walks and disks moved from numpy into the C core and no answer changed.

    ``tests/reference/fixtures/vertex_v1.json`` was written by ``libdggs/tools/freeze_vertex.py --write`` at the
    last commit where the walks recognised corners by projecting them in numpy: digests of grid_disk_vertex
    (string and integer ids, k 0-4, and k 40, 60 and 300 at level 28 round an icosahedron vertex, the antimeridian
    and the north pole), vertex_neighbors and cell_to_vertexes round the poles, the antimeridian, the 12
    icosahedron vertices and face-edge midpoints at levels 0-28, over whole levels 0-3 and at random cells.
    """
    import importlib.util
    from pathlib import Path

    root = Path(__file__).resolve().parents[2]
    spec = importlib.util.spec_from_file_location("freeze_vertex", root / "libdggs" / "tools" / "freeze_vertex.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    assert module.main(["--check", str(root / "tests" / "reference" / "fixtures" / "vertex_v1.json")]) == 0


@pytest.mark.parametrize("k", [0, 1, 2, 3, 7])
@pytest.mark.parametrize("cell", SPECIAL + ["C", "C4", "C40120"] + _random_cells(4, 28))
def test_grid_disk_vertex_is_breadth_first_over_shared_corners(cell, k):
    """The disk against a breadth-first search over the geometry: cells whose boundaries share a corner point."""
    seen = {cell}
    front = {cell}
    for _ in range(k):
        candidates = np.array(sorted({n for c in front for n in dggs.grid_disk(c, 6)}))
        fans = geometric_fans(candidates)
        front = {n for members in fans.values() if members & front for n in members} - seen
        seen |= front
    assert grid_disk_vertex(cell, k) == sorted(seen)
    assert grid_disk_vertex(dggs.str_to_int(cell), k) == sorted(dggs.str_to_int(c) for c in seen)
