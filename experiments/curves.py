"""Length-preserving curve subdivisions of thesis chapter 5.

Closed polygons are ``(n, 2)`` float64 arrays, counter-clockwise.

* :func:`circle_subdivide` - §5.1.1: a polygon inscribed in a circle; each
  edge gets the point where the bisector of its central angle meets the
  circle, then the radius is scaled by ``L / L'`` so the perimeter is kept.
* :func:`ngon_subdivide` - §5.2.1: the same on a regular ``n``-gon, where
  every edge stays equal (local length preservation).
* :func:`radial_subdivide` - §5.1.4: arbitrary closed curves; each vertex
  carries the circle through it and its two neighbours, and the new point of
  an edge sits on the *averaged* circle (mean centre, mean radius) at the
  mean of the two end angles, averaged the short way round.  With
  ``length="thesis"`` every vertex is then scaled about its own circle's
  centre by ``L_A / L_B`` (§5.1.6, not exact); ``length="exact"`` solves for
  the common scale factor that restores the length to rounding error.
  Near-colinear triples have no usable circle; with the guard of §5.1.10
  (``colinear_tol > 0``) they are treated as straight: their edges get the
  plain midpoint and the vertex is not moved by the length scaling.

Examples
--------
>>> tri = np.array([[1.0, 0.0], [-0.5, 0.8660254037844386], [-0.5, -0.8660254037844386]])
>>> levels = circle_subdivide(tri, 3)
>>> [len(p) for p in levels]
[3, 6, 12, 24]
>>> round(polygon_length(levels[-1]) - polygon_length(tri), 12)
0.0
"""

from __future__ import annotations

from typing import Literal

import numpy as np

__all__ = [
    "polygon_length",
    "regular_polygon",
    "circle_subdivide",
    "ngon_subdivide",
    "vertex_circles",
    "radial_subdivide",
    "reflex_vertices",
    "LengthMode",
]

LengthMode = Literal["none", "thesis", "exact"]


def polygon_length(points: np.ndarray) -> float:
    """Perimeter of a closed polygon.

    Examples
    --------
    >>> polygon_length(np.array([[0.0, 0.0], [3.0, 0.0], [3.0, 4.0]]))
    12.0
    """
    p = np.asarray(points, dtype=np.float64)
    return float(np.linalg.norm(np.roll(p, -1, axis=0) - p, axis=1).sum())


def regular_polygon(n: int, radius: float = 1.0, phase: float = 0.0) -> np.ndarray:
    """Regular ``n``-gon inscribed in a circle about the origin, counter-clockwise.

    Raises
    ------
    ValueError
        If ``n < 3``.

    Examples
    --------
    >>> regular_polygon(4).round(12).tolist()
    [[1.0, 0.0], [0.0, 1.0], [-1.0, 0.0], [-0.0, -1.0]]
    """
    if n < 3:
        raise ValueError(f"a polygon needs n >= 3 vertices, got {n}")
    t = phase + 2.0 * np.pi * np.arange(n) / n
    return radius * np.stack([np.cos(t), np.sin(t)], axis=1)


def circle_subdivide(
    points: np.ndarray, levels: int, centre: tuple[float, float] = (0.0, 0.0)
) -> list[np.ndarray]:
    """Perimeter-preserving, circle-converging subdivision (thesis §5.1.1).

    Parameters
    ----------
    points : numpy.ndarray
        ``(n, 2)`` polygon inscribed in a circle about ``centre``, each
        central angle in ``(0, 180)`` degrees.
    levels : int
        Number of subdivisions.
    centre : tuple of float
        Circle centre ``O``.

    Returns
    -------
    list of numpy.ndarray
        Levels ``0..levels``; level ``i`` has ``n 2**i`` vertices on a circle
        of radius ``R_i = L R_{i-1} / L'_{i-1}``.

    Examples
    --------
    >>> sq = regular_polygon(4)
    >>> out = circle_subdivide(sq, 10)
    >>> abs(polygon_length(out[-1]) - polygon_length(sq)) < 1e-12
    True
    """
    o = np.asarray(centre, dtype=np.float64)
    p = np.asarray(points, dtype=np.float64) - o
    length = polygon_length(p)
    out = [p + o]
    for _ in range(levels):
        r = float(np.linalg.norm(p, axis=1).mean())
        mid = p + np.roll(p, -1, axis=0)  # bisector direction of angle v_i O v_j
        mid = r * mid / np.linalg.norm(mid, axis=1, keepdims=True)
        fine = np.empty((2 * len(p), 2))
        fine[0::2], fine[1::2] = p, mid
        p = fine * (length / polygon_length(fine))  # thesis §5.1.1: R_{i+1} = L R_i / L'_i
        out.append(p + o)
    return out


