"""Polygons for export against H3: time a cell (ours by tolerance vs h3ronpy WKB + shapely.from_wkb) and file bytes.

    python benchmarks/bench_polygons.py [n]

Cases interleaved (ours, H3's, ours, ...), best of 3 CPU times on one core; GeoParquet (zstd) and GeoJSON bytes of
~n level-10 cells and of H3 res-6 cells (similar size) over the same points; load average and commit printed.
Then the default (10 m) polygons in parts, interleaved with H3's, best of 5: where the time of a cell goes.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import tempfile
import time

import numpy as np


def cpu(f):
    best = float("inf")
    for _ in range(3):
        t = time.process_time()
        f()
        best = min(best, time.process_time() - t)
    return best


def main(n: int = 40_000) -> None:
    os.environ.setdefault("DGGS_THREADS", "1")
    import pyarrow as pa
    import pyarrow.parquet as pq
    import shapely
    from h3ronpy import cells_to_string
    from h3ronpy.vector import cells_to_wkb_polygons, coordinates_to_cells

    import dggs
    from dggs.arrow import cells_to_table

    rng = np.random.default_rng(0)
    lat = np.degrees(np.arcsin(rng.uniform(-1, 1, n * 3)))
    lng = rng.uniform(-180, 180, n * 3)
    ours = np.unique(np.asarray(dggs.latlng_to_cell(lat, lng, 10, as_int=True), dtype=np.uint64))[:n]
    theirs = np.unique(np.asarray(coordinates_to_cells(lat, lng, 6)))[:n]
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True, text=True).stdout.strip()
    print("### bench_polygons.py: polygons for export against H3 (issue 35 item 2)\n")
    print(f"Commit {commit}, load average {os.getloadavg()}, {ours.size} level-10 cells against {theirs.size} H3 res-6 "
          "cells; best of 3 CPU times on one thread, cases interleaved; ratio = H3's time a cell / ours (>= 1x: ours "
          "at least as fast).\n")
    h3_time = cpu(lambda: shapely.from_wkb(pa.array(cells_to_wkb_polygons(pa.array(theirs))).to_numpy(zero_copy_only=False)))
    for tol in (10.0, 1.0, "exact"):
        t = cpu(lambda tol=tol: dggs.cell_to_polygon(ours, tolerance=tol))
        h3_time = min(h3_time, cpu(lambda: shapely.from_wkb(pa.array(cells_to_wkb_polygons(pa.array(theirs))).to_numpy(zero_copy_only=False))))
        coords = np.mean([len(p.exterior.coords) for p in dggs.cell_to_polygon(ours[:5000], tolerance=tol) if p.geom_type == "Polygon"])
        print(f"- cell_to_polygon tolerance={tol!r}: {1e6 * t / ours.size:.2f} us a cell, {coords:.1f} coordinates a ring; "
              f"h3ronpy WKB + from_wkb {1e6 * h3_time / theirs.size:.2f} us a cell; ratio (H3 / ours) {h3_time / theirs.size / (t / ours.size):.2f}x")
    with tempfile.TemporaryDirectory() as tmp:
        hpoly = shapely.from_wkb(pa.array(cells_to_wkb_polygons(pa.array(theirs))).to_numpy(zero_copy_only=False))
        names = cells_to_string(pa.array(theirs)).to_pylist()
        h3_table = pa.table({"cell": names, "geometry": shapely.to_wkb(hpoly)})
        pq.write_table(h3_table, f"{tmp}/h3.parquet", compression="zstd")
        h3_json = {"type": "FeatureCollection", "features": [
            {"type": "Feature", "geometry": shapely.geometry.mapping(p), "properties": {"cell": c}}
            for c, p in zip(names, hpoly, strict=True)]}
        with open(f"{tmp}/h3.geojson", "w") as fh:
            json.dump(h3_json, fh)
        hp, hj = os.path.getsize(f"{tmp}/h3.parquet"), os.path.getsize(f"{tmp}/h3.geojson")
        print(f"- H3: GeoParquet {hp / 1e6:.2f} MB, GeoJSON {hj / 1e6:.2f} MB")
        for tol in (10.0, 1.0, "exact"):
            t = cells_to_table(ours, tolerance=tol).select(["cell", "geometry"])
            pq.write_table(t, f"{tmp}/o.parquet", compression="zstd")
            with open(f"{tmp}/o.geojson", "w") as fh:
                json.dump(dggs.cells_to_geojson(ours, tolerance=tol), fh)
            op, oj = os.path.getsize(f"{tmp}/o.parquet"), os.path.getsize(f"{tmp}/o.geojson")
            print(f"- ours tolerance={tol!r}: GeoParquet {op / 1e6:.2f} MB ({op / hp:.2f}x H3's), GeoJSON {oj / 1e6:.2f} MB ({oj / hj:.2f}x)")
    parts(ours, theirs)


def parts(ours: np.ndarray, theirs: np.ndarray, tolerance: float = 10.0, rounds: int = 5) -> None:
    """The default polygons' time a cell in parts (index/_shapes.py ragged_geometries' steps) beside H3's whole."""
    import pyarrow as pa
    import shapely
    from h3ronpy.vector import cells_to_wkb_polygons

    import dggs
    from dggs.index._kernel import edge_bound
    from dggs.index._kernel import points as kp
    from dggs.index._shapes import ring_to_geometry

    n = ours.size
    counts = np.empty(n, dtype=np.int32)
    scratch = np.empty((n * edge_bound.EDGE_RING_ROWS, 2))
    rows = edge_bound.edge_rings_count(0, ours, tolerance, 0.0, counts, scratch)
    offsets = np.empty(n + 1, dtype=np.int64)
    coords = np.empty((rows, 2))
    special = np.empty(n, dtype=np.uint8)
    edge_bound.edge_rings_write(0, ours, counts, scratch, offsets, coords, special)
    poles = np.flatnonzero(special).tolist()

    def exact_rings() -> None:
        for i in poles:
            buf = np.empty((3 * (int(counts[i]) + 1) + kp.SPECIAL_EXTRA, 2))
            m = kp.special_ring(ours[i], int(counts[i]), buf)
            ring_to_geometry(buf[:m, 0], buf[:m, 1])

    cases = {
        "h3ronpy WKB + shapely.from_wkb (res 6)": (lambda: shapely.from_wkb(
            pa.array(cells_to_wkb_polygons(pa.array(theirs))).to_numpy(zero_copy_only=False)), theirs.size),
        f"dggs.cell_to_polygon(tolerance={tolerance:g}) (level 10)": (
            lambda: dggs.cell_to_polygon(ours, tolerance=tolerance), n),
        "  pass one: the count (12 inverse projections a cell) and, from its points, the ring (0, 1 or 3 an edge)": (
            lambda: edge_bound.edge_rings_count(0, ours, tolerance, 0.0, counts, scratch), n),
        "  pass two: the rings end to end (the other counts' drawn), the pole/antimeridian flags": (
            lambda: edge_bound.edge_rings_write(0, ours, counts, scratch, offsets, coords, special), n),
        "  shapely.from_ragged_array": (lambda: shapely.from_ragged_array(
            shapely.GeometryType.POLYGON, coords, (offsets, np.arange(n + 1))), n),
        f"  the {len(poles)} cells at a pole or across the antimeridian (exact rings, one by one)": (exact_rings, n),
    }
    best = dict.fromkeys(cases, float("inf"))
    for f, _ in cases.values():
        f()
    for _ in range(rounds):
        for name, (f, _) in cases.items():
            t = time.process_time()
            f()
            best[name] = min(best[name], time.process_time() - t)
    print(f"\nParts, best of {rounds} interleaved rounds, CPU, one thread, load average {os.getloadavg()}:\n")
    print("| case | per cell |\n|---|---:|")
    for name, (_, count) in cases.items():
        print(f"| {name} | {1e6 * best[name] / count:.2f} us |")
    counts_seen = np.bincount(counts)
    print(f"\nPoints an edge at level 10, {tolerance:g} m: " + ", ".join(
        f"{k}: {100 * c / n:.1f} %" for k, c in enumerate(counts_seen.tolist()) if c))


if __name__ == "__main__":
    main(*(int(a) for a in sys.argv[1:]))
