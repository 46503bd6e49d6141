"""``dggs experiments`` through click's CliRunner."""

from __future__ import annotations

import json

import pytest
from click.testing import CliRunner

from dggs.experiments.cli import experiments

KEYS = {
    "level",
    "faces",
    "area_deviation_pct",
    "avg_displacement_pct",
    "max_displacement_pct",
    "avg_displacement_km",
    "max_face_error_pct",
    "max_face_error_km2",
}


def run(*args):
    return CliRunner().invoke(experiments, list(args))


def test_subdivision_json():
    r = run("subdivision", "--scheme", "1:4", "--levels", "2", "--json")
    assert r.exit_code == 0, r.output
    rows = json.loads(r.output)
    assert [row["level"] for row in rows] == [0, 1, 2]
    assert all(set(row) == KEYS for row in rows)
    assert [row["faces"] for row in rows] == [20, 80, 320]
    assert rows[1]["max_face_error_pct"] == pytest.approx(13.42, abs=0.005)  # Table 6.6


def test_subdivision_table_shows_thesis_values():
    r = run("subdivision", "--scheme", "1:3", "--levels", "2")
    assert r.exit_code == 0
    assert "33.73= (33.73)" in r.output


@pytest.mark.parametrize(
    ("args", "needle"),
    [
        (["--scheme", "1:7"], "1:7"),
        (["--scheme", "1:4", "--levels", "-1"], "-1"),
        (["--scheme", "1:9", "--levels", "12"], "12"),
    ],
)
def test_bad_input_exits_1_naming_the_value(args, needle):
    r = run("subdivision", *args)
    assert r.exit_code == 1
    assert needle in r.output


def test_tables_quick():
    r = run("tables", "--quick", "--dggs-levels", "0")
    assert r.exit_code == 0, r.output
    for t in ("Table 5.1", "Table 6.1", "Table 6.2", "Table 6.6", "Table 6.7"):
        assert t in r.output


def test_figures(tmp_path):
    pytest.importorskip("matplotlib")
    r = run("figures", str(tmp_path), "--scheme", "1:4", "--levels", "1")
    assert r.exit_code == 0, r.output
    pngs = sorted(p.name for p in tmp_path.glob("*.png"))
    assert pngs == ["area_highlighting_1_4.png", "error_distribution_1_4.png"]
    assert all((tmp_path / p).read_bytes()[:4] == b"\x89PNG" for p in pngs)
