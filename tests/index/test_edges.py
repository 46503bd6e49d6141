"""Directed edges against the neighbour sets of edge_neighbors, the shared corners of cell_to_boundary and pyproj.Geod."""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pyarrow as pa
import pyproj
import pytest
from hypothesis import example, given, settings

import dggs
from dggs.errors import DggsValueError, InvalidCellError, LevelError
from dggs.geometry.authalic import WGS84

from ..strategies import cells, examples, special_points

GEOD = pyproj.Geod(ellps="WGS84")


def all_cells(level):
    return list(dggs.get_base_cells()) if level == 0 else dggs.cell_to_children(list(dggs.get_base_cells()), level)


def special_cells(level: int) -> list[str]:
    lat, lng = zip(*special_points(), strict=True)
    return sorted(set(dggs.latlng_to_cell(list(lat), list(lng), level)))


def layout_int(edge: str) -> int:
    """The documented integer form: the sign bit over the shadow cell (the string without its dot)."""
    return (1 << 63) | dggs.str_to_int(edge.replace(".", ""))


def unit(points) -> np.ndarray:
    lat, lng = np.radians(np.asarray(points)[..., 0]), np.radians(np.asarray(points)[..., 1])
    return np.stack([np.cos(lat) * np.cos(lng), np.cos(lat) * np.sin(lng), np.sin(lat)], axis=-1)


def check_cells(ids: list[str]) -> None:
    """Every property of the edges of ``ids``, in string and integer form."""
    edges = dggs.origin_to_directed_edges(ids)
    flat = [e for row in edges for e in row]
    assert len(set(flat)) == len(flat)
    assert all(dggs.is_valid_directed_edge(flat))
    origins, dests = zip(*dggs.directed_edge_to_cells(flat), strict=True)
    assert list(origins) == [c for c in ids for _ in range(3)]
    assert dggs.get_directed_edge_origin(flat) == list(origins)
    assert dggs.get_directed_edge_destination(flat) == list(dests)
    for c, row, nbrs in zip(ids, edges, dggs.edge_neighbors(ids), strict=True):
        got = set(dggs.get_directed_edge_destination(row))
        assert got == set(nbrs) and len(got) == 3 and c not in got  # the neighbour set
        assert [dggs.cells_to_directed_edge(c, d) for d in dggs.get_directed_edge_destination(row)] == row
    back = dggs.reverse_directed_edge(flat)
    assert dggs.get_directed_edge_origin(back) == list(dests)
    assert dggs.get_directed_edge_destination(back) == list(origins)
    assert dggs.reverse_directed_edge(back) == flat
    # the integer form: the documented layout, and the same answers
    ints = [layout_int(e) for e in flat]
    assert [x for row in dggs.origin_to_directed_edges(dggs.str_to_int(ids)) for x in row] == ints
    assert dggs.reverse_directed_edge(ints) == [layout_int(e) for e in back]
    assert dggs.get_directed_edge_destination(ints) == dggs.str_to_int(list(dests))
    # the boundary: the two corners the cells share, in the origin's order
    ends = unit(dggs.directed_edge_to_boundary(flat))
    assert np.array_equal(ends, unit(dggs.directed_edge_to_boundary(ints)))
    corners_o = unit(dggs.cell_to_boundary(list(origins)))
    corners_d = unit(dggs.cell_to_boundary(list(dests)))
    for k in range(len(flat)):
        d = k % 3
        np.testing.assert_allclose(ends[k], [corners_o[k, d], corners_o[k, (d + 1) % 3]], atol=1e-13)
        for p in ends[k]:
            assert np.linalg.norm(corners_d[k] - p, axis=1).min() < 1e-12  # a corner of the destination too
        # the reverse edge runs between the same two points
        np.testing.assert_allclose(np.sort(ends[k], axis=0), np.sort(unit(dggs.directed_edge_to_boundary(back[k])), axis=0), atol=1e-12)


@pytest.mark.parametrize("level", [0, 1, 2, 3])
def test_exhaustive(level):
    check_cells(all_cells(level))


