"""Freeze outputs of the numba dissolve kernel (index/_kernel/dissolve.py, ivea_edges.ring_points) into test_dissolve.c.

Rewrites the block between ``BEGIN FROZEN`` and ``END FROZEN`` of libdggs/tests/test_dissolve.c with C tables
(floats as C99 hex-float literals): cell sets at every level 0..28 (the cells holding the poles alone and with
their neighbours, blobs on the antimeridian, at icosahedron vertices and anywhere, compacted blobs of mixed
levels, a ring, whole faces, the globe and the globe less a blob), each with the outline's counts (cells kept,
fine cells, edges, rings), the rings' starts, and the first rows of its ring points with their corner flags on both
projections, densified 0-2 points an edge. Run with the numba package installed (the reference), from anywhere
but this checkout's root::

    cd /tmp && python /path/to/libdggs/tools/freeze_dissolve.py
"""

from __future__ import annotations

import math
import os
import re

import numpy as np

import dggs
from dggs.index._kernel import dissolve as kd
from dggs.index._kernel import hierarchy as kh
from dggs.index._kernel import ivea_edges as kie

HERE = os.path.dirname(os.path.abspath(__file__))
TEST = os.path.join(os.path.dirname(HERE), "tests", "test_dissolve.c")
#: Ring point rows frozen per set and projection.
ROWS = 16


def h(x: float) -> str:
    """A double as a C99 hex-float literal (NAN spelled out)."""
    x = float(x)
    return "NAN" if math.isnan(x) else x.hex()


def u(c) -> str:
    """A uint64 as a C literal."""
    return f"0x{int(c):016x}ULL"


def ints(cells) -> np.ndarray:
    """Sorted unique uint64 ids of string cells."""
    return np.unique(np.asarray(dggs.str_to_int(list(cells)), dtype=np.uint64))


def cell_sets() -> list[tuple[str, np.ndarray]]:
    """(what, ids) of the frozen sets."""
    out = []
    places = [(90.0, 0.0, "north pole"), (-90.0, 0.0, "south pole"), (30.0, 180.0, "antimeridian"),
              (52.62263186, -180.0, "vertex on the antimeridian"), (-10.81231696, 36.0, "vertex"),
              (12.3, 45.6, "anywhere")]
    for level in range(29):
        lat, lng, what = places[level % len(places)]
        c = dggs.latlng_to_cell(lat, lng, level)
        kind = level % 4
        if kind == 0:
            out.append((f"level {level}: the cell at the {what}", ints([c])))
        elif kind == 1:
            out.append((f"level {level}: disk 1 at the {what}", ints(dggs.grid_disk(c, 1))))
        elif kind == 2 and level >= 2:
            out.append((f"level {level}: compacted disk 2 at the {what}, levels {level - 1}..{level}",
                        ints(dggs.compact_cells(dggs.grid_disk(c, 2)))))
        else:
            out.append((f"level {level}: ring 1 at the {what} (a hole)", ints(dggs.grid_ring(c, 1))))
    out.append(("the globe", ints(dggs.get_base_cells())))
    glob_ = ints(dggs.uncompact_cells(dggs.get_base_cells(), 1))
    out.append(("the globe less a level-1 disk at the north pole",
                np.setdiff1d(glob_, ints(dggs.grid_disk(dggs.latlng_to_cell(90.0, 0.0, 1), 1)))))
    out.append(("two whole faces and a level-3 blob", ints(["A", "F"] + list(dggs.grid_disk("C4010", 1)))))
    out.append(("duplicates and ancestors", ints(["B", "B12", "B1", "C40", "C401", "C4012"])))
    return out


