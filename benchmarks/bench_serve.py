"""Load test of ``dggs serve``: concurrent clients over 127.0.0.1 while an ingest writes to the store.

Builds a store of random points, starts ``dggs serve`` as its own process on a
free port of 127.0.0.1 and an ingest process that keeps appending batches of
``--batch`` rows to the same store, then runs ``--clients`` client threads (one
keep-alive HTTP connection each) for ``--seconds`` seconds over a mix of
requests: the map's layer info and cells (the whole world at a coarse level,
random 20-degree boxes at a finer one), zone info, zone data and zone
listings.  Prints a markdown table of latency percentiles per request kind,
the errors (any status but 200, or a failed connection) and the check that
readers see only whole batches: every row count a client reads is the
starting count plus a whole number of batches, and never goes down.

Run::

    .venv-bench/bin/python benchmarks/bench_serve.py                # 16 clients, 20 s
    .venv-bench/bin/python benchmarks/bench_serve.py --clients 4 --seconds 5
    .venv-bench/bin/python benchmarks/bench_serve.py --projection IVEA   # a store binned on IVEA, its DGGRS
"""

from __future__ import annotations

import argparse
import http.client
import json
import math
import os
import random
import socket
import statistics
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

import numpy as np

import dggs
from dggs.storage import CellStore

DGGRS = "DGGS-Split26-ISEA"  # DGGS-Split26-IVEA with --projection IVEA (the store's DGGRS)

#: The writer: appends sources of 50,000 rows in batches until told to stop.
WRITER = r"""
import os, sys
import numpy as np
from dggs.storage import CellStore
path, level, batch, stop_file = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), sys.argv[4]
rng = np.random.default_rng(7)
n = 0
with CellStore(path) as store:
    while not os.path.exists(stop_file):
        lat = np.degrees(np.arcsin(rng.uniform(-1, 1, 50_000)))
        lng = rng.uniform(-180, 180, 50_000)
        store.ingest_points(lat, lng, level, {"pop": rng.integers(0, 1000, 50_000)},
                                batch_size=batch, source=f"writer-{n}")
        n += 1
print(n)
"""


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


def wait_for(port: int, proc: subprocess.Popen, timeout: float = 60.0) -> None:
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if proc.poll() is not None:
            raise SystemExit(f"dggs serve exited with {proc.returncode}: {proc.stderr.read() if proc.stderr else ''}")
        try:
            conn = http.client.HTTPConnection("127.0.0.1", port, timeout=2)
            conn.request("GET", "/map/layers")
            if conn.getresponse().status == 200:
                return
        except OSError:
            time.sleep(0.2)
    raise SystemExit("dggs serve did not answer in time")


def requests_mix(rng: random.Random, level: int) -> tuple[str, str]:
    """One request of the mix: (kind, path)."""
    kind = rng.choice(["layers", "world cells", "box cells", "zone info", "zone data", "zone list"])
    if kind == "layers":
        return kind, "/map/layers"
    if kind == "world cells":
        return kind, f"/map/cells?level={min(3, level)}&bbox=-180,-90,180,90&column=pop&stat=sum"
    if kind == "box cells":
        w, s = rng.uniform(-180, 160), rng.uniform(-90, 70)
        return kind, f"/map/cells?level={min(6, level)}&bbox={w:.3f},{s:.3f},{w + 20:.3f},{s + 20:.3f}&column=pop&stat=mean"
    lat, lng = math.degrees(math.asin(rng.uniform(-1, 1))), rng.uniform(-180, 180)  # uniform on the sphere
    if kind == "zone info":
        return kind, f"/dggs/{DGGRS}/zones/{dggs.latlng_to_cell(lat, lng, rng.randint(0, level))}"
    if kind == "zone data":
        return kind, f"/dggs/{DGGRS}/zones/{dggs.latlng_to_cell(lat, lng, 2)}/data?zone-depth=3"
    return kind, f"/dggs/{DGGRS}/zones?zone-level=3&compact-zones=true"


