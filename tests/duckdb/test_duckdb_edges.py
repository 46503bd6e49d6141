"""DuckDB's child position, local (i, j) and directed edge functions: row by row equal to the Python API, NULL-safe."""

from __future__ import annotations

import numpy as np
import pytest

duckdb = pytest.importorskip("duckdb")
pa = pytest.importorskip("pyarrow")

import dggs  # noqa: E402
from dggs.duckdb import register  # noqa: E402
from dggs.duckdb.edges import EDGE_FUNCTIONS  # noqa: E402

from ..strategies import special_points  # noqa: E402


@pytest.fixture(scope="module")
def con():
    c = register(duckdb.connect())
    yield c
    c.close()


def _cells(level: int, n: int = 300) -> np.ndarray:
    rng = np.random.default_rng(level)
    lat = np.concatenate([rng.uniform(-90, 90, n), [p[0] for p in special_points()]])
    lng = np.concatenate([rng.uniform(-180, 180, n), [p[1] for p in special_points()]])
    return dggs.latlng_to_cell(lat, lng, level, as_int=True)


def _bits(x) -> list:
    """Ids as uint64 values: a BIGINT column holds an edge's bits as a negative number."""
    a = np.asarray(x)
    return (a.view(np.uint64) if a.dtype == np.int64 else a).tolist()


def _table(con, **cols):
    con.register("t", pa.table(cols))


def test_every_function_and_overload_is_registered(con):
    names = {r[0] for r in con.sql("SELECT DISTINCT function_name FROM duckdb_functions()").fetchall()}
    for name in EDGE_FUNCTIONS:
        assert name in names and {f"{name}_i64", f"{name}_u64", f"{name}_str"} <= names


@pytest.mark.parametrize("level", [0, 1, 9, 27])
@pytest.mark.parametrize("kind", ["i64", "u64", "str"])
def test_edges_equal_python(con, level, kind):
    ids = _cells(level)
    col = {"i64": ids.view(np.int64), "u64": ids, "str": dggs.int_to_str(ids)}[kind]
    _table(con, c=col)
    edges = con.sql("SELECT dggs_origin_to_directed_edges(c) AS e FROM t").fetchnumpy()["e"]
    want = dggs.origin_to_directed_edges(col)
    assert [_bits(list(r)) for r in edges] == [_bits(list(r)) for r in want]
    flat = np.asarray(want).reshape(-1)
    if kind == "i64":  # as a BIGINT column holds them
        flat = flat.view(np.int64)
    _table(con, e=flat)
    got = con.sql("""SELECT dggs_get_directed_edge_origin(e) AS o, dggs_get_directed_edge_destination(e) AS d,
                            dggs_reverse_directed_edge(e) AS r, dggs_is_valid_directed_edge(e) AS v,
                            dggs_edge_length(e, 'km') AS km, dggs_directed_edge_to_cells(e) AS cells FROM t""").fetchnumpy()
    assert got["o"].tolist() == np.asarray(dggs.get_directed_edge_origin(flat)).tolist()
    assert got["d"].tolist() == np.asarray(dggs.get_directed_edge_destination(flat)).tolist()
    assert _bits(got["r"]) == _bits(dggs.reverse_directed_edge(flat))
    assert got["v"].all()
    np.testing.assert_allclose(got["km"], dggs.edge_length(flat, unit="km"), rtol=1e-12)
    assert [list(x) for x in got["cells"]] == np.asarray(dggs.directed_edge_to_cells(flat)).tolist()
    _table(con, a=np.repeat(col, 3), b=np.asarray(dggs.get_directed_edge_destination(flat)))
    pairs = con.sql("SELECT dggs_cells_to_directed_edge(a, b) AS e FROM t").fetchnumpy()["e"]
    assert _bits(pairs) == _bits(flat)


