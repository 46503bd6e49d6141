"""Thesis §3.1.7's claim measured: angular distortion of Snyder's ISEA and the vertex-oriented great circle IVEA.

The thesis (after van Leeuwen and Strebe 2006) says the vertex-oriented great
circle projection "results in a more even distribution of angular distortion
across the face" than Snyder's.  Both maps are equal-area, so each point's
Tissot indicatrix has semi-axes ``a >= b`` with ``a b = 1``, and its maximum
angular deformation is ``omega = 2 asin((a - b) / (a + b))`` (Snyder 1987,
*Map Projections: A Working Manual*, eq. 4-8).  Here:

- :func:`tissot` takes ``a`` and ``b`` from the singular values of the forward
  map's Jacobian (central differences in an orthonormal tangent frame of the
  sphere, step 1e-6 rad) on a dense barycentric sample of the natural
  triangle (face vertex, face centre, edge midpoint): both maps have the
  face's six-fold symmetry, so that triangle covers the face;
- :func:`edge_ratios` takes every cell of a level on each grid and the ratio
  of its longest to its shortest edge (geodesic corner-to-corner distances on
  WGS84, ``pyproj.Geod``); the planar cell, a 30-60-90 triangle, has ratio 2.

Snyder (1992, Table 2) gives ISEA's extremes: maximum angular deformation
17.27 degrees, scales 1.163 and 0.860, reached at the face centre, where
Snyder's map is not differentiable; the sample approaches them (17.22
degrees with the default margin of 1e-4 from the edges, 17.26 at 1e-5).
Run as ``dggs experiments projections``.

Examples
--------
>>> omega = tissot("ISEA", 40)
>>> bool(16.5 < omega.max() < 17.27), bool(tissot("IVEA", 40).max() < 11.2)
(True, True)
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from dggs.errors import DggsValueError
from dggs.geometry import ivea
from dggs.geometry import kernel as gk
from dggs.geometry.icosahedron import ISEA

__all__ = ["PROJECTIONS", "natural_sample", "tissot", "edge_ratios", "distortion_table", "format_table",
           "write_projection_figures"]

PROJECTIONS = ("ISEA", "IVEA")
_FACE = 2
_FRAMES = np.ascontiguousarray(ISEA.geometry.frames)


def _forward(projection: str) -> Any:
    if projection == "ISEA":
        return gk.face_forward
    if projection == "IVEA":
        return ivea.face_forward
    raise DggsValueError(f"projection {projection!r} is not one of {', '.join(PROJECTIONS)}")


def natural_triangle(face: int = _FACE) -> np.ndarray:
    """(3, 3) unit vectors V (face vertex 0), M (midpoint of the edge to vertex 1) and C (face centre)."""
    geo = ISEA.geometry
    v = geo.vertices[geo.face_vertices[face, 0]]
    w = geo.vertices[geo.face_vertices[face, 1]]
    m = (v + w) / np.linalg.norm(v + w)
    return np.array([v, m, geo.centres[face]])


def natural_sample(n: int, margin: float = 1e-4) -> np.ndarray:
    """Unit vectors on a barycentric grid of ``n`` steps a side inside the natural triangle (``margin`` from its edges)."""
    if n < 2:
        raise DggsValueError(f"samples {n} must be at least 2")
    tri = natural_triangle()
    i, j = np.meshgrid(np.arange(n + 1), np.arange(n + 1), indexing="ij")
    keep = i + j <= n
    u, v = i[keep] / n, j[keep] / n
    w = np.stack([u, v, 1.0 - u - v], axis=1) * (1 - 3 * margin) + margin
    p = w @ tri
    out: np.ndarray = p / np.linalg.norm(p, axis=1)[:, None]
    return out


def _scales(projection: str, points: np.ndarray, h: float = 1e-6) -> tuple[np.ndarray, np.ndarray]:
    """Tissot semi-axes (a, b) at each point, from the Jacobian by central differences."""
    fwd = _forward(projection)
    a = np.empty(len(points))
    b = np.empty(len(points))
    for k, p in enumerate(points):
        t1 = np.cross(p, [0.0, 0.0, 1.0]) if abs(p[2]) < 0.9 else np.cross(p, [1.0, 0.0, 0.0])
        t1 /= np.linalg.norm(t1)
        t2 = np.cross(p, t1)
        cols = []
        for t in (t1, t2):
            hi = p + h * t
            lo = p - h * t
            f_hi = np.array(fwd(_FRAMES, _FACE, *(hi / np.linalg.norm(hi))))
            f_lo = np.array(fwd(_FRAMES, _FACE, *(lo / np.linalg.norm(lo))))
            cols.append((f_hi - f_lo) / (2 * math.atan(h)))
        s = np.linalg.svd(np.array(cols).T, compute_uv=False)
        a[k], b[k] = s[0], s[1]
    return a, b


def tissot(projection: str, n: int = 120, margin: float = 1e-4) -> np.ndarray:
    """Maximum angular deformation omega (degrees) over :func:`natural_sample` for ``"ISEA"`` or ``"IVEA"``."""
    a, b = _scales(projection, natural_sample(n, margin))
    out: np.ndarray = np.degrees(2 * np.arcsin((a - b) / (a + b)))
    return out


def edge_ratios(projection: str, level: int) -> np.ndarray:
    """Longest over shortest geodesic edge (corner to corner, WGS84) of every cell at ``level`` on one grid."""
    from pyproj import Geod

    from dggs.index.hierarchy import cell_to_children, get_base_cells
    from dggs.index.projection import Grid

    ids = cell_to_children(get_base_cells(as_int=True), level) if level else get_base_cells(as_int=True)
    ring = np.asarray(Grid(projection).cell_to_boundary(np.asarray(ids, dtype=np.uint64)))
    lat0, lng0 = ring[:, :, 0], ring[:, :, 1]
    lat1, lng1 = np.roll(lat0, -1, axis=1), np.roll(lng0, -1, axis=1)
    _, _, dist = Geod(ellps="WGS84").inv(lng0.ravel(), lat0.ravel(), lng1.ravel(), lat1.ravel())
    d = np.asarray(dist).reshape(-1, 3)
    out: np.ndarray = d.max(axis=1) / d.min(axis=1)
    return out


def distortion_table(level: int = 5, samples: int = 120) -> list[dict[str, Any]]:
    """One row per projection: omega's max, mean and 95th percentile, and the edge ratios of ``level``'s cells."""
    rows = []
    for name in PROJECTIONS:
        omega = tissot(name, samples)
        ratio = edge_ratios(name, level)
        rows.append({
            "projection": name,
            "omega_max_deg": float(omega.max()),
            "omega_mean_deg": float(omega.mean()),
            "omega_p95_deg": float(np.percentile(omega, 95)),
            "omega_std_deg": float(omega.std()),
            "points": int(omega.size),
            "level": level,
            "cells": int(ratio.size),
            "edge_ratio_min": float(ratio.min()),
            "edge_ratio_mean": float(ratio.mean()),
            "edge_ratio_max": float(ratio.max()),
        })
    return rows


def format_table(rows: list[dict[str, Any]]) -> str:
    """The rows as a Markdown table."""
    head = ("| projection | max ω | mean ω | 95 % ω | sd ω | sample | level | cells | edge ratio min | mean | max |\n"
            "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    lines = [head]
    for r in rows:
        lines.append(
            f"| {r['projection']} | {r['omega_max_deg']:.2f}° | {r['omega_mean_deg']:.2f}° | {r['omega_p95_deg']:.2f}° "
            f"| {r['omega_std_deg']:.2f}° | {r['points']:,} | {r['level']} | {r['cells']:,} | {r['edge_ratio_min']:.4f} "
            f"| {r['edge_ratio_mean']:.4f} | {r['edge_ratio_max']:.4f} |"
        )
    return "\n".join(lines)


# ----------------------------------------------------------------------------------------------------
# Figures 3.13-3.14 (the slice and the dice) and the omega maps
# ----------------------------------------------------------------------------------------------------
def _view(points: np.ndarray) -> np.ndarray:
    """Orthographic view from above the natural triangle's centroid: (N, 3) -> (N, 2)."""
    tri = natural_triangle()
    z = tri.mean(axis=0)
    z /= np.linalg.norm(z)
    x = tri[0] - (tri[0] @ z) * z
    x /= np.linalg.norm(x)
    y = np.cross(z, x)
    out: np.ndarray = np.stack([points @ x, points @ y], axis=-1)
    return out


