"""Paths and lines: a shortest path between two cells, the cells along a polyline.

:func:`grid_path_cells` walks the edge graph (h3's ``grid_path_cells``);
:func:`line_to_cells` joins the WGS84 geodesics of a polyline
(:func:`dggs.geodesic_to_cells`'s cells for each segment, traced by
:mod:`dggs.index._kernel.line_trace` between exact pyproj points).  The cells within a
distance of a point are :func:`dggs.circle_to_cells` (:mod:`dggs.index.circles`).
"""

from __future__ import annotations

from functools import lru_cache
from typing import Any

import numpy as np

from dggs.errors import CoordinateError, DggsValueError

from ._checks import check_level, check_max_cells, check_projection, check_size
from ._convert import cells_out_flat, id_name, ids_array, pair
from ._corners import fans
from ._kernel import line_trace as kline
from ._kernel import paths as kpaths
from .grid import grid_distance
from .measure import level_table
from .points import latlng_to_cell

__all__ = ["grid_path_cells", "line_to_cells"]


def _paths(a: np.ndarray, b: np.ndarray, max_cells: Any) -> tuple[np.ndarray, np.ndarray]:
    """The paths of pairs of uint64 ids end to end, and their offsets (``len(a) + 1``)."""
    dist = np.asarray(grid_distance(a, b), dtype=np.int64).reshape(-1)  # raises LevelMismatchError
    offsets = np.zeros(a.shape[0] + 1, dtype=np.int64)
    np.cumsum(dist + 1, out=offsets[1:])
    check_size(int(offsets[-1]), max_cells, "grid_path_cells")
    out = np.empty(int(offsets[-1]), dtype=np.uint64)
    status = np.zeros(a.shape[0], dtype=np.int64)
    kpaths.paths(int(offsets[-1]), a, b, offsets, out, status)
    if (status != 0).any():  # pragma: no cover - the distance is exact, so a nearer neighbour always exists
        i = int(np.flatnonzero(status)[0])
        raise DggsValueError(f"no shortest path found from {id_name(a[i])!r} to {id_name(b[i])!r}")
    return out, offsets


def grid_path_cells(a: Any, b: Any, max_cells: int | None = None) -> Any:
    """A shortest path of cells from ``a`` to ``b`` in the edge graph, both ends included.

    The path has ``grid_distance(a, b) + 1`` cells and each is an edge
    neighbour of the one before.  Of the many shortest paths, it is the one a
    greedy walk takes: from each cell, the first of its
    :func:`dggs.edge_neighbors` (in column order) one step nearer to ``b``.
    The same pair always gives the same path; the reverse pair can give a
    different one.  The path follows the graph, not the geodesic between the
    centres (for the cells along a line, :func:`line_to_cells`).

    Parameters
    ----------
    a, b : cell ids
        One id each, or containers of ids of any kind that broadcast against
        each other as in numpy (one cell against many).  Strings or integers.
    max_cells : int, optional
        Refuse to return more cells than this in all (default
        :data:`dggs.index.hierarchy.MAX_CELLS`), checked before the walk.

    Returns
    -------
    list or list of paths
        For two single ids, a list of ids (str or int, as given).  For
        containers, a list with one path per pair (in the C order of the
        broadcast shape), each a 1-d container of the input's kind (a list
        for lists, a numpy array for numpy, ...).

    Raises
    ------
    InvalidCellError
        A malformed id (the message names it).
    LevelMismatchError
        A pair of cells at different levels.
    DggsValueError
        Shapes that do not broadcast, or ``max_cells`` is not None or a non-negative integer.
    TooManyCellsError
        The paths would hold more than ``max_cells`` cells.

    Examples
    --------
    >>> grid_path_cells("C401", "C420")
    ['C401', 'C411', 'C410', 'C420']
    >>> grid_path_cells(["C401", "C401"], ["C401", "C411"])
    [['C401'], ['C401', 'C411']]
    >>> import dggs
    >>> path = grid_path_cells(dggs.str_to_int("A10"), dggs.str_to_int("T31"))
    >>> len(path) == dggs.grid_distance("A10", "T31") + 1
    True
    """
    check_max_cells(max_cells)
    ia, ib, kind = pair(a, b)
    out, offsets = _paths(ia, ib, max_cells)
    flat = cells_out_flat(out, kind)  # every id converted at once, then cut into paths
    if kind.scalar:
        return flat
    if ia.shape[0] == 0:
        return []
    bounds = offsets.tolist()
    if isinstance(flat, np.ndarray):
        return np.split(flat, bounds[1:-1])
    if hasattr(flat, "iloc"):  # a pandas Series: each path with its own 0-based index
        return [flat.iloc[s:e].reset_index(drop=True) for s, e in zip(bounds[:-1], bounds[1:], strict=True)]
    if hasattr(flat, "slice"):  # pyarrow
        return [flat.slice(s, e - s) for s, e in zip(bounds[:-1], bounds[1:], strict=True)]
    return [flat[s:e] for s, e in zip(bounds[:-1], bounds[1:], strict=True)]


