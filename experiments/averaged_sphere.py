"""The averaged-sphere surface subdivision of thesis §5.1.11 (Figure 5.22).

The thesis's "preliminary exploration" extends the radial (averaged-circle)
curve subdivision of §5.1.4 to surfaces: each vertex gets the *average* of
the spheres defined by itself and its neighbours, the mesh is refined, and
every new vertex is placed on the averaged sphere of its edge.  It reports
that at level 2 "the resulting averaged spheres for the vertices become
increasingly large, and their resultant origins further from the mesh", and
that level 3 has "non-smooth, and erratic extrusions".  The thesis gives
neither its polyhedron nor its exact rules; ours, stated here, are the
direct 3D analogue of §5.1.4:

* **vertex sphere**: for vertex ``v`` with one-ring ``n_0 .. n_{k-1}`` (in
  order round ``v``), the sphere through ``v, n_j, n_{j+1}, n_{j+2}`` for every
  ``j`` (four non-coplanar points fix a sphere); the vertex's sphere is the
  mean centre and mean radius of those that are not degenerate (a quadruple
  whose tetrahedron volume is below ``coplanar_tol`` times its longest edge
  cubed is skipped; a vertex with none left is *flat*).
* **refinement**: Loop's 1:4 split (Figure 5.7); old vertices stay (the curve
  scheme interpolates too).
* **repositioning**: the new point of edge ``ab`` lies on the averaged sphere
  ``O_N = (O_a + O_b) / 2``, ``R_N = (R_a + R_b) / 2`` in the direction that
  averages ``a`` and ``b``'s directions from their own centres (the 3D form of
  ``Theta_N = (Theta_1 + Theta_2) / 2``); next to a flat vertex it is the plain
  midpoint (the §5.1.10 guard).

On a polyhedron inscribed in a sphere every vertex sphere is that sphere and
the scheme is Split (1:4) with projected midpoints (§5.1.11: "the surface
will converge to a sphere").  On the irregular octahedron of
:func:`initial_polyhedron` it shows the thesis's failure: see
:func:`run_levels` and docs/experiments.md.

Examples
--------
>>> from dggs.experiments.mesh import icosahedron
>>> ico = icosahedron()
>>> c, r, flat = vertex_spheres(ico.vertices, ico.faces[0])
>>> bool(np.allclose(c, 0.0)), bool(np.allclose(r, 1.0)), bool(flat.any())
(True, True, False)
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = [
    "initial_polyhedron",
    "sphere_through",
    "one_rings",
    "vertex_spheres",
    "subdivide",
    "LevelStats",
    "reflex_faces",
    "run_levels",
]


def initial_polyhedron() -> tuple[np.ndarray, np.ndarray]:
    """An irregular convex octahedron (our stand-in for Figure 5.22(a), which the thesis does not give).

    Returns ``(vertices (6, 3), faces (8, 3))``, faces counter-clockwise from outside.
    """
    v = np.array(
        [[1.6, 0.0, 0.1], [-1.0, 0.15, 0.0], [0.1, 1.2, 0.0], [0.0, -0.9, 0.15], [0.1, 0.1, 1.4], [-0.2, 0.0, -0.8]]
    )
    f = np.array([[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4], [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]])
    return v, _orient(v, f)


def _orient(v: np.ndarray, f: np.ndarray) -> np.ndarray:
    p = v[f]
    n = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    inward = np.einsum("ij,ij->i", n, p.mean(axis=1) - v.mean(axis=0)) < 0
    f = f.copy()
    f[inward] = f[inward, ::-1]
    return f


def sphere_through(p: np.ndarray, coplanar_tol: float = 1e-6) -> tuple[np.ndarray, float] | None:
    """Centre and radius of the sphere through four points, ``None`` if (nearly) coplanar.

    Examples
    --------
    >>> c, r = sphere_through(np.array([[1.0, 0, 0], [0, 1.0, 0], [0, 0, 1.0], [-1.0, 0, 0]]))
    >>> (c.round(12) + 0.0).tolist(), round(r, 12)
    ([0.0, 0.0, 0.0], 1.0)
    """
    d = p[1:] - p[0]
    scale = max(float(np.linalg.norm(d, axis=1).max()), 1e-300)
    det = float(np.linalg.det(d))
    if abs(det) <= coplanar_tol * scale**3:
        return None
    rhs = 0.5 * (np.einsum("ij,ij->i", p[1:], p[1:]) - p[0] @ p[0])
    c = np.linalg.solve(d, rhs)
    return c, float(np.linalg.norm(p[0] - c))


def one_rings(n_vertices: int, faces: np.ndarray) -> list[list[int]]:
    """Neighbours of each vertex in order round it (closed manifold triangle mesh)."""
    nxt: list[dict[int, int]] = [{} for _ in range(n_vertices)]
    for a, b, c in faces:
        nxt[a][b] = c
        nxt[b][c] = a
        nxt[c][a] = b
    rings = []
    for v in range(n_vertices):
        start = next(iter(nxt[v]))
        ring, cur = [start], nxt[v][start]
        while cur != start:
            ring.append(cur)
            cur = nxt[v][cur]
        rings.append(ring)
    return rings


def vertex_spheres(
    vertices: np.ndarray, faces: np.ndarray, coplanar_tol: float = 1e-6
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Averaged sphere of every vertex (mean centre, mean radius); see the module docstring.

    Returns ``centres (V, 3)`` (``nan`` where flat), ``radii (V,)`` (``inf``
    where flat) and ``flat (V,)``.
    """
    v = np.asarray(vertices, dtype=np.float64)
    centres = np.full((len(v), 3), np.nan)
    radii = np.full(len(v), np.inf)
    for i, ring in enumerate(one_rings(len(v), faces)):
        k = len(ring)
        found = [sphere_through(v[[i, ring[j], ring[(j + 1) % k], ring[(j + 2) % k]]], coplanar_tol) for j in range(k)]
        found = [s for s in found if s is not None]
        if found:
            centres[i] = np.mean([c for c, _ in found], axis=0)
            radii[i] = float(np.mean([r for _, r in found]))
    return centres, radii, ~np.isfinite(radii)


