"""A grid on either projection: ``dggs.Grid("ISEA")`` (the module-level verbs) or ``dggs.Grid("IVEA")``.

The two grids share everything but the map between each spherical face and
its planar triangle: Snyder's (ISEA, :mod:`dggs.geometry.snyder`) or van
Leeuwen and Strebe's vertex-oriented great circle projection (IVEA,
:mod:`dggs.geometry.ivea`).  Faces, face frames, planar triangles, the Split
(2:6) hierarchy, both id forms, neighbours and cell areas (both maps are
equal-area) are the same, so a :class:`Grid` answers those with the
module-level verbs (:data:`TOPOLOGICAL`), and answers every verb whose answer
depends on where a cell sits on the globe (:data:`GEOMETRIC`) with the kernels
of its projection: the module-level verb given ``projection="IVEA"``, which runs
the ISEA code compiled again on IVEA's inverse (:mod:`dggs.index._kernel.ivea_points`,
``ivea_fill``, ``ivea_edges``, ``ivea_lines``).  ``Grid("ISEA")``'s methods are the module-level
functions themselves.  :data:`MODULE_ONLY` names the public names that are not
methods.  The same id names a cell on both grids; its place on the globe
differs by up to 56 km, 0.8 % of a face's edge (docs/grid.md, "The IVEA projection").
"""

from __future__ import annotations

from typing import Any

import numpy as np

from dggs.errors import DggsValueError

from . import _ivea_shapes as ivea_shapes
from . import circles, dissolve, edges, grid, hierarchy, ids, lines, local, measure, paths, points, polyfill, vertex
from ._checks import check_densify, check_level, is_choice
from ._convert import CELL, VALUE, Op, apply, apply_points, check_points
from ._densify import DRAW_TOLERANCE, check_tolerance
from ._kernel import ivea_points as ki
from .vertex import vertex_to_latlng as _vertex_to_latlng

__all__ = ["Grid", "PROJECTIONS", "GEOMETRIC", "TOPOLOGICAL", "MODULE_ONLY"]

#: The projections a grid can take: Snyder's (the module-level verbs) and the vertex-oriented great circle one.
PROJECTIONS = ("ISEA", "IVEA")

#: Public verbs whose answer depends on where a cell sits on the globe: a method of each projection
#: (``Grid("ISEA")``'s are the module-level functions themselves, ``Grid("IVEA")``'s answer on IVEA).
GEOMETRIC = {
    "latlng_to_cell": points, "cell_to_latlng": points, "cell_to_boundary": points, "cell_to_polygon": points,
    "cells_to_geojson": points, "cells_to_polygons": dissolve, "polygon_to_cells": polyfill,
    "vertex_to_latlng": vertex, "cell_centers_distance": lines, "geodesic_to_cells": lines,
    "circle_to_cells": circles, "directed_edge_to_boundary": edges, "edge_length": edges, "line_to_cells": paths,
}
#: Public verbs that read ids only (the hierarchy, neighbours, vertex and edge ids, local ij on the unfolded
#: icosahedron, whose corners both projections share), and ``great_circle_distance`` (coordinates only):
#: the module-level functions, the same on both grids (static methods of :class:`Grid`).
TOPOLOGICAL = (
    "int_to_str", "str_to_int", "get_level", "get_face", "is_valid_cell", "cell_to_parent", "cell_to_children",
    "cell_to_center_child", "compact_cells", "uncompact_cells", "get_num_cells", "get_base_cells",
    "edge_neighbors", "are_neighbor_cells", "grid_disk", "grid_ring", "grid_distance", "grid_path_cells",
    "cell_to_child_pos", "child_pos_to_cell", "cell_to_local_ij", "local_ij_to_cell",
    "cells_to_directed_edge", "directed_edge_to_cells", "origin_to_directed_edges", "get_directed_edge_origin",
    "get_directed_edge_destination", "reverse_directed_edge", "is_valid_directed_edge",
    "cell_to_vertexes", "grid_disk_vertex", "is_valid_vertex", "vertex_neighbors", "vertex_to_cells",
    "great_circle_distance", "cell_area",
)
#: Public names that are not verbs of a grid: ``Grid`` itself, the constant ``MAX_LEVEL`` and
#: ``level_table`` (the planar guide of docs and the CLI, the same on both).
MODULE_ONLY = ("Grid", "MAX_LEVEL", "level_table")


def _locate(lat: np.ndarray, lng: np.ndarray, level: int) -> np.ndarray:
    ids = np.empty(lat.shape[0], dtype=np.uint64)
    ki.locate(ids.shape[0], lat, lng, level, ids)
    check_points(lat, lng, ids)
    return ids


