"""Plain numpy polygon meshes for the thesis's subdivision experiments.

A mesh is a ``(V, 3)`` float64 vertex array plus one or more *face blocks*:
``(F_k, k)`` int arrays holding the faces that have ``k`` sides, each listed
counter-clockwise seen from outside.  Triangle meshes have one ``(F, 3)``
block; Split (1:5) mixes pentagons and hexagons, so it carries two blocks.

Everything here is vectorised over faces; nothing loops over faces in Python.

Examples
--------
>>> m = icosahedron()
>>> m.vertices.shape, m.faces[0].shape
((12, 3), (20, 3))
>>> round(float(face_areas(m).sum()), 6)
9.574541
"""

from __future__ import annotations

from dataclasses import dataclass
from itertools import combinations

import numpy as np

__all__ = [
    "Mesh",
    "icosahedron",
    "dodecahedron",
    "normalize",
    "face_areas",
    "face_centres",
    "total_area",
    "edge_table",
    "half_edges",
]


@dataclass(frozen=True)
class Mesh:
    """A polygon mesh: vertices and face blocks of equal side count.

    Parameters
    ----------
    vertices : numpy.ndarray
        ``(V, 3)`` float64 positions.
    faces : tuple of numpy.ndarray
        Face blocks, each ``(F_k, k)`` int64, counter-clockwise from outside.

    Examples
    --------
    >>> m = icosahedron()
    >>> m.num_faces, m.num_vertices
    (20, 12)
    """

    vertices: np.ndarray
    faces: tuple[np.ndarray, ...]

    @property
    def num_faces(self) -> int:
        """Total number of faces over all blocks."""
        return int(sum(len(b) for b in self.faces))

    @property
    def num_vertices(self) -> int:
        """Number of vertices."""
        return int(len(self.vertices))

    def with_vertices(self, vertices: np.ndarray) -> Mesh:
        """Return the same connectivity on new vertex positions."""
        return Mesh(np.asarray(vertices, dtype=np.float64), self.faces)


def normalize(points: np.ndarray, radius: float = 1.0) -> np.ndarray:
    """Push points radially onto the sphere of ``radius`` about the origin.

    Parameters
    ----------
    points : numpy.ndarray
        ``(..., 3)`` positions, none at the origin.
    radius : float
        Target radius.

    Returns
    -------
    numpy.ndarray
        Points with norm ``radius``.

    Examples
    --------
    >>> normalize(np.array([[3.0, 4.0, 0.0]])).tolist()
    [[0.6, 0.8, 0.0]]
    """
    points = np.asarray(points, dtype=np.float64)
    return radius * points / np.linalg.norm(points, axis=-1, keepdims=True)


def _orient_outward(vertices: np.ndarray, faces: np.ndarray) -> np.ndarray:
    """Reverse the rows whose polygon normal points towards the origin."""
    p = vertices[faces]
    normal = np.cross(p, np.roll(p, -1, axis=1)).sum(axis=1)  # Newell normal
    inward = np.einsum("ij,ij->i", normal, p.mean(axis=1)) < 0
    faces = faces.copy()
    faces[inward] = faces[inward, ::-1]
    return faces


def icosahedron(radius: float = 1.0) -> Mesh:
    """The regular icosahedron inscribed in a sphere (thesis Figure 6.1).

    Parameters
    ----------
    radius : float
        Circumscribing sphere radius.

    Returns
    -------
    Mesh
        12 vertices, one ``(20, 3)`` block.

    Examples
    --------
    >>> m = icosahedron()
    >>> bool(np.allclose(np.linalg.norm(m.vertices, axis=1), 1.0))
    True
    """
    phi = (1.0 + 5.0**0.5) / 2.0
    base = []
    for a in (-1.0, 1.0):
        for b in (-phi, phi):
            base += [(0.0, a, b), (a, b, 0.0), (b, 0.0, a)]
    v = normalize(np.array(base), radius)
    # Faces are the vertex triples at mutual minimum (edge) distance.
    d = np.linalg.norm(v[:, None] - v[None], axis=-1)
    adj = np.abs(d - d[d > 1e-9].min()) < 1e-6 * radius
    tri = np.array(list(combinations(range(12), 3)))
    keep = adj[tri[:, 0], tri[:, 1]] & adj[tri[:, 1], tri[:, 2]] & adj[tri[:, 0], tri[:, 2]]
    faces = _orient_outward(v, tri[keep].astype(np.int64))
    return Mesh(v, (faces,))


