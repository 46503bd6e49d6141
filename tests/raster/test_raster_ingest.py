"""``CellStore.ingest_raster``: the rows of ``raster_to_cells``, exactly, resumable by block (issue 19).

The referee is ``raster_to_cells`` itself (tested against independent oracles
in test_raster_to_cells.py): the store must hold its rows to the last bit, in
every mode, after one run or after runs stopped between blocks.  SIGKILL at
any moment: test_raster_crash.py.
"""

from __future__ import annotations

import numpy as np
import pytest

pytest.importorskip("rasterio")

import dggs  # noqa: E402
from dggs.raster import MODES, RasterError, raster_to_cells  # noqa: E402
from dggs.storage import CellStore  # noqa: E402

from .helpers import field, same_rows, write  # noqa: E402


@pytest.fixture(scope="module")
def rasters(tmp_path_factory):
    folder = tmp_path_factory.mktemp("rasters")
    data = field(40, 52, bands=2)
    data[:, :6, :9] = -1.0  # nodata: cells partly covered
    classes = (data[0] // 15).astype(np.int16)
    return {"values": write(folder / "v.tif", data, nodata=-1.0), "classes": write(folder / "k.tif", classes)}


@pytest.mark.parametrize("mode", MODES)
def test_the_stored_rows_are_raster_to_cells_rows_exactly(tmp_path, rasters, mode):
    path = rasters["classes" if mode in ("mode", "fractions") else "values"]
    band = None if mode in ("mode", "fractions") else [1, 2]
    want = raster_to_cells(path, 10, mode=mode, band=band, block_size=16)
    with CellStore(tmp_path / "s.db") as store:
        result = store.ingest_raster(path, 10, mode=mode, band=band, block_size=16)
        assert result.blocks == 12 and result.rows_read == 12 and result.rows_inserted == len(want) == store.count()
        assert same_rows(store.conn, want)
        rows = store.conn.execute("SELECT cell, lat, lng, row FROM points ORDER BY cell").fetchall()
        lat, lng = dggs.cell_to_latlng([r[0] for r in rows])
        assert [r[1:3] for r in rows] == list(zip(lat, lng, strict=True))  # at the cells' centres
        assert [r[3] for r in rows] == list(range(1, len(rows) + 1))
        assert store.conn.execute("SELECT count(*) FROM raster_partials").fetchone()[0] == 0
        assert store.conn.execute("SELECT count(*) FROM raster_classes").fetchone()[0] == 0
        assert store.sources()[0]["complete"] and store.sources()[0]["rows_done"] == 12
        again = store.ingest_raster(path, 10, mode=mode, band=band, block_size=16)
        assert again.already_complete and store.count() == len(want)
        store.check()


class Stop(Exception):
    pass


def test_stopped_between_blocks_resumes_to_the_same_rows(tmp_path, rasters):
    want = raster_to_cells(rasters["classes"], 10, mode="fractions", block_size=8)
    db = tmp_path / "s.db"
    for stop_after in (3, 11, 30):
        seen = []  # a resumed run first reports the blocks committed before

        def tick(blocks, stop_after=stop_after, seen=seen):
            seen.append(blocks)
            if sum(seen) >= stop_after:
                raise Stop

        with CellStore(db) as store, pytest.raises(Stop):
            store.ingest_raster(rasters["classes"], 10, mode="fractions", block_size=8, progress=tick)
        with CellStore(db) as store:
            assert store.count() == 0 and store.sources()[0]["rows_done"] == sum(seen)  # ticked after its commit
    with CellStore(db) as store:
        result = store.ingest_raster(rasters["classes"], 10, mode="fractions", block_size=8)
        assert result.rows_resumed == sum(seen) >= 30 and result.rows_resumed + result.rows_read == result.blocks == 35
        assert same_rows(store.conn, want)


def test_kept_rollups_stay_current(tmp_path, rasters):
    with CellStore(tmp_path / "r.db") as store:
        store.ingest_points([47.0], [12.0], 10, {"value": [5.0]})  # another source's row in the same cells' world
        store.keep_rollups([6, 4])
        store.ingest_raster(rasters["values"], 10, band=1, mode="max", block_size=16)
        store.check()  # compares every kept partial with the rows
        rolled = store.aggregate(4, "value", ("count", "max"))
        kept = store.conn.execute("SELECT sum(rows) FROM rollups WHERE level = 4").fetchone()[0]
        assert kept == store.count() == sum(r["count"] for r in rolled)


def test_an_xarray_dataarray_is_a_source_by_its_content(tmp_path, rasters):
    rioxarray = pytest.importorskip("rioxarray")
    array = rioxarray.open_rasterio(rasters["values"]).sel(band=1)
    with CellStore(tmp_path / "x.db") as store:
        first = store.ingest_raster(array, 9)
        assert first.rows_inserted > 0 and same_rows(store.conn, raster_to_cells(array, 9))
        assert store.ingest_raster(array.copy(), 9).already_complete  # the same pixels: the same source
        with pytest.raises(dggs.StorageError, match="other settings"):
            store.ingest_raster(array, 9, mode="max")


def test_levels_bad_input_and_changed_files(tmp_path, rasters):
    path = write(tmp_path / "c.tif", np.ones((4, 4), np.float32))
    with CellStore(tmp_path / "l.db") as store:
        store.ingest_raster(path, 8)
        with pytest.raises(dggs.LevelMismatchError, match="level 8"):
            store.ingest_raster(rasters["values"], 9)
        for bad, error in [(tmp_path / "missing.tif", RasterError), (np.ones((2, 2)), RasterError)]:
            with pytest.raises(error):
                store.ingest_raster(bad, 8)
        with pytest.raises(dggs.DggsValueError, match="mode 'median'"):
            store.ingest_raster(path, 8, mode="median")
        with pytest.raises(dggs.DggsValueError, match="takes one band"):
            store.ingest_raster(rasters["values"], 8, mode="mode")
        assert len(store.sources()) == 1  # bad input registers nothing
        before = store.count()
        write(path, np.full((4, 4), 2.0, np.float32))  # the same name, other pixels
        with pytest.raises(dggs.StorageError, match="changed since"):
            store.ingest_raster(path, 8)
        store.ingest_raster(path, 8, replace=True)
        assert store.count() == before and len(store.sources()) == 1
        assert {r[0] for r in store.conn.execute("SELECT value FROM points")} == {2.0}
        with pytest.raises(dggs.StorageError, match="other settings"):
            store.ingest_raster(path, 8, mode="sum")


def test_deleting_an_unfinished_raster_source_drops_its_partials(tmp_path, rasters):
    def stop(blocks):
        raise Stop

    with CellStore(tmp_path / "d.db") as store:
        with pytest.raises(Stop):
            store.ingest_raster(rasters["classes"], 10, mode="mode", block_size=16, progress=stop)
        assert store.conn.execute("SELECT count(*) FROM raster_classes").fetchone()[0] > 0
        store.delete_source(str(rasters["classes"]))
        assert store.conn.execute("SELECT count(*) FROM raster_partials").fetchone()[0] == 0
        assert store.conn.execute("SELECT count(*) FROM raster_classes").fetchone()[0] == 0
