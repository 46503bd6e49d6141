"""dggs.duckdb: the SQL functions equal the Python API, on tables in memory and on Parquet files."""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import dggs

duckdb = pytest.importorskip("duckdb")
pa = pytest.importorskip("pyarrow")
pq = pytest.importorskip("pyarrow.parquet")
shapely = pytest.importorskip("shapely")

from dggs.duckdb import FUNCTIONS, register  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
KINDS = ["BIGINT", "UBIGINT", "VARCHAR"]
N = 5000  # more than two DuckDB batches (2,048 rows)


@pytest.fixture
def con():
    c = register(duckdb.connect())
    yield c
    c.close()


def _points(n=N, seed=0):
    """Random points plus poles, the antimeridian, the equator and the prime meridian."""
    rng = np.random.default_rng(seed)
    lat = rng.uniform(-90, 90, n)
    lng = rng.uniform(-180, 180, n)
    special_lat = [90.0, -90.0, 0.0, 0.0, 0.0, 45.0, -45.0, 89.9999999, -89.9999999, 0.0, 60.0, -60.0]
    special_lng = [0.0, 123.4, 180.0, -180.0, 179.9999999, -179.9999999, 180.0, 180.0, -180.0, 0.0, -180.0, 180.0]
    return np.concatenate([special_lat, lat]), np.concatenate([special_lng, lng])


def _ids(kind, level=12, n=N, seed=1):
    """Python-API ids of random points as a pyarrow array of the SQL id ``kind``."""
    lat, lng = _points(n, seed)
    ids = dggs.latlng_to_cell(lat, lng, level, as_int=True)
    if kind == "VARCHAR":
        return pa.array(dggs.int_to_str(ids).astype(object), pa.string())
    return pa.array(ids.view(np.int64) if kind == "BIGINT" else ids, pa.int64() if kind == "BIGINT" else pa.uint64())


def _py(ids):
    """The ids of a pyarrow array as the Python API's numpy form (uint64 or object strings)."""
    if pa.types.is_string(ids.type):
        return np.asarray(ids.to_pylist(), dtype=object)
    return ids.to_numpy().astype(np.uint64)


def _column(con, sql):
    return con.sql(sql).fetchnumpy()


# ---------------------------------------------------------------------------------------------- set-up


def test_import_dggs_does_not_import_duckdb():
    code = "import sys, dggs; dggs.latlng_to_cell(1.0, 2.0, 3); assert 'duckdb' not in sys.modules, sorted(sys.modules)"
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr


def test_register_adds_every_listed_function_and_can_run_twice(con):
    register(con)  # again: replaces, does not fail
    names = {r[0] for r in con.sql("SELECT DISTINCT function_name FROM duckdb_functions()").fetchall()}
    assert set(FUNCTIONS) <= names
    for name in FUNCTIONS:
        if not name.startswith(("dggs_latlng_to_cell", "dggs_polygon_to_cells")):  # no id argument
            assert {f"{name}_i64", f"{name}_u64", f"{name}_str"} <= names
    assert con.sql("SELECT dggs_get_level('C401')").fetchall()[0] == (3,)


def test_functions_are_per_connection():
    with duckdb.connect() as other:
        with pytest.raises(duckdb.CatalogException):
            other.sql("SELECT dggs_get_level('C401')").fetchall()


# ---------------------------------------------------------------------------------------------- equal to the Python API


@pytest.mark.parametrize("level", [0, 1, 7, 17, 28])
def test_latlng_to_cell_equals_python(con, level):
    lat, lng = _points()
    con.register("pts", pa.table({"lat": lat, "lng": lng}))
    got = _column(con, f"SELECT dggs_latlng_to_cell(lat, lng, {level}) AS i, dggs_latlng_to_cell_str(lat, lng, {level}) AS s FROM pts")
    want = dggs.latlng_to_cell(lat, lng, level, as_int=True)
    assert got["i"].dtype == np.int64 and (got["i"] > 0).all()
    np.testing.assert_array_equal(got["i"].astype(np.uint64), want)
    np.testing.assert_array_equal(got["s"].astype(str), dggs.int_to_str(want))
    assert con.sql("SELECT typeof(dggs_latlng_to_cell(0, 0, 3)), typeof(dggs_latlng_to_cell_str(0, 0, 3))").fetchall()[0] == (
        "BIGINT",
        "VARCHAR",
    )


