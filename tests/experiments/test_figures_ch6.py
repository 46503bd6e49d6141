"""Figure 6.18: Split (1:9)'s edge points must be symmetric."""

from __future__ import annotations

from pathlib import Path

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


# ----------------------------------------------------------------------------
# Figures 6.14-6.28: the thesis's rules by default, each figure naming its rule
# ----------------------------------------------------------------------------
def test_figures_default_to_the_thesis_rules():
    import inspect

    from dggs.experiments import figures
    from dggs.experiments.cli import figures as figures_command

    assert inspect.signature(figures.write_figures).parameters["variant"].default == "thesis"
    assert inspect.signature(figures.write_all).parameters["variant"].default == "thesis"
    assert {p.name: p.default for p in figures_command.params}["variant"] == "thesis"


def test_default_rules_agree_with_the_thesis_text():
    from dggs.experiments.schemes import run_scheme

    # §6.3.3 beside Figure 6.19(a): "all faces are resultantly larger than their expected area".
    cc = run_scheme("catmull-clark", 1, variant="thesis")[1].face_errors_pct
    assert cc.min() > 50.0  # all larger (Table 6.1: 55.78 %), not white
    assert np.abs(run_scheme("catmull-clark", 1, variant="dggs")[1].face_errors_pct).max() < 1e-9
    # Table 6.6 beside Figure 6.27: Split (2:6) level 2 at 0.21 %.
    assert run_scheme("2:6", 2, variant="thesis")[2].max_face_error_pct == pytest.approx(0.21, abs=0.005)


@pytest.mark.parametrize("key", ["2:6", "catmull-clark", "1:5"])
def test_rule_labels_differ_where_the_rules_do(key):
    from dggs.experiments.figures_ch6 import rule_label

    assert rule_label(key, "thesis").startswith("thesis's rule")
    assert rule_label(key, "dggs").startswith("dggs's rule, not the thesis's")


@pytest.mark.parametrize("variant, suffix", [(None, "_thesis"), ("dggs", "_dggs")])
def test_each_figure_is_labelled_with_its_rule(tmp_path, monkeypatch, variant, suffix):
    pytest.importorskip("matplotlib")
    from matplotlib.figure import Figure

    from dggs.experiments import figures
    from dggs.experiments.figures_ch6 import rule_label

    texts: dict[str, str] = {}
    real = Figure.savefig

    def spy(self, path, *a, **k):
        parts = [self._suptitle.get_text() if self._suptitle else ""] + [ax.get_title() for ax in self.axes]
        texts[Path(path).name] = "\n".join(parts)
        return real(self, path, *a, **k)

    monkeypatch.setattr(Figure, "savefig", spy)
    kwargs = {} if variant is None else {"variant": variant}
    figures.write_figures(tmp_path, ["catmull-clark", "1:4"], 1, **kwargs)
    label = rule_label("catmull-clark", variant or "thesis")
    assert set(texts) == {f"area_highlighting_catmull-clark{suffix}.png", f"error_distribution_catmull-clark{suffix}.png",
                          "area_highlighting_1_4.png", "error_distribution_1_4.png"}
    for name, text in texts.items():
        assert (label if "catmull" in name else rule_label("1:4", "thesis")) in text