def _slerp(a: np.ndarray, b: np.ndarray, n: int = 60) -> np.ndarray:
    t = np.linspace(0.0, 1.0, n)[:, None]
    p = (1 - t) * a + t * b
    out: np.ndarray = p / np.linalg.norm(p, axis=1)[:, None]
    return out


def _planar(points: np.ndarray) -> np.ndarray:
    return np.array([ivea.face_forward(_FRAMES, _FACE, *p) for p in points])


def _figure(plt: Any, dice: bool) -> Any:
    tri = natural_triangle()
    v, m, c = tri
    plane = _planar(tri)
    # a point P and the great circle from V through it to D on CM (a planar line V'D' after the map)
    p = 0.3 * v + 0.3 * m + 0.4 * c
    p /= np.linalg.norm(p)
    pp = np.array(ivea.face_forward(_FRAMES, _FACE, *p))
    mu, _ = np.linalg.solve(np.array([pp - plane[0], plane[1] - plane[2]]).T, plane[1] - plane[0])
    dp = plane[0] + mu * (pp - plane[0])  # V' + mu (P' - V') = M' + lam (C' - M')
    d = np.array(ivea.face_inverse(_FRAMES, _FACE, *dp))
    fig, (ax_s, ax_p) = plt.subplots(1, 2, figsize=(8.0, 3.8))
    for k in range(3):
        ax_s.plot(*_view(_slerp(tri[k], tri[(k + 1) % 3])).T, color="black", lw=1.2)
        ax_p.plot(*np.array([plane[k], plane[(k + 1) % 3]]).T, color="black", lw=1.2)
    ax_s.plot(*_view(_slerp(v, d)).T, color="tab:blue", lw=1.4)
    ax_p.plot(*np.array([plane[0], dp]).T, color="tab:blue", lw=1.4)
    if not dice:  # the slice: the part V M D of the triangle, same share of area on both sides
        ax_s.fill(*_view(np.concatenate([_slerp(v, m), _slerp(m, d), _slerp(d, v)])).T, color="tab:blue", alpha=0.15)
        ax_p.fill(*np.array([plane[0], plane[1], dp]).T, color="tab:blue", alpha=0.15)
    else:  # the dice: P on VD, |V'P'| / |V'D'| = sin(VP / 2) / sin(VD / 2)
        ax_s.plot(*_view(_slerp(v, p)).T, color="tab:red", lw=2.5, label="x")
        ax_p.plot(*np.array([plane[0], pp]).T, color="tab:red", lw=2.5, label="x'")
    names = ("V", "M", "C", "P", "D")
    for name, q in zip(names, [*tri, p, d], strict=True):
        ax_s.annotate(name, _view(q[None])[0], fontsize=9, xytext=(3, 3), textcoords="offset points")
    for name, q in zip(names, [*plane, pp, dp], strict=True):
        ax_p.annotate(name + "'", q, fontsize=9, xytext=(3, 3), textcoords="offset points")
    ax_s.plot(*_view(np.array([p, d])).T, "o", color="tab:blue", ms=4)
    ax_p.plot(*np.array([pp, dp]).T, "o", color="tab:blue", ms=4)
    for ax, title in ((ax_s, "sphere (orthographic view)"), (ax_p, "face plane")):
        ax.set_aspect("equal")
        ax.axis("off")
        ax.set_title(title, fontsize=9)
    what = ("Figure 3.13: vertex-oriented slice - the great circle V P meets C M at D; "
            "V'M'D' takes the share of V'M'C' that VMD takes of VMC") if not dice else (
        "Figure 3.14: vertex-oriented dice - (x' / (x' + y'))^2 = (1 - cos x) / (1 - cos(x + y))")
    fig.suptitle(what + "\n(drawn by dggs.geometry.ivea on the natural triangle of face 2)", fontsize=8, y=1.06)
    return fig


