"""Snyder's equal-area projection of the icosahedron (ISEA), forward and inverse: the checked public API.

Snyder, J. P. (1992), "An equal-area map projection for polyhedral globes",
Cartographica 29(1): 10-21; thesis §3.1.3-3.1.4 and chapter 4.  Constants and
conventions as in PROJ's ``+proj=isea`` (``isea.cpp``); the constants live in
:mod:`dggs.geometry.constants`, the compiled per-point formulas in
:mod:`dggs.geometry.kernel`.  This module checks input and runs the kernel.

Coordinates are on the unit sphere.  :func:`forward` maps a point to its face
and to ``(x, y)`` in that face's frame: origin at the face centre, ``+y``
towards the face's reference vertex, azimuths clockwise (``x = rho sin Az'``,
``y = rho cos Az'``).  The face is a planar equilateral triangle with
circumradius :data:`FACE_CIRCUMRADIUS` and area ``pi / 5``, exactly the area
of its spherical face: the map is equal-area.

For geodetic WGS84 coordinates use :class:`Projection`, which converts to
authalic latitude and scales by the authalic radius.  Numpy versions of the
same formulas, for the thesis's experiments, are in
:mod:`dggs.experiments.numpy_snyder`.

Examples
--------
>>> face, x, y = forward(0.0, 0.0)
>>> int(face), round(float(x), 8), round(float(y), 8)
(2, -0.20898643, -0.34773547)
>>> lat, lng = inverse(face, x, y)
>>> abs(round(float(lat), 10)), abs(round(float(lng), 10))
(0.0, 0.0)
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from dggs.errors import CoordinateError, DggsValueError
from dggs.geometry import kernel
from dggs.geometry._validate import as_latlng
from dggs.geometry.authalic import WGS84, Ellipsoid
from dggs.geometry.constants import (
    COT_THETA,
    FACE_CIRCUMRADIUS,
    FACE_EDGE,
    FACE_INRADIUS,
    G_ARC,
    R_PRIME,
    TAN_G,
    THETA,
    G,
)
from dggs.geometry.icosahedron import ISEA, NUM_FACES, Orientation

__all__ = [
    "forward",
    "inverse",
    "checked_face_xy",
    "Projection",
    "TAN_G",
    "G",
    "G_ARC",
    "THETA",
    "COT_THETA",
    "R_PRIME",
    "FACE_CIRCUMRADIUS",
    "FACE_INRADIUS",
    "FACE_EDGE",
]


# ----------------------------------------------------------------------------
# Input checks
# ----------------------------------------------------------------------------
def _numbers(value: Any, name: str) -> None:
    """Raise :class:`CoordinateError` naming the first value that is not a real number (str, bool, None...).

    numpy would turn ``"10"`` into 10.0, ``True`` into 1.0 and ``None`` into NaN.
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


# ----------------------------------------------------------------------------
# Forward
# ----------------------------------------------------------------------------
def forward(lat: Any, lng: Any, orientation: Orientation = ISEA) -> tuple[Any, Any, Any]:
    """Project spherical latitude/longitude (degrees) to a face and face-plane ``(x, y)``.

    Parameters
    ----------
    lat, lng : float or array_like
        Latitude and longitude on the sphere, degrees.  Longitudes wrap.
    orientation : Orientation
        Where the icosahedron sits (default: PROJ's ISEA orientation).

    Returns
    -------
    face : int or ndarray of int
        Face index 0..19 (PROJ's numbering).
    x, y : float or ndarray
        Planar coordinates in the face frame, unit sphere.

    Raises
    ------
    CoordinateError
        Coordinates that are not real numbers (strings, bools, None; the
        message names the value), NaN, infinite or out-of-range latitude, or
        mismatched shapes.

    Examples
    --------
    >>> face, x, y = forward([90.0, -90.0], [0.0, 0.0])
    >>> face.tolist()
    [0, 16]
    """
    _numbers(lat, "latitude")
    _numbers(lng, "longitude")
    lat_a, lng_a, scalar = as_latlng(lat, lng)
    face, x, y = _forward_rad(np.radians(lat_a), np.radians(lng_a), orientation)
    if scalar:
        return int(face[0]), float(x[0]), float(y[0])
    shape = np.shape(np.broadcast(np.asarray(lat), np.asarray(lng)))
    return face.reshape(shape), x.reshape(shape), y.reshape(shape)


