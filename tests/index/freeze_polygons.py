"""Frozen polygons: the digests of ``cell_to_polygon`` by tolerance, for random cells of every level, both grids.

    python tests/index/freeze_polygons.py --write   # only where nothing may change: it redefines the oracle

Written at commit 4b831ac (main before the fused count-and-rings pass of issue 35) and compared by
tests/index/test_polygon_frozen.py: for each grid (ISEA, IVEA), tolerance (10 m, 1 m, "exact") and level 0-28,
the SHA-256 of the points per edge each cell got and of the cells' WKB (little-endian, 2D) laid end to end.
The cells are drawn digit by digit from a seeded generator (not by the code under test), 1,500 a level (all of
them where a level has fewer), plus the cells holding the poles, points on the antimeridian, the icosahedron's
vertices and its edges' midpoints (tests/strategies.py's special points).
"""

from __future__ import annotations

import hashlib
import json
import sys
from pathlib import Path
from typing import Any

import numpy as np

FIXTURE = Path(__file__).resolve().parent / "fixtures" / "polygons_frozen.json"
PER_LEVEL = 1500
TOLERANCES: tuple[Any, ...] = (10.0, 1.0, "exact")
GRIDS = ("ISEA", "IVEA")


def cells(level: int) -> list[str]:
    """String ids of the level's frozen cells (sorted, unique): random digits, then the special points' cells."""
    import dggs

    sys.path.insert(0, str(Path(__file__).resolve().parents[2]))
    from tests.strategies import special_points

    rng = np.random.default_rng(35_000 + level)
    out = set()
    faces = rng.integers(0, 20, PER_LEVEL)
    first = rng.integers(0, 6, PER_LEVEL)
    rest = rng.integers(0, 3, (PER_LEVEL, max(level - 1, 0)))
    for i in range(PER_LEVEL):
        text = "ABCDEFGHIJKLMNOPQRST"[faces[i]]
        if level >= 1:
            text += str(first[i]) + "".join(str(d) for d in rest[i])
        out.add(text)
    pts = np.array(special_points())
    out.update(dggs.latlng_to_cell(pts[:, 0], pts[:, 1], level).tolist())
    return sorted(out)


def digests(grid: str, tolerance: Any, ids: Any) -> dict[str, str]:
    """SHA-256 of the points per edge and of the WKB of ``ids`` drawn on ``grid`` at ``tolerance``."""
    import shapely

    import dggs
    from dggs.index._densify import edge_points

    ints = np.asarray(dggs.str_to_int(list(ids)) if isinstance(ids[0], str) else ids, dtype=np.uint64)
    counts = edge_points(ints, tolerance, grid == "IVEA").astype("<i8")
    drawn = dggs.Grid(grid).cell_to_polygon(ids, tolerance=tolerance)
    wkb = shapely.to_wkb(np.asarray(drawn), byte_order=1, output_dimension=2)
    return {
        "counts": hashlib.sha256(counts.tobytes()).hexdigest(),
        "wkb": hashlib.sha256(b"".join(wkb)).hexdigest(),
    }


def table() -> dict[str, Any]:
    out: dict[str, Any] = {"ids": {}, "digests": {}}
    for level in range(29):
        ids = cells(level)
        out["ids"][str(level)] = hashlib.sha256("\n".join(ids).encode()).hexdigest()
        for grid in GRIDS:
            for tol in TOLERANCES:
                out["digests"][f"{grid} {tol} {level}"] = digests(grid, tol, ids)
    return out


if __name__ == "__main__":
    if sys.argv[1:] == ["--write"]:
        FIXTURE.write_text(json.dumps(table(), indent=1, sort_keys=True) + "\n")
    else:
        print(__doc__)
