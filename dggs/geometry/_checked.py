"""The checked public API of a face projection, written once for every kernel (Snyder's, IVEA's).

:mod:`.snyder` and :mod:`.ivea` map the same faces, face frames and planar
triangles with different per-point formulas.  Each compiles its two batch
loops (:func:`.kernel.face_loops`); this module checks the input, runs a pair
of loops and shapes the output, and :class:`EllipsoidProjection` adds the
authalic latitude and the metres, so both modules answer bad input with the
same :class:`~dggs.errors.CoordinateError` naming the bad value.

Examples
--------
>>> from dggs.geometry import kernel
>>> face, x, y = checked_forward(kernel.forward_rad, 90.0, 0.0)
>>> face
0
>>> lat, lng = checked_inverse(kernel.inverse_deg, 0, 0.0, 0.0)
>>> round(lat, 6), round(lng, 6)
(69.094843, -78.75)
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np

from dggs.errors import CoordinateError, DggsValueError
from dggs.geometry._validate import as_latlng
from dggs.geometry.authalic import WGS84, Ellipsoid
from dggs.geometry.constants import FACE_INRADIUS
from dggs.geometry.icosahedron import ISEA, NUM_FACES, Orientation

__all__ = ["numbers", "checked_face_xy", "checked_forward", "checked_inverse", "EllipsoidProjection"]


def numbers(value: Any, name: str) -> None:
    """Raise :class:`CoordinateError` naming the first value that is not a real number (str, bool, None...).

    numpy would turn ``"10"`` into 10.0, ``True`` into 1.0 and ``None`` into NaN.

    Examples
    --------
    >>> numbers([1.0, True], "latitude")
    Traceback (most recent call last):
    ...
    dggs.errors.CoordinateError: latitude True at index 1 is not a real number
    """
    try:
        # a list is read as given: numpy would make [1.0, True] floats and [1, "a"] strings
        arr = np.asarray(value, dtype=object) if isinstance(value, (list, tuple)) else np.asarray(value)
    except ValueError:  # ragged
        return  # the shape checks that follow name it
    if arr.dtype.kind in "iuf":
        return
    for i, v in enumerate(arr.ravel().tolist() if arr.dtype.kind != "O" else arr.ravel()):
        if isinstance(v, (bool, np.bool_)) or not isinstance(v, (int, float, np.integer, np.floating)):
            where = "" if arr.ndim == 0 else f" at index {i}"
            raise CoordinateError(f"{name} {v!r}{where} is not a real number")


def _outside_face(x: np.ndarray, y: np.ndarray, slack: float) -> np.ndarray:
    """True where (x, y) lies outside the face triangle by more than ``slack``."""
    # Edge normals point at the edge midpoints, azimuths 60, 180, 300 degrees.
    s3 = math.sqrt(3.0) / 2
    limit = FACE_INRADIUS * (1.0 + slack)
    return (
        (s3 * x + 0.5 * y > limit) | (-y > limit) | (-s3 * x + 0.5 * y > limit)
    )


def checked_face_xy(face: Any, x: Any, y: Any) -> tuple[np.ndarray, np.ndarray, np.ndarray, tuple[int, ...], bool]:
    """Check inverse input, naming the first bad value; return flat arrays, the shape and scalar-ness.

    Returns ``(face, x, y, shape, scalar)`` with 1-d int64 / float64 arrays.

    Raises
    ------
    CoordinateError
        A face outside 0..19, coordinates that are not real numbers, NaN or
        infinite, mismatched shapes, or a point off its face.

    Examples
    --------
    >>> checked_face_xy(20, 0.0, 0.0)
    Traceback (most recent call last):
    ...
    dggs.errors.CoordinateError: face 20 at index 0 is out of range 0..19
    """
    numbers(face, "face")
    numbers(x, "x")
    numbers(y, "y")
    scalar = np.ndim(face) == 0 and np.ndim(x) == 0 and np.ndim(y) == 0
    try:
        face_b, x_b, y_b = np.broadcast_arrays(np.asarray(face), np.asarray(x, float), np.asarray(y, float))
    except ValueError:
        raise CoordinateError(
            f"shapes of face {np.shape(face)}, x {np.shape(x)} and y {np.shape(y)} do not match"
        ) from None
    shape = face_b.shape
    face_a = np.atleast_1d(face_b).ravel()
    x_a, y_a = np.atleast_1d(x_b).ravel(), np.atleast_1d(y_b).ravel()
    if face_a.dtype.kind not in "iu" and face_a.size:
        if face_a.dtype.kind != "f" or not np.all(np.mod(face_a, 1) == 0):
            raise CoordinateError(f"face {face_a[0]!r} must be an integer 0..19")
        face_a = face_a.astype(np.int64)
    bad = (face_a < 0) | (face_a >= NUM_FACES)
    if bad.any():
        i = int(np.flatnonzero(bad)[0])
        raise CoordinateError(f"face {int(face_a[i])} at index {i} is out of range 0..19")
    for name, arr in (("x", x_a), ("y", y_a)):
        bad = ~np.isfinite(arr)
        if bad.any():
            i = int(np.flatnonzero(bad)[0])
            raise CoordinateError(f"{name} {float(arr[i])!r} at index {i} is not a finite number")
    off = _outside_face(x_a, y_a, 1e-9)
    if off.any():
        i = int(np.flatnonzero(off)[0])
        raise CoordinateError(
            f"point ({float(x_a[i])!r}, {float(y_a[i])!r}) at index {i} is off face {int(face_a[i])}"
        )
    return face_a, x_a, y_a, shape, scalar


def _run_forward(
    forward_rad: Callable[..., Any], lat: np.ndarray, lng: np.ndarray, orientation: Orientation
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Forward of radian arrays (1-d) through a compiled loop."""
    geo = orientation.geometry
    n = lat.shape[0]
    face, x, y = np.empty(n, dtype=np.intp), np.empty(n), np.empty(n)
    forward_rad(
        n, np.ascontiguousarray(lat), np.ascontiguousarray(lng),
        np.ascontiguousarray(geo.centres), np.ascontiguousarray(geo.frames), face, x, y,
    )
    return face, x, y


