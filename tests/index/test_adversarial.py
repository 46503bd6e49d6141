"""Adversarial inputs: every public function gives a correct result or a typed, named error.

Every name in ``dggs.__all__`` that is a function, and the ``dggs cell``
commands, get NaN, infinities, huge and subnormal floats, wrong dtypes (bool,
str, object, complex, datetime), empty, 0-d and 2-D inputs, mismatched shapes,
bad levels and corrupt ids.  The only acceptable outcomes are a result that
passes a cheap invariant or a :class:`dggs.DggsError` whose message names the
bad value; anything else (a raw ValueError, TypeError, IndexError,
OverflowError, a numba typing error, a hang) is a bug.
"""

from __future__ import annotations

import math
import signal
import subprocess
import sys
from contextlib import contextmanager
from pathlib import Path

import numpy as np
import pandas as pd
import pyarrow as pa
import pytest
from click.testing import CliRunner
from hypothesis import example, given, settings
from hypothesis import strategies as st
from shapely.geometry import Polygon, box

import dggs
from dggs.cli import main
from dggs.index.ids import check_level

from ..strategies import cells, examples, special_points

GOOD = "C401"
GOOD_INT = dggs.str_to_int(GOOD)
EXAMPLES = examples(150)  # per hypothesis test (make test: 30; make test-all: 150; HYPOTHESIS_PROFILE=thorough: 3000)


# --------------------------------------------------------------------------
# Outcomes
# --------------------------------------------------------------------------


@contextmanager
def time_limit(seconds: int = 60):
    """Fail (instead of hanging) if the body runs longer than ``seconds``."""

    def _raise(*_):
        raise TimeoutError(f"no answer within {seconds} s: a hang")

    old = signal.signal(signal.SIGALRM, _raise)
    signal.alarm(seconds)
    try:
        yield
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, old)


def outcome(call, *args, **kwargs):
    """(True, result) or (False, DggsError); any other exception propagates and fails the test."""
    with time_limit():
        try:
            return True, call(*args, **kwargs)
        except dggs.DggsError as exc:
            msg = str(exc)
            assert msg.strip(), f"{type(exc).__name__} without a message"
            return False, exc


def _py(value):
    return value.item() if isinstance(value, np.generic) else value


def names(exc: Exception, *values) -> None:
    """The error message names one of ``values`` (its repr, or its str for text)."""
    msg = str(exc)
    reprs = []
    for v in values:
        v = _py(v)
        reprs.append(repr(v))
        if isinstance(v, float) and not math.isnan(v):
            reprs.append(repr(float(v)))
        if isinstance(v, (str, int)) and not isinstance(v, bool):
            reprs.append(str(v))
    assert any(r in msg for r in reprs), f"{msg!r} names none of {reprs}"


# --------------------------------------------------------------------------
# Corrupt ids
# --------------------------------------------------------------------------

CORRUPT_SCALARS = [
    "", "C9", "c401", "U0", "C6", "C403", "C4" + "0" * 40, "A0\x00", "\x00", "A\x000", "Aé", "🌍", " C401", "C401 ",
    b"\xff\xfe", b"C9", b"A0\x00", bytearray(b"C9"), None, float("nan"), math.inf, 2.5, 1j, True, False, np.True_,
    -1, 0, 1, (1 << 62) | 3, (1 << 64) - 1, 1 << 64, 1 << 70, -(1 << 63), np.int64(-5), np.uint64((1 << 64) - 1),
    np.float64(1.0), pd.NA, pd.NaT, np.datetime64("2020-01-01"), object(), {"C401": 1}, Ellipsis,
]
VALID_SCALARS = ["A", "T5", GOOD, "C4" + "0" * 27, b"A01", np.str_(GOOD), np.bytes_(b"C40"), bytearray(b"C401"), GOOD_INT, np.uint64(GOOD_INT), np.int64(GOOD_INT)]


def corrupt_scalars():
    return st.one_of(
        st.sampled_from(CORRUPT_SCALARS),
        st.text(max_size=12),
        st.binary(max_size=8),
        st.integers(min_value=-(1 << 70), max_value=1 << 70),
        st.floats(),
    )


def any_scalars():
    return st.one_of(corrupt_scalars(), st.sampled_from(VALID_SCALARS), cells())


def _as_container(items: list, how: str):
    """``items`` in one of the containers dggs takes (or None where that container cannot hold them)."""
    if how == "list":
        return list(items)
    if how == "tuple":
        return tuple(items)
    if how == "object":
        arr = np.empty(len(items), dtype=object)
        arr[:] = items
        return arr
    if how == "object2d":
        arr = np.empty(len(items), dtype=object)
        arr[:] = items
        return arr.reshape(1, -1)
    if how == "pandas":
        return pd.Series(items, dtype=object)
    if how == "0d":
        return np.array(items[0]) if len(items) == 1 and isinstance(items[0], (str, bytes, int)) and not isinstance(items[0], bool) else None
    try:
        if how == "U":
            return np.array([i for i in items], dtype=str) if all(isinstance(i, str) for i in items) else None
        if how == "S":
            return np.array(items, dtype="S") if all(isinstance(i, bytes) for i in items) else None
        if how == "T":
            return np.array(items, dtype=np.dtypes.StringDType()) if all(isinstance(i, str) for i in items) else None
        if how == "int":
            return np.array(items, dtype=np.uint64) if all(type(i) is int and 0 <= i < 1 << 64 for i in items) else None
        if how == "int64":
            return np.array(items, dtype=np.int64) if all(type(i) is int and -(1 << 63) <= i < 1 << 63 for i in items) else None
        if how == "arrow":
            return pa.array(items) if all(isinstance(i, str) or i is None for i in items) else None
    except (ValueError, TypeError, OverflowError, UnicodeError):
        return None
    raise AssertionError(how)


CONTAINERS = ["list", "tuple", "object", "object2d", "pandas", "U", "S", "T", "int", "int64", "arrow", "0d"]


@st.composite
def id_containers(draw):
    """(container, its elements as Python values): mixes of valid and corrupt ids, empty too."""
    items = draw(st.lists(any_scalars(), max_size=5))
    how = draw(st.sampled_from(CONTAINERS))
    if how in ("U", "T", "arrow"):
        items = [i if isinstance(i, str) else GOOD for i in items]
    elif how == "S":
        items = [i if isinstance(i, bytes) else b"C40" for i in items]
    elif how in ("int", "int64"):
        items = [i if type(i) is int else GOOD_INT for i in items]
    obj = _as_container(items, how)
    if obj is None:
        obj = list(items)
    return obj, items


