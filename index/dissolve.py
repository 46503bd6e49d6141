"""Dissolve cells into their outline: :func:`cells_to_polygons` (h3's ``cells_to_h3shape``).

The outline is found on ids (:mod:`dggs.index._kernel.dissolve`): an edge of
a cell is on it when the cell across is not covered by the set, so edges
shared by two cells cancel by identity, never by comparing coordinates.  The
outline's edges are chained into rings, each ring with the set on its left,
and only then drawn: each edge with the points its cell's
:func:`dggs.cell_to_polygon` gives it, poles and antimeridian crossings as
that function draws them.

On the plane of (lng, lat), a ring becomes a region: its inside, unwrapped
across the antimeridian (a ring that goes round a pole is closed over the
pole on its left) and cut into the window -180..180.  Rings do not cross, so
a point is in the set exactly when it is inside an odd number of regions, or
an even number: the centre of one cell of the set says which.  Each region
at an even depth (counting the regions it lies in), less the regions right
inside it, is one polygon of the answer.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import shapely
from shapely.geometry import MultiPolygon, Polygon, box
from shapely.geometry.polygon import orient

from ._checks import check_densify, check_projection, check_size
from ._convert import cells_in
from ._densify import EXACT, edge_points
from ._kernel import dissolve as kd
from ._kernel import hierarchy as kh
from ._shapes import geometries

__all__ = ["cells_to_polygons", "GLOBE"]

#: What :func:`cells_to_polygons` gives for a set that covers the whole sphere (no outline).
GLOBE = orient(box(-180.0, -90.0, 180.0, 90.0), 1.0)

#: Corners of a ring closer than this (degrees) are one corner: where the set touches itself.
_SAME_CORNER = 1e-9
#: Most boundary descendants a coarse cell beside finer ones may stand for.
_MAX_FINE = 50_000_000


def _outline(ids: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Outline edges (cell, column) of the set ``ids`` (sorted, disjoint), at its finest level, and the fine cells."""
    levels = kh.levels(ids)
    finest = int(levels.max())
    coarse = levels < finest
    fine = ids
    if coarse.any():
        lv = levels[coarse]
        # a cell l levels coarser has at most 6 * 3 ** ceil(l / 2) + 12 boundary descendants (its edges' length)
        check_size(int(np.sum(6 * 3.0 ** np.ceil((finest - lv) / 2.0) + 12)), _MAX_FINE, "cells_to_polygons's outline")
        fine = np.sort(np.concatenate([ids[~coarse], kd.boundary_descendants(ids[coarse], finest)]))
    mask = np.empty((fine.shape[0], 3), dtype=np.bool_)
    kd.outline_mask(fine.shape[0], fine, ids, mask)
    rows, cols = np.nonzero(mask)
    return fine[rows], cols.astype(np.int64), fine


def _corner_keys(points: np.ndarray) -> np.ndarray:
    """One int64 pair per (lat, lng) point, equal for points within about :data:`_SAME_CORNER`, as a sortable record."""
    key = np.round(points / _SAME_CORNER).astype(np.int64)
    key[:, 1] %= int(round(360.0 / _SAME_CORNER))
    return np.ascontiguousarray(key).view([("lat", np.int64), ("lng", np.int64)]).reshape(-1)


def _snap_corners(out: np.ndarray, corner: np.ndarray) -> None:
    """Give every corner the outline passes more than once one coordinate (polygons touching there stay valid)."""
    rows = np.flatnonzero(corner)
    if rows.size == 0:
        return
    key = _corner_keys(out[rows])
    order = np.argsort(key, kind="stable")
    same = key[order][1:] == key[order][:-1]
    if not same.any():
        return
    first = np.maximum.accumulate(np.where(np.concatenate([[False], same]), 0, np.arange(rows.size)))
    out[rows[order]] = out[rows[order[first]]]


