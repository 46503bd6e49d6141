"""Typed errors raised by dggs.

Every error raised on bad input is a :class:`DggsValueError`, which is also a
built-in :class:`ValueError`, so ``except ValueError`` keeps working.  Messages
name the offending value and the allowed range.

Examples
--------
>>> import dggs
>>> try:
...     dggs.latlng_to_cell(91.0, 0.0, 5)
... except dggs.CoordinateError as exc:
...     print(exc)
latitude 91.0 at index 0 is out of range -90..90
"""

from __future__ import annotations

__all__ = [
    "DggsError",
    "DggsValueError",
    "CoordinateError",
    "LevelError",
    "LevelMismatchError",
    "InvalidCellError",
    "TooManyCellsError",
    "DistortionError",
    "StorageError",
    "ExtensionLoadError",
]


class DggsError(Exception):
    """Base class of every error raised by dggs."""


class DggsValueError(DggsError, ValueError):
    """Bad input of any kind."""


class CoordinateError(DggsValueError):
    """A coordinate is NaN, infinite, out of range or off its face."""


class LevelError(DggsValueError):
    """A subdivision level is outside ``0..MAX_LEVEL``."""


class LevelMismatchError(DggsValueError):
    """Two levels do not fit together (e.g. a parent finer than its cell)."""


class InvalidCellError(DggsValueError):
    """A string is not a valid cell id."""


class StorageError(DggsError):
    """The SQLite store cannot do what was asked (broken file, bad schema, bad rows)."""


class TooManyCellsError(DggsValueError):
    """An operation would return more cells than its ``max_cells`` limit allows."""


class DistortionError(DggsValueError):
    """The grid bends between two cells, so local (i, j) cannot name one from the other.

    As h3's ``E_PENTAGON`` ("pentagon distortion encountered"); docs/grid.md, "Local coordinates".
    """


class ExtensionLoadError(DggsError, RuntimeError):
    """DuckDB refused to load the native dggs extension (:func:`dggs.duckdb.load`; a RuntimeError as before)."""
