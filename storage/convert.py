"""Convert and check one batch of raw input: types, coordinates, cells.

:func:`prepare` turns a :class:`~dggs.storage.readers.RawBatch` into rows
ready to insert and a list of rejects.  Integers stay exact: a column of
SQL type ``INTEGER`` keeps Python ints (SQLite stores 64-bit integers), and
a value outside the signed 64-bit range is a bad row ("is outside the 64-bit
integer range"), never rounded through a float.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

import dggs

from .crs import transform_points
from .readers import RawBatch

__all__ = ["Prepared", "prepare", "value_types", "infer_type", "is_missing", "INT64"]

#: The range of an SQLite INTEGER.
INT64 = (-(2**63), 2**63 - 1)

_Bad = dict[int, tuple[str | None, Any, str]]


@dataclass
class Prepared:
    """Checked rows of one batch, ready to insert.

    ``values`` holds the rows' parameters one after the other, ``width`` to
    a row: one flat list, as a multi-row ``INSERT`` binds them, built in the
    reader thread with slice assignments instead of a tuple per row.
    """

    values: list[Any]
    width: int
    rejects: list[dict[str, Any]]
    with_parts: bool = False
    #: the batch's roll-up partials (:class:`dggs.storage.rollup_keep.BatchPartials`), where roll-ups are kept
    partials: Any = None
    #: the rows' cells as integer ids (uint64), where the batch came binned already (``RawBatch.located``)
    ids: Any = None

    def __len__(self) -> int:
        """The number of rows."""
        return len(self.values) // self.width


def is_missing(value: Any) -> bool:
    """Whether ``value`` is a missing value (stored as NULL): None, NaN or pandas' ``pd.NA``.

    ``pd.NA`` is told by its type's name, as :func:`dggs.index._convert.kind.fail`
    does, so pandas need not be imported.

    Examples
    --------
    >>> [is_missing(v) for v in (None, float("nan"), 0.0, "")]
    [True, True, False, False]
    """
    if value is None:
        return True
    if isinstance(value, (float, np.floating)):
        return bool(value != value)
    return type(value).__name__ == "NAType"


def _floats(raw: Sequence[Any], name: str, bad: _Bad, text: bool) -> np.ndarray:
    """Parse coordinates to float64; mark unparsable or non-finite entries bad."""
    try:
        arr = np.asarray(raw, dtype=np.float64)
        if arr.ndim != 1:
            raise ValueError
    except (ValueError, TypeError):
        arr = np.empty(len(raw), dtype=np.float64)
        for i, value in enumerate(raw):
            if is_missing(value):  # named "is missing" below
                arr[i] = np.nan
                continue
            try:
                if isinstance(value, (str, bytes)) and not value.strip():
                    raise ValueError
                arr[i] = float(value)
            except (ValueError, TypeError):
                arr[i] = np.nan
                bad.setdefault(i, (name, value, "is not a number"))
    notfinite = ~np.isfinite(arr)
    if notfinite.any():
        for i in np.flatnonzero(notfinite).tolist():
            bad.setdefault(i, (name, raw[i], "is missing or not finite"))
    return arr


def _is_number(value: object, from_text: bool) -> bool:
    if isinstance(value, (int, float)):  # bool is an int: stored as 0/1
        return True
    if from_text and isinstance(value, str):
        try:
            number = float(value)
        except ValueError:
            return False
        # "Nan", "Inf", "Infinity" parse as floats but are words (Nan is a city in Thailand): a text column
        # holding one is not "numbers and some text"
        return math.isfinite(number)
    return False


def infer_type(values: list[Any], from_text: bool) -> str:
    """Guess the SQL type of a new value column from a batch of raw values.

    ``INTEGER`` if every non-empty value is an integer (text input: parses
    as one), ``REAL`` if every one is a number, ``TEXT`` if none is, and
    ``"MIXED"`` if some are numbers and some are not: the caller refuses to
    guess then (a stray word must not turn a numeric column into text).

    Examples
    --------
    >>> infer_type(["1", "", "3"], from_text=True)
    'INTEGER'
    >>> infer_type([1.5, None, 2], from_text=False)
    'REAL'
    >>> infer_type(["a", "b"], from_text=True)
    'TEXT'
    >>> infer_type(["a", "1"], from_text=True)
    'MIXED'
    """
    kind = "INTEGER"
    numbers = texts = 0
    for value in values:
        if is_missing(value) or (isinstance(value, str) and from_text and not value.strip()):
            continue  # None, NaN, pd.NA: NULL
        if hasattr(value, "item") and not isinstance(value, (str, bytes)):
            value = value.item()  # numpy scalar
        if not _is_number(value, from_text):
            texts += 1
            continue
        numbers += 1
        if isinstance(value, float) or (isinstance(value, str) and not _is_int_text(value)):
            kind = "REAL"
    if numbers and texts:
        return "MIXED"
    return kind if numbers else "TEXT"


def _is_int_text(value: str) -> bool:
    try:
        int(value)
    except ValueError:
        return False
    return True


def _integer(value: Any) -> int | float | None:
    """An exact int for an integer-like value (float for a fractional number); raises if not a number."""
    if is_missing(value):
        return None
    if isinstance(value, (bool, np.bool_)):
        return int(value)
    if isinstance(value, (int, np.integer)):
        return int(value)
    if isinstance(value, (str, bytes)):
        text = value.strip()
        if not text:
            return None
        try:
            return int(text)
        except ValueError:
            number = float(text)
    else:
        number = float(value)
    if math.isnan(number):
        return None
    if math.isinf(number):
        raise OverflowError
    return int(number) if number.is_integer() and abs(number) < 2**53 else number


def _convert(raw: Sequence[Any], kind: str, name: str, bad: _Bad, text: bool) -> list[Any]:
    """Convert a raw value column to Python values of SQL type ``kind``.

    Empty text, ``None`` and NaN become NULL; infinities, unparsable numbers
    and integers outside the 64-bit range are bad.  ``INTEGER`` values stay
    exact (never through float64).
    """
    if kind == "TEXT":
        if text:
            return [value if value != "" else None for value in raw]
        texts: list[Any] = []
        for value in (raw.tolist() if isinstance(raw, np.ndarray) else raw):
            if is_missing(value):
                texts.append(None)
            else:
                texts.append(value if isinstance(value, str) else str(value))
        return texts
    arr = raw if isinstance(raw, np.ndarray) else None
    if arr is not None and arr.dtype.kind in "ib":
        return arr.tolist()
    if arr is not None and arr.dtype.kind == "u" and (not len(arr) or int(arr.max()) <= INT64[1]):
        return arr.tolist()
    if kind == "REAL" or (arr is not None and arr.dtype.kind == "f"):
        try:
            values = np.asarray(raw, dtype=np.float64)
            if values.ndim == 1 and not np.isinf(values).any():
                return [None if v != v else v for v in values.tolist()]
        except (ValueError, TypeError, OverflowError):
            pass
    elif text:
        try:
            ints: list[Any] = np.asarray(raw, dtype=np.int64).tolist()
            return ints
        except (ValueError, OverflowError):
            pass
    out: list[Any] = []
    for i, value in enumerate(raw.tolist() if isinstance(raw, np.ndarray) else raw):
        try:
            if kind == "INTEGER":
                number = _integer(value)
                if isinstance(number, int) and not INT64[0] <= number <= INT64[1]:
                    bad.setdefault(i, (name, value, "is outside the 64-bit integer range (declare the column str)"))
                    number = None
                out.append(number)
                continue
            if is_missing(value) or (isinstance(value, (str, bytes)) and not value.strip()):
                out.append(None)
                continue
            number_f = float(value)
            if math.isnan(number_f):
                out.append(None)
            elif math.isinf(number_f):
                bad.setdefault(i, (name, value, "is not finite"))
                out.append(None)
            else:
                out.append(number_f)
        except OverflowError:
            bad.setdefault(i, (name, value, "is not finite"))
            out.append(None)
        except (ValueError, TypeError):
            bad.setdefault(
                i, (name, value, f"is not a number (column type {kind}; declare the column str if it holds text)")
            )
            out.append(None)
    return out


def value_types(
    batch: RawBatch, existing: Mapping[str, str], declared: Mapping[str, str]
) -> dict[str, str]:
    """Return the SQL types of value columns that ``points`` does not have yet.

    An undeclared column whose values in the first batch are numbers and
    some text is numeric: the text values are bad rows (named by line,
    column and value), as they would be in any later batch.  A text column
    is one whose values are all text, or one declared ``str``.
    """
    new: dict[str, str] = {}
    for name, raw in batch.values.items():
        if name in existing:
            continue
        if name in declared:
            new[name] = declared[name]
        elif isinstance(raw, np.ndarray) and raw.dtype.kind in "iub":
            new[name] = "INTEGER"
        elif isinstance(raw, np.ndarray) and raw.dtype.kind == "f":
            new[name] = "REAL"
        elif isinstance(raw, np.ndarray) and raw.dtype.kind in "US":
            new[name] = "TEXT"
        else:
            sample = raw.tolist() if isinstance(raw, np.ndarray) else list(raw)
            kind = infer_type(sample, batch.text)
            if kind == "MIXED":  # numbers and some text: numeric, the text values are bad rows
                kind = infer_type([v for v in sample if infer_type([v, 0], batch.text) != "MIXED"], batch.text)
            new[name] = kind
    return new


def prepare(
    batch: RawBatch,
    level: int,
    types: Mapping[str, str],
    transformer: Any,
    locate: Any = None,
) -> Prepared:
    """Convert and check one batch; compute the cells of its good rows.

    Returns the rows to insert (cell, lat, lng, row, [part,] then value
    columns in ``types`` order) and the rejects.  ``locate`` bins the points
    (the store's ``Grid(projection).latlng_to_cell``; default ISEA's).
    """
    locate = dggs.latlng_to_cell if locate is None else locate
    n = len(batch)
    bad: _Bad = dict(batch.bad)
    lat_bad: _Bad = {}
    lng_bad: _Bad = {}
    lat = _floats(batch.lat, "lat", lat_bad, batch.text)
    lng = _floats(batch.lng, "lng", lng_bad, batch.text)
    if transformer is not None:
        lat, lng, failed = transform_points(transformer, lat, lng)
        for i in np.flatnonzero(failed).tolist():
            lat_bad.setdefault(i, ("lat", (batch.lat[i], batch.lng[i]), "cannot be transformed to WGS84"))
    with np.errstate(invalid="ignore"):
        for i in np.flatnonzero(np.abs(lat) > 90).tolist():
            lat_bad.setdefault(i, ("lat", batch.lat[i], "is out of range -90..90"))
        for i in np.flatnonzero(np.abs(lng) > 180).tolist():
            lng_bad.setdefault(i, ("lng", batch.lng[i], "is out of range -180..180"))
    for found in (lat_bad, lng_bad):  # report the first bad column, left to right
        for i, problem in found.items():
            bad.setdefault(i, problem)
    columns = [_convert(batch.values[name], kind, name, bad, batch.text) for name, kind in types.items()]

    good = np.ones(n, dtype=bool)
    if bad:
        good[list(bad)] = False
    keep = np.flatnonzero(good)
    all_good = len(keep) == n
    known = np.asarray(batch.cells, dtype=object) if batch.cells is not None else None
    located = batch.located if known is None else None  # binned already (ordered arrays): not binned again
    if all_good and known is None:  # the common case: every row good, no cell given
        if located is not None:
            cells: Any = dggs.int_to_str(located) if n else np.empty(0, dtype=object)
        else:
            cells = locate(lat, lng, level) if n else np.empty(0, dtype=object)
    else:
        cells = np.empty(n, dtype=object)
        todo = keep if known is None else keep[known[keep] == ""]
        if len(todo):
            cells[todo] = locate(lat[todo], lng[todo], level) if located is None else dggs.int_to_str(located[todo])
        if known is not None:
            given = keep[known[keep] != ""]
            cells[given] = known[given]
    # source_id is bound in the SQL text, and part only when there are parts:
    # fewer parameters per row make the inserts faster.
    with_parts = batch.parts is not None
    if all_good:
        parts = [cells.tolist(), lat.tolist(), lng.tolist(), batch.rows, *columns]
        if with_parts:
            parts.insert(4, batch.parts)
    else:
        idx = keep.tolist()
        parts = [
            cells[keep].tolist(),
            lat[keep].tolist(),
            lng[keep].tolist(),
            [batch.rows[i] for i in idx],
            *[[col[i] for i in idx] for col in columns],
        ]
        if with_parts:
            parts.insert(4, [batch.parts[i] for i in idx])  # type: ignore[index]
    width = len(parts)
    flat: list[Any] = [None] * (width * len(parts[0]))
    for k, part in enumerate(parts):
        flat[k::width] = part
    rejects = []
    for i in sorted(bad):
        column, value, reason = bad[i]
        rejects.append(
            {
                "row": batch.rows[i],
                "line": batch.lines[i] if batch.lines is not None else None,
                "column": column,
                "value": value,
                "reason": reason,
                "index": i,
            }
        )
    ids = None if located is None else np.asarray(located if all_good else located[keep], dtype=np.uint64)
    return Prepared(values=flat, width=width, rejects=rejects, with_parts=with_parts, ids=ids)


def jsonable(value: Any) -> Any:
    if hasattr(value, "item") and not isinstance(value, (str, bytes)):
        try:
            return value.item()
        except (ValueError, AttributeError):
            return str(value)
    return value


