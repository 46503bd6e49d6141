"""dggs.spark: Arrow UDFs on a local[2] SparkSession equal the Python API; SQL and column forms agree.

The batch functions (dggs.spark.udfs) are checked without a JVM, with hypothesis, for both id forms. The
Spark tests share one module-scoped session (the JVM starts once) and are marked ``spark``-slow: they run in
``make test-all``.
"""

from __future__ import annotations

import collections
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from hypothesis import example, given
from hypothesis import strategies as st

import dggs
from tests.strategies import cells, examples, latitudes, levels, longitudes, special_points

pa = pytest.importorskip("pyarrow")
pq = pytest.importorskip("pyarrow.parquet")
shapely = pytest.importorskip("shapely")
pytest.importorskip("pyspark")

from dggs.spark.udfs import FUNCTIONS, batch_function  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
SPECIAL = special_points()
SPECIAL_LAT = np.array([p[0] for p in SPECIAL])
SPECIAL_LNG = np.array([p[1] for p in SPECIAL])


def _points(n: int, seed: int = 0) -> tuple[np.ndarray, np.ndarray]:
    """Random points on the sphere plus the poles, the antimeridian, the icosahedron's vertices and edges."""
    rng = np.random.default_rng(seed)
    lat = np.degrees(np.arcsin(rng.uniform(-1, 1, n)))
    lng = rng.uniform(-180, 180, n)
    return np.concatenate([SPECIAL_LAT, lat]), np.concatenate([SPECIAL_LNG, lng])


def _as_kind(ids: np.ndarray, kind: str):
    ids = np.asarray(ids, dtype=np.int64)
    if kind == "str":
        return pa.array(dggs.int_to_str(ids.view(np.uint64)).astype(object), pa.string())
    return pa.array(ids, pa.int64())


# ---------------------------------------------------------------------------------------------- without a JVM


@given(st.lists(st.tuples(latitudes(), longitudes()), min_size=1, max_size=40), levels(0, 28),
       st.lists(st.booleans(), min_size=40, max_size=40))
@example([(90.0, 0.0), (-90.0, 0.0), (0.0, 180.0), (0.0, -180.0)], 12, [False] * 40)
@example([(p[0], p[1]) for p in SPECIAL[:40]], 5, [True, False] * 20)
def test_batch_latlng_to_cell_nulls_stay_put(points, level, nulls):
    """NULL rows give NULL; every other row is the Python API's cell, in both id forms."""
    lat = np.array([p[0] for p in points])
    lng = np.array([p[1] for p in points])
    mask = np.array(nulls[: len(points)])
    expected = dggs.latlng_to_cell(lat, lng, level, as_int=True)
    got = batch_function("dggs_latlng_to_cell")(pa.array(lat, mask=mask), pa.array(lng), pa.array([level] * len(lat)))
    got_str = batch_function("dggs_latlng_to_cell_str")(pa.array(lat), pa.array(lng, mask=mask),
                                                        pa.array([level] * len(lat)))
    for i in range(len(lat)):
        if mask[i]:
            assert got[i].as_py() is None and got_str[i].as_py() is None
        else:
            assert got[i].as_py() == int(expected[i])
            assert got_str[i].as_py() == dggs.int_to_str(int(expected[i]))


@given(st.lists(cells(min_level=1, max_level=20), min_size=1, max_size=30), st.sampled_from(["int", "str"]))
@example(["A0", "T5", "B20000", "K5222222222"], "int")
def test_batch_parent_children_disk(strings, kind):
    """Parents, children and disks of a batch are the Python API's, row by row."""
    ids = np.array([dggs.str_to_int(s) for s in strings], dtype=np.uint64)
    col = _as_kind(ids.view(np.int64), kind)
    lv = np.array([dggs.get_level(int(i)) for i in ids])
    parents = batch_function("dggs_cell_to_parent")(col, pa.array(lv - 1)).to_pylist()
    assert parents == [dggs.cell_to_parent(int(i), int(v) - 1) for i, v in zip(ids, lv, strict=True)]
    children = batch_function("dggs_cell_to_children")(col, pa.array(np.minimum(lv + 1, 28))).to_pylist()
    assert children == [sorted(dggs.cell_to_children(int(i), min(int(v) + 1, 28))) for i, v in zip(ids, lv, strict=True)]
    disks = batch_function("dggs_grid_disk")(col, pa.array([1] * len(ids))).to_pylist()
    assert disks == [sorted(dggs.grid_disk(int(i), 1)) for i in ids]


