"""Corners of cells: the cells around each corner (its fan), and vertex ids.

The cells around a corner are found by walking around it: from a cell,
cross the edge that starts at the corner, then, in the new cell, the other
edge that ends there, until the walk is back.  Both cells' corners run
counter-clockwise, so the corner is the far end of the edge back: the walk
follows the grid's own edge adjacency alone, in the C core
(libdggs/src/vertex.c), with no projection and no tolerance.  Used by :mod:`dggs.index.vertex` and
:mod:`dggs.index.lines`.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from dggs.errors import DggsValueError

from ._convert import id_name, parse_str
from ._kernel import vertex as kv

__all__ = ["MAX_FAN", "MAX_NEIGHBOURS", "all_fans", "check_canonical", "fans", "format_vertex", "parse_vertex", "vertex_keys"]

#: Most cells around one corner (a 30-degree corner away from icosahedron vertices).
MAX_FAN = int(kv.MAX_FAN)
#: Most cells that share a corner with one cell (12 + 6 + 4 around its corners, minus itself
#: three times, minus the 3 edge neighbours counted twice).
MAX_NEIGHBOURS = 16


def fans_with_corners(ids: np.ndarray, corner: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The cells around corner ``corner[i]`` of cell ``ids[i]``, in walking order, and the corner's index in each.

    Returns ``(fan, corners, size)``: ``fan`` and ``corners`` of shape (N, :data:`MAX_FAN`) padded with 0,
    ``size`` the number of cells around each corner (the C core's walk, :mod:`dggs.index._kernel.vertex`).

    Raises
    ------
    RuntimeError
        A walk around a corner did not close (a broken grid: never for valid ids).
    """
    n = ids.shape[0]
    fan = np.zeros((n, MAX_FAN), dtype=np.uint64)
    corners = np.zeros((n, MAX_FAN), dtype=np.int64)
    size = np.ones(n, dtype=np.int64)
    if n == 0:
        return fan, corners, size
    bad = kv.fans(
        np.ascontiguousarray(ids, dtype=np.uint64), np.ascontiguousarray(corner, dtype=np.int64), fan, corners, size
    )
    if bad >= 0:
        raise RuntimeError(f"walk around a corner of cell {id_name(ids[bad])!r} did not close")
    return fan, corners, size


def fans(ids: np.ndarray, corner: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The cells around corner ``corner[i]`` of cell ``ids[i]``, in walking order from it.

    Returns ``(fan, size)``: ``fan`` of shape (N, :data:`MAX_FAN`) padded with 0,
    ``size`` the number of cells around each corner.

    Raises
    ------
    RuntimeError
        A walk around a corner did not close (a broken grid: never for valid ids).
    """
    fan, _, size = fans_with_corners(ids, corner)
    return fan, size


def all_fans(ids: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Fans of the 3 corners of each cell: shapes (N, 3, :data:`MAX_FAN`) and (N, 3)."""
    n = ids.shape[0]
    fan, size = fans(np.repeat(ids, 3), np.tile(np.arange(3), n))
    return fan.reshape(n, 3, MAX_FAN), size.reshape(n, 3)


def vertex_keys(ids: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(owner, index) of each corner of each cell: the smallest cell around it and its corner there."""
    n = ids.shape[0]
    fan, corners, _ = fans_with_corners(np.repeat(ids, 3), np.tile(np.arange(3), n))
    at = np.where(fan == 0, np.uint64(np.iinfo(np.uint64).max), fan).argmin(axis=1)
    rows = np.arange(n * 3)
    return fan[rows, at].reshape(n, 3), corners[rows, at].reshape(n, 3)


def format_vertex(owner: int, index: int) -> str:
    return f"{id_name(owner)}:{index}"


def parse_vertex(vertex: Any) -> tuple[int, int]:
    """(owner cell id, corner index) of a vertex id, or :class:`DggsValueError` naming it.

    Raises
    ------
    DggsValueError
        ``vertex`` is not of the form ``'<cell>:<0-2>'``.
    """
    if isinstance(vertex, str) and vertex.count(":") == 1:
        cell, _, idx = vertex.partition(":")
        owner = parse_str(cell)
        if owner and idx in ("0", "1", "2"):
            return owner, int(idx)
    raise DggsValueError(f"{vertex!r} is not a vertex id (expected '<cell>:<0-2>', e.g. 'C401:1')")


def check_canonical(vertex: Any, owner: int, index: int) -> None:
    """Refuse a vertex id that is not the canonical name of its corner.

    Raises
    ------
    DggsValueError
        The corner has another name (the smallest cell around it names it).
    """
    o, i = vertex_keys(np.array([owner], dtype=np.uint64))
    if int(o[0, index]) != owner or int(i[0, index]) != index:
        raise DggsValueError(
            f"{vertex!r} is not a vertex id: that corner is named {format_vertex(int(o[0, index]), int(i[0, index]))!r}"
        )