def ngon_subdivide(n: int, levels: int, radius: float = 1.0) -> list[np.ndarray]:
    """Local length preservation on a regular ``n``-gon (thesis §5.2.1).

    Every level is a regular ``2**i n``-gon with the original perimeter, so
    each coarse edge maps to an equal share of the length.

    Examples
    --------
    >>> out = ngon_subdivide(5, 3)
    >>> e = np.linalg.norm(np.diff(out[-1], axis=0, append=out[-1][:1]), axis=1)
    >>> float(e.max() - e.min()) < 1e-12, len(out[-1])
    (True, 40)
    """
    return circle_subdivide(regular_polygon(n, radius), levels)


def vertex_circles(
    points: np.ndarray, colinear_tol: float = 1e-9
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Circle through every vertex and its two neighbours (thesis §5.1.4).

    Parameters
    ----------
    points : numpy.ndarray
        ``(n, 2)`` closed polygon.
    colinear_tol : float
        A triple whose turn ``|sin|`` is at most this is flagged straight
        (the guard of §5.1.10); ``0`` flags only exact colinearity.

    Returns
    -------
    centres : numpy.ndarray
        ``(n, 2)`` circle centres (``nan`` where straight).
    radii : numpy.ndarray
        ``(n,)`` radii (``inf`` where straight).
    straight : numpy.ndarray
        ``(n,)`` bool.

    Examples
    --------
    >>> c, r, s = vertex_circles(regular_polygon(6, 2.0))
    >>> bool(np.allclose(c, 0.0)), bool(np.allclose(r, 2.0)), bool(s.any())
    (True, True, False)
    """
    p1 = np.roll(points, 1, axis=0)
    p2 = np.asarray(points, dtype=np.float64)
    p3 = np.roll(points, -1, axis=0)
    a, b = p1 - p2, p3 - p2
    cross = a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]
    na, nb = np.einsum("ij,ij->i", a, a), np.einsum("ij,ij->i", b, b)
    straight = np.abs(cross) <= colinear_tol * np.sqrt(na * nb)
    with np.errstate(divide="ignore", invalid="ignore"):
        # Circumcentre relative to p2: perpendicular bisectors of p2p1, p2p3.
        ux = (b[:, 1] * na - a[:, 1] * nb) / (2.0 * cross)
        uy = (a[:, 0] * nb - b[:, 0] * na) / (2.0 * cross)
    centres = p2 + np.stack([ux, uy], axis=1)
    radii = np.hypot(ux, uy)
    centres[straight] = np.nan
    radii[straight] = np.inf
    return centres, radii, straight


def _insert_points(p: np.ndarray, colinear_tol: float) -> np.ndarray:
    """One level of the averaged-circle midpoint insertion (§5.1.4)."""
    c, r, straight = vertex_circles(p, colinear_tol)
    c1, r1, s1 = np.roll(c, -1, axis=0), np.roll(r, -1), np.roll(straight, -1)
    q = np.roll(p, -1, axis=0)
    with np.errstate(invalid="ignore"):
        th0 = np.arctan2(p[:, 1] - c[:, 1], p[:, 0] - c[:, 0])
        th1 = np.arctan2(q[:, 1] - c1[:, 1], q[:, 0] - c1[:, 0])
        dth = np.mod(th1 - th0 + np.pi, 2.0 * np.pi) - np.pi  # short way round
        thn = th0 + 0.5 * dth
        on = 0.5 * (c + c1)  # O_N = (O_0 + O_1) / 2
        rn = 0.5 * (r + r1)  # R_N = (R_0 + R_1) / 2
        mid = on + rn[:, None] * np.stack([np.cos(thn), np.sin(thn)], axis=1)
    lin = straight | s1
    mid[lin] = 0.5 * (p[lin] + q[lin])  # §5.1.10 guard: straight edge, plain midpoint
    fine = np.empty((2 * len(p), 2))
    fine[0::2], fine[1::2] = p, mid
    return fine


def _scale_about_circles(p: np.ndarray, s: float, colinear_tol: float) -> np.ndarray:
    c, _, straight = vertex_circles(p, colinear_tol)
    out = c + s * (p - c)  # thesis §5.1.6: scale each influencing radius
    out[straight] = p[straight]
    return out


def radial_subdivide(
    points: np.ndarray,
    levels: int,
    length: LengthMode = "thesis",
    colinear_tol: float = 1e-9,
    max_iterations: int = 60,
) -> list[np.ndarray]:
    """Radial (averaged-circle) subdivision of a closed curve (§5.1.4-5.1.10).

    Parameters
    ----------
    points : numpy.ndarray
        ``(n, 2)`` counter-clockwise closed polygon, ``n >= 3``.
    levels : int
        Number of subdivisions.
    length : {"none", "thesis", "exact"}
        No length preservation (the interpolating basic scheme); the thesis's
        one-shot scaling of every vertex about its circle's centre by
        ``L_A / L_B`` (§5.1.6); or that scaling with the factor solved
        (secant method) so the length is kept to rounding error.
    colinear_tol : float
        Co-linearity guard of §5.1.10 (see :func:`vertex_circles`); ``0``
        switches it off.
    max_iterations : int
        Secant steps for ``length="exact"``.

    Returns
    -------
    list of numpy.ndarray
        Levels ``0..levels``.

    Raises
    ------
    ValueError
        On fewer than 3 points, a bad ``length`` mode, or an exact solve
        that does not converge (e.g. a concave curve, §5.1.6).

    Examples
    --------
    >>> kite = np.array([[0.0, -1.0], [1.0, 0.0], [0.0, 2.0], [-1.0, 0.0]])
    >>> out = radial_subdivide(kite, 3, length="exact")
    >>> abs(polygon_length(out[-1]) / polygon_length(kite) - 1) < 1e-12
    True
    """
    p = np.asarray(points, dtype=np.float64)
    if p.ndim != 2 or p.shape[1] != 2 or len(p) < 3:
        raise ValueError(f"need an (n >= 3, 2) polygon, got shape {p.shape}")
    if length not in ("none", "thesis", "exact"):
        raise ValueError(f"length mode {length!r} is not one of 'none', 'thesis', 'exact'")
    target = polygon_length(p)
    out = [p]
    for _ in range(levels):
        fine = _insert_points(p, colinear_tol)
        if length == "thesis":
            fine = _scale_about_circles(fine, target / polygon_length(fine), colinear_tol)
        elif length == "exact":
            fine = _solve_scale(fine, target, colinear_tol, max_iterations)
        p = fine
        out.append(p)
    return out


def _solve_scale(p: np.ndarray, target: float, tol: float, iterations: int) -> np.ndarray:
    """Secant solve of ``length(scale(p, s)) = target`` from the thesis's guess."""

    def g(s: float) -> float:
        return polygon_length(_scale_about_circles(p, s, tol)) - target

    s0, s1 = 1.0, target / polygon_length(p)
    g0, g1 = g(s0), g(s1)
    for _ in range(iterations):
        if abs(g1) <= 1e-14 * target or g1 == g0:
            break
        s0, s1, g0 = s1, s1 - g1 * (s1 - s0) / (g1 - g0), g1
        g1 = g(s1)
    if not abs(g1) <= 1e-11 * target:
        raise ValueError(f"exact length scaling did not converge (residual {g1:.3g})")
    return _scale_about_circles(p, s1, tol)


def reflex_vertices(points: np.ndarray) -> int:
    """Number of clockwise turns in a counter-clockwise polygon (concavities, cusps).

    Examples
    --------
    >>> reflex_vertices(np.array([[0.0, 0.0], [2.0, 0.0], [1.0, 0.2], [1.0, 2.0]]))
    1
    """
    p = np.asarray(points, dtype=np.float64)
    a = p - np.roll(p, 1, axis=0)
    b = np.roll(p, -1, axis=0) - p
    return int(np.count_nonzero(a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0] < 0))
