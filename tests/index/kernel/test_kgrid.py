"""Compiled grid-graph kernels (``dggs.index._kernel.grid``) against independent oracles.

* the neighbours frozen from the string-id code before the 64-bit rewrite
  (tests/reference/fixtures/neighbours_v1.json);
* a geometric oracle: mirror the cell's planar centroid in each edge, carry it
  across the face edge, locate it (docs/grid.md, "Neighbours");
* plain Python breadth-first search (sets) for disks, rings and distances.

The str <-> int conversion is written here from the layout in docs/grid.md
("Integer ids"): bit 62 marker, face in bits 61..57, level-1 code (digit + 1)
in bits 56..54, the level-k code (digit + 1) at bit ``2 * (28 - k)`` for k >= 2.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from dggs.geometry import snyder, split26
from dggs.geometry.icosahedron import ISEA
from dggs.index._kernel import distance as KD
from dggs.index._kernel import grid as K
from dggs.index._kernel.grid_tables import chart_distance

from ...reference.numpy_split26 import locate
from .test_khier import FACES, MAX_LEVEL, i2s, s2i  # the id layout written out by hand, once

FIXTURE = Path(__file__).parents[2] / "reference" / "fixtures" / "neighbours_v1.json"


# --------------------------------------------------------------------------- conversion


def ids(cells) -> np.ndarray:
    return np.array([s2i(c) for c in cells], dtype=np.uint64)


def test_conversion_by_hand():
    # level 2 at bit 2 * (28 - 2) = 52, level 3 at bit 50 (index/_bits.py SHIFTS)
    assert s2i("C401") == (1 << 62) | (2 << 57) | ((4 + 1) << 54) | ((0 + 1) << 52) | ((1 + 1) << 50)
    assert s2i("A") == 1 << 62
    for c in ("T", "C401", "A5" + "2" * 27, "Q3012"):
        assert i2s(s2i(c)) == c


# --------------------------------------------------------------------------- helpers


def nbrs(cells: np.ndarray) -> np.ndarray:
    out = np.zeros((len(cells), 3), dtype=np.uint64)
    K.neighbours(np.asarray(cells, dtype=np.uint64), out)
    return out


def random_cells(rng: np.random.Generator, n: int, levels) -> list[str]:
    out = []
    for lv in rng.choice(np.asarray(levels), n):
        c = FACES[rng.integers(20)]
        if lv >= 1:
            c += str(rng.integers(6))
        c += "".join(str(d) for d in rng.integers(0, 3, int(lv) - 1)) if lv >= 2 else ""
        out.append(c)
    return out


def vertex_cells(levels=(1, 2, 3, 5, 10, 28)) -> list[str]:
    """Cells touching the 12 icosahedron vertices: every level-1 triangle has a face vertex as its corner A,
    and child 2 (ADE) keeps A; tails of 0s and 1s touch the face centre and edge midpoints."""
    return [f + str(d) + t * (lv - 1) for f in FACES for d in range(6) for lv in levels for t in "201"]


def cells_at_points(latlng, levels) -> list[str]:
    """Cells holding points, located with the geometry alone (snyder forward + the numpy locate)."""
    lat, lng = np.array(latlng, dtype=float).T
    face, x, y = snyder.forward(lat, lng)
    out = [FACES[f] for f in face]
    for lv in levels:
        if lv >= 1:
            dig = locate(x, y, lv)
            out += [FACES[f] + "".join(map(str, row)) for f, row in zip(face, dig, strict=True)]
    return out


SPECIAL_POINTS = [
    (90.0, 0.0), (-90.0, 0.0), (89.9999, 45.0), (-89.9999, -135.0), (0.0, 180.0), (0.0, -180.0),
    (30.0, 179.99999), (-30.0, -179.99999), (58.2825255885, 11.25), (-58.2825255885, -168.75),
]


def pinned_cells() -> list[str]:
    verts = ISEA.geometry.vertices * (1 - 1e-12)
    vlat = np.degrees(np.arctan2(verts[:, 2], np.hypot(verts[:, 0], verts[:, 1])))
    vlng = np.degrees(np.arctan2(verts[:, 1], verts[:, 0]))
    pts = SPECIAL_POINTS + list(zip(vlat, vlng, strict=True))
    return sorted(set(cells_at_points(pts, range(0, MAX_LEVEL + 1, 3)) + vertex_cells()))


def bfs_rings(cell: int, k: int) -> list[set[int]]:
    """Rings 0..k by plain breadth-first search on sets."""
    seen = {cell}
    rings = [{cell}]
    for _ in range(k):
        front = np.array(sorted(rings[-1]), dtype=np.uint64)
        new = {int(x) for x in nbrs(front).ravel()} - seen
        seen |= new
        rings.append(new)
    return rings


def bfs_distance(a: int, b: int, limit: int = 400) -> int:
    seen, front, d = {a}, {a}, 0
    while b not in front:
        assert d < limit
        new = {int(x) for x in nbrs(np.array(sorted(front), dtype=np.uint64)).ravel()} - seen
        seen |= new
        front, d = new, d + 1
    return d


@st.composite
def cell_ids(draw, min_level: int = 0, max_level: int = MAX_LEVEL) -> str:
    lv = draw(st.integers(min_level, max_level))
    c = FACES[draw(st.integers(0, 19))]
    if lv >= 1:
        c += str(draw(st.integers(0, 5)))
    return c + "".join(str(draw(st.integers(0, 2))) for _ in range(max(lv - 1, 0)))


# --------------------------------------------------------------------------- neighbours


def test_neighbours_equal_frozen_fixture():
    fx = json.loads(FIXTURE.read_text())
    got = nbrs(ids(fx["cells"]))  # one call, every level 0..28 mixed
    assert len(fx["cells"]) >= 2000
    assert [[i2s(v) for v in row] for row in got] == fx["neighbours"]


def test_neighbours_examples():
    assert [i2s(v) for v in nbrs(ids(["C401"]))[0]] == ["C411", "C402", "C400"]
    assert nbrs(np.zeros(0, dtype=np.uint64)).shape == (0, 3)


def check_symmetric(cells: list[str]) -> None:
    a = ids(cells)
    nb = nbrs(a)
    back = nbrs(nb.ravel()).reshape(len(a), 3, 3)
    for i, c in enumerate(cells):
        row = [i2s(v) for v in nb[i]]
        assert len(set(row)) == 3 and c not in row, c
        assert all(len(r) == len(c) for r in row), c
        for j in range(3):  # b in N(a) => a in N(b)
            assert a[i] in back[i, j], (c, row[j])
        # a in N(b) => b in N(a): the second neighbours of a that list a are exactly its neighbours
        for b in set(back[i].ravel()) - {a[i]}:
            assert (b in nb[i]) == (a[i] in nbrs([b])[0])


@given(st.lists(cell_ids(), min_size=1, max_size=20))
def test_neighbour_symmetry_random(cells):
    check_symmetric(cells)


def test_neighbour_symmetry_pinned():
    """Poles, antimeridian, icosahedron vertices (five faces meet), face centres and edge midpoints."""
    cells = pinned_cells()
    assert len(cells) > 600
    check_symmetric(cells)


def geometric_neighbours(cells: list[str]) -> list[list[str]]:
    """Oracle: mirror the planar centroid in each edge of the counter-clockwise corners, then locate it."""
    level = len(cells[0]) - 1
    face = np.array([FACES.index(c[0]) for c in cells])
    l1 = np.array([int(c[1]) for c in cells])
    digits = np.array([[int(ch) for ch in c[2:]] for c in cells], dtype=np.intp).reshape(len(cells), level - 1)
    a, b, c = split26.cell_vertices(l1, digits)
    ccw = (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0]) > 0
    corners = np.where(ccw[:, None, None], np.stack([a, b, c], 1), np.stack([a, c, b], 1))
    centre = corners.mean(axis=1)
    out = [[None] * 3 for _ in cells]
    for i in range(3):
        p, q = corners[:, i], corners[:, (i + 1) % 3]
        d = q - p
        t = np.einsum("ij,ij->i", centre - p, d) / np.einsum("ij,ij->i", d, d)
        img = 2 * (p + t[:, None] * d) - centre
        f2, moved = split26.neighbour_points(face, img, ISEA.geometry.face_vertices)
        dig = locate(moved[:, 0], moved[:, 1], level)
        for r in range(len(cells)):
            out[r][i] = FACES[f2[r]] + "".join(map(str, dig[r]))
    return out


@pytest.mark.parametrize("level", range(1, 16))
def test_neighbours_geometric_oracle(level):
    rng = np.random.default_rng(100 + level)
    cells = random_cells(rng, 300, [level]) + [c for c in vertex_cells((level,))]
    got = [[i2s(v) for v in row] for row in nbrs(ids(cells))]
    assert got == geometric_neighbours(cells)


def test_are_neighbours():
    rng = np.random.default_rng(7)
    cells = random_cells(rng, 200, range(MAX_LEVEL + 1)) + vertex_cells()
    a = ids(cells)
    nb = nbrs(a)
    second = nbrs(nb[:, 0])  # a and two cells 2 steps away (the graphs have no triangles)
    parent = ids([c[:-1] if len(c) > 1 else c for c in cells])
    pairs = [(x, y, True) for x, row in zip(a, nb, strict=True) for y in row]
    pairs += [(x, y, False) for x, row in zip(a, second, strict=True) for y in row]  # includes x itself
    pairs += [(x, y, False) for x, y in zip(a, parent, strict=True)]  # another level (or itself at level 0)
    aa, bb, expect = zip(*pairs, strict=True)
    out = np.zeros(len(aa), dtype=np.bool_)
    K.are_neighbours(np.array(aa, dtype=np.uint64), np.array(bb, dtype=np.uint64), out)
    assert out.tolist() == list(expect)


# --------------------------------------------------------------------------- disks and rings


def disk_rows(cells: np.ndarray, k: int, width: int | None = None):
    width = K.disk_size_bound(k) if width is None else width
    out = np.full((len(cells), width), 99, dtype=np.uint64)
    counts = np.zeros(len(cells), dtype=np.int64)
    K.disk(1 << 30, np.asarray(cells, dtype=np.uint64), k, out, counts)  # work enough for every thread
    return out, counts


def ring_rows(cells: np.ndarray, k: int):
    out = np.full((len(cells), K.ring_size_bound(k)), 99, dtype=np.uint64)
    counts = np.zeros(len(cells), dtype=np.int64)
    K.ring(1 << 30, np.asarray(cells, dtype=np.uint64), k, out, counts)
    return out, counts


def sample_origins() -> list[str]:
    rng = np.random.default_rng(3)
    return list(FACES) + random_cells(rng, 60, range(MAX_LEVEL + 1)) + pinned_cells()[::7]


@pytest.mark.parametrize("k", range(7))
def test_disks_and_rings_equal_bfs(k):
    cells = sample_origins()
    a = ids(cells)
    dout, dcount = disk_rows(a, k)
    rout, rcount = ring_rows(a, k)
    for i, c in enumerate(a):
        rings = bfs_rings(int(c), k)
        disk = sorted(set().union(*rings))
        assert dcount[i] == len(disk)
        assert dout[i, : len(disk)].tolist() == disk  # sorted ascending
        assert not dout[i, len(disk) :].any()  # padded with 0
        assert rcount[i] == len(rings[-1])
        assert rout[i, : rcount[i]].tolist() == sorted(rings[-1])
        assert not rout[i, rcount[i] :].any()
    if k:  # ring k = disk k minus disk k - 1
        prev, pcount = disk_rows(a, k - 1)
        for i in range(len(a)):
            diff = set(dout[i, : dcount[i]].tolist()) - set(prev[i, : pcount[i]].tolist())
            assert sorted(diff) == rout[i, : rcount[i]].tolist()


def test_size_bounds_exhaustive_coarse_levels():
    """Every cell of levels 0-3, every radius: BFS sizes within the bounds (level 0 reaches them at k = 2)."""
    reached_disk, reached_ring = {}, {}
    for level in range(4):
        cells = list(FACES) if level == 0 else [f + str(d) for f in FACES for d in range(6)]
        for _ in range(level - 1):
            cells = [c + x for c in cells for x in "012"]
        a = ids(cells)
        order = np.argsort(a)
        adj = order[np.searchsorted(a[order], nbrs(a))]  # (n, 3) row indices
        assert (a[adj] == nbrs(a)).all()
        seen = np.eye(len(a), dtype=bool)  # all origins at once: seen[origin, cell]
        front = seen.copy()
        k = 0
        while front.any():
            ring = front.sum(axis=1)
            disk = seen.sum(axis=1)
            reached_ring[k] = max(reached_ring.get(k, 0), int(ring.max()))
            reached_disk[k] = max(reached_disk.get(k, 0), int(disk.max()))
            reach = np.zeros_like(seen)
            for j in range(3):  # cell c is reached if one of its neighbours is in the front (the graph is symmetric)
                reach |= front[:, adj[:, j]]
            front = reach & ~seen
            seen |= front
            k += 1
        assert seen.all()
    for k, size in reached_disk.items():
        assert reached_ring[k] <= K.ring_size_bound(k)
        assert size <= K.disk_size_bound(k)
    assert reached_disk[2] == K.disk_size_bound(2) == 10  # level 0: the dodecahedron graph
    assert reached_ring[2] == K.ring_size_bound(2) == 6


def test_size_bounds_reached_in_the_plane():
    """Away from the icosahedron vertices the rings follow the 4.6.12 net: 1, 3, 5, 7, 9, 12, 15, 17, ..."""
    planar = [1, 3, 5, 7, 9, 12, 15, 17, 19, 21, 24, 27, 29, 31, 33, 36, 39]
    for cell in ("C4" + "1" * 15, "H1" + "01" * 10):  # deep inside a face
        rings = bfs_rings(s2i(cell), 16)
        assert [len(r) for r in rings] == planar
    for k in range(17):
        assert K.ring_size_bound(k) == (6 if k == 2 else planar[k])
        assert K.disk_size_bound(k) == (10 if k == 2 else sum(planar[: k + 1]))
    assert K.disk_size_bound(5) > (5 + 1) ** 2  # (k + 1)**2 undercounts from k = 5 on


def test_disk_rejects_narrow_output():
    with pytest.raises(ValueError):
        disk_rows(ids(["C401"]), 3, width=K.disk_size_bound(3) - 1)


# --------------------------------------------------------------------------- distances


def pairs_within(k: int, cells: list[str], per_cell: int, seed: int):
    rng = np.random.default_rng(seed)
    for c in cells:
        rings = bfs_rings(s2i(c), k)
        radii = [d for d in range(k + 1) if rings[d]]  # the sphere at level 0 is 5 steps across
        for _ in range(per_cell):
            d = radii[int(rng.integers(len(radii)))]
            ring = sorted(rings[d])
            yield s2i(c), ring[int(rng.integers(len(ring)))], d


def test_distance_equals_bfs_within_8():
    cells = sample_origins()[::2]
    a, b, d = map(np.array, zip(*pairs_within(8, cells, 4, seed=1), strict=True))
    a, b = a.astype(np.uint64), b.astype(np.uint64)
    got = [KD.distance(x, y, 100) for x, y in zip(a, b, strict=True)]
    assert got == d.tolist()
    assert [KD.distance(y, x, 100) for x, y in zip(a, b, strict=True)] == d.tolist()  # symmetric
    out = np.zeros(len(a), dtype=np.int64)
    KD.distances(1 << 30, a, b, 100, out)
    assert out.tolist() == d.tolist()


@pytest.mark.parametrize("level", [6, 12, 20, 28])
def test_distance_equals_bfs_far(level):
    """Longer distances: the planar count where a chart proves it, the search near vertices."""
    rng = np.random.default_rng(level)
    cells = random_cells(rng, 6, [level]) + vertex_cells((level,))[::23]
    charted = 0
    for a, b, d in pairs_within(30, cells, 3, seed=level):
        assert KD.distance(np.uint64(a), np.uint64(b), 1000) == d
        assert KD.distance(np.uint64(b), np.uint64(a), 1000) == d
        c = chart_distance(np.uint64(a), np.uint64(b), level)
        assert c in (-1, d)  # the planar count, when the chart proves it, is the distance
        charted += c >= 0
    if level >= 12:
        assert charted >= 12  # the random cells (18 pairs) lie far from the vertices


@given(cell_ids(), st.integers(0, 40), st.data())
def test_distance_random_walk(cell, steps, data):
    """distance(a, b) <= the length of any walk from a to b, and equals the BFS distance."""
    a = s2i(cell)
    b = a
    for _ in range(steps):
        b = int(nbrs([b])[0, data.draw(st.integers(0, 2))])
    d = KD.distance(np.uint64(a), np.uint64(b), 1000)
    assert 0 <= d <= steps
    assert d == bfs_distance(a, b)
    assert KD.distance(np.uint64(b), np.uint64(a), 1000) == d


def test_distance_same_cell_and_max_steps():
    for c in ["A", "C401", "T5" + "2" * 27]:
        assert KD.distance(np.uint64(s2i(c)), np.uint64(s2i(c)), 0) == 0
    a, b = s2i("C4" + "1" * 15), s2i("C4" + "1" * 14 + "0")
    d = bfs_distance(a, b)
    assert d == 1 and KD.distance(np.uint64(a), np.uint64(b), 0) == -1
    far = [int(v) for v in bfs_rings(a, 12)[12]]
    assert KD.distance(np.uint64(a), np.uint64(far[0]), 11) == -1
    assert KD.distance(np.uint64(a), np.uint64(far[0]), 12) == 12
    v = s2i("A0" + "2" * 9)  # at an icosahedron vertex: the search path
    far = sorted(bfs_rings(v, 10)[10])
    assert KD.distance(np.uint64(v), np.uint64(far[0]), 9) == -1
    assert KD.distance(np.uint64(v), np.uint64(far[0]), 10) == 10