def client(port: int, until: float, seed: int, level: int, start_count: int, batch: int, out: dict) -> None:
    rng = random.Random(seed)
    conn = http.client.HTTPConnection("127.0.0.1", port, timeout=30)
    last_count = start_count
    while time.monotonic() < until:
        kind, path = requests_mix(rng, level)
        t0 = time.perf_counter()
        try:
            conn.request("GET", path)
            resp = conn.getresponse()
            body = resp.read()
            status = resp.status
        except (OSError, http.client.HTTPException) as exc:
            status, body = f"{type(exc).__name__}", b""
            conn.close()
            conn = http.client.HTTPConnection("127.0.0.1", port, timeout=30)
        dt = time.perf_counter() - t0
        out.setdefault(kind, []).append(dt)
        if status != 200:
            out.setdefault("errors", []).append(f"{status} {path}")
        elif kind == "layers":
            count = json.loads(body)["count"]
            if (count - start_count) % batch or count < last_count:
                out.setdefault("torn", []).append((last_count, count))
            last_count = count
            out.setdefault("counts", []).append(count)
    conn.close()


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--clients", type=int, default=16)
    ap.add_argument("--seconds", type=float, default=20.0)
    ap.add_argument("--rows", type=int, default=200_000, help="rows in the store before the test")
    ap.add_argument("--level", type=int, default=9)
    ap.add_argument("--batch", type=int, default=5_000, help="rows per batch of the concurrent ingest")
    ap.add_argument("--projection", choices=["ISEA", "IVEA"], default="ISEA", help="the grid the store bins on")
    args = ap.parse_args()
    global DGGRS
    DGGRS = f"DGGS-Split26-{args.projection}"

    with tempfile.TemporaryDirectory() as tmp:
        db = Path(tmp) / "load.db"
        rng = np.random.default_rng(0)
        lat = np.degrees(np.arcsin(rng.uniform(-1, 1, args.rows)))
        lng = rng.uniform(-180, 180, args.rows)
        with CellStore(db, projection=args.projection) as store:  # the writer reads it from the file
            store.ingest_points(lat, lng, args.level, {"pop": rng.integers(0, 1000, args.rows)})
            start_count = store.count()
        port = free_port()
        dggs_cli = Path(sys.executable).with_name("dggs")
        server = subprocess.Popen([str(dggs_cli), "serve", str(db), "--port", str(port)],
                                  stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        stop_file = Path(tmp) / "stop"
        writer = None
        try:
            wait_for(port, server)
            writer = subprocess.Popen([sys.executable, "-c", WRITER, str(db), str(args.level), str(args.batch),
                                       str(stop_file)], stdout=subprocess.PIPE, text=True)
            time.sleep(1.0)  # let the writer start its first batches
            load0 = os.getloadavg()[0]
            results: list[dict] = [{} for _ in range(args.clients)]
            until = time.monotonic() + args.seconds
            threads = [threading.Thread(target=client, args=(port, until, i, args.level, start_count, args.batch,
                                                              results[i])) for i in range(args.clients)]
            t0 = time.perf_counter()
            for t in threads:
                t.start()
            for t in threads:
                t.join()
            wall = time.perf_counter() - t0
            load1 = os.getloadavg()[0]
        finally:
            stop_file.touch()
            if writer is not None:
                writer.wait(timeout=120)
            server.terminate()
            server.wait(timeout=30)
        with CellStore(db, readonly=True) as store:
            end_count = store.count()

    merged: dict[str, list] = {}
    for r in results:
        for k, v in r.items():
            merged.setdefault(k, []).extend(v)
    errors = merged.pop("errors", [])
    torn = merged.pop("torn", [])
    counts = merged.pop("counts", [])
    total = sum(len(v) for v in merged.values())
    print(f"### `dggs serve` under load ({args.clients} clients, {args.seconds:.0f} s, "
          f"while an ingest writes{'' if args.projection == 'ISEA' else ', ' + DGGRS})\n")
    print(f"One `dggs serve` process (uvicorn, one worker) on 127.0.0.1 over a store of {args.rows:,} random points "
          f"at level {args.level}; {args.clients} client threads in another process, each on one keep-alive "
          f"connection, for {args.seconds:.0f} s; meanwhile a third process ingested "
          f"{end_count - start_count:,} more rows in batches of {args.batch:,}. "
          f"Load average {load0:.2f} before, {load1:.2f} after (2 cores shared by all three).\n")
    print("| request | n | p50 | p99 | max |")
    print("|---|---:|---:|---:|---:|")
    for kind in sorted(merged):
        v = sorted(merged[kind])
        p99 = v[min(len(v) - 1, int(0.99 * len(v)))]
        print(f"| {kind} | {len(v):,} | {statistics.median(v) * 1e3:.1f} ms | {p99 * 1e3:.1f} ms "
              f"| {v[-1] * 1e3:.1f} ms |")
    everything = sorted(x for v in merged.values() for x in v)
    p99_all = everything[min(len(everything) - 1, int(0.99 * len(everything)))]
    print(f"| **all** | {total:,} ({total / wall:,.0f}/s) | {statistics.median(everything) * 1e3:.1f} ms "
          f"| {p99_all * 1e3:.1f} ms | {everything[-1] * 1e3:.1f} ms |")
    print()
    print(f"- **Errors:** {len(errors)}" + (f" (first: {errors[:3]})" if errors else "") + ".")
    distinct = len(set(counts))
    print(f"- **Whole batches only:** {len(counts):,} row counts read, {distinct} distinct, "
          + ("every one the starting count plus whole batches, never decreasing." if not torn
             else f"**{len(torn)} torn or decreasing reads** (first: {torn[:3]})."))
    print()
    if errors or torn:
        sys.exit(1)


if __name__ == "__main__":
    main()