def outline(ids: np.ndarray, densify: int) -> dict:
    """Every step's outputs for one set."""
    ids = ids[kd.drop_covered(ids)]
    levels = kh.levels(ids)
    finest = int(levels.max())
    coarse = levels < finest
    fine = ids
    if coarse.any():
        fine = np.sort(np.concatenate([ids[~coarse], kd.boundary_descendants(ids[coarse], finest)]))
    mask = np.empty((fine.shape[0], 3), dtype=np.bool_)
    kd.outline_mask(fine.shape[0], fine, ids, mask)
    rows, cols = np.nonzero(mask)
    ecell, ecol = fine[rows], cols.astype(np.int64)
    res = {"kept": ids.shape[0], "fine": fine.shape[0], "edges": ecell.shape[0], "starts": [0], "rows": []}
    if ecell.size == 0:
        return res
    order, starts, bad = kd.chain(ecell, ecol, ids)
    assert bad < 0 and starts.shape[0] <= 9
    res["starts"] = [int(s) for s in starts]
    cell, col = ecell[order], ecol[order]
    steps = np.full(cell.shape[0], densify + 1, dtype=np.int64)
    bound = kd.ring_point_bound(steps)
    for fn in (kd.ring_points, kie.ring_points):
        pts = np.empty((bound, 2))
        corner = np.zeros(bound, dtype=np.bool_)
        ends = np.empty(starts.shape[0] - 1, dtype=np.int64)
        fn(cell, col, steps, starts, pts, corner, ends)
        res["rows"].append((int(ends[-1]), [(pts[i, 0], pts[i, 1], bool(corner[i])) for i in range(min(ROWS, ends[-1]))]))
    return res


def main() -> None:
    """Rewrite the frozen block of test_dissolve.c."""
    sets, rows = [], []
    cells: list[str] = []
    for i, (what, ids) in enumerate(cell_sets()):
        densify = i % 3
        r = outline(ids, densify)
        start = len(cells)
        cells += [u(c) for c in ids]
        starts = ", ".join(str(s) for s in r["starts"])
        nrows = [r["rows"][p][0] if r["rows"] else 0 for p in range(2)]
        sets.append(f"    {{{start}, {ids.shape[0]}, {densify}, {r['kept']}, {r['fine']}, {r['edges']}, "
                    f"{len(r['starts']) - 1}, {{{starts}}}, {{{nrows[0]}, {nrows[1]}}}, {len(rows)}}}, /* {what} */")
        for p in range(2):
            for lat, lng, corner in (r["rows"][p][1] if r["rows"] else []):
                rows.append(f"    {{{h(lat)}, {h(lng)}, {int(corner)}}},")
    block = (
        "/* BEGIN FROZEN (tools/freeze_dissolve.py) */\n"
        f"#define FROZEN_ROWS {ROWS}\n"
        "/* the sets' cells (each set sorted, unique) */\n"
        "static const uint64_t FROZEN_CELLS[] = {\n"
        + "\n".join("    " + ", ".join(cells[i : i + 4]) + "," for i in range(0, len(cells), 4))
        + "\n};\n"
        "/* per set: its cells (first, count), densify, cells kept by drop_covered, fine cells, outline edges, rings,\n"
        " * the rings' starts (at most 8 rings frozen), ring point rows (ISEA, IVEA), its first frozen row (the first\n"
        " * min(rows, FROZEN_ROWS) of ISEA's, then of IVEA's, in FROZEN_RING_ROWS) */\n"
        "static const struct {\n    int first, count, densify, kept, fine, edges, rings;\n    int64_t starts[9];\n"
        "    int64_t rows[2];\n    int row;\n} FROZEN_SETS[] = {\n"
        + "\n".join(sets)
        + "\n};\n"
        "/* ring point rows: lat, lng, corner */\n"
        "static const struct {\n    double lat, lng;\n    int corner;\n} FROZEN_RING_ROWS[] = {\n"
        + "\n".join(rows)
        + "\n};\n/* END FROZEN */"
    )
    with open(TEST) as f:
        text = f.read()
    text = re.sub(r"/\* BEGIN FROZEN.*?/\* END FROZEN \*/", lambda _: block, text, flags=re.S)
    with open(TEST, "w") as f:
        f.write(text)


if __name__ == "__main__":
    main()
