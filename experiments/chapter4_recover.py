"""Chapter 4: recovering the thesis's fitting procedure, and Tables 4.1 and 4.3 marked cell by cell.

The thesis (§4.1.2) says only that Figure 4.1 and Table 4.1 come from
gnuplot 4.2's ``fit`` of the azimuth after Newton-Raphson against the
initial azimuth, "evaluating for each possible angle" over "a fixed angular
range (60 degrees for the equilateral triangle ...)".  It gives neither the
sample, the weights, the range nor the unit.  :data:`PROCEDURES` are the
readings its text allows; each is fitted at degrees 1-7 exactly as gnuplot
would (unweighted least squares unless stated, ``var = WSSR / (N - p)``)
and scored by the root mean square of ``ln(ours / printed)`` over the 14
printed cells.  :func:`best_procedure` keeps the one that matches best.

A cell is marked (:func:`mark_cell`):

``reproduced``
    ours rounds to the printed value (three significant digits in Table
    4.1, four in Table 4.3);
``close``
    within 1 %;
``differs``
    anything else, with the reason.

Why no procedure reproduces Table 4.1: ``Az(Az') - Az'`` is odd about
``Az' = 60`` degrees (and about 0), so over any sample symmetric about 60
degrees an even degree fits exactly as well as the odd degree below it
(:func:`symmetric_even_gain`; tested with random symmetric samples).  The
thesis's even degrees are 10-22 % better than the odd degree below: its
sample was not symmetric, and nothing in the text says how.

Examples
--------
>>> mark_cell(2.30e-04, 2.304e-04, 3).status
'reproduced'
>>> mark_cell(2.30e-04, 2.318e-04, 3).status
'close'
>>> mark_cell(2.30e-04, 2.40e-04, 3).status
'differs'
>>> best_procedure()
'area-120'
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from functools import lru_cache
from typing import Any, NamedTuple

import numpy as np

from dggs.experiments.chapter4_constants import _HALF, _SECTOR, _SECTOR_AREA, THESIS_TABLE_4_1, THESIS_TABLE_4_3
from dggs.experiments.chapter4_fits import exact_az, implied_sample_size, sector_samples
from dggs.experiments.chapter4_mesh import face_mesh
from dggs.geometry import snyder

__all__ = [
    "CellMark",
    "mark_cell",
    "Procedure",
    "PROCEDURES",
    "procedure_fits",
    "procedure_score",
    "best_procedure",
    "symmetric_even_gain",
    "table_4_1_marks",
    "table_4_3_marks",
    "TABLE_4_3_COLUMNS",
    "DEGREE_2_NOTE",
]


class CellMark(NamedTuple):
    """One printed cell against ours: status ``reproduced``, ``close`` or ``differs``, and why."""

    printed: float
    ours: float
    rel_diff: float
    status: str
    reason: str


def mark_cell(printed: float, ours: float, digits: int, reason: str = "") -> CellMark:
    """Mark one cell: ``reproduced`` (ours rounds to the printed ``digits`` significant digits), ``close``
    (within 1 %) or ``differs`` (``reason`` is kept for ``close`` and ``differs`` only).

    Parameters
    ----------
    printed, ours : float
        The thesis's value as printed and ours, in the same unit.
    digits : int
        Significant digits printed (3 in Table 4.1, 4 in Table 4.3).
    reason : str
        Why ours differs (kept unless the cell is reproduced).

    Examples
    --------
    >>> mark_cell(6.193e-04, 6.1934e-04, 4).status
    'reproduced'
    >>> mark_cell(1.00, 0.996, 3).status   # 1.00e+00 holds 0.9995 .. 1.005: 0.996 prints as 9.96e-01
    'close'
    >>> m = mark_cell(1.19, 1.154, 3, "another sample")
    >>> m.status, round(m.rel_diff, 4), m.reason
    ('differs', -0.0303, 'another sample')
    """
    def unit(x: float) -> float:  # the last printed digit's unit of a number like x
        return 10.0 ** (math.floor(math.log10(abs(x))) - (digits - 1))

    # the rounding interval of the printed value: below a power of ten (1.00e+00) it is ten times narrower
    lo = printed - 0.5 * unit(printed * (1 - 1e-12)) * math.copysign(1, printed)
    hi = printed + 0.5 * unit(printed) * math.copysign(1, printed)
    rel = ours / printed - 1.0
    if min(lo, hi) <= ours < max(lo, hi):
        return CellMark(printed, ours, rel, "reproduced", "")
    return CellMark(printed, ours, rel, "close" if abs(rel) <= 0.01 else "differs", reason)


# ----------------------------------------------------------------------------
# The procedures the text allows
# ----------------------------------------------------------------------------
@dataclass(frozen=True)
class Procedure:
    """One reading of §4.1.2: how ``Az'`` is sampled and weighted, over which range, in which unit."""

    description: str
    sample: Callable[[int], tuple[np.ndarray, np.ndarray | None]]
    unit: float = 1.0  # multiplies the azimuths (180 / pi for degrees)
    model: str = "full"  # "full": P(Az') of degree d; "origin": no constant term; "swap": Az' ~ P(Az)


