"""Chapter 4 (inverse Snyder speed-ups): our tables against the thesis's printed values.

Thesis values are typed in here from the thesis text (Tables 4.1-4.3, §4.3),
not taken from the module under test.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from click.testing import CliRunner

from dggs.experiments import chapter4 as c4
from dggs.experiments import inverse as thesis_inverse
from dggs.experiments import numpy_snyder

# thesis Table 4.1: degree -> (sum of squares of residuals, variance of residuals)
THESIS_4_1 = {1: (1.19, 2.02e-4), 2: (9.27e-1, 1.66e-4), 3: (2.30e-4, 3.92e-8), 4: (2.06e-4, 3.51e-8),
              5: (2.51e-5, 4.28e-9), 6: (2.20e-5, 3.75e-9), 7: (9.06e-7, 1.55e-10)}
# thesis Table 4.2: average Newton iterations of O and I per quality
THESIS_O = {25: 3.61, 50: 3.70, 75: 3.74, 100: 3.75}
THESIS_I = {25: 2.76, 50: 2.82, 75: 2.81, 100: 2.83}
# thesis Table 4.3 (cubic): max distance error, the same at every quality
THESIS_MAX_DIST = 6.193e-4
THESIS_AVG_DIST = {25: 9.379e-5, 50: 9.439e-5, 75: 9.459e-5, 100: 9.490e-5}


@pytest.fixture(scope="module")
def quick() -> dict:
    return c4.run_chapter4(quick=True)


@pytest.fixture(scope="module")
def fits() -> dict[int, dict]:
    return {r["degree"]: r for r in c4.fit_table()}


# --------------------------------------------------------------------------- Table 4.1
def test_thesis_variances_imply_about_5870_samples():
    # gnuplot: var = SS / (N - p); every row but degree 2 (one of its pair misprinted) agrees on N.
    ns = [ss / var + d + 1 for d, (ss, var) in THESIS_4_1.items() if d != 2]
    assert all(5840 < n < 5900 for n in ns)
    assert 5840 < c4.implied_sample_size() < 5900


@pytest.mark.parametrize("degree", [1, 3, 5, 7])
def test_odd_degree_ss_matches_thesis(fits, degree):
    # Full 120-degree sector, radians, area-spaced Az': odd degrees come within 10 % (1-3 %: not
    # reproduced, see test_chapter4_marks.py).
    ss, var = THESIS_4_1[degree]
    assert fits[degree]["ss"] == pytest.approx(ss, rel=0.10)
    assert fits[degree]["var"] == pytest.approx(var, rel=0.10)


@pytest.mark.parametrize("degree", [2, 4, 6])
def test_even_degree_ss_near_thesis(fits, degree):
    # Our symmetric sample gives even == odd below; the thesis's even degrees are 10-22 % lower.
    assert fits[degree]["ss"] == pytest.approx(THESIS_4_1[degree][0], rel=0.30)


def test_fit_pattern_is_the_thesis_pattern(fits):
    for table in ({d: v[0] for d, v in THESIS_4_1.items()}, {d: r["ss"] for d, r in fits.items()}):
        for even in (2, 4, 6):
            assert 0.75 * table[even - 1] <= table[even] <= table[even - 1] * (1 + 1e-9)
        # each odd degree at least 5x better than the previous odd degree (thesis 3 -> 5: 9.2x)
        for odd in (3, 5, 7):
            assert table[odd] * 5 < table[odd - 2]


def test_half_sector_fit_does_not_give_the_thesis_pattern(fits):
    # Over 0-60 degrees the quadratic gains 30x over the line: not what the thesis printed.
    assert fits[2]["ss_half"] < fits[1]["ss_half"] / 10
    assert fits[2]["ss"] > 0.75 * fits[1]["ss"]


def test_fit_units_are_radians(fits):
    # In degrees every SS would be (180/pi)^2 = 3283x larger than the thesis's.
    assert fits[3]["ss"] * (180 / math.pi) ** 2 > 100 * THESIS_4_1[3][0]


def test_area_sampling_density():
    ap = np.degrees(c4.sector_samples(200_000, "area"))
    assert ap.min() >= 0 and ap.max() <= 120
    assert np.mean(ap < 60) == pytest.approx(0.5, abs=1e-4)
    # face points are 4x denser in Az' at a vertex (0 deg) than at the edge midpoint (60 deg)
    near_vertex = np.count_nonzero(ap < 0.5)
    near_mid = np.count_nonzero(np.abs(ap - 60) < 0.25)
    assert near_vertex / near_mid == pytest.approx(4.0, rel=0.02)


# --------------------------------------------------------------------------- meshes
@pytest.mark.parametrize("q", [1, 7, 25])
def test_face_mesh_counts_and_area(q):
    pts, tri = c4.face_mesh(q)
    assert len(pts) == (q + 1) * (q + 2) // 2
    assert len(tri) == q * q
    xyz = numpy_snyder.inverse_xyz(np.zeros(len(pts), dtype=np.intp), pts[:, 0], pts[:, 1])
    # the triangles tile one icosahedron face: a twentieth of the sphere
    assert c4.spherical_triangle_areas(xyz, tri).sum() == pytest.approx(math.pi / 5, rel=1e-12)


def test_inverse_with_az_agrees_with_library():
    rng = np.random.default_rng(4)
    face, x, y = numpy_snyder.forward_xyz(_random_sphere(rng, 5000))
    exact = c4.inverse_with_az(face, x, y, c4.exact_az)
    ref = numpy_snyder.inverse_xyz(face, x, y)
    assert np.abs(exact - ref).max() < 1e-14
    poly = c4.inverse_with_az(face, x, y, lambda a: thesis_inverse.az_poly(a, 3))
    ref, _ = thesis_inverse.inverse_xyz(face, x, y, method="poly", degree=3)
    assert np.abs(poly - ref).max() < 1e-14


def _random_sphere(rng, n):
    v = rng.normal(size=(n, 3))
    return v / np.linalg.norm(v, axis=1, keepdims=True)


# --------------------------------------------------------------------------- Table 4.2
def test_newton_iterations_like_the_thesis(quick):
    for r in quick["table_4_2_iterations"]:
        assert 3.0 <= r["O"] <= 4.5
        assert r["O"] == pytest.approx(THESIS_O[r["quality"]], abs=0.3)
        assert r["I3_library"] < r["O"] and r["I3_thesis"] < r["O"]
        # thesis: I takes about 24 % fewer iterations than O
        assert 0.15 < 1 - r["I3_library"] / r["O"] < 0.35
        assert r["I3_library"] == pytest.approx(THESIS_I[r["quality"]], abs=0.3)
    o = [r["O"] for r in quick["table_4_2_iterations"]]
    assert o == sorted(o)  # rises with quality, as in the thesis


def test_timing_rows(quick):
    rows = quick["table_4_2_timing"]
    assert {r["method"] for r in rows} == {"O", "I", "E", "C"}
    for r in rows:
        assert r["points_per_s"] > 0 and math.isfinite(r["time_s"])
        if r["method"] == "O":
            assert r["time_ratio"] == 1.0
        assert r["time_ratio"] > 0 and math.isfinite(r["time_ratio"])
    # Which method is faster is a measurement (Table 4.2 in `dggs experiments snyder`, and make bench), not a
    # test: a timed assertion fails under load.


# --------------------------------------------------------------------------- Table 4.3
def _errors(quick, fit, degree):
    return {r["quality"]: r for r in quick["table_4_3"] if r["fit"] == fit and r["degree"] == degree}


@pytest.mark.parametrize("fit", ["thesis", "library"])
def test_elimination_errors_finite_and_ordered(quick, fit):
    d1, d3, d7 = (_errors(quick, fit, d) for d in (1, 3, 7))
    for q in c4.QUALITIES:
        for key in ("dist_avg", "dist_max", "area_abs_avg_pct", "area_max_pct"):
            assert all(math.isfinite(d[q][key]) for d in (d1, d3, d7))
            assert 0 < d3[q][key] < d1[q][key]
            # thesis §4.3: degree 7 is 10x better (area max of the full-sector fit: ~8x at q=25)
            assert d7[q][key] < d3[q][key] / (10 if key.startswith("dist") else 5)
        assert d3[q]["dist_avg"] <= d3[q]["dist_max"]


def test_thesis_distance_errors_are_radius_fractions(quick):
    # Read as fractions of the radius (not %), the thesis's Table 4.3 comes near our
    # full-sector cubic: the max (on the quality-25 grid) within 20 %, the average within 30 %
    # (not reproduced: 7 % and 10-21 % off, see test_chapter4_marks.py).
    d3 = _errors(quick, "thesis", 3)
    for q, avg in THESIS_AVG_DIST.items():
        assert d3[q]["dist_max"] == pytest.approx(THESIS_MAX_DIST, rel=0.20)
        assert d3[q]["dist_avg"] == pytest.approx(avg, rel=0.30)
    # As per cent (5.9 m on the Earth) they are out of a cubic's reach.
    assert min(r["dist_avg"] for r in quick["table_4_3"] if r["degree"] == 3) > 10 * 9.379e-7


def test_run_carries_the_marks(quick):
    assert len(quick["table_4_1_marks"]) == 14 and len(quick["table_4_3_marks"]) == 16
    assert min(quick["procedures"], key=lambda n: quick["procedures"][n]["score"]) == "area-120"
    text = c4._format(quick)
    assert "0 reproduced, 0 close, 14 differs of 14 cells" in text
    assert "0 reproduced, 0 close, 16 differs of 16 cells" in text


def test_degree7_iteration_claim_not_reproduced(quick):
    # thesis §4.3: 45 % fewer iterations with degree 7; Newton's quadratic convergence says no.
    first = quick["degree7"]["iterations"][0]
    assert first["tol"] == pytest.approx(1e-13)
    assert first["fewer_pct_library"] < 45 and first["fewer_pct_thesis"] < 45


# --------------------------------------------------------------------------- output
def test_json_and_text(quick):
    json.dumps(quick)
    text = c4._format(quick)
    for title in ("Table 4.1", "Table 4.2", "Table 4.3", "degree 7"):
        assert title in text


def test_cli_json():
    res = CliRunner().invoke(c4.snyder_command, ["--json", "--quick"])
    assert res.exit_code == 0, res.output
    data = json.loads(res.output)
    assert [r["degree"] for r in data["table_4_1"]] == list(range(1, 8))
    assert c4.snyder_command.name == "snyder"
