"""Benchmark child positions, directed edges and local (i, j) against h3-py's functions of the same names (issue 21).

Cells at H3 resolution 9 and at the dggs level nearest it by cell area, from
the same random points (uniform on the sphere).  dggs is timed per array
(uint64 ids, one call) and per call (a Python loop over single ``int`` and
``str`` ids); h3-py per call (``h3.api.basic_int`` and the string API), as its
API is.  The time is per item (a cell, or an edge); the ratio is h3-py's
per-call time over dggs's, so **>= 1x means dggs is at least as fast**.

Run::

    .venv-bench/bin/python benchmarks/bench_edges.py            # markdown on stdout
    .venv-bench/bin/python benchmarks/bench_edges.py --quick
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

import dggs  # noqa: E402

from _common import fmt_ns, fmt_ratio, interleaved, loadavg, nearest_level, points, print_report, try_import  # noqa: E402

H3_RES = 9
PARENT_RES = 5


def table(title: str, cases: dict[str, tuple[Callable[[], Any], int]], repeat: int, dggs_key: str, h3_key: str) -> list[str]:
    res = interleaved(cases, repeat, budget=60.0)
    rows = [f"### {title}\n", "| implementation | items | per item | h3-py int per call / this |", "|---|---:|---:|---:|"]
    ref = res.get(h3_key)
    for key, r in res.items():
        per = r["wall"] / max(r["units"], 1)
        ratio = (ref["wall"] / ref["units"]) / per if ref else None
        rows.append(f"| {key} | {r['units']:,} | {fmt_ns(per)} | {fmt_ratio(ratio)} |")
    return rows + [""]


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--cells", type=int, default=100_000)
    ap.add_argument("--calls", type=int, default=20_000)
    ap.add_argument("--repeat", type=int, default=3)
    args = ap.parse_args()
    n, calls, repeat = (10_000, 2_000, 1) if args.quick else (args.cells, args.calls, args.repeat)
    h3 = try_import("h3")
    if h3 is None:
        print("## Child positions, directed edges, local (i, j) (issue 21)\n\nh3 is not installed: nothing to compare.")
        return
    hb = h3.api.basic_int
    level = nearest_level(H3_RES, h3)
    parent_level = nearest_level(PARENT_RES, h3)
    lat, lng = points(n)
    ids = dggs.latlng_to_cell(lat, lng, level, as_int=True)
    one_int, one_str = [int(x) for x in ids[:calls]], dggs.int_to_str(ids[:calls]).tolist()
    hx = [hb.latlng_to_cell(float(y), float(x), H3_RES) for y, x in zip(lat[:calls], lng[:calls], strict=True)]
    hs = [h3.int_to_str(x) for x in hx]
    load0 = loadavg()
    out = ["## Child positions, directed edges, local (i, j) (issue 21)\n",
           f"H3 resolution {H3_RES} (parents {PARENT_RES}) against dggs level {level} (parents {parent_level}), "
           "the nearest by cell area; per item, one process; the last column is h3-py's time per item (integer "
           "API, a call per item) over each row's (**>= 1x: as fast as h3-py or faster**). `"
           + " ".join(["benchmarks/bench_edges.py", *sys.argv[1:]]) + "`.\n"]

    # child positions
    pos = np.asarray(dggs.cell_to_child_pos(ids, parent_level))
    parents = np.asarray(dggs.cell_to_parent(ids, parent_level))
    hpos = [hb.cell_to_child_pos(x, PARENT_RES) for x in hx]
    hpar = [hb.cell_to_parent(x, PARENT_RES) for x in hx]
    p_int, p_str = [int(x) for x in parents[:calls]], dggs.int_to_str(parents[:calls]).tolist()
    cp = dggs.cell_to_child_pos
    out += table("cell_to_child_pos", {
        "dggs array (uint64)": (lambda: cp(ids, parent_level), n),
        "dggs per call (int)": (lambda: [cp(c, parent_level) for c in one_int], calls),
        "dggs per call (str)": (lambda: [cp(c, parent_level) for c in one_str], calls),
        "h3-py per call (int)": (lambda: [hb.cell_to_child_pos(c, PARENT_RES) for c in hx], calls),
        "h3-py per call (str)": (lambda: [h3.cell_to_child_pos(c, PARENT_RES) for c in hs], calls),
    }, repeat, "dggs array (uint64)", "h3-py per call (int)")
    pc = dggs.child_pos_to_cell
    pos_l = [int(x) for x in pos[:calls]]
    out += table("child_pos_to_cell", {
        "dggs array (uint64)": (lambda: pc(pos, parents, level), n),
        "dggs per call (int)": (lambda: [pc(q, p, level) for q, p in zip(pos_l, p_int, strict=True)], calls),
        "dggs per call (str)": (lambda: [pc(q, p, level) for q, p in zip(pos_l, p_str, strict=True)], calls),
        "h3-py per call (int)": (lambda: [hb.child_pos_to_cell(p, H3_RES, q) for q, p in zip(hpos, hpar, strict=True)], calls),
    }, repeat, "dggs array (uint64)", "h3-py per call (int)")

    # directed edges
    oe = dggs.origin_to_directed_edges
    out += table("origin_to_directed_edges (per origin cell)", {
        "dggs array (uint64)": (lambda: oe(ids), n),
        "dggs per call (int)": (lambda: [oe(c) for c in one_int], calls),
        "dggs per call (str)": (lambda: [oe(c) for c in one_str], calls),
        "h3-py per call (int)": (lambda: [hb.origin_to_directed_edges(c) for c in hx], calls),
        "h3-py per call (str)": (lambda: [h3.origin_to_directed_edges(c) for c in hs], calls),
    }, repeat, "dggs array (uint64)", "h3-py per call (int)")
    edges = np.asarray(oe(ids))[:, 0].copy()
    e_int = [int(x) for x in edges[:calls]]
    e_str = [e[0] for e in oe(one_str)]
    he = [hb.origin_to_directed_edges(c)[0] for c in hx]
    hes = [h3.int_to_str(x) for x in he]
    for name, f, g, gs in [
        ("directed_edge_to_cells", dggs.directed_edge_to_cells, hb.directed_edge_to_cells, h3.directed_edge_to_cells),
        ("get_directed_edge_destination", dggs.get_directed_edge_destination, hb.get_directed_edge_destination,
         h3.get_directed_edge_destination),
        ("edge_length (m)", dggs.edge_length, hb.edge_length, h3.edge_length),
    ]:
        out += table(name, {
            "dggs array (uint64)": (lambda f=f: f(edges), n),
            "dggs per call (int)": (lambda f=f: [f(e) for e in e_int], calls),
            "dggs per call (str)": (lambda f=f: [f(e) for e in e_str], calls),
            "h3-py per call (int)": (lambda g=g: [g(e) for e in he], calls),
            "h3-py per call (str)": (lambda gs=gs: [gs(e) for e in hes], calls),
        }, repeat, "dggs array (uint64)", "h3-py per call (int)")

    # local (i, j): each cell around its first edge neighbour in the same level-1 cell (so in the anchor's chart,
    # one sector of Snyder's projection: docs/grid.md, "Local coordinates")
    nbs = np.asarray(dggs.edge_neighbors(ids))
    same = np.asarray(dggs.cell_to_parent(nbs.reshape(-1), 1)).reshape(nbs.shape) == np.asarray(dggs.cell_to_parent(ids, 1))[:, None]
    anchors = nbs[np.arange(len(ids)), same.argmax(axis=1)].copy()
    a_int, a_str = [int(x) for x in anchors[:calls]], dggs.int_to_str(anchors[:calls]).tolist()
    ha = [hb.grid_ring(c, 1)[0] for c in hx]
    hij = [hb.cell_to_local_ij(a, c) for a, c in zip(ha, hx, strict=True)]
    li, lj = (np.asarray(v) for v in dggs.cell_to_local_ij(anchors, ids))
    ij_l = list(zip(li[:calls].tolist(), lj[:calls].tolist(), strict=True))
    out += table("cell_to_local_ij", {
        "dggs array (uint64)": (lambda: dggs.cell_to_local_ij(anchors, ids), n),
        "dggs per call (int)": (lambda: [dggs.cell_to_local_ij(a, c) for a, c in zip(a_int, one_int, strict=True)], calls),
        "dggs per call (str)": (lambda: [dggs.cell_to_local_ij(a, c) for a, c in zip(a_str, one_str, strict=True)], calls),
        "h3-py per call (int)": (lambda: [hb.cell_to_local_ij(a, c) for a, c in zip(ha, hx, strict=True)], calls),
    }, repeat, "dggs array (uint64)", "h3-py per call (int)")
    out += table("local_ij_to_cell", {
        "dggs array (uint64)": (lambda: dggs.local_ij_to_cell(anchors, li, lj), n),
        "dggs per call (int)": (lambda: [dggs.local_ij_to_cell(a, i, j) for a, (i, j) in zip(a_int, ij_l, strict=True)], calls),
        "h3-py per call (int)": (lambda: [hb.local_ij_to_cell(a, i, j) for a, (i, j) in zip(ha, hij, strict=True)], calls),
    }, repeat, "dggs array (uint64)", "h3-py per call (int)")

    print_report(out, load0)


if __name__ == "__main__":
    main()
