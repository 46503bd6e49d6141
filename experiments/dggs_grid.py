"""The same chapter-6 metrics for the dggs grid itself (Snyder-mapped Split 2:6 cells).

The thesis's best scheme, the 3D-mesh Split (2:6), peaks at a 16.63 %
maximum face error (Table 6.6).  The dggs grid instead draws Split (2:6) on
the flat icosahedron faces and maps it with Snyder's equal-area projection,
so every cell has the same area on the (authalic) sphere.  Here each cell's
boundary from :func:`dggs.cell_to_boundary` (geodetic WGS84, densified) is
taken to the authalic unit sphere and its *spherical* area measured by
fanning spherical triangles (Van Oosterom & Strackee) from the boundary's
mean direction.  The error left is boundary sampling only: cell edges are
Snyder images of straight face segments, which a densified great-circle
polygon only approximates.

Examples
--------
>>> rows = dggs_grid_metrics(1)
>>> [r.faces for r in rows]
[20, 120]
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

import dggs
from dggs.experiments.errors import ExperimentLevelError
from dggs.experiments.mesh import Mesh
from dggs.experiments.metrics import LevelMetrics, measure

__all__ = ["dggs_grid_metrics", "spherical_polygon_areas"]

#: Deepest level offered (level 7 has 87,480 cells, boundaries fetched one by one).
MAX_DGGS_LEVEL = 8


def spherical_polygon_areas(points: np.ndarray) -> np.ndarray:
    """Areas of ``(F, k, 3)`` unit-sphere polygons (each convex about its mean).

    Examples
    --------
    >>> octant = np.array([[[1.0, 0, 0], [0, 1.0, 0], [0, 0, 1.0]]])
    >>> round(float(spherical_polygon_areas(octant)[0] / (np.pi / 2)), 12)
    1.0
    """
    c = points.mean(axis=1, keepdims=True)
    c = c / np.linalg.norm(c, axis=2, keepdims=True)
    a = np.broadcast_to(c, points.shape)
    b, d = points, np.roll(points, -1, axis=1)
    num = np.abs(np.einsum("fkj,fkj->fk", a, np.cross(b, d)))
    den = 1.0 + (a * b).sum(-1) + (b * d).sum(-1) + (d * a).sum(-1)
    return (2.0 * np.arctan2(num, den)).sum(axis=1)  # Van Oosterom & Strackee 1983


def _to_unit_xyz(latlng: np.ndarray) -> np.ndarray:
    from dggs.geometry.authalic import WGS84

    lat = WGS84.geodetic_to_authalic(np.radians(latlng[..., 0]))
    lng = np.radians(latlng[..., 1])
    return np.stack([np.cos(lat) * np.cos(lng), np.cos(lat) * np.sin(lng), np.sin(lat)], axis=-1)


def dggs_grid_metrics(levels: int, densify: int = 8, progress: bool = False) -> list[LevelMetrics]:
    """Chapter-6 metrics of the dggs grid's cells at levels ``0..levels``.

    Parameters
    ----------
    levels : int
        Deepest level, ``0..MAX_DGGS_LEVEL``.
    densify : int
        Points per cell edge passed to :func:`dggs.cell_to_boundary`.
    progress : bool
        Show a tqdm bar over cells.

    Returns
    -------
    list of LevelMetrics
        Areas are spherical (unit authalic sphere, total ``4 pi``); the
        displacement is that of each cell's boundary-point average.

    Raises
    ------
    ExperimentLevelError
        If ``levels`` is out of range.

    Examples
    --------
    >>> m = dggs_grid_metrics(1)
    >>> bool(m[1].max_face_error_pct < 1e-3)
    True
    """
    if not isinstance(levels, int) or not 0 <= levels <= MAX_DGGS_LEVEL:
        raise ExperimentLevelError(f"levels {levels!r} is out of range 0..{MAX_DGGS_LEVEL} for the dggs grid")
    cells = [str(c) for c in dggs.get_base_cells()]
    out: list[LevelMetrics] = []
    for level in range(levels + 1):
        if level:
            cells = [str(ch) for c in cells for ch in dggs.cell_to_children(c)]
        it: Any = cells
        if progress:
            from tqdm import tqdm

            it = tqdm(cells, desc=f"dggs level {level}", unit="cell", leave=False)
        rings = [np.asarray(dggs.cell_to_boundary(c, densify=densify), dtype=np.float64) for c in it]
        sizes = np.array([len(r) for r in rings])
        areas = np.empty(len(rings))
        blocks, vertices, start = [], [], 0
        for k in np.unique(sizes):  # one iteration per boundary length, not per cell
            idx = np.flatnonzero(sizes == k)
            xyz = _to_unit_xyz(np.stack([rings[i] for i in idx]))
            if np.allclose(xyz[:, 0], xyz[:, -1]):
                xyz = xyz[:, :-1]  # closed ring: drop the repeated point
            areas[idx] = spherical_polygon_areas(xyz)
            n, m = xyz.shape[:2]
            vertices.append(xyz.reshape(-1, 3))
            blocks.append(start + np.arange(n * m).reshape(n, m))
            start += n * m
        # Faces are grouped by boundary size; reorder areas the same way.
        order = np.concatenate([np.flatnonzero(sizes == k) for k in np.unique(sizes)])
        mesh = Mesh(np.concatenate(vertices), tuple(blocks))
        out.append(measure(mesh, level, 4.0 * math.pi, areas=areas[order], radius=1.0))
    return out