def _is_number(value: Any) -> bool:
    return isinstance(value, (int, float, np.integer, np.floating)) and not isinstance(value, (bool, np.bool_))


def _parts(line: Any) -> list[np.ndarray]:
    """The polyline(s) as (N, 2) float arrays of (lat, lng)."""
    import shapely

    if isinstance(line, shapely.Geometry):
        if line.geom_type in ("LineString", "LinearRing"):
            geoms = [line]
        elif line.geom_type == "MultiLineString":
            geoms = list(line.geoms)
        else:
            raise DggsValueError(f"line must be a LineString or MultiLineString, not a {line.geom_type}")
        return [np.ascontiguousarray(shapely.get_coordinates(g)[:, ::-1], dtype=np.float64) for g in geoms if not g.is_empty]
    try:
        raw = np.asarray(line)
        if raw.dtype.kind not in "iuf" and not (raw.dtype.kind == "O" and all(_is_number(v) for v in raw.reshape(-1))):
            raise TypeError  # strings, bools, bytes and None are not coordinates (as in latlng_to_cell)
        xy = raw.astype(np.float64)
    except (TypeError, ValueError):
        raise CoordinateError(f"line must be a shapely line or an (N, 2) array of (lat, lng) numbers, not {line!r}") from None
    if xy.ndim != 2 or xy.shape[1] != 2:
        raise CoordinateError(f"line must be an (N, 2) array of (lat, lng) points, not of shape {xy.shape}")
    return [xy] if xy.shape[0] else []


#: Sample spacing along each geodesic, in short cell edges (gaps between samples are bisected).  At 0.5,
#: 1.15 samples and 0.32 bisection points a cell (bench_paths.py's polylines, levels 13 and 17); 0.25 took
#: 1.8x the time; at 1.0 one polyline in 470 (levels 5-24) lost a cell, a detour between two samples in
#: neighbouring cells, at 0.75 and 0.5 none (the cells were those of the previous sampling every 0.25 edge).
_STEP_EDGES = 0.5
#: Bisection stops at this length (metres): cells that still meet only at a corner are joined around it.
_CORNER_M = 1e-4
#: Largest distance (metres) between an interpolated point and the geodesic's point at the same distance:
#: 0.1 mm (the corner length :data:`_CORNER_M`), or 1e-6 of the level's short edge where that is smaller
#: (from level 20), never below 1e-8 m (rounding in ECEF metres is 1e-9 m).  Anchors are then at most 39 km
#: apart from level 0 to 19 (11.8 km at level 28's 0.8 micrometres).
_TOL_M, _TOL_EDGE, _TOL_FLOOR = 1e-4, 1e-6, 1e-8
#: Cells per short edge of length, plus cells per segment, in the size bound checked before sampling
#: (:data:`dggs.index.lines._CELLS_PER_EDGE`'s reasoning: a segment crosses at most 1.98 cells a short edge).
_CELLS_PER_EDGE, _CELLS_EXTRA = 3.0, 24


@lru_cache(maxsize=1)
def _geod() -> Any:
    import pyproj

    return pyproj.Geod(ellps="WGS84")


@lru_cache(maxsize=32)
def _short_edge(level: int) -> float:
    edge: float = level_table(level)[level]["short_edge_m"]
    return edge


def _tolerance(level: int) -> float:
    """The bound (metres) on an interpolated point's distance from the geodesic at ``level``."""
    return max(_TOL_FLOOR, min(_TOL_M, _TOL_EDGE * _short_edge(level)))


