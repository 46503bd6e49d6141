"""Chapter 4 figures: the inverse Snyder projection and its Newton iteration (Figures 4.1, 4.3, 4.4, 4.5).

* **Figure 4.1** (§4.1.2): the planar azimuth ``Az'`` against the spherical
  azimuth ``Az`` after Snyder's Newton-Raphson (thesis eqs. 3.8-3.9), with
  the cubic least-squares fit, ``y = exp(5 (f(x) - x))`` and the residuals
  scaled for visibility, as the thesis's gnuplot figure.  Over the full
  120-degree vertex-to-vertex sector (see :mod:`dggs.experiments.chapter4`:
  that is the range the thesis's Table 4.1 was fitted over); the curve is
  symmetric about 60 degrees, the "60-degree range" of the text.
* **Figure 4.3** (§4.2): Newton iterations per point of the quality-q
  triangulated face (q = 10, 30, 60, 100), the thesis's colours (blue 4,
  green 3, red 2, black < 2; ours adds purple for 5).
* **Figure 4.4 / Table 4.3 as a figure**: distance of each inverse method
  (Newton, Newton from the cubic, the cubic and degree-7 polynomials alone)
  from the exact closed form over a face, in metres on a 6,371 km Earth.
* **Figure 4.5** (§4.4): a picture mapped to the sphere by the inverse
  Snyder projection.  NASA's Blue Marble is not available offline; the
  picture is a synthetic one: each icosahedron face gets its own colour, a
  checkerboard of 64 equal-area triangles, and three discs of the *same*
  planar area (the stand-in for the thesis's Greenland, "the same area on
  the icosahedron as on the sphere"), mapped by Newton's inverse.
  :func:`disc_areas` measures the discs on the sphere.

Examples
--------
>>> counts = iteration_counts(10)
>>> int(counts.min()) >= 1, round(float(counts.mean()), 2)
(True, 3.18)
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from dggs.experiments import inverse as thesis_inverse
from dggs.experiments import numpy_snyder
from dggs.experiments.chapter4_constants import EARTH_RADIUS_M
from dggs.experiments.chapter4_fits import exact_az, fit_sector
from dggs.experiments.chapter4_mesh import face_mesh, spherical_triangle_areas
from dggs.geometry.icosahedron import ISEA, NUM_FACES
from dggs.geometry.split26 import FACE_VERTICES

__all__ = [
    "azimuth_curve",
    "iteration_counts",
    "inverse_errors_m",
    "picture_colours",
    "disc_areas",
    "write_chapter4",
]

_SECTOR = 2.0 * math.pi / 3.0
#: Thesis Figure 4.3's colours by iteration count (0-1 black, 2 red, 3 green, 4 blue; 5+ ours, purple).
ITER_COLOURS = ["black", "black", "red", "green", "blue", "purple"]


def azimuth_curve(n: int = 2001, tol: float = 1e-13) -> dict[str, np.ndarray]:
    """Figure 4.1's data: ``Az'`` over 0-120 degrees, Newton's ``Az``, the cubic fit and its residual (radians).

    Examples
    --------
    >>> d = azimuth_curve(101)
    >>> float(np.abs(d["az"] - d["exact"]).max()) < 1e-12
    True
    """
    ap = np.linspace(0.0, _SECTOR, n)
    area = numpy_snyder.area_from_planar(np.sin(ap), np.cos(ap))
    az, its = thesis_inverse.newton(area, ap.copy(), tol, 50)
    fit = fit_sector(3)(ap)
    return {"ap": ap, "az": az, "iterations": its, "exact": exact_az(ap), "fit": fit, "residual": az - fit}


def iteration_counts(quality: int, tol: float = 1e-13) -> np.ndarray:
    """Newton iterations of every vertex of the quality-q face (Figure 4.3, Table 4.2's "O")."""
    p, _ = face_mesh(quality)
    _, its = thesis_inverse.inverse_xyz(np.zeros(len(p), dtype=np.int64), p[:, 0], p[:, 1], ISEA, "newton", tol=tol)
    return its


def inverse_errors_m(quality: int = 100) -> tuple[np.ndarray, dict[str, np.ndarray]]:
    """Distance (m, Earth) of each thesis method from the closed form at the quality-q face's vertices.

    Examples
    --------
    >>> _, err = inverse_errors_m(20)
    >>> float(err["newton"].max()) < 1e-3, 100 < float(err["poly 3"].max()) < 5000
    (True, True)
    """
    p, _ = face_mesh(quality)
    face = np.zeros(len(p), dtype=np.int64)
    exact = numpy_snyder.inverse_xyz(face, p[:, 0], p[:, 1])
    out = {}
    for label, method, degree in (
        ("newton", "newton", 3),
        ("newton-poly 3", "newton-poly", 3),
        ("poly 3", "poly", 3),
        ("poly 7", "poly", 7),
    ):
        xyz, _ = thesis_inverse.inverse_xyz(face, p[:, 0], p[:, 1], ISEA, method, degree=degree)
        chord = np.linalg.norm(xyz - exact, axis=1)
        out[label] = 2.0 * np.arcsin(np.minimum(chord / 2.0, 1.0)) * EARTH_RADIUS_M
    return p, out


# --- Figure 4.5: the synthetic picture -------------------------------------------------------------

_DISC_R = 0.09  # planar disc radius (unit-sphere face units; the face's circumradius is 0.6)


def _disc_centres() -> np.ndarray:
    """Face centre, towards vertex 0, and towards the edge midpoint opposite vertex 0."""
    v0, mid = FACE_VERTICES[0], 0.5 * (FACE_VERTICES[1] + FACE_VERTICES[2])
    return np.array([[0.0, 0.0], 0.62 * v0, 0.62 * mid])


def picture_colours(face: np.ndarray, x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """RGB of the synthetic picture at face-plane points (face hue, equal-area checkerboard, discs)."""
    from matplotlib import colormaps

    base = np.asarray(colormaps["tab20"](np.asarray(face) % 20))[:, :3]
    # Barycentric coordinates in the planar face; 8 x 8 equal-area triangles.
    m = np.column_stack([FACE_VERTICES[1] - FACE_VERTICES[0], FACE_VERTICES[2] - FACE_VERTICES[0]])
    b = np.linalg.solve(m, np.stack([x, y]) - FACE_VERTICES[0][:, None])
    i, j = np.floor(8 * b[0]), np.floor(8 * b[1])
    up = (8 * b[0] - i) + (8 * b[1] - j) < 1.0  # a triangular grid is 2-coloured by orientation
    shade = np.where(up, 1.0, 0.72)[:, None]
    rgb = base * shade + (1 - shade) * 0.15
    pts = np.stack([x, y], axis=1)
    for c in _disc_centres():
        rgb[np.linalg.norm(pts - c, axis=1) < _DISC_R] = (0.1, 0.1, 0.1)
    return rgb


def disc_areas(samples: int = 720) -> tuple[float, np.ndarray]:
    """Planar area of the picture's discs and their areas on the unit sphere after Newton's inverse.

    Snyder's projection is equal-area, so all three equal the planar area
    (up to the boundary sampling), wherever they sit on the face.

    Examples
    --------
    >>> planar, sphere = disc_areas()
    >>> bool(np.all(np.abs(sphere / planar - 1) < 1e-4))
    True
    """
    t = 2 * math.pi * np.arange(samples) / samples
    out = []
    for c in _disc_centres():
        ring = c + _DISC_R * np.stack([np.cos(t), np.sin(t)], axis=1)
        pts = np.vstack([c, ring])
        xyz, _ = thesis_inverse.inverse_xyz(np.zeros(len(pts), dtype=np.int64), pts[:, 0], pts[:, 1], ISEA, "newton")
        fan = np.stack([np.zeros(samples, dtype=np.int64), 1 + np.arange(samples), 1 + (np.arange(samples) + 1) % samples], 1)
        out.append(spherical_triangle_areas(xyz, fan).sum())
    # The inscribed polygon, not the disc, is what is mapped: compare like with like.
    planar = 0.5 * samples * _DISC_R**2 * math.sin(2 * math.pi / samples)
    return planar, np.array(out)


def _ortho(xyz: np.ndarray, view: tuple[float, float]) -> tuple[np.ndarray, np.ndarray]:
    lat, lng = np.radians(view)
    centre = np.array([np.cos(lat) * np.cos(lng), np.cos(lat) * np.sin(lng), np.sin(lat)])
    east = np.array([-np.sin(lng), np.cos(lng), 0.0])
    north = np.cross(centre, east)
    return np.stack([xyz @ east, xyz @ north], axis=-1), xyz @ centre


def _draw_picture_globe(ax, quality: int, view: tuple[float, float]) -> None:
    from matplotlib.collections import PolyCollection
    from matplotlib.patches import Circle

    p, tri = face_mesh(quality)
    cen = p[tri].mean(axis=1)
    polys, colours = [], []
    for f in range(NUM_FACES):
        xyz, _ = thesis_inverse.inverse_xyz(np.full(len(p), f, dtype=np.int64), p[:, 0], p[:, 1], ISEA, "newton")
        xy, depth = _ortho(xyz, view)
        front = depth[tri].min(axis=1) > 0.0
        polys.append(xy[tri[front]])
        colours.append(picture_colours(np.full(int(front.sum()), f), cen[front, 0], cen[front, 1]))
    coll = PolyCollection(list(np.concatenate(polys)), facecolors=np.concatenate(colours), edgecolors="face", lw=0.1)
    ax.add_collection(coll)
    ax.add_patch(Circle((0, 0), 1.0, fill=False, lw=0.6))
    ax.set_xlim(-1.05, 1.05)
    ax.set_ylim(-1.05, 1.05)
    ax.set_aspect("equal")
    ax.axis("off")


def write_chapter4(outdir: str | Path, quick: bool = False) -> list[Path]:
    """Write Figures 4.1, 4.3, 4.4 (inverse error) and 4.5 as PNGs; returns the paths."""
    from dggs.experiments.figures import _plt

    plt = _plt()
    from matplotlib.colors import ListedColormap

    out = Path(outdir)
    out.mkdir(parents=True, exist_ok=True)
    written = []

    # Figure 4.1
    d = azimuth_curve(401 if quick else 2001)
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    ax.plot(d["ap"], d["az"], ".", ms=2, color="tab:red", label="Az after Newton-Raphson")
    ax.plot(d["ap"], d["fit"], lw=1, color="tab:green", label="cubic fit f(x) (Table 4.1)")
    ax.plot(d["ap"], d["ap"], ":", lw=0.8, color="0.5", label="y = x")
    ax.plot(d["ap"], np.exp(5 * (d["fit"] - d["ap"])), lw=1, color="tab:blue", label="exp(5 (f(x) - x))")
    ax.plot(d["ap"], 1000 * d["residual"], lw=1, color="tab:purple", label="residual x 1000")
    ax.axvline(math.pi / 3, color="0.7", lw=0.6)
    ax.set_xlabel("initial (planar) azimuth Az' (rad)")
    ax.set_ylabel("azimuth after iteration Az (rad)")
    ax.set_title("Figure 4.1: azimuth before against after Newton-Raphson, cubic fit", fontsize=9)
    ax.legend(fontsize=7)
    ax.grid(alpha=0.3)
    written.append(_save(plt, fig, out / "fig4_1_azimuth.png"))

    # Figure 4.3
    qualities = (10, 30, 60) if quick else (10, 30, 60, 100)
    fig, axes = plt.subplots(1, len(qualities), figsize=(3.0 * len(qualities), 3.1))
    cmap = ListedColormap(ITER_COLOURS)
    for ax, q in zip(axes, qualities, strict=True):
        p, tri = face_mesh(q)
        its = np.minimum(iteration_counts(q), 5)
        if q <= 30:
            ax.triplot(p[:, 0], p[:, 1], tri, lw=0.2, color="0.75")
        ax.scatter(p[:, 0], p[:, 1], c=its, cmap=cmap, vmin=-0.5, vmax=5.5, s=max(40.0 / q, 0.4), lw=0)
        share = {k: 100 * float(np.mean(its == k)) for k in (3, 4, 5)}
        ax.set_title(f"quality {q}: mean {its.mean():.2f}\n3: {share[3]:.0f} %  4: {share[4]:.0f} %  "
                     f"5: {share[5]:.1f} %", fontsize=7)
        ax.set_aspect("equal")
        ax.axis("off")
    fig.suptitle("Figure 4.3: Newton iterations per point (blue 4, green 3, red 2, black < 2, purple 5)",
                 fontsize=8)
    written.append(_save(plt, fig, out / "fig4_3_iterations.png"))

    # Figure 4.4 / Table 4.3: inverse error over a face
    p, err = inverse_errors_m(40 if quick else 100)
    fig, axes = plt.subplots(1, 3, figsize=(13.0, 3.8), constrained_layout=True)
    for ax, label in zip(axes[:2], ("poly 3", "poly 7"), strict=True):
        sc = ax.scatter(p[:, 0], p[:, 1], c=err[label], s=2 if not quick else 6, lw=0, cmap="viridis")
        fig.colorbar(sc, ax=ax, fraction=0.046, label="m")
        ax.set_title(f"{label} alone ('E'): mean {err[label].mean():.1f} m, max {err[label].max():.0f} m",
                     fontsize=8)
        ax.set_aspect("equal")
        ax.axis("off")
    edges = np.logspace(-12, 4, 65)
    for label, e in err.items():
        axes[2].hist(np.maximum(e, 1.1e-12), bins=edges, histtype="step", label=label)
    axes[2].set_xscale("log")
    axes[2].set_xlabel("distance from the closed form (m, 6,371 km Earth)")
    axes[2].set_ylabel("points")
    axes[2].legend(fontsize=7)
    fig.suptitle("Inverse error of the thesis's methods against the exact inverse (Table 4.3 / Figure 4.4)",
                 fontsize=9)
    written.append(_save(plt, fig, out / "fig4_4_inverse_error.png"))

    # Figure 4.5
    fig, axes = plt.subplots(1, 3, figsize=(10.0, 3.6))
    pf, trif = face_mesh(96)
    cen = pf[trif].mean(axis=1)
    from matplotlib.collections import PolyCollection

    axes[0].add_collection(PolyCollection(list(pf[trif]), facecolors=picture_colours(
        np.zeros(len(cen), dtype=np.int64), cen[:, 0], cen[:, 1]), edgecolors="face", lw=0.1))
    axes[0].set_xlim(-0.65, 0.65)
    axes[0].set_ylim(-0.4, 0.75)
    axes[0].set_aspect("equal")
    axes[0].axis("off")
    planar, sphere = disc_areas(360 if quick else 720)
    axes[0].set_title(f"picture on face 0 (plane)\n3 discs, planar area {planar:.5f}", fontsize=8)
    for ax, view in zip(axes[1:], ((25.0, 10.0), (-25.0, 190.0)), strict=True):
        _draw_picture_globe(ax, 16 if quick else 48, view)
    axes[1].set_title("inverse Snyder (Newton) onto the sphere\n"
                      f"disc areas on the sphere {', '.join(f'{a:.5f}' for a in sphere)}", fontsize=8)
    axes[2].set_title("the other side", fontsize=8)
    fig.suptitle("Figure 4.5 stand-in: a synthetic picture (no Blue Marble offline) through the inverse "
                 "Snyder projection", fontsize=9)
    written.append(_save(plt, fig, out / "fig4_5_inverse_picture.png"))
    return written


def _save(plt, fig, path: Path) -> Path:
    fig.savefig(path, dpi=130, bbox_inches="tight")
    plt.close(fig)
    return path