def _edges(faces: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Unique undirected edges (sorted rows) and, per face side (ab, bc, ca blocks), its edge index."""
    a = np.concatenate([faces[:, 0], faces[:, 1], faces[:, 2]])
    b = np.concatenate([faces[:, 1], faces[:, 2], faces[:, 0]])
    edges, inverse = np.unique(np.sort(np.stack([a, b], axis=1), axis=1), axis=0, return_inverse=True)
    return edges, inverse.ravel()


def subdivide(
    vertices: np.ndarray, faces: np.ndarray, coplanar_tol: float = 1e-6
) -> tuple[np.ndarray, np.ndarray]:
    """One level: 1:4 split, new points on the edges' averaged spheres (§5.1.11).

    Examples
    --------
    >>> from dggs.experiments.mesh import icosahedron
    >>> v, f = subdivide(icosahedron().vertices, icosahedron().faces[0])
    >>> v.shape, f.shape, bool(np.allclose(np.linalg.norm(v, axis=1), 1.0))
    ((42, 3), (80, 3), True)
    """
    v = np.asarray(vertices, dtype=np.float64)
    c, r, flat = vertex_spheres(v, faces, coplanar_tol)
    edges, inverse = _edges(faces)
    ea, eb = edges[:, 0], edges[:, 1]
    with np.errstate(invalid="ignore"):
        ua = (v[ea] - c[ea]) / r[ea, None]
        ub = (v[eb] - c[eb]) / r[eb, None]
        d = ua + ub
        d /= np.linalg.norm(d, axis=1, keepdims=True)
        new = 0.5 * (c[ea] + c[eb]) + 0.5 * (r[ea] + r[eb])[:, None] * d
    plain = flat[ea] | flat[eb] | ~np.isfinite(new).all(axis=1)
    new[plain] = 0.5 * (v[ea[plain]] + v[eb[plain]])
    ids = len(v) + inverse.ravel()
    mab, mbc, mca = np.split(ids, 3)
    fa, fb, fc = faces[:, 0], faces[:, 1], faces[:, 2]
    fine = np.concatenate(
        [np.stack(t, axis=1) for t in ((fa, mab, mca), (fb, mbc, mab), (fc, mca, mbc), (mab, mbc, mca))]
    )
    return np.concatenate([v, new]), fine


@dataclass(frozen=True)
class LevelStats:
    """What §5.1.11 describes, measured at one level (lengths in units of the level-0 mesh's size).

    Attributes
    ----------
    level, vertices, faces : int
        Level and counts.
    flat : int
        Vertices with no usable sphere (all neighbour quadruples coplanar).
    median_radius, max_radius : float
        Averaged-sphere radii over the level-0 size (the half-diagonal of the
        level-0 bounding box).
    max_origin_offset : float
        Largest distance of a sphere centre from the level-0 centroid, same unit.
    reflex_edges : int
        Edges whose two faces fold inwards (a local non-convexity).  Not only
        extrusions: a fixed 1:4 connectivity on points of a sphere can be
        non-convex too (the tetrahedron's skinny children).
    max_bulge : float
        Largest distance of a new vertex from its edge's chord midpoint over
        the edge length (0 at level 0).  On a sphere it halves every level
        (a sagitta: about ``edge / (8 R)``); growth is the erratic extrusion.
    max_extrusion : float
        Largest distance of a vertex from the level-0 bounding box's centre
        beyond the level-0 mesh's own largest such distance, same unit (0 when
        the surface stays inside).
    """

    level: int
    vertices: int
    faces: int
    flat: int
    median_radius: float
    max_radius: float
    max_origin_offset: float
    reflex_edges: int
    max_bulge: float
    max_extrusion: float


def reflex_faces(v: np.ndarray, faces: np.ndarray) -> tuple[int, np.ndarray]:
    """Edges whose dihedral is concave (the neighbour's far vertex above a face's plane), and a mask of their faces."""
    count = 0
    opposite: dict[tuple[int, int], tuple[int, int]] = {}
    for k, (a, b, c) in enumerate(faces):
        for x, y, z in ((a, b, c), (b, c, a), (c, a, b)):
            opposite[(x, y)] = (z, k)
    mask = np.zeros(len(faces), dtype=bool)
    for (x, y), (z, k) in opposite.items():
        if x < y:
            w, j = opposite[(y, x)]
            n = np.cross(v[y] - v[x], v[z] - v[x])
            scale = np.linalg.norm(v[y] - v[x]) ** 3
            if np.dot(v[w] - v[x], n) > 1e-9 * scale:
                count += 1
                mask[[k, j]] = True
    return count, mask


def run_levels(levels: int = 3, vertices=None, faces=None, coplanar_tol: float = 1e-6):
    """Meshes and :class:`LevelStats` for levels ``0..levels`` (Figure 5.22).

    Returns ``(meshes, stats)`` where ``meshes[k] = (vertices, faces, centres, radii)``.

    Examples
    --------
    >>> meshes, stats = run_levels(2)
    >>> [s.faces for s in stats]
    [8, 32, 128]
    """
    if vertices is None:
        vertices, faces = initial_polyhedron()
    v = np.asarray(vertices, dtype=np.float64)
    f = _orient(v, np.asarray(faces))  # counter-clockwise from outside (a convex start)
    lo, hi = v.min(axis=0), v.max(axis=0)
    mid, size = 0.5 * (lo + hi), 0.5 * float(np.linalg.norm(hi - lo))
    reach0 = float(np.linalg.norm(v - mid, axis=1).max())
    meshes, stats = [], []
    for level in range(levels + 1):
        bulge = 0.0
        if level:
            edges, _ = _edges(f)
            n_old = len(v)
            v, f = subdivide(v, f, coplanar_tol)
            ends = v[edges]
            chord = np.linalg.norm(ends[:, 1] - ends[:, 0], axis=1)
            bulge = float((np.linalg.norm(v[n_old:] - ends.mean(axis=1), axis=1) / chord).max())
        c, r, flat = vertex_spheres(v, f, coplanar_tol)
        ok = ~flat
        reach = float(np.linalg.norm(v - mid, axis=1).max())
        meshes.append((v, f, c, r))
        stats.append(
            LevelStats(
                level,
                len(v),
                len(f),
                int(flat.sum()),
                float(np.median(r[ok]) / size) if ok.any() else float("inf"),
                float(r[ok].max() / size) if ok.any() else float("inf"),
                float(np.linalg.norm(c[ok] - mid, axis=1).max() / size) if ok.any() else float("inf"),
                reflex_faces(v, f)[0],
                bulge,
                max(reach - reach0, 0.0) / size,
            )
        )
    return meshes, stats