def _split_pinches(ring: np.ndarray, corner: np.ndarray) -> list[np.ndarray]:
    """The ring cut into simple loops where it passes one corner twice (the set touching itself there)."""
    loops: list[np.ndarray] = []
    todo = [(ring, corner)]
    while todo:
        ring, corner = todo.pop()
        rows = np.flatnonzero(corner)
        key = _corner_keys(ring[rows])
        order = np.argsort(key, kind="stable")
        twice = np.flatnonzero(key[order][1:] == key[order][:-1])
        if twice.size == 0:
            loops.append(ring)
            continue
        same = np.sort(order[twice[0] : twice[0] + 2])
        p, q = int(rows[same[0]]), int(rows[same[1]])
        todo.append((ring[p:q], corner[p:q]))
        todo.append((np.concatenate([ring[q:], ring[:p]]), np.concatenate([corner[q:], corner[:p]])))
    return loops


def _steps(ys: np.ndarray, xs: np.ndarray) -> np.ndarray:
    """Longitude steps to the next point: the short way, but along a pole the way the set lies (on the left)."""
    steps = np.diff(np.concatenate([xs, xs[:1]]))
    steps = (steps + 180.0) % 360.0 - 180.0
    along = (np.abs(ys) == 90.0) & (np.roll(ys, -1) == ys)  # the ring runs along a pole: west at the North Pole
    if along.any():
        raw = np.roll(xs, -1)[along] - xs[along]
        steps[along] = np.where(ys[along] > 0, -((-raw) % 360.0), raw % 360.0)
    return steps


def _shifted_back(raw: np.ndarray, shift: float) -> Any:
    """Coordinates moved ``shift`` degrees west, each longitude then the ring's own (sorted ``raw``) it rounds to.

    A longitude moved by 360 and back can lose its last bits; a corner two regions share must stay one point.
    """

    def back(xy: np.ndarray) -> np.ndarray:
        xy = xy.copy()
        xy[:, 0] -= shift
        i = np.clip(np.searchsorted(raw, xy[:, 0]), 1, max(raw.size - 1, 1))
        lo, hi = raw[i - 1], raw[np.minimum(i, raw.size - 1)]
        near = np.where(np.abs(xy[:, 0] - lo) <= np.abs(xy[:, 0] - hi), lo, hi)
        close = np.abs(near - xy[:, 0]) < _SAME_CORNER
        xy[close, 0] = near[close]
        return xy

    return back


def _regions(ring: np.ndarray) -> tuple[list[Polygon], bool]:
    """The (lng, lat) region left of a (lat, lng) ring on the sphere, cut into the window -180..180.

    Returns the pieces and whether the ring goes round a pole (its region is then closed over the pole).
    """
    ys, xs = ring[:, 0], ring[:, 1]
    steps = _steps(ys, xs)
    # a step along a pole past the antimeridian gets a point there (the kernel puts one on every other crossing)
    cross = (np.abs(ys) == 90.0) & (np.floor((xs + steps + 180.0) / 360.0) != np.floor((xs + 180.0) / 360.0))
    cross &= (np.abs(xs) != 180.0) & (np.abs(xs + steps) % 360.0 != 180.0)
    if cross.any():
        at = np.flatnonzero(cross)
        ys = np.insert(ys, at + 1, ys[at])
        xs = np.insert(xs, at + 1, np.where(steps[at] > 0, 180.0, -180.0))
        steps = _steps(ys, xs)
    turns = int(round(float(np.sum(steps)) / 360.0))
    if turns:  # round a pole: start on the antimeridian, so that the closure over the pole runs along it
        at = np.flatnonzero(np.abs(xs) == 180.0)
        if at.size:
            r = int(at[0])
            ys, xs, steps = np.roll(ys, -r), np.roll(xs, -r), np.roll(steps, -r)
            # from -180 east (or 180 west) the points keep their own longitudes: none is shifted by 360 and back
            xs = xs.copy()
            xs[0] = -180.0 if turns > 0 else 180.0
    x = xs[0] + np.concatenate([[0.0], np.cumsum(steps[:-1])])
    x = xs + 360.0 * np.round((x - xs) / 360.0)  # whole turns added to the points as they are: no rounding drift
    if turns:  # the set is north of a ring running east, south of one running west
        pole = 90.0 if turns > 0 else -90.0
        end = xs[0] + 360.0 * turns
        x = np.concatenate([x, [end, end, xs[0]]])
        ys = np.concatenate([ys, [ys[0], pole, pole]])
    poly = Polygon(np.column_stack([x, ys]))
    if not poly.is_valid:
        poly = shapely.make_valid(poly)
    lo, hi = float(x.min()), float(x.max())
    if lo >= -180.0 and hi <= 180.0:
        pieces = [poly]
    else:
        pieces = []
        for k in range(int(np.floor((lo + 180.0) / 360.0)), int(np.floor((hi + 180.0) / 360.0)) + 1):
            piece = poly.intersection(box(-180.0 + 360.0 * k, -90.0, 180.0 + 360.0 * k, 90.0))
            if not piece.is_empty:
                pieces.append(piece if k == 0 else shapely.transform(piece, _shifted_back(np.unique(xs), 360.0 * k)))
    out: list[Polygon] = []
    for p in pieces:
        out.extend(g for g in getattr(p, "geoms", [p]) if isinstance(g, Polygon) and g.area > 0.0)
    return out, turns != 0


