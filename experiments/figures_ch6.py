"""Figure 6.18 (Split (1:9)'s symmetric edge points, thesis §6.3.5) and the rule labels of Figures 6.14-6.28.

:func:`rule_label` names the rule a chapter-6 figure is drawn with: the
thesis's (the default of ``dggs experiments figures``, as the text beside
the thesis's figures describes them: Catmull-Clark's level 1 "all white",
Split (2:6)'s errors growing to 16.63 %) or dggs's own (``--variant dggs``:
Split (2:6) at 0.30 %, Catmull-Clark and Split (1:5) area-preserving).

The thesis: "Split (1:9) appears to have a few degrees of freedom.  A
trivial test concluded that this is not actually the case ... Each outer
vertex on an edge must be symmetric with respect to its partner along that
same edge.  If not, issues in edge matching will result, as a consequence
of vertices of odd valence" (Figure 6.18: (a) current approach, (b)
adjusted midpoint).  We compute both, and a third way out:

* (a) **symmetric**: the edge points at 1/3 and 2/3 of each edge (the
  experiments' Split (1:9), arc placement): every edge point is shared.
* (b) **adjusted, per face**: each face puts its two points at fractions
  ``s`` and ``u`` (``u != 1 - s``) from the corner where its counter-clockwise
  walk enters the edge.  Two neighbours walk a shared edge in opposite
  directions, so they want different points: every edge cracks.
* (c) **adjusted, per edge**: the fractions measured from one fixed end of
  each edge (its lower vertex id), so neighbours agree; but round a vertex of
  odd valence (the icosahedron has valence 5 everywhere) the edge directions
  cannot alternate in and out, so the faces are no longer congruent: the
  level-1 faces fall into more area classes and the maximum face error grows.

Examples
--------
>>> split_1_9_fractions(1 / 3, 2 / 3, "face")["cracked_edges"]
0
>>> split_1_9_fractions(0.25, 0.6, "face")["cracked_edges"]
30
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from dggs.experiments.mesh import Mesh, face_areas, icosahedron, normalize
from dggs.experiments.split_triangles import point_on_edge

__all__ = ["split_1_9_fractions", "write_figure_6_18", "rule_label", "RULE_LABELS"]

#: What each variant of a scheme whose rules differ does, for the figures' labels.
RULE_LABELS: dict[tuple[str, str], str] = {
    ("2:6", "thesis"): "thesis's rule: D at the fixed chord fraction 0.345 from C, reused at every level",
    ("2:6", "dggs"): "dggs's rule, not the thesis's: per-face equal chord areas ('area' placement)",
    ("catmull-clark", "thesis"): "thesis's rule: Catmull-Clark point rules, radius from the raw mesh, "
    "projected, no rescale",
    ("catmull-clark", "dggs"): "dggs's rule, not the thesis's: projected midpoints, rescaled after projecting",
    ("1:5", "thesis"): "thesis's rule: c_f + 0.634 (m_vw - c_f), never rescaled",
    ("1:5", "dggs"): "dggs's rule, not the thesis's: (v + w + c_f) / 3, rescaled",
    ("1:9", "thesis"): "thesis's rule, edge thirds at equal arcs (the thesis does not say where; our choice)",
    ("1:9", "dggs"): "thesis's rule, edge thirds at equal arcs (the thesis does not say where; our choice)",
}


def rule_label(key: str, variant: str) -> str:
    """The label naming the rule a chapter-6 figure of scheme ``key`` is drawn with.

    Parameters
    ----------
    key : str
        Scheme key (``"2:6"``, ``"catmull-clark"``, ...).
    variant : str
        ``"thesis"`` or ``"dggs"``.

    Examples
    --------
    >>> rule_label("2:6", "thesis")
    "thesis's rule: D at the fixed chord fraction 0.345 from C, reused at every level"
    >>> rule_label("1:4", "dggs")
    "thesis's rule (dggs's is the same)"
    """
    if (key, variant) in RULE_LABELS:
        return RULE_LABELS[(key, variant)]
    if key == "latlng":
        return "chapter 7's proposal, dggs's construction"
    return "thesis's rule (dggs's is the same)"


#: The nine children of Split (1:9) in terms of the face's corners a, b, c, the two points on each edge
#: (1 nearer its start corner, 2 nearer its end: ab1, ab2, bc1, bc2, ca1, ca2) and the centre g.
_CHILDREN = (("a", "ab1", "ca2"), ("ab1", "g", "ca2"), ("ab1", "ab2", "g"), ("ab2", "bc1", "g"),
             ("ab2", "b", "bc1"), ("bc1", "bc2", "g"), ("bc2", "c", "ca1"), ("bc2", "ca1", "g"),
             ("g", "ca1", "ca2"))


def split_1_9_fractions(s: float, u: float, mode: str = "face", placement: str = "arc") -> dict:
    """Split (1:9) of the icosahedron with edge points at fractions ``s < u`` (level 1).

    Parameters
    ----------
    s, u : float
        Fractions of the two points along an edge; ``u = 1 - s`` is symmetric.
    mode : {"face", "edge"}
        Measured from each face's own start corner (counter-clockwise), or
        from each edge's lower vertex id (shared by both neighbours).
    placement : {"arc", "chord"}
        As :func:`dggs.experiments.split_triangles.point_on_edge`.

    Returns
    -------
    dict
        ``triangles`` ``(180, 3, 3)`` child corners (unshared: each face's own),
        ``cracked_edges`` (edges whose two faces want different points),
        ``max_gap`` (largest such disagreement over the edge's chord length),
        ``area_error_pct`` (per child, against total / 180), ``area_classes``
        (distinct child areas to 1e-9).
    """
    ico = icosahedron()
    v, faces = ico.vertices, ico.faces[0]
    wanted: dict[tuple[int, int], list[np.ndarray]] = {}
    corners: list[list[np.ndarray]] = []
    for a, b, c in faces:
        pts = {"a": v[a], "b": v[b], "c": v[c], "g": normalize(v[[a, b, c]].mean(axis=0))}
        for (x, y), name in (((a, b), "ab"), ((b, c), "bc"), ((c, a), "ca")):
            if mode == "face" or x < y:
                p1 = point_on_edge(v[[x]], v[[y]], s, 1.0, placement)[0]
                p2 = point_on_edge(v[[x]], v[[y]], u, 1.0, placement)[0]
            else:  # fractions from the lower id y: the point nearer x is at u from y
                p1 = point_on_edge(v[[y]], v[[x]], u, 1.0, placement)[0]
                p2 = point_on_edge(v[[y]], v[[x]], s, 1.0, placement)[0]
            pts[name + "1"], pts[name + "2"] = p1, p2
            wanted.setdefault((min(x, y), max(x, y)), []).append(np.array([p1, p2]) if x < y else np.array([p2, p1]))
        corners += [[pts[k] for k in child] for child in _CHILDREN]
    tris = np.array(corners)
    gaps = [float(np.linalg.norm(w[0] - w[1], axis=1).max() / np.linalg.norm(v[i] - v[j]))
            for (i, j), w in wanted.items()]
    flat = Mesh(tris.reshape(-1, 3), (np.arange(len(tris) * 3).reshape(-1, 3),))
    areas = face_areas(flat)
    err = 100.0 * (areas / (areas.sum() / len(areas)) - 1.0)
    return {"triangles": tris, "cracked_edges": int(sum(g > 1e-12 for g in gaps)), "max_gap": max(gaps),
            "area_error_pct": err, "area_classes": len(np.unique(np.round(areas, 9)))}


def _view(p: np.ndarray, centre: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    east = np.cross([0.0, 0.0, 1.0], centre)
    east = east / np.linalg.norm(east) if np.linalg.norm(east) > 1e-9 else np.array([1.0, 0.0, 0.0])
    north = np.cross(centre, east)
    return np.stack([p @ east, p @ north], axis=-1), p @ centre


def write_figure_6_18(outdir: str | Path, s: float = 0.25, u: float = 0.6) -> list[Path]:
    """Figure 6.18 analogue (three panels round an icosahedron vertex, valence 5); returns the path."""
    from matplotlib.collections import PolyCollection

    from dggs.experiments.figures import _cmap, _plt

    plt = _plt()
    out = Path(outdir)
    out.mkdir(parents=True, exist_ok=True)
    centre = icosahedron().vertices[6]  # a vertex with lower- and higher-id neighbours: mixed edge directions
    runs = [("(a) current approach: thirds", split_1_9_fractions(1 / 3, 2 / 3, "face")),
            (f"(b) adjusted points ({s}, {u}) per face", split_1_9_fractions(s, u, "face")),
            (f"(c) adjusted ({s}, {u}) per edge", split_1_9_fractions(s, u, "edge"))]
    vmax = max(float(np.abs(r["area_error_pct"]).max()) for _, r in runs)
    fig, axes = plt.subplots(1, 3, figsize=(11.0, 4.0))
    for ax, (title, r) in zip(axes, runs, strict=True):
        xy, depth = _view(r["triangles"], centre)
        front = depth.min(axis=1) > 0.55
        crack = "b" in title[:3]
        coll = PolyCollection(list(xy[front]), array=None if crack else r["area_error_pct"][front], cmap=_cmap(),
                              clim=(-vmax, vmax), facecolors="none" if crack else None,
                              edgecolors="0.2", lw=0.5, alpha=0.9)
        ax.add_collection(coll)
        if crack:  # each face's own edge points: where neighbours disagree there are two sets
            pts = xy[front].reshape(-1, 2)
            ax.plot(*pts.T, ".", color="tab:red", ms=2)
        ax.plot(0, 0, "ko", ms=3)
        ax.set_xlim(-0.75, 0.75)
        ax.set_ylim(-0.75, 0.75)
        ax.set_aspect("equal")
        ax.axis("off")
        ax.set_title(f"{title}\ncracked edges {r['cracked_edges']}/30 (gap up to {100 * r['max_gap']:.1f} % "
                     f"of the edge)\narea classes {r['area_classes']}, max face error "
                     f"{np.abs(r['area_error_pct']).max():.2f} %", fontsize=7)
    fig.suptitle("Figure 6.18: Split (1:9) round a vertex of valence 5 (black dot); colour: child area error "
                 "(level 1, no rescale needed for the %)", fontsize=8)
    path = out / "fig6_18_split_1_9_issues.png"
    fig.savefig(path, dpi=130, bbox_inches="tight")
    plt.close(fig)
    return [path]
