"""Paths and lines: a shortest path between two cells, the cells along a polyline.

:func:`grid_path_cells` walks the edge graph (h3's ``grid_path_cells``);
:func:`line_to_cells` joins the WGS84 geodesics of a polyline
(:func:`dggs.geodesic_to_cells` for each segment).  The cells within a
distance of a point are :func:`dggs.circle_to_cells` (:mod:`dggs.index.circles`).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from dggs.errors import CoordinateError, DggsValueError

from ._checks import check_level, check_max_cells, check_size
from ._convert import cells_out_flat, id_name, ids_array, pair
from ._kernel import paths as kpaths
from .grid import are_neighbor_cells, grid_distance
from .lines import geodesic_to_cells

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
        xy = np.asarray(line, dtype=np.float64)
    except (TypeError, ValueError):
        raise CoordinateError(f"line must be a shapely line or an (N, 2) array of (lat, lng) numbers, not {line!r}") from None
    if xy.ndim != 2 or xy.shape[1] != 2:
        raise CoordinateError(f"line must be an (N, 2) array of (lat, lng) points, not of shape {xy.shape}")
    return [xy] if xy.shape[0] else []


def _joined(chunks: list[np.ndarray]) -> np.ndarray:
    """Consecutive cells, repeats at the joins dropped, gaps (never seen) closed by a shortest path."""
    cells = np.concatenate(chunks) if chunks else np.zeros(0, dtype=np.uint64)
    if cells.size > 1:
        cells = cells[np.concatenate([[True], cells[1:] != cells[:-1]])]
    if cells.size > 1:
        gaps = np.flatnonzero(~np.asarray(are_neighbor_cells(cells[:-1], cells[1:])))
        if gaps.size:  # a join whose two ends fell in cells that only share a corner
            pieces, prev = [], 0
            for g in gaps.tolist():
                pieces.append(cells[prev : g + 1])
                path, _ = _paths(cells[g : g + 1], cells[g + 1 : g + 2], None)
                pieces.append(path[1:-1])
                prev = g + 1
            pieces.append(cells[prev:])
            cells = np.concatenate(pieces)
    return cells


def line_to_cells(line: Any, level: int, as_int: bool = False, max_cells: int | None = None) -> np.ndarray:
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
        Another geometry than a line, or ``max_cells`` is not None or a non-negative integer.
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
    """
    level = check_level(level)
    check_max_cells(max_cells)
    parts = _parts(line)
    chunks: list[np.ndarray] = []
    for xy in parts:
        if xy.shape[0] == 1:
            xy = np.vstack([xy, xy])
        segments = [
            geodesic_to_cells(xy[i, 0], xy[i, 1], xy[i + 1, 0], xy[i + 1, 1], level, as_int=True, max_cells=max_cells)
            for i in range(xy.shape[0] - 1)
        ]
        chunks.append(_joined(segments))
    cells = np.concatenate(chunks) if chunks else np.zeros(0, dtype=np.uint64)
    if cells.size > 1:  # parts that end and start in one cell
        cells = cells[np.concatenate([[True], cells[1:] != cells[:-1]])]
    check_size(int(cells.shape[0]), max_cells, "line_to_cells")
    return ids_array(cells, as_int)
