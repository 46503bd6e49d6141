"""Helpers shared by the benchmark scripts (not a benchmark itself).

Points, timing (wall and CPU, round-robin medians), formatting, optional
imports, feature detection of the dggs API, the machine and the code state,
and running a helper in a fresh interpreter with a given thread environment.
"""

from __future__ import annotations

import importlib
import importlib.metadata
import json
import os
import platform
import statistics
import subprocess
import sys
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
SEED = 20_240_601

#: Every variable that sets a thread count of dggs or of a peer.  ONE_THREAD sets them all
#: to 1; the default environment has none of them (each library picks its own default).
THREAD_VARS = ("DGGS_THREADS", "NUMBA_NUM_THREADS", "RAYON_NUM_THREADS", "OMP_NUM_THREADS",
               "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS")
ONE_THREAD = {k: "1" for k in THREAD_VARS}

NOTES: list[str] = []
#: Seconds one table's timed rounds may take (see ``interleaved``); set by the caller.
TABLE_BUDGET = [120.0]


def note(msg: str) -> None:
    """Record a note for the report (once) and print it on stderr."""
    if msg not in NOTES:
        NOTES.append(msg)
        print(f"note: {msg}", file=sys.stderr, flush=True)


def notes_section() -> str:
    """The recorded notes as a Markdown list under "Notes:" ("" when there are none)."""
    return "Notes:\n\n" + "\n".join(f"- {n}" for n in NOTES) if NOTES else ""


# --------------------------------------------------------------------------- inputs


def points(n: int, seed: int = SEED) -> tuple[np.ndarray, np.ndarray]:
    """``n`` points uniform on the sphere: (lat, lng) in degrees, float64."""
    rng = np.random.default_rng(seed)
    lat = np.degrees(np.arcsin(rng.uniform(-1.0, 1.0, n)))
    lng = rng.uniform(-180.0, 180.0, n)
    return lat, lng


# --------------------------------------------------------------------------- timing


def clock() -> tuple[float, float]:
    """(wall, CPU of this process over all its threads) now, in seconds."""
    return time.perf_counter(), time.process_time()


def sampled(f: Callable[..., Any], *inputs: Any) -> Callable[[float], tuple[Callable[[], Any], float]]:
    """A ``sample(frac)`` for ``interleaved``: ``f`` on the first ``frac`` of every input (lists or arrays)."""
    n = len(inputs[0])

    def sample(frac: float) -> tuple[Callable[[], Any], float]:
        m = max(1, int(n * frac))
        parts = [x[:m] for x in inputs]
        return (lambda: f(*parts)), n / m
    return sample


def run_once(fn: Callable[[], Any]) -> tuple[float, float, Any]:
    """Wall seconds, CPU seconds and the result of one call of ``fn()``."""
    w0, c0 = clock()
    out = fn()
    w1, c1 = clock()
    return w1 - w0, c1 - c0, out


