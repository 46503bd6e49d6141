"""Coordinates in, ids out: the checks and containers of the point functions."""

from __future__ import annotations

import numpy as np

from dggs.errors import CoordinateError, DggsValueError

from . import _codec


def _is_pandas(obj) -> bool:
    return type(obj).__module__.startswith("pandas")


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
        arr = np.asarray(value)
        if arr.dtype.kind not in "fiu":
            if arr.dtype.kind == "O":
                try:
                    arr = arr.astype(np.float64)
                except (TypeError, ValueError):
                    raise CoordinateError(f"{name}s must be numbers, not {_first_non_number(arr)!r}") from None
            else:
                raise CoordinateError(f"{name}s must be numbers, not {arr.dtype} values such as {arr.ravel()[:1].tolist()}")
        arrays.append(arr)
    lat_a, lng_a = arrays
    try:
        shape = np.broadcast_shapes(lat_a.shape, lng_a.shape)
    except ValueError:
        raise CoordinateError(f"latitude shape {lat_a.shape} does not match longitude shape {lng_a.shape}") from None
    lat_f = np.ascontiguousarray(np.broadcast_to(lat_a, shape), dtype=np.float64).reshape(-1)
    lng_f = np.ascontiguousarray(np.broadcast_to(lng_a, shape), dtype=np.float64).reshape(-1)
    return lat_f, lng_f, shape, index


def _first_non_number(arr: np.ndarray):
    for v in arr.ravel():
        try:
            float(v)
        except (TypeError, ValueError):
            return v
        if isinstance(v, (bool, np.bool_, str, bytes)):
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
    """A Python float of a numeric scalar; strings and bools are refused."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, float, np.integer, np.floating)):
        raise CoordinateError(f"{name}s must be numbers, not {value!r}")
    return float(value)


def check_densify(densify) -> int:
    if isinstance(densify, (bool, np.bool_)) or not isinstance(densify, (int, np.integer)) or densify < 0:
        raise DggsValueError(f"densify {densify!r} must be a non-negative integer")
    if densify > 100_000:
        raise DggsValueError(f"densify {densify!r} is over the limit of 100000 points per edge")
    return int(densify)