@given(st.lists(st.tuples(cells(min_level=1, max_level=12), st.integers(0, 3), st.integers(0, 400)), min_size=1,
                max_size=8), st.sampled_from(["int", "str"]))
@example([("A0", 1, 0), ("T5", 3, 7), ("E2", 2, 3)], "str")  # across face edges
@example([("C401", 0, 0), ("K52222", 3, 11)], "int")
def test_batch_grid_path_cells(starts, kind):
    """Each row's path is the Python API's, and it is a chain of edge neighbours of the right length."""
    a_ids, b_ids = [], []
    for start, k, pick in starts:
        ring = dggs.grid_disk(start, k)  # the other end: a cell within k steps (a brute-force choice)
        a_ids.append(dggs.str_to_int(start))
        b_ids.append(dggs.str_to_int(ring[pick % len(ring)]))
    a, b = (_as_kind(np.array(x, np.uint64).view(np.int64), kind) for x in (a_ids, b_ids))
    got = batch_function("dggs_grid_path_cells")(a, b).to_pylist()
    for path, x, y in zip(got, a_ids, b_ids, strict=True):
        assert path == [int(c) for c in dggs.grid_path_cells(x, y)]
        assert path[0] == x and path[-1] == y and len(path) == dggs.grid_distance(x, y) + 1
        assert all(dggs.are_neighbor_cells(p, q) for p, q in zip(path, path[1:], strict=False))


@given(st.lists(st.lists(cells(min_level=1, max_level=6), max_size=12) | st.none(), min_size=1, max_size=5),
       st.sampled_from(["int", "str"]))
@example([["A0", "A1", "A2", "A3", "A4", "A5"], None, []], "int")  # a whole face; a NULL row; an empty set
@example([[c for c in dggs.get_base_cells()], ["E5", "J4"]], "str")  # the whole sphere; across the antimeridian
def test_batch_cells_to_polygons_wkb(rows, kind):
    """Each row's WKB is the Python API's outline of that row's set; NULL rows give NULL."""
    typ = pa.list_(pa.string() if kind == "str" else pa.int64())
    values = [None if r is None else (r if kind == "str" else [dggs.str_to_int(c) for c in r]) for r in rows]
    got = batch_function("dggs_cells_to_polygons_wkb")(pa.array(values, typ)).to_pylist()
    for wkb, r in zip(got, rows, strict=True):
        if r is None:
            assert wkb is None
        else:
            assert shapely.equals_exact(shapely.from_wkb(wkb), dggs.cells_to_polygons(r), tolerance=0)


@given(st.lists(st.sampled_from(["C401", "Q9", "B2", "", "Z0", "A00000"]), min_size=1, max_size=12),
       st.sampled_from(["int", "str"]))
@example(["C401", "Q9"], "str")
def test_batch_null_on_invalid(values, kind):
    """on_invalid='null' gives NULL exactly at the bad ids; 'raise' names the first bad one and its row."""
    good = [dggs.is_valid_cell(v) for v in values]
    if kind == "str":
        col = pa.array(values)
    else:  # a bad integer id: a level-0 id with a digit set (bits below the level in use)
        col = pa.array([dggs.str_to_int(v) if ok else dggs.str_to_int("A") + 1 for v, ok in zip(values, good, strict=True)],
                       pa.int64())
    got = batch_function("dggs_get_level", "null")(col).to_pylist()
    assert got == [len(v) - 1 if ok else None for v, ok in zip(values, good, strict=True)]
    if all(good):
        return
    row = good.index(False)
    with pytest.raises(dggs.InvalidCellError, match=rf"dggs_get_level: row {row} of the batch \(cell="):
        batch_function("dggs_get_level")(col)