def _even_odd(plain: list[Polygon], polar: list[Polygon], inside: tuple[float, float]) -> Polygon | MultiPolygon:
    """The points inside an odd (or even) number of regions, whichever holds the point ``inside`` (lng, lat).

    The ``plain`` regions are nested or apart: each at an even depth (the regions it lies in), less the
    regions right inside it.  The few ``polar`` ones (closed over a pole) are then added by symmetric difference.
    """
    geoms = np.array(plain, dtype=object)
    n = len(plain)
    parts: list[Any] = []
    if n == 1:
        parts = [geoms[0]]
    elif n:
        tree = shapely.STRtree(geoms)
        within, around = tree.query(geoms, predicate="covered_by")
        keep = within != around
        within, around = within[keep], around[keep]
        depth = np.bincount(within, minlength=n)
        direct = depth[within] == depth[around] + 1
        holes: dict[int, list[int]] = {}
        for a, b in zip(around[direct].tolist(), within[direct].tolist(), strict=True):
            holes.setdefault(a, []).append(b)
        for i in np.flatnonzero(depth % 2 == 0).tolist():
            parts.append(shapely.difference(geoms[i], shapely.union_all(geoms[holes[i]])) if i in holes else geoms[i])
    shape: Any = MultiPolygon([p for g in parts for p in getattr(g, "geoms", [g]) if isinstance(p, Polygon)])
    for region in polar:
        shape = shapely.symmetric_difference(shape, region)
    if not shape.covers(shapely.Point(*inside)):
        shape = shapely.difference(GLOBE, shape)
    out = [orient(p, 1.0) for p in getattr(shape, "geoms", [shape]) if isinstance(p, Polygon) and not p.is_empty]
    return out[0] if len(out) == 1 else MultiPolygon(out)


