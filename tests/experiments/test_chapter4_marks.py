"""Chapter 4's Tables 4.1-4.3: the transcription against the thesis's text, the readings tried, each cell's mark.

The printed values are parsed from the thesis's text (the seed file) where it
is present; the marks are checked against an independent rounding oracle
(Python's own ``%e`` formatting), the fits against numpy's ``polyfit``.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
import pytest
from hypothesis import assume, example, given, settings
from hypothesis import strategies as st

from dggs.experiments import chapter4_recover as rec
from dggs.experiments.chapter4_constants import THESIS_TABLE_4_1, THESIS_TABLE_4_2, THESIS_TABLE_4_3
from dggs.experiments.chapter4_fits import exact_az, sector_samples
from dggs.geometry import snyder

THESIS = Path("/work/shared/seeds/000_159c13f7563cdd46.txt")
SECTOR = 2 * math.pi / 3


# --------------------------------------------------------------------------- the transcription
def _table(caption: str) -> list[list[str]]:
    """Rows of the markdown table after ``caption`` in the thesis's text, cells stripped."""
    if not THESIS.exists():
        pytest.skip("the thesis's text is not on this machine")
    lines = THESIS.read_text(encoding="utf-8").splitlines()
    start = next(i for i, line in enumerate(lines) if line.startswith(caption))
    rows, seen = [], False
    for line in lines[start + 1:]:
        if line.startswith("|"):
            seen = True
            cells = [c.strip() for c in line.strip("|").split("|")]
            if not set("".join(cells)) <= set(":- "):
                rows.append(cells)
        elif seen:
            break
    return rows[1:]  # the header row


def _number(cell: str) -> float | None:
    """``$1.19 \\mathrm{e}+00$`` -> 1.19; ``$28.05 \\%$`` -> 28.05; empty -> None."""
    text = re.sub(r"\\mathrm\{e\}", "e", cell).replace("$", "").replace("\\%", "").replace(" ", "")
    return float(text) if text else None


def test_table_4_1_as_printed():
    rows = _table("Table 4.1: Polynomial Approximating Azimuthal Shift")
    parsed = {int(r[0].split()[1]): (_number(r[1]), _number(r[2])) for r in rows}
    assert parsed == THESIS_TABLE_4_1


def test_table_4_2_as_printed():
    rows = _table("Table 4.2: Profiling Results")
    parsed: dict[int, dict[str, tuple]] = {}
    for r in rows:
        method, quality = r[0].split(".")
        parsed.setdefault(int(quality), {})[method] = tuple(_number(c) for c in r[1:])
    assert parsed == THESIS_TABLE_4_2


def test_table_4_3_as_printed():
    rows = _table("Table 4.3: Error Analysis of Elimination Approach")
    assert {int(r[0]): tuple(_number(c) for c in r[1:]) for r in rows} == THESIS_TABLE_4_3


# --------------------------------------------------------------------------- the marks
def _oracle(printed: float, ours: float, digits: int) -> str:
    same = f"{ours:.{digits - 1}e}" == f"{printed:.{digits - 1}e}"
    return "reproduced" if same else ("close" if abs(ours / printed - 1) <= 0.01 else "differs")


@settings(max_examples=300, deadline=None)
@given(mantissa=st.integers(100, 999), exponent=st.integers(-12, 2), rel=st.floats(-0.05, 0.05),
       digits=st.sampled_from([3, 4]))
@example(mantissa=230, exponent=-6, rel=0.0, digits=3)
@example(mantissa=230, exponent=-6, rel=0.0099, digits=3)
@example(mantissa=999, exponent=-1, rel=0.02, digits=3)
def test_mark_cell_matches_a_rounding_oracle(mantissa, exponent, rel, digits):
    printed = float(f"{mantissa}e{exponent - 2}") if digits == 3 else float(f"{mantissa}1e{exponent - 3}")
    ours = printed * (1 + rel)
    unit = 10.0 ** (math.floor(math.log10(printed)) - (digits - 1))
    assume(abs(abs(ours - printed) / unit - 0.5) > 1e-6)  # no ties at the rounding boundary
    assume(abs(abs(rel) - 0.01) > 1e-9)
    assert rec.mark_cell(printed, ours, digits).status == _oracle(printed, ours, digits)


def test_mark_cell_keeps_the_reason_only_when_not_reproduced():
    assert rec.mark_cell(1.19, 1.19, 3, "why").reason == ""
    assert rec.mark_cell(1.19, 1.154, 3, "why") == (1.19, 1.154, 1.154 / 1.19 - 1, "differs", "why")


# --------------------------------------------------------------------------- the readings tried
def _ss_polyfit(ap: np.ndarray, degree: int) -> float:
    az = exact_az(ap)
    t = (ap - ap.mean()) / np.ptp(ap)
    r = az - np.polyval(np.polyfit(t, az, degree), t)
    return float(r @ r)


@pytest.mark.parametrize("name", ["area-120", "uniform-120", "uniform-60"])
def test_procedure_fits_agree_with_polyfit(name):
    ap, w = rec.PROCEDURES[name].sample(5871)
    assert w is None
    for d, (ss, var) in enumerate(rec.procedure_fits(name), 1):
        assert ss == pytest.approx(_ss_polyfit(ap, d), rel=1e-6, abs=1e-14)
        assert var == pytest.approx(ss / (len(ap) - d - 1))


