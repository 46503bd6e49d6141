"""Compare libdggs's directed edges (dggs._core, this checkout's build) with the numba kernels bit for bit.

Runs index/_kernel/edges.py and ivea_edges.py (the installed package: the numba reference) and this checkout's
dggs._core on random edges: cells at every level 0..27 (random points, the poles, the antimeridian, icosahedron
vertices, face edges), their three edges; pairs of cells (neighbours, non-neighbours, a cell and itself, level 28);
ends, reverse, lengths (both projections, pieces 16 and 3), boundaries (densify 0, 1, 5; both projections) and the
single-edge entries. Floats are compared as their bits. Exit code 0 only if all are equal.

    cd /tmp && nice python /work/wt/dissolve/libdggs/tools/compare_edges.py [--scale 1.0]
"""

from __future__ import annotations

import argparse
import glob
import importlib.util
import os
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))


def load_core():
    """Load dggs._core of this checkout's build, by path under its real name."""
    so = glob.glob(os.path.join(ROOT, "dggs", "_core.cpython-*.so"))[0]
    spec = importlib.util.spec_from_file_location("dggs._core", so)
    core = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(core)
    return core


core = load_core()
from dggs.index._kernel import edges as ke  # noqa: E402  (the installed package: the numba reference)
from dggs.index._kernel import grid as kg  # noqa: E402
from dggs.index._kernel import ivea_edges as kie  # noqa: E402
from dggs.index._kernel import points as kp  # noqa: E402

FAILED: list[str] = []


def same(a, b) -> bool:
    """Whether two results are equal bit for bit (floats by their bits)."""
    a, b = np.asarray(a), np.asarray(b)
    if a.shape != b.shape or a.dtype != b.dtype:
        return False
    if a.dtype.kind == "f":
        return bool(np.array_equal(a.view(np.uint64), b.view(np.uint64)))
    return bool(np.array_equal(a, b))


def report(name: str, count: int, equal: bool) -> None:
    """Print one comparison's line and remember a failure."""
    print(f"{name:44s} {count:>10,d} items  {'equal' if equal else 'DIFFERENT'}", flush=True)
    if not equal:
        FAILED.append(name)


def special_points() -> tuple[np.ndarray, np.ndarray]:
    """The poles, +-180, icosahedron vertices and face-edge points, and 1e-9 off them."""
    from dggs.geometry.icosahedron import ISEA

    v = ISEA.geometry.vertices
    lat = list(np.degrees(np.arcsin(np.clip(v[:, 2], -1, 1))))
    lng = list(np.degrees(np.arctan2(v[:, 1], v[:, 0])))
    fv = ISEA.geometry.face_vertices
    for f in range(20):
        for k in range(3):
            a, b = v[fv[f, k]], v[fv[f, (k + 1) % 3]]
            for t in (0.5, 0.25, 1e-6):
                p = (1 - t) * a + t * b
                p = p / np.linalg.norm(p)
                lat.append(float(np.degrees(np.arcsin(p[2]))))
                lng.append(float(np.degrees(np.arctan2(p[1], p[0]))))
    lat += [90.0, -90.0, 0.0, 0.0, 45.0, -45.0, 89.9999999, -89.9999999]
    lng += [0.0, 0.0, 180.0, -180.0, 180.0, -180.0, 179.9999999, -179.9999999]
    lat_a, lng_a = np.array(lat), np.array(lng)
    off = [lat_a, lat_a + 1e-9, lat_a - 1e-9]
    lat_a = np.clip(np.concatenate(off), -90, 90)
    lng_a = np.concatenate([lng_a, lng_a + 1e-9, lng_a - 1e-9])
    return lat_a, lng_a


def cells_at(lat: np.ndarray, lng: np.ndarray, levels: np.ndarray) -> np.ndarray:
    """The cell of each point at its level (numba's points.locate)."""
    out = np.empty(lat.shape[0], dtype=np.uint64)
    for lv in np.unique(levels).tolist():
        sel = levels == lv
        o = np.empty(int(sel.sum()), dtype=np.uint64)
        kp.locate(o.shape[0], np.ascontiguousarray(lat[sel]), np.ascontiguousarray(lng[sel]), int(lv), o)
        out[sel] = o
    return out


