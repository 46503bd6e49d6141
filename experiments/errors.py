"""Errors raised by the experiments on bad input (all are :class:`dggs.errors.DggsValueError`)."""

from __future__ import annotations

from dggs.errors import DggsValueError, LevelError

__all__ = ["UnknownSchemeError", "ExperimentLevelError", "UnknownShapeError"]


class UnknownSchemeError(DggsValueError):
    """A subdivision scheme name is not one of the thesis's seven (plus ``dggs``)."""


class ExperimentLevelError(LevelError):
    """A number of levels is negative or too large to fit in memory."""


class UnknownShapeError(DggsValueError):
    """A curve shape name is not known."""