def interleaved(cases: dict[Any, tuple[Callable[[], Any], Any]], repeat: int,
                budget: float) -> dict[Any, dict[str, float]]:
    """Median wall and CPU seconds per case; the cases run in turn in each of ``repeat`` rounds.

    ``cases`` maps a key to ``(fn, units)`` or ``(fn, units, sample)``.
    ``units`` is the number of things one call handles (points, input or output
    cells), or a function of the call's result that counts them.  ``sample(frac)``
    gives the same call on a part of the input (see ``sampled``), run first so that
    a case far over the budget costs only small calls (see ``_probe``).

    Round-robin rather than case after case, so that a burst of load from other
    processes hits every row of a table alike.  Each case first runs once untimed
    (a warm-up: imports, caches, thread pools), which
    also counts its units.  A case that raises is dropped with a note, so that a
    missing function never stops the run.  A case whose probe or warm-up says one
    call takes over ``budget`` seconds keeps that one run instead of repeats
    (``"flag"``: "sample" or "once", with a note).  When the rounds would pass
    ``TABLE_BUDGET[0]`` seconds, fewer rounds run (with a note).

    Returns ``{key: {"wall", "cpu", "units"[, "flag"]}}``.
    """
    live: dict[Any, Callable[[], Any]] = {}
    warm: dict[Any, float] = {}
    units: dict[Any, int] = {}
    over: dict[Any, dict[str, Any]] = {}  # cases over the budget: their one (sample) run, flagged
    for key, case in cases.items():
        fn, count = case[0], case[1]
        try:
            if len(case) > 2:  # (fn, units, sample): probe on small parts of the input first
                probe = _probe(case[2], count, budget)
                if probe is not None:
                    over[key] = probe
                    note(f"{_name(key)}: 1/{probe['scale']:.0f} of the input took {probe['wall']:.2f} s, so one "
                         f"call would take ~{probe['wall'] * probe['scale']:.0f} s (over the {budget:g} s budget "
                         "per call): timed once on that sample only (marked *).")
                    continue
            wall, cpu, out = run_once(fn)
            units[key] = int(count(out) if callable(count) else count)
            del out
            if wall > budget and len(case) > 2:  # the probe said it fits: the first call may have compiled
                wall, cpu, _ = run_once(fn)
        except Exception as exc:  # a function not there yet, or a bug: skip, never crash
            note(f"{_name(key)}: failed ({type(exc).__name__}: {str(exc)[:200]}); skipped.")
            continue
        if wall > budget:
            note(f"{_name(key)}: one call took {wall:.1f} s (over the {budget:g} s budget per call): "
                 "that one untimed-warm-up run is reported (marked *), no repeats.")
            over[key] = {"wall": wall, "cpu": cpu, "units": units[key], "flag": "once"}
            continue
        live[key] = fn
        warm[key] = wall
    total = sum(warm.values())
    if repeat > 1 and total * repeat > TABLE_BUDGET[0]:
        fewer = max(1, int(TABLE_BUDGET[0] // max(total, 1e-9)))
        if fewer < repeat:
            note(f"a table of {len(live)} cases took {total:.0f} s per round: {fewer} rounds instead of {repeat} "
                 f"to stay within {TABLE_BUDGET[0]:g} s ({', '.join(_name(k) for k in live)[:200]}).")
            repeat = fewer
    walls: dict[Any, list[float]] = {k: [] for k in live}
    cpus: dict[Any, list[float]] = {k: [] for k in live}
    for _ in range(repeat):
        for key, fn in live.items():
            w, c, out = run_once(fn)
            del out
            walls[key].append(w)
            cpus[key].append(c)
    out = {k: {"wall": statistics.median(walls[k]), "cpu": statistics.median(cpus[k]), "units": units[k]}
           for k in live}
    out.update(over)
    return {k: out[k] for k in cases if k in out}  # in the order of the cases


def _probe(sample: Callable[[float], tuple[Callable[[], Any], float]], count: Any,
           budget: float) -> dict[str, Any] | None:
    """None if one full call looks within ``budget``, else the sample run that says it is not.

    ``sample(frac)`` gives ``(thunk, scale)``: the call on about ``frac`` of the input,
    and the input's size over the sample's.  First 1/1000, then, unless that is
    already ten times over, 1/20; a sample over the limit runs a second time (its
    first call may have compiled) before it counts.
    """
    for frac, limit in ((1e-3, 10 * budget), (0.05, budget)):
        thunk, scale = sample(frac)
        wall, cpu, out = run_once(thunk)
        if wall * scale > limit:  # again: the first call of a size may compile (e.g. a parallel path)
            wall, cpu, out = run_once(thunk)
        if wall * scale > limit:
            units = int(count(out) if callable(count) else count / scale)
            return {"wall": wall, "cpu": cpu, "units": max(units, 1), "flag": "sample", "scale": scale}
    return None


def _name(key: Any) -> str:
    return " / ".join(str(k) for k in key) if isinstance(key, tuple) else str(key)


# --------------------------------------------------------------------------- formatting


def fmt_ns(seconds_per_unit: float | None) -> str:
    """A time per unit with its unit: ns, us or ms."""
    if seconds_per_unit is None:
        return "-"
    ns = seconds_per_unit * 1e9
    if ns >= 1e6:
        return f"{ns / 1e6:.3g} ms"
    if ns >= 1e4:
        return f"{ns / 1e3:.3g} us"
    return f"{ns:.3g} ns" if ns < 100 else f"{ns:.0f} ns"


def fmt_ratio(r: float | None) -> str:
    if r is None:
        return "-"
    if r < 0.1:
        return f"{r:.2g}x"
    return f"{r:.2f}x" if r < 10 else f"{r:.0f}x"


def fmt_mb(b: float | None) -> str:
    if b is None:
        return "-"
    return "0 MiB" if abs(b) < 2**19 else f"{b / 2**20:,.0f} MiB"


# --------------------------------------------------------------------------- libraries


def try_import(name: str, dist: str | None = None):
    """The module, or None with a note (not installed, or a broken wheel)."""
    try:
        return importlib.import_module(name)
    except Exception as exc:
        note(f"{dist or name} is not available ({type(exc).__name__}: {exc}); its rows are skipped.")
        return None


def version(dist: str) -> str:
    try:
        return importlib.metadata.version(dist)
    except importlib.metadata.PackageNotFoundError:
        return "not installed"


def has_int_api() -> bool:
    """Whether ``dggs.latlng_to_cell(..., as_int=True)`` exists (the 64-bit id API)."""
    import dggs

    try:
        out = dggs.latlng_to_cell(np.array([0.0, 10.0]), np.array([0.0, 20.0]), 5, as_int=True)
    except TypeError:
        return False
    return isinstance(out, np.ndarray) and out.dtype == np.uint64


def thread_info() -> dict[str, Any]:
    """What this process's libraries use: dggs's default threads and the thread variables."""
    info: dict[str, Any] = {k: os.environ.get(k, "(unset)") for k in THREAD_VARS}
    for mod, fn in (("dggs", "get_num_threads"), ("dggs.geometry._parallel", "default_threads")):
        try:
            info["dggs_threads"] = getattr(importlib.import_module(mod), fn)()
            break
        except Exception:
            continue
    return info


def machine() -> dict[str, Any]:
    cpu = platform.machine()
    try:
        with open("/proc/cpuinfo") as fh:
            cpu = next((ln.split(":", 1)[1].strip() for ln in fh if ln.startswith("model name")), cpu)
    except OSError:
        pass
    mem = ""
    try:
        with open("/proc/meminfo") as fh:
            kb = int(next(ln.split()[1] for ln in fh if ln.startswith("MemTotal")))
            mem = f"{kb / 2**20:.0f} GiB"
    except (OSError, StopIteration):
        pass
    try:
        nproc = len(os.sched_getaffinity(0))
    except AttributeError:
        nproc = os.cpu_count()
    return {"cpu": cpu, "nproc": nproc, "mem": mem, "python": platform.python_version(),
            "numpy": np.__version__, "platform": platform.platform(),
            "versions": {d: version(d) for d in ("dggs", "h3", "h3ronpy", "healpy", "pya5",
                                                 "shapely", "pyproj", "pyarrow")}}


def code_state() -> dict[str, Any]:
    """The commit measured and whether the library tree has uncommitted changes (read-only git)."""
    def git(*a: str) -> str:
        try:
            return subprocess.run(["git", *a], cwd=ROOT, capture_output=True, text=True, timeout=30).stdout.rstrip()
        except (OSError, subprocess.SubprocessError):
            return ""

    head = git("rev-parse", "--short", "HEAD") or "unknown"
    dirty = [ln[3:] for ln in git("status", "--porcelain", "--", "dggs", "index", "storage", "pyproject.toml").splitlines()]
    return {"commit": head, "dirty": dirty}


def describe_code(state: dict[str, Any]) -> str:
    if not state["dirty"]:
        return f"commit {state['commit']}, library tree clean"
    shown = ", ".join(f"`{d}`" for d in state["dirty"][:12])
    more = f" and {len(state['dirty']) - 12} more" if len(state["dirty"]) > 12 else ""
    return f"commit {state['commit']}, library tree **dirty** (uncommitted: {shown}{more})"


def loadavg() -> list[float]:
    try:
        return [round(x, 2) for x in os.getloadavg()]
    except OSError:
        return [float("nan")] * 3


# --------------------------------------------------------------------------- against h3


def nearest_level(res: int, h3: Any) -> int:
    """The dggs level whose cell area is nearest H3's average at ``res`` (in log ratio)."""
    import math

    import dggs

    target = h3.average_hexagon_area(res, unit="m^2")
    table = dggs.level_table(dggs.MAX_LEVEL)
    return min(range(dggs.MAX_LEVEL + 1), key=lambda lv: abs(math.log(table[lv]["area_m2"] / target)))


def print_report(out: list[str], load0: list[float]) -> None:
    """Print a report's lines, then the load average at the start (``load0``) and now, then the notes."""
    out.append(f"Load average at the start and the end: {', '.join(f'{x:.2f}' for x in load0)}; "
               f"{', '.join(f'{x:.2f}' for x in loadavg())}.\n")
    out.append(notes_section())
    print("\n".join(out))


# --------------------------------------------------------------------------- ISEA against IVEA


def projection_args(doc: str, argv: list[str] | None, points: int, level: int) -> Any:
    """The options of a benchmark of ISEA against IVEA: ``--points``, ``--repeats``, ``--level``."""
    import argparse

    parser = argparse.ArgumentParser(description=doc.splitlines()[0])
    parser.add_argument("--points", type=int, default=points)
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--level", type=int, default=level)
    return parser.parse_args(argv)


def projection_table(cases: dict[Any, Any], repeats: int, heading: str) -> None:
    """Time ``cases`` keyed ``(operation, "ISEA" | "IVEA")`` and print IVEA's time over ISEA's (Markdown).

    The cases run in turn (:func:`interleaved`, 60 s a case at most); the table of ns per item follows
    ``heading``, the thread setting and the load average, then the notes, if any.
    """
    res = interleaved(cases, repeats, budget=60.0)
    print(f"{heading}, DGGS_THREADS={os.environ.get('DGGS_THREADS', 'unset')}, load average {loadavg()}\n")
    print("| operation | ISEA ns/item | IVEA ns/item | IVEA / ISEA |")
    print("|---|---:|---:|---:|")
    for op in dict.fromkeys(k[0] for k in cases):
        a, b = res.get((op, "ISEA")), res.get((op, "IVEA"))
        if a is None or b is None:
            continue
        ta, tb = a["wall"] / a["units"], b["wall"] / b["units"]
        print(f"| {op} | {fmt_ns(ta)} | {fmt_ns(tb)} | {tb / ta:.2f} |")
    if NOTES:
        print("\n" + notes_section())


# --------------------------------------------------------------------------- subprocesses


def thread_env(one_thread: bool, extra: dict[str, str] | None = None) -> dict[str, str]:
    """This environment without the thread variables, plus ONE_THREAD if asked, plus ``extra``."""
    env = {k: v for k, v in os.environ.items() if k not in THREAD_VARS}
    if one_thread:
        env.update(ONE_THREAD)
    env.update(extra or {})
    return env


def run_json(args: list[str], env: dict[str, str], timeout: float) -> dict[str, Any]:
    """Run ``python args...`` in a fresh interpreter; the JSON object on its last stdout line."""
    proc = subprocess.run([sys.executable, *args], env=env, cwd=ROOT, capture_output=True, text=True,
                          timeout=timeout)
    if proc.stderr:
        sys.stderr.write(proc.stderr[-3000:])
    if proc.returncode != 0:
        tail = " | ".join(proc.stderr.strip().splitlines()[-3:])
        raise RuntimeError(f"exit {proc.returncode}: {tail[-400:]}")
    return json.loads(proc.stdout.strip().splitlines()[-1])
