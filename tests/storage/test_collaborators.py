"""Each collaborator CellStore owns works alone, over an open store file without the CellStore face (issue 37).

The collaborators (storage/querier.py, ingester.py, raster_ingester.py, exporter.py, rollup_keeper.py) are made over a
:class:`~dggs.storage.connection.Connection`; what they write is read back with plain SQL on a separate
sqlite3 connection, and the cells they should have written come from the verbs (``dggs.latlng_to_cell``,
``dggs.cell_to_parent``) or a brute-force Python count, never from the storage code.
"""

from __future__ import annotations

import inspect
import json
import sqlite3
from collections import Counter

import numpy as np
import pytest

import dggs
from dggs.errors import StorageError
from dggs.storage import CellStore
from dggs.storage.connection import Connection
from dggs.storage.exporter import Exporter
from dggs.storage.ingester import Ingester
from dggs.storage.querier import Querier
from dggs.storage.raster_ingester import RasterIngester
from dggs.storage.rollup_keeper import RollupKeeper

LATS = [48.85, 48.86, -33.9, 10.0, 10.01]
LNGS = [2.35, 2.34, 151.2, -80.0, -80.02]
POP = [10, 20, 5, 7, 1]
LEVEL = 6


def _open(path) -> Connection:
    return Connection(str(path), create=True, readonly=False, timeout=30.0)


def _sql(path, query: str) -> list[tuple]:
    """Rows of ``query`` read on a connection of its own (plain sqlite3, nothing of dggs.storage)."""
    conn = sqlite3.connect(str(path))
    try:
        return conn.execute(query).fetchall()
    finally:
        conn.close()


@pytest.fixture
def filled(tmp_path):
    """A store file with the five points, ingested by an Ingester alone; its path and Connection."""
    path = tmp_path / "alone.db"
    store = _open(path)
    Ingester(store).ingest_points(LATS, LNGS, LEVEL, {"pop": POP})
    yield path, store
    store.close()


def test_ingester_alone_stores_every_row_in_its_cell(filled):
    path, _ = filled
    rows = _sql(path, "SELECT cell, lat, lng, pop FROM all_points ORDER BY row")
    assert [(c, la, ln, p) for c, la, ln, p in rows] == [
        (dggs.latlng_to_cell(la, ln, LEVEL), la, ln, p) for la, ln, p in zip(LATS, LNGS, POP, strict=True)
    ]
    assert _sql(path, "SELECT value FROM meta WHERE key = 'level'") == [(str(LEVEL),)]


def test_ingester_alone_dispatches_records_and_merges(tmp_path):
    path = tmp_path / "records.db"
    store = _open(path)
    try:
        ingester = Ingester(store, merge_rows=10**9)  # nothing merged while ingesting
        records = [{"lat": la, "lng": ln, "v": p} for la, ln, p in zip(LATS, LNGS, POP, strict=True)]
        result = ingester.ingest(records, values=["v"], level=3)
        assert result.rows_inserted == 5
        ingester.merge()
        assert _sql(path, "SELECT count(*) FROM points_pending") == [(0,)]
        assert _sql(path, "SELECT count(*), sum(v) FROM points") == [(5, sum(POP))]
    finally:
        store.close()


def test_rollup_keeper_alone_keeps_what_group_by_gives(filled):
    path, store = filled
    keeper = RollupKeeper(store)
    assert keeper.rollup_levels == ()
    assert keeper.keep_rollups([2, 4]) == (4, 2)
    assert keeper.rollup_levels == (4, 2)
    for level in (2, 4):
        kept = _sql(path, f"SELECT cell, rows FROM rollups WHERE level = {level} ORDER BY cell")
        brute = Counter(dggs.latlng_to_cell(la, ln, level) for la, ln in zip(LATS, LNGS, strict=True))
        assert kept == sorted(brute.items())


def test_rollup_keeper_alone_refuses_a_read_only_store(filled):
    path, _ = filled
    readonly = Connection(str(path), create=False, readonly=True, timeout=30.0)
    try:
        with pytest.raises(StorageError, match="read-only"):
            RollupKeeper(readonly).keep_rollups([1])
    finally:
        readonly.close()