def cells_to_polygons(cells: Any, densify: int | None = None, *, projection: str = "ISEA") -> Polygon | MultiPolygon:
    """The outline of a set of cells: one shapely (Multi)Polygon in (lng, lat), with holes.

    Edges shared by two cells of the set cancel by their ids (never by
    comparing coordinates); the remaining edges are chained into rings,
    which become the shells and holes.  The result is the union of the
    cells' :func:`dggs.cell_to_polygon`, built without a polygon union, cut
    at the antimeridian and closed over a pole the set surrounds.

    Parameters
    ----------
    cells : str, int or array_like of ids
        Cell ids of any levels, string or integer, in any container.  Duplicates
        and cells inside another cell of the set are merged (the union is
        taken); a coarse cell beside finer ones is drawn along the finer
        cells' edges (its outline at the finest level of the set).
    densify : int, optional
        Points added along each edge of the outline.  By default each edge
        gets the points its cell gets from :func:`dggs.cell_to_polygon`
        (enough that the cell's geodesic area is within 1e-6 of the truth).
    projection : {"ISEA", "IVEA"}
        The grid's projection (``dggs.Grid(projection).cells_to_polygons`` passes it): which edges make the
        outline is the same on both, the points along them are the projection's (docs/grid.md).

    Returns
    -------
    shapely.Polygon or shapely.MultiPolygon
        A Polygon when the outline is one polygon, else a MultiPolygon; every
        shell counter-clockwise, holes clockwise.  An empty MultiPolygon for no
        cells.  A set that covers the whole sphere has no outline: the result
        is then :data:`GLOBE`, the rectangle (-180, -90, 180, 90), as the union
        of the cells' polygons is.

    Raises
    ------
    InvalidCellError
        A malformed id (the message names it).
    DggsValueError
        ``densify`` is not None or a non-negative integer.
    TooManyCellsError
        Coarse cells beside much finer ones whose outline at the fine level would
        take more than 50 million cells.

    Examples
    --------
    >>> import dggs
    >>> blob = dggs.grid_disk("C4010", 2)
    >>> shape = cells_to_polygons(blob)
    >>> shape.geom_type, len(shape.interiors)
    ('Polygon', 0)
    >>> around = dggs.uncompact_cells(dggs.grid_disk_vertex("C4010", 1), 6)
    >>> frame = cells_to_polygons([c for c in around if not c.startswith("C4010")])
    >>> frame.geom_type, len(frame.interiors)
    ('Polygon', 1)
    >>> cells_to_polygons(dggs.get_base_cells()).equals(GLOBE)
    True
    """
    ids, _ = cells_in(cells)
    step = None if densify is None else check_densify(densify) + 1
    ivea = check_projection(projection) == "IVEA"
    if ivea:  # the same outline, drawn through IVEA's inverse (loaded on first use)
        from . import _ivea_shapes
        from ._kernel import ivea_edges
    ids = np.unique(ids)
    if ids.size == 0:
        return MultiPolygon()
    ids = ids[kd.drop_covered(ids)]
    ecell, ecol, _ = _outline(ids)
    if ecell.size == 0:
        return GLOBE
    order, starts, bad = kd.chain(ecell, ecol, ids)
    if bad >= 0:  # pragma: no cover - a broken grid
        raise RuntimeError(f"the outline of the cells does not close at edge {int(bad)}")
    cell, col = ecell[order], ecol[order]
    if step is None:
        uniq, inv = np.unique(cell, return_inverse=True)
        steps = (edge_points(uniq, EXACT, ivea) + 1)[inv].astype(np.int64)  # as cell_to_polygon draws each cell
    else:
        steps = np.full(cell.shape[0], step, dtype=np.int64)
    out = np.empty((kd.ring_point_bound(steps), 2))
    corner = np.zeros(out.shape[0], dtype=np.bool_)
    ends = np.empty(starts.shape[0] - 1, dtype=np.int64)
    (ivea_edges.ring_points if ivea else kd.ring_points)(cell, col, steps, starts, out, corner, ends)
    _snap_corners(out, corner)
    plain: list[Polygon] = []
    polar: list[Polygon] = []
    begin = 0
    for end in ends.tolist():
        for loop in _split_pinches(out[begin:end], corner[begin:end]):
            pieces, round_pole = _regions(loop)
            (polar if round_pole else plain).extend(pieces)
        begin = end
    # a point inside the set: inside the first outline cell's polygon drawn as the outline is (its edges on the
    # outline are the outline's, the others inside the set), not its centre, which a coarse drawing may leave out
    inside = (_ivea_shapes.geometries if ivea else geometries)(cell[:1], int(steps[0]) - 1)[0].representative_point()
    return _even_odd(plain, polar, (inside.x, inside.y))
