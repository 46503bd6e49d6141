"""Chapter 5 experiments: Table 5.1 analogue, cusps (§5.1.9), co-linearity guard (§5.1.10).

The thesis does not give the coordinates of its Table 5.1 shapes, so ours
are our own (:data:`SHAPES`); only the *behaviour* is comparable: the
circumscribed-circle triangle keeps its length exactly, the others drift by
small amounts with the thesis's one-shot scaling (§5.1.6).  "Circumscribed
quadrilateral" is read as a tangential quadrilateral (one with an incircle,
here a kite), because a quadrilateral *inscribed* in a circle would behave
exactly like the triangle, which Table 5.1's 3.05 % rules out.

Examples
--------
>>> rows = table_5_1()
>>> rows[0]["shape"], rows[0]["error_pct"] < 1e-10
('triangle', True)
"""

from __future__ import annotations

import numpy as np

from dggs.experiments.curves import (
    LengthMode,
    polygon_length,
    radial_subdivide,
    reflex_vertices,
)

__all__ = ["SHAPES", "table_5_1", "cusp_demo", "colinear_guard_demo", "format_table_5_1"]

#: Our Table 5.1 shapes (counter-clockwise); the thesis gives none.
SHAPES: dict[str, np.ndarray] = {
    # Acute triangle: every vertex circle is its circumcircle (§5.1.9, origin inside).
    "triangle": np.array([[0.0, 0.0], [180.0, 0.0], [70.0, 140.0]]),
    # Kite: tangential ("circumscribed") quadrilateral, not cyclic.
    "circumscribed quadrilateral": np.array(
        [[0.0, -60.0], [100.0, 0.0], [0.0, 150.0], [-100.0, 0.0]]
    ),
    "convex pentagon": np.array(
        [[0.0, 0.0], [200.0, -20.0], [300.0, 120.0], [150.0, 260.0], [-40.0, 150.0]]
    ),
}

_THESIS_ROW = {
    "triangle": "triangle",
    "circumscribed quadrilateral": "circumscribed quadrilateral",
    "convex pentagon": "convex pentagon",
}


def table_5_1(length: LengthMode = "thesis") -> list[dict[str, float | str]]:
    """Length at levels 0, 2, 3 of the radial subdivision and its error.

    Parameters
    ----------
    length : {"thesis", "exact", "none"}
        Length preservation mode of :func:`~dggs.experiments.curves.radial_subdivide`.

    Returns
    -------
    list of dict
        Keys ``shape``, ``initial``, ``level_2``, ``level_3``,
        ``error_pct`` (level 3 vs level 0) and ``max_error_pct`` (worst of
        levels 1-3; the thesis's quadrilateral entry is a level-2 error).

    Examples
    --------
    >>> [round(r["max_error_pct"], 9) for r in table_5_1("exact")]
    [0.0, 0.0, 0.0]
    """
    rows: list[dict[str, float | str]] = []
    for name, pts in SHAPES.items():
        lengths = [polygon_length(p) for p in radial_subdivide(pts, 3, length=length)]
        l0 = lengths[0]
        rows.append(
            {
                "shape": name,
                "initial": l0,
                "level_2": lengths[2],
                "level_3": lengths[3],
                "error_pct": abs(lengths[3] / l0 - 1.0) * 100.0,
                "max_error_pct": max(abs(x / l0 - 1.0) for x in lengths[1:]) * 100.0,
            }
        )
    return rows


def cusp_demo(levels: int = 5) -> dict[str, list[int]]:
    """Reflex-vertex counts per level: acute vs obtuse triangle (§5.1.9).

    With the circumcentre inside (acute) the basic scheme converges to the
    circle; outside (obtuse) the short-way angle average folds the long
    edge's new points towards the obtuse corner and cusps grow each level.

    Examples
    --------
    >>> d = cusp_demo(3)
    >>> d["acute"], d["obtuse"]
    ([0, 0, 0, 0], [0, 1, 3, 7])
    """
    acute = SHAPES["triangle"]
    obtuse = np.array([[0.0, 0.0], [10.0, 0.0], [5.0, 1.0]])
    return {
        "acute": [reflex_vertices(p) for p in radial_subdivide(acute, levels, length="none")],
        "obtuse": [reflex_vertices(p) for p in radial_subdivide(obtuse, levels, length="none")],
    }


def colinear_guard_demo(levels: int = 3, noise: float = 1e-13, seed: int = 1) -> dict[str, list[float]]:
    """Length per level of a square with near-colinear edge points, guard on/off (§5.1.10).

    The edge midpoints of a 2x2 square are jittered by ``noise``; their
    circles have radii near ``1/noise`` with centres on either side.  Without
    the guard the averaged circle is enormous and the new points shoot off
    (the flipped origins of Figure 5.21); with it they are plain midpoints.

    Examples
    --------
    >>> d = colinear_guard_demo()
    >>> [round(x, 6) for x in d["guarded"]], d["unguarded"][-1] > 1e6
    ([8.0, 8.0, 8.0, 8.0], True)
    """
    sq = np.array(
        [[0, 0], [1, 0], [2, 0], [2, 1], [2, 2], [1, 2], [0, 2], [0, 1]], dtype=np.float64
    )
    rng = np.random.default_rng(seed)
    sq[1::2] += rng.normal(scale=noise, size=(4, 2))
    guarded = radial_subdivide(sq, levels, length="none", colinear_tol=1e-9)
    unguarded = radial_subdivide(sq, levels, length="none", colinear_tol=0.0)
    return {
        "guarded": [polygon_length(p) for p in guarded],
        "unguarded": [polygon_length(p) for p in unguarded],
    }


def format_table_5_1() -> str:
    """Table 5.1 analogue beside the thesis's values, as text.

    Examples
    --------
    >>> "Table 5.1" in format_table_5_1()
    True
    """
    from dggs.experiments.thesis_tables import TABLE_5_1

    lines = [
        "Table 5.1 - Length analysis of the radial subdivision (our shapes; thesis shapes unknown)",
        f"{'shape':<28}{'mode':<8}{'initial':>12}{'2 iters':>12}{'3 iters':>12}"
        f"{'err L3 %':>11}{'max err %':>11}",
    ]
    for mode in ("thesis", "exact"):
        for r in table_5_1(mode):  # type: ignore[arg-type]
            lines.append(
                f"{r['shape']:<28}{mode:<8}{r['initial']:>12.3f}{r['level_2']:>12.3f}"
                f"{r['level_3']:>12.3f}{r['error_pct']:>11.2e}{r['max_error_pct']:>11.2e}"
            )
    for name, (l0, l2, l3, err) in TABLE_5_1.items():
        lines.append(
            f"{name:<28}{'THESIS':<8}{l0:>12.3f}{l2:>12.3f}{l3:>12.3f}{err:>11.2e}{'':>11}"
        )
    cusp = cusp_demo(4)
    guard = colinear_guard_demo()
    lines.append(
        f"cusps (§5.1.9), reflex vertices per level: acute {cusp['acute']}, obtuse {cusp['obtuse']}"
    )
    lines.append(
        "co-linearity guard (§5.1.10), square length per level: "
        f"guarded {[round(x, 6) for x in guard['guarded']]}, "
        f"unguarded {[float(f'{x:.3g}') for x in guard['unguarded']]}"
    )
    return "\n".join(lines)
