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
"""

from dggs.errors import (
    CoordinateError,
    DggsError,
    DggsValueError,
    InvalidCellError,
    LevelError,
    LevelMismatchError,
    StorageError,
    TooManyCellsError,
)

# Indexing
from dggs.index.ids import MAX_LEVEL, int_to_str, str_to_int
from dggs.index.points import (
    cell_to_boundary,
    cell_to_latlng,
    cell_to_polygon,
    cells_to_geojson,
    latlng_to_cell,
)

# Hierarchy
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

# Traversal
from dggs.index.grid import are_neighbor_cells, edge_neighbors, grid_disk, grid_distance, grid_ring

# Vertices, distances, lines
from dggs.index.vertex import (
    cell_to_vertexes,
    grid_disk_vertex,
    is_valid_vertex,
    vertex_neighbors,
    vertex_to_cells,
    vertex_to_latlng,
)
from dggs.index.lines import cell_centers_distance, geodesic_to_cells, great_circle_distance

# Regions and measures
from dggs.index.polyfill import polygon_to_cells
from dggs.index.measure import cell_area, level_table

__version__ = "0.2.0"

__all__ = [
    # errors
    "DggsError",
    "DggsValueError",
    "CoordinateError",
    "LevelError",
    "LevelMismatchError",
    "InvalidCellError",
    "StorageError",
    "TooManyCellsError",
    # indexing
    "MAX_LEVEL",
    "str_to_int",
    "int_to_str",
    "latlng_to_cell",
    "cell_to_latlng",
    "cell_to_boundary",
    "cell_to_polygon",
    "cells_to_geojson",
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
    # regions and measures
    "polygon_to_cells",
    "cell_area",
    "level_table",
]