def test_latlng_to_cell_mixed_levels_equal_python(con):
    lat, lng = _points()
    level = np.random.default_rng(2).integers(0, 29, lat.size)
    con.register("pts", pa.table({"lat": lat, "lng": lng, "level": pa.array(level, pa.int8())}))
    got = _column(con, "SELECT dggs_latlng_to_cell(lat, lng, level) AS i, dggs_latlng_to_cell_str(lat, lng, level) AS s FROM pts")
    want = np.array([dggs.latlng_to_cell(a, b, int(lv), as_int=True) for a, b, lv in zip(lat, lng, level, strict=True)], np.uint64)
    np.testing.assert_array_equal(got["i"].astype(np.uint64), want)
    np.testing.assert_array_equal(got["s"].astype(str), dggs.int_to_str(want))


@pytest.mark.parametrize("kind", KINDS)
def test_cell_functions_equal_python(con, kind):
    ids = _ids(kind)
    cells = _py(ids)
    con.register("cells", pa.table({"cell": ids}))
    got = _column(
        con,
        """SELECT dggs_cell_to_parent(cell, 6) AS parent, dggs_cell_to_latlng_lat(cell) AS lat,
                  dggs_cell_to_latlng_lng(cell) AS lng, dggs_cell_to_latlng(cell).lat AS slat,
                  dggs_cell_to_latlng(cell).lng AS slng, dggs_cell_area(cell) AS area, dggs_get_level(cell) AS level,
                  dggs_str_to_int(cell) AS i, dggs_int_to_str(cell) AS s, dggs_is_valid_cell(cell) AS ok FROM cells""",
    )
    parent = dggs.cell_to_parent(cells, 6)
    if kind == "VARCHAR":
        np.testing.assert_array_equal(got["parent"].astype(str), parent.astype(str))
    else:
        np.testing.assert_array_equal(got["parent"].astype(np.uint64), parent)
    lat, lng = dggs.cell_to_latlng(cells)
    np.testing.assert_array_equal(got["lat"], lat)
    np.testing.assert_array_equal(got["lng"], lng)
    np.testing.assert_array_equal(got["slat"], lat)
    np.testing.assert_array_equal(got["slng"], lng)
    np.testing.assert_array_equal(got["area"], dggs.cell_area(cells))
    np.testing.assert_array_equal(got["level"], dggs.get_level(cells))
    assert got["i"].dtype == np.int64
    np.testing.assert_array_equal(got["i"].astype(np.uint64), dggs.str_to_int(cells))
    np.testing.assert_array_equal(got["s"].astype(str), dggs.int_to_str(cells).astype(str))
    assert got["ok"].all()


@pytest.mark.parametrize("kind", KINDS)
def test_cell_to_parent_returns_the_kind_given_and_mixed_levels(con, kind):
    ids = _ids(kind, level=20, n=3000)
    cells = _py(ids)
    levels = np.random.default_rng(3).integers(0, 21, len(ids))
    con.register("cells", pa.table({"cell": ids, "level": levels}))
    typ = con.sql("SELECT DISTINCT typeof(dggs_cell_to_parent(cell, level)) FROM cells").fetchall()
    assert typ == [(kind,)]
    got = _column(con, "SELECT dggs_cell_to_parent(cell, level) AS p FROM cells")["p"]
    want = [dggs.cell_to_parent(c, int(lv)) for c, lv in zip(cells.tolist(), levels, strict=True)]
    if kind == "VARCHAR":
        assert got.astype(str).tolist() == want
    else:
        assert got.astype(np.uint64).tolist() == want


@pytest.mark.parametrize("kind", KINDS)
def test_boundary_wkb_equals_cell_to_polygon(con, kind):
    # levels 0-2 include cells crossing the antimeridian (MultiPolygons) and touching the poles
    ids = pa.concat_arrays([_ids(kind, level=lv, n=300, seed=lv) for lv in (0, 1, 2, 9, 17)])
    cells = _py(ids)
    con.register("cells", pa.table({"cell": ids}))
    got = con.sql("SELECT dggs_cell_to_boundary_wkb(cell) AS w, typeof(dggs_cell_to_boundary_wkb(cell)) AS t FROM cells").fetchall()
    assert {t for _, t in got} == {"BLOB"}
    want = shapely.to_wkb(dggs.cell_to_polygon(cells))
    assert [bytes(w) for w, _ in got] == list(want)
    geoms = shapely.from_wkb([bytes(w) for w, _ in got])
    assert {g.geom_type for g in geoms} == {"Polygon", "MultiPolygon"}


