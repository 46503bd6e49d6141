"""Chapter 4: the thesis's triangulated faces (Figure 4.2) and an inverse Snyder with a pluggable ``Az``.

The workload of Tables 4.2-4.3 (:mod:`dggs.experiments.chapter4_speed`,
:mod:`dggs.experiments.chapter4_errors`) and of the chapter-4 figures.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

from dggs.experiments.chapter4_constants import _SECTOR
from dggs.geometry import snyder
from dggs.geometry.icosahedron import ISEA, Orientation
from dggs.geometry.split26 import FACE_VERTICES

__all__ = ["face_mesh", "inverse_with_az", "spherical_triangle_areas"]


# ----------------------------------------------------------------------------
# Triangulated faces and an inverse with a pluggable Az
# ----------------------------------------------------------------------------
def face_mesh(quality: int) -> tuple[np.ndarray, np.ndarray]:
    """The thesis's quality-``q`` triangulated face (Figure 4.2).

    The planar face triangle divided into ``q**2`` congruent triangles.

    Returns
    -------
    points : (M, 2) ndarray
        Face-frame ``(x, y)`` of the ``(q + 1)(q + 2) / 2`` vertices.
    triangles : (q**2, 3) int ndarray
        Vertex indices of the small triangles.

    Examples
    --------
    >>> p, t = face_mesh(10)
    >>> p.shape, t.shape
    ((66, 2), (100, 3))
    """
    q = int(quality)
    i, j = np.meshgrid(np.arange(q + 1), np.arange(q + 1), indexing="ij")
    keep = i + j <= q
    i, j = i[keep], j[keep]
    k = q - i - j
    points = (k[:, None] * FACE_VERTICES[0] + i[:, None] * FACE_VERTICES[1]
              + j[:, None] * FACE_VERTICES[2]) / q
    index = np.full((q + 1, q + 1), -1, dtype=np.int64)
    index[i, j] = np.arange(i.size)
    a, b = np.meshgrid(np.arange(q), np.arange(q), indexing="ij")
    up = a + b < q  # triangles (a,b), (a+1,b), (a,b+1)
    au, bu = a[up], b[up]
    tri_up = np.stack([index[au, bu], index[au + 1, bu], index[au, bu + 1]], axis=1)
    down = a + b < q - 1  # triangles (a+1,b), (a+1,b+1), (a,b+1)
    ad, bd = a[down], b[down]
    tri_down = np.stack([index[ad + 1, bd], index[ad + 1, bd + 1], index[ad, bd + 1]], axis=1)
    return points, np.concatenate([tri_up, tri_down])


def inverse_with_az(
    face: np.ndarray,
    x: np.ndarray,
    y: np.ndarray,
    az_of: Callable[[np.ndarray], np.ndarray],
    orientation: Orientation = ISEA,
) -> np.ndarray:
    """Inverse Snyder with a caller-supplied ``Az(Az')`` (unit vectors, (N, 3)).

    The same steps as :func:`dggs.experiments.numpy_snyder.inverse_xyz` (eqs. 8-12 inverted),
    except that ``Az`` comes from ``az_of`` applied to ``Az'`` reduced to the
    [0, 120) degree sector: lets us evaluate fits that the library does not
    offer (the thesis's full-sector polynomial).
    """
    geo = orientation.geometry
    rho = np.hypot(x, y)
    ap = np.mod(np.arctan2(x, y), 2.0 * math.pi)
    k = np.minimum((ap // _SECTOR).astype(np.intp), 2)
    ap = ap - k * _SECTOR
    sin_a, cos_a = np.sin(ap), np.cos(ap)
    az = az_of(ap)
    sin_az, cos_az = np.sin(az), np.cos(az)
    u = cos_az + sin_az * snyder.COT_THETA  # eq. 9: tan q = tan g / u
    sin_half_q = np.sqrt(0.5 * (1.0 - u / np.hypot(snyder.TAN_G, u)))
    d_prime = (snyder.R_PRIME * snyder.TAN_G) / (cos_a + sin_a * snyder.COT_THETA)  # eq. 10
    s = np.minimum(rho / d_prime * sin_half_q, 1.0)  # sin(z/2), eqs. 11-12
    cos_z, sin_z = 1.0 - 2.0 * s * s, 2.0 * s * np.sqrt(1.0 - s * s)
    turn = az + k * _SECTOR
    face = np.asarray(face)
    c, n, e = geo.centres[face], geo.norths[face], geo.easts[face]
    return cos_z[:, None] * c + sin_z[:, None] * (np.cos(turn)[:, None] * n + np.sin(turn)[:, None] * e)


def spherical_triangle_areas(xyz: np.ndarray, triangles: np.ndarray) -> np.ndarray:
    """Unsigned areas (steradians) of spherical triangles on the unit sphere.

    Uses ``A = 2 atan2(|a.(b x c)|, 1 + a.b + b.c + c.a)`` (Van Oosterom-Strackee).
    """
    a, b, c = xyz[triangles[:, 0]], xyz[triangles[:, 1]], xyz[triangles[:, 2]]
    triple = np.einsum("ij,ij->i", a, np.cross(b, c))
    denom = 1.0 + np.einsum("ij,ij->i", a, b) + np.einsum("ij,ij->i", b, c) + np.einsum("ij,ij->i", c, a)
    return np.abs(2.0 * np.arctan2(triple, denom))
