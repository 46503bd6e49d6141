"""Why the WebAssembly build gives another cell than the native one at some exact ties: which libm functions.

    python js/tools/libm/ties.py [OUT_DIR]    # after make wasm js-fixtures; OUT_DIR default build/libm-ties

The fixtures' points (js/tools/write_fixtures.py: random, poles, antimeridian, icosahedron vertices, face centres
and edge midpoints) are located natively on both projections at every level by trace.c, which is the core linked
with `-Wl,--wrap` round each libm function it calls, recording every call's arguments and glibc's result. musl.c,
built for wasm32-wasi as the package's .wasm is (wasi-libc: musl's libm), evaluates the same calls
(compare.mjs, under node), and the JS package locates the same points. Printed: for each function, how many of
its calls musl answers differently and by how many ulps; how many point-levels get another cell from the
WebAssembly build, whether each is a tie of the fixtures (`ties`), which functions differed on its way there,
and how far it lies from the other cell (the smallest of 101 steps from 1e-18 to 1e-8 radians toward that
cell's centre at which the native build gives it too).

Since issue 34 the core calls none of these functions (it carries its own, libdggs/src/dmath.c, in both builds):
the table is empty and no point-level gets another cell. Run on an older checkout to see the libm differences.
"""

from __future__ import annotations

import collections
import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np

import dggs

ROOT = Path(__file__).resolve().parents[3]
HERE = Path(__file__).resolve().parent
NAMES = ["sin", "cos", "asin", "atan2", "hypot", "pow", "acos", "atan", "tan"]
RECORD = np.dtype([("fn", "<i4"), ("point", "<i4"), ("proj", "<i4"), ("level", "<i4"),
                   ("x", "<f8"), ("y", "<f8"), ("r", "<f8")])
FP = ["-O3", "-std=c11", "-ffp-contract=off", "-fno-fast-math", "-fno-finite-math-only"]


def build(out: Path) -> None:
    """Build trace (native, glibc) and musl.wasm (wasm32-wasi, musl), with the flags of setup.py and the Makefile."""
    src = sorted(str(p) for p in (ROOT / "libdggs/src").glob("*.c"))
    inc = [f"-I{ROOT / 'libdggs/include'}", f"-I{ROOT / 'libdggs/src'}"]
    wrap = "-Wl," + ",".join(f"--wrap={n}" for n in [*NAMES, "sincos"])
    cc = os.environ.get("CC", "cc")
    subprocess.run([cc, *FP, *inc, "-o", str(out / "trace"), str(HERE / "trace.c"), *src, "-lm", wrap], check=True)
    sysroot = ROOT / "build/wasm/sysroot"
    if not (sysroot / ".made").exists():
        subprocess.run(["make", "-C", str(ROOT), "--no-print-directory", "wasm-toolchain"], check=True)
    subprocess.run([os.environ.get("WASM_CC", "clang"), "--target=wasm32-wasi", f"--sysroot={sysroot}", *FP,
                    "-mexec-model=reactor", "-o", str(out / "musl.wasm"), str(HERE / "musl.c")], check=True)


def unit(lat: np.ndarray, lng: np.ndarray) -> np.ndarray:
    """Unit vectors of (lat, lng) degrees on the sphere."""
    p, q = np.radians(lat), np.radians(lng)
    return np.stack([np.cos(p) * np.cos(q), np.cos(p) * np.sin(q), np.sin(p)], -1)


def distance_to(grid: dggs.Grid, lat: float, lng: float, level: int, other: int) -> float:
    """Radians the point must move toward `other`'s centre before the native build gives `other`."""
    steps = np.geomspace(1e-18, 1e-8, 101)
    u, v = unit(np.array(lat), np.array(lng)), unit(*map(np.asarray, grid.cell_to_latlng(other)))
    t = v - u * (u @ v)
    t /= np.linalg.norm(t)
    q = np.cos(steps)[:, None] * u + np.sin(steps)[:, None] * t
    qlat = np.degrees(np.arctan2(q[:, 2], np.hypot(q[:, 0], q[:, 1])))
    qlng = np.degrees(np.arctan2(q[:, 1], q[:, 0]))
    hit = np.flatnonzero(np.asarray(grid.latlng_to_cell(qlat, qlng, level, as_int=True)) == other)
    return float(steps[hit[0]]) if hit.size else float("inf")


