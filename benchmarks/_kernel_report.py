"""Markdown tables and the issue-18 targets (issue 9's where issue 18 kept them) from bench_kernel.py's JSON (no timing here)."""

from __future__ import annotations

from typing import Any

from _common import describe_code, fmt_mb, fmt_ns, fmt_ratio

MODES = (("one", "1 thread"), ("default", "default threads"))
DGGS_INT = "dggs (int ids)"
DGGS_STR = "dggs (string ids)"
TABLE_ORDER = ("point_to_cell", "levels", "cell_ops", "compact", "polyfill", "single")
RATIO_HEAD = "peer time / dggs time (>= 1x: dggs at least as fast)"


def _rows(res: dict[str, Any], mode: str, table: str) -> list[dict[str, Any]]:
    return res.get("modes", {}).get(mode, {}).get("tables", {}).get(table, {}).get("rows", [])


def per_unit(res: dict[str, Any], mode: str, table: str, op: str, impl: str, field: str = "wall") -> float | None:
    """Seconds per unit of the row whose op and impl start with ``op`` and ``impl``."""
    for r in _rows(res, mode, table):
        if r["op"].startswith(op) and r["impl"].startswith(impl) and r["units"]:
            return r[field] / r["units"]
    return None


def _ratio(res, mode, table, row) -> float | None:
    if not row.get("ref"):
        return None
    mine = per_unit(res, mode, table, row["op"], row["ref"])
    return None if mine is None else (row["wall"] / row["units"]) / mine


def render(res: dict[str, Any]) -> str:
    out: list[str] = []
    w = out.append
    m = res["machine"]
    w("### Kernel: dggs against h3ronpy, healpy, h3-py and A5 (bench_kernel.py)\n")
    v = m["versions"]
    w(f"{m['nproc']} cores ({m['cpu']}), Python {m['python']}, numpy {m['numpy']}; dggs {v['dggs']} (C core), "
      f"h3 {v['h3']}, h3ronpy {v['h3ronpy']}, healpy {v['healpy']}, pya5 {v['pya5']}, shapely "
      f"{v['shapely']}. Code measured: {describe_code(res['code'])}. Load average (1 min) {res['load_start'][0]:.2f} "
      f"at the start of bench_kernel.py, {res['load_end'][0]:.2f} at the end.\n")
    for mode, name in MODES:
        wk = res.get("modes", {}).get(mode)
        if not wk:
            w(f"- **{name}**: no numbers (the worker failed; see the notes).")
            continue
        t = wk["threads"]
        w(f"- **{name}**: dggs threads {t.get('dggs_threads', '?')}; "
          + ", ".join(f"{k}={t[k]}" for k in ("DGGS_THREADS", "NUMBA_NUM_THREADS", "RAYON_NUM_THREADS",
                                              "OMP_NUM_THREADS")) + f"; load average {wk['load'][0][0]:.2f} "
          f"at its start, {wk['load'][1][0]:.2f} at its end; int ids API present: {wk['int_api']}; "
          f"dggs imported from `{wk.get('dggs_path', '?')}`.")
    w(f"\nEvery timed table: median of {res['repeat']} runs after one untimed warm-up run, the cases of a "
      "table run in turn in each round (round-robin), wall time (`time.perf_counter`) and CPU time of the "
      "process (`time.process_time`, all threads; CPU > wall means several cores worked). Ratio = the peer's "
      "wall time per unit / dggs's wall time per unit in the same mode, so **>= 1x means dggs is at least as "
      "fast**. The 1-thread mode sets DGGS_THREADS, NUMBA_NUM_THREADS, RAYON_NUM_THREADS (h3ronpy), "
      "OMP_NUM_THREADS and OPENBLAS_NUM_THREADS to 1; the default mode unsets them. The two modes run in "
      "separate processes one after the other, so compare ratios within a mode.\n")
    for table in TABLE_ORDER:
        render_table(res, table, w)
    render_threads(res, w)
    render_rss(res, w)
    render_compile(res, w)
    notes = list(dict.fromkeys(res.get("notes", [])))
    if notes:
        w("#### Notes\n")
        for n in notes:
            w(f"- {n}")
        w("")
    return "\n".join(out) + "\n"