def _forward_rad(
    lat: np.ndarray, lng: np.ndarray, orientation: Orientation
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Forward of radian arrays (1-d) through the compiled kernel."""
    geo = orientation.geometry
    n = lat.shape[0]
    face = np.empty(n, dtype=np.intp)
    x = np.empty(n)
    y = np.empty(n)
    kernel.forward_rad(
        n, np.ascontiguousarray(lat), np.ascontiguousarray(lng),
        np.ascontiguousarray(geo.centres), np.ascontiguousarray(geo.frames), face, x, y,
    )
    return face, x, y


# ----------------------------------------------------------------------------
# Inverse
# ----------------------------------------------------------------------------
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
    """
    _numbers(face, "face")
    _numbers(x, "x")
    _numbers(y, "y")
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


def inverse(face: Any, x: Any, y: Any, orientation: Orientation = ISEA) -> tuple[Any, Any]:
    """Map face-plane ``(x, y)`` on face ``face`` back to latitude/longitude (degrees).

    The exact, non-iterative closed form of the azimuth (Snyder 1992 eqs.
    6-8 solved for Az; thesis chapter 4).  Snyder's Newton-Raphson and the thesis's polynomial inverses
    (§4.1.2-4.1.3) are research code: :mod:`dggs.experiments.inverse`.

    Parameters
    ----------
    face : int or array_like of int
        Face index 0..19.
    x, y : float or array_like
        Planar coordinates in the face frame, unit sphere.
    orientation : Orientation
        The icosahedron's orientation.

    Returns
    -------
    lat, lng : float or ndarray
        Spherical latitude and longitude, degrees; longitude in -180..180.

    Raises
    ------
    CoordinateError
        A face outside 0..19, coordinates that are not real numbers (strings,
        bools, None), NaN or infinite, or a point off its face.

    Notes
    -----
    Points within 2**-500 of the face centre (subnormal ones too) map to the
    face centre.

    Examples
    --------
    >>> lat, lng = inverse(0, 0.0, 0.0)
    >>> round(float(lat), 6), round(float(lng), 6)
    (69.094843, -78.75)
    """
    if not isinstance(orientation, Orientation):
        raise DggsValueError(f"orientation {orientation!r} is not an Orientation")
    face_a, x_a, y_a, shape, scalar = checked_face_xy(face, x, y)
    n = face_a.shape[0]
    lat, lng = np.empty(n), np.empty(n)
    kernel.inverse_deg(
        n, np.ascontiguousarray(face_a, dtype=np.int64), np.ascontiguousarray(x_a), np.ascontiguousarray(y_a),
        np.ascontiguousarray(orientation.geometry.frames), lat, lng,
    )
    if scalar:
        return float(lat[0]), float(lng[0])
    return lat.reshape(shape), lng.reshape(shape)


# ----------------------------------------------------------------------------
# On the ellipsoid
# ----------------------------------------------------------------------------
class Projection:
    """Snyder ISEA on an ellipsoid (via authalic latitude) or a sphere, in metres.

    Parameters
    ----------
    ellipsoid : Ellipsoid
        Default WGS84; use :func:`dggs.geometry.authalic.sphere` for spherical mode.
    orientation : Orientation
        Default :data:`dggs.geometry.icosahedron.ISEA`.

    Examples
    --------
    >>> p = Projection()
    >>> face, x, y = p.forward(0.0, 0.0)
    >>> int(face), round(float(y))
    (2, -2215425)
    >>> [abs(round(v, 9)) for v in p.inverse(face, x, y)]
    [0.0, 0.0]
    """

    def __init__(self, ellipsoid: Ellipsoid = WGS84, orientation: Orientation = ISEA) -> None:
        self.ellipsoid = ellipsoid
        self.orientation = orientation
        self.radius = ellipsoid.authalic_radius

    def __repr__(self) -> str:
        return f"Projection(ellipsoid={self.ellipsoid.name}, orientation={self.orientation})"

    def forward(self, lat: Any, lng: Any) -> tuple[Any, Any, Any]:
        """Geodetic degrees -> ``(face, x, y)`` with x, y in metres."""
        _numbers(lat, "latitude")
        _numbers(lng, "longitude")
        lat_a, lng_a, scalar = as_latlng(lat, lng)
        beta = self.ellipsoid.geodetic_to_authalic(np.radians(lat_a))
        face, x, y = _forward_rad(np.asarray(beta, dtype=np.float64), np.radians(lng_a), self.orientation)
        x, y = x * self.radius, y * self.radius
        if scalar:
            return int(face[0]), float(x[0]), float(y[0])
        return face, x, y

    def inverse(self, face: Any, x: Any, y: Any) -> tuple[Any, Any]:
        """``(face, x, y)`` in metres -> geodetic ``(lat, lng)`` in degrees."""
        lat, lng = inverse(face, np.divide(x, self.radius), np.divide(y, self.radius), self.orientation)
        lat = self.ellipsoid.authalic_to_geodetic_deg(lat)
        return (float(lat), lng) if np.ndim(lat) == 0 else (lat, lng)
