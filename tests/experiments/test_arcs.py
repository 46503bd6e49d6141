"""§5.1.3 / Figure 5.12: circle arcs along a cubic B-spline subdivision, against independent facts."""

from __future__ import annotations

import numpy as np
import pytest

from dggs.experiments.arcs import (
    arc_points,
    bspline_subdivide,
    limit_point,
    limit_radius_of_curvature,
    radius_convergence,
    three_point_arcs,
)

BEAN = np.array([[0.0, 0.0], [3.0, -0.6], [6.0, 0.0], [7.0, 2.0], [5.0, 3.2], [3.5, 2.0], [2.0, 3.0], [-0.5, 2.0]])


def circumcircle(p1, p2, p3):
    """Circumcentre by solving |c - p1|^2 = |c - p2|^2 = |c - p3|^2; radius by R = abc / (4 K)."""
    m = 2.0 * np.array([p2 - p1, p3 - p1])
    rhs = np.array([p2 @ p2 - p1 @ p1, p3 @ p3 - p1 @ p1])
    c = np.linalg.solve(m, rhs)
    a, b, e = np.linalg.norm(p2 - p3), np.linalg.norm(p1 - p3), np.linalg.norm(p1 - p2)
    k = 0.5 * abs((p2 - p1)[0] * (p3 - p1)[1] - (p2 - p1)[1] * (p3 - p1)[0])
    return c, a * b * e / (4.0 * k)


def test_arcs_match_the_circumcircle_formula():
    rng = np.random.default_rng(3)
    pts = rng.normal(size=(9, 2)) * 5
    arcs = three_point_arcs(pts)
    for i in range(len(pts)):
        c, r = circumcircle(pts[i - 1], pts[i], pts[(i + 1) % len(pts)])
        assert np.allclose(arcs.centre[i], c, rtol=1e-9, atol=1e-9)
        assert arcs.radius[i] == pytest.approx(r, rel=1e-9)


def test_arc_runs_from_previous_through_vertex_to_next():
    rng = np.random.default_rng(4)
    pts = rng.normal(size=(7, 2))
    arcs = three_point_arcs(pts)
    samples = arc_points(arcs, 2001)
    for i in range(len(pts)):
        assert np.allclose(samples[i, 0], pts[i - 1], atol=1e-9)
        assert np.allclose(samples[i, -1], pts[(i + 1) % len(pts)], atol=1e-9)
        assert np.linalg.norm(samples[i] - pts[i], axis=1).min() < 1e-2 * arcs.radius[i]  # passes v_i
        assert abs(arcs.sweep[i]) < 2 * np.pi


def test_colinear_triples_have_no_circle():
    arcs = three_point_arcs(np.array([[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [1.0, 1.0]]))
    assert np.isinf(arcs.radius[1]) and np.isnan(arcs.centre[1]).all()


def test_bspline_rule_and_counts():
    levels = bspline_subdivide(BEAN, 3)
    assert [len(p) for p in levels] == [8, 16, 32, 64]
    p, q = levels[0], levels[1]
    assert np.allclose(q[0::2], (np.roll(p, 1, 0) + 6 * p + np.roll(p, -1, 0)) / 8)
    assert np.allclose(q[1::2], (p + np.roll(p, -1, 0)) / 2)


def test_bspline_converges_to_the_limit_points():
    # Vertex i's descendants converge to (v_{i-1} + 4 v_i + v_{i+1}) / 6 (uniform cubic B-spline).
    fine = bspline_subdivide(BEAN, 12)[-1][:: 2**12]
    assert np.allclose(fine, limit_point(BEAN), atol=1e-6)


def test_arc_radii_converge_to_the_limit_radius_of_curvature():
    # Thesis §5.1.3: the arcs "reduce in size until they overlay the smooth curve"; the gap shrinks ~4x a level.
    gaps = radius_convergence(BEAN, 8)
    assert gaps[0] > 0.5
    assert gaps[-1] < 1e-4
    ratios = np.array(gaps[3:-1]) / np.array(gaps[4:])
    assert np.all((ratios > 3.5) & (ratios < 4.5))


def test_limit_radius_of_a_regular_polygon_b_spline():
    # Regular n-gon of circumradius 1: the B-spline limit at a vertex has P' = sin(2pi/n) and
    # P'' = 2(cos(2pi/n) - 1) in magnitude, so rho = sin^3 / (2 sin (1 - cos)).
    n = 6
    t = 2 * np.pi / n
    ngon = np.stack([np.cos(np.arange(n) * t), np.sin(np.arange(n) * t)], 1)
    expected = np.sin(t) ** 2 / (2 * (1 - np.cos(t)))
    assert np.allclose(limit_radius_of_curvature(ngon), expected)
    # ... and the arcs at the original vertices converge to it.
    arcs = three_point_arcs(bspline_subdivide(ngon, 9)[-1])
    assert np.allclose(arcs.radius[:: 2**9], expected, rtol=1e-5)
