"""Chapter 5 surface figures: Figures 5.5-5.10 (§5.1.2) and 5.22 (§5.1.11), computed.

* 5.5: the icosahedron circumscribed by its sphere S (radius R, origin O).
* 5.6: a face ABC on S with M, the foot of the height from A, and the angles
  of the area formula.  The thesis writes the chords as ``2 R tan(angle / 2)``;
  a chord of central angle ``a`` is ``2 R sin(a / 2)`` (a typo, like those
  the thesis's G = 46 degrees for 36 noted in dggs/geometry/constants.py): :func:`thesis_triangle_area`
  uses ``sin`` and matches the
  cross-product area; with ``tan`` it would not.
* 5.7: the flattened Loop (1:4) split.
* 5.8-5.10: the steps of global surface preservation: the initial
  icosahedron (area SA), refined (midpoints, flat), new vertices pushed onto S
  (area SA' > SA), all scaled to ``R' = sqrt(SA R^2 / SA')`` (area SA again).
* 5.22: the averaged-sphere subdivision of :mod:`dggs.experiments.averaged_sphere`,
  levels 0-3, with the averaged vertex spheres and their origins.

Examples
--------
>>> a, b, c = np.eye(3)
>>> round(thesis_triangle_area(a, b, c), 12) == round(0.5 * float(np.linalg.norm(np.cross(b - a, c - a))), 12)
True
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from dggs.experiments.averaged_sphere import reflex_faces, run_levels
from dggs.experiments.mesh import icosahedron, total_area
from dggs.experiments.preservation import rescale_to_area
from dggs.experiments.split_triangles import split_1_4

__all__ = ["thesis_triangle_area", "surface_steps", "write_chapter5_surfaces"]


def _angle(u: np.ndarray, v: np.ndarray) -> float:
    return float(np.arctan2(np.linalg.norm(np.cross(u, v)), np.dot(u, v)))


def thesis_triangle_area(a: np.ndarray, b: np.ndarray, c: np.ndarray, origin=(0.0, 0.0, 0.0)) -> float:
    """Area of a face ABC inscribed in a sphere about ``origin`` by the thesis's §5.1.2 formula.

    ``A = 2 R^2 sin(Theta / 2) sin(gamma / 2) sin(beta)`` with ``Theta = angle BOC``,
    ``gamma = angle AOC``, ``beta = angle ACB`` (the thesis prints ``tan`` for
    the two chord factors: a typo).
    """
    o = np.asarray(origin, dtype=np.float64)
    r = float(np.linalg.norm(a - o))
    theta, gamma, beta = _angle(b - o, c - o), _angle(a - o, c - o), _angle(a - c, b - c)
    return float(2.0 * r * r * np.sin(theta / 2) * np.sin(gamma / 2) * np.sin(beta))


def surface_steps() -> list[tuple[str, object, float, float]]:
    """Figures 5.8-5.10: (label, mesh, radius, total area) of each step of §5.1.2 on the icosahedron.

    Examples
    --------
    >>> [round(s[3], 4) for s in surface_steps()]
    [9.5745, 9.5745, 11.6659, 9.5745]
    """
    ico = icosahedron()
    sa = total_area(ico)
    fine = split_1_4(ico)
    n_old = ico.num_vertices
    # The flat refinement: new vertices at the chord midpoints, before projecting.  split_1_4 puts them
    # at the projected midpoints; every icosahedron edge has the same chord e, so the midpoint is
    # sqrt(1 - (e / 2)^2) from O along the same direction.
    a, b = ico.vertices[ico.faces[0][0, :2]]
    flat_v = fine.vertices.copy()
    flat_v[n_old:] *= np.sqrt(1.0 - (np.linalg.norm(a - b) / 2.0) ** 2)
    flat = fine.with_vertices(flat_v)
    scaled = rescale_to_area(fine, sa)
    r = lambda m: float(np.linalg.norm(m.vertices, axis=1).max())  # noqa: E731
    return [("initial", ico, 1.0, sa), ("refined (flat)", flat, 1.0, total_area(flat)),
            ("pushed onto S", fine, 1.0, total_area(fine)), ("scaled", scaled, r(scaled), total_area(scaled))]


def _sphere(ax, c, r, color="0.7", n=13, lw=0.3, alpha=0.5):
    u, v = np.linspace(0, 2 * np.pi, 2 * n), np.linspace(0, np.pi, n)
    x = c[0] + r * np.outer(np.cos(u), np.sin(v))
    y = c[1] + r * np.outer(np.sin(u), np.sin(v))
    z = c[2] + r * np.outer(np.ones_like(u), np.cos(v))
    ax.plot_wireframe(x, y, z, color=color, lw=lw, alpha=alpha)


def _mesh(ax, v, f, face="#9ecae1", edge="0.3", alpha=0.9, lw=0.3, mark_reflex=False):
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    if mark_reflex:  # faces on a concave (reflex) edge: the extrusions
        face = np.where(reflex_faces(v, f)[1][:, None], np.array([[0.85, 0.3, 0.25, 1.0]]),
                        np.array([[0.62, 0.79, 0.88, 1.0]]))
    ax.add_collection3d(Poly3DCollection(v[f], facecolor=face, edgecolor=edge, lw=lw, alpha=alpha))


def _box(ax, lo, hi, title):
    c, h = 0.5 * (lo + hi), 0.5 * float(np.max(hi - lo))
    for s, m in zip("xyz", c, strict=True):
        getattr(ax, f"set_{s}lim")(m - h, m + h)
    ax.set_box_aspect((1, 1, 1))
    ax.set_axis_off()
    ax.set_title(title, fontsize=7)


def _fig_5_5_5_7(plt):
    fig = plt.figure(figsize=(10.5, 3.6))
    ico = icosahedron()
    ax = fig.add_subplot(1, 3, 1, projection="3d")
    _sphere(ax, (0, 0, 0), 1.0)
    _mesh(ax, ico.vertices, ico.faces[0], alpha=0.6)
    _box(ax, -np.ones(3), np.ones(3), "Figure 5.5: icosahedron in sphere S (R = 1, O)")
    ax = fig.add_subplot(1, 3, 2, projection="3d")
    a, b, c = ico.vertices[ico.faces[0][0]]
    m = b + np.dot(a - b, c - b) / np.dot(c - b, c - b) * (c - b)  # foot of the height from A on BC
    _sphere(ax, (0, 0, 0), 1.0, n=9, alpha=0.25)
    _mesh(ax, np.array([a, b, c]), np.array([[0, 1, 2]]), alpha=0.7)
    for p, name in ((a, "A"), (b, "B"), (c, "C"), (m, "M"), (np.zeros(3), "O")):
        ax.text(*(p * 1.08), name, fontsize=8)
    ax.plot(*np.array([a, m]).T, "r--", lw=0.8)
    for p in (a, b, c):
        ax.plot(*np.array([np.zeros(3), p]).T, color="tab:blue", lw=0.5)
    n = (a + b + c) / np.linalg.norm(a + b + c)  # look at the face from outside, a little obliquely
    ax.view_init(elev=float(np.degrees(np.arcsin(n[2]))) + 15.0, azim=float(np.degrees(np.arctan2(n[1], n[0]))) + 20.0)
    cross = 0.5 * float(np.linalg.norm(np.cross(b - a, c - a)))
    _box(ax, -np.ones(3), np.ones(3), f"Figure 5.6: 2R² sin(Θ/2) sin(γ/2) sin β = {thesis_triangle_area(a, b, c):.6f}\n"
         f"cross-product area {cross:.6f}")
    ax = fig.add_subplot(1, 3, 3)
    t = np.array([[0.0, 0.0], [1.0, 0.0], [0.5, np.sqrt(3) / 2]])
    mids = 0.5 * (t + np.roll(t, -1, axis=0))
    for tri in (t, mids, np.array([t[0], mids[0], mids[2]]), np.array([t[1], mids[1], mids[0]])):
        ax.fill(*tri.T, fill=False, lw=1.0)
    ax.plot(*mids.T, "o", color="tab:red", ms=4)
    ax.set_aspect("equal")
    ax.axis("off")
    ax.set_title("Figure 5.7: flattened Loop subdivision (1:4)", fontsize=7)
    return fig


def _fig_5_8_5_10(plt):
    steps = surface_steps()
    fig = plt.figure(figsize=(13.0, 3.6))
    titles = ["Figure 5.8: initial setup", "Figure 5.9: refine surface", "Figure 5.10: reposition on sphere",
              "Figure 5.10: scale to R' = sqrt(SA R² / SA')"]
    for k, ((label, mesh, r, sa), title) in enumerate(zip(steps, titles, strict=True)):
        ax = fig.add_subplot(1, 4, k + 1, projection="3d")
        _sphere(ax, (0, 0, 0), 1.0, n=11, alpha=0.25)
        if k == 3:
            _sphere(ax, (0, 0, 0), r, color="tab:red", n=11, alpha=0.35)
        _mesh(ax, mesh.vertices, mesh.faces[0], alpha=0.7)
        _box(ax, -np.ones(3), np.ones(3), f"{title}\n{label}: R = {r:.4f}, area {sa:.4f}")
    return fig


def _fig_5_22(plt, levels: int = 3):
    meshes, stats = run_levels(levels)
    v0 = meshes[0][0]
    lo0, hi0 = v0.min(axis=0), v0.max(axis=0)
    fig = plt.figure(figsize=(12.0, 3.2 * (levels + 1) / 2 + 0.6))
    rows, cols = (levels + 2) // 2 + ((levels + 2) % 2 > 0), 4
    letters = iter("abcdefghijkl")
    k = 0
    for level, ((v, f, c, r), st) in enumerate(zip(meshes, stats, strict=True)):
        for with_spheres in (False, True):
            k += 1
            ax = fig.add_subplot(rows, cols, k, projection="3d")
            _mesh(ax, v, f, alpha=1.0 if not with_spheres else 0.5, lw=0.2, mark_reflex=not with_spheres)
            if with_spheres:
                ok = np.isfinite(r)
                ax.scatter(*c[ok].T, color="#2ca02c", s=4)
                for i in np.argsort(r[ok])[-6:]:  # the largest six, the rest as origins only
                    _sphere(ax, c[ok][i], r[ok][i], color="#e377c2", n=9, alpha=0.35)
                pts = np.vstack([v, c[ok]])
                lo, hi = pts.min(axis=0), pts.max(axis=0)
                title = (f"({next(letters)}) level {level} with averaged vertex spheres\n"
                         f"max R {st.max_radius:.2f}, origins up to {st.max_origin_offset:.2f} away")
            else:
                lo, hi = lo0, hi0
                title = (f"({next(letters)}) level {level}: {st.faces} faces, {st.reflex_edges} reflex edges (red)\n"
                         f"max bulge of new points {st.max_bulge:.2f} x edge")
            _box(ax, lo, hi, title)
    ax = fig.add_subplot(rows, cols, k + 1, projection="3d")
    v, f, _, r = meshes[-1]
    _mesh(ax, v, f, lw=0.2, mark_reflex=True)
    centre = v[int(np.argmax(np.where(np.isfinite(r), r, -1.0)))]  # the vertex with the largest sphere
    half = 0.2 * (hi0 - lo0)
    _box(ax, centre - half, centre + half, f"({next(letters)}) level {levels} close up at the largest sphere's vertex")
    fig.suptitle("Figure 5.22: averaged-sphere surface subdivision (§5.1.11) on an irregular octahedron; "
                 "sizes in units of the initial half-diagonal", fontsize=9)
    return fig


def write_chapter5_surfaces(outdir: str | Path, quick: bool = False) -> list[Path]:
    """Write Figures 5.5-5.7, 5.8-5.10 and 5.22 as PNGs; returns the paths."""
    from dggs.experiments.figures import save_figures

    return save_figures(outdir, {
        "fig5_5_5_7_surface_definition": _fig_5_5_5_7,
        "fig5_8_5_10_surface_steps": _fig_5_8_5_10,
        "fig5_22_averaged_sphere": lambda plt: _fig_5_22(plt, 2 if quick else 3),
    }, quick)
