"""A new user's small traps (issue 38, item 6): the README's storage example, a failed first ingest, dggs info."""

from __future__ import annotations

import re
from pathlib import Path

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
