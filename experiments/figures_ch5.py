"""Chapter 5 curve figures (Figures 5.1-5.4, 5.12-5.21) drawn from the computed subdivisions.

Every curve is computed by :mod:`dggs.experiments.curves` (§5.1.1, §5.1.4-5.1.10)
or :mod:`dggs.experiments.arcs` (§5.1.3); the thesis gives no coordinates,
so the shapes are ours (:data:`CURVES`).  Pink: the circle arc through each
three consecutive vertices; green: their origins (the thesis's colours).
The surface figures (5.5-5.10, 5.22) are in
:mod:`dggs.experiments.figures_ch5_surfaces`.

Examples
--------
>>> m = edge_construction(CURVES["pentagon"], 1)
>>> bool(np.allclose(m["m_N"], radial_subdivide(CURVES["pentagon"], 1, length="none")[1][3]))
True
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from dggs.experiments.arcs import arc_points, bspline_subdivide, radius_convergence, three_point_arcs
from dggs.experiments.curves import (
    circle_subdivide,
    polygon_length,
    radial_subdivide,
    reflex_vertices,
    regular_polygon,
    vertex_circles,
)

__all__ = ["CURVES", "edge_construction", "co_linearity_breakdown", "write_chapter5_curves"]

#: Our shapes (counter-clockwise); the thesis draws its own and gives no coordinates.
CURVES: dict[str, np.ndarray] = {
    "pentagon": np.array([[0.0, 0.0], [200.0, -20.0], [300.0, 120.0], [150.0, 260.0], [-40.0, 150.0]]),
    # Near-co-linear vertices on the bottom edge (Figure 5.14: "co-linear ... larger radii").
    "hexagon": np.array([[0.0, 0.0], [3.0, 0.0], [6.0, 0.3], [7.0, 3.0], [3.0, 5.0], [-1.0, 3.0]]),
    # A bean: one dent, so the limit curve has inflections (Figure 5.11's "change in curvature").
    "bspline": np.array([[0.0, 0.0], [3.0, -0.6], [6.0, 0.0], [7.0, 2.0], [5.0, 3.2], [3.5, 2.0], [2.0, 3.0],
                         [-0.5, 2.0]]),
    # A kidney: an ellipse (2 x 1) with a dent at the top, eight vertices.
    "concave": np.array([[2.0, 0.0], [1.2943, 0.6471], [0.0, 0.0], [-1.2943, 0.6471], [-2.0, 0.0],
                         [-1.4142, -0.7071], [0.0, -1.0], [1.4142, -0.7071]]),
    # Convex, but a flat corner next to a sharp one (Figure 5.17).
    "convex_to_concave": np.array([[0.0, 0.0], [3.0, 0.0], [6.0, 1.0], [7.0, 3.0], [0.0, 3.0]]),
    # A thin convex pentagon whose short edge's two circles have their origins outside (Figure 5.18).
    "cusp": np.array([[3.19, 0.03], [3.12, 0.32], [1.28, -1.4], [1.99, -1.19], [2.93, -0.61]]),
    "obtuse": np.array([[0.0, 0.0], [10.0, 0.0], [5.0, 1.0]]),
}

_PINK, _GREEN = "#e377c2", "#2ca02c"


def edge_construction(points: np.ndarray, i: int) -> dict[str, np.ndarray | float]:
    """The construction of Figure 5.13 for edge ``v_i v_{i+1}`` (thesis §5.1.4), step by step.

    ``C_0`` through ``v_{i-1}, v_i, v_{i+1}`` and ``C_1`` through ``v_i, v_{i+1},
    v_{i+2}``; ``O_N = (O_0 + O_1) / 2``, ``R_N = (R_0 + R_1) / 2``,
    ``Theta_N = (Theta_1 + Theta_2) / 2`` (the short way round), and
    ``m_N = O_N + R_N (cos Theta_N, sin Theta_N)``.
    """
    p = np.asarray(points, dtype=np.float64)
    n = len(p)
    v = [p[(i + k) % n] for k in (-1, 0, 1, 2)]
    c, r, _ = vertex_circles(p, 0.0)
    o0, o1, r0, r1 = c[i], c[(i + 1) % n], float(r[i]), float(r[(i + 1) % n])
    th1 = float(np.arctan2(*(v[1] - o0)[::-1]))
    th2 = float(np.arctan2(*(v[2] - o1)[::-1]))
    thn = th1 + 0.5 * ((th2 - th1 + np.pi) % (2 * np.pi) - np.pi)
    on, rn = 0.5 * (o0 + o1), 0.5 * (r0 + r1)
    return {"v": np.array(v), "O_0": o0, "O_1": o1, "R_0": r0, "R_1": r1, "O_N": on, "R_N": rn,
            "Theta_N": thn, "m_N": on + rn * np.array([np.cos(thn), np.sin(thn)])}


def co_linearity_breakdown(levels: int = 8, length: str = "thesis", colinear_tol: float = 1e-9):
    """Figure 5.21's numbers: per level, reflex (origin-flipped) vertices and length / initial length.

    Examples
    --------
    >>> d = co_linearity_breakdown(8)
    >>> d["reflex"][:6], d["reflex"][8] > 100
    ([0, 0, 0, 0, 0, 3], True)
    >>> co_linearity_breakdown(8, length="none")["reflex"]
    [0, 0, 0, 0, 0, 0, 0, 0, 0]
    """
    p = CURVES["pentagon"]
    out = radial_subdivide(p, levels, length=length, colinear_tol=colinear_tol)
    return {"levels": out, "reflex": [reflex_vertices(q) for q in out],
            "length_ratio": [polygon_length(q) / polygon_length(p) for q in out]}


# --- drawing helpers ---------------------------------------------------------------------------------

def _poly(ax, p, **kw):
    q = np.vstack([p, p[:1]])
    kw.setdefault("color", "k")
    kw.setdefault("lw", 0.9)
    ax.plot(q[:, 0], q[:, 1], **kw)


def _arcs(ax, p, origins=True, max_radius=None):
    arcs = three_point_arcs(p)
    pts = arc_points(arcs)
    keep = np.isfinite(arcs.radius) if max_radius is None else arcs.radius < max_radius
    for a in pts[keep]:
        ax.plot(a[:, 0], a[:, 1], color=_PINK, lw=0.6, alpha=0.8)
    if origins:
        ax.plot(arcs.centre[keep, 0], arcs.centre[keep, 1], ".", color=_GREEN, ms=3)


def _frame(ax, p, pad=0.25, title=None):
    lo, hi = p.min(axis=0), p.max(axis=0)
    d = (hi - lo).max() * pad
    ax.set_xlim(lo[0] - d, hi[0] + d)
    ax.set_ylim(lo[1] - d, hi[1] + d)
    ax.set_aspect("equal")
    ax.set_xticks([])
    ax.set_yticks([])
    if title:
        ax.set_title(title, fontsize=7)


def _circle(ax, c, r, **kw):
    t = np.linspace(0, 2 * np.pi, 256)
    ax.plot(c[0] + r * np.cos(t), c[1] + r * np.sin(t), **kw)


def _row(plt, n, w=2.6, h=2.7):
    fig, axes = plt.subplots(1, n, figsize=(w * n, h), squeeze=False)
    return fig, axes[0]


# --- the figures ---------------------------------------------------------------------------------------

def _fig_5_1_5_2(plt):
    p = regular_polygon(5, 1.0, 0.3) + np.array([[0.0, 0.0], [0.0, 0.0], [0.05, 0.0], [0.0, 0.0], [0.0, 0.0]])
    p = p / np.linalg.norm(p, axis=1, keepdims=True)  # irregular pentagon on the unit circle
    fig, axes = _row(plt, 2, 3.4, 3.4)
    for ax in axes:
        _circle(ax, (0, 0), 1.0, color="0.6", lw=0.8)
        _poly(ax, p)
        ax.plot(0, 0, "o", color=_GREEN, ms=3)
    for k, q in enumerate(p):
        axes[0].annotate(f"$v_{k}$", q * 1.1, ha="center", va="center", fontsize=8)
    axes[0].plot([0, p[0, 0]], [0, p[0, 1]], "--", color="tab:blue", lw=0.8)
    axes[0].annotate("R", 0.55 * p[0], color="tab:blue", fontsize=8)
    axes[0].annotate("O", (0.05, -0.12), fontsize=8)
    theta = np.arccos(np.clip(p[0] @ p[1], -1, 1))
    for q in p[:2]:
        axes[1].plot([0, q[0]], [0, q[1]], "--", color="tab:blue", lw=0.8)
    axes[1].plot(*np.vstack([p[0], p[1]]).T, color="tab:red", lw=2)
    l0 = float(np.linalg.norm(p[1] - p[0]))
    _frame(axes[0], np.vstack([p, -p]), 0.1, f"Figure 5.1: polygon in circle C, O, R\nL = {polygon_length(p):.4f}")
    _frame(axes[1], np.vstack([p, -p]), 0.1,
           f"Figure 5.2: $l_0$ = {l0:.4f} = 2R sin($\\Theta_0$/2) = {2 * np.sin(theta / 2):.4f}")
    return fig


def _fig_5_3(plt):
    tri = np.array([[1.0, 0.0], [-0.3, 0.9539392014169456], [-0.6, -0.8]])
    tri = tri / np.linalg.norm(tri, axis=1, keepdims=True)
    levels = circle_subdivide(tri, 3)
    fig, axes = _row(plt, 4)
    for k, (ax, p) in enumerate(zip(axes, levels, strict=True)):
        r = float(np.linalg.norm(p, axis=1).mean())
        _circle(ax, (0, 0), r, color="0.6", lw=0.8)
        _circle(ax, (0, 0), 1.0, color="0.85", lw=0.6, ls=":")
        _poly(ax, p)
        ax.plot(*p.T, ".", color="k", ms=3)
        _frame(ax, np.array([[-1, -1], [1, 1]]), 0.05, f"level {k}: n={len(p)}, R={r:.4f}\nL={polygon_length(p):.6f}")
    fig.suptitle("Figure 5.3: length-preserving circular subdivision (§5.1.1): R shrinks, L is kept", fontsize=8)
    return fig


def _fig_5_4(plt):
    p = regular_polygon(4, 1.0, 0.4) * np.array([1.0, 1.0])
    length = polygon_length(p)
    mids = 0.5 * (p + np.roll(p, -1, axis=0))
    flat = np.empty((8, 2))
    flat[0::2], flat[1::2] = p, mids
    proj = flat / np.linalg.norm(flat, axis=1, keepdims=True)
    scaled = circle_subdivide(p, 1)[1]
    steps = [(p, f"1. L = {length:.4f}"), (flat, "2. insert edge points"),
             (proj, f"3. onto C: L' = {polygon_length(proj):.4f}"),
             (scaled, f"5. R' = L R / L' = {length / polygon_length(proj):.4f}\nL = {polygon_length(scaled):.4f}")]
    fig, axes = _row(plt, 4)
    for ax, (q, title) in zip(axes, steps, strict=True):
        _circle(ax, (0, 0), 1.0, color="0.7", lw=0.7)
        _poly(ax, p, color="0.75", lw=0.6)
        _poly(ax, q)
        ax.plot(*q.T, ".", color="tab:red", ms=4)
        _frame(ax, np.array([[-1, -1], [1, 1]]), 0.05, title)
    fig.suptitle("Figure 5.4: steps for global curve preservation (§5.1.1)", fontsize=8)
    return fig


def _fig_5_12(plt):
    levels = bspline_subdivide(CURVES["bspline"], 7)
    limit = levels[-1]
    gaps = radius_convergence(CURVES["bspline"], 3)
    fig, axes = _row(plt, 4, 3.2, 3.0)
    for k, ax in enumerate(axes):
        p = levels[k]
        _arcs(ax, p, origins=False, max_radius=1e3)
        ax.plot(*np.vstack([limit, limit[:1]]).T, color="0.6", lw=0.5)
        _poly(ax, p)
        ax.plot(*p.T, ".", color="k", ms=3)
        _frame(ax, CURVES["bspline"], 0.3, f"stage {k}: {len(p)} vertices\nworst |R / R_limit - 1| "
               f"at the coarse vertices {gaps[k]:.3f}")
    fig.suptitle("Figure 5.12: cubic B-spline subdivision, pink: circle arcs of each three consecutive "
                 "vertices (grey: limit curve)", fontsize=8)
    return fig


def _fig_5_13(plt):
    p = CURVES["pentagon"]
    d = edge_construction(p, 1)
    fine = radial_subdivide(p, 1, length="none")[1]
    fig, axes = _row(plt, 4, 3.0, 3.0)
    v = d["v"]
    for ax in axes:
        _poly(ax, p, color="0.8", lw=0.6)
        ax.plot(*v.T, "o", color="k", ms=3)
    for c, r in ((d["O_0"], d["R_0"]), (d["O_1"], d["R_1"])):
        _circle(axes[0], c, r, color=_PINK, lw=0.7)
        axes[0].plot(*c, ".", color=_GREEN)
    axes[0].plot(*v[1:3].T, color="tab:red", lw=2)
    _circle(axes[1], d["O_N"], d["R_N"], color="tab:blue", lw=0.7)
    axes[1].plot(*d["O_N"], ".", color=_GREEN)
    axes[1].plot(*np.vstack([d["O_N"], d["m_N"]]).T, "--", color="tab:blue", lw=0.6)
    axes[1].plot(*d["m_N"], "s", color="tab:red", ms=4)
    axes[2].plot(*np.vstack([v[1], d["m_N"], v[2]]).T, color="tab:red", lw=1.5)
    axes[2].plot(*d["m_N"], "s", color="tab:red", ms=4)
    _poly(axes[3], fine)
    _arcs(axes[3], fine)
    titles = ["(a) edge e, circles $C_0$, $C_1$", f"(b) averaged circle: $R_N$={d['R_N']:.2f}, $m_N$",
              "(c) e replaced by two edges", "(d) circles recomputed (level 1)"]
    for ax, t in zip(axes, titles, strict=True):
        _frame(ax, p, 0.3, t)
    fig.suptitle("Figure 5.13: arbitrary curve construction (§5.1.4)", fontsize=8)
    return fig


def _levels_figure(plt, p, levels, title, length="none", arcs=True, marks_reflex=False, pad=0.3):
    out = radial_subdivide(p, max(levels), length=length)
    fig, axes = _row(plt, len(levels), 3.0, 3.0)
    for ax, k in zip(axes, levels, strict=True):
        q = out[k]
        if arcs:
            _arcs(ax, q, max_radius=20 * float(np.ptp(p)))
        _poly(ax, q)
        if marks_reflex:
            a, b = q - np.roll(q, 1, axis=0), np.roll(q, -1, axis=0) - q
            bad = a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0] < 0
            ax.plot(*q[bad].T, "o", color="tab:red", ms=3, mfc="none")
        _frame(ax, p, pad, f"level {k}: L = {polygon_length(q):.3f}, reflex {reflex_vertices(q)}")
    fig.suptitle(title, fontsize=8)
    return fig


def _fig_5_15(plt):
    p = CURVES["pentagon"]
    plain = radial_subdivide(p, 3, length="none")
    kept = radial_subdivide(p, 3, length="thesis")
    fig, axes = _row(plt, 2, 3.6, 3.6)
    for ax, zoom in zip(axes, (None, (200.0, -20.0)), strict=True):
        _poly(ax, p, color="0.7", lw=0.6)
        _poly(ax, plain[3], color="tab:blue", lw=0.8, label=f"no scaling, L = {polygon_length(plain[3]):.3f}")
        _poly(ax, kept[3], color="k", lw=0.8, label=f"scaled L_B/L_A (§5.1.6), L = {polygon_length(kept[3]):.3f}")
        if zoom is None:
            _frame(ax, p, 0.1, f"level 3; initial L = {polygon_length(p):.3f}")
            ax.legend(fontsize=6, loc="lower center")
        else:
            ax.set_xlim(zoom[0] - 25, zoom[0] + 25)
            ax.set_ylim(zoom[1] - 10, zoom[1] + 40)
            ax.set_aspect("equal")
            ax.set_title("close-up: vertices pulled inwards", fontsize=7)
    fig.suptitle("Figure 5.15: radial-based subdivision preserving length", fontsize=8)
    return fig


def _fig_5_19_5_20(plt):
    p = CURVES["obtuse"]
    out = radial_subdivide(p, 5, length="none")
    c, r, _ = vertex_circles(p)
    fig, axes = _row(plt, 4, 3.0, 3.0)
    _circle(axes[0], c[0], r[0], color=_PINK, lw=0.7)
    axes[0].plot(*c[0], "o", color=_GREEN, ms=3)
    for ax, k in zip(axes, (0, 1, 3, 5), strict=True):
        _poly(ax, out[k])
        ax.plot(*out[k].T, ".", color="k", ms=2)
    _frame(axes[0], np.vstack([p, c[:1] - r[0], c[:1] + r[0]]), 0.05, "Figure 5.19: obtuse triangle,\norigin outside")
    for ax, k in zip(axes[1:], (1, 3, 5), strict=True):
        arcs = three_point_arcs(out[k])
        outside = arcs.centre[:, 1] < 0.0  # origins below the long edge: outside the curve
        ax.plot(*arcs.centre[outside & (arcs.radius < 30)].T, ".", color=_GREEN, ms=3)
        ax.set_xlim(-1.0, 11.0)
        ax.set_ylim(-13.5, 2.0)  # not to scale: the origins sit 12 units below
        ax.set_xticks([])
        ax.set_yticks([])
        ax.set_title(f"Figure 5.20: level {k}, reflex {reflex_vertices(out[k])}", fontsize=7)
    fig.suptitle("Figures 5.19-5.20: a triangle with its origin outside; cusps develop, "
                 "external origins (green) stay outside", fontsize=8)
    return fig


def _fig_5_21(plt):
    p = CURVES["pentagon"]
    rows = [("thesis", "one-shot scaling (§5.1.6)"), ("none", "no scaling")]
    fig, axes = plt.subplots(2, 4, figsize=(11.0, 5.6))
    for row, (mode, label) in zip(axes, rows, strict=True):
        d = co_linearity_breakdown(8, length=mode)
        for ax, k in zip(row, (0, 6, 7, 8), strict=True):
            q = d["levels"][k]
            _poly(ax, q, lw=0.6)
            _frame(ax, p, 0.3, f"{label}, level {k}\nreflex {d['reflex'][k]}, L/L0 = {d['length_ratio'][k]:.4g}")
    fig.suptitle("Figure 5.21: the length-preserved curve develops concavity at levels 6-8 "
                 "(a co-linearity guard of 0 to 1e-2 does not prevent it); without the scaling it stays smooth",
                 fontsize=8)
    return fig


def write_chapter5_curves(outdir: str | Path, quick: bool = False) -> list[Path]:
    """Write the chapter-5 curve figures as PNGs; returns the paths."""
    from dggs.experiments.figures import save_figures

    figures = {
        "fig5_1_5_2_curve_definition": _fig_5_1_5_2,
        "fig5_3_circular_subdivision": _fig_5_3,
        "fig5_4_curve_steps": _fig_5_4,
        "fig5_12_bspline_arcs": _fig_5_12,
        "fig5_13_edge_construction": _fig_5_13,
        "fig5_14_radial_subdivision": lambda plt: _levels_figure(
            plt, CURVES["pentagon"], (0, 1, 2, 3), "Figure 5.14: radial-based subdivision (basic scheme); "
            "pink arcs, green origins, recomputed each level"),
        "fig5_15_length_preserving": _fig_5_15,
        "fig5_16_concave": lambda plt: _levels_figure(
            plt, CURVES["concave"], (0, 1, 2, 3), "Figure 5.16: preserving length on a concave curve "
            "(§5.1.6 scaling, red: reflex vertices): the length grows instead", length="thesis", arcs=False,
            marks_reflex=True, pad=0.6),
        "fig5_17_convex_to_concave": lambda plt: _levels_figure(
            plt, CURVES["convex_to_concave"], (0, 1, 2, 3), "Figure 5.17: a convex curve turns concave "
            "(red: reflex vertices)", arcs=False, marks_reflex=True, pad=0.5),
        "fig5_18_rounded_cusps": lambda plt: _levels_figure(
            plt, CURVES["cusp"], (0, 1, 3, 5), "Figure 5.18: a rounded cusp forms at the short edge "
            "(basic scheme; red: reflex vertices)", arcs=False, marks_reflex=True, pad=0.1),
        "fig5_19_5_20_cusp": _fig_5_19_5_20,
        "fig5_21_co_linearity": _fig_5_21,
    }
    return save_figures(outdir, figures, quick)
