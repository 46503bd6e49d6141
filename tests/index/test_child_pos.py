"""Child positions (h3's cell_to_child_pos / child_pos_to_cell) against brute-force enumeration of descendants."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pyarrow as pa
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

import dggs
from dggs.errors import DggsValueError, InvalidCellError, LevelError, LevelMismatchError

from ..strategies import cells, examples, special_points


def _pos_oracle(cell: str, parent_level: int) -> int:
    """The position from the string's digits, by hand: base 6 for the level-1 digit, base 3 after."""
    pos = 0
    for lv in range(parent_level + 1, len(cell)):
        pos = pos * (6 if lv == 1 else 3) + int(cell[lv])
    return pos


def _descendants(parent: str, level: int) -> list[str]:
    """Every descendant at ``level``, in digit order, built from the alphabet (not by the code under test)."""
    out = [parent]
    for lv in range(len(parent), level + 1):
        out = [c + d for c in out for d in ("012345" if lv == 1 else "012")]
    return out


@pytest.mark.parametrize("parent", ["A", "T", "C4", "N31", "S5012"])
@pytest.mark.parametrize("depth", [0, 1, 2, 3])
@pytest.mark.parametrize("as_int", [False, True])
def test_positions_enumerate_the_descendants(parent, depth, as_int):
    level = len(parent) - 1 + depth
    kids = _descendants(parent, level)
    assert sorted(kids) == sorted(dggs.cell_to_children(parent, level))
    p = dggs.str_to_int(parent) if as_int else parent
    ids = [dggs.str_to_int(k) for k in kids] if as_int else kids
    assert dggs.cell_to_child_pos(ids, len(parent) - 1) == list(range(len(kids)))
    assert dggs.child_pos_to_cell(list(range(len(kids))), p, level) == ids
    for pos in (0, len(kids) - 1):  # the scalar path
        assert dggs.child_pos_to_cell(pos, p, level) == ids[pos]
        assert dggs.cell_to_child_pos(ids[pos], len(parent) - 1) == pos
    with pytest.raises(DggsValueError, match=str(len(kids))):
        dggs.child_pos_to_cell(len(kids), p, level)
    with pytest.raises(DggsValueError, match="-1"):
        dggs.child_pos_to_cell(-1, p, level)


def _special_cells(level: int) -> list[str]:
    lat, lng = zip(*special_points(), strict=True)
    return sorted(set(dggs.latlng_to_cell(list(lat), list(lng), level)))


@settings(max_examples=examples(100))
@given(cell=cells(), data=st.data())
@example(cell="A" + "0" * 28, data=None)
@example(cell="T5" + "2" * 27, data=None)
def test_position_round_trip_at_any_level(cell, data):
    levels = range(len(cell)) if data is None else [data.draw(st.integers(0, len(cell) - 1))]
    for p in levels:
        parent = cell[: p + 1]
        pos = _pos_oracle(cell, p)
        for form in (str, dggs.str_to_int):
            c, par = form(cell), form(parent)
            assert dggs.cell_to_child_pos(c, p) == pos
            assert dggs.child_pos_to_cell(pos, par, len(cell) - 1) == c


@pytest.mark.parametrize("level", [1, 5, 17, 28])
def test_special_cells(level):
    """Poles, the antimeridian, icosahedron vertices and face-edge midpoints."""
    ids = _special_cells(level)
    for p in range(0, level + 1, max(1, level // 4)):
        pos = [_pos_oracle(c, p) for c in ids]
        assert dggs.cell_to_child_pos(ids, p) == pos
        parents = [c[: p + 1] for c in ids]
        assert dggs.child_pos_to_cell(pos, parents, level) == ids
        assert dggs.child_pos_to_cell(np.array(pos), dggs.str_to_int(parents), level) == dggs.str_to_int(ids)


def test_the_largest_positions():
    n = 6 * 3**27
    assert dggs.child_pos_to_cell(n - 1, "T", 28) == "T5" + "2" * 27
    assert dggs.cell_to_child_pos("T5" + "2" * 27, 0) == n - 1
    with pytest.raises(DggsValueError, match=f"{n}"):
        dggs.child_pos_to_cell(n, "T", 28)


def test_containers():
    ids = ["C401", "C402", "C421"]
    arr = dggs.cell_to_child_pos(np.array(ids), 1)
    assert isinstance(arr, np.ndarray) and arr.tolist() == [1, 2, 7]
    s = dggs.cell_to_child_pos(pd.Series(ids, index=[5, 6, 7]), 1)
    assert s.index.tolist() == [5, 6, 7] and s.tolist() == [1, 2, 7]
    assert dggs.cell_to_child_pos(pa.array(ids), 1).to_pylist() == [1, 2, 7]
    out = dggs.child_pos_to_cell(np.array([1, 2, 7]), "C4", 3)
    assert isinstance(out, np.ndarray) and out.tolist() == ids
    out = dggs.child_pos_to_cell(pd.Series([1, 2, 7]), dggs.str_to_int("C4"), 3)
    assert isinstance(out, pd.Series) and out.tolist() == dggs.str_to_int(ids)
    out = dggs.child_pos_to_cell(pa.array([1, 2, 7]), "C4", 3)
    assert out.to_pylist() == ids
    out = dggs.child_pos_to_cell(1, pd.Series(["C40", "C41"], index=[3, 4]), 3)
    assert out.index.tolist() == [3, 4] and out.tolist() == ["C401", "C411"]


def test_invalid_inputs():
    with pytest.raises(LevelMismatchError, match="C401"):
        dggs.cell_to_child_pos("C401", 4)
    with pytest.raises(LevelMismatchError, match="C401"):
        dggs.child_pos_to_cell(0, "C401", 2)
    with pytest.raises(LevelError):
        dggs.cell_to_child_pos("C401", 29)
    with pytest.raises(LevelError):
        dggs.child_pos_to_cell(0, "C", -1)
    with pytest.raises(InvalidCellError, match="Z1"):
        dggs.cell_to_child_pos("Z1", 0)
    for bad in (1.5, True, "1", None):
        with pytest.raises(DggsValueError, match="child position"):
            dggs.child_pos_to_cell(bad, "C4", 3)
    with pytest.raises(DggsValueError):
        dggs.child_pos_to_cell([1, 2, 3], ["C4", "C5"], 3)
