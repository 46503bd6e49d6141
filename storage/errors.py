"""Errors and warnings specific to the storage layer.

:class:`BadRowError` is both a :class:`dggs.StorageError` and a
:class:`dggs.DggsValueError` (hence a :class:`ValueError`): an input row
could not be stored because its content is wrong.
"""

from __future__ import annotations

from dggs.errors import DggsValueError, StorageError

__all__ = ["BadRowError", "RejectedRowsWarning"]


class BadRowError(StorageError, DggsValueError):
    """An input row has a bad value; names the source, line, column and value.

    Attributes
    ----------
    source : str
        The input (file path or stream name).
    row : int
        1-based number of the record in the input (data rows, features, items).
    line : int or None
        1-based line of the file, when known (CSV).
    column : str or None
        The offending column (``None`` for a malformed row).
    value : object
        The offending value.
    reason : str
        What is wrong with it.
    """

    def __init__(
        self,
        source: str,
        row: int,
        line: int | None,
        column: str | None,
        value: object,
        reason: str,
        hint: str = "batches before it are stored; fix the row or use on_error='skip'",
    ) -> None:
        self.source, self.row, self.line = source, row, line
        self.column, self.value, self.reason = column, value, reason
        where = f"line {line}" if line is not None else f"row {row}"
        what = f"column {column!r}: {value!r} {reason}" if column else reason
        super().__init__(
            f"bad input in {source}, {where}: {what} ({hint})"
        )


class RejectedRowsWarning(UserWarning):
    """Rows were skipped by ``on_error="skip"`` (and kept in table ``rejects``)."""
