"""Coordinates in, ids out: the checks and containers of the point functions."""

from __future__ import annotations

import numpy as np

from dggs.errors import CoordinateError, DggsValueError

from . import _codec


def _is_pandas(obj) -> bool:
    """A pandas Series or Index (something with an index to keep), not pandas' NA or NaT."""
    return type(obj).__module__.startswith("pandas") and hasattr(obj, "index")


def as_coordinates(lat, lng) -> tuple[np.ndarray, np.ndarray, tuple, object]:
    """``lat``, ``lng`` as flat float64 arrays, the output shape, and a pandas index (or None).

    Raises :class:`CoordinateError` for non-numeric input (strings, bools,
    objects) or shapes that do not broadcast.
    """
    index = None
    if _is_pandas(lat):
        index = lat.index
    elif _is_pandas(lng):
        index = lng.index
    arrays = []
    for name, value in (("latitude", lat), ("longitude", lng)):
        arrays.append(_as_numbers(value, name))
    lat_a, lng_a = arrays
    try:
        shape = np.broadcast_shapes(lat_a.shape, lng_a.shape)
    except ValueError:
        raise CoordinateError(f"latitude shape {lat_a.shape} does not match longitude shape {lng_a.shape}") from None
    if index is not None and shape != (len(index),):
        # the answer is a Series on the input's index: the other coordinate must not add dimensions or rows
        raise CoordinateError(
            f"a pandas Series of coordinates (length {len(index)}) needs the other coordinate as one number "
            f"or as many numbers; together they make shape {shape}"
        )
    lat_f = np.ascontiguousarray(np.broadcast_to(lat_a, shape), dtype=np.float64).reshape(-1)
    lng_f = np.ascontiguousarray(np.broadcast_to(lng_a, shape), dtype=np.float64).reshape(-1)
    return lat_f, lng_f, shape, index


_NOT_NUMBERS = (bool, np.bool_, str, bytes, np.str_, np.bytes_)
_PLAIN_NUMBERS = {float, int, np.float64, np.float32, np.int64}


def _as_numbers(value, name: str) -> np.ndarray:
    """``value`` as a numeric array; :class:`CoordinateError` naming the first value that is not a number."""
    if isinstance(value, (list, tuple)) and not set(map(type, value)) <= _PLAIN_NUMBERS:
        # numpy turns [1.0, True] into floats: judge the elements themselves
        try:
            objs = np.array(value, dtype=object)
        except (ValueError, TypeError):
            raise CoordinateError(f"{name}s must be a flat or regular (non-ragged) sequence of numbers") from None
        if objs.dtype == object and any(isinstance(v, _NOT_NUMBERS) for v in objs.reshape(-1)):
            raise CoordinateError(f"{name}s must be numbers, not {_first_non_number(objs)!r}")
    try:
        arr = np.asarray(value)
    except (ValueError, TypeError, OverflowError):
        raise CoordinateError(f"{name}s must be a flat or regular (non-ragged) sequence of numbers") from None
    if arr.dtype.kind in "fiu":
        return arr
    if arr.dtype.kind == "O":
        if any(isinstance(v, _NOT_NUMBERS) for v in arr.reshape(-1)):
            raise CoordinateError(f"{name}s must be numbers, not {_first_non_number(arr)!r}")
        try:
            return arr.astype(np.float64)
        except (TypeError, ValueError, OverflowError):
            raise CoordinateError(f"{name}s must be numbers, not {_first_non_number(arr)!r}") from None
    raise CoordinateError(f"{name}s must be numbers, not {arr.dtype} values such as {arr.ravel()[:1].tolist()}")


def _first_non_number(arr: np.ndarray):
    for v in arr.ravel():
        if isinstance(v, _NOT_NUMBERS):
            return v
        try:
            float(v)
        except (TypeError, ValueError, OverflowError):
            return v
    return arr.ravel()[0]


def raise_bad_point(lat: np.ndarray, lng: np.ndarray, i: int):
    """Raise :class:`CoordinateError` naming point ``i`` (the kernel gave it the null id)."""
    a, b = float(lat[i]), float(lng[i])
    if not np.isfinite(a):
        raise CoordinateError(f"latitude {a!r} at index {i} is not a finite number")
    if not np.isfinite(b):
        raise CoordinateError(f"longitude {b!r} at index {i} is not a finite number")
    raise CoordinateError(f"latitude {a!r} at index {i} is out of range -90..90")


def check_points(lat: np.ndarray, lng: np.ndarray, ids: np.ndarray) -> None:
    """Raise for the first point the kernel marked with the null id."""
    if ids.size and not ids.all():
        raise_bad_point(lat, lng, int(np.flatnonzero(ids == 0)[0]))


def ids_out(ids: np.ndarray, shape: tuple, index, as_int: bool):
    """Ids of points, shaped like the points: uint64 or ``U`` strings; a Series for pandas input."""
    if as_int:
        out = ids.reshape(shape)
    else:
        codes, _ = _codec.format_u32(ids)
        out = codes.view(f"<U{codes.shape[1]}").reshape(shape)
    if index is not None:
        import pandas as pd

        return pd.Series(out if as_int else out.astype(object), index=index)
    return out


def as_float_scalar(value, name: str) -> float:
    """A Python float of a numeric scalar (or 0-d array); strings and bools are refused."""
    if isinstance(value, np.ndarray) and value.ndim == 0:
        value = value[()]
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, float, np.integer, np.floating)):
        raise CoordinateError(f"{name}s must be numbers, not {value!r}")
    try:
        return float(value)
    except OverflowError:
        raise CoordinateError(f"{name} {value!r} is out of range") from None


def check_densify(densify) -> int:
    if isinstance(densify, (bool, np.bool_)) or not isinstance(densify, (int, np.integer)) or densify < 0:
        raise DggsValueError(f"densify {densify!r} must be a non-negative integer")
    if densify > 100_000:
        raise DggsValueError(f"densify {densify!r} is over the limit of 100000 points per edge")
    return int(densify)
