"""Plain-Python reference computations for the storage tests.

Everything here works on lists of dicts with the grid API only (never the
store under test), so the tests compare the store against brute force.
"""

from __future__ import annotations

import csv
import math
from collections import defaultdict
from pathlib import Path
from typing import Any

import numpy as np

import dggs


def clustered_points(rng: np.random.Generator, n: int, centres: int = 5, spread: float = 0.5):
    """``n`` points around a few random centres (so cells hold several points)."""
    clat = np.degrees(np.arcsin(rng.uniform(-0.95, 0.95, centres)))
    clng = rng.uniform(-180, 180, centres)
    pick = rng.integers(0, centres, n)
    lat = np.clip(clat[pick] + rng.normal(0, spread, n), -89.9, 89.9)
    lng = (clng[pick] + rng.normal(0, spread, n) + 180) % 360 - 180
    return lat, lng


def write_csv(path: Path, header: list[str], rows: list[list[Any]]) -> Path:
    with open(path, "w", newline="") as fh:
        writer = csv.writer(fh)
        writer.writerow(header)
        writer.writerows(rows)
    return path


def expected_rows(lat, lng, level: int, values: dict[str, list] | None = None) -> list[dict]:
    """The rows a store should hold: one per point, with its cell at ``level``."""
    cells = dggs.latlng_to_cell(np.asarray(lat, float), np.asarray(lng, float), level)
    out = []
    for i, cell in enumerate(np.atleast_1d(cells).tolist()):
        row = {"cell": cell, "lat": float(lat[i]), "lng": float(lng[i]), "row": i + 1}
        for name, col in (values or {}).items():
            row[name] = col[i]
        out.append(row)
    return out


def brute_aggregate(rows: list[dict], level: int, column: str | None) -> dict[str, dict]:
    """count/sum/mean/min/max per ancestor at ``level`` (NULLs ignored, as SQL)."""
    groups: dict[str, list] = defaultdict(list)
    counts: dict[str, int] = defaultdict(int)
    for row in rows:
        key = row["cell"][: level + 1]
        counts[key] += 1
        if column is not None and row[column] is not None:
            groups[key].append(row[column])
    out = {}
    for key, n in counts.items():
        vals = groups.get(key, [])
        out[key] = {
            "count": n,
            "sum": sum(vals) if vals else None,
            "mean": (math.fsum(vals) / len(vals)) if vals else None,
            "min": min(vals) if vals else None,
            "max": max(vals) if vals else None,
        }
    return out


def under(rows: list[dict], cells, level: int) -> list[dict]:
    """Rows whose ancestor at ``level`` is one of ``cells``."""
    wanted = set(np.asarray(cells).tolist())
    return [r for r in rows if r["cell"][: level + 1] in wanted]


def key(row: dict, columns=("cell", "row")) -> tuple:
    return tuple(row[c] for c in columns)


class FSum:
    """A SQLite aggregate: the correctly rounded sum of the non-NULL values (``math.fsum``), NULL if none.

    The rule of a REAL column's sum (:mod:`dggs.storage.rollup_columns`), for oracles written in SQL:
    ``fsum(c)`` for its sum and ``fsum(c) / count(c)`` for its mean.
    """

    def __init__(self) -> None:
        self.values: list[float] = []

    def step(self, value: Any) -> None:
        if value is not None:
            self.values.append(value)

    def finalize(self) -> float | None:
        return math.fsum(self.values) if self.values else None


def stat_sql(stat: str, column: str | None, kind: str | None) -> str:
    """The SQL of ``stat`` over ``column`` as the store's roll-ups define it (REAL sums: correctly rounded)."""
    c = f'"{column}"'
    if kind == "REAL" and stat in ("sum", "mean"):
        return f"fsum({c})" if stat == "sum" else f"fsum({c}) / count({c})"
    return {"count": "count(*)", "sum": f"sum({c})", "mean": f"avg({c})", "min": f"min({c})", "max": f"max({c})"}[stat]
