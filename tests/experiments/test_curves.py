"""Chapter 5 curve subdivisions: invariants and property tests."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from dggs.experiments.chapter5 import colinear_guard_demo, cusp_demo, table_5_1
from dggs.experiments.curves import (
    circle_subdivide,
    ngon_subdivide,
    polygon_length,
    radial_subdivide,
    reflex_vertices,
)


@st.composite
def inscribed_polygons(draw):
    """Polygons on a circle with every central angle below 180 degrees."""
    n = draw(st.integers(3, 12))
    gaps = np.array(draw(st.lists(st.floats(0.2, 1.0), min_size=n, max_size=n)))
    gaps = gaps / gaps.sum() * 2 * np.pi
    if gaps.max() >= np.pi * 0.95:
        gaps = np.full(n, 2 * np.pi / n)
    t = np.cumsum(gaps)
    r = draw(st.floats(0.5, 50.0))
    return r * np.stack([np.cos(t), np.sin(t)], axis=1)


@st.composite
def convex_polygons(draw):
    """Well-spread points on an ellipse (convex, counter-clockwise)."""
    n = draw(st.integers(4, 9))
    jitter = np.array(draw(st.lists(st.floats(-0.25, 0.25), min_size=n, max_size=n)))
    t = 2 * np.pi * (np.arange(n) + jitter) / n
    a, b = draw(st.floats(1.0, 3.0)), draw(st.floats(1.0, 3.0))
    return np.stack([a * np.cos(t), b * np.sin(t)], axis=1)


@settings(max_examples=60, deadline=None)
@given(inscribed_polygons(), st.integers(1, 6))
def test_circle_subdivision_preserves_length(poly, levels):
    out = circle_subdivide(poly, levels)
    assert len(out[-1]) == len(poly) * 2**levels
    assert polygon_length(out[-1]) == pytest.approx(polygon_length(poly), rel=1e-12)
    r = np.linalg.norm(out[-1], axis=1)
    assert np.ptp(r) < 1e-9 * r.mean()  # still on one (smaller) circle


@st.composite
def near_circles(draw):
    """Convex polygons on an ellipse of aspect ratio at most 1.25."""
    n = draw(st.integers(4, 9))
    jitter = np.array(draw(st.lists(st.floats(-0.25, 0.25), min_size=n, max_size=n)))
    t = 2 * np.pi * (np.arange(n) + jitter) / n
    a = draw(st.floats(1.0, 3.0))
    b = a * draw(st.floats(0.8, 1.25))
    return np.stack([a * np.cos(t), b * np.sin(t)], axis=1)


@settings(max_examples=60, deadline=None)
@given(near_circles(), st.integers(1, 3))
def test_radial_subdivision_exact_mode_preserves_length(poly, levels):
    # §5.1.6: the curves of chapter 5 converge to circles; near a circle the
    # scale factor that restores the length always exists
    out = radial_subdivide(poly, levels, length="exact")
    assert polygon_length(out[-1]) == pytest.approx(polygon_length(poly), rel=1e-10)


@settings(max_examples=60, deadline=None)
@given(convex_polygons(), st.integers(1, 3))
def test_radial_subdivision_exact_mode_never_fails_silently(poly, levels):
    # Far from a circle (a 1:2 rhombus) no factor may work: then it must say so
    try:
        out = radial_subdivide(poly, levels, length="exact")
    except ValueError as exc:
        assert "converge" in str(exc)
        return
    assert polygon_length(out[-1]) == pytest.approx(polygon_length(poly), rel=1e-10)


def test_exact_mode_fails_loudly_once_concave():
    rhombus = np.array([[1.0, 0.0], [0.0, 2.0], [-1.0, 0.0], [0.0, -2.0]])
    with pytest.raises(ValueError, match="converge"):
        radial_subdivide(rhombus, 2, length="exact")


@settings(max_examples=40, deadline=None)
@given(convex_polygons())
def test_basic_radial_subdivision_interpolates(poly):
    out = radial_subdivide(poly, 2, length="none")
    assert np.array_equal(out[2][0::4], poly)  # old vertices never move (§5.1.7)


def test_regular_ngon_local_preservation():
    for level in ngon_subdivide(7, 5):
        e = np.linalg.norm(np.roll(level, -1, axis=0) - level, axis=1)
        assert np.ptp(e) < 1e-12
        assert e.sum() == pytest.approx(14 * np.sin(np.pi / 7), rel=1e-12)


def test_table_5_1_triangle_exact_and_others_small():
    rows = {r["shape"]: r for r in table_5_1("thesis")}
    assert rows["triangle"]["max_error_pct"] < 1e-10
    # The thesis's one-shot scaling leaves errors of the order of Table 5.1's (<= 3.05 %).
    assert 1e-6 < rows["convex pentagon"]["max_error_pct"] < 3.05
    assert 1e-6 < rows["circumscribed quadrilateral"]["max_error_pct"] < 3.05


def test_cusps_grow_only_with_origin_outside():
    d = cusp_demo(4)
    assert d["acute"] == [0, 0, 0, 0, 0]
    assert d["obtuse"][-1] > d["obtuse"][1] > 0


def test_colinear_guard_keeps_length():
    d = colinear_guard_demo()
    assert d["guarded"] == pytest.approx([8.0] * 4, rel=1e-9)
    assert d["unguarded"][-1] > 1e3


def test_bad_polygon():
    with pytest.raises(ValueError, match="shape"):
        radial_subdivide(np.zeros((2, 2)), 1)
    assert reflex_vertices(np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]])) == 0