def checked_forward(forward_rad: Callable[..., Any], lat: Any, lng: Any, orientation: Orientation = ISEA) -> tuple[Any, Any, Any]:
    """Check spherical ``(lat, lng)`` degrees and run ``forward_rad``: ``(face, x, y)`` shaped as the input."""
    numbers(lat, "latitude")
    numbers(lng, "longitude")
    lat_a, lng_a, scalar = as_latlng(lat, lng)
    face, x, y = _run_forward(forward_rad, np.radians(lat_a), np.radians(lng_a), orientation)
    if scalar:
        return int(face[0]), float(x[0]), float(y[0])
    shape = np.shape(np.broadcast(np.asarray(lat), np.asarray(lng)))
    return face.reshape(shape), x.reshape(shape), y.reshape(shape)


def checked_inverse(inverse_deg: Callable[..., Any], face: Any, x: Any, y: Any, orientation: Orientation = ISEA) -> tuple[Any, Any]:
    """Check face-plane input and run ``inverse_deg``: spherical ``(lat, lng)`` degrees shaped as the input."""
    if not isinstance(orientation, Orientation):
        raise DggsValueError(f"orientation {orientation!r} is not an Orientation")
    face_a, x_a, y_a, shape, scalar = checked_face_xy(face, x, y)
    n = face_a.shape[0]
    lat, lng = np.empty(n), np.empty(n)
    inverse_deg(
        n, np.ascontiguousarray(face_a, dtype=np.int64), np.ascontiguousarray(x_a), np.ascontiguousarray(y_a),
        np.ascontiguousarray(orientation.geometry.frames), lat, lng,
    )
    if scalar:
        return float(lat[0]), float(lng[0])
    return lat.reshape(shape), lng.reshape(shape)


class EllipsoidProjection:
    """A face projection on an ellipsoid (via authalic latitude) or a sphere, in metres.

    A subclass names its kernel's loops in :attr:`forward_rad` and
    :attr:`inverse_deg` and its ``repr`` in :attr:`label`.

    Parameters
    ----------
    ellipsoid : Ellipsoid
        Default WGS84; use :func:`dggs.geometry.authalic.sphere` for spherical mode.
    orientation : Orientation
        Default :data:`dggs.geometry.icosahedron.ISEA`.
    """

    #: The kernel's loops (:func:`.kernel.face_loops`).
    forward_rad: Callable[..., Any]
    inverse_deg: Callable[..., Any]
    #: The class name shown by ``repr``.
    label = "Projection"

    def __init__(self, ellipsoid: Ellipsoid = WGS84, orientation: Orientation = ISEA) -> None:
        self.ellipsoid = ellipsoid
        self.orientation = orientation
        self.radius = ellipsoid.authalic_radius

    def __repr__(self) -> str:
        return f"{self.label}(ellipsoid={self.ellipsoid.name}, orientation={self.orientation})"

    def forward(self, lat: Any, lng: Any) -> tuple[Any, Any, Any]:
        """Geodetic degrees -> ``(face, x, y)`` with x, y in metres."""
        numbers(lat, "latitude")
        numbers(lng, "longitude")
        lat_a, lng_a, scalar = as_latlng(lat, lng)
        beta = self.ellipsoid.geodetic_to_authalic(np.radians(lat_a))
        face, x, y = _run_forward(self.forward_rad, np.asarray(beta, dtype=np.float64), np.radians(lng_a),
                                  self.orientation)
        x, y = x * self.radius, y * self.radius
        if scalar:
            return int(face[0]), float(x[0]), float(y[0])
        return face, x, y

    def inverse(self, face: Any, x: Any, y: Any) -> tuple[Any, Any]:
        """``(face, x, y)`` in metres -> geodetic ``(lat, lng)`` in degrees."""
        lat, lng = checked_inverse(self.inverse_deg, face, np.divide(x, self.radius), np.divide(y, self.radius),
                                   self.orientation)
        lat = self.ellipsoid.authalic_to_geodetic_deg(lat)
        return (float(lat), lng) if np.ndim(lat) == 0 else (lat, lng)