ONE_CELL_FUNCS = {
    "str_to_int": dggs.str_to_int,
    "int_to_str": dggs.int_to_str,
    "cell_to_latlng": dggs.cell_to_latlng,
    "cell_to_boundary": dggs.cell_to_boundary,
    "cell_to_polygon": lambda c: dggs.cell_to_polygon(c, densify=1),
    "cells_to_geojson": lambda c: dggs.cells_to_geojson(c, densify=0),
    "get_level": dggs.get_level,
    "get_face": dggs.get_face,
    "cell_to_parent": lambda c: dggs.cell_to_parent(c, 0),
    "cell_to_children": lambda c: dggs.cell_to_children(c, max_cells=10_000),
    "cell_to_center_child": lambda c: dggs.cell_to_center_child(c, dggs.MAX_LEVEL),
    "compact_cells": dggs.compact_cells,
    "cells_to_polygons": lambda c: dggs.cells_to_polygons(c, densify=0),
    "uncompact_cells": lambda c: dggs.uncompact_cells(c, dggs.MAX_LEVEL, max_cells=10_000),
    "edge_neighbors": dggs.edge_neighbors,
    "are_neighbor_cells": lambda c: dggs.are_neighbor_cells(c, GOOD),
    "are_neighbor_cells_2": lambda c: dggs.are_neighbor_cells(GOOD, c),
    "grid_disk": lambda c: dggs.grid_disk(c, 1),
    "grid_ring": lambda c: dggs.grid_ring(c, 2),
    "grid_distance": lambda c: dggs.grid_distance(c, c),
    "cell_area": dggs.cell_area,
    "cell_to_vertexes": dggs.cell_to_vertexes,
    "vertex_neighbors": dggs.vertex_neighbors,
    "grid_disk_vertex": lambda c: dggs.grid_disk_vertex(c, 1),
    "cell_centers_distance": lambda c: dggs.cell_centers_distance(c, GOOD),
    # issue 21: child positions, local (i, j), directed edges from cells, paths
    "cell_to_child_pos": lambda c: dggs.cell_to_child_pos(c, 0),
    "child_pos_to_cell": lambda c: dggs.child_pos_to_cell(0, c, dggs.MAX_LEVEL),
    "cell_to_local_ij": lambda c: dggs.cell_to_local_ij(c, c),
    "origin_to_directed_edges": dggs.origin_to_directed_edges,
    "grid_path_cells": lambda c: dggs.grid_path_cells(c, c),
}


def test_every_public_function_is_covered():
    covered = set(ONE_CELL_FUNCS) | {"is_valid_cell", "latlng_to_cell", "polygon_to_cells", "get_num_cells", "get_base_cells", "level_table"}
    covered |= {"vertex_to_latlng", "vertex_to_cells", "is_valid_vertex", "great_circle_distance", "geodesic_to_cells"}
    covered |= set(EDGE_FUNCS) | {"is_valid_directed_edge", "cells_to_directed_edge", "local_ij_to_cell"}
    covered |= {"line_to_cells", "circle_to_cells"}
    public = {n for n in dggs.__all__ if callable(getattr(dggs, n)) and not isinstance(getattr(dggs, n), type)}
    assert public <= covered, public - covered


@settings(max_examples=EXAMPLES)
@given(value=any_scalars(), func=st.sampled_from(sorted(ONE_CELL_FUNCS)))
def test_one_id(value, func):
    """A single id: a result only for a valid id; otherwise a DggsError naming it."""
    if func == "cell_area" and isinstance(_py(value), int) and not isinstance(_py(value), bool) and 0 <= _py(value) <= dggs.MAX_LEVEL:
        value = GOOD_INT  # small ints are levels to cell_area (tested below)
    ok, res = outcome(ONE_CELL_FUNCS[func], value)
    valid = dggs.is_valid_cell(value)
    assert valid in (True, False)
    if ok:
        assert valid, f"{func} accepted {value!r}"
    elif valid:
        assert isinstance(res, (dggs.LevelMismatchError, dggs.LevelError, dggs.TooManyCellsError)), res
    else:
        assert isinstance(res, (dggs.LevelError, dggs.InvalidCellError) if func == "cell_area" else dggs.InvalidCellError), res
        names(res, value)


@settings(max_examples=EXAMPLES)
@given(data=id_containers(), func=st.sampled_from(sorted(ONE_CELL_FUNCS)))
@example(data=(np.array([-1], dtype=object), [-1]), func="int_to_str")  # the null-id allowance took -1 for a null
def test_containers_of_ids(data, func):
    """Lists, tuples, numpy (U, S, StringDType, object, ints, 2-D), pandas, arrow; mixed, empty."""
    obj, items = data
    ok, res = outcome(ONE_CELL_FUNCS[func], obj)
    valid = dggs.is_valid_cell(obj)
    valid_flat = np.asarray(valid).reshape(-1)
    levels = func == "cell_area" and all(isinstance(_py(i), int) and not isinstance(_py(i), bool) and _py(i) < 1 << 62 for i in items)
    if levels:  # small integers are levels to cell_area (or, in an object array, cell ids)
        if not ok:
            assert isinstance(res, (dggs.LevelError, dggs.InvalidCellError)), res
            names(res, *items)
        return
    if ok:
        assert valid_flat.all(), f"{func} accepted {obj!r}"
        shape = np.shape(obj) if not isinstance(obj, (list, tuple)) else (len(obj),)
        if func == "get_level":
            assert np.shape(res) == shape
        elif func == "edge_neighbors" and isinstance(obj, np.ndarray):
            assert res.shape == shape + (3,)
        elif func == "cell_to_boundary":  # the input's container, of (lat, lng) rows
            plain = res.to_pylist() if hasattr(res, "to_pylist") else res.tolist() if isinstance(res, pd.Series) else res
            assert np.shape(plain) == shape + (3, 2) or (plain == [] and shape == (0,))  # an empty list: []
        elif func == "str_to_int":
            assert dggs.int_to_str(res) is not None and len(res) == len(obj)
    elif valid_flat.all():
        assert isinstance(res, (dggs.LevelMismatchError, dggs.LevelError, dggs.TooManyCellsError)), res
    else:
        assert isinstance(res, dggs.InvalidCellError), res
        names(res, *items, *np.asarray(obj, dtype=object).reshape(-1).tolist())


@settings(max_examples=EXAMPLES)
@given(value=st.one_of(any_scalars(), id_containers().map(lambda d: d[0])))
def test_is_valid_cell_never_raises(value):
    with time_limit():
        res = dggs.is_valid_cell(value)
    assert isinstance(res, (bool, list, np.ndarray, pd.Series, pa.Array, pa.ChunkedArray))


# --------------------------------------------------------------------------
# Levels, k, densify, max_cells
# --------------------------------------------------------------------------

BAD_LEVELS = [-1, 29, 2.5, "3", True, False, np.True_, None, math.nan, math.inf, 3.0, 1 << 70, -(1 << 70), np.array(3), np.array([3]), [3], 3j]
GOOD_LEVELS = [0, 3, 28, np.int8(3), np.int64(5), np.uint64(7), np.uint8(28)]

LEVEL_FUNCS = {
    "latlng_to_cell": lambda lv: dggs.latlng_to_cell(10.0, 20.0, lv),
    "latlng_to_cell_array": lambda lv: dggs.latlng_to_cell(np.zeros(2), np.zeros(2), lv),
    "cell_to_parent": lambda lv: dggs.cell_to_parent("C4010000", lv),
    "cell_to_parent_int": lambda lv: dggs.cell_to_parent(dggs.str_to_int("C4010000"), lv),
    "cell_to_children": lambda lv: dggs.cell_to_children("C", lv, max_cells=10**9),
    "cell_to_center_child": lambda lv: dggs.cell_to_center_child("C", lv),
    "uncompact_cells": lambda lv: dggs.uncompact_cells(["C"], lv, max_cells=10**9),
    "get_num_cells": dggs.get_num_cells,
    "cell_area": dggs.cell_area,
    "level_table": dggs.level_table,
    "polygon_to_cells": lambda lv: dggs.polygon_to_cells(box(0, 0, 1e-6, 1e-6), lv),
}


def levels():
    return st.one_of(st.sampled_from(BAD_LEVELS + GOOD_LEVELS), st.integers(-(1 << 66), 1 << 66), st.floats())


def _level_ok(level) -> bool:
    return isinstance(level, (int, np.integer)) and not isinstance(level, bool) and 0 <= level <= dggs.MAX_LEVEL


