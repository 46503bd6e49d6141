"""Benchmark the geometric verbs of ``dggs.Grid("IVEA")`` against ``dggs.Grid("ISEA")``'s, in one run.

The verbs that follow the projection beyond location, centres and boundaries (those are in
``bench_ivea.py``): directed edges' lengths and points, centre distances, GeoJSON, the dissolved outline
of a disk, circles and geodesics.  ``Grid("ISEA")``'s methods are the module-level functions; IVEA's run the
same code with IVEA's compiled kernels.  Every case runs in turn in each round (``_common.interleaved``:
medians of ``--repeats``) after an untimed warm-up.  Reports ns per item (an edge, a cell, a pair, a
feature, an outline cell, a found cell) and IVEA's time over ISEA's.  One thread unless ``DGGS_THREADS``
says otherwise.

Run::

    DGGS_THREADS=1 .venv/bin/python benchmarks/bench_projection_verbs.py
    DGGS_THREADS=1 .venv/bin/python benchmarks/bench_projection_verbs.py --points 20000
"""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parent))

import numpy as np  # noqa: E402

import dggs  # noqa: E402

import _common  # noqa: E402


def main(argv: list[str] | None = None) -> None:
    """Print the table (Markdown) of ISEA against IVEA."""
    args = _common.projection_args(__doc__, argv, points=100_000, level=12)
    lat, lng = _common.points(args.points)
    ids = dggs.latlng_to_cell(lat, lng, args.level, as_int=True)
    edges = np.asarray(dggs.origin_to_directed_edges(ids))[:, 1].copy()
    few = ids[: max(1, args.points // 100)]
    disk = dggs.grid_disk("C4012" + "0" * (args.level - 5), 20)
    cases: dict[Any, Any] = {}
    for name in ("ISEA", "IVEA"):
        g = dggs.Grid(name)
        cases[("edge_length", name)] = (lambda g=g: g.edge_length(edges), args.points)
        cases[("directed_edge_to_boundary densify=4", name)] = (
            lambda g=g: g.directed_edge_to_boundary(edges, 4), args.points)
        cases[("cell_centers_distance", name)] = (lambda g=g: g.cell_centers_distance(ids[:-1], ids[1:]), args.points - 1)
        cases[("cells_to_geojson", name)] = (lambda g=g: g.cells_to_geojson(few), few.shape[0])
        cases[(f"cells_to_polygons of a {len(disk)}-cell disk", name)] = (lambda g=g: g.cells_to_polygons(disk), len(disk))
        n_circle = len(dggs.Grid(name).circle_to_cells(48.85, 2.35, 200_000, args.level, mode="intersects"))
        cases[("circle_to_cells 200 km intersects", name)] = (
            lambda g=g: g.circle_to_cells(48.85, 2.35, 200_000, args.level, mode="intersects"), n_circle)
        n_line = len(dggs.Grid(name).geodesic_to_cells(51.05, -114.07, 49.28, -123.12, args.level))
        cases[("geodesic_to_cells Calgary-Vancouver", name)] = (
            lambda g=g: g.geodesic_to_cells(51.05, -114.07, 49.28, -123.12, args.level), n_line)
    _common.projection_table(cases, args.repeats, f"{args.points:,} points at level {args.level}")


if __name__ == "__main__":
    main()