def test_batch_errors_are_typed_and_named():
    lat, lng, lv = pa.array([10.0, 95.0]), pa.array([0.0, 0.0]), pa.array([9, 9])
    with pytest.raises(dggs.CoordinateError, match=r"row 1 of the batch \(lat=95.0, lng=0.0, level=9\)"):
        batch_function("dggs_latlng_to_cell")(lat, lng, lv)
    with pytest.raises(dggs.LevelError, match="level=40"):
        batch_function("dggs_latlng_to_cell")(pa.array([1.0]), pa.array([1.0]), pa.array([40]))
    with pytest.raises(dggs.LevelMismatchError, match="cell='C4'"):
        batch_function("dggs_cell_to_parent")(pa.array(["C4"]), pa.array([3]))
    with pytest.raises(dggs.DggsValueError, match="wkb=b'xx'"):
        batch_function("dggs_polygon_to_cells")(pa.array([b"xx"]), pa.array([3]), pa.array(["center"]))
    with pytest.raises(dggs.DggsValueError, match="on_invalid"):
        batch_function("dggs_get_level", "ignore")
    with pytest.raises(dggs.DggsValueError, match="dggs_nope"):
        batch_function("dggs_nope")


# ---------------------------------------------------------------------------------------------- Spark local[2]

pytestmark_spark = pytest.mark.slow  # the JVM and two Python workers: ~1 minute on 2 shared cores


@pytest.fixture(scope="module")
def spark(tmp_path_factory):
    import dggs.spark

    conf = {"spark.ui.enabled": "false", "spark.ui.showConsoleProgress": "false",
            "spark.sql.shuffle.partitions": "4", "spark.sql.execution.arrow.maxRecordsPerBatch": "3000"}
    # the JVM and the Python workers it starts (`python -m pyspark.daemon`, which puts the working directory
    # first on sys.path) run in a scratch directory, as a user's job would, not in the source tree
    here = os.getcwd()
    os.chdir(tmp_path_factory.mktemp("spark-cwd"))
    try:
        session = dggs.spark.local_session("local[2]", **conf)
    finally:
        os.chdir(here)
    session.sparkContext.setLogLevel("ERROR")
    yield session
    session.stop()


def _frame(spark, n=8000, seed=3):
    lat, lng = _points(n, seed)
    return spark.createDataFrame(pa.table({"lat": lat, "lng": lng, "w": np.arange(lat.size, dtype=np.float64)})), lat, lng


@pytestmark_spark
def test_spark_points_equal_python_api(spark):
    import dggs.spark as ds

    df, lat, lng = _frame(spark)
    df.createOrReplaceTempView("pts")
    sql = spark.sql("SELECT w, dggs_latlng_to_cell(lat, lng, 12) AS c, dggs_latlng_to_cell_str(lat, lng, 12) AS s, "
                    "dggs_cell_to_parent(dggs_latlng_to_cell(lat, lng, 12), 4) AS p FROM pts").toArrow()
    cols = df.select("w", ds.latlng_to_cell("lat", "lng", 12).alias("c"), ds.latlng_to_cell_str("lat", "lng", 12)
                     .alias("s"), ds.cell_to_parent(ds.latlng_to_cell("lat", "lng", 12), 4).alias("p")).toArrow()
    order = np.asarray(sql.column("w").to_numpy(), dtype=np.int64)
    expected = dggs.latlng_to_cell(lat, lng, 12, as_int=True)
    assert np.array_equal(sql.column("c").to_numpy(), expected[order])
    assert sql.column("s").to_pylist() == list(dggs.int_to_str(expected[order].view(np.uint64)))
    assert np.array_equal(sql.column("p").to_numpy(), dggs.cell_to_parent(expected, 4)[order])
    assert sql.sort_by("w").equals(cols.sort_by("w"))


