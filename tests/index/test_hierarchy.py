"""Parents, children, tiling, compaction: exhaustive at levels 0-4, random to MAX_LEVEL."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

import dggs
from dggs.errors import LevelMismatchError

from ..gridref import decode, planar_corners
from ..strategies import cells


def all_cells(level):
    return dggs.get_base_cells() if level == 0 else dggs.cell_to_children(dggs.get_base_cells(), level)


def kernel_corners(cells) -> np.ndarray:
    from dggs.index._kernel import points as _kpoints

    rows = [_kpoints.corners(np.uint64(dggs.str_to_int(c)))[1:] for c in cells]
    return np.array(rows).reshape(-1, 3, 2)


def planar_area(tri):
    a, b, c = tri[:, 0], tri[:, 1], tri[:, 2]
    return 0.5 * ((b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0]))


@pytest.mark.parametrize("level", range(0, 5))
def test_cell_counts(level):
    cells_ = all_cells(level)
    expected = 20 if level == 0 else 120 * 3 ** (level - 1)  # design card: 120 * 3^(n-1)
    assert len(cells_) == len(np.unique(cells_)) == expected == dggs.get_num_cells(level)


@pytest.mark.parametrize("level", range(1, 5))
def test_children_tile_the_parent_exhaustively(level):
    parents = all_cells(level - 1)
    kids = dggs.cell_to_children(parents)
    n = 6 if level == 1 else 3
    assert len(kids) == n * len(parents)
    assert np.all(dggs.cell_to_parent(kids) == np.repeat(parents, n))
    assert np.all(dggs.cell_to_parent(dggs.str_to_int(kids)) == dggs.str_to_int(np.repeat(parents, n)))
    tri_p = planar_corners(parents)
    tri_k = planar_corners(kids).reshape(len(parents), n, 3, 2)
    # areas add up, every child is congruent (same area) and lies inside its parent
    area_p = planar_area(tri_p)
    area_k = planar_area(tri_k.reshape(-1, 3, 2)).reshape(len(parents), n)
    assert np.allclose(area_k.sum(axis=1), area_p, rtol=1e-12)
    assert np.allclose(area_k, area_k.mean(), rtol=1e-12)
    for j in range(3):
        p, q = tri_p[:, j], tri_p[:, (j + 1) % 3]
        edge = q - p
        for corner in range(3):
            v = tri_k[:, :, corner] - p[:, None]
            cross = edge[:, None, 0] * v[..., 1] - edge[:, None, 1] * v[..., 0]
            assert cross.min() > -1e-13


@pytest.mark.parametrize("level", range(2, 5))
def test_cells_are_30_60_90_triangles(level):
    tri = planar_corners(all_cells(level))
    sides = np.sort(np.linalg.norm(tri - np.roll(tri, -1, axis=1), axis=2), axis=1)
    assert np.allclose(sides[:, 1] / sides[:, 0], np.sqrt(3), rtol=1e-12)
    assert np.allclose(sides[:, 2] / sides[:, 0], 2.0, rtol=1e-12)


@given(cells(min_level=1))
def test_parent_child_round_trip(cell):
    parent = dggs.cell_to_parent(cell)
    assert parent == cell[:-1]
    assert cell in dggs.cell_to_children(parent)
    assert dggs.cell_to_parent(cell, 0) == cell[0]


@given(cells(max_level=dggs.MAX_LEVEL - 2))
def test_grandchildren_and_center_child(cell):
    level = dggs.get_level(cell)
    kids = dggs.cell_to_children(cell, level + 2)
    assert len(kids) == (18 if level == 0 else 9)
    assert all(k.startswith(cell) for k in kids)
    centre_kid = dggs.cell_to_center_child(cell, level + 2)
    assert centre_kid in kids
    # the centre child's planar triangle holds the parent's planar centroid (the
    # centroid may sit exactly on a grandchild edge, so allow rounding)
    centroid = planar_corners([cell]).mean(axis=1)[0]
    tri = planar_corners([centre_kid])[0]
    size = np.linalg.norm(tri[1] - tri[0])
    for j in range(3):
        p, q = tri[j], tri[(j + 1) % 3]
        cross = (q[0] - p[0]) * (centroid[1] - p[1]) - (q[1] - p[1]) * (centroid[0] - p[0])
        assert cross / size >= -1e-6 * size  # rounding: ~1e-16 absolute, 1e-6 of a level-40 cell


def test_parent_errors():
    with pytest.raises(LevelMismatchError, match="base cell 'C' has no parent"):
        dggs.cell_to_parent("C")
    with pytest.raises(LevelMismatchError, match="parent level 5 is finer"):
        dggs.cell_to_parent("C401", 5)
    with pytest.raises(LevelMismatchError, match="child level 2 is coarser"):
        dggs.cell_to_children("C401", 2)


@given(st.lists(cells(min_level=2, max_level=6), min_size=1, max_size=20))
def test_compact_uncompact_round_trip(cell_list):
    level = 7
    full = dggs.uncompact_cells(cell_list, level)
    compacted = dggs.compact_cells(full)
    assert dggs.uncompact_cells(compacted, level) == full
    ints = dggs.str_to_int(cell_list)
    assert dggs.int_to_str(dggs.uncompact_cells(ints, level)) == full
    assert dggs.int_to_str(dggs.compact_cells(dggs.uncompact_cells(ints, level))) == compacted
    assert len(compacted) <= len(full)
    # compaction is minimal: no complete set of siblings remains
    for c in compacted:
        if len(c) > 1:
            sibs = dggs.cell_to_children(c[:-1])
            assert not set(sibs) <= set(compacted)


def test_compact_all_children_of_a_face_gives_the_face():
    assert dggs.compact_cells(dggs.cell_to_children("H", 3)) == ["H"]
    assert dggs.compact_cells(all_cells(2)).tolist() == all_cells(0).tolist()


def test_uncompact_rejects_finer_cells():
    with pytest.raises(LevelMismatchError):
        dggs.uncompact_cells(["C4011"], 3)


def test_shipped_jump_table_equals_the_computed_one():
    """The kernel loads split26's jump table from dggs/geometry/jump_table.npz: it must be that table."""
    from dggs.geometry import kernel

    table, packed, maps = kernel.jump_constants()
    assert np.array_equal(kernel.JUMP_TABLE, table)
    assert np.array_equal(kernel.JUMP_PACKED, packed)
    assert np.array_equal(kernel.JUMP_MAPS, maps)


