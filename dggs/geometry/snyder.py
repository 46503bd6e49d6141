"""Snyder's equal-area projection of the icosahedron (ISEA), forward and inverse.

Snyder, J. P. (1992), "An equal-area map projection for polyhedral globes",
Cartographica 29(1): 10-21; thesis §3.1.3-3.1.4 and chapter 4.  Constants and
conventions as in PROJ's ``+proj=isea`` (see ``shared/SNYDER.md``).

Coordinates are on the unit sphere.  :func:`forward` maps a point to its face
and to ``(x, y)`` in that face's frame: origin at the face centre, ``+y``
towards the face's reference vertex, azimuths clockwise (``x = rho sin Az'``,
``y = rho cos Az'``).  The face is a planar equilateral triangle with
circumradius :data:`FACE_CIRCUMRADIUS` and area ``pi / 5``, exactly the area
of its spherical face: the map is equal-area.

For geodetic WGS84 coordinates use :class:`Projection`, which converts to
authalic latitude and scales by the authalic radius.

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

import numpy as np

from dggs.geometry._validate import as_latlng
from dggs.geometry.authalic import WGS84, Ellipsoid
from dggs.errors import CoordinateError, DggsValueError
from dggs.geometry.icosahedron import ISEA, NUM_FACES, Orientation, face_dots

__all__ = [
    "forward",
    "inverse",
    "forward_xyz",
    "inverse_xyz",
    "Projection",
    "TAN_G",
    "G",
    "THETA",
    "R_PRIME",
    "FACE_CIRCUMRADIUS",
    "FACE_INRADIUS",
    "FACE_EDGE",
]

# Snyder 1992, Table 1 (icosahedron); SNYDER.md §1.
TAN_G = 3.0 - math.sqrt(5.0)  # g: arc from face centre to vertex, tan g = 3 - sqrt 5
G_ARC = math.atan(TAN_G)  # g = 37.3773681406 degrees
G = math.pi / 5  # G = 36 degrees (the thesis's "46" is a typo)
THETA = math.pi / 6  # theta = 30 degrees
COT_THETA = math.sqrt(3.0)
#: Planar circumradius of a face: sqrt(4 pi / (15 sqrt 3)) so the face has area pi / 5.
FACE_CIRCUMRADIUS = math.sqrt(4 * math.pi / (15 * math.sqrt(3.0)))
#: R' / R = 0.9103832815 (Snyder 1992, eq. 3.1 = 3.2 solved for R').
R_PRIME = FACE_CIRCUMRADIUS / TAN_G
FACE_INRADIUS = FACE_CIRCUMRADIUS / 2
FACE_EDGE = FACE_CIRCUMRADIUS * math.sqrt(3.0)

_SECTOR = 2 * math.pi / 3  # Az runs over 120-degree sectors, vertex to vertex
_SIN_G, _COS_G = math.sin(G), math.cos(G)
_COS_SMALL_G = math.cos(G_ARC)
_RT2 = (R_PRIME * TAN_G) ** 2  # R'^2 tan^2 g
_ROT_COS = np.cos(_SECTOR * np.arange(3))
_ROT_SIN = np.sin(_SECTOR * np.arange(3))
_TINY = 2.0**-500  # planar distances below this are scaled by _UNTINY before 1 / rho
_UNTINY = 2.0**600


# ----------------------------------------------------------------------------
# Input checks
# ----------------------------------------------------------------------------
def _numbers(value, name: str) -> None:
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
def forward_xyz(xyz: np.ndarray, orientation: Orientation = ISEA):
    """Project unit vectors ``xyz`` (N, 3) to ``(face, x, y)`` on the unit sphere.

    The vector form of Snyder's forward (eqs. 6-12 and 14): azimuth and
    distance from the face centre come from dot products with the face
    frame's centre, north and east vectors, and ``Az + H`` is one angle
    (``arg(e^{i Az} e^{i H})``), so the whole map costs two arctangents.
    """
    geo = orientation.geometry
    face = np.argmax(face_dots(orientation, xyz), axis=1)
    cne = np.einsum("nij,nj->ni", geo.frames[face], xyz)  # rows: centre, north, east
    c, n, e = cne[:, 0], cne[:, 1], cne[:, 2]
    az = np.arctan2(e, n)  # eq. 14, clockwise from the face's reference vertex
    az += np.where(az < 0, 2 * math.pi, 0.0)
    k = np.minimum((az * (1.0 / _SECTOR)).astype(np.intp), 2)
    az -= k * _SECTOR
    sin_az, cos_az = np.sin(az), np.cos(az)
    # sin(z/2) without cancellation near the centre: 1 - cos z = sin^2 z / (1 + cos z)
    sin_half_z = np.sqrt(0.5 * (n * n + e * e) / (1.0 + c))
    sin_p, cos_p = sector_forward(sin_az, cos_az, sin_half_z)
    rc, rs = _ROT_COS[k], _ROT_SIN[k]  # Az' + 120 k
    x = sin_p * rc + cos_p * rs
    y = cos_p * rc - sin_p * rs
    return face, x, y


def sector_forward(sin_az, cos_az, sin_half_z):
    """Snyder's forward inside one 120-degree sector: ``(rho sin Az', rho cos Az')`` (arrays).

    Takes the reduced azimuth's sine and cosine and ``sin(z/2)``.  The
    compiled kernel has the per-point twin (:func:`dggs.geometry.kernel.sector_forward`);
    this numpy form serves :func:`forward_xyz` and the thesis's experiments.
    """
    # eq. 9: tan q = tan g / (cos Az + sin Az cot theta); we need sin(q/2).
    u = cos_az + sin_az * COT_THETA
    sin_half_q = np.sqrt(0.5 * (1.0 - u / np.hypot(TAN_G, u)))
    cos_h = sin_az * (_SIN_G * _COS_SMALL_G) - cos_az * _COS_G  # eq. 6
    sin_h = np.sqrt(1.0 - cos_h * cos_h)  # H in (36, 144) degrees: sin H > 0
    az_plus_h = np.arctan2(sin_az * cos_h + cos_az * sin_h, cos_az * cos_h - sin_az * sin_h)
    az_plus_h = az_plus_h + (az_plus_h < 0) * (2 * math.pi)
    area = az_plus_h + (G - math.pi)  # eq. 7, spherical excess of triangle ABD
    # eq. 8: Az' = atan2(2 A_G, R'^2 tan^2 g - 2 A_G cot theta), kept as sin/cos.
    big_x = _RT2 - 2.0 * area * COT_THETA
    big_y = 2.0 * area
    # eq. 10 (d') and eqs. 11-12 (rho = d' sin(z/2) / sin(q/2)); |(X, Y)| cancels against d'
    rho = (R_PRIME * TAN_G) / (big_x + big_y * COT_THETA) * sin_half_z / sin_half_q
    return rho * big_y, rho * big_x


def forward(lat, lng, orientation: Orientation = ISEA):
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


def _forward_rad(lat: np.ndarray, lng: np.ndarray, orientation: Orientation):
    """Forward of radian arrays (1-d) through the compiled kernel."""
    from . import kernel

    geo = orientation.geometry
    n = lat.shape[0]
    face = np.empty(n, dtype=np.intp)
    x = np.empty(n)
    y = np.empty(n)
    kernel.forward_rad(
        np.ascontiguousarray(lat), np.ascontiguousarray(lng),
        np.ascontiguousarray(geo.centres), np.ascontiguousarray(geo.frames), face, x, y,
    )
    return face, x, y


# ----------------------------------------------------------------------------
# Inverse
# ----------------------------------------------------------------------------
def _area_from_planar(sin_a: np.ndarray, cos_a: np.ndarray) -> np.ndarray:
    """A_G of planar azimuth Az' (eq. 8 inverted; the sin/cos form has no pole at Az' = 0)."""
    return _RT2 * sin_a / (2.0 * (cos_a + COT_THETA * sin_a))


def _az_closed(area: np.ndarray) -> np.ndarray:
    """Exact spherical azimuth Az of the excess A_G (SNYDER.md §4 closed form).

    With Y = A_G + pi - G = Az + H, the cosine rule for H gives
    tan Az = (cos Y + cos G) / (sin G cos g - sin Y), rewritten without
    cancellation.
    """
    return np.arctan2(
        2.0 * np.sin(G - 0.5 * area) * np.sin(0.5 * area),
        np.sin(G - area) - _SIN_G * _COS_SMALL_G,
    )


def _az_closed_sincos(area):
    """``(sin Az, cos Az)`` of :func:`_az_closed` without the arctangent."""
    num = 2.0 * np.sin(G - 0.5 * area) * np.sin(0.5 * area)
    den = np.sin(G - area) - _SIN_G * _COS_SMALL_G
    r = np.hypot(num, den)
    return num / r, den / r


def sector_distance(sin_az, cos_az, sin_a, cos_a, rho):
    """``(cos z, sin z)`` of planar points at distance ``rho``, spherical/planar azimuths given (arrays).

    Snyder's eqs. 9-12 inverted.
    """
    u = cos_az + sin_az * COT_THETA  # eq. 9
    sin_half_q = np.sqrt(0.5 * (1.0 - u / np.hypot(TAN_G, u)))
    d_prime = (R_PRIME * TAN_G) / (cos_a + sin_a * COT_THETA)  # eq. 10
    s = rho / d_prime * sin_half_q  # sin(z/2), eqs. 11-12 inverted
    s = s - (s > 1.0) * (s - 1.0)  # at most 1 (rounding at face vertices)
    return 1.0 - 2.0 * s * s, 2.0 * s * np.sqrt(1.0 - s * s)



def _outside_face(x: np.ndarray, y: np.ndarray, slack: float) -> np.ndarray:
    """True where (x, y) lies outside the face triangle by more than ``slack``."""
    # Edge normals point at the edge midpoints, azimuths 60, 180, 300 degrees.
    s3 = math.sqrt(3.0) / 2
    limit = FACE_INRADIUS * (1.0 + slack)
    return (
        (s3 * x + 0.5 * y > limit) | (-y > limit) | (-s3 * x + 0.5 * y > limit)
    )




def planar_azimuth(x: np.ndarray, y: np.ndarray):
    """Reduce face-plane points to one 120-degree sector (arrays; the first step of the inverse).

    Returns ``(ap, k, sin_a, cos_a, rho)``: the reduced planar azimuth Az' in
    [0, 120) degrees (radians), the sector ``k`` (0..2), Az''s sine and cosine
    and the distance from the face centre.
    """
    rho = np.hypot(x, y)
    ap = np.arctan2(x, y)
    ap += np.where(ap < 0, 2 * math.pi, 0.0)
    k = np.minimum((ap * (1.0 / _SECTOR)).astype(np.intp), 2)
    ap -= k * _SECTOR
    # sin/cos of the reduced Az': turn (x, y) back by 120 k instead of calling sin and cos
    rc, rs = _ROT_COS[k], _ROT_SIN[k]
    # the azimuth's sine and cosine; tiny (x, y) are scaled first so that 1 / rho does not overflow
    scale = np.where(rho < _TINY, _UNTINY, 1.0)
    sx, sy = x * scale, y * scale
    srho = np.hypot(sx, sy)
    inv_rho = 1.0 / np.where(srho > 0, srho, 1.0)
    sin_a = (sx * rc - sy * rs) * inv_rho
    cos_a = np.where(srho > 0, (sy * rc + sx * rs) * inv_rho, 1.0)
    return ap, k, sin_a, cos_a, rho


def sector_to_xyz(face, k, sin_az, cos_az, sin_a, cos_a, rho, orientation: Orientation = ISEA) -> np.ndarray:
    """Unit vectors (N, 3) of points given their spherical azimuth Az in sector ``k`` (the inverse's last step)."""
    cos_z, sin_z = sector_distance(sin_az, cos_az, sin_a, cos_a, rho)
    rc, rs = _ROT_COS[k], _ROT_SIN[k]
    ct = cos_az * rc - sin_az * rs  # Az + 120 k
    st = sin_az * rc + cos_az * rs
    frame = orientation.geometry.frames[np.asarray(face)]  # rows: centre, north, east
    coef = np.stack([cos_z, sin_z * ct, sin_z * st], axis=1)
    return np.einsum("ni,nij->nj", coef, frame)


def inverse_xyz(face, x, y, orientation: Orientation = ISEA) -> np.ndarray:
    """Inverse of :func:`forward_xyz`: unit vectors (N, 3), by the exact closed form.

    No checks; see :func:`inverse` for the checked public version.
    """
    _, k, sin_a, cos_a, rho = planar_azimuth(x, y)
    sin_az, cos_az = _az_closed_sincos(_area_from_planar(sin_a, cos_a))
    return sector_to_xyz(face, k, sin_az, cos_az, sin_a, cos_a, rho, orientation)


def checked_face_xy(face, x, y):
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


def inverse(face, x, y, orientation: Orientation = ISEA):
    """Map face-plane ``(x, y)`` on face ``face`` back to latitude/longitude (degrees).

    The exact, non-iterative closed form of the azimuth (``shared/SNYDER.md``
    §4).  Snyder's Newton-Raphson and the thesis's polynomial inverses
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
    from . import kernel

    n = face_a.shape[0]
    lat, lng = np.empty(n), np.empty(n)
    kernel.inverse_deg(
        np.ascontiguousarray(face_a, dtype=np.int64), np.ascontiguousarray(x_a), np.ascontiguousarray(y_a),
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

    def forward(self, lat, lng):
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

    def inverse(self, face, x, y):
        """``(face, x, y)`` in metres -> geodetic ``(lat, lng)`` in degrees."""
        lat, lng = inverse(face, np.divide(x, self.radius), np.divide(y, self.radius), self.orientation)
        lat = self.ellipsoid.authalic_to_geodetic_deg(lat)
        return (float(lat), lng) if np.ndim(lat) == 0 else (lat, lng)
