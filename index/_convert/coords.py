"""Coordinates in any container in: flat float64 arrays and the :class:`Kind` the answer goes out in.

Latitudes and longitudes come as numbers, lists, numpy arrays, pandas Series,
pyarrow arrays or polars Series; the answer (ids via :func:`.cells_out.cells_out`, values
via :func:`.values.values_out`) goes back in the same kind of container.
"""

from __future__ import annotations

import sys
from typing import Any, NoReturn

import numpy as np

from dggs.errors import CoordinateError

from .frames import is_polars_series, series_to_arrow
from .kind import OBJECT, Kind


def _container(obj: Any) -> tuple[str, Any] | None:
    """``(container, the pandas index or whether chunked)`` of a coordinate container; None for a scalar."""
    mod = type(obj).__module__
    if mod.startswith("pandas") and hasattr(obj, "index"):  # a Series, not pandas' NA or NaT
        return "pandas", obj.index
    if mod.startswith("pandas") and isinstance(obj, sys.modules["pandas"].Index):
        return "pandas-index", None
    if mod.startswith("pyarrow"):
        pa = sys.modules["pyarrow"]
        if isinstance(obj, (pa.Array, pa.ChunkedArray)):
            return "arrow", isinstance(obj, pa.ChunkedArray)
    if is_polars_series(obj):
        return "polars", None
    if isinstance(obj, np.ndarray):
        return ("numpy", None) if obj.ndim else None
    if isinstance(obj, (list, tuple)):
        return "list", None
    return None


def _from_arrow(value: Any, name: str) -> np.ndarray:
    """A pyarrow numeric array as float64 (a null is a bad coordinate: NaN, named by the check)."""
    pa = sys.modules["pyarrow"]
    if not (pa.types.is_floating(value.type) or pa.types.is_integer(value.type)):
        raise CoordinateError(f"{name}s must be numbers, not a pyarrow {value.type} array")
    chunks = value.chunks if isinstance(value, pa.ChunkedArray) else [value]
    parts = [c.cast(pa.float64()).fill_null(float("nan")).to_numpy(zero_copy_only=False) for c in chunks]
    return np.concatenate(parts) if parts else np.zeros(0)


def coords_in(lat: Any, lng: Any) -> tuple[np.ndarray, np.ndarray, Kind]:
    """``lat``, ``lng`` as flat float64 arrays, and the :class:`Kind` of container the answer goes out in.

    The container is that of the first coordinate that is a container (a
    pandas Series keeps its index, a pyarrow array gives pyarrow out); two
    scalars give a scalar kind.  The form of the kind is ``"str"``; the
    caller sets the form of its output with :func:`.kind.as_form`.

    Raises
    ------
    CoordinateError
        Non-numeric input (strings, bools, objects), or shapes that do not broadcast.
    """
    found = _container(lat) or _container(lng)
    lat_a, lng_a = _as_numbers(lat, "latitude"), _as_numbers(lng, "longitude")
    try:
        shape = np.broadcast_shapes(lat_a.shape, lng_a.shape)
    except ValueError:
        raise CoordinateError(f"latitude shape {lat_a.shape} does not match longitude shape {lng_a.shape}") from None
    if found is None or shape == ():
        kind = Kind("scalar", "str", (), True) if shape == () else Kind("numpy", "str", shape)
    elif found[0] == "pandas":
        index = found[1]
        name = getattr(lat, "name", None) if _container(lat) else getattr(lng, "name", None)
        if shape != (len(index),):
            # the answer is a Series on the input's index: the other coordinate must not add dimensions or rows
            raise CoordinateError(
                f"a pandas Series of coordinates (length {len(index)}) needs the other coordinate as one number "
                f"or as many numbers; together they make shape {shape}"
            )
        kind = Kind("pandas", "str", shape, dtype=OBJECT, index=index, name=name)
    elif found[0] == "pandas-index":
        name = getattr(lat, "name", None) if _container(lat) else getattr(lng, "name", None)
        kind = Kind("pandas-index", "str", shape, dtype=OBJECT, name=name) if len(shape) == 1 else Kind("numpy", "str", shape)
    elif found[0] == "arrow":
        kind = Kind("arrow", "str", shape, chunked=bool(found[1]))
    elif found[0] == "polars":
        name = lat.name if _container(lat) else lng.name
        kind = Kind("polars", "str", shape, name=name) if len(shape) == 1 else Kind("numpy", "str", shape)
    else:
        kind = Kind(found[0], "str", shape)
    lat_f = np.ascontiguousarray(np.broadcast_to(lat_a, shape), dtype=np.float64).reshape(-1)
    lng_f = np.ascontiguousarray(np.broadcast_to(lng_a, shape), dtype=np.float64).reshape(-1)
    return lat_f, lng_f, kind


