"""Refinements that leave the triangle world: Catmull-Clark (§6.1.3) and Split (1:5) (§6.1.6).

As in :mod:`dggs.experiments.split_triangles`, old vertices stay where they
are and new vertices are pushed radially onto the common sphere; the global
rescale of §5.1.2 follows.

Catmull-Clark (``rule="projected"``, dggs's)
    One face point per face (vertex average) and one edge point per edge
    (chord midpoint), both projected; each ``k``-gon becomes ``k`` quads
    ``(corner, edge point, face point, edge point)``.  Catmull and Clark's
    smoothing weights are *not* used: every point is projected onto the
    sphere anyway, exactly as the thesis treats Loop's scheme in §6.1.1.  (The
    first level's quads then sit 5.31 % inside the sphere at their centres,
    as Table 6.3 reports.)
Catmull-Clark (``rule="standard"``, the thesis's)
    Catmull and Clark's own point rules: face point = vertex average, edge
    point ``(v1 + v2 + f1 + f2) / 4``, old vertex moved to
    ``(Q + 2 R + (n - 3) S) / n``; nothing is projected here.  The thesis then
    rescales from this *raw* mesh's area and projects afterwards
    (:func:`dggs.experiments.schemes.catmull_clark_thesis_step`), which
    reproduces its Tables 6.1 and 6.3-6.6 cell for cell.
Split (1:5)
    The dual of Kobbelt's sqrt(3) subdivision ("leapfrog"): each face is kept
    as a smaller, rotated copy of itself and every vertex of valence ``d``
    is replaced by a ``2d``-gon (a hexagon on these trivalent meshes), so a
    dodecahedron becomes a truncated icosahedron and
    ``F' = F + V`` (Table 6.2: 32, 92, 272, ...).  The new vertex on the
    ``f``-side of edge ``(v, w)`` is the projected average of ``v``, ``w``
    and the projected centre of ``f`` (``rule="average"``, dggs's).  The
    thesis's rule (``rule="thesis"``, recovered from its Tables 6.1-6.7) is
    the projection of ``c_f + ((3 - sqrt 3) / 2)(m_vw - c_f)`` with ``c_f``
    the face's vertex average and ``m_vw`` the edge's chord midpoint, and no
    rescale at all: Tables 6.1 and 6.3-6.7 follow cell for cell (the
    deviation tends to ``4 pi / A_dodecahedron - 1 = 19.51 %``).

Examples
--------
>>> from dggs.experiments.mesh import icosahedron, dodecahedron
>>> catmull_clark(icosahedron()).faces[0].shape
(60, 4)
>>> [b.shape for b in split_1_5(dodecahedron()).faces]
[(12, 5), (20, 6)]
"""

from __future__ import annotations

import math
from typing import Literal

import numpy as np

from dggs.experiments.mesh import Mesh, edge_table, half_edges, normalize

__all__ = ["catmull_clark", "split_1_5", "THESIS_1_5_FACTOR"]

#: Split (1:5)'s thesis rule: the new vertex is ``c_f + k (m_vw - c_f)``, ``k = (3 - sqrt 3) / 2``.
THESIS_1_5_FACTOR = (3.0 - math.sqrt(3.0)) / 2.0


def _radius(vertices: np.ndarray) -> float:
    return float(np.linalg.norm(vertices, axis=1).mean())


def catmull_clark(mesh: Mesh, rule: Literal["projected", "standard"] = "projected") -> Mesh:
    """One Catmull-Clark step (connectivity of §6.1.3).

    Parameters
    ----------
    mesh : Mesh
        Any closed polygon mesh inscribed in a sphere.
    rule : {"projected", "standard"}
        ``"projected"``: midpoints and face centres pushed onto the sphere,
        old vertices kept (dggs's); ``"standard"``: Catmull and Clark's point
        rules, nothing projected (the thesis's; module docstring).

    Returns
    -------
    Mesh
        One ``(sum k, 4)`` block of quads.

    Examples
    --------
    >>> from dggs.experiments.mesh import icosahedron
    >>> m = catmull_clark(catmull_clark(icosahedron()))
    >>> m.num_faces, m.num_vertices
    (240, 242)
    """
    v = mesh.vertices
    r = _radius(v)
    edges, corner_edge = edge_table(mesh.faces)
    n_faces = mesh.num_faces
    if rule == "standard":
        v, face_pts, edge_pts = _catmull_clark_points(mesh, edges, corner_edge)
    elif rule == "projected":
        face_pts = normalize(np.concatenate([v[b].mean(axis=1) for b in mesh.faces]), r)
        edge_pts = normalize(0.5 * (v[edges[:, 0]] + v[edges[:, 1]]), r)
    else:
        raise ValueError(f"rule {rule!r} is not one of 'projected', 'standard'")
    f0 = len(v)
    e0 = f0 + n_faces
    quads, start = [], 0
    for block, ce in zip(mesh.faces, corner_edge, strict=True):  # one iteration per face *size*
        fi = f0 + start + np.arange(len(block))
        nxt = e0 + ce  # edge leaving corner i
        prv = e0 + np.roll(ce, 1, axis=1)  # edge arriving at corner i
        q = np.stack([block, nxt, np.broadcast_to(fi[:, None], block.shape), prv], axis=-1)
        quads.append(q.reshape(-1, 4))
        start += len(block)
    return Mesh(np.concatenate([v, face_pts, edge_pts]), (np.concatenate(quads),))


