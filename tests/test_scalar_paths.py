"""The pure-Python single-id paths agree exactly with the array paths."""

from __future__ import annotations

import numpy as np
from hypothesis import given
from hypothesis import strategies as st

import dggs

from .strategies import cells


@given(cells())
def test_single_id_paths_equal_array_paths(cell):
    arr = np.array([cell])
    assert dggs.get_level(cell) == int(dggs.get_level(arr)[0])
    assert dggs.get_face(cell) == int(dggs.get_face(arr)[0])
    assert dggs.edge_neighbors(cell).tolist() == dggs.edge_neighbors(arr)[0].tolist()
    if len(cell) > 1:
        assert dggs.cell_to_parent(cell) == str(dggs.cell_to_parent(arr)[0])
        assert dggs.cell_to_parent(cell, 0) == str(dggs.cell_to_parent(arr, 0)[0])
    if len(cell) <= dggs.MAX_LEVEL - 1:
        assert dggs.cell_to_children(cell).tolist() == dggs.cell_to_children(arr).tolist()
        assert dggs.cell_to_children(cell, len(cell) + 1).tolist() == dggs.cell_to_children(arr, len(cell) + 1).tolist()


@given(cells(max_level=25), st.integers(0, 3))
def test_single_id_disk_equals_array_disk(cell, k):
    row = dggs.grid_disk(np.array([cell]), k)[0]
    assert dggs.grid_disk(cell, k).tolist() == [c for c in row.tolist() if c]


@given(st.text(max_size=6))
def test_validity_agrees(text):
    assert dggs.is_valid_cell(text) == bool(dggs.is_valid_cell(np.array([text]))[0])


from .strategies import latlngs, levels, special_points  # noqa: E402


@given(latlngs(), levels())
def test_single_point_path_equals_array_path(p, level):
    lat, lng = p
    assert dggs.latlng_to_cell(lat, lng, level) == str(dggs.latlng_to_cell(np.array([lat]), np.array([lng]), level)[0])


def test_single_point_path_on_edges_corners_and_many_points():
    from dggs.index import _scalar

    rng = np.random.default_rng(17)
    lat = np.degrees(np.arcsin(rng.uniform(-1, 1, 3000)))
    lng = rng.uniform(-180, 180, 3000)
    special = np.array(special_points())
    corners = dggs.cell_to_boundary(dggs.latlng_to_cell(lat[:200], lng[:200], 9)).reshape(-1, 2)
    pts = np.concatenate([np.column_stack([lat, lng]), special, corners])
    for level in (0, 1, 2, 9, 17, 30, dggs.MAX_LEVEL):
        arr = dggs.latlng_to_cell(pts[:, 0], pts[:, 1], level)
        one = [dggs.latlng_to_cell(float(a), float(b), level) for a, b in pts]
        assert one == arr.tolist()
        # and the fast path itself answers (or declines) without ever disagreeing
        fast = [_scalar.latlng_to_cell(float(a), float(b), level) for a, b in pts[:3000]]
        assert sum(f is None for f in fast) < 0.01 * len(fast)


@given(cells())
def test_single_cell_centre_and_corners_match_array_paths(cell):
    lat, lng = dggs.cell_to_latlng(cell)
    alat, alng = dggs.cell_to_latlng(np.array([cell]))
    assert abs(lat - alat[0]) < 1e-11
    assert abs((lng - alng[0] + 180) % 360 - 180) * np.cos(np.radians(lat)) < 1e-11
    assert dggs.latlng_to_cell(lat, lng, len(cell) - 1) == cell
    one = np.array(dggs.cell_to_boundary(cell, densify=2))
    arr = dggs.cell_to_boundary(np.array([cell]), densify=2)[0]
    assert one.shape == arr.shape == (9, 2)
    assert np.abs(one[:, 0] - arr[:, 0]).max() < 1e-11
    dlng = np.abs((one[:, 1] - arr[:, 1] + 180) % 360 - 180) * np.cos(np.radians(one[:, 0]))
    assert dlng.max() < 1e-11
