"""Benchmark the IVEA projection and grid against ISEA's, operation by operation, in one run.

N random points uniform on the sphere (fixed seed).  Rows: the checked projections
(``dggs.geometry.snyder`` / ``dggs.geometry.ivea`` ``forward`` and ``inverse`` on the unit sphere),
then the grids (``dggs.Grid("ISEA")``, which is the module-level verbs, and ``dggs.Grid("IVEA")``):
point location at level 15, cell centres, and boundaries (3 corners, and ``densify=8``).
Every case runs in turn in each round (``_common.interleaved``: medians of ``--repeats``), after an
untimed warm-up (imports, caches).  Reports ns per item and IVEA's time over ISEA's.
One thread unless ``--threads`` is given (``DGGS_THREADS`` is read at import).

Run::

    DGGS_THREADS=1 .venv/bin/python benchmarks/bench_ivea.py                 # 1,000,000 points
    DGGS_THREADS=1 .venv/bin/python benchmarks/bench_ivea.py --points 100000
"""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parent))

import dggs  # noqa: E402
from dggs.geometry import ivea, snyder  # noqa: E402

import _common  # noqa: E402


def main(argv: list[str] | None = None) -> None:
    """Print the table (Markdown) of ISEA against IVEA."""
    args = _common.projection_args(__doc__, argv, points=1_000_000, level=15)
    lat, lng = _common.points(args.points)
    grids = {"ISEA": dggs.Grid("ISEA"), "IVEA": dggs.Grid("IVEA")}
    projections = {"ISEA": snyder, "IVEA": ivea}
    planar = {k: m.forward(lat, lng) for k, m in projections.items()}
    ids = dggs.latlng_to_cell(lat, lng, args.level, as_int=True)
    cases: dict[Any, Any] = {}
    for name in ("ISEA", "IVEA"):
        m, g, fxy = projections[name], grids[name], planar[name]
        cases[("projection forward", name)] = (lambda m=m: m.forward(lat, lng), args.points)
        cases[("projection inverse", name)] = (lambda m=m, fxy=fxy: m.inverse(*fxy), args.points)
        cases[(f"latlng_to_cell level {args.level}", name)] = (
            lambda g=g: g.latlng_to_cell(lat, lng, args.level, as_int=True), args.points)
        cases[("cell_to_latlng", name)] = (lambda g=g: g.cell_to_latlng(ids), args.points)
        cases[("cell_to_boundary", name)] = (lambda g=g: g.cell_to_boundary(ids), args.points)
        cases[("cell_to_boundary densify=8", name)] = (lambda g=g: g.cell_to_boundary(ids, densify=8), args.points)
    _common.projection_table(cases, args.repeats, f"{args.points:,} points")


if __name__ == "__main__":
    main()
