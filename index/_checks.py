"""Argument checks shared by the verbs: levels, radii, limits, densify.

Each check returns the argument as a plain ``int`` or raises the
:class:`~dggs.errors.DggsValueError` subclass that names the bad value; the
verbs call them before any work, on every path.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from functools import partial
from typing import Any

import numpy as np

from dggs.errors import DggsValueError, LevelError, TooManyCellsError

from ._kernel.bits import MAX_LEVEL
from ._kernel.scalar import plain_level

__all__ = ["MAX_CELLS", "MAX_POINTS", "K_LIMIT", "check_point_count", "check_densify", "check_k", "check_level", "check_max_cells", "check_radius", "check_size", "property_rows",
           "check_projection", "is_choice"]

#: Default limit on the cells one call may return (400 MB of integer ids).
MAX_CELLS = 50_000_000
#: Largest ``k`` (and ``max_steps``) the kernels take; a disk of this radius covers the globe at every level.
K_LIMIT = 1 << 31
_INT64_MAX = (1 << 63) - 1
#: Default limit on the boundary points one call may build (800 MB of float64 pairs; more with shapely's copies).
MAX_POINTS = 50_000_000
#: Most points a caller may ask for along one edge.
DENSIFY_LIMIT = 100_000


def _is_int(value: Any) -> bool:
    return isinstance(value, (int, np.integer)) and not isinstance(value, (bool, np.bool_))


def _check_level(level: Any, name: str = "level") -> int:
    """Return ``level`` as an int, or raise :class:`LevelError` naming it (:func:`check_level`'s whole check).

    Python and numpy integers are accepted; bools, floats and strings are not.

    Raises
    ------
    LevelError
        Not an integer, or outside 0..MAX_LEVEL.

    Examples
    --------
    >>> check_level(np.int64(5))
    5
    """
    if type(level) is int and 0 <= level <= MAX_LEVEL:  # the common case, first
        return level
    if not _is_int(level):
        raise LevelError(f"{name} {level!r} must be an integer 0..{MAX_LEVEL}")
    if not 0 <= level <= MAX_LEVEL:
        raise LevelError(f"{name} {level!r} is out of range 0..{MAX_LEVEL}")
    return int(level)


#: Return ``level`` as an int, or raise :class:`LevelError` naming it: a plain int 0..MAX_LEVEL in one C call
#: (the verbs' common case), anything else through :func:`_check_level`.
check_level: Callable[..., int] = partial(plain_level, _check_level)
check_level.__doc__ = _check_level.__doc__


def check_max_cells(max_cells: Any) -> int:
    """``max_cells`` as an int (:data:`MAX_CELLS` for None).

    Raises
    ------
    DggsValueError
        Not a non-negative integer or None.
    """
    if max_cells is None:
        return MAX_CELLS
    if type(max_cells) is int and 0 <= max_cells <= _INT64_MAX:
        return max_cells
    if not _is_int(max_cells) or max_cells < 0:
        raise DggsValueError(f"max_cells {max_cells!r} must be a non-negative integer (or None for {MAX_CELLS:,})")
    return min(int(max_cells), _INT64_MAX)  # more than any call can return: no limit, in a kernel's integer


def check_size(total: int, max_cells: Any, what: str) -> None:
    """Refuse, before allocating, to return more than ``max_cells`` cells.

    Raises
    ------
    TooManyCellsError
        ``total`` is over the limit (the message names both).
    DggsValueError
        ``max_cells`` is not a non-negative integer or None.
    """
    limit = check_max_cells(max_cells)
    if total > limit:
        raise TooManyCellsError(
            f"{what} would return {total:,} cells, over the limit of {limit:,} (raise max_cells to allow it)"
        )


def check_point_count(cells: int, per_cell: int, max_points: Any) -> None:
    """Refuse, before allocating, to build more than ``max_points`` boundary points.

    Raises
    ------
    TooManyCellsError
        ``cells * per_cell`` is over the limit (the message names the cells, the points and the limit).
    DggsValueError
        ``max_points`` is not a non-negative integer or None.
    """
    if max_points is None:
        limit = MAX_POINTS
    elif not _is_int(max_points) or max_points < 0:
        raise DggsValueError(f"max_points {max_points!r} must be a non-negative integer (or None for {MAX_POINTS:,})")
    else:
        limit = int(max_points)
    if cells * per_cell > limit:
        raise TooManyCellsError(
            f"{cells:,} cells of {per_cell:,} boundary points would make {cells * per_cell:,} points, "
            f"over the limit of {limit:,} (lower densify, or raise max_points to allow it)"
        )


def check_k(k: Any, name: str = "k") -> int:
    """A non-negative integer step count, as an int.

    Raises
    ------
    DggsValueError
        Not a non-negative integer.
    """
    if type(k) is int and k >= 0:
        return k
    if not _is_int(k) or k < 0:
        raise DggsValueError(f"{name} {k!r} must be a non-negative integer")
    return int(k)


def check_radius(k: Any, what: str) -> int:
    """A disk or ring radius, as an int.

    Raises
    ------
    DggsValueError
        Not a non-negative integer.
    TooManyCellsError
        Past :data:`K_LIMIT`, where a disk would hold more cells than any level has.
    """
    radius = check_k(k)
    if radius > K_LIMIT:
        raise TooManyCellsError(f"{what} with k={radius} would return more cells than the grid has at any level")
    return radius


def check_densify(densify: Any) -> int:
    """Points to add along each edge, as an int.

    Raises
    ------
    DggsValueError
        Not a non-negative integer, or over :data:`DENSIFY_LIMIT`.
    """
    if not _is_int(densify) or densify < 0:
        raise DggsValueError(f"densify {densify!r} must be a non-negative integer")
    if densify > DENSIFY_LIMIT:
        raise DggsValueError(f"densify {densify!r} is over the limit of {DENSIFY_LIMIT} points per edge")
    return int(densify)


def property_rows(properties: Any, n: int) -> Iterator[dict[str, Any]]:
    """One dict of plain (JSON-ready) values per cell from columns or rows of properties.

    Raises
    ------
    DggsValueError
        ``properties`` are neither a dict of columns nor a sequence of dicts, or
        do not give one value (row) per cell.
    """
    if properties is None:
        return ({} for _ in range(n))
    if isinstance(properties, dict):
        bad = [k for k, v in properties.items() if isinstance(v, (str, bytes)) or not hasattr(v, "__len__")]
        if bad:
            raise DggsValueError(f"property {bad[0]!r} must be a column (a sequence of {n} values), not {properties[bad[0]]!r}")
        cols = {k: list(v) for k, v in properties.items()}
        for k, col in cols.items():
            if len(col) != n:
                raise DggsValueError(f"property {k!r} has {len(col)} values for {n} cells")
        return ({k: _plain(col[i]) for k, col in cols.items()} for i in range(n))
    if isinstance(properties, (str, bytes)) or not hasattr(properties, "__iter__"):
        raise DggsValueError(f"properties must be a dict of columns or a list of dicts, not {properties!r}")
    listed = list(properties)
    if len(listed) != n:
        raise DggsValueError(f"properties has {len(listed)} rows for {n} cells")
    odd = next((r for r in listed if not hasattr(r, "keys")), None)
    if odd is not None:
        raise DggsValueError(f"properties rows must be dicts, not {odd!r}")
    return ({k: _plain(v) for k, v in dict(r).items()} for r in listed)


def _plain(v: Any) -> Any:
    """Numpy scalars -> Python scalars, for JSON."""
    return v.item() if isinstance(v, np.generic) else v


def is_choice(value: Any, choices: Any) -> bool:
    """Whether ``value`` is one of the string ``choices`` (a unit, a mode); never raises.

    An array, list or other unhashable or array-like value is no choice (``value in choices``
    would compare it element-wise, and numpy then raises "truth value ... is ambiguous"), so
    the verb raises its own typed error naming the argument.

    Examples
    --------
    >>> is_choice("km", ("m", "km")), is_choice(np.array(["km"]), ("m", "km"))
    (True, False)
    """
    return isinstance(value, str) and value in choices


def check_projection(projection: Any) -> str:
    """``projection`` (a verb's keyword, which :class:`dggs.Grid` passes) as ``"ISEA"`` or ``"IVEA"``.

    Raises
    ------
    DggsValueError
        Any other value (the message names it).
    """
    if not is_choice(projection, ("ISEA", "IVEA")):
        raise DggsValueError(f"projection {projection!r} is not one of ISEA, IVEA")
    return str(projection)
