"""Triangle-to-triangle refinements of thesis §6.1: Splits (1:3), (1:4), (1:6), (1:9).

Each function takes a triangle :class:`~dggs.experiments.mesh.Mesh` whose
vertices lie on a sphere about the origin and returns the refined mesh with
every *new* vertex pushed radially onto that same sphere (thesis §6.2: "the
vertices were re-projected to the surface of the inscribing sphere").  Old
vertices never move; the global area rescale of §5.1.2 is applied afterwards
by :func:`dggs.experiments.preservation.rescale_to_area`.

Where the thesis does not say where a new point goes on its edge (the Split (1:9)
edge thirds), ``placement`` chooses:

``"chord"``
    the point at the stated fraction along the straight chord, then pushed
    radially onto the sphere (the construction of Figures 6.4 and 6.12 drawn
    on the flat face, then projected);
``"arc"``
    the point at the stated fraction of the great-circle arc (equal angles).

Midpoints are the same under both rules.

Examples
--------
>>> from dggs.experiments.mesh import icosahedron
>>> split_1_4(icosahedron()).num_faces
80
"""

from __future__ import annotations

from typing import Literal

import numpy as np

from dggs.experiments.mesh import Mesh, normalize

__all__ = [
    "Placement",
    "point_on_edge",
    "split_1_3",
    "split_1_4",
    "split_1_6",
    "split_1_9",
]

Placement = Literal["chord", "arc"]


def _radius(vertices: np.ndarray) -> float:
    """Radius of the common circumscribing sphere."""
    return float(np.linalg.norm(vertices, axis=1).mean())


def point_on_edge(
    a: np.ndarray, b: np.ndarray, t: float, radius: float, placement: Placement = "chord"
) -> np.ndarray:
    """Point a fraction ``t`` of the way from ``a`` to ``b``, on the sphere.

    Parameters
    ----------
    a, b : numpy.ndarray
        ``(N, 3)`` endpoints on the sphere of ``radius``.
    t : float
        Fraction from ``a`` (0) to ``b`` (1).
    radius : float
        Sphere radius.
    placement : {"chord", "arc"}
        Fraction of the chord (then projected) or of the great-circle arc.

    Returns
    -------
    numpy.ndarray
        ``(N, 3)`` points on the sphere.

    Examples
    --------
    >>> a, b = np.array([[1.0, 0, 0]]), np.array([[0, 1.0, 0]])
    >>> point_on_edge(a, b, 1 / 3, 1.0, "arc").round(6).tolist()
    [[0.866025, 0.5, 0.0]]
    """
    if placement == "chord":
        return normalize((1.0 - t) * a + t * b, radius)
    if placement != "arc":
        raise ValueError(f"placement {placement!r} is not one of 'chord', 'arc'")
    ua, ub = a / radius, b / radius
    omega = np.arccos(np.clip(np.einsum("ij,ij->i", ua, ub), -1.0, 1.0))[:, None]
    s = np.sin(omega)
    return radius * (np.sin((1.0 - t) * omega) * ua + np.sin(t * omega) * ub) / s


