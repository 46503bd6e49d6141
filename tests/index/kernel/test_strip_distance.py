"""Distances at any range (issue 17 item 10): the face-strip count against breadth-first search.

The oracle is a breadth-first search over the whole level's edge graph (every
cell's three neighbours from the compiled walk, itself checked against the
geometric mirror oracle in test_kgrid.py): it knows nothing of charts, strips
or mirror lines.  Every pair at levels 1-3, many sources at levels 4-6 and
every cell touching an icosahedron vertex at level 6 are compared; at levels
where a whole-level search is too big, the metric's own laws and the rings of
:func:`dggs.grid_ring` (grown by a different kernel) stand in.
"""

from __future__ import annotations

import itertools

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import dggs
from dggs.index._kernel import distance as KD
from dggs.index._kernel import grid as K
from dggs.index._kernel.strips import strip_distance

from .test_kgrid import vertex_cells
from .test_khier import FACES, s2i


def level_cells(level: int) -> np.ndarray:
    """Every cell of a level (>= 1), sorted, by writing out the digit strings."""
    tails = ("".join(t) for t in itertools.product("012", repeat=level - 1))
    names = [f + str(d) + t for t in list(tails) for f in FACES for d in range(6)]
    return np.sort(np.array([s2i(c) for c in names], dtype=np.uint64))


def adjacency(cells: np.ndarray) -> np.ndarray:
    out = np.zeros((cells.shape[0], 3), dtype=np.uint64)
    K.neighbours(cells, out)
    return np.searchsorted(cells, out).astype(np.int64)


def _bfs(adj: np.ndarray, src: int) -> np.ndarray:
    """Edge steps from cell ``src`` to every cell: breadth-first, one ring of the adjacency at a time."""
    dist = np.full(adj.shape[0], -1, np.int64)
    dist[src], frontier, steps = 0, np.array([src]), 0
    while frontier.size:
        steps += 1
        ring = np.unique(adj[frontier].ravel())
        ring = ring[dist[ring] < 0]
        dist[ring] = steps
        frontier = ring
    return dist


def _from(cells: np.ndarray, i: int, level: int) -> tuple[np.ndarray, np.ndarray]:
    strip = np.array([strip_distance(cells[i], c, level) if i != j else 0 for j, c in enumerate(cells)], np.int64)
    full = np.empty(cells.shape[0], np.int64)
    KD.distances(cells.shape[0], np.full(cells.shape[0], cells[i], np.uint64), cells, 1 << 40, full)
    return strip, full


def compare(level: int, sources) -> int:
    cells = level_cells(level)
    adj = adjacency(cells)
    assert (cells[adj] == cells[adj]).all() and adj.max() < cells.shape[0]
    longest = 0
    for i in sources:
        truth = _bfs(adj, int(i))
        assert (truth >= 0).all()  # the graph is connected
        strip, full = _from(cells, int(i), level)
        wrong = np.flatnonzero(strip != truth)
        assert not wrong.size, (dggs.int_to_str(int(cells[i])), dggs.int_to_str(int(cells[wrong[0]])), truth[wrong[0]])
        assert (full == truth).all()
        longest = max(longest, int(truth.max()))
    return longest


@pytest.mark.parametrize("level", [1, 2])
def test_every_pair_at_coarse_levels(level):
    n = level_cells(level).shape[0]
    assert compare(level, range(n)) == {1: 15, 2: 27}[level]  # the graph's diameter, by the search


@pytest.mark.slow
def test_every_pair_at_level_3():
    assert compare(3, range(1080)) == 47


@pytest.mark.slow
@pytest.mark.parametrize("level, sources", [(4, 400), (5, 100), (6, 30)])
def test_random_sources(level, sources):
    n = level_cells(level).shape[0]
    compare(level, np.random.default_rng(level).choice(n, sources, replace=False))


@pytest.mark.slow
def test_every_cell_touching_an_icosahedron_vertex_at_level_6():
    cells = level_cells(6)
    corners = np.array([s2i(c) for c in vertex_cells((6,))], dtype=np.uint64)
    compare(6, np.unique(np.searchsorted(cells, corners))[::3])


def test_the_strips_and_the_search_agree_across_the_vertices_at_level_2():
    """Each of the 12 vertices' five faces: every level-2 pair in them, both id forms."""
    cells = level_cells(2)
    adj = adjacency(cells)
    names = [dggs.int_to_str(int(c)) for c in cells]
    i = np.arange(0, cells.shape[0], 7)
    truth = np.array([_bfs(adj, int(s))[i] for s in i])
    got = dggs.grid_distance(np.array(names)[i][:, None], np.array(names)[i][None, :])
    assert (np.asarray(got) == truth).all()
    assert (dggs.grid_distance(cells[i][:, None], cells[i][None, :]) == truth).all()


