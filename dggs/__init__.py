"""dggs: an equal-area triangular discrete global grid.

Split (2:6) subdivision of the icosahedron (thesis "Equal Area Spherical
Subdivision", §6.1.7) mapped to the globe by Snyder's equal-area polyhedral
projection on the WGS84 authalic sphere: every cell at a level has exactly
the same area on the ellipsoid.

Coordinates are (lat, lng) in degrees, geodetic WGS84, as in h3; GeoJSON and
shapely output is (lng, lat).  Cell ids are strings (``"C401"``: a face
letter, a level-1 digit 0-5, one digit 0-2 per further level) or 64-bit
integers with the same order; every function takes either, in any container,
and gives back the kind it was given.

Examples
--------
>>> import dggs
>>> cell = dggs.latlng_to_cell(51.05, -114.07, 9)
>>> dggs.get_level(cell), dggs.cell_to_parent(cell) == cell[:-1]
(9, True)

The names are loaded on first use (PEP 562): ``import dggs`` reads only this
file and :mod:`dggs.errors`, and the first call of, say,
``dggs.latlng_to_cell`` imports :mod:`dggs.index.points` (and with it numba
and the compiled kernel).  Subpackages (``dggs.index``, ``dggs.storage``,
``dggs.geometry``, ...) load the same way on first attribute access.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

from dggs.errors import (
    CoordinateError,
    DggsError,
    DggsValueError,
    DistortionError,
    ExtensionLoadError,
    InvalidCellError,
    LevelError,
    LevelMismatchError,
    StorageError,
    TooManyCellsError,
)

__version__ = "0.3.0"


def _check_layout() -> None:
    """Raise a clear ImportError when ``dggs.index`` cannot be found (the source tree imported as it is).

    ``dggs.index`` and ``dggs.storage`` are the folders ``index/`` and ``storage/`` beside ``dggs/``,
    mapped into the package by ``[tool.setuptools.package-dir]`` in pyproject.toml; only an install
    (a wheel or ``pip install -e .``) applies that mapping.  Python run in the repository root finds the
    bare ``dggs/`` folder first and would fail later with ``No module named 'dggs.index'``.

    Raises
    ------
    ImportError
        If ``dggs.index`` is not importable, naming the folder ``dggs`` was imported from.
    """
    import importlib.util
    import os

    if importlib.util.find_spec("dggs.index") is None:
        here = os.path.dirname(os.path.abspath(__file__))
        raise ImportError(
            f"dggs was imported from the source folder {here}, which shadows the installed package: "
            "its dggs.index and dggs.storage are the folders index/ and storage/ beside it, joined only "
            "by an install; run Python from another folder, or install this tree with pip install -e ."
        )


_check_layout()

#: Public name -> the module that defines it, imported on first access.
#: The one table to update when a module moves.
_LAZY: dict[str, str] = {
    # indexing
    "MAX_LEVEL": "dggs.index.ids",
    "int_to_str": "dggs.index.ids",
    "str_to_int": "dggs.index.ids",
    "cell_to_boundary": "dggs.index.points",
    "cell_to_latlng": "dggs.index.points",
    "cell_to_polygon": "dggs.index.points",
    "cells_to_geojson": "dggs.index.points",
    "latlng_to_cell": "dggs.index.points",
    "cells_to_polygons": "dggs.index.dissolve",
    # hierarchy
    "cell_to_center_child": "dggs.index.hierarchy",
    "cell_to_children": "dggs.index.hierarchy",
    "cell_to_parent": "dggs.index.hierarchy",
    "compact_cells": "dggs.index.hierarchy",
    "get_base_cells": "dggs.index.hierarchy",
    "get_face": "dggs.index.hierarchy",
    "get_level": "dggs.index.hierarchy",
    "get_num_cells": "dggs.index.hierarchy",
    "is_valid_cell": "dggs.index.hierarchy",
    "uncompact_cells": "dggs.index.hierarchy",
    # traversal
    "are_neighbor_cells": "dggs.index.grid",
    "edge_neighbors": "dggs.index.grid",
    "grid_disk": "dggs.index.grid",
    "grid_distance": "dggs.index.grid",
    "grid_ring": "dggs.index.grid",
    # positions and directed edges
    "cell_to_child_pos": "dggs.index.local",
    "child_pos_to_cell": "dggs.index.local",
    "cell_to_local_ij": "dggs.index.local",
    "local_ij_to_cell": "dggs.index.local",
    "cells_to_directed_edge": "dggs.index.edges",
    "directed_edge_to_cells": "dggs.index.edges",
    "origin_to_directed_edges": "dggs.index.edges",
    "get_directed_edge_origin": "dggs.index.edges",
    "get_directed_edge_destination": "dggs.index.edges",
    "directed_edge_to_boundary": "dggs.index.edges",
    "reverse_directed_edge": "dggs.index.edges",
    "is_valid_directed_edge": "dggs.index.edges",
    "edge_length": "dggs.index.edges",
    # vertices, distances, lines
    "cell_to_vertexes": "dggs.index.vertex",
    "grid_disk_vertex": "dggs.index.vertex",
    "is_valid_vertex": "dggs.index.vertex",
    "vertex_neighbors": "dggs.index.vertex",
    "vertex_to_cells": "dggs.index.vertex",
    "vertex_to_latlng": "dggs.index.vertex",
    "cell_centers_distance": "dggs.index.lines",
    "geodesic_to_cells": "dggs.index.lines",
    "great_circle_distance": "dggs.index.lines",
    "grid_path_cells": "dggs.index.paths",
    "line_to_cells": "dggs.index.paths",
    "circle_to_cells": "dggs.index.circles",
    # regions and measures
    "polygon_to_cells": "dggs.index.polyfill",
    "Grid": "dggs.index.projection",
    "cell_area": "dggs.index.measure",
    "level_table": "dggs.index.measure",
}

#: Subpackages and modules reachable as attributes after a bare ``import dggs`` (``dggs.index.points``...).
_SUBMODULES = frozenset(
    {
        "arrow",
        "cell_cli",
        "cli",
        "dask",
        "duckdb",
        "experiments",
        "geometry",
        "index",
        "pandas",
        "server",
        "spark",
        "storage",
        "xdggs",
    }
)

__all__ = [
    # errors
    "DggsError",
    "DggsValueError",
    "CoordinateError",
    "LevelError",
    "LevelMismatchError",
    "InvalidCellError",
    "StorageError",
    "ExtensionLoadError",
    "TooManyCellsError",
    "DistortionError",
    # indexing
    "MAX_LEVEL",
    "str_to_int",
    "int_to_str",
    "latlng_to_cell",
    "cell_to_latlng",
    "cell_to_boundary",
    "cell_to_polygon",
    "cells_to_geojson",
    "cells_to_polygons",
    # hierarchy
    "get_level",
    "get_face",
    "is_valid_cell",
    "cell_to_parent",
    "cell_to_children",
    "cell_to_center_child",
    "compact_cells",
    "uncompact_cells",
    "get_num_cells",
    "get_base_cells",
    # traversal
    "edge_neighbors",
    "are_neighbor_cells",
    "grid_disk",
    "grid_ring",
    "grid_distance",
    # positions and directed edges
    "cell_to_child_pos",
    "child_pos_to_cell",
    "cell_to_local_ij",
    "local_ij_to_cell",
    "cells_to_directed_edge",
    "directed_edge_to_cells",
    "origin_to_directed_edges",
    "get_directed_edge_origin",
    "get_directed_edge_destination",
    "directed_edge_to_boundary",
    "reverse_directed_edge",
    "is_valid_directed_edge",
    "edge_length",
    # vertices, distances, lines
    "cell_to_vertexes",
    "vertex_to_latlng",
    "vertex_to_cells",
    "is_valid_vertex",
    "vertex_neighbors",
    "grid_disk_vertex",
    "great_circle_distance",
    "cell_centers_distance",
    "geodesic_to_cells",
    "grid_path_cells",
    "line_to_cells",
    "circle_to_cells",
    # regions and measures
    "polygon_to_cells",
    "Grid",
    "cell_area",
    "level_table",
]


def __getattr__(name: str) -> Any:
    """Import a public name or a submodule on first access (PEP 562).

    Parameters
    ----------
    name : str
        An attribute of :mod:`dggs`.

    Returns
    -------
    object
        The function, constant or module; cached in the module's namespace.

    Raises
    ------
    AttributeError
        ``name`` is neither a public name nor a submodule.
    """
    if name in _LAZY:
        value = getattr(importlib.import_module(_LAZY[name]), name)
    elif name in _SUBMODULES:
        value = importlib.import_module(f"{__name__}.{name}")
        # the modules of the name table inside it, as the eager face loaded them (dggs.index.points...)
        for module in sorted(set(_LAZY.values())):
            if module.startswith(f"{__name__}.{name}."):
                importlib.import_module(module)
    else:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    """The module's names, the lazy ones included."""
    return sorted(set(globals()) | set(__all__) | _SUBMODULES)


