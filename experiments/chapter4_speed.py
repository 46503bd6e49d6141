"""Chapter 4, Table 4.2: Newton iterations and speed of the inverse; the degree-7 check of §4.3."""

from __future__ import annotations

import math
import statistics
import time
from collections.abc import Callable
from typing import Any

import numpy as np

from dggs.experiments import inverse as thesis_inverse
from dggs.experiments import numpy_snyder
from dggs.experiments.chapter4_constants import _SECTOR, QUALITIES, TOL, TOLERANCES
from dggs.experiments.chapter4_errors import error_rows
from dggs.experiments.chapter4_fits import fit_sector
from dggs.experiments.chapter4_mesh import face_mesh
from dggs.geometry.icosahedron import NUM_FACES

__all__ = ["iteration_rows", "timing_rows", "degree7_check"]


# ----------------------------------------------------------------------------
# Table 4.2: iterations and timings
# ----------------------------------------------------------------------------
def _all_faces(quality: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Mesh vertices of all 20 faces (face index, x, y): the timing workload."""
    pts, _ = face_mesh(quality)
    face = np.repeat(np.arange(NUM_FACES), len(pts))
    return face, np.tile(pts[:, 0], NUM_FACES), np.tile(pts[:, 1], NUM_FACES)


def _sector_azimuths(x: np.ndarray, y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Planar azimuth reduced to [0, 120) degrees and the planar area A_G (eq. 8 inverted)."""
    ap = np.mod(np.arctan2(x, y), 2.0 * math.pi)
    ap = ap - np.minimum(ap // _SECTOR, 2) * _SECTOR
    return ap, numpy_snyder.area_from_planar(np.sin(ap), np.cos(ap))


def iteration_rows(qualities=QUALITIES, tol: float = TOL, max_iter: int = 20) -> list[dict[str, Any]]:
    """Average Newton iterations per point of O and I (cubic and degree 7, both fits).

    Iterations count every Newton update, the last (below ``tol``) included,
    as in the thesis's Algorithm 1.
    """
    rows = []
    for q in qualities:
        pts, _ = face_mesh(q)
        ap, area = _sector_azimuths(pts[:, 0], pts[:, 1])
        row: dict[str, Any] = {"quality": q, "tol": tol}
        _, it = thesis_inverse.newton(area, ap, tol, max_iter)
        row["O"] = float(it.mean())
        row["O_histogram"] = np.bincount(it).tolist()
        for d in (3, 7):
            _, it = thesis_inverse.newton(area, thesis_inverse.az_poly(ap, d), tol, max_iter)
            row[f"I{d}_library"] = float(it.mean())
            _, it = thesis_inverse.newton(area, fit_sector(d)(ap), tol, max_iter)
            row[f"I{d}_thesis"] = float(it.mean())
        rows.append(row)
    return rows


def _median_time(fn: Callable[[], Any], repeats: int) -> float:
    """Median wall time of ``fn()`` over ``repeats`` runs (after one warm-up)."""
    fn()
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


def timing_rows(qualities=QUALITIES, repeats: int = 7, tol: float = TOL) -> list[dict[str, Any]]:
    """Median time of the whole inverse and of the ``Az`` step alone, per method (thesis Table 4.2).

    The workload is the quality-``q`` mesh vertices of all 20 faces, inverted
    in one vectorized call (:func:`dggs.experiments.inverse.inverse_xyz`, no input checks).
    Methods: O = ``"newton"``, I = ``"newton-poly"`` (cubic), E = ``"poly"``
    (cubic), C = ``"closed"``; the cubic is the library's.  The ``Az`` step
    alone times only the solve for ``Az`` from ``A_G`` (and ``Az'``).  Methods are
    interleaved within each repeat so that drifts in machine speed hit all alike.
    """
    methods = {"O": "newton", "I": "newton-poly", "E": "poly", "C": "closed"}
    rows = []
    for q in qualities:
        face, x, y = _all_faces(q)
        ap, area = _sector_azimuths(x, y)
        # this quality's arrays are bound as defaults (B023), as the method name is
        whole: dict[str, Callable[..., Any]] = {m: (lambda name=name, face=face, x=x, y=y:
                     thesis_inverse.inverse_xyz(face, x, y, method=name, degree=3, tol=tol))
                 for m, name in methods.items()}
        step: dict[str, Callable[..., Any]] = {
            "O": lambda area=area, ap=ap: thesis_inverse.newton(area, ap, tol, 20),
            "I": lambda area=area, ap=ap: thesis_inverse.newton(area, thesis_inverse.az_poly(ap, 3), tol, 20),
            "E": lambda ap=ap: thesis_inverse.az_poly(ap, 3),
            "C": lambda area=area: numpy_snyder.az_closed(area),
        }
        t_whole: dict[str, list[float]] = {m: [] for m in methods}
        t_step: dict[str, list[float]] = {m: [] for m in methods}
        for m in methods:  # warm-up
            whole[m]()
            step[m]()
        for _ in range(repeats):
            for m in methods:
                t0 = time.perf_counter()
                whole[m]()
                t_whole[m].append(time.perf_counter() - t0)
                t0 = time.perf_counter()
                step[m]()
                t_step[m].append(time.perf_counter() - t0)
        n = len(x)
        _, iters_o = thesis_inverse.inverse_xyz(face, x, y, method="newton", tol=tol)
        _, iters_i = thesis_inverse.inverse_xyz(face, x, y, method="newton-poly", degree=3, tol=tol)
        med_w = {m: statistics.median(v) for m, v in t_whole.items()}
        med_s = {m: statistics.median(v) for m, v in t_step.items()}
        for m in methods:
            rows.append({
                "quality": q, "method": m, "points": n,
                "iterations": {"O": float(iters_o.mean()), "I": float(iters_i.mean())}.get(m, 0.0),
                "time_s": med_w[m], "points_per_s": n / med_w[m],
                "time_ratio": med_w[m] / med_w["O"],
                "time_improvement_pct": 100.0 * (1.0 - med_w[m] / med_w["O"]),
                "stdev_s": statistics.stdev(t_whole[m]) if repeats > 1 else 0.0,
                "az_step_s": med_s[m], "az_step_ratio": med_s[m] / med_s["O"],
                "az_step_share_pct": 100.0 * med_s[m] / med_w[m],
            })
    return rows


def degree7_check(tolerances=TOLERANCES, quality: int = 100) -> dict[str, Any]:
    """Check thesis §4.3: degree 7 gives 45 % fewer iterations and 10x smaller errors than the cubic."""
    pts, _ = face_mesh(quality)
    ap, area = _sector_azimuths(pts[:, 0], pts[:, 1])
    iters = []
    for tol in tolerances:
        row: dict[str, Any] = {"tol": tol}
        _, it = thesis_inverse.newton(area, ap, tol, 20)
        row["O"] = float(it.mean())
        for kind in ("library", "thesis"):
            for d in (3, 7):
                start = thesis_inverse.az_poly(ap, d) if kind == "library" else fit_sector(d)(ap)
                _, it = thesis_inverse.newton(area, start, tol, 20)
                row[f"I{d}_{kind}"] = float(it.mean())
            row[f"fewer_pct_{kind}"] = 100.0 * (1.0 - row[f"I7_{kind}"] / row[f"I3_{kind}"])
        iters.append(row)
    errs = {(r["fit"], r["degree"]): r for r in error_rows((quality,), (3, 7))}
    factors = {}
    for kind in ("thesis", "library"):
        c, s = errs[(kind, 3)], errs[(kind, 7)]
        factors[kind] = {key: c[key] / s[key] for key in
                         ("dist_avg", "dist_max", "area_abs_avg_pct", "area_max_pct")}
    return {"quality": quality, "iterations": iters, "error_factor_cubic_over_deg7": factors}
