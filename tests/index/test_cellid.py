"""Cell id format: validity, parsing, errors."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

import dggs
from dggs.errors import InvalidCellError, LevelError

from ..strategies import cells


@given(cells())
def test_valid_ids_are_valid(cell):
    assert dggs.is_valid_cell(cell)
    assert dggs.get_level(cell) == len(cell) - 1
    assert dggs.get_face(cell) == "ABCDEFGHIJKLMNOPQRST".index(cell[0])


@given(st.text(max_size=45))
def test_is_valid_cell_never_raises_and_agrees_with_the_grammar(text):
    import re

    expected = re.fullmatch(r"[A-T]([0-5][0-2]{0,%d})?" % (dggs.MAX_LEVEL - 1), text) is not None
    assert dggs.is_valid_cell(text) == expected


@pytest.mark.parametrize(
    "bad", ["", "U", "a", "A6", "A03", "C4013", "C" + "0" * 41, " A", "A0 ", "A\x001", 42, None, 3.5, b"A6", True]
)
def test_invalid_ids(bad):
    assert dggs.is_valid_cell(bad) is False
    with pytest.raises(InvalidCellError):
        dggs.get_level(bad)


def test_error_names_the_bad_id_and_index():
    with pytest.raises(InvalidCellError, match=r"'C9' at index 1"):
        dggs.cell_to_latlng(["C4", "C9"])


def test_max_level_ids_are_accepted_and_one_more_is_not():
    deepest = "C4" + "1" * (dggs.MAX_LEVEL - 1)
    assert dggs.is_valid_cell(deepest)
    assert not dggs.is_valid_cell(deepest + "0")


def test_array_validity():
    arr = np.array(["C401", "C9", "T5"])
    assert dggs.is_valid_cell(arr).tolist() == [True, False, True]
    assert dggs.is_valid_cell(["C401", 5]) == [True, False]


@pytest.mark.parametrize("level", [-1, dggs.MAX_LEVEL + 1, 2.5, "3", True])
def test_bad_levels(level):
    with pytest.raises(LevelError, match="level"):
        dggs.latlng_to_cell(0.0, 0.0, level)


def test_bytes_ids_are_ids():
    assert dggs.get_level(b"A01") == 2
    assert dggs.cell_to_parent(np.array([b"A01"])).tolist() == [b"A0"]


def test_ids_sort_depth_first_and_prefix_ranges_hold_descendants():
    kids = dggs.cell_to_children("C4", 4)
    assert kids == sorted(kids)
    everything = np.sort(np.concatenate([dggs.cell_to_children("C", 3), dggs.cell_to_children("D", 3)]))
    lo, hi = "C40", "C40~"
    in_range = everything[(everything >= lo) & (everything < hi)]
    assert set(in_range.tolist()) == set(dggs.cell_to_children("C40", 3))