@settings(max_examples=EXAMPLES)
@given(level=levels(), func=st.sampled_from(sorted(LEVEL_FUNCS)))
def test_levels(level, func):
    ok, res = outcome(LEVEL_FUNCS[func], level)
    if level is None and func in ("cell_to_parent", "cell_to_parent_int", "cell_to_children", "cell_to_center_child"):
        assert ok, res  # None: the default level
        return
    if ok:
        arr = np.asarray(level, dtype=object)
        if func == "cell_area" and isinstance(level, np.ndarray) and level.dtype.kind in "iu":
            arr = level  # cell_area takes arrays of levels
        assert all(_level_ok(v) for v in np.asarray(arr).reshape(-1)) if func == "cell_area" else _level_ok(level), f"{func} accepted level {level!r}"
    elif _level_ok(level):
        assert isinstance(res, (dggs.LevelMismatchError, dggs.TooManyCellsError)), res
    elif func == "cell_area":  # a level, or else a cell id
        assert isinstance(res, (dggs.LevelError, dggs.InvalidCellError)), res
    else:
        assert isinstance(res, dggs.LevelError), res
        names(res, level)


def test_check_level_takes_numpy_integers():
    assert check_level(np.int64(5)) == 5 and check_level(np.uint8(28)) == 28
    assert type(check_level(np.int32(3))) is int
    for bad in (True, 2.5, "3", np.float64(3), None, 29, -1):
        with pytest.raises(dggs.LevelError, match=repr(bad).replace("(", r"\(").replace(")", r"\)")):
            check_level(bad)


COUNT_ARGS = [-1, 2.5, "3", True, None, math.nan, 1 << 70, np.int64(2), np.array([3]), 0, 3]
COUNT_FUNCS = {
    "grid_disk k": lambda v: dggs.grid_disk(GOOD, v),
    "grid_disk k array": lambda v: dggs.grid_disk([GOOD], v),
    "grid_ring k": lambda v: dggs.grid_ring(GOOD, v),
    "grid_distance max_steps": lambda v: dggs.grid_distance("C401", "C410", v),
    "cell_to_boundary densify": lambda v: dggs.cell_to_boundary(GOOD, v),
    "cell_to_polygon densify": lambda v: dggs.cell_to_polygon(GOOD, v),
    "cells_to_geojson densify": lambda v: dggs.cells_to_geojson([GOOD], densify=v),
    "cell_to_children max_cells": lambda v: dggs.cell_to_children(GOOD, 6, max_cells=v),
    "uncompact_cells max_cells": lambda v: dggs.uncompact_cells([GOOD], 6, max_cells=v),
    "grid_disk max_cells": lambda v: dggs.grid_disk(GOOD, 2, max_cells=v),
    "grid_ring max_cells": lambda v: dggs.grid_ring([GOOD], 2, max_cells=v),
    "polygon_to_cells max_cells": lambda v: dggs.polygon_to_cells(box(0, 0, 1, 1), 6, max_cells=v),
}


@settings(max_examples=EXAMPLES)
@given(value=st.one_of(st.sampled_from(COUNT_ARGS), st.integers(-(1 << 70), 1 << 70)), func=st.sampled_from(sorted(COUNT_FUNCS)))
@example(value=46, func="grid_ring k")  # a ring past the level's extent: rows of width 0 (reshape(-1, 0) failed)
@example(value=None, func="grid_distance max_steps")  # no limit, the default since distances are exact at any range
def test_counts(value, func):
    """k, max_steps, densify and max_cells: non-negative ints, else a DggsValueError naming the value."""
    ok, res = outcome(COUNT_FUNCS[func], value)
    good = isinstance(value, (int, np.integer)) and not isinstance(value, bool) and value >= 0
    defaults = ("cell_to_polygon densify", "cells_to_geojson densify", "grid_distance max_steps")  # None: the default
    good = good or (value is None and ("max_cells" in func or func in defaults))
    if ok:
        assert good, f"{func} accepted {value!r}"
    elif not good:
        assert isinstance(res, dggs.DggsValueError)
        names(res, value)


def test_max_cells_is_validated():
    for bad in (-1, 2.5, "3", True, math.nan):
        with pytest.raises(dggs.DggsValueError, match="max_cells"):
            dggs.cell_to_children("C", 2, max_cells=bad)
        with pytest.raises(dggs.DggsValueError, match="max_cells"):
            dggs.grid_disk("C401", 1, max_cells=bad)  # the single-cell path too
    assert len(dggs.grid_disk("C401", 1, max_cells=np.int64(10))) == 4


# --------------------------------------------------------------------------
# Coordinates
# --------------------------------------------------------------------------

BAD_NUMBERS = [math.nan, math.inf, -math.inf, 1e308, -1e308, 90.0000001, -91.0, 1 << 62, "1", b"1", True, np.True_, None, 1j, pd.NA]
EDGE_NUMBERS = [5e-324, -5e-324, 2.2250738585072014e-308, 0.0, -0.0, 90.0, -90.0, 180.0, -180.0, 540.0, -1e300 * 0 + 1e15, np.float32(45.5), np.int8(-7), np.uint64(3)]


def coordinates():
    # Python ints past int64 on the scalar fast path: see test_ragged_and_huge_int_coordinates
    scalars = st.one_of(st.sampled_from(BAD_NUMBERS + EDGE_NUMBERS), st.floats(), st.integers(-(1 << 63), (1 << 63) - 1))
    arrays = st.one_of(
        st.lists(scalars, max_size=4),
        st.lists(st.floats(), max_size=4).map(np.array),
        st.sampled_from([
            np.array([], dtype=float), np.array(45.0), np.zeros((2, 2)), np.zeros((1, 3)), np.zeros(3),
            np.array([True, False]), np.array(["1", "2"]), np.array([1j]), np.array(["2020-01-01"], dtype="datetime64[D]"),
            np.array([1.0, None], dtype=object), np.array([1.0, True], dtype=object), np.array([1.0, "2"], dtype=object),
            pd.Series([1.0, None]), pd.Series([1.0, pd.NA], dtype="Float64"), pd.Series([1, 2], dtype="Int64"),
            np.array([1], dtype=np.float16), [[1.0, 2.0], [3.0, 4.0]],
        ]),
    )
    return st.one_of(scalars, arrays)


def _numbers_ok(value) -> bool:
    """Whether every element is a real finite number (not a bool or str)."""
    arr = np.asarray(value, dtype=object).reshape(-1) if not isinstance(value, pd.Series) else value.to_numpy(dtype=object)
    for v in arr:
        v = _py(v)
        if isinstance(v, (bool, str, bytes, complex)) or v is None or v is pd.NA or not isinstance(v, (int, float)):
            return False
        if not math.isfinite(float(v)):
            return False
    return True


@settings(max_examples=EXAMPLES)
@given(lat=coordinates(), lng=coordinates(), level=st.sampled_from([0, 5, 28]), as_int=st.booleans())
# a Series that broadcasts to 2-D (found by a 2,000-example run: a raw ValueError from pandas)
@example(lat=pd.Series([1, 2], dtype="Int64"), lng=[[1.0, 2.0], [3.0, 4.0]], level=0, as_int=False)
@example(lat=pd.Series([1.0]), lng=[1.0, 2.0, 3.0], level=5, as_int=True)
def test_latlng_to_cell(lat, lng, level, as_int):
    ok, res = outcome(dggs.latlng_to_cell, lat, lng, level, as_int=as_int)
    if ok:
        shape = np.broadcast_shapes(np.shape(lat), np.shape(lng))
        assert 0 in shape or (_numbers_ok(lat) and _numbers_ok(lng)), f"accepted {lat!r}, {lng!r}"
        if shape == ():
            assert isinstance(res, int if as_int else str)
            assert dggs.get_level(res) == level
        else:
            assert np.shape(res) == shape
            if np.size(res):
                assert (np.asarray(dggs.get_level(res)) == level).all()
    else:
        assert isinstance(res, dggs.CoordinateError), res


