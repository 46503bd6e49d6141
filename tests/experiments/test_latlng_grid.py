"""Chapter 7's equal-area latitude-longitude grid: the parallels, the exact cell areas, the polyhedral
approximation measured with the chapter-6 metrics."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from click.testing import CliRunner

from dggs.errors import DggsValueError
from dggs.experiments.cli import experiments
from dggs.experiments.latlng_grid import (
    cell_areas,
    equal_area_parallels,
    latlng_level,
    latlng_mesh,
    octahedron,
    spherical_cell_errors,
)
from dggs.experiments.mesh import half_edges, total_area
from dggs.experiments.schemes import get_scheme, run_scheme


def _quadrature_area(a: float, b: float, dlng: float, nodes: int = 40) -> float:
    """Area of the cell lat in [a, b], a longitude span dlng: Gauss-Legendre over cos(lat) dlat dlng."""
    x, w = np.polynomial.legendre.leggauss(nodes)
    lat = 0.5 * (b - a) * x + 0.5 * (b + a)
    return float(dlng * 0.5 * (b - a) * np.sum(w * np.cos(lat)))


@pytest.mark.parametrize(("n", "m"), [(2, 3), (3, 4), (7, 5), (10, 36), (64, 128)])
def test_every_cell_has_the_same_area_by_the_exact_formula(n, m):
    lat = equal_area_parallels(n)
    assert np.sin(lat) == pytest.approx(-1 + 2 * np.arange(n + 1) / n, abs=1e-15)
    expected = 4 * math.pi / (n * m)
    for a, b in zip(lat[:-1], lat[1:], strict=True):  # independent of the code's zone formula
        assert _quadrature_area(float(a), float(b), 2 * math.pi / m) == pytest.approx(expected, rel=1e-12)
    assert cell_areas(n, m) == pytest.approx(np.full(n * m, expected), rel=1e-12)
    assert np.abs(spherical_cell_errors(n, m)).max() < 1e-9


def test_the_grid_is_hierarchical():
    coarse, fine = equal_area_parallels(8), equal_area_parallels(16)
    assert fine[::2] == pytest.approx(coarse, abs=1e-15)


def test_mesh_level_0_is_the_octahedron_and_meshes_are_closed():
    assert total_area(octahedron()) == pytest.approx(4 * math.sqrt(3), rel=1e-15)
    for level in range(4):
        mesh = latlng_level(level)
        assert mesh.num_faces == 8 * 4**level == get_scheme("latlng").faces(level)
        half_edges(mesh.faces)  # raises unless closed and consistently oriented
        assert np.linalg.norm(mesh.vertices, axis=1) == pytest.approx(1.0, abs=1e-15)


def test_bad_sizes_are_named():
    with pytest.raises(DggsValueError, match="bands 1"):
        latlng_mesh(1, 8)
    with pytest.raises(DggsValueError, match="meridians 2"):
        latlng_mesh(4, 2)


def test_polyhedral_approximation_with_the_chapter_6_metrics():
    rows = run_scheme("latlng", 6)
    assert [r.faces for r in rows] == [8 * 4**k for k in range(7)]
    assert all(abs(r.area_deviation_pct) < 1e-10 for r in rows)  # rescaled as every scheme (§5.1.2)
    err = [r.max_face_error_pct for r in rows]
    assert err[0] == pytest.approx(0.0, abs=1e-9)  # the octahedron's faces are congruent
    for k in range(3, 7):  # the flat faces' worst error halves with each level
        assert 0.45 < err[k] / err[k - 1] < 0.56


def test_cli_json_and_tables_row():
    r = CliRunner().invoke(experiments, ["subdivision", "--scheme", "latlng", "--levels", "2", "--json"])
    assert r.exit_code == 0, r.output
    rows = json.loads(r.output)
    assert [row["faces"] for row in rows] == [8, 32, 128]
    assert set(rows[0]) == {"level", "faces", "area_deviation_pct", "avg_displacement_pct", "max_displacement_pct",
                            "avg_displacement_km", "max_face_error_pct", "max_face_error_km2"}
