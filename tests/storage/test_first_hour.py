"""A new user's small traps (issue 38, item 6): the README's storage example, a failed first ingest, dggs info."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

from dggs.errors import DggsValueError, StorageError
from dggs.storage import CellStore

ROOT = Path(__file__).resolve().parents[2]


def test_readme_storage_example_runs_where_there_is_no_clone(tmp_path, monkeypatch):
    """After a pip install there is no examples/data: the README's block must need none."""
    readme = (ROOT / "README.md").read_text()
    block = readme.split("### Storing data on cells", 1)[1].split("```python", 1)[1].split("```", 1)[0]
    monkeypatch.chdir(tmp_path)  # an empty directory
    exec(compile(block, "README.md storage block", "exec"), {"__name__": "__readme__"})  # noqa: S102 - our README
    with CellStore(tmp_path / "points.db", create=False) as store:
        assert store.count() > 0


@pytest.mark.parametrize("trap", ["missing file", "missing column"])
def test_a_failed_first_ingest_leaves_no_store_file(tmp_path, trap):
    csv = tmp_path / "p.csv"
    if trap == "missing column":
        csv.write_text("lat,lng\n1,2\n")
    db = tmp_path / "points.db"
    with pytest.raises((StorageError, DggsValueError)), CellStore(db) as store:
        store.ingest_csv(csv, values=["pop"], level=5)
    assert sorted(p.name for p in tmp_path.iterdir()) == (["p.csv"] if csv.exists() else [])


def test_a_store_with_data_or_made_before_stays_after_an_error(tmp_path):
    kept = tmp_path / "kept.db"
    with pytest.raises(KeyError), CellStore(kept) as store:  # made here, but it holds a row: kept
        store.ingest_points([1.0], [2.0], 5)
        raise KeyError("the user's own error")
    with CellStore(kept) as store:
        assert store.count() == 1
    empty = tmp_path / "empty.db"
    CellStore(empty).close()  # an empty store made on purpose, earlier
    with pytest.raises(StorageError), CellStore(empty) as store:
        store.ingest_csv(tmp_path / "missing.csv", level=5)
    assert empty.exists()
    with CellStore(tmp_path / "quiet.db"):  # no error: an empty store is what was asked for
        pass
    assert (tmp_path / "quiet.db").exists()


def test_readme_cli_line_names_where_the_sample_is():
    line = next(x for x in (ROOT / "README.md").read_text().splitlines() if x.startswith("dggs bin examples/data/"))
    assert re.search(r"clone", line)


def test_a_ring_across_the_antimeridian_is_cut_into_its_two_sides():
    from dggs.storage.plot import _split_at_antimeridian

    ring = np.array([[170.0, -10.0], [-170.0, -10.0], [-170.0, 10.0], [170.0, 10.0], [170.0, -10.0]])
    pieces = _split_at_antimeridian(ring)
    assert len(pieces) == 2
    for piece in pieces:  # no edge runs across the map
        assert np.all(np.abs(np.diff(piece[:, 0])) <= 180) and np.all(np.abs(piece[:, 0]) <= 180)
    # the two sides: 10 x 20 degrees each, by the shoelace formula
    areas = sorted(abs(float(np.dot(p[:-1, 0], p[1:, 1]) - np.dot(p[1:, 0], p[:-1, 1]))) / 2 for p in pieces)
    assert areas == pytest.approx([200.0, 200.0])
    plain = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 0.0]])
    assert [p.tolist() for p in _split_at_antimeridian(plain)] == [plain.tolist()]


def _land_installed() -> bool:
    import dggs

    have = (Path(dggs.__file__).parent / "server/static/vendor/world-atlas/countries-50m.json").is_file()
    try:
        import pyogrio  # noqa: F401
    except ImportError:
        return False
    return have


@pytest.mark.skipif(not _land_installed(), reason="the map's world-atlas files (make static) or pyogrio missing")
def test_dggs_plot_draws_land_and_says_so(tmp_path):
    pytest.importorskip("matplotlib")
    from click.testing import CliRunner

    from dggs.cli import main
    from dggs.storage.plot import land_rings

    rings = land_rings()
    assert rings and all(np.all(np.abs(np.diff(r[:, 0])) <= 180) for r in rings if np.ptp(r[:, 0]) < 359)
    db = tmp_path / "s.db"
    with CellStore(db) as store:
        store.ingest_points([48.85, -33.9], [2.35, 151.2], 6)
    out = CliRunner().invoke(main, ["plot", str(db), "--level", "3", "--png", str(tmp_path / "m.png")])
    assert out.exit_code == 0 and "land from Natural Earth" in out.output
    out = CliRunner().invoke(main, ["plot", str(db), "--level", "3", "--png", str(tmp_path / "n.png"), "--no-land"])
    assert out.exit_code == 0 and "no land drawn" in out.output


def test_land_asked_for_but_absent_is_an_error_naming_what_is_missing(tmp_path, monkeypatch):
    pytest.importorskip("matplotlib")
    from dggs.errors import DggsError
    from dggs.storage import plot

    monkeypatch.setattr(plot, "land_rings", lambda: None)
    with pytest.raises(DggsError, match="land=True.*pyogrio.*make static"):
        plot.plot_cells(["A0"], [1.0], tmp_path / "m.png", land=True)
    assert plot.plot_cells(["A0"], [1.0], tmp_path / "m.png") is False  # the default: drawn without land


def test_a_text_column_holding_the_city_nan_stays_text(tmp_path):
    """1M points round real cities failed at line 2: 'Nan' (a city in Thailand) parsed as a float, so the city
    column was taken for numbers with some text, and every other name was a bad row."""
    path = tmp_path / "p.csv"
    path.write_text("lat,lng,city,spend\n3.4,101.1,Kampung Sungai Kajang,1.5\n18.78,100.78,Nan,2\n"
                    "45.0,7.0,Inf,3\n1,1,,nan\n")
    with CellStore(tmp_path / "s.db") as store:
        store.ingest_csv(path, values=["city", "spend"], level=5, on_error="skip")
        assert store.columns == {"city": "TEXT", "spend": "REAL"}
        cities = sorted(str(r[0]) for r in store.conn.execute("SELECT city FROM points WHERE city IS NOT NULL"))
    assert cities == ["Inf", "Kampung Sungai Kajang", "Nan"]
