"""Corners of cells: the cells around each corner (its fan), and vertex ids.

The cells around a corner are found by walking around it: from a cell,
cross one of the two edges that end at the corner, then, in the new cell,
cross the other edge that ends there, until the walk is back.  The corner is
recognised in each cell as the nearest of its three corners (unit vectors of
the kernel's corner coordinates), so the walk follows the grid's own edge
adjacency and needs no tolerance.  Used by :mod:`dggs.index.vertex` and
:mod:`dggs.index.lines`.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from dggs.errors import DggsValueError

from ._convert import id_name, parse_str
from ._kernel import grid as kg
from ._shapes import boundaries

__all__ = ["MAX_FAN", "MAX_NEIGHBOURS", "all_fans", "check_canonical", "fans", "format_vertex", "parse_vertex", "vertex_keys"]

#: Most cells around one corner (a 30-degree corner away from icosahedron vertices).
MAX_FAN = 12
#: Most cells that share a corner with one cell (12 + 6 + 4 around its corners, minus itself
#: three times, minus the 3 edge neighbours counted twice).
MAX_NEIGHBOURS = 16


def corners_xyz(ids: np.ndarray) -> np.ndarray:
    """(N, 3 corners, 3) unit vectors of the cells' corners."""
    b = np.radians(boundaries(ids, 0))
    lat, lng = b[..., 0], b[..., 1]
    return np.stack([np.cos(lat) * np.cos(lng), np.cos(lat) * np.sin(lng), np.sin(lat)], axis=-1)


def neighbours(ids: np.ndarray) -> np.ndarray:
    out = np.empty((ids.shape[0], 3), dtype=np.uint64)
    kg.neighbours(np.ascontiguousarray(ids), out)
    return out


def fans(ids: np.ndarray, corner: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The cells around corner ``corner[i]`` of cell ``ids[i]``, in walking order from it.

    Returns ``(fan, size)``: ``fan`` of shape (N, :data:`MAX_FAN`) padded with 0,
    ``size`` the number of cells around each corner.

    Raises
    ------
    RuntimeError
        A walk around a corner did not close (a broken grid: never for valid ids).
    """
    n = ids.shape[0]
    fan = np.zeros((n, MAX_FAN), dtype=np.uint64)
    size = np.ones(n, dtype=np.int64)
    if n == 0:
        return fan, size
    fan[:, 0] = ids
    v = corners_xyz(ids)[np.arange(n), corner]
    cur = ids.copy()
    edge = corner.astype(np.int64)  # edge i runs from corner i to corner i + 1
    active = np.arange(n)
    for step in range(1, MAX_FAN + 1):
        nxt = neighbours(cur[active])[np.arange(active.size), edge[active]]
        back = nxt == ids[active]
        active, nxt = active[~back], nxt[~back]
        if active.size == 0:
            return fan, size
        if step == MAX_FAN:
            break
        fan[active, step] = nxt
        size[active] += 1
        c = corners_xyz(nxt)
        m = np.argmin(((c - v[active, None, :]) ** 2).sum(axis=-1), axis=1)
        nb = neighbours(nxt)
        rows = np.arange(active.size)
        came_by_m = nb[rows, m] == cur[active]
        edge[active] = np.where(came_by_m, (m + 2) % 3, m)
        cur[active] = nxt
    raise RuntimeError(f"walk around a corner of cell {id_name(ids[active[0]])!r} did not close")


def all_fans(ids: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Fans of the 3 corners of each cell: shapes (N, 3, :data:`MAX_FAN`) and (N, 3)."""
    n = ids.shape[0]
    fan, size = fans(np.repeat(ids, 3), np.tile(np.arange(3), n))
    return fan.reshape(n, 3, MAX_FAN), size.reshape(n, 3)


def vertex_keys(ids: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(owner, index) of each corner of each cell: the smallest cell around it and its corner there."""
    n = ids.shape[0]
    fan, _ = all_fans(ids)
    flat = fan.reshape(n * 3, MAX_FAN)
    owner = np.where(flat == 0, np.uint64(np.iinfo(np.uint64).max), flat).min(axis=1)
    v = corners_xyz(ids).reshape(n * 3, 3)
    c = corners_xyz(owner)
    index = np.argmin(((c - v[:, None, :]) ** 2).sum(axis=-1), axis=1)
    return owner.reshape(n, 3), index.reshape(n, 3)


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