def _centres(ids: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    lat, lng = np.empty(ids.shape[0]), np.empty(ids.shape[0])
    ki.centres(ids.shape[0], ids, lat, lng)
    return lat, lng


_IVEA_LOCATE = Op(many=_locate, out=CELL, one=ki.one_point, form="str")
_IVEA_LOCATE_INT = Op(many=_locate, out=CELL, one=ki.one_point, form="int")
_IVEA_CENTRE = Op(many=_centres, out=VALUE, one=ki.centre_of)
_IVEA_BOUNDARY = Op(many=ivea_shapes.boundaries, out=VALUE)
_IVEA_POLYGON = Op(many=ivea_shapes.geometries, out=VALUE)


class Grid:
    """The Split (2:6) grid on one projection: ``Grid("ISEA")`` (the default) or ``Grid("IVEA")``.

    Methods take and give ids and coordinates exactly as the module-level
    functions of the same names do (any container in, the same kind out).
    ``Grid("ISEA")``'s methods *are* the module-level functions.

    Parameters
    ----------
    projection : {"ISEA", "IVEA"}
        Snyder's icosahedral equal-area projection, or the vertex-oriented
        great circle projection of van Leeuwen and Strebe (2006).  Case-insensitive.

    Raises
    ------
    DggsValueError
        Any other projection (the message names it).

    Examples
    --------
    >>> ivea = Grid("IVEA")
    >>> ivea.latlng_to_cell(51.05, -114.07, 9)
    'F200021102'
    >>> cell = ivea.latlng_to_cell(0.5, 0.5, 12)
    >>> cell, Grid().latlng_to_cell(0.5, 0.5, 12)
    ('C310222222022', 'C311222221022')
    >>> ivea.latlng_to_cell(*ivea.cell_to_latlng(cell), 12) == cell
    True
    >>> ivea.cell_area(cell) == Grid("isea").cell_area(cell)  # both equal-area
    True
    >>> round(ivea.edge_length("C401.1", unit="km"), 1), round(Grid().edge_length("C401.1", unit="km"), 1)
    (728.7, 726.3)
    >>> ivea.grid_disk is Grid().grid_disk  # topological verbs: the module-level functions on both
    True
    """

    def __init__(self, projection: str = "ISEA") -> None:
        name = projection.upper() if isinstance(projection, str) else projection
        if not is_choice(name, PROJECTIONS):
            raise DggsValueError(f"projection {projection!r} is not one of {', '.join(PROJECTIONS)}")
        self.projection: str = name
        if name == "ISEA":  # the module-level functions themselves
            for verb, module in GEOMETRIC.items():
                setattr(self, verb, getattr(module, verb))

    def __repr__(self) -> str:
        return f"Grid({self.projection!r})"

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Grid) and other.projection == self.projection

    def __hash__(self) -> int:
        return hash(("Grid", self.projection))


    # --- what depends on the projection: IVEA's here; Grid("ISEA") binds the module-level functions --------
    def latlng_to_cell(self, lat: Any, lng: Any, level: int, as_int: bool = False) -> Any:
        """The cell at ``level`` holding each point (geodetic WGS84 degrees); see :func:`dggs.latlng_to_cell`."""
        return apply_points(_IVEA_LOCATE_INT if as_int else _IVEA_LOCATE, lat, lng, check_level(level))

    def cell_to_latlng(self, cell: Any) -> Any:
        """Centre (geodetic lat, lng degrees) of each cell; see :func:`dggs.cell_to_latlng`."""
        return apply(_IVEA_CENTRE, cell)

    def cell_to_boundary(self, cell: Any, densify: int = 0, max_points: int | None = None) -> Any:
        """Corners (and ``densify`` points an edge) as (lat, lng), counter-clockwise; see :func:`dggs.cell_to_boundary`."""
        return apply(_IVEA_BOUNDARY, cell, check_densify(densify), False, max_points)

    def cell_to_polygon(
        self, cell: Any, densify: int | None = None, max_points: int | None = None, *, tolerance: Any = "exact"
    ) -> Any:
        """Each cell as a shapely (lng, lat) polygon split at the antimeridian; see :func:`dggs.cell_to_polygon`.

        By default each cell gets the points per edge its own edges' bulge needs for a geodesic area within
        1e-6 of the cell's, as on ISEA; ``tolerance`` in metres asks for a distance to the true edge instead.
        """
        check_tolerance(tolerance)
        return apply(_IVEA_POLYGON, cell, None if densify is None else check_densify(densify), max_points, tolerance)

    def cells_to_geojson(
        self, cells: Any, properties: Any = None, densify: int | None = None, max_points: int | None = None,
        *, tolerance: Any = DRAW_TOLERANCE,
    ) -> dict[str, Any]:
        """A GeoJSON FeatureCollection of the cells drawn on this grid; see :func:`dggs.cells_to_geojson`."""
        return points.cells_to_geojson(
            cells, properties, densify, max_points, projection=self.projection, tolerance=tolerance
        )

    def cells_to_polygons(self, cells: Any, densify: int | None = None) -> Any:
        """The outline of a set of cells (the same edges on both grids, drawn on this one); see :func:`dggs.cells_to_polygons`."""
        return dissolve.cells_to_polygons(cells, densify, projection=self.projection)

    def polygon_to_cells(
        self, polygon: Any, level: int, mode: str = "center", as_int: bool = False, max_cells: int | None = None
    ) -> np.ndarray:
        """Cells at ``level`` in a (lng, lat) polygon by ``mode``; see :func:`dggs.polygon_to_cells`.

        The same compiled descent on either projection, with the centres and cell polygons of this grid.
        """
        return polyfill.polygon_to_cells(polygon, level, mode, as_int, max_cells, projection=self.projection)

    def vertex_to_latlng(self, vertex: Any) -> Any:
        """The (lat, lng) of a vertex (or of a container of them): the same vertex ids on both grids, this grid's corner; see :func:`dggs.vertex_to_latlng`."""
        return _vertex_to_latlng(vertex, projection=self.projection)

    def cell_centers_distance(self, a: Any, b: Any, unit: str = "m") -> Any:
        """Distance between this grid's centres of cells ``a`` and ``b``; see :func:`dggs.cell_centers_distance`."""
        return lines.cell_centers_distance(a, b, unit, projection=self.projection)

    def geodesic_to_cells(
        self, lat1: Any, lng1: Any, lat2: Any, lng2: Any, level: int, as_int: bool = False, max_cells: int | None = None
    ) -> np.ndarray:
        """The grid's cells along the WGS84 geodesic between two points, in order; see :func:`dggs.geodesic_to_cells`."""
        return lines.geodesic_to_cells(lat1, lng1, lat2, lng2, level, as_int, max_cells, projection=self.projection)

    def line_to_cells(self, line: Any, level: int, as_int: bool = False, max_cells: int | None = None) -> np.ndarray:
        """The grid's cells along a polyline of WGS84 geodesics, in order; see :func:`dggs.line_to_cells`."""
        return paths.line_to_cells(line, level, as_int, max_cells, projection=self.projection)

    def circle_to_cells(
        self, lat: Any, lng: Any, radius_m: Any, level: int, mode: str = "center", as_int: bool = False,
        max_cells: int | None = None,
    ) -> np.ndarray:
        """The grid's cells within a geodesic distance of a point; see :func:`dggs.circle_to_cells`."""
        return circles.circle_to_cells(lat, lng, radius_m, level, mode, as_int, max_cells, projection=self.projection)

    def directed_edge_to_boundary(self, edge: Any, densify: int = 0) -> Any:
        """The ends (and ``densify`` points between) of each directed edge on this grid; see :func:`dggs.directed_edge_to_boundary`."""
        return edges.directed_edge_to_boundary(edge, densify, projection=self.projection)

    def edge_length(self, edge: Any, unit: str = "m") -> Any:
        """The length of each directed edge's curve on this grid; see :func:`dggs.edge_length`."""
        return edges.edge_length(edge, unit, projection=self.projection)

    # --- what does not: the module-level functions (TOPOLOGICAL) --------------------------------------------
    int_to_str = staticmethod(ids.int_to_str)
    str_to_int = staticmethod(ids.str_to_int)
    get_level = staticmethod(hierarchy.get_level)
    get_face = staticmethod(hierarchy.get_face)
    is_valid_cell = staticmethod(hierarchy.is_valid_cell)
    cell_to_parent = staticmethod(hierarchy.cell_to_parent)
    cell_to_children = staticmethod(hierarchy.cell_to_children)
    cell_to_center_child = staticmethod(hierarchy.cell_to_center_child)
    compact_cells = staticmethod(hierarchy.compact_cells)
    uncompact_cells = staticmethod(hierarchy.uncompact_cells)
    get_num_cells = staticmethod(hierarchy.get_num_cells)
    get_base_cells = staticmethod(hierarchy.get_base_cells)
    edge_neighbors = staticmethod(grid.edge_neighbors)
    are_neighbor_cells = staticmethod(grid.are_neighbor_cells)
    grid_disk = staticmethod(grid.grid_disk)
    grid_ring = staticmethod(grid.grid_ring)
    grid_distance = staticmethod(grid.grid_distance)
    grid_path_cells = staticmethod(paths.grid_path_cells)
    cell_to_child_pos = staticmethod(local.cell_to_child_pos)
    child_pos_to_cell = staticmethod(local.child_pos_to_cell)
    cell_to_local_ij = staticmethod(local.cell_to_local_ij)
    local_ij_to_cell = staticmethod(local.local_ij_to_cell)
    cells_to_directed_edge = staticmethod(edges.cells_to_directed_edge)
    directed_edge_to_cells = staticmethod(edges.directed_edge_to_cells)
    origin_to_directed_edges = staticmethod(edges.origin_to_directed_edges)
    get_directed_edge_origin = staticmethod(edges.get_directed_edge_origin)
    get_directed_edge_destination = staticmethod(edges.get_directed_edge_destination)
    reverse_directed_edge = staticmethod(edges.reverse_directed_edge)
    is_valid_directed_edge = staticmethod(edges.is_valid_directed_edge)
    cell_to_vertexes = staticmethod(vertex.cell_to_vertexes)
    grid_disk_vertex = staticmethod(vertex.grid_disk_vertex)
    is_valid_vertex = staticmethod(vertex.is_valid_vertex)
    vertex_neighbors = staticmethod(vertex.vertex_neighbors)
    vertex_to_cells = staticmethod(vertex.vertex_to_cells)
    great_circle_distance = staticmethod(lines.great_circle_distance)
    cell_area = staticmethod(measure.cell_area)