_NOT_NUMBERS = (bool, np.bool_, str, bytes, np.str_, np.bytes_)
_PLAIN_NUMBERS = {float, int, np.float64, np.float32, np.int64}


_ID_START = 1 << 62  # every id is at least this: smaller integers are levels


def _flat_values(obj: Any) -> tuple[np.ndarray, Kind] | None:
    """The elements of a scalar or container as a flat numpy array, and its kind; None for anything else."""
    found = _container(obj)
    if found is None:
        if isinstance(obj, (int, np.integer, bool, np.bool_)):
            return np.array([obj], dtype=object), Kind("scalar", "int", (), True)
        return None
    c, extra = found
    if c == "pandas":
        return obj.to_numpy(), Kind("pandas", "int", (len(obj),), index=extra, name=getattr(obj, "name", None))
    if c == "pandas-index":
        return obj.to_numpy(), Kind("pandas-index", "int", (len(obj),), name=obj.name)
    if c == "arrow":
        pa = sys.modules["pyarrow"]
        flat = obj.combine_chunks() if isinstance(obj, pa.ChunkedArray) else obj
        return flat.to_numpy(zero_copy_only=False), Kind("arrow", "int", (len(obj),), chunked=bool(extra))
    if c == "polars":
        return obj.to_numpy(), Kind("polars", "int", (len(obj),), name=obj.name)
    if c == "numpy":
        return obj.reshape(-1), Kind("numpy", "int", obj.shape)
    try:
        arr = np.asarray(obj, dtype=object)
    except ValueError:  # ragged
        return None
    return arr.reshape(-1), Kind("list", "int", arr.shape)


def levels_in(obj: Any) -> tuple[np.ndarray, Kind] | None:
    """Levels in any container (integers below 2**62, bools to be refused as levels), or None if they are ids.

    Returns the flat elements (unchecked: the caller checks each level) and
    the kind of container the answer goes out in.
    """
    flat = _flat_values(obj)
    if flat is None or flat[0].size == 0:
        return None
    arr, kind = flat
    if arr.dtype.kind == "b":
        return arr, kind
    if arr.dtype.kind in "iu":
        return (arr, kind) if int(arr.max()) < _ID_START else None
    if arr.dtype != object:
        return None
    items = arr.tolist()
    if all(isinstance(v, (int, np.integer, bool, np.bool_)) for v in items) and max(int(v) for v in items) < _ID_START:
        return arr, kind
    return None


def _as_numbers(value: Any, name: str) -> np.ndarray:
    """``value`` as a numeric array; :class:`CoordinateError` naming the first value that is not a number."""
    if (_container(value) or ("",))[0] == "arrow":
        return _from_arrow(value, name)
    if is_polars_series(value):
        return _from_arrow(series_to_arrow(value), name)
    if isinstance(value, np.ma.MaskedArray):  # masked entries are missing values, not their hidden data
        mask = np.ma.getmaskarray(value)
        if mask.any():
            i = int(np.flatnonzero(mask)[0])
            at = i if mask.ndim <= 1 else tuple(int(j) for j in np.unravel_index(i, mask.shape))
            raise CoordinateError(f"{name} at index {at} is a missing value (masked)")
        value = np.asarray(value.data)
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


def _first_non_number(arr: np.ndarray) -> Any:
    for v in arr.ravel():
        if isinstance(v, _NOT_NUMBERS):
            return v
        try:
            float(v)
        except (TypeError, ValueError, OverflowError):
            return v
    return arr.ravel()[0]


def raise_bad_point(lat: np.ndarray, lng: np.ndarray, i: int) -> NoReturn:
    """Raise :class:`CoordinateError` naming point ``i`` (the kernel gave it the null id).

    Raises
    ------
    CoordinateError
        Always: naming the non-finite or out-of-range coordinate of point ``i``.
    """
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


def as_float_scalar(value: Any, name: str) -> float:
    """A Python float of a numeric scalar (or 0-d array); strings and bools are refused.

    Raises
    ------
    CoordinateError
        ``value`` is not a number, or too large for a float.
    """
    if isinstance(value, np.ndarray) and value.ndim == 0:
        value = value[()]
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, float, np.integer, np.floating)):
        raise CoordinateError(f"{name}s must be numbers, not {value!r}")
    try:
        return float(value)
    except OverflowError:
        raise CoordinateError(f"{name} {value!r} is out of range") from None
