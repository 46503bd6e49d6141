"""Numpy twins of Snyder's forward and inverse: independent oracles of the compiled kernel, and the experiments' steps.

Until issue 16 these were ``dggs.geometry.snyder.forward_xyz``,
``inverse_xyz``, ``sector_forward``, ``planar_azimuth``, ``sector_to_xyz``,
``sector_distance``, ``_area_from_planar``, ``_az_closed`` and
``_az_closed_sincos``.  The package itself projects with the compiled
:mod:`dggs.geometry.kernel` (through :func:`dggs.geometry.snyder.forward` and
``inverse``); these array forms stay here because the tests compare the
kernel against them and the thesis's chapter 4 experiments
(:mod:`dggs.experiments.inverse`, ``chapter4_*``, ``figures_ch4``) and
``benchmarks/bench_snyder.py`` build on their steps.

Snyder, J. P. (1992), "An equal-area map projection for polyhedral globes",
Cartographica 29(1): 10-21, eqs. 6-14; thesis chapter 4.

Examples
--------
>>> import numpy as np
>>> face, x, y = forward_xyz(np.array([[1.0, 0.0, 0.0]]))
>>> int(face[0]), round(float(x[0]), 8), round(float(y[0]), 8)
(2, -0.20898643, -0.34773547)
>>> xyz = inverse_xyz(face, x, y)
>>> bool(np.allclose(xyz, [[1.0, 0.0, 0.0]]))
True
"""

from __future__ import annotations

import math

import numpy as np

from dggs.geometry.constants import (
    COS_G,
    COS_SMALL_G,
    COT_THETA,
    R_PRIME,
    ROT_COS,
    ROT_SIN,
    RT2,
    SECTOR,
    SIN_G,
    TAN_G,
    TINY,
    UNTINY,
    G,
)
from dggs.geometry.icosahedron import ISEA, Orientation, face_dots

__all__ = [
    "forward_xyz",
    "sector_forward",
    "inverse_xyz",
    "planar_azimuth",
    "sector_to_xyz",
    "sector_distance",
    "area_from_planar",
    "az_closed",
    "az_closed_sincos",
]


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
    k = np.minimum((az * (1.0 / SECTOR)).astype(np.intp), 2)
    az -= k * SECTOR
    sin_az, cos_az = np.sin(az), np.cos(az)
    # sin(z/2) without cancellation near the centre: 1 - cos z = sin^2 z / (1 + cos z)
    sin_half_z = np.sqrt(0.5 * (n * n + e * e) / (1.0 + c))
    sin_p, cos_p = sector_forward(sin_az, cos_az, sin_half_z)
    rc, rs = ROT_COS[k], ROT_SIN[k]  # Az' + 120 k
    x = sin_p * rc + cos_p * rs
    y = cos_p * rc - sin_p * rs
    return face, x, y


def sector_forward(sin_az, cos_az, sin_half_z):
    """Snyder's forward inside one 120-degree sector: ``(rho sin Az', rho cos Az')`` (arrays).

    Takes the reduced azimuth's sine and cosine and ``sin(z/2)``.  The
    compiled kernel has the per-point twin (:func:`dggs.geometry.kernel.sector_forward`).
    """
    # eq. 9: tan q = tan g / (cos Az + sin Az cot theta); we need sin(q/2).
    u = cos_az + sin_az * COT_THETA
    sin_half_q = np.sqrt(0.5 * (1.0 - u / np.hypot(TAN_G, u)))
    cos_h = sin_az * (SIN_G * COS_SMALL_G) - cos_az * COS_G  # eq. 6
    sin_h = np.sqrt(1.0 - cos_h * cos_h)  # H in (36, 144) degrees: sin H > 0
    az_plus_h = np.arctan2(sin_az * cos_h + cos_az * sin_h, cos_az * cos_h - sin_az * sin_h)
    az_plus_h = az_plus_h + (az_plus_h < 0) * (2 * math.pi)
    area = az_plus_h + (G - math.pi)  # eq. 7, spherical excess of triangle ABD
    # eq. 8: Az' = atan2(2 A_G, R'^2 tan^2 g - 2 A_G cot theta), kept as sin/cos.
    big_x = RT2 - 2.0 * area * COT_THETA
    big_y = 2.0 * area
    # eq. 10 (d') and eqs. 11-12 (rho = d' sin(z/2) / sin(q/2)); |(X, Y)| cancels against d'
    rho = (R_PRIME * TAN_G) / (big_x + big_y * COT_THETA) * sin_half_z / sin_half_q
    return rho * big_y, rho * big_x


