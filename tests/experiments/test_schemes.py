"""Chapter 6 schemes against the thesis's tables (values typed in from the seed text here)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from dggs.errors import DggsValueError, LevelError
from dggs.experiments.mesh import edge_table, face_areas, icosahedron, total_area
from dggs.experiments.schemes import SCHEMES, get_scheme, iter_levels, run_scheme
from dggs.experiments.split_2_6 import split_2_6
from dggs.experiments.split_triangles import split_1_6

# Table 6.6, typed independently from the thesis (seed lines ~1999-2007).
T66_1_4 = [13.42, 18.64, 20.14, 20.53]
T66_1_3 = [0.00, 33.73, 172.39, 552.13]
T66_1_6 = [0.00, 2.81, 5.39]
# Tables 6.3 / 6.4 / 6.5 for Split (1:4).
T63_1_4 = [5.84, 1.51, 0.38, 0.10]
T64_1_4 = [6.58, 1.78, 0.45, 0.11]
T65_1_4 = [372.31, 96.27, 24.27, 6.08]


def _levels(key: str, n: int):
    return run_scheme(key, n)[1:]


@pytest.mark.parametrize(
    ("key", "expected"), [("1:4", T66_1_4), ("1:3", T66_1_3), ("1:6", T66_1_6)]
)
def test_max_face_error_matches_table_6_6(key, expected):
    got = [m.max_face_error_pct for m in _levels(key, len(expected))]
    assert got == pytest.approx(expected, abs=0.006)


def test_split_1_4_displacement_tables_6_3_to_6_5():
    rows = _levels("1:4", 4)
    assert [r.avg_displacement_pct for r in rows] == pytest.approx(T63_1_4, abs=0.006)
    assert [r.max_displacement_pct for r in rows] == pytest.approx(T64_1_4, abs=0.006)
    assert [r.avg_displacement_km for r in rows] == pytest.approx(T65_1_4, abs=0.006)


def test_icosahedron_face_centres_are_20_5_percent_inside():
    (m,) = run_scheme("1:4", 0)
    assert m.avg_displacement_pct == pytest.approx(20.5, abs=0.05)  # §6.3.3


def test_split_1_3_level_1_has_no_face_error():
    assert run_scheme("1:3", 1)[1].max_face_error_pct < 1e-9


@pytest.mark.parametrize("key", list(SCHEMES))
def test_global_area_preserved_after_rescale(key):
    base = get_scheme(key).base()
    a0 = total_area(base)
    for mesh, m in iter_levels(key, 2):
        assert abs(math.fsum(face_areas(mesh).tolist()) / a0 - 1.0) < 1e-12
        assert abs(m.area_deviation_pct) < 1e-10


FORMULAS = {
    "1:4": lambda n: 20 * 4**n,
    "1:9": lambda n: 20 * 9**n,
    "1:3": lambda n: 20 * 3**n,
    "1:6": lambda n: 20 * 6**n,
    "2:6": lambda n: 20 if n == 0 else 120 * 3 ** (n - 1),
    "catmull-clark": lambda n: 20 if n == 0 else 60 * 4 ** (n - 1),
    "1:5": lambda n: 10 * 3**n + 2,  # 12, 32, 92, 272 (Table 6.2)
}


@pytest.mark.parametrize("key", list(SCHEMES))
def test_face_counts_by_formula(key):
    for mesh, m in iter_levels(key, 3 if key != "1:9" else 2):
        assert mesh.num_faces == m.faces == FORMULAS[key](m.level)


@pytest.mark.parametrize("key", list(SCHEMES))
def test_meshes_are_closed_spheres(key):
    # Euler characteristic 2 and every vertex on one sphere: shared points
    # really are shared (no duplicated edge points).
    for mesh, _ in iter_levels(key, 2):
        edges, _ = edge_table(mesh.faces)
        assert mesh.num_vertices - len(edges) + mesh.num_faces == 2
        r = np.linalg.norm(mesh.vertices, axis=1)
        assert np.ptp(r) < 1e-12 * r.mean()


@pytest.mark.parametrize("placement", ["area", "chord", "arc"])
def test_split_2_6_children_equal_in_the_plane_sense(placement):
    ico = icosahedron()
    m = split_2_6(split_1_6(ico), placement)
    a = face_areas(m).reshape(3, -1)
    # Each parent's three children are within a few percent of each other.
    assert np.all(np.abs(a / a.mean(axis=0) - 1) < 0.05)


def test_split_2_6_area_placement_equalises_level_2():
    assert run_scheme("2:6", 2)[2].max_face_error_pct < 1e-6


def test_unknown_scheme_names_the_value():
    with pytest.raises(DggsValueError, match="1:7"):
        get_scheme("1:7")


@pytest.mark.parametrize("levels", [-1, 40])
def test_bad_levels(levels):
    with pytest.raises(LevelError, match=str(levels)):
        run_scheme("1:4", levels)


@pytest.mark.slow
def test_full_thesis_depth_tables():
    t66_1_4 = [13.42, 18.64, 20.14, 20.53, 20.62, 20.65]
    t66_1_3 = [0.00, 33.73, 172.39, 552.13, 1469.73, 3619.13, 8525.78]
    t67_1_4 = [8.56e05, 2.97e05, 8.02e04, 2.04e04, 5.14e03, 1.29e03]
    rows = _levels("1:4", 6)
    assert [r.max_face_error_pct for r in rows] == pytest.approx(t66_1_4, abs=0.006)
    assert [r.max_face_error_km2 for r in rows] == pytest.approx(t67_1_4, rel=0.01)
    assert [r.max_face_error_pct for r in _levels("1:3", 7)] == pytest.approx(t66_1_3, abs=0.011)
    assert [r.max_face_error_pct for r in _levels("1:6", 4)] == pytest.approx(
        [0.00, 2.81, 5.39, 8.84], abs=0.006
    )
    # Table 6.5 for 2:6 (geometry independent of the placement details to ~0.01 km).
    km = [r.avg_displacement_km for r in _levels("2:6", 7)]
    assert km == pytest.approx([304.98, 110.65, 37.96, 12.78, 4.28, 1.43, 0.48], abs=0.02)
