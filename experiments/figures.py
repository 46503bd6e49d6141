"""PNG analogues of the thesis's figures; Figures 6.14-6.28 (area highlighting, error histograms) here.

Area highlighting (Figures 6.14, 6.16, 6.19, 6.21, 6.23, 6.25, 6.27): faces
on an orthographic globe, white at 0 % error, blue where a face is too big
and purple where it is too small, the scale running to the level's maximum
error as in the thesis (§6.3.3).  Error distributions (Figures 6.15, 6.17,
6.20, 6.22, 6.24, 6.26, 6.28): one histogram of signed face errors per level.

The error distributions run to the thesis's depth (levels 1-7 for Split (2:6),
Figure 6.28, and Split (1:3), Split (1:5)); the globes to level 5 as the
thesis's (a)-(e) panels, drawn without edges (and rasterized) once a level has
more than 20,000 faces.  :func:`write_all` adds the other chapters:
:mod:`~dggs.experiments.figures_ch4`, :mod:`~dggs.experiments.figures_ch5`,
:mod:`~dggs.experiments.figures_ch5_surfaces` and
:mod:`~dggs.experiments.figures_ch6` (Figure 6.18).

matplotlib is an optional extra (``pip install dggs[plot]``) and is imported
only here and in those modules, lazily.

Examples
--------
>>> import tempfile
>>> paths = write_figures(tempfile.mkdtemp(), ["1:4"], 1)  # doctest: +SKIP
"""

from __future__ import annotations

from collections.abc import Iterable
from pathlib import Path
from typing import Any

import numpy as np

from dggs.errors import DggsError
from dggs.experiments.figures_ch6 import rule_label
from dggs.experiments.mesh import Mesh
from dggs.experiments.schemes import SCHEMES, THESIS_SCHEMES, get_scheme, iter_levels

__all__ = [
    "MissingPlotDependency",
    "CHAPTERS",
    "write_all",
    "write_figures",
    "plot_area_highlighting",
    "plot_error_distribution",
]

#: Chapters with figures (``dggs experiments figures --chapter``).
CHAPTERS = ("3", "4", "5", "6")

#: Above this many faces a globe is drawn without edges and rasterized (levels 6-7).
_BIG = 20_000

#: Thesis figure numbers per scheme: (area highlighting, error distribution).
FIGURE_NUMBERS = {
    "1:4": ("6.14", "6.15"),
    "1:9": ("6.16", "6.17"),
    "catmull-clark": ("6.19", "6.20"),
    "1:3": ("6.21", "6.22"),
    "1:6": ("6.23", "6.24"),
    "1:5": ("6.25", "6.26"),
    "2:6": ("6.27", "6.28"),
}


class MissingPlotDependency(DggsError):
    """matplotlib is not installed."""


def _plt() -> Any:
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError as exc:
        raise MissingPlotDependency(
            "figures need matplotlib: pip install 'dggs[plot]' (or pip install matplotlib)"
        ) from exc
    return plt


def save_figures(outdir: str | Path, makers: dict[str, Any], quick: bool = False) -> list[Path]:
    """Draw ``makers[name](plt)`` for each name and save it as ``outdir/name.png``; returns the paths."""
    plt = _plt()
    out = Path(outdir)
    out.mkdir(parents=True, exist_ok=True)
    written = []
    for name, make in makers.items():
        fig = make(plt)
        path = out / f"{name}.png"
        fig.savefig(path, dpi=110 if quick else 130, bbox_inches="tight")
        plt.close(fig)
        written.append(path)
    return written


def _cmap() -> Any:
    from matplotlib.colors import LinearSegmentedColormap

    return LinearSegmentedColormap.from_list("thesis", ["#6a1b9a", "#ffffff", "#1f4fbf"])


