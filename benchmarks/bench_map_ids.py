"""The globe's cells from ids (WebAssembly) against GeoJSON: bytes over the wire, time to first paint, frame time
while panning, in headless Chromium (issue 34).

    python benchmarks/bench_map_ids.py [--sizes 10000 100000 1000000] [--level 9] [--ways geojson ids] [--timeout 600]
                                       [--geojson-up-to 100000]

For each size N: a store of N cells at `level`, or the first finer level with at least 2N cells (level 10 for
1M; the centres of N distinct random cells), `dggs serve` on
127.0.0.1 with --max-features N, and the page in headless Chromium (Debian's chromium and chromedriver, as
make test-browser) with the whole globe in view. For each way (`?cells=geojson`, then the default ids): the
level is chosen and timed from the choice to MapLibre's `idle` after the cells are drawn (the server's first
answer, "cold", then again after a coarser level, "warm": the GeoJSON polygons are cached by then), the bytes
of the map/cells answer (encodedBodySize), and the frame times (requestAnimationFrame) while the globe pans for
3 s. Software WebGL (SwiftShader) on a shared 2-core machine: compare within a row.

Each way has --timeout seconds (the page's script timeout and selenium's command timeout) to load, draw and pan;
one that does not finish is reported as such, with how far it got. Beside each row: the peak resident memory of
the browser (all of Chromium's processes together) and of `dggs serve`, sampled every 0.2 s, and the 1-minute
load average before and after. For the ids way, the WebGL layer's own figures (dggs/server/static/cells_layer.js):
the time to build its buffers from the ids (WebAssembly outlines, fans, upload), their chunks (one draw call
each), vertices and indices.
"""

from __future__ import annotations

import argparse
import os
import socket
import subprocess
import sys
import tempfile
import threading
import time
import urllib.request
from pathlib import Path

import numpy as np
import psutil

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


class PeakMemory:
    """The peak resident memory (MB) of a process and its children, sampled every 0.2 s in a thread."""

    def __init__(self, pid: int) -> None:
        self.pid, self.peak, self._stop = pid, 0.0, threading.Event()
        self._thread = threading.Thread(target=self._run, daemon=True)
        self._thread.start()

    def _run(self) -> None:
        while not self._stop.wait(0.2):
            try:
                root = psutil.Process(self.pid)
                procs = [root, *root.children(recursive=True)]
            except psutil.Error:
                continue
            rss = 0
            for proc in procs:
                try:
                    rss += proc.memory_info().rss
                except psutil.Error:
                    pass
            self.peak = max(self.peak, rss / 1e6)

    def stop(self) -> float:
        self._stop.set()
        self._thread.join()
        return self.peak


def browser(timeout: float) -> object:
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service

    options = webdriver.ChromeOptions()
    options.binary_location = CHROMIUM
    for flag in ("--headless=new", "--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
                 "--ignore-gpu-blocklist", "--disable-dev-shm-usage", "--no-proxy-server", "--window-size=1000,840",
                 f"--user-data-dir={tempfile.mkdtemp()}"):
        options.add_argument(flag)
    driver = webdriver.Chrome(service=Service(CHROMEDRIVER), options=options)
    driver.set_script_timeout(timeout)
    driver.command_executor._client_config.timeout = timeout + 60  # selenium's own HTTP timeout, 120 s by default
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
    const layer = window.dggsCellsLayer;
    done([performance.now() - t0, document.body.dataset.state, s.featureCount, s.level, s.source,
          last ? last.encodedBodySize : -1, last ? last.name : '',
          s.source === 'ids' && layer ? layer.stats : null]);
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


