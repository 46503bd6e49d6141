"""``dggs bin-raster``: into a store, into GeoParquet partitions; errors are one line and exit 1 (issue 19)."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("rasterio")
from click.testing import CliRunner  # noqa: E402

import dggs  # noqa: E402
from dggs.cli import main  # noqa: E402
from dggs.raster import MODES, raster_to_cells  # noqa: E402
from dggs.raster_cli import CLI_MODES  # noqa: E402
from dggs.storage import CellStore  # noqa: E402

from .helpers import field, same_rows, write  # noqa: E402

DOC = Path(__file__).resolve().parents[2] / "docs" / "raster.md"


@pytest.fixture
def raster(tmp_path):
    return write(tmp_path / "dem.tif", field(30, 40, bands=2), nodata=-9999.0)


def run(*args):
    return CliRunner().invoke(main, [str(a) for a in args])


def test_into_a_store_and_again(tmp_path, raster):
    db = tmp_path / "dem.db"
    res = run("bin-raster", raster, "--level", 10, "--mode", "max", "--band", 2, "--db", db, "--block-size", 16)
    assert res.exit_code == 0, res.output
    assert re.search(r"read 6 of 6 blocks, stored [\d,]+ cells -> .*dem.db \(level 10\)", res.output)
    with CellStore(db) as store:
        assert same_rows(store.conn, raster_to_cells(raster, 10, mode="max", band=2, block_size=16))
    again = run("bin-raster", raster, "--level", 10, "--mode", "max", "--band", 2, "--db", db, "--block-size", 16)
    assert again.exit_code == 0 and "already ingested" in again.output


def test_into_geoparquet_partitions(tmp_path, raster):
    gpd = pytest.importorskip("geopandas")
    import pyarrow.dataset as ds

    out = tmp_path / "cells"
    res = run("bin-raster", raster, "--level", 9, "--mode", "mean", "--parquet", out)
    assert res.exit_code == 0, res.output
    want = raster_to_cells(raster, 9)
    parts = sorted(p.name for p in out.iterdir())
    assert parts and all(p.startswith("parent=") for p in parts)
    table = ds.dataset(out, format="parquet", partitioning="hive").to_table().to_pandas().sort_values("cell_id")
    assert np.array_equal(table["cell_id"], want["cell_id"]) and np.array_equal(table["band_1"], want["band_1"])
    assert (table["parent"] == [c[:2] for c in table["cell"]]).all()  # each cell under its level-1 parent
    one = gpd.read_parquet(next(out.glob("parent=*/part-0.parquet")))  # GeoParquet: geometry and CRS read back
    assert one.crs.to_string() == "OGC:CRS84" and (one.geometry.area > 0).all()
    res = run("bin-raster", raster, "--level", 9, "--mode", "count", "--parquet", out)  # a folder of ours: replaced
    assert res.exit_code == 0, res.output
    counts = ds.dataset(out, format="parquet", partitioning="hive").to_table().to_pandas().sort_values("cell_id")
    assert np.array_equal(counts["band_1"], raster_to_cells(raster, 9, mode="count")["band_1"])
    (out / "notes.txt").write_text("mine")
    res = run("bin-raster", raster, "--level", 9, "--parquet", out)
    assert res.exit_code == 1 and "other than parent=* partitions" in res.output and (out / "notes.txt").exists()


@pytest.mark.parametrize("args, message", [
    (["missing.tif", "--level", 5, "--db", "x.db"], "no raster file"),
    (["{raster}", "--level", 40, "--db", "x.db"], "level 40"),
    (["{raster}", "--level", 5, "--band", 3, "--db", "x.db"], "band 3 is out of range"),
    (["{raster}", "--level", 5, "--mode", "mode", "--db", "x.db"], "takes one band"),
])
def test_errors_are_one_line_and_exit_1(tmp_path, raster, monkeypatch, args, message):
    monkeypatch.chdir(tmp_path)
    res = run("bin-raster", *[str(a).format(raster=raster) for a in args])
    assert res.exit_code == 1 and message in res.output
    assert res.output.startswith("Error: ") and res.output.count("\n") == 1 and "Traceback" not in res.output
    assert not (tmp_path / "x.db").exists() or CellStore(tmp_path / "x.db").sources() == []


def test_usage_needs_one_output(raster):
    assert run("bin-raster", raster, "--level", 5).exit_code == 2
    assert run("bin-raster", raster, "--level", 5, "--db", "a.db", "--parquet", "b").exit_code == 2


def test_the_command_is_documented_and_its_modes_are_the_librarys():
    assert CLI_MODES == MODES
    text = DOC.read_text()
    assert "dggs bin-raster" in text and "--parquet" in text and "--db" in text
    from dggs.raster.frames import GRID_NAME

    xdggs = pytest.importorskip("dggs.xdggs")
    assert GRID_NAME == xdggs.GRID_NAME
    assert dggs.raster.cells_to_raster is not None