@settings(max_examples=examples(100))
@given(cell=cells(max_level=27))
@example(cell="A" + "0" * 27)
@example(cell="T5" + "2" * 26)
@example(cell="C")
def test_any_cell(cell):
    check_cells([cell])


@pytest.mark.parametrize("level", [1, 9, 17, 27])
def test_special_cells(level):
    """Poles, the antimeridian, icosahedron vertices and face edges."""
    check_cells(special_cells(level))


def _geod_length(edge: str, densify: int = 2000) -> float:
    """pyproj.Geod's length of the edge's curve, densified through cell_to_boundary (not the edge code)."""
    origin, d = edge.split(".")
    ring = np.asarray(dggs.cell_to_boundary(origin, densify=densify))
    d = int(d)
    pts = np.concatenate([ring, ring[:1]])[d * (densify + 1) : (d + 1) * (densify + 1) + 1]
    return float(GEOD.line_length(pts[:, 1], pts[:, 0]))


@pytest.mark.parametrize("level", [0, 1, 3, 8, 14, 20, 27])
def test_length_against_geod(level):
    ids = special_cells(level)[::3] + dggs.latlng_to_cell([12.5, -60.1, 89.9], [-170.0, 33.3, 179.9], level)
    flat = [e for row in dggs.origin_to_directed_edges(ids) for e in row]
    got = dggs.edge_length(flat)
    ref = np.array([_geod_length(e) for e in flat])
    np.testing.assert_allclose(got, ref, rtol=1e-7 if level < 27 else 2e-7)
    np.testing.assert_allclose(dggs.edge_length(flat, unit="km"), ref / 1000, rtol=2e-7)
    # the same curve walked from the other side
    np.testing.assert_allclose(dggs.edge_length(dggs.reverse_directed_edge(flat)), got, rtol=1e-10, atol=1e-6)


@pytest.mark.parametrize("level", [0, 2, 10])
def test_length_in_radians_on_the_authalic_sphere(level):
    """Great-circle steps between densified points, moved to authalic latitude by the geometry floor's series."""
    ids = special_cells(level)[:4]
    flat = [e for row in dggs.origin_to_directed_edges(ids) for e in row]
    got = dggs.edge_length(flat, unit="rads")
    for e, g in zip(flat, got, strict=True):
        pts = np.asarray(dggs.directed_edge_to_boundary(e, densify=3000))
        beta = np.asarray(WGS84.geodetic_to_authalic(np.radians(pts[:, 0])))
        xyz = unit(np.stack([np.degrees(beta), pts[:, 1]], axis=1))
        steps = np.linalg.norm(np.diff(xyz, axis=0), axis=1)
        ref = float(np.sum(2 * np.arcsin(steps / 2)))
        assert math.isclose(g, ref, rel_tol=1e-7)
    level_edge = np.array(dggs.edge_length(flat, unit="m")) / WGS84.authalic_radius
    np.testing.assert_allclose(got, level_edge, rtol=1e-2)  # the sphere and the ellipsoid agree to flattening


def test_containers():
    edges = ["C401.1", "A.0"]
    out = dggs.reverse_directed_edge(np.array(edges))
    assert isinstance(out, np.ndarray) and out.tolist() == ["C402.1", dggs.reverse_directed_edge("A.0")]
    s = dggs.get_directed_edge_origin(pd.Series(edges, index=[4, 5]))
    assert s.index.tolist() == [4, 5] and s.tolist() == ["C401", "A"]
    ints = np.array([layout_int(e) for e in edges], dtype=np.uint64)
    assert dggs.get_directed_edge_origin(ints).tolist() == dggs.str_to_int(["C401", "A"])
    neg = ints.view(np.int64)  # an int64 column holds edges as negative numbers: read back, given as uint64
    assert dggs.reverse_directed_edge(neg).dtype == np.uint64
    assert dggs.reverse_directed_edge(neg).tolist() == [layout_int(e) for e in dggs.reverse_directed_edge(edges)]
    cells64 = np.array(dggs.str_to_int(["C401", "A"]), dtype=np.int64)
    assert dggs.origin_to_directed_edges(cells64).dtype == np.uint64
    assert dggs.origin_to_directed_edges(pd.Series(cells64))[0] == [layout_int(f"C401.{d}") for d in range(3)]
    assert dggs.reverse_directed_edge(pd.Series(neg)).dtype == np.uint64
    assert dggs.origin_to_directed_edges(pa.array(cells64)).type.value_type == pa.uint64()
    arr = dggs.origin_to_directed_edges(pa.array(["C401", "B"]))
    assert arr.to_pylist() == [["C401.0", "C401.1", "C401.2"], ["B.0", "B.1", "B.2"]]
    assert dggs.edge_length(pa.chunked_array([pa.array(edges)])).to_pylist() == pytest.approx(dggs.edge_length(edges))
    assert dggs.origin_to_directed_edges(pd.Series(["C401"])).tolist() == [["C401.0", "C401.1", "C401.2"]]
    assert dggs.is_valid_directed_edge(pd.Series(["C401.1", "C401"])).tolist() == [True, False]


