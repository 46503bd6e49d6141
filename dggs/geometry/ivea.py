"""The vertex-oriented great circle projection of the icosahedron (IVEA), forward and inverse.

van Leeuwen, D. and Strebe, D. (2006), "A 'Slice-and-Dice' approach to area
equivalence in polyhedral map projections", Cartography and Geographic
Information Science 33(4): 269-286; thesis §3.1.5 and §3.1.7 (Figures
3.13-3.14).  An equal-area map of each spherical face onto its planar face,
like Snyder's (:mod:`.snyder`), with the same faces, the same face frames and
the same planar triangles, so that the Split (2:6) hierarchy and both id forms
are unchanged: only the map between a face and its plane differs.

The map works on the *natural triangle* (thesis §3.1.5): the face vertex V,
the face centre C and the edge midpoint M, which is our level-1 cell.  Its
angles on the sphere are 36 degrees at V, 60 at C and 90 at M, so its area is
6 degrees, ``pi / 30`` (one 120th of the sphere).

*Slice* (thesis §3.1.7, first equation): the great circle from V through P
meets CM at D.  With ``rho`` the angle MVD at V and ``delta`` the angle VDM at
D, the right triangle VMD has area ``rho + delta - pi / 2`` (Girard); Napier's
rule in that right triangle gives ``cos delta = cos VM sin rho``, so the area is
``A(rho) = rho - asin(cos VM sin rho)``.  D' divides M'C' so that triangle V'M'D'
holds the same share of the planar triangle: ``|M'D'| / |M'C'| = A / (pi / 30)``.

*Dice* (thesis §3.1.7, second equation): P' lies on V'D' with
``(|V'P'| / |V'D'|)**2 = (1 - cos VP) / (1 - cos VD)``, i.e. ``|V'P'| / |V'D'| =
sin(VP / 2) / sin(VD / 2)``, where ``tan VD = tan VM / cos rho`` (Napier again).

*Inverse* (derived here; docs/grid.md "The IVEA projection"): the planar point
gives ``s = |V'P'| / |V'D'|`` and ``t = |M'D'| / |M'C'|`` by one line
intersection.  ``A = t pi / 30 = rho - asin(k sin rho)`` with ``k = cos VM``
reads ``k sin rho = sin(rho - A) = sin rho cos A - cos rho sin A``, so
``tan rho = sin A / (cos A - k)``: a closed form (``cos A >= cos 6° > k = 0.8507``,
so the denominator never vanishes).  Then ``VD`` from ``rho``, and ``VP`` from
``sin(VP / 2) = s sin(VD / 2)``.  No iteration.

The per-point maps are compiled C (``libdggs/src/ivea.c``), re-exported here from :mod:`dggs._core`; the
module constants below are what ``libdggs/tools/gen_tables.py`` copies into the C core (run it after changing
them).

Examples
--------
>>> face, x, y = forward(0.0, 0.0)
>>> int(face), round(float(x), 8), round(float(y), 8)
(2, -0.21071309, -0.34773547)
>>> lat, lng = inverse(face, x, y)
>>> abs(round(float(lat), 10)), abs(round(float(lng), 10))
(0.0, 0.0)
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from dggs._core import ivea_face_forward as face_forward
from dggs._core import ivea_face_inverse as face_inverse
from dggs._core import ivea_forward_rad, ivea_inverse_deg
from dggs._core import ivea_forward_unit as forward_unit
from dggs._core import ivea_natural_forward as natural_forward
from dggs._core import ivea_natural_inverse as natural_inverse
from dggs.geometry._checked import EllipsoidProjection, checked_forward, checked_inverse
from dggs.geometry.constants import FACE_CIRCUMRADIUS, FACE_INRADIUS, G_ARC, SQRT3
from dggs.geometry.icosahedron import ISEA, Orientation

__all__ = [
    "forward",
    "inverse",
    "Projection",
    "face_forward",
    "face_inverse",
    "forward_unit",
    "natural_forward",
    "natural_inverse",
    "NATURAL_AREA",
    "VM_ARC",
]

_H = 0.5 * SQRT3
#: Area of the natural triangle on the unit sphere: 36 + 60 + 90 - 180 degrees (Girard).
NATURAL_AREA = math.pi / 30
# The natural triangle in face-frame components (c, n, e) = (towards the centre, north, east):
# V at azimuth 0 and arc g from C; M at azimuth 60 and arc r from C, tan r = tan g cos 60 (Napier).
_R_IN = math.atan(0.5 * math.tan(G_ARC))
_V = np.array([math.cos(G_ARC), math.sin(G_ARC), 0.0])
_M = np.array([math.cos(_R_IN), math.sin(_R_IN) * 0.5, math.sin(_R_IN) * _H])
_C = np.array([1.0, 0.0, 0.0])
#: cos VM = cos CV / cos CM (spherical Pythagoras in the right triangle CMV); VM is half an edge.
COS_VM = math.cos(G_ARC) / math.cos(_R_IN)
VM_ARC = math.acos(COS_VM)
_TAN_VM2 = math.tan(VM_ARC) ** 2


def _unit(v: np.ndarray) -> np.ndarray:
    out: np.ndarray = v / np.linalg.norm(v)
    return out


# Tangent directions at V: towards M, and the one 90 degrees from it on C's side.
_TM = _unit(_M - (_V @ _M) * _V)
_TC = _unit(_C - (_V @ _C) * _V)
_TN = _unit(_TC - (_TC @ _TM) * _TM)
#: det(V, T_M, T_N) = +-1: the sign that makes the angle at V positive towards C.
_SGN = float(np.sign(np.linalg.det(np.stack([_V, _TM, _TN]))))
_VX, _VY, _VZ = (float(v) for v in _V)
_MX, _MY, _MZ = (float(v) for v in _M)
_VM = float(_V @ _M)
_T = (float(_TM[0]), float(_TM[1]), float(_TM[2]), float(_TN[0]), float(_TN[1]), float(_TN[2]))
# The planar natural triangle: V' = (0, R), M' = r (sin 60, cos 60), C' = (0, 0); (x, y) = (east, north).
_RV = FACE_CIRCUMRADIUS
_RM = FACE_INRADIUS

#: The batch loops over IVEA's per-point maps, called as :data:`.kernel.forward_rad` / ``inverse_deg`` are
#: (static methods, so that :attr:`Projection.forward_rad` is not bound as a method).
forward_rad = staticmethod(ivea_forward_rad)
inverse_deg = staticmethod(ivea_inverse_deg)


# ----------------------------------------------------------------------------
# The checked public API (as dggs.geometry.snyder's)
# ----------------------------------------------------------------------------
def forward(lat: Any, lng: Any, orientation: Orientation = ISEA) -> tuple[Any, Any, Any]:
    """Project spherical latitude/longitude (degrees) to a face and face-plane ``(x, y)`` by IVEA.

    The same faces, face frames and planar triangles as :func:`dggs.geometry.snyder.forward`.

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
        Coordinates that are not real numbers, NaN, infinite, out of range, or mismatched shapes.

    Examples
    --------
    >>> face, x, y = forward([90.0, -90.0], [0.0, 0.0])
    >>> face.tolist()
    [0, 16]
    """
    return checked_forward(forward_rad, lat, lng, orientation)


def inverse(face: Any, x: Any, y: Any, orientation: Orientation = ISEA) -> tuple[Any, Any]:
    """Map face-plane ``(x, y)`` on ``face`` back to spherical latitude/longitude (degrees) by IVEA.

    The closed form derived in docs/grid.md ("The IVEA projection"): no iteration.

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
        A face outside 0..19, coordinates that are not real numbers, NaN or infinite, or a point off its face.

    Examples
    --------
    >>> lat, lng = inverse(0, 0.0, 0.0)  # the face centre, as Snyder's
    >>> round(float(lat), 6), round(float(lng), 6)
    (69.094843, -78.75)
    """
    return checked_inverse(inverse_deg, face, x, y, orientation)


class Projection(EllipsoidProjection):
    """IVEA on an ellipsoid (via authalic latitude) or a sphere, in metres (as :class:`.snyder.Projection`).

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

    forward_rad = forward_rad
    inverse_deg = inverse_deg
    label = "ivea.Projection"