@pytestmark_spark
def test_spark_cell_functions_equal_python_api(spark):
    from pyspark.sql import functions as F

    import dggs.spark as ds

    lat, lng = _points(300, seed=5)
    ids = np.asarray(dggs.latlng_to_cell(lat, lng, 7, as_int=True), np.uint64).view(np.int64)
    df = spark.createDataFrame(pa.table({"i": np.arange(ids.size), "c": ids, "s": dggs.int_to_str(ids.view(np.uint64))}))
    out = df.select("i", ds.cell_to_latlng("c").alias("ll"), ds.cell_to_boundary_wkb("s").alias("wkb"),
                    ds.cell_area("c").alias("a"), ds.get_level("s").alias("lv"), ds.grid_disk("c", 1).alias("d"),
                    ds.cell_to_children("s", 8).alias("ch"), ds.int_to_str("c").alias("str"),
                    ds.str_to_int("s").alias("int"), ds.is_valid_cell("s").alias("ok")).toArrow().sort_by("i")
    clat, clng = dggs.cell_to_latlng(ids)
    ll = out.column("ll").combine_chunks()
    assert np.array_equal(ll.field("lat").to_numpy(), clat) and np.array_equal(ll.field("lng").to_numpy(), clng)
    polys = shapely.from_wkb(np.asarray(out.column("wkb").to_pylist(), dtype=object))
    assert shapely.equals_exact(polys, dggs.cell_to_polygon(ids), tolerance=0).all()
    assert np.array_equal(out.column("a").to_numpy(), dggs.cell_area(ids))
    assert set(out.column("lv").to_pylist()) == {7} and all(out.column("ok").to_pylist())
    assert out.column("d").to_pylist() == [sorted(r[r != 0].tolist()) for r in dggs.grid_disk(ids, 1)]
    assert out.column("ch").to_pylist() == [dggs.cell_to_children(int(c), 8) for c in ids]
    assert out.column("str").to_pylist() == list(dggs.int_to_str(ids.view(np.uint64)))
    assert np.array_equal(out.column("int").to_numpy(), ids)
    sql = spark.sql("SELECT dggs_cell_area(5392473139689029632) AS a, dggs_get_level('F200021102') AS lv").first()
    assert sql.a == pytest.approx(float(dggs.cell_area("F200021102")), rel=0) and sql.lv == 9
    path = spark.sql("SELECT dggs_grid_path_cells('A0', 'E2') AS p").first().p
    assert path == [dggs.str_to_int(c) for c in dggs.grid_path_cells("A0", "E2")]
    df.createOrReplaceTempView("cells")
    outline = spark.sql("SELECT dggs_cells_to_polygons_wkb(collect_list(c)) AS w FROM cells").first().w
    assert shapely.equals(shapely.from_wkb(outline), dggs.cells_to_polygons(ids))
    far = F.element_at(ds.grid_disk("c", 2), -1)  # the last of the sorted disk: some cell within 2 steps
    paths = df.select("i", ds.grid_path_cells("c", far).alias("p")).toArrow().sort_by("i").column("p").to_pylist()
    assert paths == [[int(x) for x in dggs.grid_path_cells(int(c), int(sorted(dggs.grid_disk(int(c), 2))[-1]))]
                     for c in ids]


@pytestmark_spark
def test_spark_polygons_equal_python_api(spark):
    import dggs.spark as ds

    shapes = [shapely.box(-10, -10, 10, 10), shapely.box(170, 60, 190, 70),  # across the antimeridian
              shapely.Polygon([(0, 80), (120, 80), (-120, 80)]).buffer(0),  # round the north pole
              shapely.box(0, 0, 50, 50).difference(shapely.box(10, 10, 40, 40))]  # with a hole
    table = pa.table({"i": list(range(len(shapes))), "g": [shapely.to_wkb(s) for s in shapes]})
    df = spark.createDataFrame(table)
    df.createOrReplaceTempView("polys")
    for mode in ("center", "contains", "overlaps"):
        col = df.select("i", ds.polygon_to_cells("g", 4, mode).alias("c")).toArrow().sort_by("i")
        sql = spark.sql(f"SELECT i, dggs_polygon_to_cells(g, 4, '{mode}') AS c FROM polys").toArrow().sort_by("i")
        want = [sorted(np.asarray(dggs.polygon_to_cells(s, 4, mode=mode, as_int=True)).tolist()) for s in shapes]
        assert [sorted(r) for r in col.column("c").to_pylist()] == want
        assert sql.equals(col)