def main() -> int:
    """Run every comparison; 0 if all equal."""
    ap = argparse.ArgumentParser()
    ap.add_argument("--scale", type=float, default=1.0, help="multiply the random input sizes")
    ap.add_argument("--threads", type=int, default=2, help="threads of the C batch loops (dggs._core.set_threads)")
    args = ap.parse_args()
    core.set_threads(args.threads)
    rng = np.random.default_rng(20240531)
    t0 = time.time()
    n = int(400_000 * args.scale)
    z = rng.uniform(-1, 1, n)
    lat = np.degrees(np.arcsin(z))
    lng = rng.uniform(-180, 180, n)
    slat, slng = special_points()
    lat = np.concatenate([lat, np.repeat(slat, 28)])
    lng = np.concatenate([lng, np.repeat(slng, 28)])
    levels = np.concatenate([rng.integers(0, 29, n), np.tile(np.arange(28), slat.shape[0])])
    cells = cells_at(lat, lng, levels)
    cells = cells[cells != 0]

    # origin edges (level 28 answers 0)
    a = np.empty((cells.shape[0], 3), np.uint64)
    b = np.empty((cells.shape[0], 3), np.uint64)
    ke.origin_edges(cells.shape[0] * 3, cells, a)
    core.edges_origin_edges(cells.shape[0] * 3, cells, b)
    report("origin_edges (levels 0..28)", a.size, same(a, b))
    c27 = cells[kp_levels(cells) < 28]
    e27 = np.empty((c27.shape[0], 3), np.uint64)
    ke.origin_edges(c27.shape[0] * 3, c27, e27)
    edges = e27.ravel()

    # pair edges: each cell with its 3 neighbours, a random other cell, itself
    nb = np.empty((cells.shape[0], 3), np.uint64)
    kg.neighbours(cells, nb)
    pa = np.concatenate([np.repeat(cells, 3), cells, cells, cells])
    pb = np.concatenate([nb.ravel(), rng.permutation(cells), cells, nb[:, ::-1][:, 0]])
    o1 = np.empty(pa.shape[0], np.uint64)
    o2 = np.empty(pa.shape[0], np.uint64)
    ke.pair_edges(pa.shape[0], pa, pb, o1)
    core.edges_pair_edges(pa.shape[0], pa, pb, o2)
    report("pair_edges (neighbours, others, itself)", pa.shape[0], same(o1, o2))

    # ends, reverse
    r = [np.empty(edges.shape[0], np.uint64) for _ in range(4)]
    ke.ends(edges.shape[0], edges, r[0], r[1])
    core.edges_ends(edges.shape[0], edges, r[2], r[3])
    report("ends (origin, destination)", edges.shape[0], same(r[0], r[2]) and same(r[1], r[3]))
    ke.reverse(edges.shape[0], edges, r[0])
    core.edges_reverse(edges.shape[0], edges, r[1])
    report("reverse", edges.shape[0], same(r[0], r[1]))
    report("reverse of reverse is the edge", edges.shape[0], same(edges, _rev(r[1])))

    # lengths and boundaries, both projections (a subset: 2 pieces + 1 inverses per edge)
    sub = edges[rng.permutation(edges.shape[0])[: int(300_000 * args.scale)]]
    for name, kn, cl, cb, kb in (("ISEA", ke.lengths, core.edges_lengths, core.edges_boundaries, ke.boundaries),
                                 ("IVEA", kie.lengths, core.ivea_edges_lengths, core.ivea_edges_boundaries,
                                  kie.boundaries)):
        for pieces in (16, 3):
            m = [np.empty(sub.shape[0]) for _ in range(4)]
            kn(sub.shape[0] * pieces, sub, pieces, m[0], m[1])
            cl(sub.shape[0] * pieces, sub, pieces, m[2], m[3])
            report(f"lengths {name} pieces {pieces} (m, rad)", sub.shape[0], same(m[0], m[2]) and same(m[1], m[3]))
        for densify in (0, 1, 5):
            s2 = edges if densify == 0 else sub[: max(1, sub.shape[0] // densify)]
            x = np.empty((s2.shape[0], densify + 2, 2))
            y = np.empty((s2.shape[0], densify + 2, 2))
            kb(s2.shape[0] * (densify + 1), s2, densify, x)
            cb(s2.shape[0] * (densify + 1), s2, densify, y)
            report(f"boundaries {name} densify {densify}", s2.shape[0], same(x, y))

    # the single-edge entries (Python ints, as index/edges.py calls them)
    one = [int(e) for e in edges[rng.permutation(edges.shape[0])[: int(20_000 * args.scale)]]]
    ok = all(ke.one_origin(e) == core.edges_one_origin(e) for e in one)
    report("one_origin", len(one), ok)
    ok = all(ke.one_destination(e) == core.edges_one_destination(e) for e in one)
    report("one_destination", len(one), ok)
    ok = all(tuple(ke.one_ends(e)) == tuple(core.edges_one_ends(e)) for e in one)
    report("one_ends", len(one), ok)
    ok = all(ke.one_reverse(e) == core.edges_one_reverse(e) for e in one)
    report("one_reverse", len(one), ok)
    ok = all(same(np.array(ke.one_length(e, 16)), np.array(core.edges_one_length(e, 16))) for e in one[:5000])
    report("one_length ISEA", min(len(one), 5000), ok)
    ok = all(same(np.array(kie.one_length(np.uint64(e), 16)), np.array(core.ivea_edges_one_length(e, 16)))
             for e in one[:5000])
    report("one_length IVEA", min(len(one), 5000), ok)
    ok = all(int(ke.edge_of(np.uint64(c), d)) == core.edges_edge_of(int(c), d) for c in cells[:3000] for d in range(3))
    report("edge_of", 9000, ok)
    print(f"{time.time() - t0:.1f} s; {'ALL EQUAL' if not FAILED else 'DIFFERENT: ' + ', '.join(FAILED)}")
    return 1 if FAILED else 0


def kp_levels(ids: np.ndarray) -> np.ndarray:
    """Levels of valid ids."""
    from dggs.index._kernel import hierarchy as kh

    return kh.levels(ids)


def _rev(e: np.ndarray) -> np.ndarray:
    out = np.empty(e.shape[0], np.uint64)
    core.edges_reverse(e.shape[0], e, out)
    return out


if __name__ == "__main__":
    sys.exit(main())