def main(out: Path) -> None:
    """Trace, compare and print the tables into and from `out`."""
    out.mkdir(parents=True, exist_ok=True)
    fixtures = ROOT / "build/js-fixtures/fixtures.json"
    if not fixtures.exists():
        subprocess.run([sys.executable, str(ROOT / "js/tools/write_fixtures.py"), str(fixtures.parent)], check=True)
    fx = json.loads(fixtures.read_text())
    points = fx["points"]
    (out / "points.txt").write_text("".join(f"{lat!r} {lng!r}\n" for lat, lng, _ in points))
    build(out)
    with open(out / "points.txt") as stdin:
        subprocess.run([str(out / "trace"), str(out / "trace.bin"), str(out / "cells.txt")], stdin=stdin, check=True)
    subprocess.run(["node", str(HERE / "compare.mjs"), str(out)], check=True)

    trace = np.fromfile(out / "trace.bin", RECORD)
    musl = np.fromfile(out / "musl.bin", "<f8")
    differs = trace["r"].view("<i8") != musl.view("<i8")
    ulps = musl.view("<i8") - trace["r"].view("<i8")
    print("| function | calls | musl differs | by (ulps: count) |\n|---|---:|---:|---|")
    for f, name in enumerate(NAMES):
        mine = trace["fn"] == f
        if mine.any():
            by = ", ".join(f"{u:+d}: {c:,}" for u, c in sorted(collections.Counter(ulps[mine & differs].tolist()).items()))
            print(f"| {name} | {mine.sum():,} | {differs[mine].sum():,} ({100 * differs[mine].mean():.1f} %) | {by} |")

    if not trace.size:
        print("(no calls: the core carries its own sin, cos, atan2, hypot and asin, libdggs/src/dmath.c, issue 34)")
    native = np.loadtxt(out / "cells.txt", dtype=np.uint64)
    wasm = np.loadtxt(out / "wasm_cells.txt", dtype=np.uint64)
    assert (native[:, :3] == wasm[:, :3]).all()
    changed = np.flatnonzero(native[:, 3] != wasm[:, 3])
    key = trace["point"].astype(np.int64) * 58 + trace["proj"] * 29 + trace["level"]
    projections = ("ISEA", "IVEA")
    n_ties = sum(len(fx["projections"][p]["levels"][str(lv)]["ties"]) for p in projections for lv in range(29))
    combos: collections.Counter[str] = collections.Counter()
    kinds: collections.Counter[str] = collections.Counter()
    per_proj: collections.Counter[str] = collections.Counter()
    far, in_ties = [], 0
    grids = [dggs.Grid(p) for p in projections]
    for k in changed:
        i, p, level = (int(v) for v in native[k, :3])
        combos[" + ".join(sorted({NAMES[f] for f in trace["fn"][(key == k) & differs]})) or "none"] += 1
        kinds[points[i][2]] += 1
        per_proj[projections[p]] += 1
        in_ties += str(i) in fx["projections"][projections[p]]["levels"][str(level)]["ties"]
        far.append(distance_to(grids[p], points[i][0], points[i][1], level, int(wasm[k, 3])))
    dist = np.array(far)
    print(f"\npoint-levels: {len(native):,}; ties in the fixtures: {n_ties:,}; another cell in WebAssembly: "
          f"{changed.size:,} ({in_ties:,} of them ties); by projection {dict(per_proj)}; by kind {dict(kinds)}")
    print(f"functions that differed on the way to each changed cell: {dict(combos.most_common())}")
    if dist.size:
        q = np.quantile(dist, [0.5, 0.9, 1.0])
        print(f"distance to the other cell (radians): median {q[0]:.2g}, 90 % {q[1]:.2g}, max {q[2]:.2g} "
              f"({q[2] * 6371007.2 * 1e9:.0f} nm on the authalic sphere)")


if __name__ == "__main__":
    main(Path(sys.argv[1]) if len(sys.argv) > 1 else ROOT / "build/libm-ties")