@pytest.mark.parametrize("level", [1, 12, 28])
@pytest.mark.parametrize("kind", ["i64", "str"])
def test_child_pos_and_local_ij_equal_python(con, level, kind):
    ids = _cells(level, 100)
    col = ids.view(np.int64) if kind == "i64" else dggs.int_to_str(ids)
    parent_level = level // 2
    parents = dggs.cell_to_parent(col, parent_level)
    _table(con, c=col, p=parents, lv=np.full(ids.size, parent_level))
    got = con.sql("SELECT dggs_cell_to_child_pos(c, lv) AS pos FROM t").fetchnumpy()["pos"]
    assert got.tolist() == np.asarray(dggs.cell_to_child_pos(col, parent_level)).tolist()
    _table(con, pos=got, p=parents)
    back = con.sql(f"SELECT dggs_child_pos_to_cell(pos, p, {level}) AS c FROM t").fetchnumpy()["c"]
    assert back.tolist() == np.asarray(col).tolist()
    # the first edge neighbour local (i, j) answers for (docs/grid.md, "Local coordinates": one sector and its mirror)
    rows = [[n for n in ns if not isinstance(_local_or_error(c, n), Exception)] for c, ns in zip(col, dggs.edge_neighbors(col), strict=True)]
    near = np.asarray([r[0] for r in rows], dtype=np.asarray(col).dtype)
    _table(con, a=col, b=near)
    ij = con.sql("SELECT dggs_cell_to_local_ij(a, b) AS ij FROM t").fetchall()
    i, j = dggs.cell_to_local_ij(col, near)
    assert [(r[0]["i"], r[0]["j"]) for r in ij] == list(zip(np.asarray(i).tolist(), np.asarray(j).tolist(), strict=True))
    _table(con, a=col, i=np.asarray(i), j=np.asarray(j))
    cells = con.sql("SELECT dggs_local_ij_to_cell(a, i, j) AS c FROM t").fetchnumpy()["c"]
    assert cells.tolist() == np.asarray(near).tolist()


def _local_or_error(anchor, cell):
    try:
        return dggs.cell_to_local_ij(anchor, cell)
    except dggs.DistortionError as exc:
        return exc


def test_local_ij_refuses_across_the_bend(con):
    """A pair local (i, j) refuses (across a line from a face's centre to a vertex) is an error naming both cells in
    SQL, as in Python; the pairs it answers agree."""
    with pytest.raises(dggs.DistortionError, match="K210121"):
        dggs.cell_to_local_ij("K110121", "K210121")
    with pytest.raises(duckdb.Error, match="K210121.*K110121"):
        con.sql("SELECT dggs_cell_to_local_ij('K110121', 'K210121')").fetchall()
    with pytest.raises(duckdb.Error, match="names no cell"):
        con.sql("SELECT dggs_local_ij_to_cell('K110121', 11, 11)").fetchall()
    row = con.sql("SELECT dggs_cell_to_local_ij('K110121', 'K110021'), dggs_local_ij_to_cell('K110121', 3, 6)").fetchall()[0]
    assert row == ({"i": 3, "j": 6}, "K110021")


def test_nulls_and_errors(con):
    row = con.sql("""SELECT dggs_reverse_directed_edge(NULL::VARCHAR), dggs_edge_length('C401.1', NULL),
                            dggs_cell_to_child_pos('C401', NULL), dggs_child_pos_to_cell(NULL, 'C4', 3),
                            dggs_cell_to_local_ij('C401', NULL::VARCHAR), dggs_local_ij_to_cell('C401', 0, NULL),
                            dggs_is_valid_directed_edge(NULL::VARCHAR), dggs_origin_to_directed_edges(NULL::BIGINT)""").fetchall()[0]
    assert row == (None,) * 8
    assert con.sql("SELECT dggs_is_valid_directed_edge(x) FROM (VALUES ('C401'), ('C401.2'), ('junk')) t(x)").fetchall() == [
        (False,), (True,), (False,)]
    for sql, message in [
        ("SELECT dggs_reverse_directed_edge('C401')", "dggs_reverse_directed_edge: 'C401' is not a valid directed edge"),
        ("SELECT dggs_cells_to_directed_edge('C401', 'C401')", "not edge neighbours"),
        ("SELECT dggs_child_pos_to_cell(3, 'C4', 2)", "out of range 0..2"),
        ("SELECT dggs_local_ij_to_cell('C401', 1, 0)", "names no cell"),
        ("SELECT dggs_edge_length('C401.1', 'miles')", "unit 'miles'"),
    ]:
        with pytest.raises(duckdb.InvalidInputException, match=message):
            con.sql(sql).fetchall()
