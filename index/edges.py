"""Directed edges: the side a cell shares with each of its three edge neighbours, as an id (h3's directed edges).

The edge from a cell across its side ``d`` (0-2: from corner ``d`` to corner
``d + 1`` of :func:`dggs.cell_to_boundary`, the neighbour in column ``d`` of
:func:`dggs.edge_neighbors`) has two ids, as cells do (docs/grid.md,
"Directed edges"):

* the string ``"C401.2"``: the origin's string id, a dot, the direction;
* the integer ``(1 << 63) | cell | (d + 1) << shift(level + 1)``: the sign bit
  marks an edge, the direction fills the cell's first empty field.  It is
  above 2**63 - 1: edges come back as uint64 (Python ints, numpy, pandas and
  Arrow alike) even for int64 cells, and an int64 column holding them as
  negative numbers (their bits) is read back as well.

Edges of level-28 cells have no id (no field is left empty): they are refused
with a :class:`~dggs.errors.LevelError`.  Every function takes either form in
any container and gives back the same kind.  The kernels are in
:mod:`dggs.index._kernel.edges`, the converters in :mod:`dggs.index._edge_ids`.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from dggs.errors import DggsValueError, LevelError

from ._checks import check_densify, check_projection, is_choice
from ._convert import Entry, cells_in, id_name, is_valid_any, pair, values_out
from ._edge_ids import CELL, CELL_PAIR, EDGE_OUT, VALUE, apply_edge, edges_in, edges_out, to_shadow
from ._kernel import edges as ke
from ._kernel import hierarchy as kh
from ._kernel.bits import MAX_LEVEL

__all__ = [
    "cells_to_directed_edge",
    "directed_edge_to_cells",
    "origin_to_directed_edges",
    "get_directed_edge_origin",
    "get_directed_edge_destination",
    "directed_edge_to_boundary",
    "reverse_directed_edge",
    "is_valid_directed_edge",
    "edge_length",
]

#: Chords per edge for lengths (and twice as many), extrapolated: within 1e-8 of the length.
PIECES = 16
_UNITS = {"m": 1.0, "km": 1e-3}
_ONE_ORIGIN = Entry(ke.one_origin)
_ONE_DESTINATION = Entry(ke.one_destination)
_ONE_ENDS = Entry(ke.one_ends)
_ONE_REVERSE = Entry(ke.one_reverse)
_ONE_LENGTH = Entry(ke.one_length)


def _refuse_level_28(ids: np.ndarray) -> None:
    levels = kh.levels(ids)
    if (levels >= MAX_LEVEL).any():
        i = int(np.flatnonzero(levels >= MAX_LEVEL)[0])
        raise LevelError(f"cell {id_name(ids[i])!r} is at level {MAX_LEVEL}, whose directed edges have no id")


def cells_to_directed_edge(origin: Any, destination: Any) -> Any:
    """The directed edge from ``origin`` to its edge neighbour ``destination`` (element-wise, shapes broadcast).

    Parameters
    ----------
    origin, destination : str, int or any container of ids
        Cells of either form (the answer takes the form and container of the first non-scalar).

    Returns
    -------
    str, int or container
        Edge ids.

    Raises
    ------
    InvalidCellError
        A malformed id.
    LevelError
        A cell at level 28 (its edges have no id).
    DggsValueError
        Two cells that are not edge neighbours (the message names both).

    Examples
    --------
    >>> cells_to_directed_edge("C401", "C402")
    'C401.1'
    >>> cells_to_directed_edge(["C401", "C401"], ["C411", "C400"])
    ['C401.0', 'C401.2']
    """
    a, b, kind = pair(origin, destination)
    _refuse_level_28(a)
    out = np.empty(a.shape[0], dtype=np.uint64)
    ke.pair_edges(a.shape[0], a, b, out)
    if not out.all():
        i = int(np.flatnonzero(out == 0)[0])
        raise DggsValueError(f"cells {id_name(a[i])!r} and {id_name(b[i])!r} are not edge neighbours")
    return edges_out(out, kind)


def origin_to_directed_edges(cell: Any) -> Any:
    """The three directed edges from each cell, in the order of :func:`dggs.edge_neighbors`' columns.

    Returns
    -------
    list or container
        A list of 3 for one cell; ``input shape + (3,)`` for containers.

    Raises
    ------
    InvalidCellError
        A malformed id.
    LevelError
        A cell at level 28.

    Examples
    --------
    >>> origin_to_directed_edges("C401")
    ['C401.0', 'C401.1', 'C401.2']
    """
    ids, kind = cells_in(cell)
    _refuse_level_28(ids)
    out = np.empty((ids.shape[0], 3), dtype=np.uint64)
    ke.origin_edges(ids.shape[0] * 3, ids, out)
    return edges_out(out, kind, (3,))


def _ends_of(ids: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    origin = np.empty(ids.shape[0], dtype=np.uint64)
    dest = np.empty(ids.shape[0], dtype=np.uint64)
    ke.ends(ids.shape[0], ids, origin, dest)
    return origin, dest


def directed_edge_to_cells(edge: Any) -> Any:
    """The origin and destination of each directed edge.

    Returns
    -------
    list or container
        ``[origin, destination]`` for one edge; ``input shape + (2,)`` for containers.

    Raises
    ------
    InvalidCellError
        A malformed edge id (the message names it).

    Examples
    --------
    >>> directed_edge_to_cells("C401.1")
    ['C401', 'C402']
    """
    return apply_edge(lambda ids: np.stack(_ends_of(ids), axis=1), lambda e: _ONE_ENDS.call(e), edge, CELL_PAIR)


def get_directed_edge_origin(edge: Any) -> Any:
    """The cell each directed edge starts from.

    Raises
    ------
    InvalidCellError
        A malformed edge id (the message names it).

    Examples
    --------
    >>> get_directed_edge_origin("C401.1")
    'C401'
    """
    return apply_edge(lambda ids: _ends_of(ids)[0], lambda e: _ONE_ORIGIN.call(e), edge, CELL)


def get_directed_edge_destination(edge: Any) -> Any:
    """The cell each directed edge leads to (its origin's edge neighbour across the edge).

    Raises
    ------
    InvalidCellError
        A malformed edge id (the message names it).

    Examples
    --------
    >>> get_directed_edge_destination("C401.1")
    'C402'
    """
    return apply_edge(lambda ids: _ends_of(ids)[1], lambda e: _ONE_DESTINATION.call(e), edge, CELL)


def reverse_directed_edge(edge: Any) -> Any:
    """The edge from each edge's destination back to its origin.

    Raises
    ------
    InvalidCellError
        A malformed edge id (the message names it).

    Examples
    --------
    >>> reverse_directed_edge("C401.1")
    'C402.1'
    """
    return apply_edge(_reverse, lambda e: _ONE_REVERSE.call(e), edge, EDGE_OUT)


def _reverse(ids: np.ndarray) -> np.ndarray:
    out = np.empty(ids.shape[0], dtype=np.uint64)
    ke.reverse(ids.shape[0], ids, out)
    return out


def is_valid_directed_edge(edge: Any) -> Any:
    """Whether each value is a well-formed directed edge id (either form).  Never raises.

    Examples
    --------
    >>> is_valid_directed_edge("C401.1"), is_valid_directed_edge("C401"), is_valid_directed_edge(["C.2", "C.3"])
    (True, False, [True, False])
    """
    return is_valid_any(to_shadow(edge))


def directed_edge_to_boundary(edge: Any, densify: int = 0, *, projection: str = "ISEA") -> Any:
    """The ends of each directed edge (the origin's corners ``d`` and ``d + 1``) as (lat, lng), ``densify`` between.

    Parameters
    ----------
    edge : str, int or any container of edge ids
        Directed edges of either form.
    densify : int
        Points to add along the (curved) edge; 0 gives its two corners.
    projection : {"ISEA", "IVEA"}
        The grid's projection (``dggs.Grid(projection).directed_edge_to_boundary`` passes it; docs/grid.md).

    Returns
    -------
    tuple or container
        For one edge, a tuple of ``densify + 2`` (lat, lng) tuples; for containers ``input shape + (densify + 2, 2)``.

    Raises
    ------
    InvalidCellError
        A malformed edge id (the message names it).
    DggsValueError
        ``densify`` is not a non-negative integer, or is over the limit.

    Examples
    --------
    >>> [tuple(round(x, 4) for x in p) for p in directed_edge_to_boundary("A.0")]
    [(58.3971, -168.75), (31.8324, -78.75)]
    """
    densify = check_densify(densify)
    kernel = _edge_kernel(check_projection(projection))
    ids, kind = edges_in(edge)
    out = np.empty((ids.shape[0], densify + 2, 2))
    kernel.boundaries(ids.shape[0] * (densify + 1), ids, densify, out)
    return values_out(out, kind, (densify + 2, 2))


def edge_length(edge: Any, unit: str = "m", *, projection: str = "ISEA") -> Any:
    """The length of each directed edge's true curve: on WGS84 (``"m"``, ``"km"``) or on the unit authalic sphere (``"rads"``).

    The edge is a straight segment on its icosahedron face, a curve on the
    globe (Snyder's projection).  Its length is the sum of the chords between
    points along it, cut into 16 and 32 pieces and extrapolated (Richardson):
    within 1e-8 of the length.

    Parameters
    ----------
    edge : str, int or any container of edge ids
        Directed edges of either form.
    unit : {"m", "km", "rads"}
        Metres or kilometres on the ellipsoid, or radians on the authalic sphere.
    projection : {"ISEA", "IVEA"}
        The grid's projection (``dggs.Grid(projection).edge_length`` passes it; docs/grid.md).

    Returns
    -------
    float or container of float

    Raises
    ------
    InvalidCellError
        A malformed edge id (the message names it).
    DggsValueError
        An unknown ``unit``.

    Examples
    --------
    >>> round(edge_length("C401.1", unit="km"), 1)
    726.3
    """
    if not is_choice(unit, ("m", "km", "rads")):
        raise DggsValueError(f"unit {unit!r} must be 'm', 'km' or 'rads'")
    which, scale = (1, 1.0) if unit == "rads" else (0, _UNITS[unit])
    kernel = _edge_kernel(check_projection(projection))
    one = _ONE_LENGTH.call if kernel is ke else lambda e, pieces: kernel.one_length(np.uint64(e), pieces)

    def many(ids: np.ndarray) -> np.ndarray:
        lengths = (np.empty(ids.shape[0]), np.empty(ids.shape[0]))
        kernel.lengths(ids.shape[0] * PIECES, ids, PIECES, *lengths)
        return lengths[which] * scale

    return apply_edge(many, lambda e: one(e, PIECES)[which] * scale, edge, VALUE)


def _edge_kernel(projection: str) -> Any:
    """The compiled edge curves of a projection: :mod:`._kernel.edges`, or its IVEA rebuild (loaded on first use)."""
    if projection == "ISEA":
        return ke
    from ._kernel import ivea_edges

    return ivea_edges