def plot_area_highlighting(ax: Any, mesh: Mesh, errors_pct: np.ndarray, view=(20.0, 30.0)) -> Any:
    """Draw faces on an orthographic globe coloured by signed error.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        Target axes.
    mesh : Mesh
        Mesh of the level.
    errors_pct : numpy.ndarray
        Signed per-face errors, blocks concatenated as in ``mesh.faces``.
    view : tuple of float
        (latitude, longitude) of the view centre, degrees.

    Returns
    -------
    matplotlib.collections.PolyCollection
        The face collection (for a colour bar).
    """
    from matplotlib.collections import PolyCollection
    from matplotlib.patches import Circle

    lat, lng = np.radians(view)
    centre = np.array([np.cos(lat) * np.cos(lng), np.cos(lat) * np.sin(lng), np.sin(lat)])
    east = np.array([-np.sin(lng), np.cos(lng), 0.0])
    north = np.cross(centre, east)
    verts, depth, start = [], [], 0
    for block in mesh.faces:
        p = mesh.vertices[block]
        p = p / np.linalg.norm(p, axis=2, keepdims=True)
        verts += list(np.stack([p @ east, p @ north], axis=-1))
        depth.append(p.mean(axis=1) @ centre)
        start += len(block)
    depth_a = np.concatenate(depth)
    front = np.flatnonzero(depth_a > 0.05)
    vmax = max(float(np.abs(errors_pct).max()), 1e-9)
    big = len(front) > _BIG
    coll = PolyCollection(
        [verts[i] for i in front],
        array=errors_pct[front],
        cmap=_cmap(),
        clim=(-vmax, vmax),
        edgecolors="0.35" if len(front) < 2500 else ("none" if big else "face"),
        linewidths=0.2,
        antialiaseds=not big,
        rasterized=big,
    )
    ax.add_collection(coll)
    ax.add_patch(Circle((0, 0), 1.0, fill=False, lw=0.6))
    ax.set_xlim(-1.05, 1.05)
    ax.set_ylim(-1.05, 1.05)
    ax.set_aspect("equal")
    ax.axis("off")
    return coll


def plot_error_distribution(ax: Any, errors_by_level: dict[int, np.ndarray], bins: int = 40) -> None:
    """Histogram of signed face errors (percentage of faces), one line per level."""
    allv = np.concatenate(list(errors_by_level.values()))
    lo, hi = float(allv.min()), float(allv.max())
    if hi - lo < 1e-9:
        lo, hi = lo - 1.0, hi + 1.0
    edges = np.linspace(lo, hi, bins + 1)
    mids = 0.5 * (edges[1:] + edges[:-1])
    for level, e in errors_by_level.items():
        counts, _ = np.histogram(e, bins=edges)
        ax.plot(mids, 100.0 * counts / len(e), marker="o", ms=2.5, lw=1.0, label=f"level {level}")
    ax.set_xlabel("face area error (%)  (- smaller, + larger than total/faces)")
    ax.set_ylabel("faces (%)")
    ax.legend(fontsize=7)
    ax.grid(alpha=0.3)


