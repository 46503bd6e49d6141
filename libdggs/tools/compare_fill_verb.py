"""Compare libdggs's public dggs_polygon_to_cells (the C verb, through ctypes) with dggs.polygon_to_cells (numba).

On compare_fill.py's random polygons (wrapped into -180..180 first, as the C verb wants them), in every mode,
on ISEA and IVEA: ``"center"`` must be the same cells (the exit code says so); the other modes test boundary cells
on rings drawn with a level's most points per edge where Python draws each cell with its own (fill.c), so a cell
whose boundary passes within that densification's error of the polygon's may differ: their differences are
counted and listed. dggs_polygon_to_cells_size must bound every result.

Run with the numba package importable (the reference) and the C library built (cmake)::

    nice .venv/bin/python libdggs/tools/compare_fill_verb.py --lib build/libdggs/libdggs.so
"""

from __future__ import annotations

import argparse
import ctypes
import sys
import time

import numpy as np

from dggs.index.polyfill import _wrap_polygon, polygon_to_cells

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from compare_fill import pick_level, polygons  # noqa: E402 - this folder's helper

MODES = ("center", "contains", "overlaps", "overlapping_bbox")


def c_polygon_to_cells(lib, poly, level: int, mode: str, proj: int) -> np.ndarray:
    """The C verb's cells (size asked first, as its documentation says)."""
    rings = [r for g in getattr(poly, "geoms", [poly]) for r in (g.exterior, *g.interiors)]
    lat_lng = np.ascontiguousarray(np.concatenate([np.asarray(r.coords)[:, ::-1] for r in rings]))
    sizes = np.array([len(r.coords) for r in rings], dtype=np.int64)
    args = (lat_lng.ctypes.data_as(ctypes.c_void_p), sizes.ctypes.data_as(ctypes.c_void_p), ctypes.c_int64(len(sizes)),
            level, MODES.index(mode), proj)
    size = ctypes.c_int64()
    err = lib.dggs_polygon_to_cells_size(*args, ctypes.byref(size))
    if err:
        raise RuntimeError(f"dggs_polygon_to_cells_size: error {err}")
    out = np.empty(size.value, dtype=np.uint64)
    count = ctypes.c_int64()
    err = lib.dggs_polygon_to_cells(*args, out.ctypes.data_as(ctypes.c_void_p), ctypes.c_int64(size.value),
                                    ctypes.byref(count))
    if err:
        raise RuntimeError(f"dggs_polygon_to_cells: error {err} (count {count.value}, size {size.value})")
    return out[: count.value]


def main() -> int:
    """Run the comparison; print the counts; 0 if every center-mode result is equal and every size a bound."""
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--lib", default="build/libdggs/libdggs.so", help="path of the built shared library")
    ap.add_argument("--polygons", type=int, default=40)
    ap.add_argument("--most", type=int, default=20_000, help="about the most cells a polygon's level holds")
    ap.add_argument("--seed", type=int, default=7)
    args = ap.parse_args()
    lib = ctypes.CDLL(args.lib)
    rng = np.random.default_rng(args.seed)
    calls = dict.fromkeys(MODES, 0)
    cells = dict.fromkeys(MODES, 0)
    differ = dict.fromkeys(MODES, 0)
    t0 = time.time()
    for poly in polygons(rng, args.polygons):
        target = _wrap_polygon(poly)
        level = pick_level(poly, rng, args.most)
        for mode in MODES:
            for proj, name in enumerate(("ISEA", "IVEA")):
                want = polygon_to_cells(poly, level, mode=mode, as_int=True, projection=name)
                got = c_polygon_to_cells(lib, target, level, mode, proj)
                calls[mode] += 1
                cells[mode] += want.shape[0]
                odd = np.setxor1d(want, got)
                differ[mode] += odd.shape[0]
                if odd.shape[0] or not np.array_equal(want, got):
                    print(f"{mode} {name} level {level}: {odd.shape[0]} cells differ {odd[:4].tolist()} "
                          f"in {target.wkt[:160]}", file=sys.stderr)
    for mode in MODES:
        print(f"{mode:>17}: {calls[mode]:>5} calls, {cells[mode]:>10,} cells, {differ[mode]:,} different")
    ok = differ["center"] == 0
    print(f"dggs_polygon_to_cells {'IDENTICAL' if ok else 'DIFFERENT'} to dggs.polygon_to_cells in center mode "
          f"({time.time() - t0:.0f} s)")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
