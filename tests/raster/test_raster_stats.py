"""A block's pieces grouped by cell (dggs.raster.stats): the one-pass grouping of sorted cells against np.unique.

The lat/lng cut hands a block's pieces over cell by cell in id order, and the partials group them without the
sort ``np.unique`` does; the grouping must be np.unique's (cells and inverse) for sorted and unsorted input alike,
and a block's partials the same as those made with np.unique's groups.
"""

from __future__ import annotations

import numpy as np
from hypothesis import example, given, settings
from hypothesis import strategies as st

import dggs
from dggs.raster.stats import _groups, block_partials

from ..strategies import examples

IDS = st.lists(st.sampled_from([0, 1, 2**63, 2**64 - 1, 12345, 12346]) | st.integers(0, 2**64 - 1), max_size=40)


@settings(max_examples=examples(200), deadline=None)
@given(IDS, st.booleans())
@example([], True)
@example([7], True)
@example([5, 5, 5], True)
@example([9, 3, 9], False)  # unsorted: np.unique's own answer
@example([2**64 - 1, 0], False)  # the top bit: compared as unsigned, not as int64
def test_groups_are_np_unique(ids, sort):
    cell = np.array(sorted(ids) if sort else ids, dtype=np.uint64)
    cells, inv = _groups(cell)
    ref_cells, ref_inv = np.unique(cell, return_inverse=True)
    assert cells.dtype == np.uint64
    assert cells.tolist() == ref_cells.tolist()
    assert inv.tolist() == ref_inv.reshape(-1).tolist()


def test_partials_of_a_sorted_block_equal_those_grouped_by_np_unique():
    """Partials from the one-pass groups against the same sums made by hand from np.unique's groups."""
    rng = np.random.default_rng(3)
    cells_at = np.sort(dggs.latlng_to_cell(rng.uniform(-80, 80, 50), rng.uniform(-180, 180, 50), 9, as_int=True))
    cell = np.repeat(np.asarray(cells_at, np.uint64), rng.integers(1, 6, 50))
    pixel = rng.integers(0, 30, cell.size)
    area = rng.uniform(1.0, 2.0, cell.size)
    total = np.bincount(pixel, weights=area, minlength=30)
    values = rng.uniform(0, 100, (2, 30))
    got = block_partials(pixel, cell, area, total, values, "mean", False)
    ref_cells, inv = np.unique(cell, return_inverse=True)
    assert got.cells.tolist() == ref_cells.tolist()
    for b in range(2):
        want = [float(np.sum(area[inv == i] * values[b, pixel[inv == i]])) for i in range(ref_cells.size)]
        np.testing.assert_allclose(got.sums[b], want, rtol=1e-12)
    assert got.count.tolist() == np.bincount(inv).tolist()
