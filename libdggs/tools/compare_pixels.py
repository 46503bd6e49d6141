"""Compare libdggs's raster pixel weights (dggs._core, this checkout's build) with the numba kernel bit for bit.

Runs index/_kernel/pixels.py and clip.py (the installed package: the numba reference; ISEA only, as raster weights
have no IVEA variant) and this checkout's dggs._core on random rasters: grids of pixels, straight in lng/lat or in a
rotated and sheared frame (as a projected CRS's), at random places and at the poles, across the antimeridian, on
icosahedron vertices and face edges; pixel sides from 1e-4 to 4 degrees; k = 1, 2, 3, 4, 6 points an edge; levels
from coarser than the pixels to much finer (equal shares of wholly covered cells); random invalid pixels. Compares
grid_pieces' (pixel, cell, area, coarse), chord_errors on the pixels' 16 points, and clip's area and clip on random
polygons, floats as their bits. Exit code 0 only if all are equal.

    cd /tmp && nice python /work/wt/dissolve/libdggs/tools/compare_pixels.py [--scale 1.0]
"""

from __future__ import annotations

import argparse
import glob
import importlib.util
import math
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
from dggs.index._kernel import clip as kc  # noqa: E402  (the installed package: the numba reference)
from dggs.index._kernel import pixels as kpx  # noqa: E402

COUNTS: dict[str, int] = {}
FAILED: dict[str, int] = {}
SPECIAL = [(90.0, 0.0), (-90.0, 0.0), (0.0, 180.0), (52.6226, -180.0), (-52.6226, 180.0), (10.8123, -144.0),
           (-10.8123, 36.0), (26.5651, 0.0), (-26.5651, 36.0), (58.3971, -168.75), (31.7175, 180.0), (0.0, 0.0)]


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


