"""Edge neighbours, the mesh as a closed manifold, disks, rings and distances."""

from __future__ import annotations

from collections import Counter

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

import dggs
from dggs.errors import DggsValueError, InvalidCellError, LevelMismatchError

from ..gridref import mirror_neighbours
from ..strategies import cells


def all_cells(level):
    return dggs.get_base_cells() if level == 0 else dggs.cell_to_children(dggs.get_base_cells(), level)


def corner_keys(ids):
    """Corners of cells as rounded unit vectors on the sphere (independent of neighbour code)."""
    b = dggs.cell_to_boundary(ids)  # (N, 3, 2) geodetic degrees
    lat, lng = np.radians(b[..., 0]), np.radians(b[..., 1])
    xyz = np.stack([np.cos(lat) * np.cos(lng), np.cos(lat) * np.sin(lng), np.sin(lat)], axis=-1)
    return np.round(xyz, 9) + 0.0


@pytest.mark.parametrize("level", range(0, 5))
def test_mesh_is_a_closed_manifold(level):
    """Every edge (pair of shared corners on the sphere) belongs to exactly two cells."""
    ids = all_cells(level)
    keys = corner_keys(ids)
    edges = Counter()
    for tri in keys:
        pts = [tuple(p) for p in tri]
        for i in range(3):
            edges[frozenset((pts[i], pts[(i + 1) % 3]))] += 1
    assert set(edges.values()) == {2}
    # Euler characteristic of the sphere: V - E + F = 2
    verts = {tuple(p) for tri in keys for p in tri}
    assert len(verts) - len(edges) + len(ids) == 2


@pytest.mark.parametrize("level", range(0, 5))
def test_neighbours_exhaustive(level):
    ids = all_cells(level)
    nb = dggs.edge_neighbors(ids)
    index = {c: i for i, c in enumerate(ids.tolist())}
    keys = corner_keys(ids)
    for i, c in enumerate(ids.tolist()):
        row = nb[i].tolist()
        assert len(set(row)) == 3 and c not in row
        for j, other in enumerate(row):
            assert c in nb[index[other]].tolist()  # symmetric
            # and really across edge j: the two cells share exactly the corners j and j+1
            shared = {tuple(p) for p in keys[i]} & {tuple(p) for p in keys[index[other]]}
            assert shared == {tuple(keys[i][j]), tuple(keys[i][(j + 1) % 3])}


@given(cells(min_level=1))
def test_neighbours_random_cells_any_level(cell):
    nb = dggs.edge_neighbors(cell)
    assert len(set(nb)) == 3 and cell not in nb
    assert dggs.edge_neighbors(dggs.str_to_int(cell)) == dggs.str_to_int(nb)
    level = dggs.get_level(cell)
    assert all(dggs.get_level(n) == level for n in nb)
    for n in nb:
        assert cell in dggs.edge_neighbors(n)
        assert dggs.are_neighbor_cells(cell, n)


def test_neighbours_across_face_edges_and_at_poles():
    for lat, lng in [(90.0, 0.0), (-90.0, 0.0), (0.0, 180.0), (58.282525588539, 11.25)]:
        for level in (1, 5, 12, dggs.MAX_LEVEL):
            c = dggs.latlng_to_cell(lat, lng, level)
            for n in dggs.edge_neighbors(c):
                assert c in dggs.edge_neighbors(n)


@given(cells(min_level=1, max_level=14))
def test_disk_sizes_and_rings(cell):
    d1, d2 = dggs.grid_disk(cell, 1), dggs.grid_disk(cell, 2)
    assert len(d1) == 4 and cell in d1
    assert set(d1) <= set(d2)
    ring2 = dggs.grid_ring(cell, 2)
    assert set(ring2) == set(d2) - set(d1)
    assert dggs.grid_disk(dggs.str_to_int(cell), 2) == dggs.str_to_int(d2)
    for c in ring2:
        assert dggs.grid_distance(cell, c) == 2


def test_disk_sizes_in_a_face_interior():
    # 30-60-90 tiling: 3 neighbours; at distance 2 the two neighbours meeting at the
    # cell's right-angle corner (4 cells meet there) share their other neighbour: 6 - 1 = 5
    c = dggs.latlng_to_cell(45.0, -100.0, 12)
    sizes = [len(dggs.grid_disk(c, k)) for k in range(5)]
    assert sizes[:3] == [1, 4, 9]
    assert all(b > a for a, b in zip(sizes, sizes[1:], strict=False))


def test_bad_input():
    with pytest.raises(InvalidCellError, match="'Z1'"):
        dggs.edge_neighbors("Z1")
    with pytest.raises(DggsValueError, match="k -1"):
        dggs.grid_disk("C401", -1)
    with pytest.raises(LevelMismatchError):
        dggs.grid_distance("C401", "C40")


def test_digit_neighbours_equal_geometric_mirror_neighbours():
    """The digit-walk neighbours equal the mirror-the-centroid construction (random deep cells)."""
    rng = np.random.default_rng(9)
    lat = np.degrees(np.arcsin(rng.uniform(-1, 1, 5_000)))
    lng = rng.uniform(-180, 180, 5_000)
    for level in (1, 6, 7, 13, 25, dggs.MAX_LEVEL):
        cells = dggs.latlng_to_cell(lat, lng, level)
        assert np.array_equal(dggs.edge_neighbors(cells), mirror_neighbours(cells))
        ints = dggs.edge_neighbors(dggs.str_to_int(cells))
        assert np.array_equal(dggs.int_to_str(ints), mirror_neighbours(cells))
    mixed = np.concatenate([cells[:30], dggs.cell_to_parent(cells[:30], 4)])
    assert np.array_equal(dggs.edge_neighbors(mixed)[30:60], mirror_neighbours(mixed[30:60]))


@given(st.lists(cells(min_level=0, max_level=20), min_size=1, max_size=15), st.integers(0, 3))
def test_array_disks_equal_single_disks(cell_list, k):
    out = dggs.grid_disk(np.array(cell_list), k)
    assert out.shape[0] == len(cell_list)
    for row, c in zip(out, cell_list, strict=True):
        assert [x for x in row.tolist() if x] == dggs.grid_disk(c, k)


def test_disks_reject_bad_ids_at_every_k():
    for k in (0, 1, 2):
        with pytest.raises(InvalidCellError, match="'C9'"):
            dggs.grid_disk(np.array(["C401", "C9"]), k)
        with pytest.raises(InvalidCellError, match="'C9'"):
            dggs.grid_disk("C9", k)
