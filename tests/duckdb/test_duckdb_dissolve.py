"""Dissolve in SQL: dggs_cells_to_multi_polygon_wkt / _wkb / _geometry in the DuckDB CLI, against dggs.cells_to_polygons.

Each set of cells is one row (a LIST of ids, UBIGINT and VARCHAR); the answer is compared with the Python
package's shapely polygons (the referee: same number of polygons, the same holes, symmetric difference of area
~0), and read by DuckDB's spatial extension (ST_IsValid, ST_Area). The sets: random ones at several levels,
dense random ones (cells touching at corners: pinched rings), rings with holes, sets across the antimeridian
and round each pole, mixed levels, the whole globe and the globe less a few cells, one cell, an empty list.
"""

from __future__ import annotations

import csv
import json
import subprocess
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import dggs

from .test_duckdb_extension import CLI, ext, rows, run, spatial  # noqa: F401  (fixtures)

pytestmark = pytest.mark.skipif(not CLI.is_file(), reason="no duckdb CLI (pip install duckdb-cli)")
shapely = pytest.importorskip("shapely")
from shapely.validation import explain_validity  # noqa: E402

#: Points where sets are centred: the poles, the antimeridian (both signs), an icosahedron vertex, plain places.
CENTRES = [(90.0, 0.0), (-90.0, 0.0), (0.0, 180.0), (10.0, -180.0), (89.9, 170.0), (-89.5, -179.9), (60.0, 180.0),
           (26.56505117707799, 36.0), (20.0, 30.0)]  # fmt: skip


def _sets() -> list[tuple[str, list[str]]]:
    """(name, string ids) of every kind of set the dissolve must draw."""
    rng = np.random.default_rng(33)
    out: list[tuple[str, list[str]]] = [("one", ["C4010"]), ("disk", list(dggs.grid_disk("C4010", 2)))]
    around = dggs.uncompact_cells(dggs.grid_disk_vertex("C4010", 1), 6)
    out.append(("frame", [c for c in around if not c.startswith("C4010")]))  # one hole
    out.append(("globe", list(dggs.get_base_cells())))
    all2 = list(dggs.uncompact_cells(dggs.get_base_cells(), 2))
    for lat, lng in CENTRES:
        c = dggs.latlng_to_cell(lat, lng, 5)
        out.append((f"disk@{lat},{lng}", list(dggs.grid_disk(c, 3))))
        ring = set(dggs.grid_ring(c, 2))
        out.append((f"annulus@{lat},{lng}", [x for x in dggs.grid_disk(c, 4) if x not in ring]))  # shells in holes
        gone = set(dggs.grid_disk(dggs.latlng_to_cell(lat, lng, 2), 1))
        out.append((f"globe-less@{lat},{lng}", [x for x in all2 if x not in gone]))  # a hole in the whole window
        mixed = list(dggs.compact_cells(dggs.grid_disk(c, 6)))
        finer = dggs.grid_disk(dggs.latlng_to_cell(lat - 3.0 if lat > 0 else lat + 3.0, lng, 7), 3)
        out.append((f"mixed@{lat},{lng}", mixed + list(finer)))
    for level in (1, 3, 4):
        for t in range(3):
            lat, lng = np.degrees(np.arcsin(rng.uniform(-1, 1, 40))), rng.uniform(-180, 180, 40)
            out.append((f"random{level}-{t}", sorted(set(dggs.latlng_to_cell(lat, lng, level)))))
    all3 = list(dggs.uncompact_cells(dggs.get_base_cells(), 3))
    for frac in (0.3, 0.5, 0.9):
        out.append((f"dense{frac}", [c for c in all3 if rng.random() < frac]))  # corners touched twice
    return out


SETS = _sets()


def _sets_table(path: Path, sets: list[tuple[str, list[str]]]) -> str:
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["i", "name", "ids"])
        for i, (name, ids) in enumerate(sets):
            w.writerow([i, name, " ".join(ids)])
    return (f"(SELECT i, name, string_split(ids, ' ') AS s, list_transform(string_split(ids, ' '), lambda x: "
            f"dggs_str_to_int(x)::UBIGINT) AS u FROM read_csv('{path}', header=true, "
            f"columns={{'i': 'BIGINT', 'name': 'VARCHAR', 'ids': 'VARCHAR'}}))")  # fmt: skip


def _same(got: Any, want: Any, name: str) -> None:
    """got (a MultiPolygon from SQL) is want (dggs.cells_to_polygons' Polygon or MultiPolygon)."""
    assert got.geom_type == "MultiPolygon", name
    parts_w = [] if want.is_empty else list(getattr(want, "geoms", [want]))
    parts_g = list(got.geoms)
    assert len(parts_g) == len(parts_w), name
    assert sorted(len(p.interiors) for p in parts_g) == sorted(len(p.interiors) for p in parts_w), name
    assert got.is_valid, (name, explain_validity(got))
    assert all(p.exterior.is_ccw and not any(h.is_ccw for h in p.interiors) for p in parts_g), name
    if parts_w:
        assert shapely.symmetric_difference(got, want).area <= 1e-9 * want.area, name
        assert abs(got.area - want.area) <= 1e-9 * want.area, name


