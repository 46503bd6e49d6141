"""The native DuckDB extension (libdggs/duckdb/) in the real DuckDB CLI, row by row against the Python API.

Each test starts pip's ``duckdb`` CLI (the ``duckdb-cli`` package) with ``-unsigned``, LOADs the extension
built by ``make duckdb-extension`` (built here if missing or older than its sources) and compares what SQL
answers with what ``dggs`` answers for the same inputs: random points and ids at every level, and the edge
cases (the poles, the antimeridian, levels 0 and 28, NULL, invalid ids and coordinates). The SQL files of
``duckdb_sql/`` (a subset of sqllogictest: ``statement ok|error`` and ``query`` blocks) run the same way.
"""

from __future__ import annotations

import csv
import json
import os
import shutil
import subprocess
import sys
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import dggs

ROOT = Path(__file__).resolve().parents[2]
EXT = ROOT / "build" / "duckdb" / "dggs.duckdb_extension"
SQL_DIR = Path(__file__).resolve().parent / "duckdb_sql"
CLI = Path(os.environ.get("DGGS_DUCKDB_CLI", "") or sys.executable).with_name("duckdb")
if os.environ.get("DGGS_DUCKDB_CLI"):  # a CLI binary, e.g. duckdb_cli/duckdb of pip's package, for a sanitizer run
    CLI = Path(os.environ["DGGS_DUCKDB_CLI"])
if not CLI.is_file():
    CLI = Path(shutil.which("duckdb") or CLI)
# Set for the CLI processes only: LD_PRELOAD of libasan with an extension built by build.py --sanitize.
CLI_ENV = {**os.environ, "LD_PRELOAD": os.environ.get("DGGS_DUCKDB_CLI_PRELOAD", ""),
           "ASAN_OPTIONS": "detect_leaks=0"} if os.environ.get("DGGS_DUCKDB_CLI_PRELOAD") else None  # fmt: skip

pytestmark = pytest.mark.skipif(not CLI.is_file(), reason="no duckdb CLI (pip install duckdb-cli)")


def _sources() -> list[Path]:
    return [*ROOT.glob("libdggs/duckdb/*.[ch]"), *ROOT.glob("libdggs/src/*.[ch]"), ROOT / "libdggs/include/dggs.h",
            ROOT / "libdggs/duckdb/build.py"]  # fmt: skip


@pytest.fixture(scope="module")
def ext() -> Path:
    if os.environ.get("DGGS_DUCKDB_EXTENSION"):  # a given build (a sanitizer build): used as it is
        return Path(os.environ["DGGS_DUCKDB_EXTENSION"]).resolve()
    stale = not EXT.is_file() or EXT.stat().st_mtime < max(p.stat().st_mtime for p in _sources())
    if stale:
        if shutil.which("cc") is None:
            pytest.skip("no C compiler to build the extension")
        subprocess.run([sys.executable, str(ROOT / "libdggs/duckdb/build.py"), "--out", str(EXT)], check=True)
    return EXT


def run(ext: Path, sql: str, db: Path | None = None, mode: str = "-json", load: bool = True) -> subprocess.CompletedProcess:
    prefix = f"LOAD '{ext}'; " if load else ""
    args = [str(CLI), "-unsigned", mode, *(["-noheader", "-separator", "\t", "-nullvalue", "NULL"] if mode == "-list" else [])]
    return subprocess.run([*args, *([str(db)] if db else []), "-c", prefix + sql], capture_output=True, text=True,
                          timeout=600, env=CLI_ENV)  # fmt: skip


def rows(ext: Path, sql: str, db: Path | None = None) -> list[dict[str, Any]]:
    """The rows of the last statement of ``sql`` as dicts (DuckDB's JSON output mode)."""
    proc = run(ext, sql, db)
    assert proc.returncode == 0, proc.stderr + proc.stdout
    out: list[dict[str, Any]] = []
    text, at, decoder = proc.stdout, 0, json.JSONDecoder()
    while text[at:].strip():  # one JSON array per statement with results; the last one's
        at += len(text[at:]) - len(text[at:].lstrip())
        out, at = decoder.raw_decode(text, at)
    return out


def table(path: Path, columns: dict[str, np.ndarray]) -> str:
    """Write ``columns`` to a CSV file; the SQL that reads it back typed, with a row number ``i``."""
    names = list(columns)
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["i", *names])
        for i, values in enumerate(zip(*(columns[n] for n in names), strict=True)):
            w.writerow([i, *(repr(float(v)) if isinstance(v, float | np.floating) else v for v in values)])
    types = {"i": "BIGINT", **{n: "DOUBLE" if columns[n].dtype.kind == "f" else "UBIGINT" if columns[n].dtype.kind == "u"
                               else "BIGINT" for n in names}}  # fmt: skip
    spec = ", ".join(f"'{k}': '{v}'" for k, v in types.items())
    return f"read_csv('{path}', header=true, columns={{{spec}}})"


# ---------------------------------------------------------------------------------------------- points to ids

EDGE_POINTS = [(90.0, 0.0), (-90.0, 0.0), (90.0, 180.0), (-90.0, -180.0), (0.0, 180.0), (0.0, -180.0),
               (45.0, 179.9999999), (-45.0, -179.9999999), (0.0, 0.0), (89.9999, 45.0), (-89.9999, -135.0),
               (10.0, 540.0), (-10.0, -359.5), (26.56505117707799, 36.0), (-26.56505117707799, 0.0)]  # fmt: skip


def _points(n: int, seed: int) -> tuple[np.ndarray, np.ndarray]:
    rng = np.random.default_rng(seed)
    lat = np.degrees(np.arcsin(rng.uniform(-1, 1, n)))
    lng = rng.uniform(-180, 180, n)
    edge = np.array(EDGE_POINTS)
    return np.concatenate([lat, edge[:, 0]]), np.concatenate([lng, edge[:, 1]])


@pytest.mark.parametrize("level", [0, 1, 7, 17, 28])
def test_latlng_to_cell_row_by_row(ext: Path, tmp_path: Path, level: int) -> None:
    lat, lng = _points(2000, level)
    src = table(tmp_path / "p.csv", {"lat": lat, "lng": lng})
    got = rows(ext, f"SELECT dggs_latlng_to_cell(lat, lng, {level}) AS c, dggs_latlng_to_cell_str(lat, lng, {level}) AS s, "
                    f"dggs_latlng_to_cell_ubigint(lat, lng, {level}) AS u FROM {src} ORDER BY i")  # fmt: skip
    want = np.asarray(dggs.latlng_to_cell(lat, lng, level, as_int=True), np.uint64)
    assert [int(r["c"]) for r in got] == want.tolist()
    assert [int(r["u"]) for r in got] == want.tolist()
    assert [r["s"] for r in got] == list(dggs.latlng_to_cell(lat, lng, level))


# ---------------------------------------------------------------------------------------------- one id per row


def _ids(seed: int = 7) -> np.ndarray:
    """Cells at every level 0..28: random points, the edge points, the 20 faces."""
    lat, lng = _points(60, seed)
    out = [np.asarray(dggs.latlng_to_cell(lat, lng, lv, as_int=True), np.uint64) for lv in range(29)]
    faces = np.asarray(dggs.str_to_int([chr(ord("A") + f) for f in range(20)]), np.uint64)
    return np.unique(np.concatenate([*out, faces]))


