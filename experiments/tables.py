"""Text tables: our chapter-6 numbers beside the thesis's (Tables 6.1-6.7).

Examples
--------
>>> from dggs.experiments.schemes import run_scheme
>>> print(format_scheme("1:4", run_scheme("1:4", 1)).splitlines()[0])
Split (1:4), §6.1.1 - ours (dggs) vs thesis; = reproduced, ~ close, x differs
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

from dggs.experiments.metrics import LevelMetrics
from dggs.experiments.reproduction import SYMBOLS, Mark, mark, thesis_value
from dggs.experiments.schemes import SCHEMES, THESIS_SCHEMES, get_scheme
from dggs.experiments.thesis_tables import (
    DGGS_BEST_MAX_FACE_ERROR_PCT,
    TABLE_6_6,
    TABLES_6,
)

__all__ = ["COLUMNS", "format_scheme", "format_all_tables", "format_dggs_row", "run_all"]

#: (table number, attribute, number format) for each metric column.
COLUMNS: tuple[tuple[str, str, str], ...] = (
    ("6.2", "faces", "{:d}"),
    ("6.1", "area_deviation_pct", "{:.2e}"),
    ("6.3", "avg_displacement_pct", "{:.2f}"),
    ("6.4", "max_displacement_pct", "{:.2f}"),
    ("6.5", "avg_displacement_km", "{:.2f}"),
    ("6.6", "max_face_error_pct", "{:.2f}"),
    ("6.7", "max_face_error_km2", "{:.3g}"),
)


def _thesis(table: str, key: str, level: int) -> float | None:
    return thesis_value(table, key, level)


def _fmt(fmt: str, x: float | int | None) -> str:
    if x is None:
        return "-"
    if fmt == "{:d}":
        return fmt.format(int(x))
    if fmt == "{:.2e}" and abs(x) >= 1e-3:  # Table 6.1: the thesis prints 55.78, not 5.58e+01
        return f"{x:.2f}"
    return fmt.format(x)


def _cell(table: str, fmt: str, key: str, r: LevelMetrics, variant: str) -> tuple[str, Mark]:
    value = getattr(r, COLUMNS_BY_TABLE[table])
    m = mark(table, key, r.level, float(value), variant)
    return _fmt(fmt, value) + SYMBOLS[m.status], m


COLUMNS_BY_TABLE = {t: a for t, a, _ in COLUMNS}


def format_scheme(key: str, rows: Sequence[LevelMetrics], variant: str = "dggs") -> str:
    """One scheme's levels, each metric as ``ours<mark> (thesis)``; marks ``=`` reproduced, ``~`` close, ``x`` differs.

    Examples
    --------
    >>> from dggs.experiments.schemes import run_scheme
    >>> "13.42= (13.42)" in format_scheme("1:4", run_scheme("1:4", 1))
    True
    """
    scheme = get_scheme(key, variant)
    who = "thesis's rule" if scheme.variant == "thesis" else ("dggs" if scheme.key in SCHEMES else "ch. 7, ours")
    head = ["level"] + [f"T{t} {a}" for t, a, _ in COLUMNS]
    lines = [f"{scheme.title} - ours ({who}) vs thesis; = reproduced, ~ close, x differs", "  ".join(head)]
    notes: dict[str, list[str]] = {}
    for r in rows:
        cells = [str(r.level)]
        for table, _, fmt in COLUMNS:
            text, m = _cell(table, fmt, scheme.key, r, scheme.variant)
            cells.append(f"{text} ({_fmt(fmt, _thesis(table, scheme.key, r.level))})")
            if m.status in ("close", "differs"):
                notes.setdefault(f"{m.status}: {m.note}" if m.status == "differs" else "close", []).append(
                    f"T{table} L{r.level}" + (f" {m.note}" if m.status == "close" else ""))
        lines.append("  ".join(cells))
    for what, where in notes.items():
        lines.append(f"  {what} - {', '.join(where)}")
    return "\n".join(lines)


def _levels_text(levels: list[int]) -> str:
    """``[2, 3, 4, 7]`` -> ``"L2-L4, L7"``."""
    runs: list[list[int]] = []
    for level in levels:
        if runs and level == runs[-1][-1] + 1:
            runs[-1].append(level)
        else:
            runs.append([level])
    return ", ".join(f"L{r[0]}" if len(r) == 1 else f"L{r[0]}-L{r[-1]}" for r in runs)


def format_all_tables(
    results: dict[str, Sequence[LevelMetrics]],
    thesis_results: dict[str, Sequence[LevelMetrics]] | None = None,
) -> str:
    """Tables 6.1-6.7, one block per table: per scheme the printed row, the thesis's rule and dggs's.

    Every computed cell carries a mark (``=`` reproduced, ``~`` close, ``x``
    differs) and each block ends with the differences and their reasons
    (:mod:`dggs.experiments.reproduction`); a summary follows the tables.

    Parameters
    ----------
    results : dict
        Scheme key -> metrics for levels ``0..n`` with dggs's rules.
    thesis_results : dict, optional
        Scheme key -> metrics with the thesis's rules, for the schemes where
        they differ (:data:`~dggs.experiments.schemes.THESIS_SCHEMES`).

    Examples
    --------
    >>> from dggs.experiments.schemes import run_scheme
    >>> text = format_all_tables({"1:3": run_scheme("1:3", 2)})
    >>> "Table 6.6" in text and "33.73=" in text
    True
    """
    thesis_results = thesis_results or {}
    out = []
    counts: dict[str, dict[str, int]] = {"thesis's rules": {}, "dggs": {}}
    for table, _attr, fmt in COLUMNS:
        caption = TABLES_6[table][0]
        width = max(len(v) for v in [*results.values(), *thesis_results.values()]) - 1
        lines = [
            f"Table {table}: {caption}   (= reproduced, ~ close, x differs)",
            f"{'scheme':<28}" + "".join(f"{'L' + str(i):>12}" for i in range(1, width + 1)),
        ]
        notes = []
        for key in [*SCHEMES, *(k for k in results if k not in SCHEMES)]:
            variants = []
            if key in thesis_results:
                variants.append(("thesis", thesis_results[key]))
            if key in results:
                variants.append(("dggs", results[key]))
            if not variants:
                continue
            n = max(len(rows) for _, rows in variants) - 1
            printed = [_fmt(fmt, _thesis(table, key, level)) for level in range(1, n + 1)]
            if key in SCHEMES:
                lines.append(f"{key + ' printed':<28}" + "".join(f"{c:>12}" for c in printed))
            for variant, rows in variants:
                if variant == "thesis":
                    label = "thesis's rule"
                elif key in THESIS_SCHEMES:
                    label = "dggs"
                elif key not in SCHEMES:
                    label = "(ch. 7, ours)"
                else:
                    label = "ours = thesis's"
                tally = counts["dggs" if label in ("dggs", "(ch. 7, ours)") else "thesis's rules"]
                cells, by_note, close = [], {}, []
                for r in rows[1:]:
                    text, m = _cell(table, fmt, key, r, variant)
                    cells.append(text)
                    if m.status:
                        tally[m.status] = tally.get(m.status, 0) + 1
                    noted = m.status in ("reproduced", "close") and "rounding" in m.note
                    if m.status == "differs" or noted:
                        by_note.setdefault((m.status, m.note), []).append(r.level)
                    elif m.status == "close":
                        close.append(f"L{r.level} {m.note}")
                lines.append(f"{key + ' ' + label:<28}" + "".join(f"{c:>12}" for c in cells))
                if close:
                    notes.append(f"  {key} {label}: close - {', '.join(close)}")
                for (status, note), levels in by_note.items():
                    notes.append(f"  {key} {label} {_levels_text(levels)}: {status} - {note}")
        out.append("\n".join(lines + notes))
    summary = ["Summary (cells with a printed value):"]
    for who, tally in counts.items():
        if tally:
            summary.append(
                f"  {who}: " + ", ".join(f"{tally.get(k, 0)} {k}" for k in ("reproduced", "close", "differs"))
            )
    out.append("\n".join(summary))
    return "\n\n".join(out)


def format_dggs_row(rows: Sequence[LevelMetrics], densify: int) -> str:
    """The dggs grid's maximum face error beside the thesis's best (Split 2:6).

    Examples
    --------
    >>> from dggs.experiments.schemes import run_scheme
    >>> "dggs grid" in format_dggs_row(run_scheme("2:6", 1), 8)
    True
    """
    best = TABLE_6_6["2:6"]
    lines = [
        f"dggs grid (Snyder-mapped Split 2:6, spherical areas, densify={densify}) "
        f"vs thesis Split (2:6) mesh (the thesis's own placement); thesis best = "
        f"{DGGS_BEST_MAX_FACE_ERROR_PCT} % at level 7",
        "level  faces  area dev %   max face err % (thesis 2:6)   max face err km^2",
    ]
    for r in rows:
        t = best[r.level - 1] if 1 <= r.level <= len(best) else None
        lines.append(
            f"{r.level:>5}  {r.faces:>5}  {r.area_deviation_pct:>10.2e}   "
            f"{r.max_face_error_pct:>14.3e} ({_fmt('{:.2f}', t):>6})   {r.max_face_error_km2:>12.3g}"
        )
    lines.append(
        "  The cells are exactly equal-area; what remains is the boundary sampling (chords between "
        f"{densify} points per curved edge), which shrinks as 1/densify^2."
    )
    return "\n".join(lines)


def run_all(
    levels: Callable[[str], int] | None = None, progress: bool = False, variant: str = "dggs"
) -> dict[str, list[LevelMetrics]]:
    """Run every scheme to its thesis depth (or ``levels(key)``).

    With ``variant="thesis"`` only the schemes whose thesis rule differs from
    dggs's are run (:data:`~dggs.experiments.schemes.THESIS_SCHEMES`).

    Examples
    --------
    >>> r = run_all(lambda k: 1)
    >>> sorted(r) == sorted(SCHEMES)
    True
    """
    from dggs.experiments.schemes import run_scheme

    chosen = THESIS_SCHEMES if variant == "thesis" else SCHEMES
    return {
        k: run_scheme(s, s.thesis_levels if levels is None else levels(k), progress)
        for k, s in chosen.items()
    }
