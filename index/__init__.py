"""Cell addressing: ids, point-to-cell, boundaries, hierarchy, neighbours, polyfill."""

from .cellid import MAX_LEVEL
from .points import cell_to_boundary, cell_to_latlng, cell_to_polygon, cells_to_geojson, latlng_to_cell

__all__ = [
    "MAX_LEVEL",
    "latlng_to_cell",
    "cell_to_latlng",
    "cell_to_boundary",
    "cell_to_polygon",
    "cells_to_geojson",
]
