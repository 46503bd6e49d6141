"""The globe's cells from ids (WebAssembly) against GeoJSON: bytes over the wire, time to first paint, frame time
while panning, in headless Chromium (issue 34).

    python benchmarks/bench_map_ids.py [--sizes 10000 100000] [--level 9] [--ways geojson ids]

For each size N: a store of N cells at `level` (the centres of N distinct random cells), `dggs serve` on
127.0.0.1 with --max-features N, and the page in headless Chromium (Debian's chromium and chromedriver, as
make test-browser) with the whole globe in view. For each way (`?cells=geojson`, then the default ids): the
level is chosen and timed from the choice to MapLibre's `idle` after the cells are drawn (the server's first
answer, "cold", then again after a coarser level, "warm": the GeoJSON polygons are cached by then), the bytes
of the map/cells answer (encodedBodySize), and the frame times (requestAnimationFrame) while the globe pans for
3 s. Software WebGL (SwiftShader) on a shared 2-core machine: compare within a row.
"""

from __future__ import annotations

import argparse
import os
import socket
import subprocess
import sys
import tempfile
import time
import urllib.request
from pathlib import Path

import numpy as np

import dggs
from dggs.storage import CellStore

CHROMIUM, CHROMEDRIVER = "/usr/bin/chromium", "/usr/bin/chromedriver"


def store_of(n: int, level: int, folder: Path) -> Path:
    """A store holding exactly n cells of `level` (one point at the centre of each)."""
    rng = np.random.default_rng(34)
    cells: np.ndarray = np.empty(0, dtype=np.uint64)
    while cells.size < n:
        m = 2 * n
        lat = np.degrees(np.arcsin(rng.uniform(-1, 1, m)))
        lng = rng.uniform(-180, 180, m)
        cells = np.unique(np.concatenate([cells, np.asarray(dggs.latlng_to_cell(lat, lng, level, as_int=True))]))
    cells = rng.permutation(cells)[:n]
    clat, clng = dggs.cell_to_latlng(cells)
    path = folder / f"cells-{n}.db"
    with CellStore(path) as store:
        store.ingest_points(np.asarray(clat), np.asarray(clng), level, {"v": rng.integers(1, 1000, n)})
    return path


def free_port() -> int:
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        return int(sock.getsockname()[1])


def serve(path: Path, n: int) -> tuple[subprocess.Popen[bytes], str]:
    port = free_port()
    exe = Path(sys.executable).parent / "dggs"
    cmd = [str(exe), "serve", str(path), "--host", "127.0.0.1", "--port", str(port), "--max-features", str(n + 10)]
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    base = f"http://127.0.0.1:{port}"
    opener = urllib.request.build_opener(urllib.request.ProxyHandler({}))
    for _ in range(300):
        try:
            opener.open(f"{base}/map/layers", timeout=2).read()
            return proc, base
        except OSError:
            time.sleep(0.1)
    proc.terminate()
    raise RuntimeError("dggs serve did not start")


def browser() -> object:
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service

    options = webdriver.ChromeOptions()
    options.binary_location = CHROMIUM
    for flag in ("--headless=new", "--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
                 "--ignore-gpu-blocklist", "--disable-dev-shm-usage", "--no-proxy-server", "--window-size=1000,840",
                 f"--user-data-dir={tempfile.mkdtemp()}"):
        options.add_argument(flag)
    driver = webdriver.Chrome(service=Service(CHROMEDRIVER), options=options)
    driver.set_script_timeout(600)
    return driver


# Choose a level and wait for the map to be idle with it drawn: ms from the choice to MapLibre's idle.
CHOOSE = """
const [level, done] = arguments;
const s = window.dggsState;
const before = s.renders;
const select = document.getElementById('level');
const t0 = performance.now();
select.value = String(level);
select.dispatchEvent(new Event('change'));
(function wait() {
  if (s.renders > before && document.body.dataset.state !== 'loading') {
    const entries = performance.getEntriesByType('resource').filter(e => e.name.includes('/map/cells?'));
    const last = entries[entries.length - 1];
    done([performance.now() - t0, document.body.dataset.state, s.featureCount, s.level, s.source,
          last ? last.encodedBodySize : -1, last ? last.name : '']);
  } else setTimeout(wait, 5);
})();
"""

# Pan the globe for 3 s and collect the frame times (ms).
PAN = """
const done = arguments[0];
const map = window.dggsMap;
const times = [];
let last = performance.now();
const end = last + 3000;
map.easeTo({ center: [map.getCenter().lng + 120, map.getCenter().lat], duration: 3000, easing: (t) => t });
(function frame(now) {
  times.push(now - last);
  last = now;
  if (now < end) requestAnimationFrame(frame); else done(times);
})(performance.now());
"""


def measure(driver: object, base: str, level: int, way: str) -> dict[str, object]:
    d = driver  # selenium's WebDriver
    d.get(f"{base}/" + ("?cells=geojson" if way == "geojson" else ""))  # type: ignore[attr-defined]
    for _ in range(600):
        if d.execute_script("return document.body.dataset.state") in ("idle", "error"):  # type: ignore[attr-defined]
            break
        time.sleep(0.1)
    d.execute_script("window.dggsMap.jumpTo({center: [10, 20], zoom: 0.6, pitch: 0, bearing: 0})")  # type: ignore[attr-defined]
    time.sleep(1.0)
    cold = d.execute_async_script(CHOOSE, level)  # type: ignore[attr-defined]
    d.execute_async_script(CHOOSE, 0)  # type: ignore[attr-defined]
    warm = d.execute_async_script(CHOOSE, level)  # type: ignore[attr-defined]
    frames = np.array(d.execute_async_script(PAN)[2:])  # type: ignore[attr-defined]
    return {"cold_ms": cold[0], "warm_ms": warm[0], "state": warm[1], "cells": warm[2], "level": warm[3],
            "source": warm[4], "bytes": warm[5], "frame_median_ms": float(np.median(frames)),
            "frame_p95_ms": float(np.percentile(frames, 95)), "frames": len(frames)}


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--sizes", type=int, nargs="+", default=[10_000, 100_000])
    parser.add_argument("--level", type=int, default=9)
    parser.add_argument("--ways", nargs="+", default=["geojson", "ids"], choices=["geojson", "ids"])
    args = parser.parse_args()
    if not (os.path.exists(CHROMIUM) and os.path.exists(CHROMEDRIVER)):
        sys.exit("needs Debian's chromium and chromium-driver (make test-browser installs them)")
    folder = Path(tempfile.mkdtemp())
    print("| cells | way | bytes | first paint, cold (ms) | warm (ms) | frame median (ms) | frame p95 (ms) |")
    print("|---:|---|---:|---:|---:|---:|---:|")
    for n in args.sizes:
        path = store_of(n, args.level, folder)
        proc, base = serve(path, n)
        driver = browser()
        try:
            for way in args.ways:
                r = measure(driver, base, args.level, way)
                assert r["source"] == way and r["cells"] == n and r["state"] == "idle", r
                print(f"| {n:,} | {way} | {r['bytes']:,} | {r['cold_ms']:,.0f} | {r['warm_ms']:,.0f} | "
                      f"{r['frame_median_ms']:.1f} | {r['frame_p95_ms']:.1f} |", flush=True)
        finally:
            driver.quit()  # type: ignore[attr-defined]
            proc.terminate()
            proc.wait(10)


if __name__ == "__main__":
    main()