def test_jump_table_locate_equals_per_level_descent():
    """The 4-levels-at-once table reproduces the per-level comparisons exactly."""
    from dggs.geometry import snyder

    from ..reference.numpy_split26 import locate, locate_per_level

    rng = np.random.default_rng(21)
    lat = np.degrees(np.arcsin(rng.uniform(-1, 1, 200_000)))
    lng = rng.uniform(-180, 180, 200_000)
    _, x, y = snyder.forward(lat, lng)
    for level in (5, 9, 13, 21, 28):
        assert np.array_equal(locate(x, y, level), locate_per_level(x, y, level))


def test_locate_nests_for_points_exactly_on_corners_and_edges():
    """Digits of a level never depend on how deep the lookup goes, even on cell edges."""
    from ..reference.numpy_split26 import locate

    corners = planar_corners(dggs.cell_to_children("C4", 6))
    pts = np.concatenate([corners.reshape(-1, 2), 0.5 * (corners + np.roll(corners, 1, axis=1)).reshape(-1, 2)])
    x, y = pts[:, 0].copy(), pts[:, 1].copy()
    deepest = locate(x, y, dggs.MAX_LEVEL)
    for level in range(1, dggs.MAX_LEVEL):
        assert np.array_equal(locate(x, y, level), deepest[:, :level])


@given(cells(min_level=0, max_level=dggs.MAX_LEVEL - 1))
def test_children_tile_the_parent_at_any_level(cell):
    kids = dggs.cell_to_children(cell)
    assert kids == [cell + d for d in ("012345" if len(cell) == 1 else "012")]
    assert dggs.cell_to_children(dggs.str_to_int(cell)) == dggs.str_to_int(kids)
    tri_p = planar_corners([cell])[0]
    tri_k = planar_corners(kids)
    area_p = planar_area(tri_p[None])[0]
    area_k = planar_area(tri_k)
    assert area_k.sum() == pytest.approx(area_p, rel=1e-6)  # deep levels: corners carry ~1e-16 absolute
    assert np.allclose(area_k, area_k.mean(), rtol=1e-5)
    size = np.linalg.norm(tri_p[1] - tri_p[0])
    for j in range(3):
        p, q = tri_p[j], tri_p[(j + 1) % 3]
        v = tri_k.reshape(-1, 2) - p
        cross = (q[0] - p[0]) * v[:, 1] - (q[1] - p[1]) * v[:, 0]
        assert cross.min() / size > -1e-6 * size


def test_block_composed_corners_equal_midpoint_construction():
    """Corners composed 4 digits at a time equal the thesis's construction (D at a third, E midpoint)."""
    from dggs.geometry.split26 import cell_vertices

    from ..reference.numpy_split26 import cell_vertices_per_level

    rng = np.random.default_rng(33)
    lat = np.degrees(np.arcsin(rng.uniform(-1, 1, 5000)))
    lng = rng.uniform(-180, 180, 5000)
    mixed = np.concatenate([dggs.latlng_to_cell(lat, lng, lv) for lv in (1, 2, 5, 6, 9, 17, 28)])
    _, level, l1, digits = decode(mixed)
    fast = cell_vertices(l1, digits, level)
    ref = cell_vertices_per_level(l1, digits, level)
    size = np.linalg.norm(ref[0] - ref[2], axis=1)
    for a, b in zip(fast, ref, strict=True):
        assert (np.abs(a - b).max(axis=1) / size).max() < 1e-8
    # the kernel builds corners level by level in floats: the same triangles
    tri = planar_corners(mixed)
    kern = kernel_corners(mixed)
    scale = np.linalg.norm(tri[:, 0] - tri[:, 1], axis=1)
    assert (np.abs(kern - tri).max(axis=(1, 2)) / scale).max() < 1e-7


@given(st.lists(cells(max_level=dggs.MAX_LEVEL), min_size=1, max_size=6), st.booleans())
def test_center_child_of_many_cells_goes_one_level_down_from_each(many, as_int):
    """The default level is each cell's own level + 1 (a level-28 cell is its own), in a container as alone: a list
    of cells of mixed levels went one level below the deepest of them."""
    ids = dggs.str_to_int(many) if as_int else many
    got = dggs.cell_to_center_child(ids)
    got = dggs.int_to_str(got) if as_int else got
    want = [dggs.cell_to_center_child(c, min(dggs.get_level(c) + 1, dggs.MAX_LEVEL)) for c in many]
    assert list(got) == want
    assert all(dggs.get_level(g) == min(dggs.get_level(c) + 1, dggs.MAX_LEVEL) for g, c in zip(got, many, strict=True))


def test_center_child_of_mixed_levels_pinned():
    assert dggs.cell_to_center_child(["C401", "A0000000000"]) == ["C4011", "A00000000001"]
