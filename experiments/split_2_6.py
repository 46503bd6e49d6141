"""Split (2:6) as a 3D mesh refinement (thesis §6.1.7).

Level 1 is Split (1:6) (:func:`~dggs.experiments.split_triangles.split_1_6`),
which leaves 120 congruent 30-60-90 triangles listed in role order
``(A, B, C)`` = corners of 30°, 60°, 90°.  Every later level turns each face
into ``(B, D, C)``, ``(B, D, E)`` and ``(A, D, E)`` (again in role order):
``E`` lies on the hypotenuse ``AB``, shared with the mirror-image partner face
(the "2" of 2:6), and ``D`` on the long leg ``AC``, shared with the neighbour
across it.  In the plane ``E`` is the midpoint of ``AB`` and ``D`` is a third
of the way from ``C`` to ``A`` (bisecting the 60° angle, Figure 6.12), and the
three children are congruent.

On the sphere the thesis only says the points are "selected and positioned
based on the preservation of local area".  ``placement`` chooses:

``"area"`` (default)
    per face, solve (two Newton unknowns: the fractions along ``AB`` and
    ``AC``) for the points that give the three children equal chord area
    once projected onto the sphere; each shared point is then the
    projected mean of the two faces' wishes.  dggs's own scheme, better than
    the thesis's (0.30 % maximum face error at level 7 against 16.63 %).
``"thesis"``
    the thesis's own rule, recovered from its Tables 6.3-6.6: ``E`` is the
    chord midpoint of the hypotenuse and ``D`` sits at one fixed chord
    fraction ``t`` from ``C`` towards ``A``, the ``t`` (0.345050, see
    :func:`thesis_fraction`) that gives the level-1 child ``BDC`` exactly a
    third of the chord area of the level-1 face's three children, reused at
    every level.  Table 6.6 (0.21, 2.28, 5.37, 8.91, 12.69, 16.63 at levels
    2-7) and Tables 6.3-6.5 follow; the error grows because one ``t`` does
    not fit the flatter triangles of later levels.
``"chord"`` / ``"arc"``
    the planar fractions (1/2 and 1/3) along the chord or the great-circle
    arc, as in :mod:`dggs.experiments.split_triangles`.

Examples
--------
>>> from dggs.experiments.mesh import icosahedron
>>> from dggs.experiments.split_triangles import split_1_6
>>> split_2_6(split_1_6(icosahedron())).num_faces
360
"""

from __future__ import annotations

from functools import lru_cache
from typing import Literal

import numpy as np

from dggs.experiments.mesh import Mesh, normalize
from dggs.experiments.split_triangles import point_on_edge

__all__ = ["Placement26", "split_2_6", "equal_area_fractions", "thesis_fraction"]

Placement26 = Literal["area", "thesis", "chord", "arc"]


def _tri_area(p: np.ndarray, q: np.ndarray, r: np.ndarray) -> np.ndarray:
    return 0.5 * np.linalg.norm(np.cross(q - p, r - p), axis=-1)


def _children(a, b, c, s, t, radius):
    e = normalize(a + (b - a) * s[:, None], radius)
    d = normalize(c + (a - c) * t[:, None], radius)
    return _tri_area(b, d, c), _tri_area(b, d, e), _tri_area(a, d, e), d, e


def equal_area_fractions(
    a: np.ndarray, b: np.ndarray, c: np.ndarray, radius: float, iterations: int = 12
) -> tuple[np.ndarray, np.ndarray]:
    """Chord fractions ``s`` (A->B) and ``t`` (C->A) giving equal child areas.

    Vectorised Newton iteration with a finite-difference Jacobian, started at
    the planar answer ``s = 1/2``, ``t = 1/3``.

    Parameters
    ----------
    a, b, c : numpy.ndarray
        ``(N, 3)`` role-ordered corners on the sphere.
    radius : float
        Sphere radius.
    iterations : int
        Newton steps (quadratic convergence; 12 is ample).

    Returns
    -------
    s, t : numpy.ndarray
        ``(N,)`` fractions.

    Examples
    --------
    >>> from dggs.experiments.mesh import icosahedron
    >>> from dggs.experiments.split_triangles import split_1_6
    >>> m = split_1_6(icosahedron())
    >>> f = m.faces[0][:1]
    >>> s, t = equal_area_fractions(*(m.vertices[f[:, i]] for i in range(3)), 1.0)
    >>> round(float(s[0]), 3), round(float(t[0]), 3)
    (0.501, 0.345)
    """
    s = np.full(len(a), 0.5)
    t = np.full(len(a), 1.0 / 3.0)
    h = 1e-7

    def residual(s_: np.ndarray, t_: np.ndarray) -> np.ndarray:
        a1, a2, a3, _, _ = _children(a, b, c, s_, t_, radius)
        return np.stack([a1 - a2, a2 - a3], axis=1) / (a1 + a2 + a3)[:, None]

    for _ in range(iterations):
        f0 = residual(s, t)
        jac = np.stack([(residual(s + h, t) - f0) / h, (residual(s, t + h) - f0) / h], axis=2)
        step = np.linalg.solve(jac, -f0[..., None])[..., 0]
        s, t = s + step[:, 0], t + step[:, 1]
    return s, t


