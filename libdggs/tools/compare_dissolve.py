"""Compare libdggs's dissolve (dggs._core, this checkout's build) with the numba kernel bit for bit.

Runs index/_kernel/dissolve.py and ivea_edges.ring_points (the installed package: the numba reference) and this
checkout's dggs._core through every step of dggs.cells_to_polygons on random cell sets: blobs (overlapping disks)
at the poles, across the antimeridian, on icosahedron vertices and anywhere, with holes and sparse sets touching at
corners, compacted sets (coarse cells beside fine ones: boundary descendants), duplicates and ancestors, whole
faces and the globe less a blob; levels 0..20. Each set's drop_covered mask, boundary descendants, outline mask,
chain (order, starts, bad) and ring points (steps 1, 2, 5 and random per edge; both projections: rows, corner
flags, ends) are compared, floats as their bits. Exit code 0 only if all are equal.

    cd /tmp && nice python /work/wt/dissolve/libdggs/tools/compare_dissolve.py [--scale 1.0]
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
import dggs  # noqa: E402  (the installed package: the numba reference)
from dggs.index._kernel import dissolve as kd  # noqa: E402
from dggs.index._kernel import hierarchy as kh  # noqa: E402
from dggs.index._kernel import ivea_edges as kie  # noqa: E402

COUNTS: dict[str, int] = {}
FAILED: dict[str, int] = {}


def same(a, b) -> bool:
    """Whether two results are equal bit for bit (floats by their bits)."""
    a, b = np.asarray(a), np.asarray(b)
    if a.shape != b.shape or a.dtype != b.dtype:
        return False
    if a.dtype.kind == "f":
        return bool(np.array_equal(a.view(np.uint64), b.view(np.uint64)))
    return bool(np.array_equal(a, b))


def tally(name: str, count: int, equal: bool) -> None:
    """Count one comparison's items; remember a failure."""
    COUNTS[name] = COUNTS.get(name, 0) + count
    if not equal:
        FAILED[name] = FAILED.get(name, 0) + 1


def ids_of(cells) -> np.ndarray:
    """uint64 ids of string or int cells."""
    return np.asarray(dggs.str_to_int(list(cells)), dtype=np.uint64)


def compare_set(ids: np.ndarray, rng: np.random.Generator) -> None:
    """Every step of the outline of one cell set, numba against C."""
    ids = np.unique(ids)
    if ids.size == 0:
        return
    k1, k2 = kd.drop_covered(ids), core.dissolve_drop_covered(ids)
    tally("drop_covered", ids.size, same(k1, k2))
    ids = ids[k1]
    levels = kh.levels(ids)
    finest = int(levels.max())
    coarse = levels < finest
    fine = ids
    if coarse.any():
        b1 = kd.boundary_descendants(ids[coarse], finest)
        b2 = core.dissolve_boundary_descendants(ids[coarse], finest)
        tally("boundary_descendants", int(coarse.sum()), same(b1, b2))
        fine = np.sort(np.concatenate([ids[~coarse], b1]))
    m1 = np.empty((fine.shape[0], 3), dtype=np.bool_)
    m2 = np.empty((fine.shape[0], 3), dtype=np.bool_)
    kd.outline_mask(fine.shape[0], fine, ids, m1)
    core.dissolve_outline_mask(fine.shape[0], fine, ids, m2)
    tally("outline_mask", fine.shape[0], same(m1, m2))
    rows, cols = np.nonzero(m1)
    ecell, ecol = fine[rows], cols.astype(np.int64)
    if ecell.size == 0:
        tally("globe (no outline)", 1, True)
        return
    c1, c2 = kd.chain(ecell, ecol, ids), core.dissolve_chain(ecell, ecol, ids)
    tally("chain", ecell.size, same(c1[0], c2[0]) and same(c1[1], c2[1]) and int(c1[2]) == int(c2[2]))
    order, starts, bad = c1
    if bad >= 0:
        return
    cell, col = ecell[order], ecol[order]
    choices = [np.ones(cell.shape[0], np.int64), np.full(cell.shape[0], 2, np.int64),
               np.full(cell.shape[0], 5, np.int64), rng.integers(1, 6, cell.shape[0]).astype(np.int64)]
    steps = choices[rng.integers(0, 4)]
    bound = kd.ring_point_bound(steps)
    tally("ring_point_bound", 1, bound == core.dissolve_ring_point_bound(steps))
    for name, kfun, cfun in (("ISEA", kd.ring_points, core.dissolve_ring_points),
                             ("IVEA", kie.ring_points, core.ivea_dissolve_ring_points)):
        out = [np.full((bound, 2), np.nan) for _ in range(2)]
        corner = [np.zeros(bound, dtype=np.bool_) for _ in range(2)]
        ends = [np.empty(starts.shape[0] - 1, dtype=np.int64) for _ in range(2)]
        kfun(cell, col, steps, starts, out[0], corner[0], ends[0])
        cfun(cell, col, steps, starts, out[1], corner[1], ends[1])
        n = int(ends[0][-1])
        COUNTS[f"  of which at a pole ({name})"] = COUNTS.get(f"  of which at a pole ({name})", 0) + int(
            (np.abs(out[0][:n, 0]) == 90.0).sum())
        COUNTS[f"  of which at +-180 ({name})"] = COUNTS.get(f"  of which at +-180 ({name})", 0) + int(
            (np.abs(out[0][:n, 1]) == 180.0).sum())
        tally(f"ring_points {name} (rows)", n, same(ends[0], ends[1]) and same(out[0][:n], out[1][:n])
              and same(corner[0][:n], corner[1][:n]))