def dodecahedron(radius: float = 1.0) -> Mesh:
    """The regular dodecahedron inscribed in a sphere (thesis Figure 6.8).

    Built as the dual of :func:`icosahedron`: one vertex per icosahedron
    face, one pentagon per icosahedron vertex.

    Parameters
    ----------
    radius : float
        Circumscribing sphere radius.

    Returns
    -------
    Mesh
        20 vertices, one ``(12, 5)`` block.

    Examples
    --------
    >>> dodecahedron().faces[0].shape
    (12, 5)
    """
    ico = icosahedron()
    tri = ico.faces[0]
    verts = normalize(ico.vertices[tri].mean(axis=1), radius)
    # Around each icosahedron vertex, order its 5 incident faces by angle.
    fid = (np.argsort(tri.ravel(), kind="stable") // 3).reshape(12, 5)
    n = ico.vertices
    u = verts[fid] - n[:, None, :]
    e1 = normalize(u[:, 0] - np.einsum("vj,vj->v", u[:, 0], n)[:, None] * n)
    e2 = np.cross(n, e1)
    ang = np.arctan2(np.einsum("vkj,vj->vk", u, e2), np.einsum("vkj,vj->vk", u, e1))
    faces = np.take_along_axis(fid, np.argsort(ang, axis=1), axis=1)
    return Mesh(verts, (_orient_outward(verts, faces.astype(np.int64)),))


def face_centres(mesh: Mesh) -> np.ndarray:
    """Vertex average of every face, blocks concatenated in order.

    This is the face "midpoint" of thesis §6.3.3 (Table 6.3).

    Examples
    --------
    >>> c = face_centres(icosahedron())
    >>> round(float(np.linalg.norm(c, axis=1).min()), 4)
    0.7947
    """
    return np.concatenate([mesh.vertices[b].mean(axis=1) for b in mesh.faces])


def face_areas(mesh: Mesh) -> np.ndarray:
    """Area of every face, blocks concatenated in order.

    Triangles get their exact (planar, chord) area.  A polygon with more
    sides is fanned into triangles from its vertex average; this is exact for
    planar convex polygons and is our documented choice for the non-planar
    quadrilaterals and hexagons of Catmull-Clark and Split (1:5), about which
    the thesis is silent (§6.1.3, §6.1.6).

    Examples
    --------
    >>> a = face_areas(icosahedron())
    >>> bool(np.allclose(a, a[0]))
    True
    """
    out = []
    for block in mesh.faces:
        p = mesh.vertices[block]
        if block.shape[1] == 3:
            cr = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
            out.append(0.5 * np.linalg.norm(cr, axis=1))
            continue
        c = p.mean(axis=1, keepdims=True)
        cr = np.cross(p - c, np.roll(p, -1, axis=1) - c)
        out.append(0.5 * np.linalg.norm(cr, axis=2).sum(axis=1))
    return np.concatenate(out)


def total_area(mesh: Mesh) -> float:
    """Sum of :func:`face_areas` with compensated summation.

    Examples
    --------
    >>> round(total_area(icosahedron()), 6)
    9.574541
    """
    import math

    return math.fsum(face_areas(mesh).tolist())


def edge_table(faces: tuple[np.ndarray, ...]) -> tuple[np.ndarray, tuple[np.ndarray, ...]]:
    """Unique undirected edges of a mesh and, per face corner, its edge id.

    Parameters
    ----------
    faces : tuple of numpy.ndarray
        Face blocks.

    Returns
    -------
    edges : numpy.ndarray
        ``(E, 2)`` vertex pairs, smaller id first.
    corner_edge : tuple of numpy.ndarray
        For each block, ``(F_k, k)`` ids into ``edges``; column ``i`` is the
        edge from corner ``i`` to corner ``i + 1``.

    Examples
    --------
    >>> edges, ce = edge_table(icosahedron().faces)
    >>> edges.shape, ce[0].shape
    ((30, 2), (20, 3))
    """
    pairs = []
    for b in faces:
        pairs.append(np.stack([b, np.roll(b, -1, axis=1)], axis=-1).reshape(-1, 2))
    allp = np.sort(np.concatenate(pairs), axis=1)
    edges, inverse = np.unique(allp, axis=0, return_inverse=True)
    inverse = inverse.ravel()
    out, start = [], 0
    for b in faces:
        n = b.size
        out.append(inverse[start : start + n].reshape(b.shape))
        start += n
    return edges, tuple(out)


def half_edges(faces: tuple[np.ndarray, ...]) -> dict[str, np.ndarray]:
    """Half-edge arrays for a closed, consistently oriented mesh.

    Half-edge ``h`` runs from ``origin[h]`` to ``target[h]`` inside face
    ``face[h]``; ``next[h]`` follows it round that face and ``twin[h]`` is
    the opposite half-edge in the neighbouring face.

    Examples
    --------
    >>> he = half_edges(icosahedron().faces)
    >>> len(he["twin"]), bool((he["twin"][he["twin"]] == np.arange(60)).all())
    (60, True)
    """
    origin, target, face, nxt = [], [], [], []
    h0, f0 = 0, 0
    for b in faces:
        f, k = b.shape
        ids = h0 + np.arange(f * k).reshape(f, k)
        origin.append(b.ravel())
        target.append(np.roll(b, -1, axis=1).ravel())
        face.append(np.repeat(f0 + np.arange(f), k))
        nxt.append(np.roll(ids, -1, axis=1).ravel())
        h0 += f * k
        f0 += f
    origin_a, target_a = np.concatenate(origin), np.concatenate(target)
    nv = int(max(origin_a.max(), target_a.max())) + 1
    key = origin_a * nv + target_a
    order = np.argsort(key)
    twin_key = target_a * nv + origin_a
    pos = np.searchsorted(key[order], twin_key)
    twin = order[np.clip(pos, 0, len(order) - 1)]
    if not np.array_equal(key[twin], twin_key):
        raise ValueError("mesh is not closed and consistently oriented")
    return {
        "origin": origin_a,
        "target": target_a,
        "face": np.concatenate(face),
        "next": np.concatenate(nxt),
        "twin": twin,
    }