def test_group_by_on_parquet(con, tmp_path):
    lat, lng = _points()
    pop = np.random.default_rng(4).integers(1, 1000, lat.size)
    cell = dggs.latlng_to_cell(lat, lng, 12, as_int=True)
    path = tmp_path / "points.parquet"
    pq.write_table(pa.table({"cell": pa.array(cell.view(np.int64)), "cell_u": cell, "lat": lat, "lng": lng, "pop": pop}), path)
    got = dict(con.sql(f"SELECT dggs_cell_to_parent(cell, 6) AS p, sum(pop) FROM '{path}' GROUP BY 1").fetchall())
    parents = dggs.cell_to_parent(cell, 6)
    want = {int(p): int(pop[parents == p].sum()) for p in np.unique(parents)}
    assert {int(np.uint64(np.int64(k))): int(v) for k, v in got.items()} == want
    assert all(k > 0 for k in got)  # BIGINT ids are positive
    # the same roll-up from points, from uint64 ids and from string ids
    for expr in (
        "dggs_latlng_to_cell(lat, lng, 6)",
        "dggs_cell_to_parent(cell_u, 6)",
        "dggs_str_to_int(dggs_cell_to_parent(dggs_int_to_str(cell), 6))",
    ):
        rows = con.sql(f"SELECT {expr} AS p, sum(pop) FROM read_parquet('{path}') GROUP BY 1").fetchall()
        assert {int(k) & (2**64 - 1): int(v) for k, v in rows} == want, expr


def test_string_ids_on_parquet(con, tmp_path):
    ids = _ids("VARCHAR", level=9)
    path = tmp_path / "cells.parquet"
    pq.write_table(pa.table({"cell": ids}), path)
    got = con.sql(f"SELECT dggs_cell_to_parent(cell, 4) AS p, count(*) AS n FROM '{path}' GROUP BY 1 ORDER BY 1").fetchall()
    parents, counts = np.unique(dggs.cell_to_parent(_py(ids), 4).astype(str), return_counts=True)
    assert got == list(zip(parents.tolist(), counts.tolist(), strict=True))


# ---------------------------------------------------------------------------------------------- NULLs and errors


@pytest.mark.parametrize("kind", KINDS)
def test_nulls_give_nulls(con, kind):
    cells = _ids(kind, level=10, n=3000).to_pylist()
    cells[5] = cells[2500] = None
    levels = [4] * len(cells)
    levels[7] = None
    typ = {"BIGINT": pa.int64(), "UBIGINT": pa.uint64(), "VARCHAR": pa.string()}[kind]
    con.register("cells", pa.table({"cell": pa.array(cells, typ), "level": pa.array(levels, pa.int32())}))
    rows = con.sql(
        """SELECT dggs_cell_to_parent(cell, level), dggs_cell_to_latlng(cell), dggs_cell_to_latlng_lat(cell),
                  dggs_cell_to_latlng_lng(cell), dggs_cell_to_boundary_wkb(cell), dggs_cell_area(cell),
                  dggs_get_level(cell), dggs_str_to_int(cell), dggs_int_to_str(cell), dggs_is_valid_cell(cell)
           FROM cells"""
    ).fetchall()
    for i, row in enumerate(rows):
        if i in (5, 2500):
            assert row == (None,) * 10
        elif i == 7:
            assert row[0] is None and None not in row[1:]
        else:
            assert None not in row
            assert row[0] == dggs.cell_to_parent(cells[i], 4)
            assert row[6] == 10
    typed_null = f"NULL::{kind}"
    assert con.sql(f"SELECT dggs_get_level({typed_null}), dggs_cell_to_parent({typed_null}, 3)").fetchall()[0] == (None, None)
    assert con.sql("SELECT dggs_get_level(NULL), dggs_cell_to_parent('C401', NULL)").fetchall()[0] == (None, None)
    assert con.sql("SELECT dggs_latlng_to_cell(NULL, 1, 2), dggs_latlng_to_cell_str(1, NULL, 2), "
                   "dggs_latlng_to_cell(1, 2, NULL)").fetchall()[0] == (None, None, None)  # fmt: skip