def random_point(rng: np.random.Generator) -> tuple[float, float]:
    """A random point, half of them at the special places (poles, +-180, vertices, face edges)."""
    special = [(90.0, 0.0), (-90.0, 0.0), (0.0, 180.0), (0.0, -180.0), (52.6226, -180.0), (-52.6226, 180.0),
               (10.8123, -144.0), (-10.8123, 36.0), (26.5651, 0.0), (-26.5651, 36.0), (58.3971, -168.75),
               (89.9, 179.9), (-89.9, -179.9), (31.7175, 180.0), (-31.7175, -180.0)]
    if rng.random() < 0.5:
        lat, lng = special[rng.integers(0, len(special))]
        return float(np.clip(lat + rng.normal(0, 0.5), -90, 90)), float(lng + rng.normal(0, 0.5))
    return float(np.degrees(np.arcsin(rng.uniform(-1, 1)))), float(rng.uniform(-180, 180))


def random_set(rng: np.random.Generator) -> np.ndarray:
    """One random cell set of a random kind."""
    kind = rng.integers(0, 8)
    level = int(rng.integers(1, 13))
    k = int(rng.integers(0, 6))
    lat, lng = random_point(rng)
    c = dggs.latlng_to_cell(lat, lng, level)
    if kind == 0:  # overlapping disks
        seeds = [dggs.latlng_to_cell(*random_point(rng) if rng.random() < 0.3 else
                                     (float(np.clip(lat + rng.normal(0, 1), -90, 90)), lng + rng.normal(0, 1)), level)
                 for _ in range(3)]
        return ids_of(np.concatenate([dggs.grid_disk(s, k) for s in seeds]))
    if kind == 1:  # a blob with holes
        cells = ids_of(dggs.grid_disk(c, k + 2))
        return cells[rng.random(cells.size) > 0.15]
    if kind == 2:  # sparse: corner-touching cells
        cells = ids_of(dggs.grid_disk(c, k + 2))
        return cells[rng.random(cells.size) < 0.4]
    if kind == 3:  # compacted: coarse cells beside fine ones, with duplicates and ancestors
        fine = dggs.grid_disk(c, k + 3)
        comp = ids_of(dggs.compact_cells(fine))
        extra = ids_of(fine[: int(rng.integers(0, 5))])
        return np.concatenate([comp, extra, comp[:3]])
    if kind == 4:  # a cell less its surroundings, or mixed levels around a vertex
        around = dggs.uncompact_cells(dggs.grid_disk_vertex(c, 1), min(level + 2, 20))
        return ids_of([x for x in around if not x.startswith(str(c))])
    if kind == 5:  # whole faces, or a face beside fine cells
        faces = list(rng.choice(dggs.get_base_cells(), int(rng.integers(1, 5)), replace=False))
        fine = dggs.grid_disk(dggs.latlng_to_cell(lat, lng, 4), 2)
        return ids_of(faces + list(fine)) if rng.random() < 0.5 else ids_of(dggs.uncompact_cells(faces, 2))
    if kind == 6:  # the globe less a blob, or the whole globe
        lv = int(rng.integers(1, 4))
        glob_ = ids_of(dggs.uncompact_cells(dggs.get_base_cells(), lv))
        if rng.random() < 0.2:
            return glob_
        return np.setdiff1d(glob_, ids_of(dggs.grid_disk(dggs.latlng_to_cell(lat, lng, lv), int(rng.integers(0, 3)))))
    # fine levels: a small disk deep down, or a ring (a hole in the middle)
    lv = int(rng.integers(13, 21))
    c = dggs.latlng_to_cell(lat, lng, lv)
    if rng.random() < 0.5:
        return ids_of(dggs.grid_ring(c, k + 1))
    return ids_of(dggs.grid_disk(c, k))


def main() -> int:
    """Run every comparison; 0 if all equal."""
    ap = argparse.ArgumentParser()
    ap.add_argument("--scale", type=float, default=1.0, help="multiply the number of random sets")
    ap.add_argument("--threads", type=int, default=2, help="threads of the C batch loops (dggs._core.set_threads)")
    args = ap.parse_args()
    core.set_threads(args.threads)
    rng = np.random.default_rng(20240601)
    t0 = time.time()
    sets = int(20000 * args.scale)
    for _ in range(sets):
        compare_set(random_set(rng), rng)
    # compacted larger blobs: many coarse cells standing for their boundary descendants
    for _ in range(int(300 * args.scale)):
        lv = int(rng.integers(4, 24))
        fine = dggs.grid_disk(dggs.latlng_to_cell(*random_point(rng), lv), int(rng.integers(5, 25)))
        compare_set(ids_of(dggs.compact_cells(fine)), rng)
    # a large blob and a large compacted blob: the bulk of the cells
    for level, k in ((9, 300), (12, 250), (16, 200)):
        c = dggs.latlng_to_cell(*random_point(rng), level)
        fine = ids_of(dggs.grid_disk(c, k))
        compare_set(fine, rng)
        compare_set(ids_of(dggs.compact_cells(fine)), rng)
    print(f"{sets + 6 + int(300 * args.scale):,d} cell sets")
    for name, count in COUNTS.items():
        print(f"{name:36s} {count:>10,d} items  {'DIFFERENT' if name in FAILED else 'equal'}")
    print(f"{time.time() - t0:.1f} s; {'ALL EQUAL' if not FAILED else 'DIFFERENT: ' + ', '.join(FAILED)}")
    return 1 if FAILED else 0


if __name__ == "__main__":
    sys.exit(main())
