"""Circle arcs along a cubic B-spline subdivision (thesis §5.1.3, Figure 5.12).

The thesis overlays, on three stages of a cubic B-spline subdivision of a
closed curve, the circle arc through every three consecutive vertices, and
observes that the arcs, large and far from the coarse polygon at first,
shrink onto the smooth limit curve as the subdivision proceeds.  This module
computes both:

* :func:`bspline_subdivide` - the uniform cubic B-spline (Lane-Riesenfeld)
  rule on a closed polygon: each old vertex becomes
  ``(v_{i-1} + 6 v_i + v_{i+1}) / 8`` and each edge gets ``(v_i + v_{i+1}) / 2``.
* :func:`three_point_arcs` - for every vertex, the circle through it and its
  two neighbours (centre, radius) and the arc from the previous to the next
  vertex that passes through it (start angle and signed sweep).
* :func:`limit_point` and :func:`limit_radius_of_curvature` - the limit
  curve (the uniform cubic B-spline of the control polygon) at a control
  vertex: position ``(v_{i-1} + 4 v_i + v_{i+1}) / 6`` and radius of curvature
  ``|P'|^3 / |P' x P''|`` with ``P' = (v_{i+1} - v_{i-1}) / 2`` and
  ``P'' = v_{i-1} - 2 v_i + v_{i+1}``: the radius the arcs converge to.

Examples
--------
>>> square = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
>>> [len(p) for p in bspline_subdivide(square, 3)]
[4, 8, 16, 32]
>>> arcs = three_point_arcs(square)
>>> [round(float(r), 6) for r in arcs.radius]
[0.707107, 0.707107, 0.707107, 0.707107]
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .curves import vertex_circles

__all__ = [
    "Arcs",
    "bspline_subdivide",
    "three_point_arcs",
    "arc_points",
    "limit_point",
    "limit_radius_of_curvature",
    "radius_convergence",
]


@dataclass(frozen=True)
class Arcs:
    """Circle arcs through each vertex and its two neighbours.

    Attributes
    ----------
    centre : numpy.ndarray
        ``(n, 2)`` circumcentres (``nan`` where the three points are co-linear).
    radius : numpy.ndarray
        ``(n,)`` circumradii (``inf`` where co-linear).
    start : numpy.ndarray
        ``(n,)`` angle (radians, about ``centre``) of the previous vertex.
    sweep : numpy.ndarray
        ``(n,)`` signed angle from the previous to the next vertex through the
        vertex itself: positive counter-clockwise, ``|sweep| < 2 pi``.
    """

    centre: np.ndarray
    radius: np.ndarray
    start: np.ndarray
    sweep: np.ndarray


def bspline_subdivide(points: np.ndarray, levels: int) -> list[np.ndarray]:
    """Uniform cubic B-spline subdivision of a closed polygon (thesis §5.1.3).

    Parameters
    ----------
    points : numpy.ndarray
        ``(n, 2)`` (or ``(n, d)``) closed control polygon, ``n >= 3``.
    levels : int
        Number of subdivision steps.

    Returns
    -------
    list of numpy.ndarray
        Levels ``0..levels``; level ``k`` has ``n 2**k`` vertices, vertex
        ``2 i`` the descendant of vertex ``i`` of the level before.

    Examples
    --------
    >>> tri = np.array([[0.0, 0.0], [8.0, 0.0], [0.0, 8.0]])
    >>> bspline_subdivide(tri, 1)[1].tolist()
    [[1.0, 1.0], [4.0, 0.0], [6.0, 1.0], [4.0, 4.0], [1.0, 6.0], [0.0, 4.0]]
    """
    p = np.asarray(points, dtype=np.float64)
    if p.ndim != 2 or len(p) < 3:
        raise ValueError(f"need an (n >= 3, d) closed polygon, got shape {p.shape}")
    out = [p]
    for _ in range(levels):
        prev, nxt = np.roll(p, 1, axis=0), np.roll(p, -1, axis=0)
        fine = np.empty((2 * len(p), p.shape[1]))
        fine[0::2] = (prev + 6.0 * p + nxt) / 8.0  # vertex rule
        fine[1::2] = 0.5 * (p + nxt)  # edge rule
        p = fine
        out.append(p)
    return out


def three_point_arcs(points: np.ndarray, colinear_tol: float = 1e-12) -> Arcs:
    """The arc through each vertex's previous, own and next position (thesis §5.1.3).

    The circumcentre is the intersection of the perpendicular bisectors
    (thesis §5.1.8); the sweep runs from the previous vertex to the next one
    the way that passes the vertex itself.

    Examples
    --------
    >>> a = three_point_arcs(np.array([[1.0, 0.0], [0.0, 1.0], [-1.0, 0.0], [0.0, -1.0]]))
    >>> a.centre.round(12).tolist()[0], round(float(a.sweep[0]), 6)
    ([0.0, 0.0], 3.141593)
    """
    p2 = np.asarray(points, dtype=np.float64)
    p1, p3 = np.roll(p2, 1, axis=0), np.roll(p2, -1, axis=0)
    centre, radius, straight = vertex_circles(p2, colinear_tol)  # the circumcircles (§5.1.8)
    with np.errstate(invalid="ignore"):
        ang = [np.arctan2(q[:, 1] - centre[:, 1], q[:, 0] - centre[:, 0]) for q in (p1, p2, p3)]
        ccw_end = np.mod(ang[2] - ang[0], 2.0 * np.pi)
        ccw_mid = np.mod(ang[1] - ang[0], 2.0 * np.pi)
        sweep = np.where(ccw_mid < ccw_end, ccw_end, ccw_end - 2.0 * np.pi)
    sweep[straight] = np.nan
    return Arcs(centre, radius, ang[0], sweep)


def arc_points(arcs: Arcs, samples: int = 48) -> np.ndarray:
    """``(n, samples, 2)`` points along each arc (``nan`` rows for co-linear triples)."""
    t = np.linspace(0.0, 1.0, samples)
    th = arcs.start[:, None] + arcs.sweep[:, None] * t[None, :]
    return arcs.centre[:, None, :] + arcs.radius[:, None, None] * np.stack([np.cos(th), np.sin(th)], axis=-1)


def limit_point(points: np.ndarray) -> np.ndarray:
    """Limit position of each control vertex under the cubic B-spline rule.

    Examples
    --------
    >>> limit_point(np.array([[0.0, 0.0], [6.0, 0.0], [0.0, 6.0]])).tolist()[0]
    [1.0, 1.0]
    """
    p = np.asarray(points, dtype=np.float64)
    return (np.roll(p, 1, axis=0) + 4.0 * p + np.roll(p, -1, axis=0)) / 6.0


def limit_radius_of_curvature(points: np.ndarray) -> np.ndarray:
    """Radius of curvature of the limit B-spline at each control vertex's parameter.

    Examples
    --------
    >>> sq = np.array([[1.0, 0.0], [0.0, 1.0], [-1.0, 0.0], [0.0, -1.0]])
    >>> limit_radius_of_curvature(sq).round(6).tolist()
    [0.5, 0.5, 0.5, 0.5]
    """
    p = np.asarray(points, dtype=np.float64)
    prev, nxt = np.roll(p, 1, axis=0), np.roll(p, -1, axis=0)
    d1 = 0.5 * (nxt - prev)
    d2 = prev - 2.0 * p + nxt
    cross = np.abs(d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0])
    with np.errstate(divide="ignore"):
        return np.linalg.norm(d1, axis=1) ** 3 / cross


def radius_convergence(points: np.ndarray, levels: int) -> list[float]:
    """Worst relative gap, per level, between the arcs at the coarse vertices and the limit.

    At level ``k`` the descendants of the control vertices are every
    ``2**k``-th vertex; the arc radius there is compared with the limit
    curve's radius of curvature at the same parameter.  The gap shrinks by
    about a factor of four per level (the arcs "overlay the smooth curve").

    Examples
    --------
    >>> gaps = radius_convergence(np.array([[0.0, 0.0], [3.0, 0.0], [2.0, 2.0], [0.0, 1.0]]), 6)
    >>> gaps[-1] < gaps[1] / 100
    True
    """
    target = limit_radius_of_curvature(points)
    gaps = []
    for k, p in enumerate(bspline_subdivide(points, levels)):
        r = three_point_arcs(p).radius[:: 2**k]
        gaps.append(float(np.max(np.abs(r / target - 1.0))))
    return gaps