def render_table(res: dict[str, Any], table: str, w) -> None:
    info = next((res["modes"][m]["tables"][table] for m, _ in MODES
                 if table in res.get("modes", {}).get(m, {}).get("tables", {})), None)
    if info is None:
        w(f"#### {table}\n\nNo numbers (see the notes).\n")
        return
    unit = info["unit"]
    w(f"#### {info['title']}\n")
    head = f"| operation | implementation | {unit}s per timed run |"
    sep = "|---|---|---:|"
    for _, name in MODES:
        head += f" {name}: wall per {unit} | CPU per {unit} | {RATIO_HEAD} |"
        sep += "---:|---:|---:|"
    w(head)
    w(sep)
    flagged = False
    keys = list(dict.fromkeys((r["op"], r["impl"]) for m, _ in MODES for r in _rows(res, m, table)))
    for op, impl in keys:
        units = next((r["units"] for m, _ in MODES for r in _rows(res, m, table)
                      if (r["op"], r["impl"]) == (op, impl)), None)
        cells = [op, impl, f"{units:,}" if units else "-"]
        for mode, _ in MODES:
            r = next((x for x in _rows(res, mode, table) if (x["op"], x["impl"]) == (op, impl)), None)
            if r is None:
                cells += ["-", "-", "-"]
                continue
            ratio = _ratio(res, mode, table, r)
            star = " *" if r.get("flag") else ""
            cells += [fmt_ns(r["wall"] / r["units"]) + star, fmt_ns(r["cpu"] / r["units"]) + star,
                      fmt_ratio(ratio) if r.get("ref") else "(dggs)"]
        w("| " + " | ".join(cells) + " |")
        flagged = flagged or any(x.get("flag") for m, _ in MODES for x in _rows(res, m, table)
                                 if (x["op"], x["impl"]) == (op, impl))
    if flagged:
        w("\n\\* over the time budget per call: one run only (of the full input, or of a sample of it: see "
          "the notes), not a median.")
    w("")


def render_threads(res: dict[str, Any], w) -> None:
    th = res.get("threads")
    if not th:
        return
    w(f"#### Threads: point to cell on {th['points']:,} points, level 17 (h3ronpy res 9), each run a fresh "
      f"process, 1-thread and default processes alternating, median of {th['rounds']} rounds\n")
    w(f"Load average {th['load'][0][0]:.2f} at the start of this table, {th['load'][1][0]:.2f} at its end "
      "(a speed-up near 2x needs an idle second core).\n")
    w("| environment | dggs wall ms | dggs CPU ms | h3ronpy wall ms | h3ronpy CPU ms |")
    w("|---|---:|---:|---:|---:|")
    for mode, name in MODES:
        d = th.get(mode, {})
        w(f"| {name} | " + " | ".join(f"{d[k][f] * 1e3:.0f}" if k in d else "-"
                                      for k in ("dggs", "h3ronpy") for f in ("wall", "cpu")) + " |")
    sp = threads_speedup(res)
    hp = _speedup(th, "h3ronpy")
    w(f"| speed-up (1-thread wall / default wall) | {fmt_ratio(sp)} | | {fmt_ratio(hp)} | |\n")


def _speedup(th: dict[str, Any], impl: str) -> float | None:
    a, b = th.get("one", {}).get(impl), th.get("default", {}).get(impl)
    return a["wall"] / b["wall"] if a and b else None


def threads_speedup(res: dict[str, Any]) -> float | None:
    return _speedup(res.get("threads") or {}, "dggs")