def test_bools_and_strings_are_not_coordinates():
    for lat in ([1.0, True], np.array([1.0, True], dtype=object), [1.0, "2"], True, "10", [[1.0], [True]]):
        with pytest.raises(dggs.CoordinateError, match="True|'2'|'10'"):
            dggs.latlng_to_cell(lat, 0.0, 3)


def test_zero_dim_and_empty_coordinates():
    assert dggs.latlng_to_cell(np.array(51.05), np.array(-114.07), 9) == "F200021102"
    assert dggs.latlng_to_cell(np.array([]), np.array([]), 3).shape == (0,)
    assert dggs.latlng_to_cell([], [], 3, as_int=True) == []  # a list in, a list out
    with pytest.raises(dggs.CoordinateError, match=r"\(2,\).*\(3,\)"):
        dggs.latlng_to_cell(np.zeros(2), np.zeros(3), 3)


def test_ragged_and_huge_int_coordinates():
    for lat in ([[1.0], [1.0, 2.0]], 1 << 70):
        with pytest.raises(dggs.CoordinateError):
            dggs.latlng_to_cell(lat, 0.0, 3)


@pytest.mark.parametrize("point", special_points())
def test_special_points(point):
    """Poles, antimeridian, vertices, edge midpoints: a cell at every level, its centre maps back."""
    lat, lng = point
    for level in (0, 1, 7, 17, dggs.MAX_LEVEL):
        cell = dggs.latlng_to_cell(lat, lng, level)
        assert dggs.get_level(cell) == level
        assert dggs.latlng_to_cell(*dggs.cell_to_latlng(cell), level) == cell
        assert len(dggs.cell_to_boundary(cell)) == 3
        assert dggs.cell_to_polygon(cell).is_valid
        assert all(dggs.are_neighbor_cells(cell, dggs.edge_neighbors(cell)))


# --------------------------------------------------------------------------
# Pairs of cells
# --------------------------------------------------------------------------

SHAPES = [(), (0,), (1,), (2,), (3,), (1, 2), (2, 1), (2, 2), (2, 3)]


@settings(max_examples=EXAMPLES)
@given(sa=st.sampled_from(SHAPES), sb=st.sampled_from(SHAPES), func=st.sampled_from(["are_neighbor_cells", "grid_distance"]))
def test_pair_shapes(sa, sb, func):
    a = GOOD if sa == () else np.full(sa, "C402")
    b = "C400" if sb == () else np.full(sb, "C401")
    ok, res = outcome(getattr(dggs, func), a, b)
    try:
        shape = np.broadcast_shapes(sa, sb)
    except ValueError:
        assert not ok and isinstance(res, dggs.DggsValueError)
        assert str(int(np.prod(sa))) in str(res) and str(int(np.prod(sb))) in str(res), res
        return
    assert ok, res
    assert np.shape(res) == shape


def test_pairs_of_lists_of_different_lengths():
    with pytest.raises(dggs.DggsValueError, match="2 cells .* 3 cells"):
        dggs.are_neighbor_cells(["C401", "C402"], ["C400", "C401", "C402"])
    with pytest.raises(dggs.DggsValueError, match=r"4 cells \(shape \(2, 2\)\) with 3 cells"):
        dggs.grid_distance(np.full((2, 2), "C401"), ["C400", "C401", "C402"])
    assert dggs.grid_distance([], "A0") == []  # a list in, a list out
    assert dggs.are_neighbor_cells(["C401"], ["C402", "C400"]) == [True, True]


# --------------------------------------------------------------------------
# The regressions of issue 10, item 16, one by one
# --------------------------------------------------------------------------


def test_item16_regressions():
    with pytest.raises(dggs.InvalidCellError, match=r"\('A0',\) at index 0"):
        dggs.get_level([("A0",), "K1"])
    with pytest.raises(dggs.InvalidCellError, match=r"b'\\xff'"):
        dggs.get_level(b"\xff")
    with pytest.raises(dggs.InvalidCellError, match=r"b'\\xff'"):
        dggs.str_to_int([b"\xff"])
    assert dggs.get_level(b"A01") == 2 and dggs.get_level([b"A01"]) == [2]
    with pytest.raises(dggs.InvalidCellError, match="b'A0x'"):
        dggs.get_level(np.array([b"A0x"]))
    assert dggs.cell_to_boundary([]) == [] and dggs.cell_to_boundary(np.array([], dtype=str)).shape == (0, 3, 2)
    assert dggs.cell_to_latlng([]) == ([], []) and dggs.cell_to_latlng(np.array([], dtype=str))[0].shape == (0,)
    for bad in (["A0\x00"], np.array(["A0\x00"], dtype=object), pa.array(["A0\x00"]), pd.Series(["A0\x00"], dtype="string"),
                np.array(["A\x000"]), np.array(["A0\x00"], dtype=np.dtypes.StringDType()), "A0\x00"):
        with pytest.raises(dggs.InvalidCellError, match=r"'A0?\\x000?'"):
            dggs.get_level(bad)
    assert dggs.cell_area([[]]) == [[]] and dggs.cell_area(np.zeros((1, 0), dtype=str)).shape == (1, 0)
    with pytest.raises(dggs.TooManyCellsError, match="k=1180591620717411303424"):
        dggs.grid_disk("C401", 1 << 70)
    with pytest.raises(dggs.LevelError, match="1180591620717411303424"):
        dggs.cell_to_parent("C401", 1 << 70)


# --------------------------------------------------------------------------
# Functions without ids
# --------------------------------------------------------------------------


@settings(max_examples=EXAMPLES)
@given(polygon=st.one_of(
    st.sampled_from([None, "POLYGON ((0 0, 1 0, 1 1, 0 0))", 5, [(0, 0), (1, 0), (1, 1)], box(0, -100, 1, 1),
                     Polygon([(0, 0), (1, 1), (1, 0), (0, 1)]), Polygon(), box(179, -1, 181, 1), box(-1, 89, 1, 90)]),
    st.tuples(st.floats(-400, 400), st.floats(-100, 100), st.floats(0, 2), st.floats(0, 2)).map(lambda t: box(t[0], t[1], t[0] + t[2], t[1] + t[3])),
))
def test_polygon_to_cells(polygon):
    ok, res = outcome(dggs.polygon_to_cells, polygon, 4)
    if ok:
        assert isinstance(res, np.ndarray) and res.ndim == 1
        if res.size:
            assert (dggs.get_level(res) == 4).all()
    else:
        assert isinstance(res, dggs.DggsValueError)


def test_polygon_with_huge_longitudes_does_not_hang():
    with time_limit(3):
        with pytest.raises(dggs.DggsValueError):
            dggs.polygon_to_cells(box(0, 0, 1e300, 1), 3)


def test_geojson_properties_of_the_wrong_shape():
    for props in (5, [1, 2], "ab", {"a": 5}):
        with pytest.raises(dggs.DggsValueError):
            dggs.cells_to_geojson(["C401", "C402"], properties=props)


def test_functions_without_ids():
    assert dggs.get_base_cells().shape == (20,) and dggs.get_base_cells(as_int=True).dtype == np.uint64
    assert len(dggs.level_table(np.int64(2))) == 3
    for bad in ("m2", None, 3):
        with pytest.raises(dggs.DggsValueError, match=repr(bad)):
            dggs.cell_area("C", bad)


