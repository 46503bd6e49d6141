"""Warming the grid kernels before ``dggs serve`` listens (numba compiles or loads each on its first call)."""

from __future__ import annotations

import numpy as np

import dggs

from .reader import map_densify

__all__ = ["warm_kernels"]


def warm_kernels() -> None:
    """Run once each grid kernel the server calls, so that the first request does not wait for it.

    numba compiles a kernel on its first call in a fresh installation (2-7 s each) and caches it on
    disk; later processes load it in milliseconds.  ``dggs serve`` calls this before it listens.

    Examples
    --------
    >>> warm_kernels()
    """
    import shapely

    ids = np.array(["A0", "C4012", "E", "R", "E0"])  # E and R have a pole on an edge: their own ring builder
    many = np.asarray(dggs.uncompact_cells(["A"], 8))  # 13,122 cells: above the threshold of the threaded kernels
    for grid in (dggs.Grid("ISEA"), dggs.Grid("IVEA")):  # both DGGRS draw zones (dggrs.py)
        for cells in (ids, many):
            grid.cell_to_latlng(cells)
            for densify in sorted({map_densify(level) for level in range(dggs.MAX_LEVEL + 1)}):
                shapely.to_geojson(grid.cell_to_polygon(cells, densify=densify))
        grid.cell_to_latlng("A0")
        grid.cell_to_polygon("A0")
    dggs.cell_to_children("A0")
    dggs.cell_to_children("A0", 3)
    dggs.edge_neighbors("A0")
    dggs.cell_to_parent("C4012", 1)
    dggs.compact_cells(dggs.cell_to_children("A0", 2))
    dggs.uncompact_cells(["A0"], 2)
    dggs.str_to_int("A0")
