"""Snyder's equal-area projection of the icosahedron (ISEA), forward and inverse: the checked public API.

Snyder, J. P. (1992), "An equal-area map projection for polyhedral globes",
Cartographica 29(1): 10-21; thesis §3.1.3-3.1.4 and chapter 4.  Constants and
conventions as in PROJ's ``+proj=isea`` (``isea.cpp``); the constants live in
:mod:`dggs.geometry.constants`, the compiled per-point formulas in
:mod:`dggs.geometry.kernel`.  This module runs the kernel behind the checks of :mod:`._checked`.

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

from typing import Any

from dggs.geometry import kernel
from dggs.geometry._checked import EllipsoidProjection, checked_face_xy, checked_forward, checked_inverse
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
from dggs.geometry.icosahedron import ISEA, Orientation

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
    return checked_forward(kernel.forward_rad, lat, lng, orientation)


# ----------------------------------------------------------------------------
# Inverse
# ----------------------------------------------------------------------------
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
    return checked_inverse(kernel.inverse_deg, face, x, y, orientation)


# ----------------------------------------------------------------------------
# On the ellipsoid
# ----------------------------------------------------------------------------
class Projection(EllipsoidProjection):
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

    forward_rad = kernel.forward_rad
    inverse_deg = kernel.inverse_deg