@pytestmark_spark
def test_spark_nulls_and_errors(spark):
    import dggs.spark as ds

    df = spark.createDataFrame([(1, 10.0, 0.0), (2, None, 0.0), (3, 95.0, 0.0)], "i long, lat double, lng double")
    got = df.select("i", ds.latlng_to_cell("lat", "lng", 9, on_invalid="null").alias("c")).orderBy("i").collect()
    assert [r.c for r in got] == [dggs.latlng_to_cell(10.0, 0.0, 9, as_int=True), None, None]
    with pytest.raises(dggs.CoordinateError, match=r"dggs_latlng_to_cell: row \d of the batch \(lat=95.0, lng=0.0, "
                                                   r"level=9\), partition \d"):
        with ds.spark_errors():
            df.select(ds.latlng_to_cell("lat", "lng", 9)).collect()
    with pytest.raises(dggs.InvalidCellError, match="dggs_cell_to_parent_str: .*'Q9'"), ds.spark_errors():
        spark.sql("SELECT dggs_cell_to_parent_str('Q9', 1)").collect()
    with pytest.raises(dggs.DggsValueError, match="on_invalid"):
        ds.cell_area("c", on_invalid="skip")
    assert spark.sql("SELECT dggs_cell_area(CAST(NULL AS BIGINT)) AS a").first().a is None


@pytestmark_spark
def test_spark_workers_compile_nothing(spark):
    """The workers answer from the compiled core: no numba (or any JIT) is loaded in them."""
    def probe(_):
        import sys

        import dggs

        return dggs.latlng_to_cell(1.0, 2.0, 5), sorted(m for m in ("numba", "llvmlite") if m in sys.modules)

    seen = spark.sparkContext.parallelize(range(2), 2).map(probe).collect()
    import dggs

    assert seen == [(dggs.latlng_to_cell(1.0, 2.0, 5), [])] * 2


@pytestmark_spark
def test_spark_parquet_job_bins_rolls_up_and_writes(spark, tmp_path):
    """A folder of Parquet points: binned, rolled up (equal to a brute-force count of id prefixes), written as
    GeoParquet by parent and read back by dggs.dask and DuckDB."""
    import dggs.spark as ds

    lat, lng = _points(6000, seed=11)
    value = np.random.default_rng(2).exponential(3.0, lat.size)
    src = tmp_path / "points"
    src.mkdir()
    for k, rows in enumerate(np.array_split(np.arange(lat.size), 3)):
        pq.write_table(pa.table({"lat": lat[rows], "lng": lng[rows], "value": value[rows]}), src / f"p{k}.parquet")
    binned = spark.read.parquet(str(src)).select(ds.latlng_to_cell_str("lat", "lng", 10).alias("cell"), "value")
    rolled = ds.rollup(binned, 2, values=["value"], stats=["sum", "max"]).toPandas().set_index("cell")
    strings = dggs.int_to_str(np.asarray(dggs.latlng_to_cell(lat, lng, 10, as_int=True), np.uint64))
    counts = collections.Counter(s[:3] for s in strings)  # a level-2 parent is the id's first 3 characters
    assert rolled["count"].to_dict() == dict(counts)
    sums = collections.defaultdict(float)
    for s, v in zip(strings, value, strict=True):
        sums[s[:3]] += v
    assert rolled["value_sum"].to_dict() == pytest.approx(dict(sums), rel=1e-12)

    out = tmp_path / "geo"
    assert ds.write_geoparquet(binned, str(out), level=1) == lat.size
    parents = {p.name for p in out.glob("face=*/parent=*")}
    assert parents == {f"parent={s[:2]}" for s in strings}
    import duckdb

    from dggs.dask import read_parquet

    back = read_parquet(str(out)).compute()
    assert sorted(back["cell"]) == sorted(strings)
    assert (back["parent"].astype(str) == back["cell"].str.slice(0, 2)).all()
    one_face = read_parquet(str(out), faces=["A"]).compute()
    assert sorted(one_face["cell"]) == sorted(s for s in strings if s[0] == "A")
    ((n, geo),) = duckdb.sql(f"SELECT count(*), count(geometry) FROM read_parquet('{out}/**/*.parquet', "
                             "hive_partitioning = true)").fetchall()
    assert n == geo == lat.size
    assert "geo" in {k.decode() for k in pq.read_schema(next(out.rglob("*.parquet"))).metadata}