def test_invalid_inputs():
    for bad in ("C401", "C401.3", "A.3", "A.5", "C4011", "Z.1", ".1", "", 5, 1 << 62, -1, (1 << 64) - 1, dggs.str_to_int("C401")):
        assert dggs.is_valid_directed_edge(bad) is False
        with pytest.raises(InvalidCellError, match="directed edge"):
            dggs.get_directed_edge_origin(bad)
    for junk in (None, 1.5, b"C41", b"\xff.1", object()):
        assert not dggs.is_valid_directed_edge(junk)
    assert dggs.is_valid_directed_edge(b"C4.1")  # ASCII bytes are the edge they spell, as in a numpy S array (issue 32)
    with pytest.raises(InvalidCellError, match="'Z.1' at index 1"):
        dggs.reverse_directed_edge(["C401.1", "Z.1"])
    with pytest.raises(DggsValueError, match="not edge neighbours"):
        dggs.cells_to_directed_edge("C401", "C401")
    with pytest.raises(DggsValueError, match="not edge neighbours"):
        dggs.cells_to_directed_edge("C401", "C41")
    with pytest.raises(LevelError, match="level 28"):
        dggs.origin_to_directed_edges("A" + "0" * 28)
    with pytest.raises(LevelError, match="level 28"):
        dggs.cells_to_directed_edge("A" + "0" * 28, dggs.edge_neighbors("A" + "0" * 28)[0])
    with pytest.raises(DggsValueError, match="unit"):
        dggs.edge_length("C401.1", unit="miles")
    with pytest.raises(DggsValueError):
        dggs.directed_edge_to_boundary("C401.1", densify=-1)


# Issue 32 item 10: bytes are read as the ASCII string they spell, as the cell verbs and numpy ``S`` arrays do:
# b"C401" is a level-3 cell, not the edge "C40.1", and b"C40.1" is that edge.
@pytest.mark.parametrize("make", [bytes, np.bytes_, bytearray, lambda b: [b], lambda b: np.array([b], dtype=object), lambda b: pd.Series([b])])
def test_bytes_edge_ids_read_as_their_text(make):
    assert not np.asarray(dggs.is_valid_directed_edge(make(b"C401"))).any()  # a bool or a container of them
    with pytest.raises(dggs.InvalidCellError, match="C401"):
        dggs.get_directed_edge_origin(make(b"C401"))
    assert np.asarray(dggs.is_valid_directed_edge(make(b"C40.1"))).all()
    origin = dggs.get_directed_edge_origin(make(b"C40.1"))
    assert str(np.asarray(origin, dtype=object).reshape(-1)[0]) == "C40"
    assert np.allclose(dggs.edge_length(make(b"C40.1")), dggs.edge_length("C40.1"))


def test_numpy_bytes_edges_agree_with_lone_bytes():
    arr = np.array([b"C40.1", b"C401"], dtype="S")
    assert dggs.is_valid_directed_edge(arr).tolist() == [dggs.is_valid_directed_edge(b) for b in arr.tolist()] == [True, False]