def _shared_points(
    n_old: int, a: np.ndarray, b: np.ndarray, points: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """Deduplicate per-face edge points: one new vertex per undirected edge.

    Returns the new vertex id of every row and the unique new positions.
    The position kept for an edge is the first row's; neighbours that share
    an edge compute the same point by construction (tested).
    """
    key = np.sort(np.stack([a, b], axis=1), axis=1)
    _, first, inverse = np.unique(key, axis=0, return_index=True, return_inverse=True)
    return n_old + inverse.ravel(), points[first]


def _triangles(mesh: Mesh) -> np.ndarray:
    if len(mesh.faces) != 1 or mesh.faces[0].shape[1] != 3:
        raise ValueError("this split needs a pure triangle mesh")
    return mesh.faces[0]


def split_1_3(mesh: Mesh) -> Mesh:
    """Split (1:3): join the projected face centroid to the three corners (§6.1.4).

    Examples
    --------
    >>> from dggs.experiments.mesh import icosahedron
    >>> split_1_3(icosahedron()).faces[0].shape
    (60, 3)
    """
    f = _triangles(mesh)
    v = mesh.vertices
    r = _radius(v)
    c = normalize(v[f].mean(axis=1), r)  # thesis §6.1.4: v_f = (1/n) sum v_i
    ci = len(v) + np.arange(len(f))
    a, b, cc = f[:, 0], f[:, 1], f[:, 2]
    faces = np.concatenate([np.stack(t, axis=1) for t in ((a, b, ci), (b, cc, ci), (cc, a, ci))])
    return Mesh(np.concatenate([v, c]), (faces,))


def split_1_4(mesh: Mesh) -> Mesh:
    """Split (1:4): Loop's connectivity, midpoints pushed to the sphere (§6.1.1).

    Original vertices are not smoothed ("we eliminate the repositioning of
    the vertices").

    Examples
    --------
    >>> from dggs.experiments.mesh import icosahedron
    >>> m = split_1_4(icosahedron())
    >>> m.num_vertices, m.num_faces
    (42, 80)
    """
    f = _triangles(mesh)
    v = mesh.vertices
    r = _radius(v)
    a, b, c = f[:, 0], f[:, 1], f[:, 2]
    rows_a = np.concatenate([a, b, c])
    rows_b = np.concatenate([b, c, a])
    pts = normalize(0.5 * (v[rows_a] + v[rows_b]), r)
    ids, new = _shared_points(len(v), rows_a, rows_b, pts)
    mab, mbc, mca = np.split(ids, 3)
    faces = np.concatenate(
        [
            np.stack(t, axis=1)
            for t in ((a, mab, mca), (b, mbc, mab), (c, mca, mbc), (mab, mbc, mca))
        ]
    )
    return Mesh(np.concatenate([v, new]), (faces,))


def split_1_6(mesh: Mesh) -> Mesh:
    """Split (1:6): centroid plus edge midpoints, six triangles per face (§6.1.5).

    Faces are listed in *role order* (original vertex, centroid, edge
    midpoint), i.e. the 30°, 60° and 90° corners of the first level's
    30-60-90 triangles, which Split (2:6) relies on; half of them are
    therefore clockwise.  Areas and centres do not depend on orientation.

    Examples
    --------
    >>> from dggs.experiments.mesh import icosahedron
    >>> split_1_6(icosahedron()).num_faces
    120
    """
    f = _triangles(mesh)
    v = mesh.vertices
    r = _radius(v)
    g = normalize(v[f].mean(axis=1), r)  # thesis §6.1.5: v_f = (1/n) sum v_i
    gi = len(v) + np.arange(len(f))
    a, b, c = f[:, 0], f[:, 1], f[:, 2]
    rows_a = np.concatenate([a, b, c])
    rows_b = np.concatenate([b, c, a])
    pts = normalize(0.5 * (v[rows_a] + v[rows_b]), r)  # v_e = (v_i + v_i+1) / 2
    ids, new = _shared_points(len(v) + len(f), rows_a, rows_b, pts)
    mab, mbc, mca = np.split(ids, 3)
    faces = np.concatenate(
        [
            np.stack(t, axis=1)
            for t in (
                (a, gi, mab),
                (b, gi, mab),
                (b, gi, mbc),
                (c, gi, mbc),
                (c, gi, mca),
                (a, gi, mca),
            )
        ]
    )
    return Mesh(np.concatenate([v, g, new]), (faces,))


def split_1_9(mesh: Mesh, placement: Placement = "arc") -> Mesh:
    """Split (1:9): edges cut in thirds plus the centroid, nine triangles (§6.1.2).

    The thesis does not say where the thirds go once on the sphere; see the
    module docstring for ``placement``.  The default ``"arc"`` (equal
    angles) reproduces Tables 6.3-6.4 for this split exactly and Table 6.6
    to within 0.08 percentage points; ``"chord"`` is far off (15 % maximum
    face error at level 1 against the thesis's 8.12 %).  The centre point is
    the projected centroid of the three corners.

    Examples
    --------
    >>> from dggs.experiments.mesh import icosahedron
    >>> split_1_9(icosahedron()).num_faces
    180
    """
    f = _triangles(mesh)
    v = mesh.vertices
    r = _radius(v)
    g = normalize(v[f].mean(axis=1), r)
    gi = len(v) + np.arange(len(f))
    a, b, c = f[:, 0], f[:, 1], f[:, 2]
    # Each undirected edge gets two points; orient each edge from its smaller
    # id so both neighbouring faces name the same two points.
    starts = np.concatenate([a, b, c])
    ends = np.concatenate([b, c, a])
    lo, hi = np.minimum(starts, ends), np.maximum(starts, ends)
    near_lo = point_on_edge(v[lo], v[hi], 1.0 / 3.0, r, placement)
    near_hi = point_on_edge(v[lo], v[hi], 2.0 / 3.0, r, placement)
    base = len(v) + len(f)
    id_lo, new_lo = _shared_points(base, lo, hi, near_lo)
    id_hi, new_hi = _shared_points(base + len(new_lo), lo, hi, near_hi)
    swap = starts > ends
    first = np.where(swap, id_hi, id_lo)  # point a third of the way from `starts`
    second = np.where(swap, id_lo, id_hi)
    ab1, bc1, ca1 = np.split(first, 3)
    ab2, bc2, ca2 = np.split(second, 3)
    tris = (
        (a, ab1, ca2),
        (ab1, gi, ca2),
        (ab1, ab2, gi),
        (ab2, bc1, gi),
        (ab2, b, bc1),
        (bc1, bc2, gi),
        (bc2, c, ca1),
        (bc2, ca1, gi),
        (gi, ca1, ca2),
    )
    faces = np.concatenate([np.stack(t, axis=1) for t in tris])
    return Mesh(np.concatenate([v, g, new_lo, new_hi]), (faces,))