def test_dissolve_row_by_row(ext: Path, tmp_path: Path) -> None:  # noqa: F811
    """Each set's WKT (VARCHAR ids) and WKB (UBIGINT ids) is dggs.cells_to_polygons' answer; the two agree."""
    src = _sets_table(tmp_path / "sets.csv", SETS)
    got = rows(ext, f"SELECT name, dggs_cells_to_multi_polygon_wkt(s) AS wkt, hex(dggs_cells_to_multi_polygon_wkb(u)) AS wkb, "
                    f"hex(ST_AsWKB(dggs_cells_to_multi_polygon_geometry(u::BIGINT[]))) AS g FROM {src} ORDER BY i")  # fmt: skip
    assert [r["name"] for r in got] == [n for n, _ in SETS]
    for r, (name, ids) in zip(got, SETS, strict=True):
        wkb = shapely.from_wkb(bytes.fromhex(r["wkb"]))
        assert shapely.equals_exact(shapely.from_wkt(r["wkt"]), wkb, tolerance=0), name  # %.17g round-trips
        assert r["g"] == r["wkb"], name
        _same(wkb, dggs.cells_to_polygons(ids), name)


@pytest.mark.parametrize(("densify", "projection"), [(0, "ISEA"), (3, "ISEA"), (2, "IVEA")])
def test_dissolve_densify_and_projection(ext: Path, tmp_path: Path, densify: int, projection: str) -> None:  # noqa: F811
    """(cells, densify [, projection]) and (cells, projection) as dggs.Grid(projection).cells_to_polygons."""
    sets = [s for s in SETS if s[0].startswith(("disk", "annulus", "globe-less@9", "frame", "mixed@-90"))]
    src = _sets_table(tmp_path / "sets.csv", sets)
    got = rows(ext, f"SELECT dggs_cells_to_multi_polygon_wkt(u, {densify}, '{projection}') AS a, "
                    f"dggs_cells_to_multi_polygon_wkt(s, '{projection}') AS b FROM {src} ORDER BY i")  # fmt: skip
    grid = dggs.Grid(projection)
    for r, (name, ids) in zip(got, sets, strict=True):
        _same(shapely.from_wkt(r["a"]), grid.cells_to_polygons(ids, densify=densify), name)
        _same(shapely.from_wkt(r["b"]), grid.cells_to_polygons(ids), name)


def test_dissolve_edge_cases(ext: Path) -> None:  # noqa: F811
    """Empty list: MULTIPOLYGON EMPTY; NULL list: NULL; NULL elements skipped; an invalid id: NULL (as
    dggs_compact_cells and the h3 extension's list functions); duplicates and covered cells merged."""
    got = rows(ext, """
        SELECT dggs_cells_to_multi_polygon_wkt([]::VARCHAR[]) AS empty, dggs_cells_to_multi_polygon_wkt(NULL::VARCHAR[]) AS null_list,
               dggs_cells_to_multi_polygon_wkt(['C401', NULL]) = dggs_cells_to_multi_polygon_wkt(['C401']) AS null_elem,
               dggs_cells_to_multi_polygon_wkt(['C401', 'nope']) AS bad, dggs_cells_to_multi_polygon_wkb([0::UBIGINT]) AS bad_int,
               dggs_cells_to_multi_polygon_wkt(['C401', 'C4010', 'C401', 'C40']) = dggs_cells_to_multi_polygon_wkt(['C40']) AS merged,
               dggs_cells_to_multi_polygon_wkt(['C401'], NULL) AS null_densify,
               hex(dggs_cells_to_multi_polygon_wkb([]::UBIGINT[])) AS empty_wkb""")[0]  # fmt: skip
    assert got == {"empty": "MULTIPOLYGON EMPTY", "null_list": None, "null_elem": True, "bad": None, "bad_int": None,
                   "merged": True, "null_densify": None, "empty_wkb": "010600000000000000"}  # fmt: skip
    proc = run(ext, "SELECT dggs_cells_to_multi_polygon_wkt(['C401'], 5000)")
    assert proc.returncode != 0 and "densify 5000 is out of range" in proc.stderr
    proc = run(ext, "SELECT dggs_cells_to_multi_polygon_wkt(['C401'], 'NOPE')")
    assert proc.returncode != 0 and "projection 'NOPE'" in proc.stderr
    # two level-0 cells beside a level-28 one: 2 x 28.7 million boundary descendants, refused before any is drawn
    proc = run(ext, "SELECT dggs_cells_to_multi_polygon_wkt(['A', 'B', 'C3212222210000222221002222222'])")
    assert proc.returncode != 0 and "50000000" in proc.stderr


def test_spatial_extension_reads_the_dissolve(ext: Path, spatial: tuple[Path, Path], tmp_path: Path) -> None:  # noqa: F811
    """DuckDB's spatial extension as referee: every dissolved set is valid for GEOS, with the area of the
    Python package's polygons."""
    cli, spatial_ext = spatial
    src = _sets_table(tmp_path / "sets.csv", SETS)
    sql = (f"LOAD '{spatial_ext}'; LOAD '{ext}'; SELECT ST_IsValid(g) AS ok, ST_Area(g) AS area FROM (SELECT i, "
           f"ST_GeomFromWKB(dggs_cells_to_multi_polygon_wkb(u)) AS g FROM {src}) ORDER BY i")  # fmt: skip
    proc = subprocess.run([str(cli), "-unsigned", "-json", "-c", sql], capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr
    got = json.loads(proc.stdout)
    assert [r["ok"] for r in got] == [True] * len(SETS)
    want = [dggs.cells_to_polygons(ids).area for _, ids in SETS]
    assert np.allclose([r["area"] for r in got], want, rtol=1e-9, atol=0)
