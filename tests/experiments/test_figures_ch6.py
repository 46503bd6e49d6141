"""Figure 6.18: Split (1:9)'s edge points must be symmetric."""

from __future__ import annotations

import numpy as np
import pytest

from dggs.experiments.figures_ch6 import split_1_9_fractions
from dggs.experiments.schemes import iter_levels


def test_thirds_match_the_scheme():
    r = split_1_9_fractions(1 / 3, 2 / 3, "face")
    assert r["cracked_edges"] == 0 and r["max_gap"] < 1e-12
    _, level1 = list(iter_levels("1:9", 1))[1]
    assert np.abs(r["area_error_pct"]).max() == pytest.approx(level1.max_face_error_pct, abs=1e-9)
    assert r["area_classes"] == 3  # corner, edge and centre children by symmetry


@pytest.mark.parametrize("s", [0.2, 0.3, 0.4])
def test_symmetric_points_never_crack(s):
    assert split_1_9_fractions(s, 1 - s, "face")["cracked_edges"] == 0


def test_asymmetric_points_crack_every_edge_per_face():
    r = split_1_9_fractions(0.25, 0.6, "face")
    assert r["cracked_edges"] == 30
    assert r["max_gap"] > 0.1


def test_asymmetric_points_per_edge_break_congruence():
    # Shared per edge: no cracks, but round the odd-valence vertices the faces differ.
    sym = split_1_9_fractions(0.25, 0.75, "edge")
    asym = split_1_9_fractions(0.25, 0.6, "edge")
    assert asym["cracked_edges"] == 0
    assert asym["area_classes"] > sym["area_classes"]
    assert np.abs(asym["area_error_pct"]).max() > np.abs(sym["area_error_pct"]).max()