class Frame:
    """A raster's pixel frame: (row, col) -> (lat, lng), an affine map in lng/lat (rotated, sheared)."""

    def __init__(self, rng: np.random.Generator, lat0: float, lng0: float, d: float) -> None:
        self.lat0, self.lng0, self.d = lat0, lng0, d
        if rng.random() < 0.5:
            self.m = np.array([[0.0, -d], [d, 0.0]])  # north-up lng/lat pixels: rows go south
        else:
            a = rng.uniform(0, 2 * math.pi)
            s = rng.uniform(-0.3, 0.3)
            self.m = d * np.array([[math.sin(a), -math.cos(a) + s], [math.cos(a), math.sin(a)]])

    def at(self, r: np.ndarray, c: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(lat, lng) of fractional pixel positions; latitudes folded back into -90..90."""
        lng = self.lng0 + self.m[1, 0] * c + self.m[1, 1] * r
        lat = self.lat0 + self.m[0, 0] * c + self.m[0, 1] * r
        over = lat > 90.0
        lat = np.where(over, 180.0 - lat, lat)
        under = lat < -90.0
        lat = np.where(under, -180.0 - lat, lat)
        lng = np.where(over | under, lng + 180.0, lng)
        return lat, lng


def edge_grid(frame: Frame, rows: int, cols: int, k: int):
    """hlat, hlng, vlat, vlng of rows x cols pixels, k points an edge (dggs._raster_grid.edge_grid's layout)."""
    hr = np.arange(rows + 1)[:, None] + np.zeros((1, cols * k + 1))
    hc = (np.arange(cols * k + 1) / k)[None, :] + np.zeros((rows + 1, 1))
    vr = (np.arange(rows * k + 1) / k)[:, None] + np.zeros((1, cols + 1))
    vc = np.arange(cols + 1)[None, :] + np.zeros((rows * k + 1, 1))
    hlat, hlng = frame.at(hr, hc)
    vlat, vlng = frame.at(vr, vc)
    return hlat, hlng, vlat, vlng


def sixteen(frame: Frame, rows: int, cols: int):
    """The 16 points round each pixel (corner, quarter, half, three quarters of each edge), as chord_errors takes."""
    t = np.array([0.0, 0.25, 0.5, 0.75])
    dr = np.concatenate([0 * t, t, 1 + 0 * t, 1 - t])
    dc = np.concatenate([t, 1 + 0 * t, 1 - t, 0 * t])
    rr, cc = np.meshgrid(np.arange(rows, dtype=float), np.arange(cols, dtype=float), indexing="ij")
    return frame.at(rr.reshape(-1, 1) + dr, cc.reshape(-1, 1) + dc)


def compare_raster(rng: np.random.Generator) -> None:
    """One random raster: its pieces at one level, and its pixels' chord errors."""
    if rng.random() < 0.5:
        lat0, lng0 = SPECIAL[rng.integers(0, len(SPECIAL))]
        lat0, lng0 = float(np.clip(lat0 + rng.normal(0, 0.3), -90, 90)), lng0 + float(rng.normal(0, 0.3))
    else:
        lat0, lng0 = float(np.degrees(np.arcsin(rng.uniform(-1, 1)))), float(rng.uniform(-180, 180))
    d = float(10 ** rng.uniform(-4, math.log10(4.0)))
    rows, cols = int(rng.integers(1, 12)), int(rng.integers(1, 12))
    frame = Frame(rng, lat0, lng0, d)
    # the level whose cells are about the pixel's size, give or take 4 levels (finer: equal shares)
    base = math.log(63.0 / d) / math.log(math.sqrt(3.0))
    level = int(np.clip(round(base + rng.integers(-3, 5)), 0, 28))
    k = int(rng.choice([1, 2, 2, 3, 4, 6]))
    hlat, hlng, vlat, vlng = edge_grid(frame, rows, cols, k)
    valid = rng.random((rows, cols)) < 0.9
    # keep the work bounded: a pixel may hold at most ~3**8 cells of the level
    while level > 0 and (d / (63.0 / math.sqrt(3.0) ** level)) ** 2 > 6000:
        level -= 1
    a = kpx.grid_pieces(hlat, hlng, vlat, vlng, k, valid, level)
    b = core.pixels_grid_pieces(hlat, hlng, vlat, vlng, k, valid, level)
    eq = all(same(x, y) for x, y in zip(a, b, strict=True))
    tally("grid_pieces (pieces)", a[0].shape[0], eq)
    tally("grid_pieces (pixels)", int(valid.sum()), eq)
    if not eq and len(FAILED) < 3:
        print("first difference:", lat0, lng0, d, rows, cols, level, k, frame.m.tolist(), flush=True)
    lat, lng = sixteen(frame, rows, cols)
    tally("chord_errors", lat.shape[0], same(kpx.chord_errors(lat, lng), core.pixels_chord_errors(lat, lng)))


def compare_clip(rng: np.random.Generator, n: int) -> None:
    """clip.area and clip.clip on random polygons (convex and not) and triangles of both orientations."""
    ok_area, ok_clip = True, True
    for _ in range(n):
        m = int(rng.integers(0, 12))
        x, y = rng.normal(0, 1, m), rng.normal(0, 1, m)
        if rng.random() < 0.5 and m >= 3:  # convex: points on a circle
            t = np.sort(rng.uniform(0, 2 * math.pi, m))
            x, y = np.cos(t) + rng.normal(0, 0.1), np.sin(t) + rng.normal(0, 0.1)
        ok_area &= same(kc.area(x, y, m), core.clip_area(x, y, m))
        tri = rng.normal(0, 1.2, 6)
        bufs = [np.full(4 * m + 8, np.nan) for _ in range(8)]
        g1 = kc.clip(x, y, m, *tri, bufs[0], bufs[1], bufs[2], bufs[3])
        g2 = core.clip_clip(x, y, m, *tri, bufs[4], bufs[5], bufs[6], bufs[7])
        ok_clip &= g1 == g2 and same(bufs[2][:g1], bufs[6][:g2]) and same(bufs[3][:g1], bufs[7][:g2])
    tally("clip.area", n, ok_area)
    tally("clip.clip", n, ok_clip)


def main() -> int:
    """Run every comparison; 0 if all equal."""
    ap = argparse.ArgumentParser()
    ap.add_argument("--scale", type=float, default=1.0, help="multiply the number of random rasters")
    ap.add_argument("--threads", type=int, default=2, help="threads of the C batch loops (dggs._core.set_threads)")
    args = ap.parse_args()
    core.set_threads(args.threads)
    rng = np.random.default_rng(20240602)
    t0 = time.time()
    rasters = int(6000 * args.scale)
    for _ in range(rasters):
        compare_raster(rng)
    # a large raster at a fine level and a global one-degree raster at a coarse level: most of the pieces
    for lat0, lng0, d, rows, cols, level, k in ((45.0, 10.0, 0.01, 60, 60, 14, 4), (90.0, -180.0, 1.0, 180, 360, 5, 2)):
        frame = Frame(rng, lat0, lng0, d)
        frame.m = np.array([[0.0, -d], [d, 0.0]])
        grid = edge_grid(frame, rows, cols, k)
        valid = np.ones((rows, cols), bool)
        a = kpx.grid_pieces(*grid, k, valid, level)
        b = core.pixels_grid_pieces(*grid, k, valid, level)
        eq = all(same(x, y) for x, y in zip(a, b, strict=True))
        tally("grid_pieces (pieces)", a[0].shape[0], eq)
        tally("grid_pieces (pixels)", rows * cols, eq)
        lat, lng = sixteen(frame, rows, cols)
        tally("chord_errors", lat.shape[0], same(kpx.chord_errors(lat, lng), core.pixels_chord_errors(lat, lng)))
    # chord errors of many random pixels (a sixth of them at the special places)
    n = int(1_000_000 * args.scale)
    lat0 = np.degrees(np.arcsin(rng.uniform(-1, 1, n)))
    lng0 = rng.uniform(-180, 180, n)
    sp = np.array(SPECIAL)[rng.integers(0, len(SPECIAL), n // 6)]
    lat0[: n // 6], lng0[: n // 6] = sp[:, 0] + rng.normal(0, 0.2, n // 6), sp[:, 1] + rng.normal(0, 0.2, n // 6)
    d = 10 ** rng.uniform(-4, 0.6, n)
    t = np.array([0.0, 0.25, 0.5, 0.75])
    dr = np.concatenate([0 * t, t, 1 + 0 * t, 1 - t])
    dc = np.concatenate([t, 1 + 0 * t, 1 - t, 0 * t])
    lat = np.clip(lat0[:, None] - d[:, None] * dr, -90, 90)
    lng = lng0[:, None] + d[:, None] * dc
    tally("chord_errors", n, same(kpx.chord_errors(lat, lng), core.pixels_chord_errors(lat, lng)))
    compare_clip(rng, int(20000 * args.scale))
    print(f"{rasters + 2:,d} rasters")
    for name, count in COUNTS.items():
        print(f"{name:36s} {count:>10,d} items  {'DIFFERENT' if name in FAILED else 'equal'}")
    print(f"{time.time() - t0:.1f} s; {'ALL EQUAL' if not FAILED else 'DIFFERENT: ' + ', '.join(FAILED)}")
    return 1 if FAILED else 0


if __name__ == "__main__":
    sys.exit(main())
