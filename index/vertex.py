"""Cell corners (vertices) and the cells that share them.

In the 30-60-90 (kisrhombille) tiling of a level, 4 cells meet at a
right-angle corner, 6 at a 60-degree corner and 12 at a 30-degree corner.
At the 12 icosahedron vertices 5 faces meet instead of 6: 10 cells at
levels >= 1 (two 30-degree corners per face), 5 faces at level 0.

The cells around a corner are found by walking around it: from a cell,
cross one of the two edges that end at the corner, then, in the new cell,
cross the other edge that ends there, until the walk is back.  Both cells'
corners run counter-clockwise, so the corner is the far end of the edge
back: the walk follows the grid's own edge adjacency
(:func:`dggs.edge_neighbors`) alone and needs no projection and no
tolerance.  The walks and the disks of :func:`grid_disk_vertex` run in the
C core (libdggs/src/vertex.c, ``dggs_grid_disk_vertex``).

Vertex ids
----------
A vertex is named by the smallest cell id (integer order, the same as string
order) among the cells around it and the index (0-2) of the vertex among
that cell's corners, as in :func:`dggs.cell_to_boundary`: ``"C400:1"``.
Every cell around a vertex gives the same vertex id; the id is a string
whatever the form of the cell ids.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from dggs.errors import DggsValueError, TooManyCellsError

from ._checks import check_max_cells, check_projection, check_radius, check_size
from ._convert import ROWS, VALUES, Op, apply, format_int, id_name
from ._convert.values import values_out
from ._corners import MAX_FAN, MAX_NEIGHBOURS, all_fans, fans, format_vertex, vertex_keys
from ._kernel import hierarchy as kh
from ._kernel import vertex as kv
from ._shapes import boundaries
from ._vertex_ids import parse_vertexes, vertex_args, vertex_flags

__all__ = [
    "cell_to_vertexes",
    "vertex_to_latlng",
    "vertex_to_cells",
    "vertex_neighbors",
    "grid_disk_vertex",
    "is_valid_vertex",
]


def _vertex_names(ids: np.ndarray) -> np.ndarray:
    owner, index = vertex_keys(ids)
    names = [format_vertex(int(o), int(i)) for o, i in zip(owner.reshape(-1), index.reshape(-1), strict=True)]
    return np.array(names, dtype=str).reshape(ids.shape[0], 3)


def _vertex_neighbours(ids: np.ndarray) -> np.ndarray:
    fan, _ = all_fans(ids)
    out = np.zeros((ids.shape[0], MAX_NEIGHBOURS), dtype=np.uint64)
    for i in range(ids.shape[0]):
        row = np.unique(fan[i])
        row = row[(row != 0) & (row != ids[i])]
        out[i, : row.size] = row
    return out


def _disk_bound(level: int, k: int) -> int:
    """A proven upper bound of the cells within ``k`` corner-sharing steps of a cell at ``level``.

    One corner-sharing step joins two cells of one corner's fan of at most 12 cells, at most
    6 edge steps apart the shorter way around it, so the vertex disk of radius k lies in the
    edge disk of radius 6k (:func:`dggs.index._kernel.grid_tables.disk_size_bound`), and in
    the level (:func:`dggs.index._kernel.vertex.disk_width`).
    """
    return int(kv.disk_width(k, level))


def _disk_vertex(start: int, k: int, bound: int) -> np.ndarray:
    # The C core's breadth-first search (each corner walked once), in a row sized for the disks seen
    # (9 k^2 cells far from icosahedron vertices) and grown up to the proven bound: the bound of the
    # edge disk of radius 6k is 4x the real disk.
    width = min(bound, 10 * (k + 1) ** 2 + 64)
    while True:
        disk = kv.disk_row(start, k, width)
        if disk is not None:
            return disk  # type: ignore[no-any-return]
        if width >= bound:
            raise RuntimeError(f"grid_disk_vertex({id_name(start)!r}, {k}) outgrew its proven bound {bound}")
        width = min(bound, 4 * width)


def _disks_vertex(ids: np.ndarray, k: int, max_cells: int) -> np.ndarray:
    levels = kh.levels(ids) if ids.size else np.zeros(0, dtype=np.int64)
    bounds = {int(lv): _disk_bound(int(lv), k) for lv in np.unique(levels)}
    bound = max(bounds.values(), default=1)
    if bound > max_cells:
        raise TooManyCellsError(
            f"grid_disk_vertex with k={k} may return up to {bound:,} cells per disk, over the limit of "
            f"{max_cells:,} (raise max_cells to allow it)"
        )
    disks = [_disk_vertex(int(c), k, bounds[int(lv)]) for c, lv in zip(ids, levels, strict=True)]
    width = max((d.size for d in disks), default=1)
    check_size(len(disks) * width, max_cells, f"grid_disk_vertex with k={k}")
    out = np.zeros((ids.shape[0], width), dtype=np.uint64)
    for i, d in enumerate(disks):
        out[i, : d.size] = d
    return out


_VERTEXES = Op(many=_vertex_names, out=VALUES)
_VERTEX_NEIGHBOURS = Op(many=_vertex_neighbours, out=ROWS)
_DISK_VERTEX = Op(many=_disks_vertex, out=ROWS)


def cell_to_vertexes(cell: Any) -> Any:
    """The ids of a cell's three corners (vertices), in the order of :func:`dggs.cell_to_boundary`.

    A vertex id is ``"<cell>:<i>"``: the smallest cell id around the vertex
    and the vertex's index among that cell's corners.  All cells that share a
    corner give it the same id.  Vertex ids are strings whatever the form of
    the cell ids.

    Parameters
    ----------
    cell : str, int or array_like of ids
        Cell id(s), any level.

    Returns
    -------
    list of str, or ndarray of str
        For one cell, a list of 3 vertex ids; for an array of cells, a numpy
        string array of shape ``input shape + (3,)``.

    Raises
    ------
    InvalidCellError
        A malformed cell id.

    Examples
    --------
    >>> cell_to_vertexes("C401")
    ['B100:0', 'C401:1', 'C400:1']
    >>> sorted(set(cell_to_vertexes("C401")) & set(cell_to_vertexes("C402")))
    ['C400:1', 'C401:1']
    """
    return apply(_VERTEXES, cell)


def is_valid_vertex(vertex: Any) -> Any:
    """Whether ``vertex`` is a vertex id as :func:`cell_to_vertexes` gives them (never raises).

    Parameters
    ----------
    vertex : str or array_like of str
        One vertex id, or a container of them (as :func:`cell_to_vertexes` gives).

    Returns
    -------
    bool, or the input's kind of container of bool
        One flag per vertex id (a malformed container gives False).

    Examples
    --------
    >>> is_valid_vertex("C400:1"), is_valid_vertex("C401:0"), is_valid_vertex("C401")
    (True, False, False)
    >>> is_valid_vertex(cell_to_vertexes("C401") + ["C401"])
    [True, True, True, False]
    """
    try:
        items, kind = vertex_args(vertex)
    except DggsValueError:
        return False
    flags = vertex_flags(items)
    return values_out(flags, kind)


def vertex_to_latlng(vertex: Any, *, projection: str = "ISEA") -> Any:
    """The (lat, lng) of a vertex, geodetic WGS84 degrees.

    Parameters
    ----------
    vertex : str or array_like of str
        One vertex id, or a container of them (as :func:`cell_to_vertexes` gives).
    projection : {"ISEA", "IVEA"}
        The grid whose corner is given (``dggs.Grid(projection).vertex_to_latlng`` passes it; the vertex
        ids are the same on both).

    Returns
    -------
    tuple of float, or a tuple of two containers
        For one id, ``(lat, lng)``; for a container, ``(lats, lngs)`` in the input's kind of
        container (as :func:`dggs.cell_to_latlng`).

    Raises
    ------
    DggsValueError
        Not a vertex id, or not the canonical name of its corner (in a container, the message
        gives its index).

    Examples
    --------
    >>> lat, lng = vertex_to_latlng("C401:1")
    >>> round(lat, 6), round(lng, 6)
    (20.91287, -1.220765)
    >>> lats, lngs = vertex_to_latlng(cell_to_vertexes("C401"))
    >>> len(lats), round(lats[1], 6)
    (3, 20.91287)
    """
    shapes = boundaries
    if check_projection(projection) == "IVEA":
        from ._ivea_shapes import boundaries as shapes  # IVEA's kernels load on first use
    items, kind = vertex_args(vertex)
    owners, index = parse_vertexes(items, not kind.scalar)
    ring = shapes(owners, 0) if owners.size else np.zeros((0, 3, 2))
    pts = ring[np.arange(owners.size), index] if owners.size else np.zeros((0, 2))
    lat, lng = pts[:, 0].astype(np.float64), pts[:, 1].astype(np.float64)
    if kind.scalar:
        return float(lat[0]), float(lng[0])
    return values_out(lat, kind), values_out(lng, kind)


def vertex_to_cells(vertex: Any) -> Any:
    """The cells that meet at a vertex (4, 5, 6, 10 or 12 of them), sorted string ids.

    Parameters
    ----------
    vertex : str or array_like of str
        One vertex id, or a container of them (as :func:`cell_to_vertexes` gives).

    Returns
    -------
    list of str, or the input's kind of container of rows
        For one id, the sorted list; for a container, shape ``input shape + (12,)``, each row
        sorted and padded with ``""`` (as :func:`vertex_neighbors`).

    Raises
    ------
    DggsValueError
        Not a vertex id, or not the canonical name of its corner (in a container, the message
        gives its index).

    Examples
    --------
    >>> vertex_to_cells("C401:1")
    ['C401', 'C402', 'C411', 'C412']
    >>> vertex_to_cells(["C401:1"])[0][:4]
    ['C401', 'C402', 'C411', 'C412']
    """
    items, kind = vertex_args(vertex)
    owners, index = parse_vertexes(items, not kind.scalar)
    if kind.scalar:
        fan, size = fans(owners, index)
        return sorted(format_int(int(c)) or "" for c in fan[0, : size[0]])
    rows = np.full((owners.size, MAX_FAN), "", dtype=object)
    if owners.size:
        fan, size = fans(owners, index)
        for i in range(owners.size):
            names = sorted(format_int(int(c)) or "" for c in fan[i, : size[i]])
            rows[i, : len(names)] = names
    return values_out(rows.astype(str) if kind.container in ("numpy", "arrow", "polars") else rows, kind, (MAX_FAN,), rows=True)


def vertex_neighbors(cell: Any) -> Any:
    """The cells that share at least one corner with ``cell`` (not itself), sorted.

    Like ``grid_disk(cell, adjacency="vertex")`` in other grids minus the cell.
    A superset of :func:`dggs.edge_neighbors`: 16 cells for most cells (4, 6
    and 12 cells meet at the right-angle, 60-degree and 30-degree corners),
    fewer next to an icosahedron vertex.

    Returns
    -------
    list or array
        For one id, a sorted list of the same form (str or int).  For an
        array, shape ``input shape + (16,)`` of the same kind, rows sorted and
        padded with ``""`` (or 0).

    Raises
    ------
    InvalidCellError
        A malformed id (the message names it).

    Examples
    --------
    >>> import dggs
    >>> len(vertex_neighbors("C40120")), set(dggs.edge_neighbors("C40120")) <= set(vertex_neighbors("C40120"))
    (16, True)
    """
    return apply(_VERTEX_NEIGHBOURS, cell)


def grid_disk_vertex(cell: Any, k: int = 1, max_cells: int | None = None) -> Any:
    """All cells within ``k`` steps of ``cell``, a step joining cells that share a corner, sorted.

    ``grid_disk_vertex(c, 1)`` is ``c`` and its :func:`vertex_neighbors`
    (17 cells for most cells); larger ``k`` grows the disk ring by ring.

    Parameters
    ----------
    cell : str, int or array_like of ids
        Centre cell(s).
    k : int
        Radius in corner-sharing steps (0 gives the cell).
    max_cells : int, optional
        Refuse disks larger than this (default :data:`dggs.index.hierarchy.MAX_CELLS`).

    Returns
    -------
    list or array
        For one id, a sorted list of the same form.  For an array, shape
        ``input shape + (M,)`` of the same kind, M the largest disk, rows
        sorted and padded with ``""`` (or 0).

    Raises
    ------
    InvalidCellError
        A malformed id (the message names it).
    DggsValueError
        ``k`` is not a non-negative integer, or ``max_cells`` is not None or a non-negative integer.
    TooManyCellsError
        A disk would exceed ``max_cells``, or ``k`` is past :data:`dggs.index._checks.K_LIMIT`.
        Refused before any work when a proven bound of the disk (the edge disk of radius
        6k, capped by the cells of the level) exceeds ``max_cells``; the message names k and the bound.

    Examples
    --------
    >>> len(grid_disk_vertex("C40120", 1)), len(grid_disk_vertex("C40120", 0))
    (17, 1)
    >>> len(grid_disk_vertex("C40120", 2))
    52
    """
    return apply(_DISK_VERTEX, cell, check_radius(k, "grid_disk_vertex"), check_max_cells(max_cells))
