"""The dggs grid row: Snyder-mapped Split (2:6) cells should be equal area on the sphere."""

from __future__ import annotations

import math

import numpy as np
import pytest

from dggs.experiments.dggs_grid import dggs_grid_metrics, spherical_polygon_areas

THESIS_BEST_2_6 = 16.63  # Table 6.6, Split (2:6), level 7


def test_spherical_polygon_areas_octant_and_hemisphere_cap():
    octant = np.array([[[1.0, 0, 0], [0, 1.0, 0], [0, 0, 1.0]]])
    assert spherical_polygon_areas(octant)[0] == pytest.approx(math.pi / 2, rel=1e-12)
    t = np.linspace(0, 2 * np.pi, 400, endpoint=False)
    z = 0.5
    ring = np.stack([np.sqrt(1 - z * z) * np.cos(t), np.sqrt(1 - z * z) * np.sin(t), np.full_like(t, z)], 1)
    assert spherical_polygon_areas(ring[None])[0] == pytest.approx(2 * math.pi * (1 - z), rel=1e-4)


def test_grid_cells_are_equal_area():
    rows = dggs_grid_metrics(3, densify=8)
    assert [r.faces for r in rows] == [20, 120, 360, 1080]
    for r in rows:
        assert abs(r.area_deviation_pct) < 1e-9  # cells tile the sphere
        assert r.max_face_error_pct < 0.1  # boundary sampling only
    assert rows[-1].max_face_error_pct < THESIS_BEST_2_6 / 100


def test_grid_error_shrinks_with_denser_boundaries():
    coarse = dggs_grid_metrics(2, densify=2)[-1].max_face_error_pct
    fine = dggs_grid_metrics(2, densify=16)[-1].max_face_error_pct
    assert fine < coarse / 4