@pytestmark_spark
def test_spark_example_runs(tmp_path):
    proc = subprocess.run([sys.executable, str(ROOT / "examples" / "spark_job.py"), "--points", "20000", "--out",
                           str(tmp_path / "out")], capture_output=True, text=True, timeout=600, cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr[-3000:]
    assert "rolled up" in proc.stdout and "wrote" in proc.stdout


def test_function_table_is_complete():
    """Every SQL function the issue lists is registered, with a Spark return type."""
    wanted = {"dggs_latlng_to_cell", "dggs_cell_to_parent", "dggs_cell_to_children", "dggs_cell_to_latlng",
              "dggs_cell_to_boundary_wkb", "dggs_grid_disk", "dggs_polygon_to_cells", "dggs_cell_area",
              "dggs_str_to_int", "dggs_int_to_str"}
    assert wanted <= set(FUNCTIONS)
    assert {spec[1] for spec in FUNCTIONS.values()} <= {"bigint", "string", "array<bigint>", "binary", "double",
                                                        "int", "boolean", "struct<lat:double,lng:double>"}
    assert examples(100) >= 5


# ------------------------------------------------------------------ corrupt columns (issue 32 item 9), no JVM

from dggs.spark.udfs import ColumnTypeError  # noqa: E402

_CORRUPT = {
    "strings": pa.array(["n/a", "C401", "", "1e400"]),
    "numbers": pa.array([1.5, float("nan"), -1.0, 1e300]),
    "ints": pa.array([0, -1, 2**62, 5]),
    "lists": pa.array([["C401"], [], ["Z9"], ["C402", "C401"]]),
    "binary": pa.array([b"\x00\x01", b"C401", b"", b"\xff"]),
    "nulls": pa.nulls(4, pa.string()),
}


def test_string_coordinates_with_junk_are_bad_values_of_their_rows():
    lat, lng, level = pa.array(["51.05", "n/a", "10"]), pa.array(["-114.07", "0", "x"]), pa.array([9, 9, 9])
    fn = batch_function("dggs_latlng_to_cell_str", "null")
    assert fn(lat, lng, level).to_pylist() == [dggs.latlng_to_cell(51.05, -114.07, 9), None, None]
    with pytest.raises(dggs.CoordinateError, match="row 1 .*'n/a'"):
        batch_function("dggs_latlng_to_cell_str")(lat, lng, level)


def test_is_valid_cell_never_raises_on_any_column():
    for name, col in _CORRUPT.items():
        got = batch_function("dggs_is_valid_cell")(col).to_pylist()
        assert len(got) == len(col), name
        assert all(v in (True, False, None) for v in got), name
    assert batch_function("dggs_is_valid_cell")(_CORRUPT["lists"]).to_pylist() == [False] * 4


def test_cells_to_polygons_wkb_on_a_plain_id_column_is_a_typed_error():
    for on_invalid in ("raise", "null"):
        with pytest.raises(ColumnTypeError, match="array of cell ids"):
            batch_function("dggs_cells_to_polygons_wkb", on_invalid)(pa.array(["C401", "C402"]))


@pytest.mark.parametrize("name", sorted(FUNCTIONS))
@pytest.mark.parametrize("column", sorted(_CORRUPT))
def test_every_function_takes_corrupt_columns_with_typed_errors(name, column):
    """Any column in any argument: an answer (NULL for bad values with on_invalid='null') or a DggsValueError."""
    arity = len(FUNCTIONS[name][0].strip("()").split(","))
    good = {"cell": pa.array(["C401"] * 4), "a": pa.array(["C401"] * 4), "b": pa.array(["C402"] * 4),
            "lat": pa.array([1.0] * 4), "lng": pa.array([2.0] * 4), "level": pa.array([5] * 4), "k": pa.array([1] * 4),
            "cells": pa.array([["C401"]] * 4), "mode": pa.array(["center"] * 4),
            "wkb": pa.array([shapely.box(0, 0, 1, 1).wkb] * 4)}
    names = [n.strip() for n in FUNCTIONS[name][0].strip("()").split(",")]
    for i in range(arity):
        args = [good[n] for n in names]
        args[i] = _CORRUPT[column]
        for on_invalid in ("raise", "null"):
            try:
                out = batch_function(name, on_invalid)(*args)
            except dggs.DggsValueError:
                continue
            assert len(out) == 4
