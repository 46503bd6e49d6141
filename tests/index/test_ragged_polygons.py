"""The default polygons' chunked one-pass build (index/_shapes.py ragged_geometries) against the per-count path.

Each cell drawn by ``cell_to_polygon(ids, tolerance=t)`` must be the polygon ``cell_to_polygon(cell, densify=d)``
draws at the count ``d`` the tolerance asks for (dggs_one_boundary + ``shapely.polygons``, another path), across
the chunks' boundaries and for the cells at a pole or across the antimeridian; ``max_points`` names every cell's
points, however many chunks were drawn before the limit was crossed.
"""

from __future__ import annotations

import numpy as np
import pytest
import shapely

import dggs
from dggs.errors import TooManyCellsError
from dggs.index._densify import edge_points
from dggs.index._shapes import _RAGGED_CHUNK


def _cells(n: int, level: int, seed: int) -> np.ndarray:
    rng = np.random.default_rng(seed)
    lat = np.degrees(np.arcsin(rng.uniform(-1, 1, n)))
    lng = rng.uniform(-180, 180, n)
    spots = np.linspace(0, n - 1, 80).astype(int)  # cells at a pole and on the antimeridian, in every chunk
    lat[spots[0::2]] = np.linspace(88.5, 90.0, 40) * np.where(np.arange(40) % 2, 1.0, -1.0)
    lng[spots[1::2]] = np.where(np.arange(40) % 2, 180.0, -180.0)
    return np.asarray(dggs.latlng_to_cell(lat, lng, level, as_int=True), dtype=np.uint64)


@pytest.mark.parametrize("grid", ["ISEA", "IVEA"])
def test_chunks_draw_what_each_count_draws(grid):
    ids = _cells(2 * _RAGGED_CHUNK + 77, 10, 35)
    drawn = dggs.Grid(grid).cell_to_polygon(ids, tolerance=10.0)
    counts = edge_points(ids, 10.0, grid == "IVEA")
    assert {0, 1, 2, 3} <= set(counts.tolist())  # rings from the count's points, and rings drawn anew
    want = np.empty(ids.size, dtype=object)
    for d in np.unique(counts).tolist():
        rows = np.flatnonzero(counts == d)
        want[rows] = dggs.Grid(grid).cell_to_polygon(ids[rows], densify=d)
    assert (shapely.to_wkb(drawn) == shapely.to_wkb(want)).all()
    assert sum(g.geom_type == "MultiPolygon" for g in drawn) > 0  # the antimeridian's cells were among them


def test_max_points_names_every_cells_points():
    ids = _cells(2 * _RAGGED_CHUNK + 77, 10, 36)
    total = int((3 * (edge_points(ids, 10.0) + 1) + 1).sum())
    assert len(dggs.cell_to_polygon(ids, tolerance=10.0, max_points=total)) == ids.size
    first = int((3 * (edge_points(ids[:_RAGGED_CHUNK], 10.0) + 1) + 1).sum())
    with pytest.raises(TooManyCellsError, match=f"make {total:,} points"):
        dggs.cell_to_polygon(ids, tolerance=10.0, max_points=first + 1)  # crossed in the second chunk
    with pytest.raises(TooManyCellsError, match=f"make {total:,} points"):
        dggs.cell_to_polygon(ids, tolerance=10.0, max_points=total - 1)