def test_all_null_batch_and_empty_table(con):
    con.register("t", pa.table({"cell": pa.array([None, None], pa.string()), "lat": pa.array([None, 1.0])}))
    assert con.sql("SELECT dggs_cell_to_parent(cell, 2), dggs_cell_to_latlng(cell), dggs_latlng_to_cell(lat, 0, 3) FROM t").fetchall() == [
        (None, None, None),
        (None, None, dggs.latlng_to_cell(1.0, 0.0, 3, as_int=True)),
    ]
    con.register("e", pa.table({"cell": pa.array([], pa.int64())}))
    assert con.sql("SELECT dggs_cell_area(cell), dggs_cell_to_boundary_wkb(cell) FROM e").fetchall() == []


@pytest.mark.parametrize(
    "sql, pattern",
    [
        ("SELECT dggs_get_level('X9')", r"InvalidCellError: dggs_get_level: 'X9' is not a valid cell id"),
        ("SELECT dggs_cell_area('C6')", r"dggs_cell_area: 'C6' is not a valid cell id"),
        ("SELECT dggs_str_to_int('C401 ')", r"dggs_str_to_int: 'C401 ' is not a valid cell id"),
        ("SELECT dggs_cell_to_latlng(-5)", r"dggs_cell_to_latlng: -5 is not a valid cell id"),
        ("SELECT dggs_int_to_str(42)", r"dggs_int_to_str: 42 is not a valid cell id"),
        ("SELECT dggs_cell_to_boundary_wkb(42::UBIGINT)", r"dggs_cell_to_boundary_wkb: 42 is not a valid cell id"),
        ("SELECT dggs_cell_to_parent('C4', 3)", r"LevelMismatchError: dggs_cell_to_parent: parent level 3 is finer than cell 'C4'"),
        ("SELECT dggs_cell_to_parent('C401', 29)", r"dggs_cell_to_parent: .*29"),
        ("SELECT dggs_latlng_to_cell(91, 0, 3)", r"CoordinateError: dggs_latlng_to_cell: latitude 91(\.0)? is out of range"),
        ("SELECT dggs_latlng_to_cell_str('nan'::DOUBLE, 0, 3)", r"dggs_latlng_to_cell_str: latitude nan"),
        ("SELECT dggs_latlng_to_cell(0, 0, 29)", r"LevelError: dggs_latlng_to_cell: level 29 is out of range 0\.\.28"),
        ("SELECT dggs_latlng_to_cell_str(0, 0, -1)", r"dggs_latlng_to_cell_str: level -1 is out of range"),
    ],
)
def test_bad_input_raises_naming_the_value(con, sql, pattern):
    with pytest.raises(duckdb.Error) as info:
        con.sql(sql).fetchall()
    assert re.search(pattern, str(info.value)), str(info.value)
    assert " at index " not in str(info.value)  # batch-relative positions would mislead


@pytest.mark.parametrize("kind", KINDS)
def test_bad_id_deep_in_a_table_is_named(con, kind):
    cells = _ids(kind, level=5, n=4000).to_pylist()
    bad = {"BIGINT": -7, "UBIGINT": 7, "VARCHAR": "Z123"}[kind]
    cells[3000] = bad
    typ = {"BIGINT": pa.int64(), "UBIGINT": pa.uint64(), "VARCHAR": pa.string()}[kind]
    con.register("cells", pa.table({"cell": pa.array(cells, typ)}))
    assert con.sql("SELECT count(*) FILTER (NOT dggs_is_valid_cell(cell)) FROM cells").fetchall()[0] == (1,)
    with pytest.raises(duckdb.Error, match=re.escape(f"dggs_cell_to_parent: {bad!r} is not a valid cell id")):
        con.sql("SELECT dggs_cell_to_parent(cell, 2) FROM cells").fetchall()


# ---------------------------------------------------------------------------------------------- docs


def _python_blocks(text):
    return re.findall(r"^```python\n(.*?)^```", text, re.S | re.M)


def test_docs_examples_run(tmp_path, monkeypatch):
    text = (ROOT / "docs" / "duckdb.md").read_text()
    blocks = _python_blocks(text)
    assert blocks
    for name in FUNCTIONS:
        assert name in text, f"{name} is not documented"
    monkeypatch.chdir(tmp_path)
    namespace: dict = {}
    for block in blocks:
        exec(compile(block, "docs/duckdb.md", "exec"), namespace)


def test_module_docstring_examples():
    import doctest

    import dggs.duckdb.udfs  # register's examples

    result = doctest.testmod(dggs.duckdb.udfs, optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    assert result.failed == 0 and result.attempted > 0
