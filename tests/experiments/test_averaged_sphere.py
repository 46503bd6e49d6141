"""§5.1.11 / Figure 5.22: the averaged-sphere surface subdivision."""

from __future__ import annotations

import numpy as np
import pytest

from dggs.experiments.averaged_sphere import (
    initial_polyhedron,
    one_rings,
    run_levels,
    sphere_through,
    subdivide,
    vertex_spheres,
)
from dggs.experiments.mesh import dodecahedron, icosahedron
from dggs.experiments.split_triangles import split_1_4


def test_sphere_through_four_points():
    rng = np.random.default_rng(0)
    c, r = rng.normal(size=3), 2.5
    d = rng.normal(size=(4, 3))
    p = c + r * d / np.linalg.norm(d, axis=1, keepdims=True)
    got = sphere_through(p)
    assert got is not None
    assert np.allclose(got[0], c) and got[1] == pytest.approx(r)
    assert sphere_through(np.array([[0.0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]])) is None


def test_one_rings_are_closed_cycles():
    v, f = initial_polyhedron()
    rings = one_rings(len(v), f)
    assert [len(r) for r in rings] == [4] * 6
    for i, ring in enumerate(rings):
        for a, b in zip(ring, ring[1:] + ring[:1], strict=True):
            assert any({i, a, b} == set(t) for t in f.tolist())


def test_inscribed_polyhedron_is_split_1_4_on_its_sphere():
    # §5.1.11: with the origin inside, every averaged sphere is the circumsphere and the new
    # points lie on it: exactly Split (1:4) with projected midpoints.
    ico = icosahedron(2.0)
    c, r, flat = vertex_spheres(ico.vertices, ico.faces[0])
    assert np.allclose(c, 0.0, atol=1e-12) and np.allclose(r, 2.0) and not flat.any()
    v, f = subdivide(ico.vertices, ico.faces[0])
    ref = split_1_4(ico)
    assert np.allclose(np.linalg.norm(v, axis=1), 2.0)
    assert {tuple(np.round(x, 9)) for x in v} == {tuple(np.round(x, 9)) for x in ref.vertices}


def test_converges_to_a_sphere_from_a_tetrahedron_inscribed_in_one():
    tet = np.array([[1.0, 1, 1], [1, -1, -1], [-1, 1, -1], [-1, -1, 1]]) / np.sqrt(3)
    f = np.array([[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]])
    _, stats = run_levels(4, tet, f)
    assert all(s.max_radius == pytest.approx(1.0) and s.max_origin_offset < 1e-12 for s in stats)
    bulges = [s.max_bulge for s in stats[1:]]
    assert bulges == sorted(bulges, reverse=True) and bulges[-1] < 0.1  # a sagitta: shrinks with the edges


def test_irregular_polyhedron_shows_the_thesis_failure():
    # Thesis §5.1.11: at level 2 the averaged spheres "become increasingly large, and their resultant
    # origins further from the mesh"; level 3 has "non-smooth, and erratic extrusions".
    _, stats = run_levels(3)
    assert [s.faces for s in stats] == [8, 32, 128, 512]
    radii = [s.max_radius for s in stats]
    offsets = [s.max_origin_offset for s in stats]
    assert radii == sorted(radii) and radii[3] > 20 * radii[0]
    assert offsets == sorted(offsets) and offsets[3] > 10 * offsets[1]
    assert stats[0].reflex_edges == stats[1].reflex_edges == 0
    assert 0 < stats[2].reflex_edges < stats[3].reflex_edges
    assert stats[3].reflex_edges > 0.1 * 768  # of the 768 edges at level 3
    # New points bulge away from their chords more at level 3 than at levels 1-2 (on a sphere: less).
    assert stats[3].max_bulge > 1.5 * max(stats[1].max_bulge, stats[2].max_bulge)


def test_dodecahedron_triangulated_stays_on_its_sphere():
    d = dodecahedron()
    tris = np.concatenate([np.stack([b[:, 0], b[:, i], b[:, i + 1]], 1) for b in d.faces for i in range(1, b.shape[1] - 1)])
    v, _ = subdivide(d.vertices, tris)
    # Coplanar pentagon fans: quadruples inside one pentagon are skipped, the others give the circumsphere.
    assert np.allclose(np.linalg.norm(v, axis=1), 1.0)
