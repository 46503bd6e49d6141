"""Benchmark dggs.geometry.snyder's forward and inverse against PROJ's ``+proj=isea``.

N random points uniform on the sphere (unit sphere, degrees in, fixed seed).
Ours: :func:`dggs.geometry.snyder.forward` / :func:`dggs.geometry.snyder.inverse` (the public,
checked API) and the unchecked numpy twins ``forward_xyz`` / ``inverse_xyz`` (:mod:`dggs.experiments.numpy_snyder`);
the inverse runs the library's closed form and the thesis's methods (newton,
newton-poly, poly: :func:`dggs.experiments.inverse.inverse`) on our own
forward output.  PROJ: ``pyproj.Transformer.from_pipeline("+proj=isea +R=1")``
forward, and inverse on PROJ's own forward output, in the same run.  Reports
points/s (median of ``--repeats``), the ratio to PROJ's same direction, the
worst round-trip error, and the thesis's "1e-4 s per inverse call" (§4.1) as
a reference row (ratio = our points/s x 1e-4).

With ``--threads N`` every run is also split into N chunks run in a
:class:`~concurrent.futures.ThreadPoolExecutor` (numpy and PROJ release the
GIL), and the speed-up over one thread is reported.

The library's own chunked thread pool (``dggs.geometry._parallel``, used by the public
``forward``/``inverse``) is switched off here with ``DGGS_THREADS=1``, so the
"points/s" column is one core and ``--threads`` alone adds threads (the
public functions still process 2**16-point cache-sized blocks; the ``_xyz``
cores do one pass over all points).  ``--library-threads`` instead leaves the
library's pool on (``DGGS_THREADS`` unset) and adds a column for it.

Run::

    .venv/bin/python benchmarks/bench_snyder.py                    # 1,000,000 points
    .venv/bin/python benchmarks/bench_snyder.py --points 100000 --threads 2
"""

from __future__ import annotations

import argparse
import contextlib
import os
import statistics
import threading
import time
from collections.abc import Callable, Sequence
from concurrent.futures import ThreadPoolExecutor

import numpy as np

from dggs.experiments import inverse as thesis_inverse
from dggs.experiments import numpy_snyder
from dggs.geometry import snyder
from dggs.geometry.icosahedron import latlng_to_xyz

#: thesis §4.1: "a single call of the original Snyder inverse projection can occur within
#: 1/10,000ths of a second".
THESIS_SECONDS_PER_INVERSE = 1e-4
INVERSE_METHODS = ("closed", "newton", "newton-poly", "poly")


def inverse(face, x, y, method: str):
    """The library's checked inverse (closed form) or the thesis's method of that name (experiments)."""
    if method == "closed":
        return snyder.inverse(face, x, y)
    return thesis_inverse.inverse(face, x, y, method=method)


@contextlib.contextmanager
def library_threads(n: int | None):
    """Set ``DGGS_THREADS`` to ``n`` (None: unset, the library's default) for the block."""
    old = os.environ.get("DGGS_THREADS")
    if n is None:
        os.environ.pop("DGGS_THREADS", None)
    else:
        os.environ["DGGS_THREADS"] = str(n)
    try:
        yield
    finally:
        if old is None:
            os.environ.pop("DGGS_THREADS", None)
        else:
            os.environ["DGGS_THREADS"] = old


def random_points(n: int, seed: int = 0) -> tuple[np.ndarray, np.ndarray]:
    """``n`` latitudes and longitudes (degrees) uniform on the sphere."""
    rng = np.random.default_rng(seed)
    lat = np.degrees(np.arcsin(rng.uniform(-1.0, 1.0, n)))
    lng = rng.uniform(-180.0, 180.0, n)
    return lat, lng


def timed(fn: Callable[[], object]) -> float:
    """Wall time (time.perf_counter) of one call of ``fn()``."""
    t0 = time.perf_counter()
    fn()
    return time.perf_counter() - t0


def chunked(fn: Callable[..., object], arrays: Sequence[np.ndarray], threads: int,
            pool: ThreadPoolExecutor | None) -> Callable[[], list]:
    """A thunk applying ``fn`` to ``arrays`` whole (1 thread) or in ``threads`` chunks in ``pool``."""
    if threads <= 1 or pool is None:
        return lambda: [fn(*arrays)]
    bounds = np.linspace(0, len(arrays[0]), threads + 1).astype(int)
    parts = [[a[lo:hi] for a in arrays] for lo, hi in zip(bounds[:-1], bounds[1:], strict=True)]
    return lambda: list(pool.map(lambda p: fn(*p), parts))


def great_circle(lat1, lng1, lat2, lng2) -> np.ndarray:
    """Great-circle distances (radians) between degree coordinates."""
    a = latlng_to_xyz(np.radians(lat1), np.radians(lng1))
    b = latlng_to_xyz(np.radians(lat2), np.radians(lng2))
    return 2.0 * np.arcsin(np.minimum(np.linalg.norm(a - b, axis=-1) / 2.0, 1.0))