def _area_weights(ap: np.ndarray) -> np.ndarray:
    """Swept face area per unit ``Az'`` (the face points' density), scaled to mean 1."""
    d = (snyder.R_PRIME * snyder.TAN_G) / (np.cos(ap) + np.sin(ap) * snyder.COT_THETA)
    return d * d / np.mean(d * d)


def _grid(q: int) -> np.ndarray:
    """``Az'`` of the vertices of the thesis's quality-``q`` triangulated face, reduced to the sector."""
    p, _ = face_mesh(q)
    ap = np.mod(np.arctan2(p[:, 0], p[:, 1]), 2.0 * math.pi)
    return np.sort(ap - np.minimum(ap // _SECTOR, 2) * _SECTOR)


def _half_area(n: int) -> np.ndarray:
    area = (np.arange(n) + 0.5) / n * 0.5 * _SECTOR_AREA
    rt2 = (snyder.R_PRIME * snyder.TAN_G) ** 2
    return np.arctan2(2.0 * area, rt2 - 2.0 * snyder.COT_THETA * area)


#: The readings of §4.1.2 tried, by name.
PROCEDURES: dict[str, Procedure] = {
    "area-120": Procedure("Az' over the 120-degree sector at equal steps of swept face area (face points)",
                          lambda n: (sector_samples(n, "area"), None)),
    "uniform-120": Procedure("Az' at equal steps over the 120-degree sector ('each possible angle')",
                             lambda n: (sector_samples(n, "uniform"), None)),
    "weighted-120": Procedure("equal steps over 120 degrees, least squares weighted by the swept face area",
                              lambda n: (sector_samples(n, "uniform"), _area_weights(sector_samples(n, "uniform")))),
    "grid-107": Procedure("the vertices of the quality-107 triangulated face (5,886 points, the grid nearest N)",
                          lambda n: (_grid(107), None)),
    "uniform-60": Procedure("equal steps over 0-60 degrees (the text's '60 degrees'; mirrored at 60)",
                            lambda n: (sector_samples(n, "half"), None)),
    "area-60": Procedure("equal steps of swept area over 0-60 degrees", lambda n: (_half_area(n), None)),
    "area-120-degrees": Procedure("as area-120, azimuths in degrees", lambda n: (sector_samples(n, "area"), None),
                                  180.0 / math.pi),
    "origin-area-120": Procedure("as area-120, the polynomial through Az(0) = 0 (no constant term)",
                                 lambda n: (sector_samples(n, "area"), None), model="origin"),
    "origin-uniform-120": Procedure("as uniform-120, the polynomial through Az(0) = 0 (no constant term)",
                                    lambda n: (sector_samples(n, "uniform"), None), model="origin"),
    "swap-area-120": Procedure("as area-120, the roles swapped: Az' ~ P(Az)", lambda n: (sector_samples(n, "area"), None),
                               model="swap"),
}


@lru_cache(maxsize=32)
def procedure_fits(name: str, n: int | None = None) -> tuple[tuple[float, float], ...]:
    """``(SS, var)`` of degrees 1-7 under procedure ``name`` (gnuplot's WSSR and WSSR / (N - p)).

    Examples
    --------
    >>> ss1, var1 = procedure_fits("area-120")[0]
    >>> round(ss1 / var1) + 2   # N
    5871
    """
    if name not in PROCEDURES:
        raise KeyError(f"unknown procedure {name!r}; choose one of {', '.join(PROCEDURES)}")
    proc = PROCEDURES[name]
    ap, w = proc.sample(implied_sample_size() if n is None else n)
    x, y = ap * proc.unit, exact_az(ap) * proc.unit
    if proc.model == "swap":
        x, y = y, x
    t = (x - 0.5 * (x.min() + x.max())) / (0.5 * (x.max() - x.min())) if proc.model != "origin" else x
    sw = np.ones_like(t) if w is None else np.sqrt(w)
    out = []
    for d in range(1, 8):
        vander = np.vander(t, d + 1)[:, :-1] if proc.model == "origin" else np.vander(t, d + 1)
        coeffs, *_ = np.linalg.lstsq(vander * sw[:, None], y * sw, rcond=None)
        r = (y - vander @ coeffs) * sw
        ss = float(r @ r)
        out.append((ss, ss / (len(t) - vander.shape[1])))
    return tuple(out)


def procedure_score(name: str) -> float:
    """RMS of ``ln(ours / printed)`` over the 14 cells of Table 4.1 (0 would reproduce it)."""
    logs = [math.log(o / p) for d, pair in enumerate(procedure_fits(name), 1)
            for o, p in zip(pair, THESIS_TABLE_4_1[d], strict=True)]
    return math.sqrt(sum(v * v for v in logs) / len(logs))


def best_procedure() -> str:
    """The procedure of :data:`PROCEDURES` that matches Table 4.1 best (lowest :func:`procedure_score`)."""
    return min(PROCEDURES, key=procedure_score)


def symmetric_even_gain(ap: np.ndarray, degree: int) -> float:
    """``SS(degree) / SS(degree - 1)`` for an even ``degree`` fitted over ``ap`` mirrored about 60 degrees.

    1 for every symmetric sample (``Az - Az'`` is odd about 60 degrees): an even
    degree gains nothing over the odd degree below it.
    """
    x = np.concatenate([ap, _SECTOR - ap])
    az = exact_az(x)
    t = (x - _HALF) / _HALF
    ss = []
    for d in (degree - 1, degree):
        vander = np.vander(t, d + 1)
        coeffs, *_ = np.linalg.lstsq(vander, az, rcond=None)
        r = az - vander @ coeffs
        ss.append(float(r @ r))
    return ss[1] / ss[0]


# ----------------------------------------------------------------------------
# The marks
# ----------------------------------------------------------------------------
def _reason_4_1(degree: int, name: str) -> str:
    ss = THESIS_TABLE_4_1
    if degree % 2 == 0:
        gain = 100.0 * (1.0 - ss[degree][0] / ss[degree - 1][0])
        text = (f"the thesis's degree {degree} is {gain:.0f} % below its degree {degree - 1}; over any sample "
                "symmetric about 60 deg (every reading the text allows) a full polynomial of even degree gains "
                "nothing, so its sample was asymmetric in a way the text does not give (a polynomial without "
                "constant term gains 8-25 % but doubles every SS)")
    else:
        text = (f"the thesis's sample, weights and Newton stop are not given; {name} is the closest reading found, "
                "and the sample's density cannot close the gap (the variance column moves < 0.4 % from 2,000 "
                "to 20,000 points)")
    return text + "; " + DEGREE_2_NOTE if degree == 2 else text


#: Degree 2's printed pair disagrees with the other rows on N (gnuplot: var = SS / (N - p)).
DEGREE_2_NOTE = (f"its SS / var implies N = {THESIS_TABLE_4_1[2][0] / THESIS_TABLE_4_1[2][1] + 3:,.0f} against "
                 "5,853-5,893 for the other degrees, so one of the pair is misprinted (9.72e-01 would give 5,858)")


def table_4_1_marks(name: str | None = None) -> list[dict[str, Any]]:
    """Table 4.1 cell by cell under procedure ``name`` (default: :func:`best_procedure`).

    Returns
    -------
    list of dict
        ``degree``, ``column`` (``"SS"`` or ``"var"``), ``procedure`` and the
        fields of :class:`CellMark`.
    """
    name = best_procedure() if name is None else name
    rows = []
    for d, pair in enumerate(procedure_fits(name), 1):
        for col, ours, printed in zip(("SS", "var"), pair, THESIS_TABLE_4_1[d], strict=True):
            m = mark_cell(printed, ours, 3, _reason_4_1(d, name))
            rows.append({"degree": d, "column": col, "procedure": name, **m._asdict()})
    return rows


#: Table 4.3's columns: (name, our error_rows key, our reading of the printed column, reason it differs).
TABLE_4_3_COLUMNS = (
    ("avg dist", "dist_avg", "mean great-circle distance in radius units: the printed number read as a fraction "
     "of R (597 m), not as the thesis's own % (5.9 m), which no cubic reaches (its residual alone moves "
     "points by hundreds of metres)",
     "the thesis's average grows with quality (9.379 -> 9.490e-05) where ours falls (8.5 -> 7.5e-05) under "
     "every reading tried (per vertex, per triangle corner, per centroid; every procedure's cubic): its "
     "cubic, and so its error field over the face, is not ours"),
    ("max dist", "dist_max", "maximum great-circle distance in radius units, at a point of the quality-25 grid "
     "(the same at every quality, as the thesis's)",
     "the maximum sits where the cubic's residual times the distance from the face centre is largest: a "
     "different cubic moves it"),
    ("avg area %", "area_abs_avg_pct", "mean of |dA| / A over the quality triangles, in %",
     "no reading found: the thesis's column falls as 1/q^1.75 and is 1e4-1e5 times below our relative "
     "error, which grows with q; its definition is not given (its own 713.5 m^2 at quality 100 matches no "
     "triangle of that quality)"),
    ("max area %", "area_max_pct", "maximum of |dA| / A, in %, read against the printed value times 100 "
     "(a fraction labelled %, like the distances)",
     "read as a fraction the column grows with quality like ours (1.6 -> 5.1 % against ours 1.1 -> 5.8 %), "
     "but more slowly: the cubic is not the thesis's"),
)


def table_4_3_marks(error_rows: list[dict[str, Any]] | None = None) -> list[dict[str, Any]]:
    """Table 4.3 cell by cell: the printed cubic rows against our degree-3 ``"thesis"`` rows.

    Parameters
    ----------
    error_rows : list of dict, optional
        :func:`dggs.experiments.chapter4_errors.error_rows` output with degree 3
        (default: computed).  Its ``"thesis"`` cubic is the ``area-120`` fit,
        the best reading of Table 4.1 (:func:`best_procedure`).

    Returns
    -------
    list of dict
        ``quality``, ``column``, ``reading`` (how we read the printed column)
        and the fields of :class:`CellMark`.
    """
    if error_rows is None:
        from dggs.experiments.chapter4_errors import error_rows as compute

        error_rows = compute(tuple(THESIS_TABLE_4_3), (3,))
    ours = {r["quality"]: r for r in error_rows if r["degree"] == 3 and r["fit"] == "thesis"}
    rows = []
    for q, printed_row in THESIS_TABLE_4_3.items():
        if q not in ours:
            continue
        for i, (col, key, reading, reason) in enumerate(TABLE_4_3_COLUMNS):
            printed = printed_row[i] * (100.0 if key == "area_max_pct" else 1.0)
            m = mark_cell(printed, ours[q][key], 4, reason)
            rows.append({"quality": q, "column": col, "reading": reading, **m._asdict()})
    return rows