def test_area_samples_sweep_equal_planar_areas():
    # The planar sector triangle centre - vertex - edge point at Az': its area by the shoelace formula.
    ap = sector_samples(600, "area")
    ap = ap[ap <= SECTOR / 2]
    d0 = snyder.R_PRIME * snyder.TAN_G  # centre to vertex (Az' = 0)
    edge = d0 / (np.cos(ap) + np.sin(ap) * math.sqrt(3))  # centre to the edge along Az' (cot 30 deg)
    area = 0.5 * d0 * edge * np.sin(ap)
    steps = np.diff(area)
    assert steps == pytest.approx(np.full_like(steps, steps.mean()), rel=1e-9)


def test_best_reading_is_area_spaced_over_the_full_sector():
    scores = {n: rec.procedure_score(n) for n in rec.PROCEDURES}
    assert rec.best_procedure() == "area-120" == min(scores, key=scores.get)
    # the text's "60 degrees" and degrees as unit are far off, every reading misses
    assert scores["uniform-60"] > 1 and scores["area-120-degrees"] > 5 and scores["area-120"] > 0.05
    # a fit without constant term gains at even degrees, as the thesis's does, but doubles every SS
    origin = [ss for ss, _ in rec.procedure_fits("origin-area-120")]
    assert all(origin[d] < 0.95 * origin[d - 1] for d in (1, 3, 5))
    assert all(o > 1.3 * THESIS_TABLE_4_1[d][0] for d, o in enumerate(origin, 1))


def test_density_does_not_move_the_variance():
    sparse, dense = rec.procedure_fits("area-120", 2000), rec.procedure_fits("area-120", 20000)
    for (_, v1), (_, v2) in zip(sparse, dense, strict=True):
        assert v1 == pytest.approx(v2, rel=0.005)


@settings(max_examples=40, deadline=None)
@given(st.lists(st.floats(0.0, SECTOR / 2), min_size=12, max_size=60, unique=True),
       st.sampled_from([2, 4, 6]))
@example([0.0, math.pi / 3, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0], 2)  # vertex ray and edge midpoint
@example([1e-9 * k for k in range(1, 13)] + [math.pi / 3 - 1e-3], 4)  # crowded at the vertex
def test_symmetric_samples_give_even_degrees_no_gain(half, degree):
    ap = np.array(half)
    assume(np.ptp(ap) > 0.2 and len(np.unique(np.round(np.concatenate([ap, SECTOR - ap]), 6))) > degree + 2)
    assert rec.symmetric_even_gain(ap, degree) == pytest.approx(1.0, abs=1e-6)


# --------------------------------------------------------------------------- the marks of Tables 4.1, 4.3
def test_table_4_1_marks():
    marks = rec.table_4_1_marks()
    assert len(marks) == 14
    for m in marks:
        assert m["printed"] == THESIS_TABLE_4_1[m["degree"]][0 if m["column"] == "SS" else 1]
        assert m["status"] == _oracle(m["printed"], m["ours"], 3)
        if m["status"] != "reproduced":
            assert ("symmetric" in m["reason"]) == (m["degree"] % 2 == 0)
    rel = {(m["degree"], m["column"]): m["rel_diff"] for m in marks}
    # the independent rerun's finding: odd degrees 1-4 % off, even degrees 13-25 %, nothing reproduced
    assert all(0.01 < abs(rel[(d, "SS")]) < 0.035 for d in (1, 3, 5, 7))
    assert all(0.12 < rel[(d, "SS")] < 0.25 for d in (2, 4, 6))
    assert [m["status"] for m in marks].count("differs") == 14
    assert "misprinted" in next(m["reason"] for m in marks if m["degree"] == 2)


def test_table_4_3_marks():
    marks = rec.table_4_3_marks()
    assert len(marks) == 16
    for m in marks:
        assert m["status"] == _oracle(m["printed"], m["ours"], 4) and m["reading"] and m["reason"]
    by = {(m["quality"], m["column"]): m for m in marks}
    assert all(-0.22 < by[(q, "avg dist")]["rel_diff"] < -0.09 for q in THESIS_TABLE_4_3)
    assert all(0.05 < by[(q, "max dist")]["rel_diff"] < 0.09 for q in THESIS_TABLE_4_3)
    assert by[(25, "max area %")]["printed"] == pytest.approx(100 * THESIS_TABLE_4_3[25][3])
    assert [m["status"] for m in marks].count("differs") == 16


def test_degree_2_pair_disagrees_on_n():
    # gnuplot: var = SS / (N - p).  Every printed pair but degree 2's implies the same N to rounding.
    n = {d: ss / var + d + 1 for d, (ss, var) in THESIS_TABLE_4_1.items()}
    assert all(5850 < v < 5895 for d, v in n.items() if d != 2) and n[2] < 5600
    assert 5850 < 0.972 / 1.66e-4 + 3 < 5895  # the evidence the note gives: 9.72e-01 would fit
    assert "5,587" in rec.DEGREE_2_NOTE and "5,853-5,893" in rec.DEGREE_2_NOTE
