"""Choice arguments (a unit, a mode, a projection) given as an array raise the typed error naming the argument.

Issue 32 item 12: ``value not in choices`` compares an array element-wise, so numpy raised "the truth
value of an array ... is ambiguous" instead of the verb's :class:`dggs.DggsValueError`.
"""

from __future__ import annotations

import numpy as np
import pytest
import shapely

import dggs

BOX = shapely.box(0.0, 0.0, 1.0, 1.0)
CALLS = {
    "edge_length-unit": (lambda v: dggs.edge_length("C401.1", unit=v), "unit"),
    "cell_area-unit": (lambda v: dggs.cell_area("C401", unit=v), "unit"),
    "great_circle_distance-unit": (lambda v: dggs.great_circle_distance(0.0, 0.0, 1.0, 1.0, unit=v), "unit"),
    "cell_centers_distance-unit": (lambda v: dggs.cell_centers_distance("C401", "C402", unit=v), "unit"),
    "circle_to_cells-mode": (lambda v: dggs.circle_to_cells(0.0, 0.0, 1000.0, 5, mode=v), "mode"),
    "polygon_to_cells-mode": (lambda v: dggs.polygon_to_cells(BOX, 3, mode=v), "mode"),
    "geodesic_to_cells-projection": (lambda v: dggs.geodesic_to_cells(0.0, 0.0, 1.0, 1.0, 3, projection=v), "projection"),
    "Grid-projection": (lambda v: dggs.Grid(v), "projection"),
    "circle_to_cells-projection": (lambda v: dggs.circle_to_cells(0.0, 0.0, 1000.0, 5, projection=v), "projection"),
}


@pytest.mark.parametrize("value", [np.array(["km"]), np.array(["m", "km"]), ["km"], np.array([1.0])], ids=repr)
@pytest.mark.parametrize("name", list(CALLS))
def test_array_valued_choice_is_a_typed_error_naming_the_argument(name, value):
    call, arg = CALLS[name]
    with pytest.raises(dggs.DggsValueError, match=arg):
        call(value)
