"""The ``"overlapping_bbox"`` polygon fill: cells whose lng/lat bounding box meets the polygon.

h3's ``CONTAINMENT_OVERLAPPING_BBOX`` (its experimental polygon fill): a cheap
superset of the cells that touch a polygon.  A cell's boxes are those of the
parts of its :func:`dggs.cell_to_polygon` polygon (one part, or two where the
cell is split at the antimeridian; a cell at a pole reaches latitude 90 over
all longitudes), in the lng/lat plane where the polygon's edges are straight.
A cell is kept when one of its boxes meets the polygon, boundary included.
Since every cell lies in its boxes, this holds every cell of ``"overlaps"``.

The search descends from the base cells: a child lies in its parent, so its
boxes lie in the parent's (tested with a margin of a thousandth of the box,
for the densified polygons); a cell wholly inside the polygon keeps all its
descendants untested; any other cell whose boxes meet the polygon is split.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np
import shapely

from ._checks import check_size
from ._kernel import hierarchy as kh
from ._kernel.bits import MARKER
from ._shapes import geometries

__all__ = ["bbox_fill"]

#: Relative margin of a coarser cell's boxes (densified polygons are within 1e-6 of the true cells).
_MARGIN = 1e-3


def _descendants(ids: np.ndarray, level: int) -> np.ndarray:
    total, _ = kh.count_children(ids, level)
    out = np.empty(total, dtype=np.uint64)
    kh.children(ids, level, out)
    return out


def _box_hits(target: Any, geoms: np.ndarray, margin: float) -> np.ndarray:
    """Whether any part's bounding box (grown by ``margin`` of its size) meets the target, per geometry."""
    parts, owner = shapely.get_parts(geoms, return_index=True)
    b = shapely.bounds(parts)
    grow = margin * np.maximum(b[:, 2] - b[:, 0], b[:, 3] - b[:, 1])[:, None] * np.array([-1.0, -1.0, 1.0, 1.0])
    b = b + grow
    hit = shapely.intersects(target, shapely.box(b[:, 0], b[:, 1], b[:, 2], b[:, 3]))
    out = np.zeros(geoms.shape[0], dtype=bool)
    np.logical_or.at(out, owner, hit)
    return out


def bbox_fill(target: Any, level: int, limit: int, shapes: Callable[[np.ndarray], np.ndarray] | None = None) -> np.ndarray:
    """Sorted uint64 ids of the cells at ``level`` whose boxes meet ``target`` (prepared, in -180..180).

    ``shapes(ids)`` draws the cells (default: :func:`dggs.cell_to_polygon`'s polygons; another projection's grid
    passes its own).

    Raises
    ------
    TooManyCellsError
        The cells kept whole and the candidates of the next level exceed ``limit``.
    """
    ids = MARKER | (np.arange(20, dtype=np.uint64) << np.uint64(57))
    whole: list[np.ndarray] = []
    wholes = 0
    for lv in range(level + 1):
        geoms = geometries(ids, None) if shapes is None else shapes(ids)
        if lv == level:
            keep = _box_hits(target, geoms, 0.0)
            whole.append(ids[keep])
            break
        inside = shapely.contains(target, geoms)
        whole.append(ids[inside])
        wholes += kh.count_children(ids[inside], level)[0]
        ids = ids[~inside & _box_hits(target, geoms, _MARGIN)]
        check_size(wholes + kh.count_children(ids, lv + 1)[0], limit, "polygon_to_cells")
        ids = _descendants(ids, lv + 1)
    found = np.concatenate([_descendants(w, level) for w in whole]) if whole else np.zeros(0, np.uint64)
    check_size(int(found.shape[0]), limit, "polygon_to_cells")
    return np.sort(found)