# --------------------------------------------------------------------------
# The command line
# --------------------------------------------------------------------------


def _cli_ok(args: list[str]) -> None:
    res = CliRunner().invoke(main, args)
    assert res.exit_code in (0, 1, 2), (args, res.output, res.exception)
    if res.exception is not None:
        assert isinstance(res.exception, SystemExit), (args, res.exception)
    assert "Traceback" not in res.output
    if res.exit_code == 1:
        lines = [line for line in res.output.splitlines() if line.strip()]
        assert len(lines) == 1 and lines[0].startswith("Error: "), res.output


cli_text = st.one_of(st.sampled_from(["nan", "inf", "-inf", "1e308", "91", "-0", "C9", "A0\x01", "é", "", "29", "-1", "2.5", "--", "C401"]), st.text(max_size=6).filter(lambda s: "\x00" not in s))


@settings(max_examples=EXAMPLES)
@given(a=cli_text, b=cli_text, c=cli_text, command=st.sampled_from(["from-latlng", "info", "boundary", "levels"]))
def test_cell_commands(a, b, c, command):
    args = {
        "from-latlng": ["cell", "from-latlng", a, b, "--level", c],
        "info": ["cell", "info", a, "--json"],
        "boundary": ["cell", "boundary", a, "--densify", c],
        "levels": ["cell", "levels", "--max-level", a],
    }[command]
    _cli_ok(args)


