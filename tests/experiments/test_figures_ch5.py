"""Chapter 5 figures: the computations behind them (edge construction, surface steps, co-linearity)."""

from __future__ import annotations

import numpy as np
import pytest

from dggs.experiments.curves import polygon_length, radial_subdivide
from dggs.experiments.figures_ch5 import CURVES, co_linearity_breakdown, edge_construction
from dggs.experiments.figures_ch5_surfaces import surface_steps, thesis_triangle_area


@pytest.mark.parametrize("name", ["pentagon", "hexagon", "bspline"])
def test_edge_construction_is_the_subdivision_step(name):
    p = CURVES[name]
    fine = radial_subdivide(p, 1, length="none", colinear_tol=0.0)[1]
    for i in range(len(p)):
        d = edge_construction(p, i)
        assert np.allclose(d["m_N"], fine[2 * i + 1])
        # C_0 and C_1 pass through their three vertices.
        v = d["v"]
        assert np.allclose(np.linalg.norm(v[:3] - d["O_0"], axis=1), d["R_0"])
        assert np.allclose(np.linalg.norm(v[1:] - d["O_1"], axis=1), d["R_1"])


def test_thesis_triangle_area_uses_sin_not_tan():
    rng = np.random.default_rng(5)
    for _ in range(20):
        a, b, c = (x / np.linalg.norm(x) * 3.0 for x in rng.normal(size=(3, 3)))
        cross = 0.5 * np.linalg.norm(np.cross(b - a, c - a))
        assert thesis_triangle_area(a, b, c) == pytest.approx(cross, rel=1e-9)


def test_surface_steps_preserve_area():
    steps = surface_steps()
    (_, _, _, sa), (_, _, _, flat), (_, _, _, pushed), (_, scaled, r, back) = steps
    assert flat == pytest.approx(sa)  # the flat 1:4 split does not change the area
    assert pushed > sa  # pushing onto S adds area (§5.1.2)
    assert back == pytest.approx(sa, rel=1e-12)
    assert r == pytest.approx(np.sqrt(sa / pushed))  # R' = sqrt(SA R^2 / SA')


def test_co_linearity_breakdown_levels_6_to_8():
    # Thesis §5.1.10 / Figure 5.21: the length-preserved curve develops concavity at levels 6-8.
    d = co_linearity_breakdown(8)
    assert d["reflex"][:5] == [0] * 5
    assert d["reflex"][6] > 50 and d["reflex"][8] > d["reflex"][6]
    assert abs(d["length_ratio"][4] - 1) < 1e-4 and d["length_ratio"][8] > 10
    # A co-linearity guard does not prevent it; without the scaling the curve stays convex.
    assert co_linearity_breakdown(6, colinear_tol=1e-2)["reflex"][6] > 50
    plain = co_linearity_breakdown(8, length="none")
    assert plain["reflex"] == [0] * 9 and abs(plain["length_ratio"][8] - plain["length_ratio"][7]) < 1e-5


def test_concave_scaling_lengthens():
    # Thesis §5.1.6 / Figure 5.16: on a concave curve the scaling does not keep the length.
    out = radial_subdivide(CURVES["concave"], 2, length="thesis")
    assert polygon_length(out[2]) > 1.5 * polygon_length(out[0])
