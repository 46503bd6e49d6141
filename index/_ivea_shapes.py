"""The shapes floor on IVEA: cell boundaries and shapely polygons of ``dggs.Grid("IVEA")``.

:func:`boundaries` and :func:`geometries` are :mod:`._shapes`' functions of the same names over the IVEA
point kernels (:mod:`dggs.index._kernel.ivea_points`): ordinary rings in one ``shapely.polygons`` call, the
few at a pole or across the antimeridian exactly, and by default the points per edge each cell's own edge
bulge needs for 1e-6 of its area, or for a distance (:func:`dggs.index._densify.edge_points`).
"""

from __future__ import annotations

from typing import Any

import numpy as np
import shapely

from ._checks import check_point_count
from ._densify import EXACT
from ._kernel import ivea_points as ki
from ._shapes import densify_groups, ragged_geometries, ring_to_geometry, special_rings

__all__ = ["boundaries", "geometries"]


def boundaries(ids: np.ndarray, densify: int, lnglat: bool = False, max_points: int | None = None) -> np.ndarray:
    """(N, 3 (densify + 1), 2) (lat, lng) points of valid ids on IVEA, or closed (lng, lat) rings one point longer."""
    check_point_count(ids.shape[0], 3 * (densify + 1) + int(lnglat), max_points)
    out = np.empty((ids.shape[0], 3 * (densify + 1) + int(lnglat), 2))
    ki.boundaries(ids.shape[0] * (densify + 1), ids, densify, out, lnglat)
    return out


def geometries(ids: np.ndarray, densify: int | None, max_points: int | None = None, tolerance: Any = EXACT) -> np.ndarray:
    """Shapely geometries of valid ids on IVEA (as :func:`dggs.index._shapes.geometries`)."""
    if densify is None:
        return ragged_geometries(ids, tolerance, max_points, ivea=True)
    out = np.empty(ids.shape[0], dtype=object)
    groups = densify_groups(ids, densify, tolerance, ivea=True)
    for rows, d in groups:
        coords = boundaries(ids[rows], d, True, max_points)
        special = special_rings(coords)
        out[rows[~special]] = shapely.polygons(coords[~special])
        buf = np.empty((3 * (d + 1) + ki.SPECIAL_EXTRA, 2))
        for i in rows[special].tolist():
            m = ki.special_ring(ids[i], d, buf)
            out[i] = ring_to_geometry(buf[:m, 0], buf[:m, 1])
    return out
