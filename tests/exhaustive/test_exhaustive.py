"""Exhaustive checks over every cell of a level (the deepest ones marked slow: `make test-all`)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from pyproj import Geod

import dggs

from ..gridref import mirror_neighbours

GEOD = Geod(ellps="WGS84")


def all_cells(level):
    return dggs.get_base_cells() if level == 0 else dggs.cell_to_children(dggs.get_base_cells(), level)


@pytest.mark.parametrize("level", [0, 1, 2, 3, 4, pytest.param(5, marks=pytest.mark.slow), pytest.param(6, marks=pytest.mark.slow)])
def test_every_cell_has_the_same_geodesic_area(level):
    cells = all_cells(level)
    b = dggs.cell_to_boundary(cells, densify=256)
    areas = np.array([abs(GEOD.polygon_area_perimeter(r[:, 1], r[:, 0])[0]) for r in b])
    assert np.abs(areas / dggs.cell_area(level) - 1).max() <= 2e-6
    assert math.fsum(areas) == pytest.approx(dggs.cell_area(0) * 20, rel=2e-6)


@pytest.mark.parametrize("level", [5, 6, pytest.param(8, marks=pytest.mark.slow), pytest.param(9, marks=pytest.mark.slow)])
def test_every_cell_neighbours_symmetric_and_equal_to_mirror_construction(level):
    cells = all_cells(level)
    nb = dggs.edge_neighbors(cells)
    assert np.array_equal(nb, mirror_neighbours(cells))
    index = np.searchsorted(cells, nb)
    assert np.array_equal(cells[index], nb)  # every neighbour is a cell of the level
    back = nb[index]  # (N, 3, 3): the neighbours' neighbours
    assert np.all(np.any(back == cells[:, None, None], axis=2))
    assert np.all(nb[:, 0] != nb[:, 1]) and np.all(nb[:, 1] != nb[:, 2]) and np.all(nb[:, 0] != nb[:, 2])


@pytest.mark.parametrize("level", [5, 6, pytest.param(9, marks=pytest.mark.slow), pytest.param(10, marks=pytest.mark.slow)])
def test_every_centre_maps_back(level):
    cells = all_cells(level)
    lat, lng = dggs.cell_to_latlng(cells)
    assert np.array_equal(dggs.latlng_to_cell(lat, lng, level), cells)