def render_rss(res: dict[str, Any], w) -> None:
    rss = res.get("rss")
    if not rss:
        return
    w(f"#### Memory: peak RSS of point to cell on {rss['points']:,} points, level 17 / h3 res 9 / healpy "
      "nside 16384 (default threads, each in a fresh process)\n")
    resets = {d.get("reset") for d in rss["cases"].values() if "delta" in d}
    how = ("the peak mark reset to the current RSS just before the call (`/proc/self/clear_refs`)"
           if resets == {True} else "no reset of the peak mark (`/proc/self/clear_refs` not writable here)")
    w("Extra peak = `ru_maxrss` after the call minus `ru_maxrss` after the imports, the input arrays (made in "
      f"place) and a 200,000-point warm-up call, with {how}. Gap = that baseline minus the resident size just "
      "before the call: memory the call could use without raising the high-water mark (0 after a reset). "
      "Ratio = h3ronpy's extra peak / this row's, so **>= 1x means dggs uses at most as much** (the target, "
      "dggs <= 1.5x h3ronpy, is a ratio >= 0.67x).\n")
    w("| implementation | baseline | peak | extra peak | gap | output array | bytes per id | wall s | h3ronpy / this |")
    w("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    base = rss["cases"].get("h3ronpy", {}).get("delta")
    for impl, d in rss["cases"].items():
        if "error" in d or "skipped" in d:
            w(f"| {impl} | {'skipped' if 'skipped' in d else 'failed'}: {d.get('skipped', d.get('error', ''))[:120]} "
              "| | | | | | | |")
            continue
        ratio = base / d["delta"] if base and d["delta"] > 0 else None
        w(f"| {impl} | {fmt_mb(d['baseline'])} | {fmt_mb(d['peak'])} | {fmt_mb(d['delta'])} | {fmt_mb(d['gap'])} | "
          f"{fmt_mb(d['out_bytes'])} | {d['itemsize'] if d['itemsize'] else '-'} | {d['wall']:.2f} | "
          f"{fmt_ratio(ratio)} |")
    widths = rss.get("string_widths")
    if widths:
        w("\nBytes per id: uint64 ids 8 at every level; string ids are numpy `U` arrays, 4 bytes per character: "
          + ", ".join(f"level {lv} {b} bytes" for lv, b in widths.items())
          + ". h3ronpy's ids are arrow uint64 (8 bytes); a Python int id from h3-py is a 32-byte object, a "
            "15-character h3-py string 64 bytes (plus the list's 8-byte pointer).")
    w("")


def render_compile(res: dict[str, Any], w) -> None:
    c = res.get("compile")
    if not c:
        return
    w("#### First call in a fresh process, default threads\n")
    w(f"Two fresh processes in turn (the compiled core has no cache: both are alike; `bench_core.py` times a fresh "
      f"wheel install). ids: {c.get('kind', '?')}. Each number is one run (seconds, wall / CPU).\n")
    w("| cache | `import dggs` | first `latlng_to_cell` (1,000 points) | second call | first `grid_disk(ids, 1)` "
      "(100 cells) | second call |")
    w("|---|---:|---:|---:|---:|---:|")
    for name in ("cold", "warm"):
        d = c.get(name)
        if not d:
            continue
        if "error" in d:
            w(f"| {name} | failed: {d['error'][:150]} | | | | |")
            continue
        cells = [f"{d[k][0]:.2f} / {d[k][1]:.2f}" if d.get(k) else "-"
                 for k in ("import", "latlng_first", "latlng_second", "disk_first", "disk_second")]
        w(f"| {name} | " + " | ".join(cells) + " |")
    w("")


# --------------------------------------------------------------------------- targets


def _verdict(r: float | None, need: float) -> str:
    if r is None:
        return "n/a"
    return "**met**" if r >= need else "**missed**"


def targets(res: dict[str, Any]) -> list[dict[str, str]]:
    """Rows {target, need, one, one_verdict, default, default_verdict} for run_all.py's targets table."""
    rows: list[dict[str, str]] = []
    int_api = any(res.get("modes", {}).get(m, {}).get("int_api") for m, _ in MODES)
    prim = DGGS_INT if int_api else DGGS_STR
    kind_note = "" if int_api else " (string ids: no int API yet)"

    def both(target: str, need: float, table: str, op: str, peer: str, mine: str = prim) -> None:
        row = {"target": target, "need": f"ratio >= {need:.2g}"}
        for mode, _ in MODES:
            p, d = per_unit(res, mode, table, op, peer), per_unit(res, mode, table, op, mine)
            r = p / d if p is not None and d is not None else None
            row[mode] = "-" if r is None else f"{fmt_ratio(r)} (dggs {fmt_ns(d)}, peer {fmt_ns(p)}){kind_note}"
            row[mode + "_verdict"] = _verdict(r, need)
        rows.append(row)

    for lv, r in ((10, 5), (17, 9)):
        both(f"point to cell >= 2x h3ronpy, level {lv} vs res {r}", 2, "point_to_cell", f"level {lv} ", "h3ronpy",
             DGGS_INT if int_api else DGGS_STR)
        both(f"point to cell within 2x of healpy `ang2pix(nest=True)`, level {lv}", 0.5, "point_to_cell",
             f"level {lv} ", "healpy", DGGS_INT if int_api else DGGS_STR)
    for op, label in (("parent", "cell_to_parent"), ("children", "cell_to_children (per output cell)"),
                      ("disk k=1", "grid_disk k=1 (per output cell)"), ("disk k=5", "grid_disk k=5 (per output cell)"),
                      ("boundary", "cell_to_boundary (vs h3ronpy WKB polygons)")):
        both(f"{label} >= 1x h3ronpy, 100k level-17 cells", 1, "cell_ops", op, "h3ronpy")
    both("cell_to_polygon densify=0 >= 1.5x h3ronpy WKB + shapely.from_wkb", 1.5, "cell_ops", "polygon densify=0",
         "h3ronpy")
    both("cell_to_polygon default densify within 2x of h3ronpy WKB + shapely.from_wkb", 0.5, "cell_ops",
         "polygon default densify", "h3ronpy")
    both("compact_cells >= 1x h3ronpy `compact` (per input cell), level 15 vs res 8", 1, "compact", "compact", "h3ronpy")
    both("uncompact_cells >= 1x h3ronpy `uncompact` (per output cell), level 15 vs res 8", 1, "compact", "uncompact",
         "h3ronpy")
    for shape in ("box", "circle", "countries"):
        op = next((r["op"] for m, _ in MODES for r in _rows(res, m, "polyfill") if shape in r["op"]), shape)
        both(f"polygon_to_cells >= 1x h3ronpy (per output cell): {op}", 1, "polyfill", op, "h3ronpy")
    for op in ("latlng_to_cell", "cell_to_latlng", "cell_to_parent", "grid_disk(c, 1)"):
        for kind, peer, mine in (("string", "h3-py string API", DGGS_STR), ("int", "h3-py int API", DGGS_INT)):
            both(f"one call of `{op}` with {kind} ids >= 1x h3-py's (ratio = h3 ns / dggs ns)", 1, "single", op,
                 peer, mine + " one call")
    # memory (default threads only)
    rss = (res.get("rss") or {}).get("cases", {})
    dd, hd = rss.get("dggs-int", {}).get("delta"), rss.get("h3ronpy", {}).get("delta")
    r = hd / dd if dd and hd else None
    n = (res.get("rss") or {}).get("points", 0)
    rows.append({"target": f"peak RSS of point to cell on {n:,} points <= 1.5x h3ronpy's (ratio = h3ronpy / dggs int)",
                 "need": "ratio >= 0.67", "one": "-", "one_verdict": "-",
                 "default": "-" if r is None else f"{fmt_ratio(r)} ({fmt_mb(dd)} vs {fmt_mb(hd)})",
                 "default_verdict": _verdict(r, 1 / 1.5)})
    th = res.get("threads") or {}
    sp = threads_speedup(res)
    load = th.get("load", [[float("nan")], [float("nan")]])
    rows.append({"target": "point to cell, default threads vs 1 thread >= 1.7x (machine idle)", "need": "speed-up >= 1.7",
                 "one": "-", "one_verdict": "-",
                 "default": "-" if sp is None else f"{fmt_ratio(sp)} (load average {load[0][0]:.2f} -> {load[1][0]:.2f})",
                 "default_verdict": _verdict(sp, 1.7)})
    return rows


def render_targets(rows: list[dict[str, str]]) -> str:
    out = ["| target | needed | 1 thread: measured | verdict | default threads: measured | verdict |",
           "|---|---|---|---|---|---|"]
    for r in rows:
        out.append(f"| {r['target']} | {r['need']} | {r['one']} | {r['one_verdict']} | {r['default']} | "
                   f"{r['default_verdict']} |")
    verdicts = [r[k] for r in rows for k in ("one_verdict", "default_verdict")]
    out.append(f"\n{verdicts.count('**met**')} met, {verdicts.count('**missed**')} missed, "
               f"{verdicts.count('n/a')} not measured (n/a). Ratios: the peer's time / dggs's time per unit, so "
               "**>= 1x means dggs is at least as fast** (the speed-up row: 1-thread time / default time).")
    return "\n".join(out) + "\n"