@pytest.mark.slow  # 9 s here: six interpreters (tests/server/test_errors.py has a one-process version)
def test_cli_errors_in_a_real_process():
    for args in (["cell", "info", "C9"], ["cell", "from-latlng", "nan", "0", "--level", "3"], ["cell", "levels", "--max-level", "29"],
                 ["cell", "boundary", "C401", "--densify", "-1"]):
        proc = subprocess.run([sys.executable, "-m", "dggs.cli", *args], capture_output=True, text=True, timeout=300)
        assert proc.returncode == 1, (args, proc.stderr)
        assert "Traceback" not in proc.stderr and proc.stdout == ""
        assert len(proc.stderr.strip().splitlines()) == 1 and proc.stderr.startswith("Error: "), proc.stderr
    proc = subprocess.run([sys.executable, "-m", "dggs.cli", "cell", "from-latlng", "51.05", "-114.07", "--level", "9"],
                          capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0 and proc.stdout.strip() == "F200021102"
    script = Path(sys.executable).with_name("dggs")  # the installed console script
    if script.exists():
        proc = subprocess.run([str(script), "cell", "info", "A0\u00e9"], capture_output=True, text=True, timeout=300)
        assert proc.returncode == 1 and "Traceback" not in proc.stderr
        assert proc.stderr.strip().splitlines() == [proc.stderr.strip()] and "'A0\u00e9'" in proc.stderr, proc.stderr


@settings(max_examples=EXAMPLES)
@given(value=any_scalars())
def test_vertex_ids(value):
    """Vertex functions: a result for a valid vertex id, else a DggsError naming the value; never raises in is_valid_vertex."""
    assert dggs.is_valid_vertex(value) in (True, False)
    for fn in (dggs.vertex_to_latlng, dggs.vertex_to_cells):
        ok, res = outcome(fn, value)
        assert ok or isinstance(res, dggs.DggsError), (fn.__name__, value, res)


@settings(max_examples=EXAMPLES)
@given(a=st.floats(allow_nan=True, allow_infinity=True), b=st.floats(allow_nan=True, allow_infinity=True))
def test_distances_and_lines(a, b):
    """Any floats: a finite distance / a path, or a CoordinateError."""
    ok, res = outcome(lambda: dggs.great_circle_distance(a, b, 0.0, 0.0))
    assert (ok and np.isfinite(res)) or isinstance(res, dggs.CoordinateError), (a, b, res)
    ok, res = outcome(lambda: dggs.geodesic_to_cells(a, b, 1.0, 1.0, 3))
    assert ok or isinstance(res, dggs.DggsError), (a, b, res)


# --------------------------------------------------------------------------
# Issue 17: sizes, missing values, memory and time
# --------------------------------------------------------------------------


def test_grid_disk_max_cells_counts_the_real_disk():
    """Item 11: max_cells counts the cells of the disk, not the padded row width of the kernel's bound."""
    # 9 cells within 2 steps of a cell away from the icosahedron's vertices (docs/grid.md: 1 + 3 + 5)
    row = dggs.grid_disk(["C401"], 2, max_cells=9)
    assert sorted(c for c in row[0] if c) == dggs.grid_disk("C401", 2)
    assert len(dggs.grid_disk("C401", 2)) == 9
    for limit in range(12):  # the scalar and the list path agree at every limit
        outcomes = []
        for arg, first in (("C401", lambda r: r), (["C401"], lambda r: r[0])):
            try:
                outcomes.append(sorted(c for c in first(dggs.grid_disk(arg, 2, max_cells=limit)) if c))
            except dggs.TooManyCellsError as e:
                assert "C401" in str(e) and f"{limit:,}" in str(e)
                outcomes.append("refused")
        assert outcomes[0] == outcomes[1] == ("refused" if limit < 9 else dggs.grid_disk("C401", 2)), limit
    # a disk is never larger than its level: level 1 has 120 cells (20 faces x 6), level 3 has 1,080
    assert len(dggs.grid_disk("C4", 10**6)) == 120
    assert {len([c for c in r if c]) for r in dggs.grid_disk(np.array(["C401"] * 100), 1000)} == {1080}
    assert len(dggs.grid_disk("C401", 64, max_cells=1080)) == 1080
    with pytest.raises(dggs.TooManyCellsError, match="over the limit of 5"):
        dggs.grid_disk("C401", 64, max_cells=5)
    with pytest.raises(dggs.TooManyCellsError, match="over the limit of 5"):
        dggs.grid_disk(["C401"], 64, max_cells=5)


def test_masked_entries_are_missing_values():
    """Item 6: a numpy masked array's masked entries are missing values (as pandas NA), never their hidden data."""
    strs = np.ma.masked_array(["C401", "C402", "A0"], mask=[0, 1, 0])
    ints = np.ma.masked_array(dggs.str_to_int(["C401", "C402", "A0"]), mask=[0, 1, 0])
    for ids in (strs, ints):
        for call in (dggs.get_level, dggs.cell_to_parent, dggs.edge_neighbors, dggs.cell_to_latlng, dggs.cell_area):
            with pytest.raises(dggs.InvalidCellError, match="at index 1 is not a valid cell id: a missing value"):
                call(ids)
        assert dggs.is_valid_cell(ids).tolist() == [True, False, True]
    two_d = np.ma.masked_array([["C401", "C402"], ["A0", "B1"]], mask=[[0, 0], [0, 1]])
    with pytest.raises(dggs.InvalidCellError, match=r"at index \(1, 1\) is not a valid cell id: a missing value"):
        dggs.get_level(two_d)
    with pytest.raises(dggs.InvalidCellError, match="missing"):
        dggs.get_level([np.ma.masked])
    # an array with a mask but nothing masked is an ordinary array
    assert dggs.get_level(np.ma.masked_array(["C401", "A0"], mask=[0, 0])).tolist() == [3, 1]
    lat = np.ma.masked_array([10.0, 20.0, 30.0], mask=[0, 1, 0])
    for call in (lambda: dggs.latlng_to_cell(lat, 0.0, 5), lambda: dggs.latlng_to_cell(0.0, lat, 5)):
        with pytest.raises(dggs.CoordinateError, match="at index 1 is a missing value"):
            call()
    assert dggs.latlng_to_cell(np.ma.masked_array([10.0], mask=[0]), 0.0, 5).tolist() == [dggs.latlng_to_cell(10.0, 0.0, 5)]


def test_boundary_points_are_checked_before_allocating():
    """Item 9: cells x boundary points over a documented limit is refused before allocating (was numpy's MemoryError)."""
    many = np.full(2000, "C401")
    # 2,000 cells x 3 edges x 100,001 points = 600,006,000 points (8.9 GiB of float64 pairs)
    for call in (
        lambda: dggs.cell_to_boundary(many, densify=100_000),
        lambda: dggs.cell_to_polygon(many, densify=100_000),
        lambda: dggs.cells_to_geojson(many, densify=100_000),
    ):
        with pytest.raises(dggs.TooManyCellsError, match=r"2,000 cells .*600,00\d,\d{3} points.*over the limit of 50,000,000"):
            call()
    with pytest.raises(dggs.TooManyCellsError, match=r"2 cells .* 12 points.*limit of 11"):
        dggs.cell_to_boundary(["C401", "C402"], densify=1, max_points=11)
    assert np.asarray(dggs.cell_to_boundary(["C401", "C402"], densify=1, max_points=12)).shape == (2, 6, 2)
    assert len(dggs.cells_to_geojson(["C401"], densify=2, max_points=10)["features"]) == 1  # a closed ring: 3 x 3 + 1
    with pytest.raises(dggs.TooManyCellsError, match="limit of 9"):
        dggs.cell_to_polygon("C401", densify=2, max_points=9)
    with pytest.raises(dggs.DggsValueError, match="max_points -1"):
        dggs.cell_to_boundary("C401", max_points=-1)


def _zigzag(n: int) -> Polygon:
    """A strip 20 degrees long whose two long sides zigzag 1 degree with ``n`` vertices each."""
    x = np.linspace(-10.0, 10.0, n)
    y = np.where(np.arange(n) % 2 == 0, 0.0, 1.0)
    return Polygon(np.c_[np.r_[x, x[::-1]], np.r_[y, y[::-1] + 2.0]])


@pytest.mark.parametrize("n", [2_000, pytest.param(200_000, marks=pytest.mark.slow)])
def test_a_jagged_polygon_is_filled_exactly_and_its_work_follows_the_output(n):
    """Item 10: a 200,000-vertex zigzag at level 9 took 69 s and 3.4 GB, then GEOS's bad_alloc.

    The oracle: every level-9 cell touching the polygon's bounding box, kept when
    its centre lies inside (shapely's point-in-polygon on the centres).
    """
    import shapely

    from dggs.index.polyfill import _fill

    poly = _zigzag(n)
    work: dict[str, int] = {}
    got = _fill(poly, 9, None, work)
    near = np.asarray(dggs.polygon_to_cells(box(*poly.bounds), 9, mode="overlaps", as_int=True))
    lat, lng = dggs.cell_to_latlng(near)
    want = np.sort(near[shapely.contains_xy(poly, lng, lat)])
    assert got.tolist() == want.tolist() and len(got) > 700
    # cells looked at: a few times those near the bounding box, however many vertices
    assert work["classified"] + work["tested"] < 20 * len(near)


# --------------------------------------------------------------------------
# Issue 21: directed edge ids, local (i, j), lines and circles
# --------------------------------------------------------------------------

GOOD_EDGE = "C401.1"
EDGE_FUNCS = {
    "directed_edge_to_cells": dggs.directed_edge_to_cells,
    "get_directed_edge_origin": dggs.get_directed_edge_origin,
    "get_directed_edge_destination": dggs.get_directed_edge_destination,
    "reverse_directed_edge": dggs.reverse_directed_edge,
    "directed_edge_to_boundary": dggs.directed_edge_to_boundary,
    "edge_length": dggs.edge_length,
}
CORRUPT_EDGES = ["C401.3", "C401.", "C401.1.1", ".1", "C9.0", "C401 .1", "C401.-1", "C401.1 ", 1 << 63, (1 << 64) - 1]


def edge_scalars():
    edges = st.sampled_from([GOOD_EDGE, "A.0", "T5.2", "C4" + "0" * 26 + ".2", dggs.cells_to_directed_edge(GOOD_INT, dggs.edge_neighbors(GOOD_INT)[0])])
    return st.one_of(any_scalars(), st.sampled_from(CORRUPT_EDGES), edges, st.text(alphabet="ACT0125.", max_size=8))


@settings(max_examples=EXAMPLES)
@given(value=edge_scalars(), func=st.sampled_from(sorted(EDGE_FUNCS)))
def test_directed_edge_ids(value, func):
    """An edge function answers exactly the valid directed edges; anything else is an InvalidCellError naming it."""
    valid = dggs.is_valid_directed_edge(value)
    assert valid in (True, False)
    ok, res = outcome(EDGE_FUNCS[func], value)
    if ok:
        assert valid, f"{func} accepted {value!r}"
    else:
        assert not valid, (func, value, res)
        assert isinstance(res, dggs.InvalidCellError), res
        names(res, value)


@settings(max_examples=EXAMPLES)
@given(a=any_scalars(), b=any_scalars())
@example(a=GOOD, b="C4012")  # a neighbour's child: two levels
@example(a=GOOD, b="T522")  # same level, not neighbours
def test_cells_to_directed_edge_pairs(a, b):
    """Two cells: an edge only for two edge neighbours; else a typed error (the corrupt id named)."""
    ok, res = outcome(dggs.cells_to_directed_edge, a, b)
    va, vb = dggs.is_valid_cell(a), dggs.is_valid_cell(b)
    if ok:
        assert va and vb and dggs.are_neighbor_cells(a, b), (a, b)
        assert dggs.directed_edge_to_cells(res) == [a, b] or dggs.is_valid_directed_edge(res)
    elif not (va and vb):
        assert isinstance(res, dggs.InvalidCellError), res
        names(res, *([] if va else [a]), *([] if vb else [b]))
    else:
        assert isinstance(res, dggs.DggsValueError), res


@settings(max_examples=EXAMPLES)
@given(i=st.one_of(st.sampled_from(COUNT_ARGS + BAD_NUMBERS), st.integers(-(1 << 70), 1 << 70)), j=st.sampled_from([0, 1, -1, 2.5, None]))
def test_local_ij_to_cell_arguments(i, j):
    """Lattice coordinates: integers only; a pair that names no cell or lies out of range is a DggsValueError."""
    ok, res = outcome(dggs.local_ij_to_cell, GOOD, i, j)
    ints = all(isinstance(_py(v), int) and not isinstance(_py(v), bool) for v in (i, j))
    if ok:
        assert ints, (i, j)
        assert dggs.cell_to_local_ij(GOOD, res) == (i, j) or list(dggs.cell_to_local_ij(GOOD, res)) == [i, j]
    else:
        assert isinstance(res, dggs.DggsValueError), res


@settings(max_examples=EXAMPLES)
@given(lat=st.one_of(st.sampled_from(BAD_NUMBERS + EDGE_NUMBERS), st.floats()), lng=st.one_of(st.sampled_from(BAD_NUMBERS + EDGE_NUMBERS), st.floats()))
def test_line_to_cells_coordinates(lat, lng):
    """A polyline's vertex: a path of neighbours for real coordinates in range, else a CoordinateError."""
    ok, res = outcome(lambda: dggs.line_to_cells(np.array([[lat, lng], [0.0, 0.0]], dtype=object), 4))
    good = _numbers_ok([lat, lng]) and -90 <= float(_py(lat)) <= 90
    if ok:
        assert good, (lat, lng)
        assert all(dggs.are_neighbor_cells(x, y) for x, y in zip(res[:-1], res[1:], strict=True))
    else:
        assert isinstance(res, dggs.CoordinateError), res


@settings(max_examples=EXAMPLES)
@given(radius=st.one_of(st.sampled_from(BAD_NUMBERS + EDGE_NUMBERS + [-1.0, 1e7, 1e7 + 1]), st.floats()), lat=st.sampled_from([0.0, 90.0, -90.0, 91.0, math.nan]))
def test_circle_to_cells_arguments(radius, lat):
    """A radius in metres 0..10,000 km and a centre in range give cells; anything else a typed error."""
    ok, res = outcome(dggs.circle_to_cells, lat, 179.9, radius, 2)
    r = _py(radius)
    good_r = isinstance(r, (int, float)) and not isinstance(r, bool) and math.isfinite(r) and 0 <= r <= 1e7
    good_c = math.isfinite(lat) and abs(lat) <= 90
    if ok:
        assert good_r and good_c, (lat, radius)
        assert all(dggs.get_level(c) == 2 for c in res)
    elif not good_c:
        assert isinstance(res, dggs.CoordinateError), res
    else:
        assert not good_r and isinstance(res, dggs.DggsValueError), res
        names(res, radius)


# --------------------------------------------------------------------------
# A store's roll-up, as dicts and as a table (issue 32: the suite skipped as_table=True)
# --------------------------------------------------------------------------

AGGREGATE_ARGS = {
    "level": BAD_LEVELS,
    "column": [5, b"pop", ["pop"], "nope", "", np.str_("nope"), "pop\x00", '"pop"', "cell", math.nan],
    "stats": [5, None, "", "SUM", ["sum", 5], [b"sum"], [None], {"sum": 1}, b"sum", math.nan, ["count", "nope"]],
    "cell": [*CORRUPT_SCALARS, ["C401", 5], np.array([1.5]), "C4" + "0" * 27],
    "order_by": [5, "nope", ["sum"], b"sum", "max", math.nan],
    "descending": ["yes", None, np.array([True, False]), 2, math.nan, "False"],
    "limit": [-1, 2.5, "3", True, math.nan, 1 << 70, np.array([3]), "", -(1 << 70)],
    "as_table": ["no", None, 2, np.array([True, False]), 0, "", math.nan, "True"],
}
AGGREGATE_CASES = [(k, v) for k, values in AGGREGATE_ARGS.items() for v in values]


@pytest.fixture(scope="module")
def small_store():
    from dggs.storage import CellStore

    with CellStore() as store:
        store.ingest_points(
            [1.0, 1.1, -40.0], [2.0, 2.1, 100.0], 6, {"pop": [5, 7, 1], "name": ["a", "b", "c"], "x": [1.5, None, 2.0]}
        )
        yield store


@pytest.mark.parametrize("as_table", [False, True])
@pytest.mark.parametrize(("arg", "value"), AGGREGATE_CASES, ids=[f"{k}-{i}" for i, (k, _) in enumerate(AGGREGATE_CASES)])
def test_aggregate(small_store, arg, value, as_table):
    kwargs = {"column": "pop", "stats": ("count", "sum"), "as_table": as_table, arg: value}
    level = kwargs.pop("level", 3)
    ok, got = outcome(small_store.aggregate, level, **kwargs)
    if not ok:
        if isinstance(value, (str, int, float, np.generic)) and not isinstance(value, bool) and value != "":
            names(got, value)
        return
    if kwargs["as_table"]:
        assert isinstance(got, pa.Table) and "cell" in got.column_names
        rows = got.to_pylist()
    else:
        assert isinstance(got, list)
        rows = got
    assert sum(r["count"] for r in rows) <= 3
    assert all(dggs.is_valid_cell(r["cell"]) for r in rows)


def test_aggregate_as_table_equals_the_dicts(small_store):
    for stats in (("count",), ("count", "sum", "mean", "min", "max")):
        for cell in (None, "C", dggs.latlng_to_cell(1.0, 2.0, 2)):
            want = small_store.aggregate(3, "pop", stats, cell=cell)
            assert small_store.aggregate(3, "pop", stats, cell=cell, as_table=True).to_pylist() == want


# --------------------------------------------------------------------------
# dggs.duckdb.load (issue 32: the suite skipped it)
# --------------------------------------------------------------------------


@pytest.fixture(scope="module")
def unsigned_con():
    duckdb = pytest.importorskip("duckdb")
    con = duckdb.connect(config={"allow_unsigned_extensions": "true"})
    yield con
    con.close()


@pytest.mark.parametrize("con", [None, 5, "x", object(), GOOD, b"duckdb"])
def test_duckdb_load_takes_only_a_connection(con):
    from dggs.duckdb import load

    ok, got = outcome(load, con)
    assert not ok and isinstance(got, dggs.DggsValueError)
    if isinstance(con, (str, int)):
        names(got, con)


LOAD_PATHS = [p for p in CORRUPT_SCALARS if p is not None]  # None: the default file


@pytest.mark.parametrize("path", [*LOAD_PATHS, "spatial", "json", "x'; SELECT 1; --", "/nonexistent/x.duckdb_extension"])
def test_duckdb_load_takes_only_a_file(unsigned_con, path):
    """Any other text was read by DuckDB as the name of an installed extension ("spatial" loads that one)."""
    from dggs.duckdb import load

    ok, got = outcome(load, unsigned_con, path)
    assert not ok and isinstance(got, dggs.DggsValueError)
    if isinstance(path, (str, int, float)) and not isinstance(path, bool) and "\x00" not in str(path):
        names(got, path)


def test_duckdb_load_of_a_broken_file_or_connection(unsigned_con, tmp_path):
    duckdb = pytest.importorskip("duckdb")
    from dggs.duckdb import load

    junk = tmp_path / "it's.duckdb_extension"
    junk.write_bytes(b"\x00" * 64)
    for con, path in [(unsigned_con, junk), (unsigned_con, str(junk).encode()), (unsigned_con, tmp_path)]:
        ok, got = outcome(load, con, path)
        assert not ok
    closed = duckdb.connect()
    closed.close()
    ok, got = outcome(load, closed, junk)
    assert not ok and isinstance(got, dggs.ExtensionLoadError) and isinstance(got, RuntimeError)
    ok, got = outcome(load, unsigned_con, junk)
    assert isinstance(got, dggs.ExtensionLoadError) and "it's" in str(got)


# --------------------------------------------------------------------------
# Integrations the suite skipped (issue 32): dggs.arrow's box, the pandas accessor, the polars namespace
# --------------------------------------------------------------------------

BOXES = [None, 1, 2.5, "1234", "abcd", b"\x01\x02\x03\x04", bytearray(b"\x01\x02\x03\x04"), {"a": 1, "b": 2, "c": 3, "d": 4},
         (1, 2, 3), (1, 2, 3, 4, 5), (), np.array([[0, 0, 1, 1]]), (True, 0, 1, 1), (np.True_, 0, 1, 1), (1 << 1100, 0, 1, 1),
         (1j, 0, 1, 1), (object(), 0, 1, 1)]
BOXES += [(v, -10, 1, 10) for v in CORRUPT_SCALARS] + [(0, v, 1, 10) for v in BAD_NUMBERS]


@pytest.mark.parametrize("box", BOXES, ids=repr)
def test_split_box_and_bbox_filter(box):
    """A query box is 4 finite real numbers in range: anything else (text and bytes, which iterate to 4 characters
    or bytes, booleans, numbers too large for a float) is a DggsValueError naming the box, never a raw error or a
    box read from the wrong values."""
    from dggs.arrow import bbox_filter, split_box

    ok, res = outcome(split_box, box)
    numbers = isinstance(box, tuple) and len(box) == 4 and all(
        isinstance(v, (int, float, np.integer, np.floating)) and not isinstance(v, (bool, np.bool_)) for v in box)
    if ok:
        assert numbers and res[0][1] == float(box[1]) and all(len(b) == 4 for b in res), (box, res)
    else:
        assert isinstance(res, dggs.DggsValueError)
        assert repr(box) in str(res)
        assert not outcome(bbox_filter, box)[0]


ACCESSOR_ARGS = {"cell_to_children": (4,), "linetrace": (4,), "resample": (2,), "aggregate": (2,)}
ACCESSOR_CELL_VERBS = ["aggregate", "cell_area", "cell_to_center_child", "cell_to_children", "cell_to_geometry", "cell_to_latlng",
                       "cell_to_parent", "cell_to_point", "disk_smoothing", "get_face", "get_level", "grid_disk", "grid_ring",
                       "is_valid_cell", "resample"]


def test_every_accessor_method_is_covered():
    pytest.importorskip("geopandas")
    import dggs.pandas  # noqa: F401

    methods = {m for m in dir(pd.DataFrame().dggs) if not m.startswith("_")}
    assert methods == set(ACCESSOR_CELL_VERBS) | {"latlng_to_cell", "linetrace", "polyfill", "sjoin_cells"}


@pytest.mark.parametrize("value", CORRUPT_SCALARS, ids=repr)
@pytest.mark.parametrize("verb", ACCESSOR_CELL_VERBS)
def test_accessor_cell_verbs_on_corrupt_ids(verb, value):
    """``df.dggs.<verb>()`` over a cell column holding a corrupt id: a DggsError naming it (is_valid_cell: False),
    never a raw error nor an answer for the bad row."""
    pytest.importorskip("geopandas")
    import dggs.pandas  # noqa: F401

    df = pd.DataFrame({"cell_3": pd.Series([GOOD, value], dtype=object), "x": [1.0, 2.0]})
    ok, res = outcome(getattr(df.dggs, verb), *ACCESSOR_ARGS.get(verb, ()))
    if verb == "is_valid_cell":
        assert ok and res["is_valid"].tolist() == [True, False]
    else:
        assert not ok, (verb, value, res)
        names(res, value)


@pytest.mark.parametrize("verb", ACCESSOR_CELL_VERBS)
def test_accessor_index_of_row_numbers_is_no_cell(verb):
    """A frame without a cell column reads its index: row numbers 0, 1 are no cell ids (cell_area read them as
    levels and answered each level's mean area)."""
    pytest.importorskip("geopandas")
    import dggs.pandas  # noqa: F401

    ok, res = outcome(getattr(pd.DataFrame({"x": [1.0, 2.0]}).dggs, verb), *ACCESSOR_ARGS.get(verb, ()))
    if verb == "is_valid_cell":
        assert ok and res["is_valid"].tolist() == [False, False]
    else:
        assert not ok and isinstance(res, dggs.InvalidCellError), (verb, res)
        names(res, 0)


@pytest.mark.parametrize("label", [["cell_3"], np.array(["cell_3"]), {"cell_3"}, "nope", 3, ("cell_3",)], ids=repr)
@pytest.mark.parametrize("verb", ACCESSOR_CELL_VERBS)
def test_accessor_column_labels(verb, label):
    """``column=`` that is no column of the frame (or no label at all: a list, an array) is a DggsError naming it."""
    pytest.importorskip("geopandas")
    import dggs.pandas  # noqa: F401

    df = pd.DataFrame({"cell_3": [GOOD, "C402"], "x": [1.0, 2.0]})
    ok, res = outcome(getattr(df.dggs, verb), *ACCESSOR_ARGS.get(verb, ()), column=label)
    assert not ok
    assert repr(label) in str(res) or str(label) in str(res)


@pytest.mark.parametrize("value", [1j, np.complex128(1 + 0j), True, "n/a", b"1", object(), math.inf, 91.0], ids=repr)
@pytest.mark.parametrize("where", ["lat", "lng"])
def test_accessor_latlng_to_cell_coordinates(where, value):
    """Complex numbers, booleans, text and objects in a coordinate column are refused naming the value (a complex
    column lost its imaginary part on the way to float64, and the row got a cell)."""
    pytest.importorskip("geopandas")
    import dggs.pandas  # noqa: F401

    cols = {"lat": pd.Series([1.0, 2.0], dtype=object), "lng": pd.Series([3.0, 4.0], dtype=object)}
    cols[where][1] = value
    typed = pd.DataFrame({k: (pd.Series(list(v)) if k == where else v) for k, v in cols.items()})  # complex128, bool, ...
    for df in (pd.DataFrame(cols), typed):
        ok, res = outcome(df.dggs.latlng_to_cell, 3)
        if where == "lng" and value == 91.0:  # any finite longitude is on the globe
            assert ok and res["cell_3"].tolist() == dggs.latlng_to_cell([1.0, 2.0], [3.0, 91.0], 3)
            continue
        assert not ok and isinstance(res, dggs.CoordinateError), (value, res)
        if df is not typed or not isinstance(value, (complex, np.complexfloating)):  # a complex column names its row 0
            names(res, value)


POLARS_SERIES = [["C9", GOOD], ["", None], [" C401"], ["A0\x00"], ["C403"], [GOOD, None]]
POLARS_INT_SERIES = [[-1, 5], [0, 1], [(1 << 64) - 1], [GOOD_INT, None]]


@pytest.mark.parametrize("values", POLARS_SERIES + POLARS_INT_SERIES + [[1.5, math.nan], [True], [b"C9"]], ids=repr)
def test_polars_namespace_on_corrupt_ids(values):
    """Every verb of ``pl.col(...).dggs`` and ``Series.dggs`` over a column with a corrupt id: a DggsError naming it
    (is_valid_cell: False), never a raw polars error nor an answer for the bad row."""
    pl = pytest.importorskip("polars")
    import dggs.polars

    dtype = pl.UInt64 if values in POLARS_INT_SERIES and min(v for v in values if v is not None) >= 0 else None
    s = pl.Series("cell", values, dtype=dtype, strict=False)
    bad = next(v for v in values if not dggs.is_valid_cell(v))
    for verb in dggs.polars.VERBS:
        for run in (lambda verb=verb: getattr(s.dggs, verb)(), lambda verb=verb: pl.DataFrame({"cell": s}).select(getattr(pl.col("cell").dggs, verb)())):
            ok, res = outcome(run)
            if verb == "is_valid_cell":
                got = res.to_list() if ok and isinstance(res, pl.Series) else res["cell"].to_list()
                assert ok and got == [bool(dggs.is_valid_cell(v)) for v in values], (values, got)
            else:
                assert not ok, (verb, values, res)
                names(res, bad)


@pytest.mark.parametrize("column", [["x"], [True], [b"1"], [None]], ids=repr)
def test_polars_latlng_to_cell_columns(column):
    """Text, booleans and binary in a coordinate column are a CoordinateError naming the value (polars' strict cast
    raised its raw InvalidOperationError on text and read booleans as 0 and 1); a null is a missing value, refused."""
    pl = pytest.importorskip("polars")
    import dggs.polars

    df = pl.DataFrame({"lat": column, "lng": [0.0]})
    ok, res = outcome(lambda: df.select(dggs.polars.latlng_to_cell("lat", "lng", 3)))
    assert not ok and isinstance(res, dggs.CoordinateError), res
    if column[0] is not None:
        names(res, column[0])