def _catmull_clark_points(mesh: Mesh, edges: np.ndarray, corner_edge: tuple[np.ndarray, ...]):
    """Catmull and Clark's moved old vertices, face points and edge points (closed mesh)."""
    v = mesh.vertices
    face_pts = np.concatenate([v[b].mean(axis=1) for b in mesh.faces])
    edge_faces = np.zeros((len(edges), 3))  # sum of the two adjacent face points
    q_sum = np.zeros_like(v)  # sum of the face points around each vertex
    q_n = np.zeros(len(v))
    start = 0
    for block, ce in zip(mesh.faces, corner_edge, strict=True):
        fp = face_pts[start : start + len(block)]
        for k in range(block.shape[1]):
            np.add.at(edge_faces, ce[:, k], fp)
            np.add.at(q_sum, block[:, k], fp)
            np.add.at(q_n, block[:, k], 1.0)
        start += len(block)
    mid = 0.5 * (v[edges[:, 0]] + v[edges[:, 1]])
    edge_pts = 0.5 * mid + 0.25 * edge_faces  # (v1 + v2 + f1 + f2) / 4
    r_sum = np.zeros_like(v)  # sum of the midpoints of the edges at each vertex
    np.add.at(r_sum, edges[:, 0], mid)
    np.add.at(r_sum, edges[:, 1], mid)
    n = np.bincount(edges.ravel(), minlength=len(v)).astype(np.float64)[:, None]
    moved = (q_sum / q_n[:, None] + 2.0 * r_sum / n + (n - 3.0) * v) / n  # (Q + 2R + (n - 3) S) / n
    return moved, face_pts, edge_pts


def split_1_5(mesh: Mesh, rule: Literal["average", "thesis"] = "average") -> Mesh:
    """One Split (1:5) step: faces shrink in place, vertices become 2d-gons (§6.1.6).

    Parameters
    ----------
    mesh : Mesh
        A closed, consistently oriented polygon mesh inscribed in a sphere
        (the dodecahedron and its refinements are trivalent).
    rule : {"average", "thesis"}
        Where the new vertices go (module docstring).

    Returns
    -------
    Mesh
        One new vertex per half-edge; old face blocks keep their sizes and
        the vertex faces form new blocks by valence.

    Examples
    --------
    >>> from dggs.experiments.mesh import dodecahedron
    >>> m = split_1_5(split_1_5(dodecahedron()))
    >>> m.num_faces, m.num_vertices
    (92, 180)
    """
    v = mesh.vertices
    r = _radius(v)
    he = half_edges(mesh.faces)
    centres = np.concatenate([v[b].mean(axis=1) for b in mesh.faces])
    # One new vertex per half-edge h = (origin -> target) inside face[h].
    if rule == "average":
        new_v = normalize((v[he["origin"]] + v[he["target"]] + normalize(centres, r)[he["face"]]) / 3.0, r)
    elif rule == "thesis":
        c_f = centres[he["face"]]
        m_vw = 0.5 * (v[he["origin"]] + v[he["target"]])
        new_v = normalize(c_f + THESIS_1_5_FACTOR * (m_vw - c_f), r)
    else:
        raise ValueError(f"rule {rule!r} is not one of 'average', 'thesis'")
    blocks: list[np.ndarray] = []
    start = 0
    for block in mesh.faces:  # the shrunken copy of every old face
        f, k = block.shape
        blocks.append(start + np.arange(f * k).reshape(f, k))
        start += f * k
    # Around each vertex: h_out, twin(h_out), next(twin(h_out)), ...
    nh = len(he["origin"])
    first_out = np.full(len(v), -1)
    first_out[he["origin"][::-1]] = np.arange(nh)[::-1]
    valence = np.bincount(he["origin"], minlength=len(v))
    for d in np.unique(valence):
        verts = np.flatnonzero(valence == d)
        h = first_out[verts]
        ring = []
        for _ in range(d):  # d is a valence (3 here), not a face count
            t = he["twin"][h]
            ring += [h, t]  # clockwise round the vertex seen from outside ...
            h = he["next"][t]
        blocks.append(np.stack(ring, axis=1)[:, ::-1])  # ... so reverse: CCW
    return Mesh(new_v, tuple(blocks))
