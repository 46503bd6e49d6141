"""Cell areas and the level table: every cell at a level has the same area."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from dggs.errors import DggsValueError
from dggs.geometry.authalic import WGS84

from ._checks import check_level, is_choice
from ._convert import VALUE, Op, apply, levels_in, values_out
from ._kernel import hierarchy as kh
from ._kernel.bits import MAX_LEVEL

__all__ = ["cell_area", "level_table"]

_UNITS = {"m^2": 1.0, "km^2": 1e-6}


def _num_cells(level: Any) -> np.ndarray:
    return np.where(level == 0, 20.0, 120.0 * 3.0 ** (np.asarray(level, dtype=float) - 1))


def _areas_of_levels(level: np.ndarray, unit: str) -> np.ndarray:
    total = 4 * math.pi if unit == "rads^2" else WGS84.area * _UNITS[unit]
    areas: np.ndarray = total / _num_cells(level)
    return areas


def _areas(ids: np.ndarray, unit: str) -> np.ndarray:
    return _areas_of_levels(kh.levels(ids).astype(np.int64), unit)


_AREA = Op(many=_areas, out=VALUE)


def cell_area(cell_or_level: Any, unit: str = "m^2") -> Any:
    """Area of a cell, or of every cell at a level, on the WGS84 ellipsoid.

    Exactly the ellipsoid's area divided by the number of cells at the level:
    the planar cells are congruent and the projection is equal-area on the
    authalic sphere, which has the ellipsoid's area.

    Parameters
    ----------
    cell_or_level : str, int, or array_like of them
        Cell id(s) (strings or 64-bit integers) or level(s) (integers 0..MAX_LEVEL).
    unit : {"m^2", "km^2", "rads^2"}
        Square metres, square kilometres, or steradians (unit sphere).

    Raises
    ------
    DggsValueError
        An unknown ``unit``.
    LevelError
        A level that is not an integer 0..MAX_LEVEL.
    InvalidCellError
        A malformed id (the message names it).

    Examples
    --------
    >>> round(cell_area(0, "km^2"))
    25503281
    >>> cell_area("C401") == cell_area(3)
    True
    """
    if not is_choice(unit, (*_UNITS, "rads^2")):
        raise DggsValueError(f"unit {unit!r} is not one of m^2, km^2, rads^2")
    levels = levels_in(cell_or_level)
    if levels is not None:
        values, kind = levels
        checked = np.array([check_level(v) for v in values.tolist()], dtype=np.int64)
        return values_out(_areas_of_levels(checked, unit), kind)
    return apply(_AREA, cell_or_level, unit)


def level_table(max_level: int = MAX_LEVEL) -> list[dict[str, Any]]:
    """Cell count, area and edge lengths at each level (for docs and the CLI).

    Edge lengths are those of the planar 30-60-90 cell of the same area
    (short leg, long leg, hypotenuse), a close guide to the curved edges.

    Raises
    ------
    LevelError
        ``max_level`` is not an integer 0..MAX_LEVEL.

    Examples
    --------
    >>> row = level_table(10)[10]
    >>> row["cells"], round(row["area_km2"], 1)
    (2361960, 216.0)
    """
    rows: list[dict[str, Any]] = []
    for level in range(check_level(max_level) + 1):
        area = cell_area(level)
        if level == 0:
            edge = math.sqrt(4 * area / math.sqrt(3))
            legs = (edge, edge, edge)
        else:
            short = math.sqrt(2 * area / math.sqrt(3))
            legs = (short, math.sqrt(3) * short, 2 * short)
        rows.append(
            {
                "level": level,
                "cells": 20 if level == 0 else 120 * 3 ** (level - 1),
                "area_m2": area,
                "area_km2": area * 1e-6,
                "short_edge_m": legs[0],
                "long_edge_m": legs[1],
                "hypotenuse_m": legs[2],
            }
        )
    return rows