def _omega_maps(plt: Any, n: int) -> Any:
    pts = natural_sample(n)
    xy = _planar(pts)
    fig, axes = plt.subplots(1, 2, figsize=(8.0, 3.8))
    omegas = {name: tissot(name, n) for name in PROJECTIONS}
    top = max(float(o.max()) for o in omegas.values())
    for ax, name in zip(axes, PROJECTIONS, strict=True):
        xy_name = xy if name == "IVEA" else np.array([gk.face_forward(_FRAMES, _FACE, *p) for p in pts])
        sc = ax.scatter(xy_name[:, 0], xy_name[:, 1], c=omegas[name], s=3, cmap="viridis", vmin=0, vmax=top)
        ax.set_aspect("equal")
        ax.axis("off")
        ax.set_title(f"{name}: max ω {omegas[name].max():.2f}°, mean {omegas[name].mean():.2f}°", fontsize=9)
    fig.colorbar(sc, ax=list(axes), shrink=0.8, label="maximum angular deformation ω (degrees)")
    fig.suptitle("Angular deformation over the natural triangle (its face plane), ISEA and IVEA", fontsize=9)
    return fig


def write_projection_figures(outdir: Any, quick: bool = False) -> list[Any]:
    """Write Figures 3.13 and 3.14 and the omega maps of both projections as PNG; returns the paths."""
    from dggs.experiments.figures import save_figures

    n = 30 if quick else 90
    return save_figures(outdir, {
        "figure_3_13_vertex_oriented_slice": lambda plt: _figure(plt, False),
        "figure_3_14_vertex_oriented_dice": lambda plt: _figure(plt, True),
        "projections_angular_deformation": lambda plt: _omega_maps(plt, n),
    }, quick)
