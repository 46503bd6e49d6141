"""Input checks shared by the public functions: typed errors naming the bad value."""

from __future__ import annotations

import numpy as np

from dggs.errors import CoordinateError


def _first_bad(mask: np.ndarray) -> int:
    return int(np.flatnonzero(mask.ravel())[0])


def as_latlng(lat, lng) -> tuple[np.ndarray, np.ndarray, bool]:
    """Broadcast ``lat``/``lng`` to float64 arrays and check them.

    Returns the two arrays (at least 1-d) and whether the input was scalar.
    Raises :class:`CoordinateError` naming the first bad value and its index:
    NaN or infinite coordinates, latitudes outside -90..90, mismatched shapes.
    """
    scalar = np.ndim(lat) == 0 and np.ndim(lng) == 0
    try:
        lat_a = np.asarray(lat, dtype=np.float64)
        lng_a = np.asarray(lng, dtype=np.float64)
    except (TypeError, ValueError) as exc:
        raise CoordinateError(f"coordinates must be numbers: {exc}") from None
    if lat_a.shape != lng_a.shape:
        if lat_a.ndim and lng_a.ndim:
            raise CoordinateError(
                f"latitude shape {lat_a.shape} does not match longitude shape {lng_a.shape}"
            )
        lat_a, lng_a = np.broadcast_arrays(lat_a, lng_a)
    lat_a = np.atleast_1d(lat_a).ravel()
    lng_a = np.atleast_1d(lng_a).ravel()
    bad = ~np.isfinite(lat_a)
    if bad.any():
        i = _first_bad(bad)
        raise CoordinateError(f"latitude {float(lat_a[i])!r} at index {i} is not a finite number")
    bad = ~np.isfinite(lng_a)
    if bad.any():
        i = _first_bad(bad)
        raise CoordinateError(f"longitude {float(lng_a[i])!r} at index {i} is not a finite number")
    bad = np.abs(lat_a) > 90.0
    if bad.any():
        i = _first_bad(bad)
        raise CoordinateError(f"latitude {float(lat_a[i])!r} at index {i} is out of range -90..90")
    return lat_a, lng_a, scalar
