"""The dggs command line (click's CliRunner)."""

from __future__ import annotations

import json

from click.testing import CliRunner

import dggs
from dggs.cli import main


def run(*args):
    return CliRunner().invoke(main, list(args))


def test_help_lists_commands():
    res = run("--help")
    assert res.exit_code == 0
    for name in ("cell", "experiments"):
        assert name in res.output


def test_cell_from_latlng_with_negative_longitude():
    res = run("cell", "from-latlng", "51.05", "-114.07", "--level", "9")
    assert res.exit_code == 0
    assert res.output.strip() == dggs.latlng_to_cell(51.05, -114.07, 9)


def test_cell_info_json():
    res = run("cell", "info", "C401", "--json")
    assert res.exit_code == 0
    data = json.loads(res.output)
    assert data["level"] == 3 and data["parent"] == "C40" and len(data["neighbors"]) == 3


def test_cell_boundary_geojson():
    res = run("cell", "boundary", "C401", "--geojson")
    assert res.exit_code == 0
    feature = json.loads(res.output)
    assert feature["geometry"]["type"] == "Polygon"


def test_errors_are_clean_messages_with_exit_1():
    res = run("cell", "info", "C9")
    assert res.exit_code == 1
    assert "'C9'" in res.output and "Traceback" not in res.output
    res = run("cell", "from-latlng", "91", "0", "--level", "3")
    assert res.exit_code == 1 and "latitude 91.0" in res.output


def test_levels_table():
    res = run("cell", "levels", "--max-level", "28")
    assert res.exit_code == 0
    assert "0.5574 m^2" in res.output.splitlines()[-1]  # 510,065,621,724,088 m^2 / 915,071,698,198,440 cells


def test_a_bad_level_prints_only_the_error():
    res = run("cell", "levels", "--max-level", "29")
    assert res.exit_code == 1
    assert res.output.strip().splitlines() == ["Error: level 29 is out of range 0..28"]