@lru_cache(maxsize=1)
def thesis_fraction() -> float:
    """The thesis's fixed chord fraction ``t`` of ``D`` from ``C`` towards ``A`` (``placement="thesis"``).

    On a level-1 face (Split (1:6) of the unit icosahedron) with ``E`` the
    projected chord midpoint of ``AB``, ``t`` solves (bisection)
    ``area(BDC) = (area(BDC) + area(BDE) + area(ADE)) / 3`` in chord
    (flat-triangle) areas.  Requiring a third of the face's *spherical* area
    instead gives ``t = 0.344505`` and misses Table 6.6 (0.29 % at level 2
    against the printed 0.21 %).

    Examples
    --------
    >>> round(thesis_fraction(), 6)
    0.34505
    """
    from dggs.experiments.mesh import icosahedron
    from dggs.experiments.split_triangles import split_1_6

    m = split_1_6(icosahedron())
    f = m.faces[0][:1]
    a, b, c = (m.vertices[f[:, i]] for i in range(3))
    e = normalize(0.5 * (a + b))

    def excess(t: float) -> float:
        d = normalize(c + (a - c) * t)
        bdc, bde, ade = _tri_area(b, d, c)[0], _tri_area(b, d, e)[0], _tri_area(a, d, e)[0]
        return float(bdc - (bdc + bde + ade) / 3.0)

    lo, hi = 0.25, 0.45  # excess(lo) < 0 < excess(hi)
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if excess(mid) < 0 else (lo, mid)
    return 0.5 * (lo + hi)


def _shared_mean(n_old: int, p: np.ndarray, q: np.ndarray, pts: np.ndarray, radius: float):
    """One new vertex per undirected edge: the projected mean of the rows' points."""
    key = np.sort(np.stack([p, q], axis=1), axis=1)
    uniq, inverse = np.unique(key, axis=0, return_inverse=True)
    inverse = inverse.ravel()
    acc = np.zeros((len(uniq), 3))
    np.add.at(acc, inverse, pts)
    return n_old + inverse, normalize(acc, radius)


def split_2_6(mesh: Mesh, placement: Placement26 = "area") -> Mesh:
    """One Split (2:6) step on role-ordered 30-60-90 triangles.

    Parameters
    ----------
    mesh : Mesh
        Output of :func:`~dggs.experiments.split_triangles.split_1_6` or of
        this function (faces in role order).
    placement : {"area", "thesis", "chord", "arc"}
        Where ``D`` and ``E`` go on the sphere (module docstring).

    Returns
    -------
    Mesh
        Three faces per face, in role order.

    Raises
    ------
    ValueError
        If ``placement`` is unknown.

    Examples
    --------
    >>> from dggs.experiments.mesh import icosahedron
    >>> from dggs.experiments.split_triangles import split_1_6
    >>> m = split_2_6(split_2_6(split_1_6(icosahedron())))
    >>> m.num_faces
    1080
    """
    f = mesh.faces[0]
    v = mesh.vertices
    r = float(np.linalg.norm(v, axis=1).mean())
    a, b, c = f[:, 0], f[:, 1], f[:, 2]
    if placement == "area":
        s, t = equal_area_fractions(v[a], v[b], v[c], r)
        _, _, _, d_pts, e_pts = _children(v[a], v[b], v[c], s, t, r)
    elif placement == "thesis":
        e_pts = normalize(0.5 * (v[a] + v[b]), r)
        d_pts = normalize(v[c] + (v[a] - v[c]) * thesis_fraction(), r)
    elif placement in ("chord", "arc"):
        e_pts = point_on_edge(v[a], v[b], 0.5, r, placement)
        d_pts = point_on_edge(v[c], v[a], 1.0 / 3.0, r, placement)
    else:
        raise ValueError(f"placement {placement!r} is not one of 'area', 'thesis', 'chord', 'arc'")
    e_ids, e_new = _shared_mean(len(v), a, b, e_pts, r)
    d_ids, d_new = _shared_mean(len(v) + len(e_new), c, a, d_pts, r)
    faces = np.concatenate(
        [np.stack(t_, axis=1) for t_ in ((b, d_ids, c), (b, d_ids, e_ids), (a, d_ids, e_ids))]
    )
    return Mesh(np.concatenate([v, e_new, d_new]), (faces,))
