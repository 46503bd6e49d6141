"""Chapter 4, Table 4.3: distance and triangle-area errors of the elimination approach ``E``."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from dggs.experiments import inverse as thesis_inverse
from dggs.experiments.chapter4_constants import EARTH_RADIUS_M, QUALITIES
from dggs.experiments.chapter4_fits import exact_az, fit_sector
from dggs.experiments.chapter4_mesh import face_mesh, inverse_with_az, spherical_triangle_areas

__all__ = ["error_rows"]


# ----------------------------------------------------------------------------
# Table 4.3: errors of the elimination approach E
# ----------------------------------------------------------------------------
def _library_poly(degree: int) -> Callable[[np.ndarray], np.ndarray]:
    """The library's ``method="poly"`` azimuth (:func:`dggs.experiments.inverse.polynomial`, mirrored at 60)."""
    return lambda ap: thesis_inverse.az_poly(ap, degree)


def error_rows(qualities=QUALITIES, degrees=(3, 7)) -> list[dict[str, Any]]:
    """Distance and triangle-area errors of ``E`` against the exact inverse (thesis Table 4.3).

    One face suffices: every face has the same planar frame and the inverse
    differs from face to face only by a rotation.  For each quality and each
    polynomial (``"thesis"``: our full-sector, area-spaced fit of Table 4.1;
    ``"library"``: :func:`dggs.experiments.inverse.polynomial`, 0-60 degrees mirrored):

    ``dist_avg``/``dist_max`` are great-circle distances in units of the radius;
    ``area_abs_avg_pct`` the mean of ``|dA| / A`` in %, ``area_signed_avg_pct``
    the mean of ``dA / A``, ``area_max_pct`` the max of ``|dA| / A``, and
    ``area_abs_avg_sr`` the mean ``|dA|`` in steradians.
    """
    rows = []
    for q in qualities:
        pts, tri = face_mesh(q)
        face = np.zeros(len(pts), dtype=np.intp)
        exact = inverse_with_az(face, pts[:, 0], pts[:, 1], exact_az)
        area0 = spherical_triangle_areas(exact, tri)
        for d in degrees:
            for kind, az_of in (("thesis", fit_sector(d)), ("library", _library_poly(d))):
                approx = inverse_with_az(face, pts[:, 0], pts[:, 1], az_of)
                chord = np.linalg.norm(approx - exact, axis=1)
                dist = 2.0 * np.arcsin(np.minimum(chord / 2.0, 1.0))
                da = spherical_triangle_areas(approx, tri) - area0
                rel = da / area0 * 100.0
                rows.append({
                    "quality": q, "degree": d, "fit": kind, "points": len(pts), "triangles": len(tri),
                    "dist_avg": float(dist.mean()), "dist_max": float(dist.max()),
                    "dist_avg_m": float(dist.mean() * EARTH_RADIUS_M),
                    "dist_max_m": float(dist.max() * EARTH_RADIUS_M),
                    "area_abs_avg_pct": float(np.abs(rel).mean()),
                    "area_signed_avg_pct": float(rel.mean()),
                    "area_max_pct": float(np.abs(rel).max()),
                    "area_abs_avg_sr": float(np.abs(da).mean()),
                })
    return rows