def measure(driver: object, base: str, level: int, way: str, progress: list[str]) -> dict[str, object]:
    d = driver  # selenium's WebDriver
    d.get(f"{base}/" + ("?cells=geojson" if way == "geojson" else ""))  # type: ignore[attr-defined]
    progress.append("page loaded")
    for _ in range(600):
        if d.execute_script("return document.body.dataset.state") in ("idle", "error"):  # type: ignore[attr-defined]
            break
        time.sleep(0.1)
    d.execute_script("window.dggsMap.jumpTo({center: [10, 20], zoom: 0.6, pitch: 0, bearing: 0})")  # type: ignore[attr-defined]
    time.sleep(1.0)
    cold = d.execute_async_script(CHOOSE, level)  # type: ignore[attr-defined]
    progress.append(f"cold first paint {cold[0]:,.0f} ms ({cold[2]:,} cells, state {cold[1]})")
    d.execute_async_script(CHOOSE, 0)  # type: ignore[attr-defined]
    warm = d.execute_async_script(CHOOSE, level)  # type: ignore[attr-defined]
    progress.append(f"warm first paint {warm[0]:,.0f} ms")
    frames = np.array(d.execute_async_script(PAN)[2:])  # type: ignore[attr-defined]
    return {"cold_ms": cold[0], "warm_ms": warm[0], "state": warm[1], "cells": warm[2], "level": warm[3],
            "source": warm[4], "bytes": warm[5], "layer": warm[7], "frame_median_ms": float(np.median(frames)),
            "frame_p95_ms": float(np.percentile(frames, 95)), "frames": len(frames)}


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--sizes", type=int, nargs="+", default=[10_000, 100_000, 1_000_000])
    parser.add_argument("--level", type=int, default=9)
    parser.add_argument("--ways", nargs="+", default=["geojson", "ids"], choices=["geojson", "ids"])
    parser.add_argument("--timeout", type=float, default=600.0, help="seconds a way may take (default 600)")
    parser.add_argument("--geojson-up-to", type=int, default=100_000,
                        help="the largest size the GeoJSON way is run at (default 100,000: at 1M its tab grew to "
                             "5.9 GB and crashed after about 300 s, BENCHMARKS.md)")
    args = parser.parse_args()
    if not (os.path.exists(CHROMIUM) and os.path.exists(CHROMEDRIVER)):
        sys.exit("needs Debian's chromium and chromium-driver (make test-browser installs them)")
    from selenium.common.exceptions import WebDriverException

    folder = Path(tempfile.mkdtemp())
    print(f"level {args.level} or finer, timeout {args.timeout:.0f} s a way, load average {os.getloadavg()[0]:.2f} at the start")
    print("| cells (level) | way | bytes | first paint, cold (ms) | warm (ms) | frame median (ms) | frame p95 (ms) "
          "| browser peak RSS (MB) | server peak RSS (MB) | WebGL buffers: build (ms), chunks, vertices, indices |")
    print("|---:|---|---:|---:|---:|---:|---:|---:|---:|---|")
    for n in args.sizes:
        level = next(lv for lv in range(args.level, 29) if dggs.get_num_cells(lv) >= 2 * n)
        path = store_of(n, level, folder)
        proc, base = serve(path, n)
        server_mem = PeakMemory(proc.pid)
        try:
            for way in args.ways:
                if way == "geojson" and n > args.geojson_up_to:
                    print(f"| {n:,} ({level}) | {way} | not run (--geojson-up-to {args.geojson_up_to:,}) | | | | | | | |")
                    continue
                driver = browser(args.timeout)
                browser_mem = PeakMemory(driver.service.process.pid)  # type: ignore[attr-defined]
                progress: list[str] = []
                t0 = time.monotonic()
                try:
                    r = measure(driver, base, level, way, progress)
                except (WebDriverException, OSError) as exc:  # a timeout, or the renderer gone
                    first = (getattr(exc, "msg", None) or str(exc)).strip().splitlines()[0][:120]
                    r = {"error": f"{type(exc).__name__} ({first}) after {time.monotonic() - t0:,.0f} s"}
                finally:
                    driver.quit()  # type: ignore[attr-defined]
                    peak = browser_mem.stop()
                if "error" in r:
                    got = "; ".join(progress) or "nothing"
                    print(f"| {n:,} ({level}) | {way} | did not finish: {r['error']} (got: {got}) | | | | | {peak:,.0f} | "
                          f"{server_mem.peak:,.0f} | |", flush=True)
                    continue
                assert r["source"] == way and r["cells"] == n and r["state"] == "idle", r
                lay = r["layer"]
                buffers = (f"{lay['buildMs']:,.0f}, {lay['chunks']:,}, {lay['vertices']:,}, {lay['indices']:,}"
                           if isinstance(lay, dict) else "(GeoJSON source)")
                print(f"| {n:,} ({level}) | {way} | {r['bytes']:,} | {r['cold_ms']:,.0f} | {r['warm_ms']:,.0f} | "
                      f"{r['frame_median_ms']:.1f} | {r['frame_p95_ms']:.1f} | {peak:,.0f} | {server_mem.peak:,.0f} | "
                      f"{buffers} |", flush=True)
        finally:
            server_mem.stop()
            proc.terminate()
            proc.wait(10)
    print(f"load average {os.getloadavg()[0]:.2f} at the end")


if __name__ == "__main__":
    main()