def write_figures(
    outdir: str | Path,
    schemes: Iterable[str] | None = None,
    levels: int | None = None,
    progress: bool = False,
    variant: str = "thesis",
) -> list[Path]:
    """Write the highlighting and distribution PNGs for each scheme.

    Parameters
    ----------
    outdir : str or pathlib.Path
        Directory (created if needed).
    schemes : iterable of str, optional
        Scheme names (default: all seven).
    levels : int, optional
        Deepest level of both figures (default: the thesis's depth for the
        error distribution, e.g. 7 for Figure 6.28, and at most 5 for the
        globes, as the thesis's panels).
    progress : bool
        tqdm progress bar.
    variant : str
        ``"thesis"`` (default: the thesis's rules for 2:6, Catmull-Clark and
        1:5, as the text beside its figures describes them) or ``"dggs"``
        (dggs's own).  Those three schemes' files get a ``_thesis`` or
        ``_dggs`` suffix, and every figure is labelled with its rule
        (:func:`~dggs.experiments.figures_ch6.rule_label`).

    Returns
    -------
    list of pathlib.Path
        The files written.

    Raises
    ------
    MissingPlotDependency
        If matplotlib is not installed.
    UnknownSchemeError, ExperimentLevelError
        On bad input.
    """
    plt = _plt()
    out = Path(outdir)
    out.mkdir(parents=True, exist_ok=True)
    written: list[Path] = []
    for name in schemes or SCHEMES:
        scheme = get_scheme(name, variant)
        depth = scheme.thesis_levels if levels is None else levels
        globes = min(depth, 5) if levels is None else levels
        everything = list(iter_levels(scheme, depth, progress))[1:]
        meshes = everything[:globes]
        numbers = FIGURE_NUMBERS.get(scheme.key)  # none for chapter 7's latlng
        fig_a, fig_d = (f" (cf. Figure {f})" for f in numbers) if numbers else ("", "")
        ncol = max(len(meshes), 1)
        fig, axes = plt.subplots(1, ncol, figsize=(2.6 * ncol + 0.8, 3.0), squeeze=False)
        for ax, (mesh, m) in zip(axes[0], meshes, strict=False):  # no meshes: one empty panel
            coll = plot_area_highlighting(ax, mesh, m.face_errors_pct)
            ax.set_title(f"level {m.level}: max {m.max_face_error_pct:.2f} %", fontsize=8)
            cb = fig.colorbar(coll, ax=ax, orientation="horizontal", fraction=0.05, pad=0.02)
            cb.ax.tick_params(labelsize=6)
        rule = rule_label(scheme.key, scheme.variant)
        fig.suptitle(f"Area highlighting - {scheme.title}{fig_a}; blue larger, purple smaller\n{rule}", fontsize=9)
        slug = scheme.key.replace(":", "_") + (f"_{scheme.variant}" if scheme.key in THESIS_SCHEMES else "")
        path = out / f"area_highlighting_{slug}.png"
        fig.savefig(path, dpi=130, bbox_inches="tight")
        plt.close(fig)
        written.append(path)
        fig, ax = plt.subplots(figsize=(6.0, 3.6))
        plot_error_distribution(ax, {m.level: m.face_errors_pct for _, m in everything})
        ax.set_title(f"Face area error distribution - {scheme.title}{fig_d}\n{rule}", fontsize=9)
        path = out / f"error_distribution_{slug}.png"
        fig.savefig(path, dpi=130, bbox_inches="tight")
        plt.close(fig)
        written.append(path)
    return written


def write_all(
    outdir: str | Path,
    chapters: Iterable[str] = CHAPTERS,
    schemes: Iterable[str] | None = None,
    levels: int | None = None,
    progress: bool = False,
    variant: str = "thesis",
    quick: bool = False,
) -> list[Path]:
    """Write the figures of the given chapters ("3", "4", "5", "6"); returns the paths.

    Chapter 6 is :func:`write_figures` (``schemes``, ``levels``, ``variant``)
    plus Figure 6.18 when Split (1:9) is among the schemes.  ``quick`` makes
    every figure cheaper (coarser samples; chapter 6 to level 3).

    Raises
    ------
    ValueError
        On an unknown chapter.
    MissingPlotDependency
        If matplotlib is not installed.
    """
    chapters = [str(c) for c in chapters]
    bad = sorted(set(chapters) - set(CHAPTERS))
    if bad:
        raise ValueError(f"no figures for chapter(s) {', '.join(bad)}; choose from {', '.join(CHAPTERS)}")
    _plt()
    written: list[Path] = []
    if "3" in chapters:  # Figures 3.13-3.14 and the angular deformation of ISEA and IVEA
        from dggs.experiments.projections import write_projection_figures

        written += write_projection_figures(outdir, quick)
    if "4" in chapters:
        from dggs.experiments.figures_ch4 import write_chapter4

        written += write_chapter4(outdir, quick)
    if "5" in chapters:
        from dggs.experiments.figures_ch5 import write_chapter5_curves
        from dggs.experiments.figures_ch5_surfaces import write_chapter5_surfaces

        written += write_chapter5_curves(outdir, quick)
        written += write_chapter5_surfaces(outdir, quick)
    if "6" in chapters:
        names = list(schemes) if schemes else None
        depth = levels if levels is not None else (3 if quick else None)
        written += write_figures(outdir, names, depth, progress, variant)
        if names is None or "1:9" in names:
            from dggs.experiments.figures_ch6 import write_figure_6_18

            written += write_figure_6_18(outdir)
    return written
