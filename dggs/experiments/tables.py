"""Text tables: our chapter-6 numbers beside the thesis's (Tables 6.1-6.7).

Examples
--------
>>> from dggs.experiments.schemes import run_scheme
>>> print(format_scheme("1:4", run_scheme("1:4", 1)).splitlines()[0])
Split (1:4), §6.1.1 - ours vs thesis
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

from dggs.experiments.metrics import LevelMetrics
from dggs.experiments.schemes import SCHEMES, get_scheme
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
    row = TABLES_6[table][1].get(key, ())
    return row[level - 1] if 1 <= level <= len(row) else None


def _fmt(fmt: str, x: float | int | None) -> str:
    if x is None:
        return "-"
    return fmt.format(int(x)) if fmt == "{:d}" else fmt.format(x)


def format_scheme(key: str, rows: Sequence[LevelMetrics]) -> str:
    """One scheme's levels, each metric as ``ours (thesis)``.

    Examples
    --------
    >>> from dggs.experiments.schemes import run_scheme
    >>> "13.42 (13.42)" in format_scheme("1:4", run_scheme("1:4", 1))
    True
    """
    scheme = get_scheme(key)
    head = ["level"] + [f"T{t} {a}" for t, a, _ in COLUMNS]
    lines = [f"{scheme.title} - ours vs thesis", "  ".join(head)]
    for r in rows:
        cells = [str(r.level)]
        for table, attr, fmt in COLUMNS:
            cells.append(f"{_fmt(fmt, getattr(r, attr))} ({_fmt(fmt, _thesis(table, scheme.key, r.level))})")
        lines.append("  ".join(cells))
    return "\n".join(lines)


def format_all_tables(results: dict[str, Sequence[LevelMetrics]]) -> str:
    """Tables 6.1-6.7, one block per table, rows ``ours`` and ``thesis`` per scheme.

    Parameters
    ----------
    results : dict
        Scheme key -> metrics for levels ``0..n``.

    Examples
    --------
    >>> from dggs.experiments.schemes import run_scheme
    >>> text = format_all_tables({"1:3": run_scheme("1:3", 2)})
    >>> "Table 6.6" in text and "33.73" in text
    True
    """
    out = []
    for table, attr, fmt in COLUMNS:
        caption = TABLES_6[table][0]
        width = max(len(v) for v in results.values()) - 1
        lines = [f"Table {table}: {caption}", "scheme               " + "".join(f"{'L' + str(i):>11}" for i in range(1, width + 1))]
        for key, rows in results.items():
            ours = [_fmt(fmt, getattr(r, attr)) for r in rows[1:]]
            theirs = [_fmt(fmt, _thesis(table, key, r.level)) for r in rows[1:]]
            lines.append(f"{key + ' ours':<21}" + "".join(f"{c:>11}" for c in ours))
            lines.append(f"{key + ' thesis':<21}" + "".join(f"{c:>11}" for c in theirs))
        out.append("\n".join(lines))
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
        f"vs thesis Split (2:6) mesh; thesis best = {DGGS_BEST_MAX_FACE_ERROR_PCT} % at level 7",
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


def run_all(levels: Callable[[str], int] | None = None, progress: bool = False) -> dict[str, list[LevelMetrics]]:
    """Run every scheme to its thesis depth (or ``levels(key)``).

    Examples
    --------
    >>> r = run_all(lambda k: 1)
    >>> sorted(r) == sorted(SCHEMES)
    True
    """
    from dggs.experiments.schemes import run_scheme

    return {
        k: run_scheme(k, s.thesis_levels if levels is None else levels(k), progress)
        for k, s in SCHEMES.items()
    }
