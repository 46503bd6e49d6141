"""Smoke test: every chapter's figures are written (quick, small)."""

from __future__ import annotations

import pytest
from click.testing import CliRunner

from dggs.experiments.cli import experiments

pytest.importorskip("matplotlib")


def run(*args):
    return CliRunner().invoke(experiments, list(args))


@pytest.mark.parametrize(
    "chapter, expected",
    [
        ("4", {"fig4_1_azimuth.png", "fig4_3_iterations.png", "fig4_4_inverse_error.png",
               "fig4_5_inverse_picture.png"}),
        ("5", {"fig5_1_5_2_curve_definition.png", "fig5_3_circular_subdivision.png", "fig5_4_curve_steps.png",
               "fig5_5_5_7_surface_definition.png", "fig5_8_5_10_surface_steps.png", "fig5_12_bspline_arcs.png",
               "fig5_13_edge_construction.png", "fig5_14_radial_subdivision.png",
               "fig5_15_length_preserving.png", "fig5_16_concave.png", "fig5_17_convex_to_concave.png",
               "fig5_18_rounded_cusps.png", "fig5_19_5_20_cusp.png", "fig5_21_co_linearity.png",
               "fig5_22_averaged_sphere.png"}),
    ],
)
def test_chapter_figures_written(tmp_path, chapter, expected):
    r = run("figures", str(tmp_path), "--chapter", chapter, "--quick")
    assert r.exit_code == 0, r.output
    assert {p.name for p in tmp_path.glob("*.png")} == expected
    assert all(p.read_bytes()[:4] == b"\x89PNG" and p.stat().st_size > 5000 for p in tmp_path.glob("*.png"))


def test_chapter_6_with_figure_6_18(tmp_path):
    r = run("figures", str(tmp_path), "--chapter", "6", "--scheme", "1:9", "--levels", "1")
    assert r.exit_code == 0, r.output
    assert {p.name for p in tmp_path.glob("*.png")} == {
        "area_highlighting_1_9.png", "error_distribution_1_9.png", "fig6_18_split_1_9_issues.png"}


def test_figure_6_28_runs_to_level_7(tmp_path, monkeypatch):
    # Figure 6.28 has levels 1-7; the error distribution now runs to the thesis's depth.
    from dggs.experiments import figures

    seen = {}
    real = figures.plot_error_distribution

    def spy(ax, errors_by_level, bins=40):
        seen["levels"] = sorted(errors_by_level)
        return real(ax, errors_by_level, bins)

    monkeypatch.setattr(figures, "plot_error_distribution", spy)
    figures.write_figures(tmp_path, ["2:6"], None, False, "thesis")
    assert seen["levels"] == [1, 2, 3, 4, 5, 6, 7]
