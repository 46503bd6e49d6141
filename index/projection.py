"""A grid on either projection: ``dggs.Grid("ISEA")`` (the module-level verbs) or ``dggs.Grid("IVEA")``.

The two grids share everything but the map between each spherical face and
its planar triangle: Snyder's (ISEA, :mod:`dggs.geometry.snyder`) or van
Leeuwen and Strebe's vertex-oriented great circle projection (IVEA,
:mod:`dggs.geometry.ivea`).  Faces, face frames, planar triangles, the Split
(2:6) hierarchy, both id forms, neighbours and cell areas (both maps are
equal-area) are the same, so a :class:`Grid` answers those with the
module-level verbs, and answers location, centres, boundaries and polygons
with the point kernels of its projection (:mod:`dggs.index._kernel.ivea_points`
for IVEA).  The same id names a cell on both grids; its place on the globe
differs by up to 56 km, 0.8 % of a face's edge (docs/grid.md, "The IVEA projection").
"""

from __future__ import annotations

from typing import Any

import numpy as np

from dggs.errors import DggsValueError

from . import _ivea_shapes as ivea_shapes
from ._checks import check_densify, check_level
from ._convert import CELL, VALUE, Op, apply, apply_points, check_points
from ._kernel import ivea_points as ki
from .grid import are_neighbor_cells, edge_neighbors, grid_disk, grid_distance, grid_ring
from .hierarchy import (
    cell_to_center_child,
    cell_to_children,
    cell_to_parent,
    compact_cells,
    get_face,
    get_level,
    is_valid_cell,
    uncompact_cells,
)
from .ids import int_to_str, str_to_int
from .measure import cell_area
from .points import cell_to_boundary, cell_to_latlng, cell_to_polygon, latlng_to_cell
from .polyfill import polygon_to_cells

__all__ = ["Grid", "PROJECTIONS"]

#: The projections a grid can take: Snyder's (the module-level verbs) and the vertex-oriented great circle one.
PROJECTIONS = ("ISEA", "IVEA")


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
    """

    def __init__(self, projection: str = "ISEA") -> None:
        name = projection.upper() if isinstance(projection, str) else projection
        if name not in PROJECTIONS:
            raise DggsValueError(f"projection {projection!r} is not one of {', '.join(PROJECTIONS)}")
        self.projection: str = name

    def __repr__(self) -> str:
        return f"Grid({self.projection!r})"

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Grid) and other.projection == self.projection

    def __hash__(self) -> int:
        return hash(("Grid", self.projection))

    # --- what depends on the projection -------------------------------------------------
    def latlng_to_cell(self, lat: Any, lng: Any, level: int, as_int: bool = False) -> Any:
        """The cell at ``level`` holding each point (geodetic WGS84 degrees); see :func:`dggs.latlng_to_cell`."""
        if self.projection == "ISEA":
            return latlng_to_cell(lat, lng, level, as_int)
        return apply_points(_IVEA_LOCATE_INT if as_int else _IVEA_LOCATE, lat, lng, check_level(level))

    def cell_to_latlng(self, cell: Any) -> Any:
        """Centre (geodetic lat, lng degrees) of each cell; see :func:`dggs.cell_to_latlng`."""
        if self.projection == "ISEA":
            return cell_to_latlng(cell)
        return apply(_IVEA_CENTRE, cell)

    def cell_to_boundary(self, cell: Any, densify: int = 0, max_points: int | None = None) -> Any:
        """Corners (and ``densify`` points an edge) as (lat, lng), counter-clockwise; see :func:`dggs.cell_to_boundary`."""
        if self.projection == "ISEA":
            return cell_to_boundary(cell, densify, max_points)
        return apply(_IVEA_BOUNDARY, cell, check_densify(densify), False, max_points)

    def cell_to_polygon(self, cell: Any, densify: int | None = None, max_points: int | None = None) -> Any:
        """Each cell as a shapely (lng, lat) polygon split at the antimeridian; see :func:`dggs.cell_to_polygon`.

        By default each cell gets the points per edge its own edges' bulge needs for a geodesic area within
        1e-6 of the cell's, as on ISEA.
        """
        if self.projection == "ISEA":
            return cell_to_polygon(cell, densify, max_points)
        return apply(_IVEA_POLYGON, cell, None if densify is None else check_densify(densify), max_points)

    def polygon_to_cells(
        self, polygon: Any, level: int, mode: str = "center", as_int: bool = False, max_cells: int | None = None
    ) -> np.ndarray:
        """Cells at ``level`` in a (lng, lat) polygon by ``mode``; see :func:`dggs.polygon_to_cells`.

        The same compiled descent on either projection, with the centres and cell polygons of this grid.
        """
        return polygon_to_cells(polygon, level, mode, as_int, max_cells, projection=self.projection)

    # --- what does not ---------------------------------------------------------------------
    @staticmethod
    def cell_area(cell_or_level: Any, unit: str = "m^2") -> Any:
        """Cell areas: the same on both projections (both are equal-area); see :func:`dggs.cell_area`."""
        return cell_area(cell_or_level, unit)

    cell_to_parent = staticmethod(cell_to_parent)
    cell_to_children = staticmethod(cell_to_children)
    cell_to_center_child = staticmethod(cell_to_center_child)
    compact_cells = staticmethod(compact_cells)
    uncompact_cells = staticmethod(uncompact_cells)
    get_level = staticmethod(get_level)
    get_face = staticmethod(get_face)
    int_to_str = staticmethod(int_to_str)
    str_to_int = staticmethod(str_to_int)
    is_valid_cell = staticmethod(is_valid_cell)
    edge_neighbors = staticmethod(edge_neighbors)
    grid_disk = staticmethod(grid_disk)
    grid_ring = staticmethod(grid_ring)
    grid_distance = staticmethod(grid_distance)
    are_neighbor_cells = staticmethod(are_neighbor_cells)
