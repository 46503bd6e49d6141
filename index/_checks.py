"""Argument checks shared by the verbs: levels, radii, limits, densify.

Each check returns the argument as a plain ``int`` or raises the
:class:`~dggs.errors.DggsValueError` subclass that names the bad value; the
verbs call them before any work, on every path.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from dggs.errors import DggsValueError, LevelError, TooManyCellsError

from ._kernel.bits import MAX_LEVEL

__all__ = ["MAX_CELLS", "K_LIMIT", "check_densify", "check_k", "check_level", "check_max_cells", "check_radius", "check_size", "is_level_input"]

#: Default limit on the cells one call may return (400 MB of integer ids).
MAX_CELLS = 50_000_000
#: Largest ``k`` (and ``max_steps``) the kernels take; a disk of this radius covers the globe at every level.
K_LIMIT = 1 << 31
#: Most points a caller may ask for along one edge.
DENSIFY_LIMIT = 100_000


def _is_int(value: Any) -> bool:
    return isinstance(value, (int, np.integer)) and not isinstance(value, (bool, np.bool_))


def check_level(level: Any, name: str = "level") -> int:
    """Return ``level`` as an int, or raise :class:`LevelError` naming it.

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
    if not _is_int(level):
        raise LevelError(f"{name} {level!r} must be an integer 0..{MAX_LEVEL}")
    if not 0 <= level <= MAX_LEVEL:
        raise LevelError(f"{name} {level!r} is out of range 0..{MAX_LEVEL}")
    return int(level)


def check_max_cells(max_cells: Any) -> int:
    """``max_cells`` as an int (:data:`MAX_CELLS` for None).

    Raises
    ------
    DggsValueError
        Not a non-negative integer or None.
    """
    if max_cells is None:
        return MAX_CELLS
    if not _is_int(max_cells) or max_cells < 0:
        raise DggsValueError(f"max_cells {max_cells!r} must be a non-negative integer (or None for {MAX_CELLS:,})")
    return int(max_cells)


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


def check_k(k: Any, name: str = "k") -> int:
    """A non-negative integer step count, as an int.

    Raises
    ------
    DggsValueError
        Not a non-negative integer.
    """
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
    k = check_k(k)
    if k > K_LIMIT:
        raise TooManyCellsError(f"{what} with k={k} would return more cells than the grid has at any level")
    return k


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


def is_level_input(value: Any) -> bool:
    """Small integers are levels; strings, ids (>= 2**62) and containers of them are cells."""
    if isinstance(value, (bool, np.bool_)):
        return True  # check_level refuses it with a LevelError
    if isinstance(value, (int, np.integer)):
        return int(value) < 2**62
    if isinstance(value, np.ndarray) and value.dtype.kind in "iu":
        return bool(value.size) and int(value.max()) < 2**62
    if isinstance(value, (list, tuple)) and len(value):
        try:
            items = np.asarray(value, dtype=object).ravel()
        except ValueError:  # ragged: judged (and refused) as cells
            return False
        if items.size and all(isinstance(v, (int, np.integer)) and not isinstance(v, bool) for v in items):
            return int(max(items)) < 2**62
    return False