if TYPE_CHECKING:  # what the name table loads, for type checkers and IDEs
    from dggs.index.circles import circle_to_cells
    from dggs.index.dissolve import cells_to_polygons
    from dggs.index.edges import (
        cells_to_directed_edge,
        directed_edge_to_boundary,
        directed_edge_to_cells,
        edge_length,
        get_directed_edge_destination,
        get_directed_edge_origin,
        is_valid_directed_edge,
        origin_to_directed_edges,
        reverse_directed_edge,
    )
    from dggs.index.grid import are_neighbor_cells, edge_neighbors, grid_disk, grid_distance, grid_ring
    from dggs.index.hierarchy import (
        cell_to_center_child,
        cell_to_children,
        cell_to_parent,
        compact_cells,
        get_base_cells,
        get_face,
        get_level,
        get_num_cells,
        is_valid_cell,
        uncompact_cells,
    )
    from dggs.index.ids import MAX_LEVEL, int_to_str, str_to_int
    from dggs.index.lines import cell_centers_distance, geodesic_to_cells, great_circle_distance
    from dggs.index.local import cell_to_child_pos, cell_to_local_ij, child_pos_to_cell, local_ij_to_cell
    from dggs.index.measure import cell_area, level_table
    from dggs.index.paths import grid_path_cells, line_to_cells
    from dggs.index.points import (
        cell_to_boundary,
        cell_to_latlng,
        cell_to_polygon,
        cells_to_geojson,
        latlng_to_cell,
    )
    from dggs.index.polyfill import polygon_to_cells
    from dggs.index.projection import Grid
    from dggs.index.vertex import (
        cell_to_vertexes,
        grid_disk_vertex,
        is_valid_vertex,
        vertex_neighbors,
        vertex_to_cells,
        vertex_to_latlng,
    )
