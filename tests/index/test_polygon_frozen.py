"""Polygons unchanged: ``cell_to_polygon`` by tolerance equals the digests frozen before the fused count-and-rings pass.

The oracle (tests/index/fixtures/polygons_frozen.json, tests/index/freeze_polygons.py) was written by the commit
before it (4b831ac): for random cells of every level 0-28 and the cells at the poles, the antimeridian and the
icosahedron's vertices and edges, on both grids, the points per edge each cell got and its WKB, bit for bit.
Both id forms are drawn and must give those same bytes.
"""

from __future__ import annotations

import json

import numpy as np
import pytest

import dggs

from .freeze_polygons import FIXTURE, GRIDS, cells, digests

FROZEN = json.loads(FIXTURE.read_text())


def test_the_cells_are_the_frozen_ones():
    """The inputs themselves: a change of the cell generator would make every digest differ for nothing."""
    import hashlib

    for level in range(29):
        assert hashlib.sha256("\n".join(cells(level)).encode()).hexdigest() == FROZEN["ids"][str(level)], level


@pytest.mark.parametrize("grid", GRIDS)
@pytest.mark.parametrize("tolerance", [10.0, 1.0, pytest.param("exact", marks=pytest.mark.slow)])
@pytest.mark.parametrize("form", ["int", "str"])
def test_polygons_equal_the_frozen_ones(grid, tolerance, form):
    wrong = []
    for level in range(29):
        ids = cells(level)
        drawn = ids if form == "str" else np.asarray(dggs.str_to_int(ids), dtype=np.uint64)
        if digests(grid, tolerance, drawn) != FROZEN["digests"][f"{grid} {tolerance} {level}"]:
            wrong.append(level)
    assert wrong == [], f"{grid} tolerance {tolerance!r} ({form} ids): levels {wrong} differ from the frozen polygons"