# -- fine levels: the metric's laws and the independently grown rings --------

_FINE = st.integers(9, 28)


@st.composite
def far_pairs(draw):
    level = draw(_FINE)
    lat = draw(st.floats(-90, 90, allow_nan=False)), draw(st.floats(-90, 90, allow_nan=False))
    lng = draw(st.floats(-180, 180, allow_nan=False)), draw(st.floats(-180, 180, allow_nan=False))
    return dggs.latlng_to_cell(np.array(lat), np.array(lng), level)


@settings(deadline=None)
@given(far_pairs(), st.integers(0, 2), st.sampled_from(["str", "int"]))
def test_far_pairs_obey_the_metric_laws(pair, column, form):
    """Symmetric, zero only on the diagonal, 1-Lipschitz along an edge, and within the sphere's size."""
    a, b = (dggs.str_to_int(c) for c in pair) if form == "int" else pair
    d = dggs.grid_distance(a, b)
    assert d == dggs.grid_distance(b, a)
    assert (d == 0) == (a == b)
    step = dggs.edge_neighbors(b)[column]
    assert abs(dggs.grid_distance(a, step) - d) <= 1
    level = dggs.get_level(a)
    assert d <= 2 * 5 * 3 ** (level / 2 + 1)  # far less than the cells on a path round the globe


@settings(deadline=None, max_examples=10)
@given(st.sampled_from(vertex_cells((20,))), st.sampled_from([40, 150]))
def test_rings_round_a_vertex_at_level_20_lie_at_their_radius(cell, k):
    ring = dggs.grid_ring(cell, k)
    assert ring and (np.asarray(dggs.grid_distance(cell, ring)) == k).all()


def test_half_the_globe_apart_at_level_28_is_a_number_not_a_refusal():
    """Once 14 s to give up at the default limit, and unbounded with a larger one."""
    a, b = dggs.latlng_to_cell(np.array([0.1, 0.1]), np.array([0.1, 100.0]), 28)
    d = dggs.grid_distance(a, b)
    a, b = [a], [b]
    # the straight line between them: at least its length over the longest step between centroids
    # a step moves at most about a cell's long edge (2 s for short leg s, area sqrt3/2 s**2), and Snyder's
    # projection stretches lengths by well under a factor of 2: so at least a quarter of metres / s
    short = np.sqrt(2 * dggs.cell_area(a[0]) / np.sqrt(3))
    assert d > 0.25 * dggs.cell_centers_distance(a[0], b[0]) / short
    with pytest.raises(dggs.DggsValueError, match=f"more than {d - 1} steps"):
        dggs.grid_distance(a, b, max_steps=d - 1)
    assert dggs.grid_distance(a, b, max_steps=d) == [d]


def test_level_0_reads_the_face_graph():
    """The 20 base cells: distances of the dodecahedron graph (the search over the whole level agrees)."""
    base = np.sort(np.array([s2i(f) for f in FACES], dtype=np.uint64))
    out = np.zeros((20, 3), dtype=np.uint64)
    K.neighbours(base, out)
    adj = np.searchsorted(base, out).astype(np.int64)
    for i in range(20):
        truth = _bfs(adj, i)
        assert [KD.distance(base[i], base[j], 99) for j in range(20)] == truth.tolist()
    assert max(KD.distance(base[0], base[j], 99) for j in range(20)) == 5  # the graph's diameter


def test_pairs_no_strip_serves_go_to_the_search(monkeypatch):
    """The fallback (never needed in the checks) gives the same distances, or the named refusal."""
    import dggs.index.grid as grid

    cells = level_cells(3)
    adj = adjacency(cells)
    truth = _bfs(adj, 0)
    picks = np.arange(0, cells.shape[0], 37)

    def only_search(n, a, b, max_steps, out):
        out[:] = KD.NEEDS_SEARCH

    monkeypatch.setattr(grid.kd, "distances", only_search)
    got = dggs.grid_distance(np.full(picks.size, cells[0]), cells[picks])
    assert np.asarray(got).tolist() == truth[picks].tolist()
    with pytest.raises(dggs.DggsValueError, match="more than 3 steps"):
        dggs.grid_distance(cells[0], cells[picks[-1]], max_steps=3)