def area_from_planar(sin_a: np.ndarray, cos_a: np.ndarray) -> np.ndarray:
    """A_G of planar azimuth Az' (eq. 8 inverted; the sin/cos form has no pole at Az' = 0)."""
    return RT2 * sin_a / (2.0 * (cos_a + COT_THETA * sin_a))


def az_closed(area: np.ndarray) -> np.ndarray:
    """Exact spherical azimuth Az of the excess A_G (closed form: Snyder 1992 eqs. 6-7 solved for Az; thesis chapter 4).

    With Y = A_G + pi - G = Az + H, the cosine rule for H gives
    tan Az = (cos Y + cos G) / (sin G cos g - sin Y), rewritten without
    cancellation.
    """
    return np.arctan2(
        2.0 * np.sin(G - 0.5 * area) * np.sin(0.5 * area),
        np.sin(G - area) - SIN_G * COS_SMALL_G,
    )


def az_closed_sincos(area):
    """``(sin Az, cos Az)`` of :func:`az_closed` without the arctangent."""
    num = 2.0 * np.sin(G - 0.5 * area) * np.sin(0.5 * area)
    den = np.sin(G - area) - SIN_G * COS_SMALL_G
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



def planar_azimuth(x: np.ndarray, y: np.ndarray):
    """Reduce face-plane points to one 120-degree sector (arrays; the first step of the inverse).

    Returns ``(ap, k, sin_a, cos_a, rho)``: the reduced planar azimuth Az' in
    [0, 120) degrees (radians), the sector ``k`` (0..2), Az''s sine and cosine
    and the distance from the face centre.
    """
    rho = np.hypot(x, y)
    ap = np.arctan2(x, y)
    ap += np.where(ap < 0, 2 * math.pi, 0.0)
    k = np.minimum((ap * (1.0 / SECTOR)).astype(np.intp), 2)
    ap -= k * SECTOR
    # sin/cos of the reduced Az': turn (x, y) back by 120 k instead of calling sin and cos
    rc, rs = ROT_COS[k], ROT_SIN[k]
    # the azimuth's sine and cosine; tiny (x, y) are scaled first so that 1 / rho does not overflow
    scale = np.where(rho < TINY, UNTINY, 1.0)
    sx, sy = x * scale, y * scale
    srho = np.hypot(sx, sy)
    inv_rho = 1.0 / np.where(srho > 0, srho, 1.0)
    sin_a = (sx * rc - sy * rs) * inv_rho
    cos_a = np.where(srho > 0, (sy * rc + sx * rs) * inv_rho, 1.0)
    return ap, k, sin_a, cos_a, rho


def sector_to_xyz(face, k, sin_az, cos_az, sin_a, cos_a, rho, orientation: Orientation = ISEA) -> np.ndarray:
    """Unit vectors (N, 3) of points given their spherical azimuth Az in sector ``k`` (the inverse's last step)."""
    cos_z, sin_z = sector_distance(sin_az, cos_az, sin_a, cos_a, rho)
    rc, rs = ROT_COS[k], ROT_SIN[k]
    ct = cos_az * rc - sin_az * rs  # Az + 120 k
    st = sin_az * rc + cos_az * rs
    frame = orientation.geometry.frames[np.asarray(face)]  # rows: centre, north, east
    coef = np.stack([cos_z, sin_z * ct, sin_z * st], axis=1)
    return np.einsum("ni,nij->nj", coef, frame)


def inverse_xyz(face, x, y, orientation: Orientation = ISEA) -> np.ndarray:
    """Inverse of :func:`forward_xyz`: unit vectors (N, 3), by the exact closed form.

    No checks; :func:`dggs.geometry.snyder.inverse` is the checked public version.
    """
    _, k, sin_a, cos_a, rho = planar_azimuth(x, y)
    sin_az, cos_az = az_closed_sincos(area_from_planar(sin_a, cos_a))
    return sector_to_xyz(face, k, sin_az, cos_az, sin_a, cos_a, rho, orientation)