def test_exporter_alone_writes_the_roll_up(filled, tmp_path):
    _, store = filled
    out = tmp_path / "cells.geojson"
    assert Exporter(store).export(out, 1, "pop", progress=False) == 3
    features = json.loads(out.read_text())["features"]
    got = {f["properties"]["cell"]: (f["properties"]["count"], f["properties"]["sum"]) for f in features}
    brute: dict[str, list[int]] = {}
    for la, ln, p in zip(LATS, LNGS, POP, strict=True):
        brute.setdefault(dggs.latlng_to_cell(la, ln, 1), []).append(p)
    assert got == {cell: (len(ps), sum(ps)) for cell, ps in brute.items()}


def test_exporter_alone_refuses_to_write_over_its_store(filled):
    path, store = filled
    with pytest.raises(StorageError):
        Exporter(store).to_geojson(1, path=path)
    assert _sql(path, "SELECT count(*) FROM all_points") == [(5,)]  # the store is whole


def test_raster_ingester_alone_stores_a_row_per_cell(tmp_path):
    xr = pytest.importorskip("xarray")
    pytest.importorskip("rioxarray")
    from dggs.raster import raster_to_cells

    grid = xr.DataArray(np.arange(16.0).reshape(4, 4), dims=("y", "x"),
                        coords={"y": [3.5, 2.5, 1.5, 0.5], "x": [0.5, 1.5, 2.5, 3.5]}).rio.write_crs("EPSG:4326")
    path = tmp_path / "raster.db"
    store = _open(path)
    try:
        RasterIngester(store).ingest_raster(grid, 4, progress=False)
    finally:
        store.close()
    expected = raster_to_cells(grid, 4, as_str=True)  # the in-memory function, no store involved
    assert len(expected) > 1
    stored = _sql(path, "SELECT cell, value, coverage FROM points ORDER BY cell")
    assert stored == sorted(zip(expected["cell"], expected["value"], expected["coverage"], strict=True))


def test_querier_alone_answers_from_the_rows(filled):
    _, store = filled
    querier = Querier(store)
    paris = dggs.latlng_to_cell(48.85, 2.35, 2)
    assert querier.count() == 5 and querier.count(paris) == 2
    assert sorted(r["pop"] for r in querier.descendants(paris)) == [10, 20]
    brute: dict[str, list[int]] = {}
    for la, ln, p in zip(LATS, LNGS, POP, strict=True):
        brute.setdefault(dggs.latlng_to_cell(la, ln, 0), []).append(p)
    got = querier.aggregate(0, "pop", ("count", "sum", "max"), progress=False)
    assert [(r["cell"], r["count"], r["sum"], r["max"]) for r in got] == [
        (cell, len(ps), sum(ps), max(ps)) for cell, ps in sorted(brute.items())
    ]
    here = dggs.latlng_to_cell(10.0, -80.0, LEVEL)
    assert sorted(r["pop"] for r in querier.disk(here, 1)) == sorted(
        p for la, ln, p in zip(LATS, LNGS, POP, strict=True)
        if dggs.latlng_to_cell(la, ln, LEVEL) in set(dggs.grid_disk(here, 1))
    )


@pytest.mark.parametrize("collaborator", [Querier, Ingester, RasterIngester, Exporter, RollupKeeper])
def test_cell_store_methods_are_the_collaborators(collaborator):
    """Each public method a collaborator does has the same parameters and docstring on CellStore."""
    for name, method in vars(collaborator).items():
        if name.startswith("_") or name in ("path", "timeout"):
            continue
        face = getattr(CellStore, name)
        assert inspect.getdoc(face) == inspect.getdoc(method), name
        if callable(method):
            ours = [(p.name, p.kind, p.default) for p in inspect.signature(face).parameters.values()]
            theirs = [(p.name, p.kind, p.default) for p in inspect.signature(method).parameters.values()]
            assert ours == theirs, name