def _tracer(projection: str) -> Any:
    """The compiled tracer of ``projection``: :mod:`.line_trace` (ISEA) or its IVEA build (loaded on first use)."""
    if projection == "ISEA":
        return kline
    from ._kernel import ivea_lines

    return ivea_lines


def _anchors(xy: np.ndarray, level: int) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Exact geodesic points along a polyline of distinct consecutive points, at most a span apart.

    Returns (lat, lng, az_out, az_in, span, dist): anchor ``k``'s point, the
    geodesic's azimuth leaving and arriving there, the length of span ``k``
    (to anchor ``k + 1``), and each segment's length.  The polyline's
    points are anchors as given; between them, ``pyproj.Geod.fwd`` gives the
    points (one call for all segments) and their azimuths.
    """
    az12, az21, dist = (np.asarray(v, dtype=np.float64) for v in _geod().inv(xy[:-1, 1], xy[:-1, 0], xy[1:, 1], xy[1:, 0]))
    lat, lng, az_out, az_in, span, at, seg, s = kline.layout(xy, az12, az21, dist, kline.span_for(_tolerance(level)))
    if at.size:
        x, y, back = _geod().fwd(xy[seg, 1], xy[seg, 0], az12[seg], s)
        lat[at], lng[at] = y, x
        az_out[at] = az_in[at] = np.asarray(back) + 180.0
    return lat, lng, az_out, az_in, span, dist


def _around(a: int, b: int) -> list[int]:
    """The cells strictly between ``a`` and ``b`` the shorter way around a corner they share (as geodesic_to_cells)."""
    around, sizes = fans(np.full(3, a, dtype=np.uint64), np.arange(3))
    best: list[int] | None = None
    for fan, size in zip(around, sizes.tolist(), strict=True):
        ring = [int(c) for c in fan[:size]]
        if b in ring:
            p = ring.index(b)
            way = ring[1:p] if p <= size - p else ring[p + 1 :][::-1]
            if best is None or len(way) < len(best):
                best = way
    if best is None:  # pragma: no cover - bisection reaches 0.1 mm only next to a shared corner
        path, _ = _paths(np.array([a], np.uint64), np.array([b], np.uint64), None)
        return [int(c) for c in path[1:-1]]
    return best


def _trace(xy: np.ndarray, level: int, max_cells: Any, projection: str = "ISEA") -> np.ndarray:
    """The cells along one polyline of (lat, lng) points (at least two), traced by ``projection``'s compiled kernel."""
    i, pts = kline.clean(np.ascontiguousarray(xy, dtype=np.float64))  # repeated points add no segment
    if i >= 0:
        raise CoordinateError(f"point ({float(xy[i, 0])!r}, {float(xy[i, 1])!r}) at index {i} is not a finite latitude in -90..90 and a finite longitude")
    xy = pts
    if xy.shape[0] == 1 and projection == "ISEA":
        return np.asarray(latlng_to_cell(xy[:, 0], xy[:, 1], level, as_int=True), dtype=np.uint64).reshape(-1)
    if xy.shape[0] == 1:  # IVEA's location of the one point, as Grid("IVEA").latlng_to_cell's
        from ._kernel import ivea_points

        return np.array([ivea_points.one_point(float(xy[0, 0]), float(xy[0, 1]), level)], dtype=np.uint64)
    lat, lng, az_out, az_in, span, dist = _anchors(xy, level)
    edge = _short_edge(level)
    bound = int(np.ceil(_CELLS_PER_EDGE * dist / edge).sum()) + _CELLS_EXTRA * dist.size
    check_size(bound, max_cells, "line_to_cells")
    cap = bound + 16
    while True:
        out = np.empty(cap, dtype=np.uint64)
        fix = np.empty(max(16, cap // 8), dtype=np.int64)
        n, nfix = _tracer(projection).trace(lat, lng, az_out, az_in, span, level, _STEP_EDGES * edge, _CORNER_M, out, fix)
        if n >= 0:
            break
        cap *= 2  # pragma: no cover - the bound holds
    out = out[:n]
    if nfix == 0:
        return out
    pieces, prev = [], 0
    for i in fix[:nfix].tolist():
        pieces += [out[prev:i], np.array(_around(int(out[i - 1]), int(out[i])), dtype=np.uint64)]
        prev = i
    pieces.append(out[prev:])
    return np.concatenate(pieces)


def line_to_cells(
    line: Any, level: int, as_int: bool = False, max_cells: int | None = None, *, projection: str = "ISEA"
) -> np.ndarray:
    """The cells along a polyline, in order; each segment is the WGS84 geodesic between its points.

    Each segment gives :func:`dggs.geodesic_to_cells`'s cells: the first holds
    its start, the last its end, every one meets the geodesic, and consecutive
    cells share an edge (a line within 0.1 mm of a corner goes around it the
    shorter way).  Where segments join, the cell of the shared point is kept
    once, so the cells of one line are edge neighbours all along, without
    repeats in a row.  A cell can come back later (the line leaves and
    re-enters it).  Segments across the antimeridian take the short way
    (170 to -170 degrees crosses 180), as geodesics do.  The parts of a
    MultiLineString follow one another; where one part ends and the next
    starts, the cells need not be neighbours.

    The polyline's own points and exact geodesic points every 39 km or less
    (``pyproj.Geod``) are located as :func:`dggs.latlng_to_cell` locates
    them; between them a compiled tracer samples every half short edge a
    curve within 0.1 mm of the geodesic (1e-6 of the short edge from level
    20) and bisects the gaps (:mod:`dggs.index._kernel.line_trace` derives
    the bound), and every pair of samples in edge neighbours that a test in
    the face plane cannot show to have crossed only their shared edge (the
    line may pass round an end of it, :mod:`dggs.index._kernel.chord`).

    Parameters
    ----------
    line : shapely LineString, LinearRing or MultiLineString, or array_like (N, 2)
        Shapely coordinates are (lng, lat) degrees as GeoJSON's (a third
        coordinate is ignored); an array or list of points is (lat, lng)
        degrees, as h3's.  One point gives its cell; no points, no cells.
    level : int
        Level of the cells.
    as_int : bool
        Return uint64 ids instead of strings.
    max_cells : int, optional
        Refuse lines of more cells than this (each segment checked before
        sampling, as :func:`dggs.geodesic_to_cells`, then the whole line;
        default :data:`dggs.index.hierarchy.MAX_CELLS`).
    projection : {"ISEA", "IVEA"}
        The grid whose cells are traced (``dggs.Grid(projection).line_to_cells``
        passes it; the same tracer compiled on IVEA's forward, docs/grid.md).

    Returns
    -------
    ndarray of str or uint64

    Raises
    ------
    CoordinateError
        Points that are not (lat, lng) pairs of finite numbers with latitudes in -90..90.
    LevelError
        A bad level.
    DggsValueError
        Another geometry than a line, ``max_cells`` is not None or a non-negative integer, or another projection.
    TooManyCellsError
        The line would have more than ``max_cells`` cells.

    Examples
    --------
    >>> cells = line_to_cells([(51.05, -114.07), (49.28, -123.12), (47.61, -122.33)], 7)
    >>> str(cells[0]), str(cells[-1]), len(cells)
    ('F2000211', 'F2010102', 17)
    >>> import dggs
    >>> bool(dggs.are_neighbor_cells(cells[:-1], cells[1:]).all())
    True
    >>> from shapely.geometry import LineString
    >>> line_to_cells(LineString([(179.5, 0.0), (-179.5, 0.0)]), 3).tolist()
    ['O321', 'O320', 'O310', 'O311', 'O301', 'O300']
    >>> len(line_to_cells([(51.05, -114.07), (49.28, -123.12), (47.61, -122.33)], 7, projection="IVEA"))
    19
    """
    level = check_level(level)
    check_max_cells(max_cells)
    projection = check_projection(projection)
    parts = _parts(line)
    chunks: list[np.ndarray] = []
    for xy in parts:
        chunks.append(_trace(np.vstack([xy, xy]) if xy.shape[0] == 1 else xy, level, max_cells, projection))
    if len(chunks) == 1:  # one part: no repeats in a row already
        cells = chunks[0]
    else:
        cells = np.concatenate(chunks) if chunks else np.zeros(0, dtype=np.uint64)
        if cells.size > 1:  # parts that end and start in one cell
            cells = cells[np.concatenate([[True], cells[1:] != cells[:-1]])]
    check_size(int(cells.shape[0]), max_cells, "line_to_cells")
    return ids_array(cells, as_int)