@pytest.mark.parametrize("kind", ["BIGINT", "UBIGINT", "VARCHAR"])
def test_cell_functions_row_by_row(ext: Path, tmp_path: Path, kind: str) -> None:
    ids = _ids()
    levels = np.asarray(dggs.get_level(ids), np.int64)
    src = table(tmp_path / "c.csv", {"u": ids})
    cell = {"BIGINT": "u::BIGINT", "UBIGINT": "u", "VARCHAR": "dggs_int_to_str(u)"}[kind]
    got = rows(ext, f"""
        SELECT dggs_get_level(c) AS level, dggs_is_valid_cell(c) AS ok, dggs_int_to_str(c) AS s, dggs_str_to_int(c) AS n,
               dggs_cell_to_parent(c, dggs_get_level(c) // 2) AS parent,
               dggs_cell_to_center_child(c, least(dggs_get_level(c) + 2, 28)) AS centre_child,
               dggs_cell_to_latlng_lat(c) AS lat, dggs_cell_to_latlng_lng(c) AS lng, dggs_cell_to_latlng(c) AS ll,
               dggs_cell_area(c) AS area, dggs_cell_to_boundary(c) AS corners,
               dggs_cell_to_child_pos(c, dggs_get_level(c) // 2) AS pos,
               dggs_child_pos_to_cell(dggs_cell_to_child_pos(c, dggs_get_level(c) // 2),
                                      dggs_cell_to_parent(c, dggs_get_level(c) // 2), dggs_get_level(c)) AS back,
               dggs_grid_disk(c, 1) AS disk, dggs_grid_ring(c, 2) AS ring, dggs_get_face(c) AS face,
               dggs_edge_neighbors(c) AS nbrs, dggs_are_neighbor_cells(c, (dggs_edge_neighbors(c))[2]) AS nb,
               dggs_are_neighbor_cells(c, c) AS self, dggs_cell_area(c, 'km^2') AS km2, dggs_cell_area(c, 'rads^2') AS sr
        FROM (SELECT i, {cell} AS c FROM {src}) ORDER BY i""")
    strings = list(dggs.int_to_str(ids))

    def form(values: Any) -> list[Any]:
        values = np.asarray(values, np.uint64)
        return list(dggs.int_to_str(values)) if kind == "VARCHAR" else [int(v) for v in values]

    def got_ids_row(values: list[Any]) -> list[Any]:
        return [v if kind == "VARCHAR" else int(v) for v in values]

    def got_ids(col: str) -> list[Any]:
        return [r[col] if kind == "VARCHAR" else int(r[col]) for r in got]

    assert [r["level"] for r in got] == levels.tolist()
    assert all(r["ok"] is True for r in got)
    assert [r["s"] for r in got] == strings
    assert [int(r["n"]) for r in got] == ids.tolist()
    parents = np.array([dggs.cell_to_parent(int(c), int(lv) // 2) for c, lv in zip(ids, levels, strict=True)], np.uint64)
    assert got_ids("parent") == form(parents)
    centre = np.array([dggs.cell_to_center_child(int(c), min(int(lv) + 2, 28)) for c, lv in zip(ids, levels, strict=True)])
    assert got_ids("centre_child") == form(centre.astype(np.uint64))
    lat, lng = dggs.cell_to_latlng(ids)
    assert [r["lat"] for r in got] == np.asarray(lat).tolist()  # the same doubles: one C core
    assert [r["lng"] for r in got] == np.asarray(lng).tolist()
    assert [(r["ll"]["lat"], r["ll"]["lng"]) for r in got] == list(zip(np.asarray(lat).tolist(), np.asarray(lng).tolist(), strict=True))
    assert [r["area"] for r in got] == np.asarray(dggs.cell_area(ids)).tolist()
    assert [r["km2"] for r in got] == np.asarray(dggs.cell_area(ids, "km^2")).tolist()
    assert [r["sr"] for r in got] == np.asarray(dggs.cell_area(ids, "rads^2")).tolist()
    corners = np.asarray(dggs.cell_to_boundary(ids), np.float64)
    assert [[(p["lat"], p["lng"]) for p in r["corners"]] for r in got] == [[tuple(p) for p in c] for c in corners.tolist()]
    pos = [dggs.cell_to_child_pos(int(c), int(lv) // 2) for c, lv in zip(ids, levels, strict=True)]
    assert [r["pos"] for r in got] == pos
    assert got_ids("back") == form(ids)
    assert [r["face"] for r in got] == np.asarray(dggs.get_face(ids)).tolist()
    assert [got_ids_row(r["nbrs"]) for r in got] == [form(n) for n in np.asarray(dggs.edge_neighbors(ids), np.uint64)]
    assert all(r["nb"] is True and r["self"] is False for r in got)
    for r, c in zip(got, ids, strict=True):
        disk = np.sort(np.asarray(dggs.grid_disk(int(c), 1), np.uint64).ravel())
        ring = np.sort(np.asarray(dggs.grid_ring(int(c), 2), np.uint64).ravel())
        want_disk, want_ring = form(disk[disk != 0]), form(ring[ring != 0])
        assert [v if kind == "VARCHAR" else int(v) for v in r["disk"]] == want_disk
        assert [v if kind == "VARCHAR" else int(v) for v in r["ring"]] == want_ring


def test_level_table(ext: Path) -> None:
    got = rows(ext, "SELECT lv, dggs_get_num_cells(lv) AS n, dggs_level_area(lv, 'm^2') AS m2, dggs_level_area(lv, 'km^2') AS km2, "
                    "dggs_level_area(lv, 'rads^2') AS sr FROM range(29) t(lv) ORDER BY lv")  # fmt: skip
    levels = list(range(29))
    assert [r["n"] for r in got] == [int(dggs.get_num_cells(lv)) for lv in levels]
    for col, unit in (("m2", "m^2"), ("km2", "km^2"), ("sr", "rads^2")):
        assert [r[col] for r in got] == [float(dggs.cell_area(lv, unit)) for lv in levels]
    base = rows(ext, "SELECT dggs_get_base_cells() AS a, dggs_get_base_cells_str() AS s")[0]
    assert [int(v) for v in base["a"]] == np.asarray(dggs.get_base_cells(as_int=True)).tolist()
    assert base["s"] == list(dggs.get_base_cells())
    proc = run(ext, "SELECT dggs_level_area(3, 'acres')")
    assert proc.returncode != 0 and "unit 'acres' is not one of" in proc.stderr + proc.stdout


def test_children_distances_paths_compaction(ext: Path, tmp_path: Path) -> None:
    ids = _ids(11)
    ids = ids[np.asarray(dggs.get_level(ids)) <= 26]
    levels = np.asarray(dggs.get_level(ids), np.int64)
    src = table(tmp_path / "c.csv", {"u": ids})
    got = rows(ext, f"""
        SELECT dggs_cell_to_children(u, least(dggs_get_level(u) + 2, 28)) AS kids,
               dggs_compact_cells(dggs_cell_to_children(u, least(dggs_get_level(u) + 2, 28))) AS compact,
               dggs_uncompact_cells([u], least(dggs_get_level(u) + 1, 28)) AS uncompact,
               dggs_grid_distance(u, (dggs_grid_ring(u, 3))[1]) AS d3,
               dggs_grid_path_cells(u, (dggs_grid_ring(u, 3))[1]) AS path
        FROM {src} ORDER BY i""")
    for r, c, lv in zip(got, ids, levels, strict=True):
        kids = np.asarray(dggs.cell_to_children(int(c), min(int(lv) + 2, 28)), np.uint64).ravel()
        assert [int(v) for v in r["kids"]] == kids.tolist()
        assert [int(v) for v in r["compact"]] == [int(c)]
        assert [int(v) for v in r["uncompact"]] == np.asarray(dggs.uncompact_cells([int(c)], min(int(lv) + 1, 28)), np.uint64).tolist()
        far = int(r["path"][-1])
        assert r["d3"] == dggs.grid_distance(int(c), far) == 3 or lv == 0
        assert [int(v) for v in r["path"]] == np.asarray(dggs.grid_path_cells(int(c), far), np.uint64).tolist()


def test_edges_and_local_ij(ext: Path) -> None:
    got = rows(ext, """
        SELECT dggs_cells_to_directed_edge('C401', 'C402') AS e, dggs_origin_to_directed_edges('C401') AS es,
               dggs_directed_edge_to_cells('C401.1') AS cells, dggs_reverse_directed_edge('C401.1') AS back,
               dggs_get_directed_edge_origin('C401.1') AS o, dggs_get_directed_edge_destination('C401.1') AS d,
               dggs_is_valid_directed_edge('C401.1') AS ok, dggs_is_valid_directed_edge('C401') AS not_edge,
               dggs_edge_length('C401.1', 'km') AS km, dggs_directed_edge_to_boundary('C401.1') AS ends,
               dggs_cell_to_local_ij('C401', 'C402') AS ij, dggs_local_ij_to_cell('C401', 4, 2) AS at,
               dggs_cells_to_directed_edge(dggs_str_to_int('C401'), dggs_str_to_int('C402')) AS e_int""")[0]
    assert got["e"] == "C401.1" and got["es"] == list(dggs.origin_to_directed_edges("C401"))
    assert got["cells"] == list(dggs.directed_edge_to_cells("C401.1"))
    assert got["back"] == dggs.reverse_directed_edge("C401.1")
    assert (got["o"], got["d"]) == (dggs.get_directed_edge_origin("C401.1"), dggs.get_directed_edge_destination("C401.1"))
    assert got["ok"] is True and got["not_edge"] is False
    assert got["km"] == dggs.edge_length("C401.1", unit="km")
    ends = np.asarray(dggs.directed_edge_to_boundary("C401.1"), np.float64)
    assert [(p["lat"], p["lng"]) for p in got["ends"]] == [tuple(p) for p in ends.tolist()]
    assert (got["ij"]["i"], got["ij"]["j"]) == tuple(int(v) for v in dggs.cell_to_local_ij("C401", "C402"))
    assert got["at"] == "C402"
    assert int(got["e_int"]) + (1 << 64) == int(dggs.cells_to_directed_edge(dggs.str_to_int("C401"), dggs.str_to_int("C402")))


def test_local_ij_across_the_bend_is_null(ext: Path) -> None:
    """The C core refuses K210121 around K110121 (across a line from the face's centre to a vertex, as Python's
    DistortionError): NULL, as the extension answers every pair the core refuses; the pair it keeps agrees."""
    got = rows(ext, """
        SELECT dggs_cell_to_local_ij('K110121', 'K210121') AS bend, dggs_cell_to_local_ij('K110121', 'K110021') AS ij,
               dggs_local_ij_to_cell('K110121', 11, 11) AS gone, dggs_local_ij_to_cell('K110121', 3, 6) AS at""")[0]
    assert got["bend"] is None and got["gone"] is None and got["at"] == "K110021"
    assert (got["ij"]["i"], got["ij"]["j"]) == dggs.cell_to_local_ij("K110121", "K110021") == (3, 6)


# ---------------------------------------------------------------------------------------------- NULL, invalid, WKT/WKB


def test_null_and_invalid_give_null_as_h3(ext: Path) -> None:
    got = rows(ext, """
        SELECT dggs_get_level(NULL::VARCHAR) AS a, dggs_get_level('X9') AS b, dggs_get_level(-5) AS c,
               dggs_is_valid_cell('X9') AS d, dggs_is_valid_cell(NULL::BIGINT) AS e, dggs_latlng_to_cell(100, 0, 5) AS f,
               dggs_latlng_to_cell(0, 0, 29) AS g, dggs_latlng_to_cell('nan'::DOUBLE, 0, 5) AS h,
               dggs_cell_to_parent('C4', 3) AS i, dggs_cell_to_parent('C401', NULL) AS j, dggs_grid_disk('C401', -1) AS k,
               dggs_grid_distance('C401', 'C4') AS l, dggs_compact_cells(['C401', 'nope']) AS m,
               dggs_compact_cells(['C401', NULL]) AS n, dggs_cell_to_lat(0::UBIGINT) AS o,
               dggs_latlng_to_cell(0, 'inf'::DOUBLE, 5) AS p, dggs_cell_to_children('C401', 2) AS q,
               dggs_local_ij_to_cell('C401', 1, 1) AS r""")[0]
    assert got == {**dict.fromkeys("abcfghijklmopqr"), "d": False, "e": None, "n": ["C401"]}


def test_bad_argument_is_an_error_naming_it(ext: Path) -> None:
    proc = run(ext, "SELECT dggs_edge_length('C401.1', 'miles')")
    assert proc.returncode != 0 and "dggs_edge_length: unit 'miles' is not one of" in proc.stderr + proc.stdout
    proc = run(ext, "SELECT dggs_cell_to_boundary_wkt('C401', 5000)")
    assert proc.returncode != 0 and "densify 5000 is out of range" in proc.stderr + proc.stdout


def test_boundary_wkt_and_wkb(ext: Path) -> None:
    shapely = pytest.importorskip("shapely")
    got = rows(ext, "SELECT dggs_cell_to_boundary_wkt('C401', 0) AS wkt, hex(dggs_cell_to_boundary_wkb('C401', 0)) AS wkb, "
                    "dggs_cell_to_boundary_wkt('C401', 3) AS dense")[0]  # fmt: skip
    ring = np.asarray(dggs.cell_to_boundary("C401"), np.float64)
    shape = shapely.from_wkt(got["wkt"])
    assert np.asarray(shape.exterior.coords).tolist() == [[lng, lat] for lat, lng in [*ring.tolist(), ring[0].tolist()]]
    assert shapely.from_wkb(bytes.fromhex(got["wkb"])).equals_exact(shape, 0)
    dense = np.asarray(dggs.cell_to_boundary("C401", densify=3), np.float64)
    assert len(shapely.from_wkt(got["dense"]).exterior.coords) == len(dense) + 1


# ---------------------------------------------------------------------------------------------- where users are


def test_persisted_view_after_reopen_and_load(ext: Path, tmp_path: Path) -> None:
    db = tmp_path / "cells.duckdb"
    setup = ("CREATE TABLE pts AS SELECT * FROM (VALUES (51.05, -114.07), (-33.9, 18.4)) t(lat, lng); "
             "CREATE VIEW binned AS SELECT dggs_latlng_to_cell_str(lat, lng, 9) AS cell, "
             "dggs_cell_to_parent(dggs_latlng_to_cell_str(lat, lng, 9), 3) AS parent FROM pts")  # fmt: skip
    assert run(ext, setup, db).returncode == 0
    without = run(ext, "SELECT * FROM binned", db, load=False)
    assert without.returncode != 0 and "dggs_latlng_to_cell_str" in without.stderr + without.stdout
    got = rows(ext, "SELECT * FROM binned", db)
    want = dggs.latlng_to_cell([51.05, -33.9], [-114.07, 18.4], 9)
    assert [r["cell"] for r in got] == list(want)
    assert [r["parent"] for r in got] == list(dggs.cell_to_parent(want, 3))


def test_python_load(ext: Path) -> None:
    duckdb = pytest.importorskip("duckdb")
    import dggs.duckdb

    con = duckdb.connect(config={"allow_unsigned_extensions": "true"})
    assert dggs.duckdb.load(con, ext) is True
    assert con.sql("SELECT dggs_latlng_to_cell_str(51.05, -114.07, 9)").fetchall() == [("F200021102",)]
    with pytest.raises(RuntimeError, match="allow_unsigned_extensions"):
        dggs.duckdb.load(duckdb.connect(), ext)


# ---------------------------------------------------------------------------------------------- the SQL files


def _blocks(text: str) -> list[tuple[str, str, list[str]]]:
    """(kind, sql, expected lines) of each block: 'statement ok', 'statement error' (expected: a message part),
    or 'query ...' followed by the SQL, '----' and the rows, tab-separated."""
    out = []
    for chunk in text.split("\n\n"):
        lines = [ln for ln in chunk.strip().splitlines() if not ln.startswith("#")]
        if not lines:
            continue
        head, body = lines[0], lines[1:]
        sep = body.index("----") if "----" in body else len(body)
        out.append((head.split()[0] + (" error" if head == "statement error" else ""), "\n".join(body[:sep]), body[sep + 1:]))
    return out


@pytest.mark.parametrize("path", sorted(SQL_DIR.glob("*.test")), ids=lambda p: p.stem)
def test_sql_file(ext: Path, path: Path) -> None:
    done: list[str] = []  # statements so far, run again before each block (one CLI process a block)
    for kind, sql, expected in _blocks(path.read_text()):
        proc = run(ext, "; ".join([*done, sql]), mode="-list")
        if kind == "statement error":
            assert proc.returncode != 0 and all(e in proc.stderr + proc.stdout for e in expected), (sql, proc.stderr)
            continue
        assert proc.returncode == 0, (sql, proc.stderr)
        if kind == "statement":
            done.append(sql)
        else:
            assert proc.stdout.splitlines() == expected, sql


# ---------------------------------------------------------------------------------------------- polygon fill


def _shapes() -> list[Any]:
    shapely = pytest.importorskip("shapely")
    box = shapely.box(-10, -10, 10, 10)
    holed = shapely.Polygon([(30, 40), (45, 40), (45, 52), (30, 52)], [[(35, 44), (40, 44), (40, 48), (35, 48)]])
    multi = shapely.MultiPolygon([shapely.box(170, -5, 180, 5), shapely.box(-180, -5, -170, 5)])
    polar = shapely.Polygon([(-180, 80), (-60, 75), (60, 78), (180, 80), (180, 90), (-180, 90)])
    thin = shapely.Polygon([(100.1, -33.3), (101.7, -33.1), (100.4, -31.9)])
    return [box, holed, multi, polar, thin]


@pytest.mark.parametrize("mode", ["center", "contains", "overlaps", "overlapping_bbox"])
def test_polygon_fill_wkb_and_wkt_row_by_row(ext: Path, mode: str) -> None:
    shapely = pytest.importorskip("shapely")
    shapes, levels = _shapes(), [5, 7, 6, 4, 9]
    values = ", ".join(f"({i}, from_hex('{shapely.to_wkb(s).hex()}'), '{shapely.to_wkt(s, rounding_precision=-1)}', {lv})"
                       for i, (s, lv) in enumerate(zip(shapes, levels, strict=True)))  # fmt: skip
    got = rows(ext, f"""SELECT dggs_polygon_to_cells(wkb, lv, '{mode}') AS a, dggs_polygon_wkt_to_cells(wkt, lv, '{mode}') AS b,
                            dggs_polygon_to_cells_str(wkb, lv, '{mode}') AS s
                        FROM (VALUES {values}) t(i, wkb, wkt, lv) ORDER BY i""")  # fmt: skip
    for r, shape, lv in zip(got, shapes, levels, strict=True):
        want = np.asarray(dggs.polygon_to_cells(shape, lv, mode=mode, as_int=True), np.uint64)
        assert [int(v) for v in r["a"]] == np.sort(want).tolist()
        assert r["b"] == r["a"] and r["s"] == list(dggs.int_to_str(np.sort(want)))


def test_polygon_fill_errors_and_nulls(ext: Path) -> None:
    got = rows(ext, "SELECT dggs_polygon_wkt_to_cells('POLYGON ((0 0, 1 0, 1 1, 0 0))', 29, 'center') AS a, "
                    "dggs_polygon_wkt_to_cells(NULL, 5, 'center') AS b, dggs_polygon_wkt_to_cells('POLYGON EMPTY', 5, 'center') AS c")[0]  # fmt: skip
    assert got == {"a": None, "b": None, "c": []}
    for sql, part in [("dggs_polygon_wkt_to_cells('POLYGON ((1 2, 3', 6, 'center')", "not a WKT (Multi)Polygon"),
                      ("dggs_polygon_to_cells('\\x01\\x02'::BLOB, 6, 'center')", "not a WKB (Multi)Polygon"),
                      ("dggs_polygon_wkt_to_cells('POLYGON ((0 0, 1 0, 1 1, 0 0))', 6, 'inside')", "mode 'inside' is not one of"),
                      ("dggs_polygon_wkt_to_cells('POLYGON ((170 0, 190 0, 190 5, 170 0))', 6, 'center')", "-180..180")]:  # fmt: skip
        proc = run(ext, f"SELECT {sql}")
        assert proc.returncode != 0 and part in proc.stderr + proc.stdout, sql


def test_docs_sql_blocks_run_in_the_cli(ext: Path) -> None:
    """docs/duckdb.md's ``sql`` blocks, each in its own CLI process from the repository root (their LOAD path)."""
    import re
    import textwrap

    text = (ROOT / "docs" / "duckdb.md").read_text()
    blocks = [textwrap.dedent(m.group(2)) for m in re.finditer(r"^( *)```sql\n(.*?)^\1```", text, re.M | re.S)]
    assert len(blocks) >= 2
    for sql in blocks:
        proc = subprocess.run([str(CLI), "-unsigned", "-c", sql], capture_output=True, text=True, cwd=ROOT, timeout=300,
                              env=CLI_ENV)  # fmt: skip
        assert proc.returncode == 0 and "Error" not in proc.stdout + proc.stderr, (sql, proc.stderr)


# ---------------------------------------------------------------------------------------------- adversarial values

BAD_IDS = ["0", "1", "-1", "-9223372036854775808", "9223372036854775807", "4996743786567565311", "4996743786567565313"]
BAD_STRINGS = ["''", "'C'", "'c401'", "'Z0'", "'C9'", "'C4013'", "'C' || repeat('0', 40)", "'C401\\0'", "'C401.9'",
               "'C401.'", "'.1'", "' C401'", "'ééé'"]  # fmt: skip
BAD_INTS = ["-1", "0", "29", "9223372036854775807", "-9223372036854775808", "3"]
CALLS = [  # (expression over i (an id of any kind), n, m (integers) and x, y (doubles)) for every function
    "dggs_latlng_to_cell(x, y, n)", "dggs_latlng_to_cell_str(x, y, n)", "dggs_latlng_to_cell_ubigint(x, y, n)",
    "dggs_cell_to_latlng(i)", "dggs_cell_to_lat(i)", "dggs_cell_to_lng(i)", "dggs_cell_to_boundary(i)",
    "dggs_cell_to_boundary_wkt(i)", "dggs_cell_to_boundary_wkb(i)", "dggs_cell_area(i)", "dggs_get_level(i)",
    "dggs_is_valid_cell(i)", "dggs_str_to_int(i)", "dggs_int_to_str(i)", "dggs_cell_to_parent(i, n)",
    "dggs_cell_to_center_child(i, n)", "dggs_cell_to_child_pos(i, n)", "dggs_child_pos_to_cell(m, i, n)",
    "dggs_grid_ring(i, least(n, 3))", "dggs_grid_distance(i, i)", "dggs_grid_path_cells(i, i)",
    "dggs_compact_cells([i, i])", "dggs_uncompact_cells([i], n)", "dggs_cell_to_local_ij(i, i)",
    "dggs_local_ij_to_cell(i, m, n)", "dggs_get_directed_edge_origin(i)", "dggs_get_directed_edge_destination(i)",
    "dggs_reverse_directed_edge(i)", "dggs_is_valid_directed_edge(i)", "dggs_directed_edge_to_cells(i)",
    "dggs_directed_edge_to_boundary(i)", "dggs_cells_to_directed_edge(i, i)", "dggs_origin_to_directed_edges(i)",
    "dggs_edge_length(i, 'm')", "dggs_grid_disk(i, least(n, 3))", "dggs_cell_to_children(i, least(n, 6))",
    "dggs_get_face(i)", "dggs_edge_neighbors(i)", "dggs_are_neighbor_cells(i, i)", "dggs_get_num_cells(n)",
    "dggs_level_area(n, 'm^2')", "dggs_cell_area(i, 'km^2')", "dggs_latlng_to_cell(x, y, n, 'IVEA')",
    "dggs_cell_to_latlng(i, 'IVEA')", "dggs_cell_to_boundary_wkb(i, least(n, 5), 'IVEA')",
    "dggs_polygon_to_cells(dggs_cell_to_boundary_wkb(i), least(n, 7), 'overlaps')",
    "dggs_polygon_wkt_to_cells_str(dggs_cell_to_boundary_wkt(i), least(n, 7), 'center', 'IVEA')",
    "dggs_polygon_wkt_to_cells('POLYGON ((0 0, 1 0, 1 1, 0 0))', least(n, 8), 'inside')",
    "dggs_cell_to_boundary_wkt(i, n)", "dggs_cell_to_boundary_wkb(i, n, 'IVEA')", "dggs_cell_to_boundary_geometry(i, n)",
    "dggs_polygon_to_cells(dggs_cell_to_boundary_geometry(i), least(n, 7), 'contains')",
    "dggs_cell_to_vertexes(i)", "dggs_vertex_to_latlng(i::VARCHAR || ':' || n::VARCHAR)",
    "dggs_is_valid_vertex(i::VARCHAR || ':' || n::VARCHAR)", "dggs_vertex_to_latlng(i::VARCHAR || ':1', 'IVEA')",
]  # fmt: skip


@pytest.mark.parametrize("kind", ["BIGINT", "UBIGINT", "VARCHAR"])
def test_adversarial_values_never_crash(ext: Path, kind: str) -> None:
    """Bad ids, levels, positions and coordinates through every function: each row NULL or a right value, or the
    query refused with an error naming the function (a densify out of range); never a crash."""
    ids = BAD_STRINGS + ["'C401'", "'C401.1'", "NULL"] if kind == "VARCHAR" else BAD_IDS + ["4996743786567565312", "NULL"]
    if kind == "UBIGINT":
        ids = [v for v in ids if not v.startswith("-")] + ["18446744073709551615", "14220678773375762432"]
    ints = ", ".join(f"({v})" for v in [*BAD_INTS, "NULL"])
    nums = ", ".join(f"({v})" for v in ["'nan'::DOUBLE", "'inf'::DOUBLE", "-1e308", "90.0000001", "0.0", "NULL"])
    source = (f"(SELECT i::{kind} AS i, n, n AS m, x, x AS y FROM (VALUES {', '.join(f'({v})' for v in ids)}) a(i), "
              f"(VALUES {ints}) b(n), (VALUES {nums}) c(x))")  # fmt: skip
    for call in CALLS:
        proc = run(ext, f"SELECT count(*), count({call}) FROM {source}")
        name = call.split("(")[0]
        clean_error = proc.returncode == 1 and proc.stderr.startswith(f"Invalid Input Error: {name}: ")  # a choice refused
        assert proc.returncode == 0 or clean_error, (call, proc.returncode, proc.stderr)
        assert "INTERNAL" not in proc.stdout + proc.stderr, call


def test_random_values_validity_as_python(ext: Path, tmp_path: Path) -> None:
    """Random 64-bit values and mutated ids: dggs_is_valid_cell and dggs_get_level as dggs's, row by row."""
    rng = np.random.default_rng(3)
    ids = _ids(5)
    flips = ids ^ (np.uint64(1) << rng.integers(0, 64, ids.size).astype(np.uint64))
    values = np.concatenate([rng.integers(0, 2**64 - 1, 2000, dtype=np.uint64, endpoint=True), flips, ids])
    src = table(tmp_path / "v.csv", {"u": values})
    got = rows(ext, f"SELECT dggs_is_valid_cell(u) AS ok, dggs_get_level(u) AS lv, dggs_is_valid_directed_edge(u) AS e "
                    f"FROM {src} ORDER BY i")  # fmt: skip
    ok = np.asarray(dggs.is_valid_cell(values), bool)
    assert [r["ok"] for r in got] == ok.tolist()
    assert [r["lv"] for r in got] == [int(dggs.get_level(int(v))) if k else None for v, k in zip(values, ok, strict=True)]
    assert [r["e"] for r in got] == np.asarray(dggs.is_valid_directed_edge(values), bool).tolist()


def test_parallel_threads_give_the_same_ids(ext: Path, tmp_path: Path) -> None:
    """DuckDB runs the functions on its own threads (a Parquet-like scan split across 2): the same ids as numpy."""
    lat, lng = _points(300_000, 21)
    src = table(tmp_path / "p.csv", {"lat": lat, "lng": lng})
    got = rows(ext, f"SET threads = 2; CREATE TABLE p AS SELECT * FROM {src}; "
                    "SELECT sum(c::HUGEINT)::VARCHAR AS s, bit_xor(c) AS x, count(c) AS n, "
                    "sum(dggs_get_level(dggs_cell_to_parent(c, 9))) AS lv "
                    "FROM (SELECT dggs_latlng_to_cell_ubigint(lat, lng, 20) AS c FROM p)")[0]  # fmt: skip
    want = np.asarray(dggs.latlng_to_cell(lat, lng, 20, as_int=True), np.uint64)
    assert int(got["s"]) == sum(int(v) for v in want)
    assert int(got["x"]) == int(np.bitwise_xor.reduce(want))
    assert got["n"] == want.size and int(got["lv"]) == 9 * want.size


def test_strings_validity_as_python(ext: Path) -> None:
    strings = ["", "C", "c401", "Z0", "C9", "C4013", "C" + "0" * 40, "C401.9", " C401", "C401 ", "ééé", "C401.1",
               "T5" + "2" * 27, "T5" + "2" * 28, "A0", "B20", "C401.3", "C.1", "C4.0"]  # fmt: skip
    literal = ", ".join(f"('{x}')" for x in strings)
    got = rows(ext, f"SELECT s, dggs_is_valid_cell(s) AS ok, dggs_is_valid_directed_edge(s) AS e FROM (VALUES {literal}) t(s)")
    assert [r["s"] for r in got] == strings
    assert [r["ok"] for r in got] == [bool(dggs.is_valid_cell(x)) for x in strings]
    assert [r["e"] for r in got] == [bool(dggs.is_valid_directed_edge(x)) for x in strings]


def test_ivea_projection_as_grid_ivea(ext: Path, tmp_path: Path) -> None:
    """The optional projection argument: 'IVEA' gives dggs.Grid("IVEA")'s ids, centres, boundaries and fill."""
    shapely = pytest.importorskip("shapely")
    grid = dggs.Grid("IVEA")
    lat, lng = _points(1500, 4)
    src = table(tmp_path / "p.csv", {"lat": lat, "lng": lng})
    got = rows(ext, f"SELECT dggs_latlng_to_cell(lat, lng, 12, 'IVEA') AS c, dggs_latlng_to_cell_str(lat, lng, 12, 'ivea') AS s, "
                    f"dggs_cell_to_latlng(dggs_latlng_to_cell(lat, lng, 12, 'IVEA'), 'IVEA') AS ll, "
                    f"dggs_cell_to_boundary(dggs_latlng_to_cell(lat, lng, 12, 'IVEA'), 0, 'IVEA') AS b, "
                    f"dggs_latlng_to_cell(lat, lng, 12, 'ISEA') = dggs_latlng_to_cell(lat, lng, 12) AS same FROM {src} ORDER BY i")  # fmt: skip
    ids = np.asarray(grid.latlng_to_cell(lat, lng, 12, as_int=True), np.uint64)
    assert [int(r["c"]) for r in got] == ids.tolist() and [r["s"] for r in got] == list(dggs.int_to_str(ids))
    clat, clng = grid.cell_to_latlng(ids)
    assert [(r["ll"]["lat"], r["ll"]["lng"]) for r in got] == list(zip(np.asarray(clat).tolist(), np.asarray(clng).tolist(), strict=True))
    corners = np.asarray(grid.cell_to_boundary(ids), np.float64)
    assert [[(p["lat"], p["lng"]) for p in r["b"]] for r in got] == [[tuple(p) for p in c] for c in corners.tolist()]
    assert all(r["same"] for r in got)
    box = shapely.box(-10, -10, 10, 10)
    fill = rows(ext, f"SELECT dggs_polygon_wkt_to_cells('{box.wkt}', 6, 'center', 'IVEA') AS f")[0]["f"]
    assert [int(v) for v in fill] == np.sort(np.asarray(grid.polygon_to_cells(box, 6, as_int=True), np.uint64)).tolist()
    proc = run(ext, "SELECT dggs_latlng_to_cell(0, 0, 5, 'healpix')")
    assert proc.returncode != 0 and "projection 'healpix' is not 'ISEA' or 'IVEA'" in proc.stderr + proc.stdout


def test_polygon_fill_as_rows(ext: Path) -> None:
    """The table functions of the same names: one row a cell, as the list, in id order."""
    shapely = pytest.importorskip("shapely")
    for shape, level in zip(_shapes(), [5, 7, 6, 4, 9], strict=True):
        wkt, wkb = shapely.to_wkt(shape, rounding_precision=-1), shapely.to_wkb(shape).hex()
        got = rows(ext, f"""SELECT (SELECT list(cell) FROM dggs_polygon_wkt_to_cells('{wkt}', {level}, 'overlaps')) AS a,
                                   (SELECT list(cell) FROM dggs_polygon_to_cells_str(from_hex('{wkb}'), {level}, 'overlaps')) AS s,
                                   (SELECT list(cell) FROM dggs_polygon_wkt_to_cells('{wkt}', {level}, 'center', projection := 'IVEA')) AS v""")[0]  # fmt: skip
        want = np.sort(np.asarray(dggs.polygon_to_cells(shape, level, mode="overlaps", as_int=True), np.uint64))
        assert [int(c) for c in got["a"]] == want.tolist() and got["s"] == list(dggs.int_to_str(want))
        ivea = np.sort(np.asarray(dggs.Grid("IVEA").polygon_to_cells(shape, level, as_int=True), np.uint64))
        assert [int(c) for c in got["v"] or []] == ivea.tolist()
    assert rows(ext, "SELECT count(*) AS n FROM dggs_polygon_wkt_to_cells(NULL, 5, 'center')")[0]["n"] == 0
    proc = run(ext, "SELECT * FROM dggs_polygon_wkt_to_cells('POLYGON ((0 0, 1 0, 1 1, 0 0))', 5, 'center', projection := 'x')")
    assert proc.returncode != 0 and "projection 'x' is not 'ISEA' or 'IVEA'" in proc.stderr


def test_mangled_wkb_and_wkt_never_crash(ext: Path) -> None:
    """Truncated, bit-flipped and random WKB, and cut or garbled WKT, through both parsers: each row a list or a
    clean error (caught by DuckDB's try()), never a crash."""
    shapely = pytest.importorskip("shapely")
    rng = np.random.default_rng(9)
    blobs, texts = [], []
    for shape in _shapes():
        wkb, wkt = bytearray(shapely.to_wkb(shape)), shapely.to_wkt(shape, rounding_precision=6)
        for _ in range(40):
            b = bytearray(wkb)
            cut = int(rng.integers(0, len(b) + 1))
            if rng.random() < 0.5:
                b = b[:cut]
            for _ in range(int(rng.integers(0, 4))):
                if b:
                    b[int(rng.integers(0, len(b)))] = int(rng.integers(0, 256))
            blobs.append(bytes(b))
            t = list(wkt[: int(rng.integers(0, len(wkt) + 1))] if rng.random() < 0.5 else wkt)
            for _ in range(int(rng.integers(0, 4))):
                if t:
                    t[int(rng.integers(0, len(t)))] = "(),. 0-9eE"[int(rng.integers(0, 10))]
            texts.append("".join(t))
    blobs += [rng.bytes(int(n)) for n in rng.integers(0, 64, 50)]
    values = ", ".join(f"(from_hex('{b.hex()}'), '{t}')" for b, t in zip(blobs, texts + [""] * 50, strict=True))
    proc = run(ext, f"SELECT count(*) AS n, count(try(dggs_polygon_to_cells(b, 4, 'overlaps'))) AS a, "
                    f"count(try(dggs_polygon_wkt_to_cells(t, 4, 'center'))) AS c FROM (VALUES {values}) v(b, t)")  # fmt: skip
    assert proc.returncode == 0, proc.stderr
    assert "INTERNAL" not in proc.stdout + proc.stderr


def _shape_ids() -> np.ndarray:
    """Every cell of levels 0..3, the cells at and round the poles and across the antimeridian at levels 8 and
    28, and the random and edge cells of every level (:func:`_ids`)."""
    faces = [chr(ord("A") + f) for f in range(20)]
    every = [np.asarray(dggs.str_to_int(np.asarray(dggs.cell_to_children(f, lv)).ravel().tolist()), np.uint64)
             for f in faces for lv in range(4)]  # fmt: skip
    pts = np.array([(90.0, 0.0), (-90.0, 0.0), (89.99999, 100.0), (-89.99999, -80.0), (0.0, 180.0), (30.0, -180.0),
                    (-60.0, 179.999999999), (75.0, 180.0)])  # fmt: skip
    edge = []
    for level in (8, 28):
        cells = np.asarray(dggs.latlng_to_cell(pts[:, 0], pts[:, 1], level, as_int=True), np.uint64)
        disk = np.asarray(dggs.grid_disk(cells, 2), np.uint64).ravel()
        edge.append(disk[disk != 0])
    return np.unique(np.concatenate([*every, *edge, _ids(11)]))


def _assert_same_polygons(got: list[dict[str, Any]], ids: np.ndarray, want: np.ndarray) -> int:
    """Each row's WKB and WKT are ``want``'s polygon: ordinary cells byte for byte (shapely's WKB), split or
    pole cells part by part within 1e-11 degrees; the number of MultiPolygons compared that way."""
    shapely = pytest.importorskip("shapely")
    assert len(got) == len(want) == ids.size
    multi = 0
    for r, c, w in zip(got, ids, want, strict=True):
        blob = bytes.fromhex(r["wkb"])
        g, t = shapely.from_wkb(blob), shapely.from_wkt(r["wkt"])
        name = dggs.int_to_str(int(c))
        assert g.geom_type == w.geom_type, name
        assert shapely.equals_exact(t, g, tolerance=0), name  # the WKT's %.17g round-trips the doubles
        if blob == shapely.to_wkb(w, byte_order=1):
            continue
        multi += w.geom_type == "MultiPolygon"
        parts_g, parts_w = list(getattr(g, "geoms", [g])), list(getattr(w, "geoms", [w]))
        assert len(parts_g) == len(parts_w), name
        for a, b in zip(parts_g, parts_w, strict=True):
            assert len(a.exterior.coords) == len(b.exterior.coords), name
            assert a.exterior.is_ccw, name
            assert shapely.hausdorff_distance(a, b) < 1e-11, name
            assert abs(a.area - b.area) <= 1e-12 * max(b.area, 1e-300), name
    return multi


@pytest.mark.parametrize(("densify", "projection"), [(0, "ISEA"), (1, "ISEA"), (5, "ISEA"), (1, "IVEA")])
def test_boundary_wkb_and_wkt_as_cell_to_polygon_row_by_row(ext: Path, tmp_path: Path, densify: int, projection: str) -> None:
    """dggs_cell_to_boundary_wkb/_wkt(c, d) give dggs.cell_to_polygon(c, densify=d): split at +-180, closed
    along the poles, counter-clockwise; ordinary cells byte for byte (shapely's WKB of the Python polygon)."""
    ids = _shape_ids()
    src = table(tmp_path / "c.csv", {"u": ids})
    got = rows(ext, f"SELECT hex(dggs_cell_to_boundary_wkb(u, {densify}, '{projection}')) AS wkb, "
                    f"dggs_cell_to_boundary_wkt(dggs_int_to_str(u), {densify}, '{projection}') AS wkt "
                    f"FROM {src} ORDER BY i")  # fmt: skip
    want = dggs.Grid(projection).cell_to_polygon(ids, densify=densify)
    assert _assert_same_polygons(got, ids, want) > 0  # the split cells were compared (the others byte for byte)


def _default_shape_ids(projection: str) -> np.ndarray:
    """Every cell of levels 0..3, and at levels 8, 15 and 28 the cells round the poles, on the antimeridian and
    round the 12 icosahedron vertices (the corners of the level-0 cells), with their neighbours."""
    grid = dggs.Grid(projection)
    faces = [chr(ord("A") + f) for f in range(20)]
    every = [np.asarray(dggs.str_to_int(np.asarray(dggs.cell_to_children(f, lv)).ravel().tolist()), np.uint64)
             for f in faces for lv in range(4)]  # fmt: skip
    corners = np.asarray(grid.cell_to_boundary(faces), np.float64).reshape(-1, 2)
    pts = np.concatenate([corners, [(90.0, 0.0), (-90.0, 0.0), (89.99999, 100.0), (-89.99999, -80.0), (0.0, 180.0),
                                    (30.0, -180.0), (-60.0, 179.999999999), (75.0, 180.0), (-45.0, 180.0)]])  # fmt: skip
    near = []
    for level in (8, 15, 28):
        cells = np.asarray(grid.latlng_to_cell(pts[:, 0], pts[:, 1], level, as_int=True), np.uint64)
        disk = np.asarray(dggs.grid_disk(cells, 1), np.uint64).ravel()
        near.append(disk[disk != 0])
    return np.unique(np.concatenate([*every, *near]))


@pytest.mark.parametrize("projection", ["ISEA", "IVEA"])
def test_boundary_default_is_cell_to_polygon_default_row_by_row(ext: Path, tmp_path: Path, projection: str) -> None:
    """Without a densify, dggs_cell_to_boundary_wkb/_wkt/_geometry(c) (ISEA) and (c, projection) draw
    dggs.cell_to_polygon(c)'s default polygon: the same points per edge for each cell (area-exact to 1e-6),
    the same split at +-180 and closing along a pole."""
    ids = _default_shape_ids(projection)
    src = table(tmp_path / "c.csv", {"u": ids})
    want = dggs.Grid(projection).cell_to_polygon(ids)
    forms = ["(u)", "(dggs_int_to_str(u))", "(u::BIGINT)"] if projection == "ISEA" else []
    forms += [f"(u, '{projection}')", f"(dggs_int_to_str(u), '{projection}')"]
    for form in forms:
        got = rows(ext, f"SELECT hex(dggs_cell_to_boundary_wkb{form}) AS wkb, dggs_cell_to_boundary_wkt{form} AS wkt, "
                        f"hex(ST_AsWKB(dggs_cell_to_boundary_geometry{form})) AS g FROM {src} ORDER BY i")  # fmt: skip
        assert all(r["g"] == r["wkb"] for r in got), form
        assert _assert_same_polygons(got, ids, want) > 0, form
    some = rows(ext, f"SELECT dggs_cell_to_boundary_wkb('C401', NULL::VARCHAR) AS a, dggs_cell_to_boundary_wkb(NULL::BIGINT, "
                     f"'{projection}') AS b, dggs_cell_to_boundary_wkt('nope', '{projection}') AS c")[0]  # fmt: skip
    assert some == {"a": None, "b": None, "c": None}


def test_geometry_in_and_out_as_wkb(ext: Path) -> None:
    """DuckDB's GEOMETRY (core from 1.5, the spatial extension's before): polygon fill takes it as it takes its WKB,
    and dggs_cell_to_boundary_geometry is dggs_cell_to_boundary_wkb's polygon (ST_AsWKB gives the same bytes)."""
    poly = "POLYGON((170 -10, -170 -10, -170 10, 170 10, 170 -10))"
    got = rows(ext, f"""
        SELECT dggs_polygon_to_cells('{poly}'::GEOMETRY, 5, 'overlaps') = dggs_polygon_to_cells(ST_AsWKB('{poly}'::GEOMETRY), 5, 'overlaps') AS same_fill,
               len(dggs_polygon_to_cells_str('{poly}'::GEOMETRY, 5, 'overlaps')) AS n,
               dggs_polygon_to_cells(NULL::GEOMETRY, 5, 'center') AS null_fill,
               hex(ST_AsWKB(dggs_cell_to_boundary_geometry('O321222221000', 2))) AS g,
               hex(dggs_cell_to_boundary_wkb('O321222221000', 2)) AS w,
               typeof(dggs_cell_to_boundary_geometry('O321222221000')) AS t,
               dggs_cell_to_boundary_geometry('nope') AS bad""")[0]  # fmt: skip
    assert got["same_fill"] is True and got["null_fill"] is None and got["bad"] is None
    shapely = pytest.importorskip("shapely")
    assert got["n"] == len(dggs.polygon_to_cells(shapely.from_wkt(poly), 5, mode="overlaps"))
    assert got["t"] == "GEOMETRY" and got["g"] == got["w"]


@pytest.mark.parametrize("kind", ["BIGINT", "VARCHAR"])
def test_vertices_row_by_row(ext: Path, tmp_path: Path, kind: str) -> None:
    """dggs_cell_to_vertexes / dggs_vertex_to_latlng / dggs_is_valid_vertex as dggs's, on every cell of levels 0-3
    (every icosahedron vertex among their corners), cells at the poles and across the antimeridian, all levels."""
    ids = _shape_ids()
    src = table(tmp_path / "c.csv", {"u": ids})
    cell = "u::BIGINT" if kind == "BIGINT" else "dggs_int_to_str(u)"
    got = rows(ext, f"SELECT dggs_cell_to_vertexes({cell}) AS v FROM {src} ORDER BY i")
    want = np.asarray(dggs.cell_to_vertexes(ids)).tolist()
    assert [r["v"] for r in got] == want
    names = sorted({v for row in want for v in row})
    bad = ["C401:0", "C401:3", "C401:", ":1", "C401:1x", "C401::1", "", "Z0:1", "C401 :1", "c401:1"]
    with open(tmp_path / "v.csv", "w", newline="") as f:
        csv.writer(f).writerows([["v"], *([v] for v in [*names, *bad]), ["NULL"]])
    got = rows(ext, f"SELECT v, dggs_vertex_to_latlng(v) AS ll, dggs_is_valid_vertex(v) AS ok, "
                    f"dggs_vertex_to_latlng(v, 'IVEA') AS ivea FROM read_csv('{tmp_path / 'v.csv'}', header=true, "
                    "columns={'v': 'VARCHAR'}, nullstr='NULL', quote='\"')")  # fmt: skip
    by = {r["v"]: r for r in got}
    lat, lng = dggs.vertex_to_latlng(names)
    ilat, ilng = dggs.Grid("IVEA").vertex_to_latlng(names)
    assert [(by[v]["ll"]["lat"], by[v]["ll"]["lng"]) for v in names] == list(zip(lat, lng, strict=True))
    assert [(by[v]["ivea"]["lat"], by[v]["ivea"]["lng"]) for v in names] == list(zip(ilat, ilng, strict=True))
    assert [by[v]["ok"] for v in [*names, *bad]] == list(dggs.is_valid_vertex([*names, *bad]))
    assert all(by[v]["ll"] is None for v in bad) and by[None]["ok"] is None and by[None]["ll"] is None


#: DuckDB's spatial extension comes from pip (``duckdb-extension-spatial``) for one DuckDB release only, with the
#: CLI of that release beside it; 1.5.5 is the latest such pair (docs/duckdb.md, "GEOMETRY").
SPATIAL_VERSION = "1.5.5"


@pytest.fixture(scope="module")
def spatial(ext: Path) -> tuple[Path, Path]:
    """(CLI, spatial extension file) of DuckDB SPATIAL_VERSION, installed by pip into build/duckdb-spatial/."""
    target = ROOT / "build" / "duckdb-spatial" / SPATIAL_VERSION
    cli, found = target / "duckdb_cli" / "duckdb", list(target.glob("duckdb_extension_spatial/extensions/*/spatial.duckdb_extension"))
    if not cli.is_file() or not found:
        proc = subprocess.run([sys.executable, "-m", "pip", "install", "--quiet", "--no-deps", "--target", str(target),
                               f"duckdb-cli=={SPATIAL_VERSION}", f"duckdb-extension-spatial=={SPATIAL_VERSION}"],
                              capture_output=True, text=True)  # fmt: skip
        assert proc.returncode == 0, proc.stderr
        found = list(target.glob("duckdb_extension_spatial/extensions/*/spatial.duckdb_extension"))
    cli.chmod(0o755)
    return cli, found[0]


def test_spatial_extension_reads_the_polygons(ext: Path, spatial: tuple[Path, Path]) -> None:
    """The spatial extension as the referee: every boundary polygon of the pole, antimeridian and level 0-3 cells
    is valid for GEOS (ST_IsValid) with the area shapely gives dggs.cell_to_polygon's, and the fill takes its
    GEOMETRY as the WKB of it."""
    shapely = pytest.importorskip("shapely")
    cli, spatial_ext = spatial
    ids = _shape_ids()[:4000]
    values = ", ".join(f"({int(c)})" for c in ids)
    sql = (f"LOAD '{spatial_ext}'; LOAD '{ext}'; SELECT ST_IsValid(g) AS ok, ST_Area(g) AS area FROM (SELECT i, "
           f"ST_GeomFromWKB(dggs_cell_to_boundary_wkb(u::UBIGINT, 1)) AS g FROM (SELECT row_number() OVER () AS i, u "
           f"FROM (VALUES {values}) t(u))) ORDER BY i")  # fmt: skip
    with open(ROOT / "build" / "duckdb-spatial" / "q.sql", "w") as f:
        f.write(sql)
    proc = subprocess.run([str(cli), "-unsigned", "-json", "-f", str(ROOT / "build" / "duckdb-spatial" / "q.sql")],
                          capture_output=True, text=True, timeout=600)  # fmt: skip
    assert proc.returncode == 0, proc.stderr
    got = json.loads(proc.stdout)
    want = shapely.area(dggs.cell_to_polygon(ids, densify=1))
    assert all(r["ok"] is True for r in got)
    assert np.allclose([r["area"] for r in got], want, rtol=1e-12, atol=0)
    poly = "POLYGON((170 -10, -170 -10, -170 10, -170 10, 170 10, 170 -10))"
    proc = subprocess.run([str(cli), "-unsigned", "-json", "-c", f"LOAD '{spatial_ext}'; LOAD '{ext}'; SELECT "
                           f"dggs_polygon_to_cells(ST_GeomFromText('{poly}'), 4, 'overlaps') = "
                           f"dggs_polygon_to_cells(ST_AsWKB(ST_GeomFromText('{poly}')), 4, 'overlaps') AS same"],
                          capture_output=True, text=True, timeout=600)  # fmt: skip
    assert proc.returncode == 0 and json.loads(proc.stdout) == [{"same": True}], proc.stderr