def run(points: int, repeats: int, threads: int, library: bool = False,
        radius_m: float = 6_371_000.0) -> str:
    """Run the benchmark; the markdown report."""
    import pyproj

    lat, lng = random_points(points)
    xyz = latlng_to_xyz(np.radians(lat), np.radians(lng))
    face, x, y = snyder.forward(lat, lng)

    # PROJ: one transformer per thread (a Transformer must not be shared between threads).
    local = threading.local()

    def proj() -> pyproj.Transformer:
        if not hasattr(local, "t"):
            local.t = pyproj.Transformer.from_pipeline("+proj=isea +R=1")
        return local.t

    px, py = proj().transform(lng, lat)
    plng, plat = proj().transform(px, py, direction="INVERSE")

    cases: list[tuple[str, str, Callable[..., object], list[np.ndarray], str]] = [
        ("forward", "dggs forward (lat/lng)", snyder.forward, [lat, lng], "fwd"),
        ("forward", "numpy reference forward_xyz", numpy_snyder.forward_xyz, [xyz], "fwd"),
        ("forward", "PROJ isea forward", lambda a, b: proj().transform(a, b), [lng, lat], "proj"),
    ]
    for m in INVERSE_METHODS:
        cases.append(("inverse", f"dggs inverse {m}",
                      lambda f, a, b, m=m: inverse(f, a, b, m), [face, x, y], m))
    cases.append(("inverse", "numpy reference inverse_xyz closed",
                  lambda f, a, b: numpy_snyder.inverse_xyz(f, a, b), [face, x, y], "closed"))
    cases.append(("inverse", "PROJ isea inverse",
                  lambda a, b: proj().transform(a, b, direction="INVERSE"), [px, py], "proj"))

    # Round-trip accuracy (metres on a 6371 km sphere), once per inverse; PROJ 9.5's
    # inverse returns inf for a few points near face edges: count them apart.
    err: dict[str, float] = {}
    failed: dict[str, int] = {}
    for m in INVERSE_METHODS:
        ilat, ilng = inverse(face, x, y, m)
        err[m] = float(great_circle(lat, lng, ilat, ilng).max() * radius_m)
        failed[m] = 0
    ok = np.isfinite(plat) & np.isfinite(plng)
    err["proj"] = float(great_circle(lat[ok], lng[ok], plat[ok], plng[ok]).max() * radius_m)
    failed["proj"] = int(np.count_nonzero(~ok))

    # Cases are interleaved within each repeat, so that drifts in the machine's load
    # (other processes) hit every case alike; each case's median is reported.
    pool = ThreadPoolExecutor(threads) if threads > 1 else None
    single = [chunked(fn, arrays, 1, None) for _, _, fn, arrays, _ in cases]
    multi = [chunked(fn, arrays, threads, pool) for _, _, fn, arrays, _ in cases] if pool else []
    t1: list[list[float]] = [[] for _ in cases]
    tn: list[list[float]] = [[] for _ in cases]
    tl: list[list[float]] = [[] for _ in cases]
    try:
        with library_threads(1):
            for thunk in single + multi:  # warm-up
                thunk()
        for _ in range(repeats):
            for i in range(len(cases)):
                with library_threads(1):
                    t1[i].append(timed(single[i]))
                    if pool:
                        tn[i].append(timed(multi[i]))
                if library:
                    with library_threads(None):
                        tl[i].append(timed(single[i]))
    finally:
        if pool:
            pool.shutdown()
    results = []
    for i, (kind, name, _, _, key) in enumerate(cases):
        r1 = points / statistics.median(t1[i])
        rn = points / statistics.median(tn[i]) if pool else None
        rl = points / statistics.median(tl[i]) if library else None
        results.append((kind, name, key, r1, rn, rl))

    proj_rate = {kind: r for kind, name, key, r, _, _ in results if key == "proj"}
    thesis_rate = 1.0 / THESIS_SECONDS_PER_INVERSE
    head = "| operation | implementation | points/s | ratio to PROJ | x thesis (1e-4 s/call) | max round-trip error (m) |"
    sep = "|---|---|---:|---:|---:|---:|"
    if pool:
        head += f" points/s, {threads} threads | speed-up |"
        sep += "---:|---:|"
    if library:
        head += " points/s, library pool | speed-up |"
        sep += "---:|---:|"
    lines = [f"Snyder ISEA benchmark: {points:,} random points on the unit sphere, median of {repeats}"
             f" (interleaved), {os.cpu_count()} cores, PROJ {_proj_version()}", "", head, sep]
    for kind, name, key, r1, rn, rl in results:
        ratio = r1 / proj_rate[kind]
        vs_thesis = f"{r1 * THESIS_SECONDS_PER_INVERSE:.0f}" if kind == "inverse" else ""
        e = err.get(key) if kind == "inverse" else None
        e_txt = "" if e is None else f"{e:.2e}"
        if kind == "inverse" and failed.get(key):
            e_txt += f" ({failed[key]} points gave inf)"
        row = f"| {kind} | {name} | {r1:,.0f} | {ratio:.2f} | {vs_thesis} | {e_txt} |"
        if pool:
            row += f" {rn:,.0f} | {rn / r1:.2f} |"
        if library:
            row += " | |" if key == "proj" else f" {rl:,.0f} | {rl / r1:.2f} |"
        lines.append(row)
    row = f"| inverse | thesis (Qt/C++, §4.1: 1e-4 s/call) | {thesis_rate:,.0f} | {thesis_rate / proj_rate['inverse']:.3f} | 1 | |"
    row += " | |" * (bool(pool) + library)
    lines.append(row)
    return "\n".join(lines)


def _proj_version() -> str:
    import pyproj

    return pyproj.proj_version_str


def main(argv: Sequence[str] | None = None) -> None:
    """Command-line entry point."""
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--points", type=int, default=1_000_000, help="random points (default 1,000,000)")
    p.add_argument("--repeats", type=int, default=3, help="timed runs per case; the median is reported")
    p.add_argument("--threads", type=int, default=1, help="also run in N chunks on N threads")
    p.add_argument("--library-threads", action="store_true",
                   help="also time dggs with its own thread pool (DGGS_THREADS unset)")
    args = p.parse_args(argv)
    print(run(args.points, args.repeats, args.threads, args.library_threads))


if __name__ == "__main__":
    main()
