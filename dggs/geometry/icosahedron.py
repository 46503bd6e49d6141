"""The icosahedron: orientation on the globe, faces, vertices and face lookup.

Conventions follow PROJ's ``+proj=isea`` (Snyder 1992; PROJ ``isea.cpp``):

* The *frame* is a rotated copy of the globe whose north pole is icosahedron
  vertex 0.  A geographic point at azimuth ``Az`` from vertex 0 gets frame
  longitude ``pi + azi - Az`` (PROJ ``isea_ctran``).
* Frame vertices: V0 at the frame north pole; V1..V5 at latitude
  ``atan(1/2)`` and longitudes 180, -108, -36, 36, 108; V6..V10 at
  ``-atan(1/2)`` and -144, -72, 0, 72, 144; V11 at the frame south pole.
* Faces 0..19 are numbered as in PROJ: 0-4 around V0, 5-9 and 10-14 the
  equatorial belt, 15-19 around V11.  Faces 0-4 and 10-14 point "up" (their
  reference vertex lies due frame-north of the centre), 5-9 and 15-19 "down".

Every face has a *face frame*: origin at the face centre, ``+y`` towards the
face's reference vertex (its vertex 0), ``+x`` 90 degrees clockwise from it as
seen from outside the globe.  Face vertex ``k`` lies at azimuth ``120 k``
degrees, clockwise.

Examples
--------
>>> from dggs.geometry.icosahedron import ISEA, face_of
>>> import numpy as np
>>> int(face_of(ISEA, np.array([[0.0, 0.0, 1.0]]))[0])  # North Pole: edge 0/4, lowest wins
0
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache
from typing import Any

import numpy as np

__all__ = [
    "Orientation",
    "ISEA",
    "POLE",
    "Geometry",
    "geometry",
    "face_of",
    "latlng_to_xyz",
    "xyz_to_latlng",
    "VERTEX_LATITUDE",
    "NUM_FACES",
]

NUM_FACES = 20
#: Latitude of vertex 0 in the standard ISEA orientation: atan(golden ratio), degrees.
VERTEX_LATITUDE = math.degrees(math.atan((1 + math.sqrt(5)) / 2))

# Frame latitudes (degrees): the vertex ring atan(1/2) and the face-centre
# rings E = atan((3+sqrt5)/4) and F = atan((3-sqrt5)/4)  (Snyder 1992, Table 1).
_RING = math.degrees(math.atan(0.5))
_E = math.degrees(math.atan((3 + math.sqrt(5)) / 4))
_F = math.degrees(math.atan((3 - math.sqrt(5)) / 4))

_VERTEX_LATLNG = (
    [(90.0, 0.0)]
    + [(_RING, lng) for lng in (180.0, -108.0, -36.0, 36.0, 108.0)]
    + [(-_RING, lng) for lng in (-144.0, -72.0, 0.0, 72.0, 144.0)]
    + [(-90.0, 0.0)]
)
_CENTRE_LATLNG = (
    [(_E, lng) for lng in (-144.0, -72.0, 0.0, 72.0, 144.0)]
    + [(_F, lng) for lng in (-144.0, -72.0, 0.0, 72.0, 144.0)]
    + [(-_F, lng) for lng in (-108.0, -36.0, 36.0, 108.0, 180.0)]
    + [(-_E, lng) for lng in (-108.0, -36.0, 36.0, 108.0, 180.0)]
)
#: True for faces whose reference vertex lies frame-south of the centre.
DOWN_FACES = np.array([(i // 5) in (1, 3) for i in range(NUM_FACES)])


@dataclass(frozen=True)
class Orientation:
    """Where the icosahedron sits on the globe (a value object).

    Parameters
    ----------
    lat, lng : float
        Position of icosahedron vertex 0, degrees (on the authalic sphere).
    azimuth : float
        Rotation about vertex 0, degrees (PROJ's ``+azi``).

    Examples
    --------
    >>> ISEA.lat == VERTEX_LATITUDE, ISEA.lng
    (True, 11.25)
    >>> POLE
    Orientation(lat=90.0, lng=0.0, azimuth=0.0)
    """

    lat: float
    lng: float
    azimuth: float = 0.0

    def __post_init__(self) -> None:
        for name in ("lat", "lng", "azimuth"):
            value = getattr(self, name)
            if not math.isfinite(value):
                raise ValueError(f"orientation {name} {value!r} must be finite")
        if abs(self.lat) > 90:
            raise ValueError(f"orientation lat {self.lat!r} is out of range -90..90")

    @property
    def geometry(self) -> Geometry:
        """The derived face and vertex geometry (computed once, cached)."""
        return geometry(self)


#: The standard ISEA orientation (PROJ's and DGGRID's default).
ISEA = Orientation(VERTEX_LATITUDE, 11.25, 0.0)
#: Vertex 0 at the North Pole (PROJ's ``+orient=pole``).
POLE = Orientation(90.0, 0.0, 0.0)


def latlng_to_xyz(lat_rad: Any, lng_rad: Any) -> np.ndarray:
    """Unit vectors (..., 3) of latitudes and longitudes in radians."""
    cl = np.cos(lat_rad)
    return np.stack([cl * np.cos(lng_rad), cl * np.sin(lng_rad), np.sin(lat_rad)], axis=-1)


def xyz_to_latlng(xyz: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Latitude and longitude in radians of vectors (..., 3); the norm need not be 1."""
    x, y, z = xyz[..., 0], xyz[..., 1], xyz[..., 2]
    return np.arctan2(z, np.hypot(x, y)), np.arctan2(y, x)


def _north_east(lat: float, lng: float) -> tuple[np.ndarray, np.ndarray]:
    """Local north and east unit vectors at a point (radians)."""
    sl, cl, so, co = math.sin(lat), math.cos(lat), math.sin(lng), math.cos(lng)
    north = np.array([-sl * co, -sl * so, cl])
    east = np.array([-so, co, 0.0])
    return north, east


@dataclass(frozen=True, eq=False)
class Geometry:
    """Face and vertex geometry of one orientation, in geographic xyz.

    Attributes
    ----------
    rotation : (3, 3) array
        Geographic xyz -> frame xyz (``frame = rotation @ geo``).
    centres, norths, easts : (20, 3) arrays
        Face centres and the face frames' +y (north) and +x (east) directions
        at each centre, as geographic unit vectors.
    vertices : (12, 3) array
        Icosahedron vertices, geographic unit vectors.
    face_vertices : (20, 3) int array
        The vertex ids of each face in face-frame order (vertex k at azimuth
        120 k degrees clockwise from +y).
    frames : (20, 3, 3) array
        Rows centre, north, east of each face: ``frames[f] @ p`` gives
        ``(cos z, north, east)`` components of a point in face f's frame.
    """

    rotation: np.ndarray
    centres: np.ndarray
    norths: np.ndarray
    easts: np.ndarray
    vertices: np.ndarray
    face_vertices: np.ndarray
    frames: np.ndarray


@lru_cache(maxsize=16)
def geometry(orientation: Orientation) -> Geometry:
    """Derive the face geometry of an orientation (cached per orientation)."""
    lat_p, lng_p = math.radians(orientation.lat), math.radians(orientation.lng)
    # Frame axes in geographic xyz (PROJ isea_ctran): Z' = vertex 0, and a point
    # at azimuth Az from vertex 0 has frame longitude beta - Az, beta = pi + azi.
    z_axis = latlng_to_xyz(lat_p, lng_p)
    n0, e0 = _north_east(lat_p, lng_p)
    beta = math.pi + math.radians(orientation.azimuth)
    x_axis = math.cos(beta) * n0 + math.sin(beta) * e0
    y_axis = math.sin(beta) * n0 - math.cos(beta) * e0
    rotation = np.stack([x_axis, y_axis, z_axis])  # rows: frame axes
    to_geo = rotation.T

    def frame_points(latlngs: Any) -> np.ndarray:
        arr = np.radians(np.array(latlngs))
        points: np.ndarray = latlng_to_xyz(arr[:, 0], arr[:, 1]) @ to_geo.T
        return points

    vertices = frame_points(_VERTEX_LATLNG)
    centres = frame_points(_CENTRE_LATLNG)
    norths = np.empty((NUM_FACES, 3))
    easts = np.empty((NUM_FACES, 3))
    face_vertices = np.empty((NUM_FACES, 3), dtype=np.int64)
    for i, (clat, clng) in enumerate(np.radians(np.array(_CENTRE_LATLNG))):
        n, e = _north_east(clat, clng)
        if DOWN_FACES[i]:  # the reference vertex is frame-south: turn the face frame
            n, e = -n, -e
        norths[i], easts[i] = n @ to_geo.T, e @ to_geo.T
        # The three nearest vertices, ordered clockwise by azimuth from +y.
        near = np.argsort(-(vertices @ centres[i]))[:3]
        az = np.mod(np.arctan2(vertices[near] @ easts[i], vertices[near] @ norths[i]), 2 * math.pi)
        az[az > 2 * math.pi - 1e-9] = 0.0
        face_vertices[i] = near[np.argsort(az)]
    frames = np.stack([centres, norths, easts], axis=1)
    for arr in (rotation, vertices, centres, norths, easts, face_vertices, frames):
        arr.setflags(write=False)
    return Geometry(rotation, centres, norths, easts, vertices, face_vertices, frames)


def face_of(orientation: Orientation, xyz: np.ndarray) -> np.ndarray:
    """Face index (0..19) of unit vectors ``xyz`` (N, 3): the nearest face centre.

    The faces are the Voronoi cells of their centres, so the nearest centre is
    the containing face.  A point on an edge or a vertex is equally near two
    or five centres; it goes to the lowest-numbered of them.  "Equally"
    allows for rounding: face ``i``'s dot product gets a bias of
    ``-i * TIE_STEP`` (at most 7.6e-15, about 50 nm on the Earth), so a
    lower-numbered face wins any near-tie.
    """
    faces: np.ndarray = np.argmax(face_dots(orientation, xyz), axis=1)
    return faces


def face_dots(orientation: Orientation, xyz: np.ndarray) -> np.ndarray:
    """Dot products (N, 20) of points with the face centres, tie bias included.

    The product runs in blocks of 4,096 rows: small enough that OpenBLAS keeps
    it on the calling thread (its own threads would fight dggs's thread pool
    for the cores, which made point location 1.4-2.4x slower).
    """
    centres_t = geometry(orientation).centres.T
    n = xyz.shape[0]
    out = np.empty((n, NUM_FACES))
    for start in range(0, n, _BLAS_BLOCK):
        stop = min(start + _BLAS_BLOCK, n)
        np.matmul(xyz[start:stop], centres_t, out=out[start:stop])
    out += _BIAS
    return out


# OpenBLAS multithreads a product once M * N * K exceeds 65536 * 4; 4096 * 20 * 3 does not.
_BLAS_BLOCK = 4096


#: Dot-product step per face index that settles near-ties towards lower faces.
TIE_STEP = 4e-16
_BIAS = -TIE_STEP * np.arange(NUM_FACES)
