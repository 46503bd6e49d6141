"""The compiled single-id entries (dggs.index._kernel.scalar) against the array path and the Python codec.

The oracles are independent of the code under test: the string <-> int codec of
``dggs.index._convert.strings`` (pure Python dict look-ups, itself checked against
the per-digit layout in tests/index/convert), the array kernels (``dggs.latlng_to_cell``
on a numpy array, ``dggs.cell_to_latlng`` on a list) and the prefix rule of string ids.
Each property runs on valid ids of every level, on junk, and at the poles, the
antimeridian and the icosahedron's vertices.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import example, given
from hypothesis import strategies as st

import dggs
from dggs.index._convert import strings
from dggs.index._kernel import scalar
from tests.strategies import cells, latlngs, levels, special_points

SPECIAL = special_points()
_JUNK = ["", "Z", "U1", "A6", "A03", "A0 1", "a01", "A01\x00", "A0١", "A" + "0" * 29, "T5" + "2" * 28, "+A0", "A_0"]


@given(st.one_of(cells(), st.text(max_size=32), st.text(alphabet="ABTU0123456 _+-", max_size=31)))
@example("A")
@example("T5" + "2" * 27)
@example("T5" + "2" * 28)
@example("A0١")
@example("")
def test_parse_one_agrees_with_the_python_codec(s):
    assert scalar.parse_one(s) == strings.parse_str(s)


@pytest.mark.parametrize("s", _JUNK)
def test_parse_one_refuses_junk(s):
    assert scalar.parse_one(s) == 0


@given(st.one_of(st.integers(min_value=0, max_value=2**63 - 1), cells().map(strings.parse_str)))
@example(0)
@example(1 << 62)
@example((1 << 62) | (20 << 57))
@example((1 << 62) | (7 << 54))
@example((1 << 62) | (1 << 54) | 1)  # a hole above level 28's field
@example(2**63 - 1)
def test_format_one_agrees_with_the_python_codec(c):
    assert scalar.format_one(c) == (strings.format_int(c) or "")


@given(cells(), st.integers(min_value=-1, max_value=dggs.MAX_LEVEL + 1))
@example("A", -1)
@example("A", 0)
@example("T5" + "2" * 27, 27)
def test_parent_str_is_the_prefix(cell, level):
    n = len(cell) - 1
    want = level if level >= 0 else n - 1
    expected = cell[: want + 1] if 0 <= want <= n else ""
    assert scalar.parent_str(cell, level) == expected


@pytest.mark.parametrize("s", _JUNK)
def test_parent_str_misses_junk(s):
    assert scalar.parent_str(s, -1) == ""


@given(latlngs(), levels())
@example((90.0, 0.0), 5)
@example((-90.0, 180.0), 28)
@example((0.0, 180.0), 17)
@example((0.0, -180.0), 17)
def test_point_str_matches_the_array_path(p, level):
    lat, lng = p
    expected = dggs.latlng_to_cell(np.array([lat]), np.array([lng]), level)[0]
    assert scalar.point_str(lat, lng, level) == expected


@pytest.mark.parametrize("lat, lng", SPECIAL)
def test_point_str_at_the_special_points(lat, lng):
    for level in (0, 1, 9, 17, dggs.MAX_LEVEL):
        assert scalar.point_str(lat, lng, level) == dggs.latlng_to_cell(np.array([lat]), np.array([lng]), level)[0]


@pytest.mark.parametrize("lat, lng", [(math.nan, 0.0), (0.0, math.inf), (90.5, 0.0), (-91.0, 3.0)])
def test_point_str_misses_points_off_the_globe(lat, lng):
    assert scalar.point_str(lat, lng, 5) == ""


@given(cells())
@example("A")
@example("T5" + "2" * 27)
def test_centre_str_matches_the_array_path(cell):
    lat, lng = dggs.cell_to_latlng([cell])
    assert scalar.centre_str(cell) == (lat[0], lng[0])


@pytest.mark.parametrize("s", _JUNK)
def test_centre_str_misses_junk(s):
    lat, lng = scalar.centre_str(s)
    assert math.isnan(lat) and math.isnan(lng)


@pytest.mark.parametrize("lat, lng", SPECIAL)
def test_the_verbs_single_calls_equal_their_one_element_calls_at_the_special_points(lat, lng):
    for level in (0, 1, 17, dggs.MAX_LEVEL):
        for as_int in (False, True):
            one = dggs.latlng_to_cell(lat, lng, level, as_int=as_int)
            assert one == dggs.latlng_to_cell([lat], [lng], level, as_int=as_int)[0]
            assert type(one) is (int if as_int else str)
            assert dggs.cell_to_latlng(one) == tuple(v[0] for v in dggs.cell_to_latlng([one]))
            if level:
                assert dggs.cell_to_parent(one) == dggs.cell_to_parent([one])[0]
                assert dggs.cell_to_parent(one, 0) == dggs.cell_to_parent([one], 0)[0]
