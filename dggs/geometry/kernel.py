"""The compiled geometry kernel: one point or one planar triangle at a time.

Every function here is a numba ``@njit`` over Python floats and ints, so the
point-location, centre and boundary loops of :mod:`dggs.index` (and the
public :func:`dggs.geometry.snyder.forward` / ``inverse``, which check their
input and then call this module) run one implementation for a single point
and for a billion.  The formulas are Snyder's (Snyder 1992, eqs. 6-14, with
the closed-form inverse azimuth derived in thesis chapter 4), the authalic
series of :mod:`.authalic` (Karney 2023) and the Split (2:6) steps of
:mod:`.split26` (thesis §6.1.7), written per point.

This module sits below :mod:`.snyder`: it reads its constants from
:mod:`.constants` and its tables from :mod:`.authalic`, :mod:`.icosahedron`
and :mod:`.split26`, and imports nothing above them.  The tables of the
standard grid (PROJ's ISEA orientation, WGS84) are module constants that
numba bakes into the compiled code: a call passes no arrays.  Functions that
take an ``orientation`` take its tables as arrays instead.
"""

from __future__ import annotations

import math
import os

import numpy as np
from numba import njit, prange

from ._parallel import Loops, loops
from .authalic import WGS84
from .constants import (
    COS_G,
    COS_SMALL_G,
    COT_THETA,
    D_PRIME_NUM,
    ROT_COS,
    ROT_SIN,
    RT2,
    SIN_G,
    SQRT3,
    TAN_G2,
    TINY,
    UNTINY,
    G,
)
from .icosahedron import ISEA, NUM_FACES, TIE_STEP
from .split26 import AMBIGUOUS, CHILD_M, CHILD_T, FACE_VERTICES, GRID_H, GRID_W, L1_C, L1_ROWS, LEVEL1, jump_table

_TWO_PI = 2.0 * math.pi
_HALF_SQRT3 = 0.5 * SQRT3

# The standard grid's tables, as compile-time constants.
ISEA_CENTRES = np.ascontiguousarray(ISEA.geometry.centres)
ISEA_FRAMES = np.ascontiguousarray(ISEA.geometry.frames)
TIE_BIAS = -TIE_STEP * np.arange(NUM_FACES, dtype=np.float64)
TO_AUTHALIC = np.ascontiguousarray(WGS84.to_authalic_series)
TO_GEODETIC = np.ascontiguousarray(WGS84.to_geodetic_series)
L1_C = np.ascontiguousarray(L1_C)
L1_ROWS = np.ascontiguousarray(L1_ROWS)
CHILD_M = np.ascontiguousarray(CHILD_M)
CHILD_T = np.ascontiguousarray(CHILD_T)
LEVEL1_CORNERS = np.ascontiguousarray(LEVEL1)


def jump_constants():
    """split26's 4-level jump table as flat arrays: cell codes, packed digit codes, maps (computed, ~0.5 s)."""
    table, digit_rows, coef = jump_table()
    # the 4 digit codes (digit + 1) of each path, packed 2 bits each, first level highest
    packed = np.zeros(81, dtype=np.uint64)
    for j in range(4):
        packed = (packed << np.uint64(2)) | (digit_rows[j].astype(np.uint64) + np.uint64(1))
    return np.ascontiguousarray(table), packed, np.ascontiguousarray(np.stack(coef, axis=1))


#: The jump table shipped with the package, so that import does not recompute it
#: (tests/test_hierarchy.py checks it equals :func:`jump_constants`;
#: :func:`write_jump_file` rewrites it).
JUMP_FILE = os.path.join(os.path.dirname(__file__), "jump_table.npz")


def _load_jump_constants():
    try:
        with np.load(JUMP_FILE) as data:
            return data["table"], data["packed"], data["maps"]
    except (OSError, KeyError, ValueError):  # missing or unreadable: compute it
        return jump_constants()


JUMP_TABLE, JUMP_PACKED, JUMP_MAPS = _load_jump_constants()
_JUMP_SX = GRID_W / SQRT3
_JUMP_W2 = GRID_W + 2
#: A base cell's corners counter-clockwise: the face vertices in reverse (azimuth) order.
FACE_CORNERS_CCW = np.ascontiguousarray(FACE_VERTICES[::-1])


# ----------------------------------------------------------------------------
# Latitudes and longitudes
# ----------------------------------------------------------------------------
@njit(cache=True, nogil=True)
def wrap_degrees(lng: float) -> float:
    """A longitude reduced exactly to -180..180 (``fmod`` is exact; no radians first)."""
    if -180.0 <= lng <= 180.0:
        return lng
    lng = np.fmod(lng, 360.0)
    if lng > 180.0:
        lng -= 360.0
    elif lng < -180.0:
        lng += 360.0
    return lng


@njit(cache=True, nogil=True)
def unit_to_geodetic(px: float, py: float, pz: float):
    """Vector on the authalic sphere (any norm) -> geodetic WGS84 (lat, lng) degrees.

    ``sin 2 beta`` and ``cos 2 beta`` for the series come from the vector
    itself, so only the two arctangents remain.
    """
    h2 = px * px + py * py
    h = math.sqrt(h2)
    beta = math.atan2(pz, h)
    r2 = h2 + pz * pz
    s2 = 2.0 * pz * h / r2
    two_c2 = 2.0 * (h2 - pz * pz) / r2
    b1 = b2 = 0.0
    for i in range(TO_GEODETIC.shape[0] - 1, -1, -1):
        b1, b2 = two_c2 * b1 - b2 + TO_GEODETIC[i], b1
    return math.degrees(beta + b1 * s2), math.degrees(math.atan2(py, px))


@njit(cache=True, nogil=True)
def authalic_sincos(sp: float, cp: float):
    """``(sin beta, cos beta)`` of the authalic latitude from the geodetic one's ``sin phi`` and ``cos phi``.

    The shift ``d = beta - phi`` (below 0.0023 rad for WGS84) is summed from ``sin 2 phi`` and ``cos 2 phi``;
    ``sin d``, ``cos d`` are Taylor series to the ninth order (error below 1e-28), then the angle-sum rule.
    """
    s2 = 2.0 * sp * cp
    two_c2 = 2.0 * ((cp - sp) * (cp + sp))
    b1 = b2 = 0.0
    for i in range(TO_AUTHALIC.shape[0] - 1, -1, -1):
        b1, b2 = two_c2 * b1 - b2 + TO_AUTHALIC[i], b1
    d = b1 * s2
    d2 = d * d
    sd = d * (1.0 - d2 / 6.0 * (1.0 - d2 / 20.0 * (1.0 - d2 / 42.0 * (1.0 - d2 / 72.0))))
    cd = 1.0 - d2 / 2.0 * (1.0 - d2 / 12.0 * (1.0 - d2 / 30.0 * (1.0 - d2 / 56.0)))
    return sp * cd + cp * sd, cp * cd - sp * sd


@njit(cache=True, nogil=True)
def geodetic_to_unit(lat_deg: float, lng_deg: float):
    """Geodetic WGS84 degrees -> unit vector on the authalic sphere (:func:`authalic_sincos`)."""
    phi = math.radians(lat_deg)
    sb, cb = authalic_sincos(math.sin(phi), math.cos(phi))
    lam = math.radians(wrap_degrees(lng_deg))
    return cb * math.cos(lam), cb * math.sin(lam), sb


# ----------------------------------------------------------------------------
# Snyder forward and inverse (Snyder 1992, eqs. 6-14)
# ----------------------------------------------------------------------------
@njit(cache=True, nogil=True)
def nearest_face(centres: np.ndarray, px: float, py: float, pz: float) -> int:
    """The face whose centre is nearest; near-ties go to the lower face (icosahedron.face_of)."""
    best = 0
    best_dot = -4.0
    for f in range(centres.shape[0]):
        d = px * centres[f, 0] + py * centres[f, 1] + pz * centres[f, 2] + TIE_BIAS[f]
        if d > best_dot:
            best_dot = d
            best = f
    return best


@njit(cache=True, nogil=True)
def sector_forward(sin_az: float, cos_az: float, sin_half_z: float):
    """Snyder's forward inside one 120-degree sector: ``(rho sin Az', rho cos Az')``."""
    u = cos_az + sin_az * COT_THETA  # eq. 9
    sin_half_q = math.sqrt(0.5 * (1.0 - u / math.sqrt(TAN_G2 + u * u)))
    cos_h = sin_az * (SIN_G * COS_SMALL_G) - cos_az * COS_G  # eq. 6
    sin_h = math.sqrt(1.0 - cos_h * cos_h)  # H in (36, 144) degrees
    az_plus_h = math.atan2(sin_az * cos_h + cos_az * sin_h, cos_az * cos_h - sin_az * sin_h)
    if az_plus_h < 0.0:
        az_plus_h += _TWO_PI
    area = az_plus_h + (G - math.pi)  # eq. 7
    big_x = RT2 - 2.0 * area * COT_THETA  # eq. 8 as (X, Y)
    big_y = 2.0 * area
    rho = D_PRIME_NUM / (big_x + big_y * COT_THETA) * sin_half_z / sin_half_q  # eqs. 10-12
    return rho * big_y, rho * big_x


@njit(cache=True, nogil=True)
def forward_unit(centres: np.ndarray, frames: np.ndarray, px: float, py: float, pz: float):
    """Unit vector -> ``(face, x, y)`` in the face frame (unit sphere); the 120-degree sector by half-planes.

    The reduced azimuth's sine and cosine come from rotating (east, north)
    by -120 k degrees, so only the arctangent of ``Az + H`` (eq. 7) remains.
    """
    face = nearest_face(centres, px, py, pz)
    return (face, *face_forward(frames, face, px, py, pz))


@njit(cache=True, nogil=True)
def face_forward(frames: np.ndarray, face: int, px: float, py: float, pz: float):
    """Unit vector -> ``(x, y)`` in the frame of ``face``, nearest or not (the sector formulas hold past its edges)."""
    c = frames[face, 0, 0] * px + frames[face, 0, 1] * py + frames[face, 0, 2] * pz
    n = frames[face, 1, 0] * px + frames[face, 1, 1] * py + frames[face, 1, 2] * pz
    e = frames[face, 2, 0] * px + frames[face, 2, 1] * py + frames[face, 2, 2] * pz
    h2 = n * n + e * e
    if h2 == 0.0:
        return 0.0, 0.0
    # sector k = azimuth // 120 degrees: sin(Az - 120) < 0 on [0, 120), sin(Az - 240) >= 0 on [240, 360)
    if e >= 0.0 and -0.5 * e - _HALF_SQRT3 * n < 0.0 and not (e == 0.0 and n < 0.0):
        k = 0
    elif e < 0.0 and -0.5 * e + _HALF_SQRT3 * n >= 0.0:
        k = 2
    else:
        k = 1
    rc, rs = ROT_COS[k], ROT_SIN[k]
    inv_h = 1.0 / math.sqrt(h2)
    sin_az = (e * rc - n * rs) * inv_h
    cos_az = (n * rc + e * rs) * inv_h
    sin_half_z = math.sqrt(0.5 * h2 / (1.0 + c))
    sp, cp = sector_forward(sin_az, cos_az, sin_half_z)
    return sp * rc + cp * rs, cp * rc - sp * rs


@njit(cache=True, nogil=True)
def sector_of(x: float, y: float) -> int:
    """120-degree sector (planar azimuth // 120, clockwise from +y) by half-planes, no arctangent."""
    if x > 0.0 or (x == 0.0 and y >= 0.0):  # azimuth in [0, 180]
        if x == 0.0 and y == 0.0:
            return 0
        return 1 if -0.5 * x - _HALF_SQRT3 * y >= 0.0 else 0  # azimuth >= 120
    return 2 if -0.5 * x + _HALF_SQRT3 * y >= 0.0 else 1  # azimuth >= 240


@njit(cache=True, nogil=True)
def inverse_unit(frames: np.ndarray, face: int, x: float, y: float):
    """Face-frame ``(x, y)`` -> unit vector, by the exact closed form (Snyder 1992 eqs. 6-8 solved for Az; thesis ch. 4).

    Two sines and cosines in all: the sector comes from half-planes, and
    ``sin(G - A/2)``, ``sin(G - A)`` from ``sin(A/2)``, ``cos(A/2)`` by the
    angle-sum rules.
    """
    rho = math.hypot(x, y)
    k = sector_of(x, y)
    rc, rs = ROT_COS[k], ROT_SIN[k]
    if rho > TINY:
        inv_rho = 1.0 / rho
        sin_a = (x * rc - y * rs) * inv_rho
        cos_a = (y * rc + x * rs) * inv_rho
    elif rho > 0.0:  # subnormal or tiny: 1 / rho would overflow; the direction from scaled copies
        sx, sy = x * UNTINY, y * UNTINY
        inv_rho = 1.0 / math.hypot(sx, sy)
        sin_a = (sx * rc - sy * rs) * inv_rho
        cos_a = (sy * rc + sx * rs) * inv_rho
    else:
        sin_a, cos_a = 0.0, 1.0
    area = RT2 * sin_a / (2.0 * (cos_a + COT_THETA * sin_a))  # eq. 8 inverted
    sh = math.sin(0.5 * area)
    ch = math.cos(0.5 * area)
    sin_g_half = SIN_G * ch - COS_G * sh  # sin(G - A/2)
    sin_g_full = SIN_G * (ch * ch - sh * sh) - COS_G * (2.0 * sh * ch)  # sin(G - A)
    num = 2.0 * sin_g_half * sh
    den = sin_g_full - SIN_G * COS_SMALL_G
    r = math.sqrt(num * num + den * den)
    sin_az, cos_az = num / r, den / r
    u = cos_az + sin_az * COT_THETA  # eq. 9
    sin_half_q = math.sqrt(0.5 * (1.0 - u / math.sqrt(TAN_G2 + u * u)))
    d_prime = D_PRIME_NUM / (cos_a + sin_a * COT_THETA)  # eq. 10
    s = min(rho / d_prime * sin_half_q, 1.0)  # sin(z/2), eqs. 11-12 inverted
    cos_z = 1.0 - 2.0 * s * s
    sin_z = 2.0 * s * math.sqrt(1.0 - s * s)
    ct = (cos_az * rc - sin_az * rs) * sin_z  # Az + 120 k
    st = (sin_az * rc + cos_az * rs) * sin_z
    ox = cos_z * frames[face, 0, 0] + ct * frames[face, 1, 0] + st * frames[face, 2, 0]
    oy = cos_z * frames[face, 0, 1] + ct * frames[face, 1, 1] + st * frames[face, 2, 1]
    oz = cos_z * frames[face, 0, 2] + ct * frames[face, 1, 2] + st * frames[face, 2, 2]
    return ox, oy, oz


# ----------------------------------------------------------------------------
# Split (2:6) on a face plane (thesis §6.1.7; split26.py)
# ----------------------------------------------------------------------------
@njit(cache=True, nogil=True)
def level1_digit(x: float, y: float) -> int:
    """Planar azimuth // 60 degrees (clockwise from +y) by half-planes; the centre gives 0.

    ``sin(Az - t) = (x cos t - y sin t) / rho``: a point on a dividing ray
    goes to the triangle clockwise of it, as ``int(Az / 60)`` would.
    """
    if x > 0.0 or (x == 0.0 and y >= 0.0):
        if x == 0.0 and y == 0.0:
            return 0
        if -0.5 * x - _HALF_SQRT3 * y >= 0.0:  # Az >= 120
            return 2
        if 0.5 * x - _HALF_SQRT3 * y >= 0.0:  # Az >= 60
            return 1
        return 0
    if 0.5 * x + _HALF_SQRT3 * y >= 0.0:  # Az >= 300
        return 5
    if -0.5 * x + _HALF_SQRT3 * y >= 0.0:  # Az >= 240
        return 4
    return 3


@njit(cache=True, nogil=True)
def level1_start(x: float, y: float):
    """Level-1 digit (planar azimuth // 60 degrees) and the point in that triangle's canonical frame."""
    d = level1_digit(x, y)
    dx, dy = x - L1_C[d, 0], y - L1_C[d, 1]
    m = L1_ROWS[d]
    return d, m[0, 0] * dx + m[0, 1] * dy, m[1, 0] * dx + m[1, 1] * dy


@njit(cache=True, nogil=True)
def descend(px: float, py: float):
    """One level down in the canonical frame: child digit and the point in the child's frame.

    Child 0 (BCD) lies on C's side of BD (``sqrt3 x + y < 1``), child 2 (ADE)
    on A's side of DE (``sqrt3 x - y > 1``), child 1 between them.
    """
    sx = SQRT3 * px
    # branch-free (the digits of random points are random): 0 wins over 2
    c = (1 - int(sx + py < 1.0)) * (1 + int(sx - py > 1.0))
    return (
        c,
        CHILD_M[c, 0, 0] * px + CHILD_M[c, 0, 1] * py + CHILD_T[c, 0],
        CHILD_M[c, 1, 0] * px + CHILD_M[c, 1, 1] * py + CHILD_T[c, 1],
    )


@njit(cache=True, nogil=True)
def descend4(px: float, py: float):
    """Four levels down at once: packed digit codes (8 bits, first level highest) and the point.

    One look-up in split26's jump table (a grid over the canonical triangle
    whose cells lie inside one level-4 descendant); points in ambiguous grid
    cells, near an edge, take four exact steps of :func:`descend`.
    """
    fx = min(max(px * _JUMP_SX + 1.0, 0.0), GRID_W + 1.0)
    fy = min(max(py * GRID_H + 1.0, 0.0), GRID_H + 1.0)
    code = JUMP_TABLE[int(fy) * _JUMP_W2 + int(fx)]
    if code == AMBIGUOUS:
        packed = np.uint64(0)
        for _ in range(4):
            c, px, py = descend(px, py)
            packed = (packed << np.uint64(2)) | np.uint64(c + 1)
        return packed, px, py
    m = JUMP_MAPS[code]
    return JUMP_PACKED[code], m[0] * px + m[1] * py + m[4], m[2] * px + m[3] * py + m[5]


@njit(cache=True, nogil=True)
def child_corners(ax, ay, bx, by, cx, cy, digit: int):
    """Corners (A, B, C) of child ``digit`` of the 30-60-90 triangle (A, B, C).

    D is a third of the way from C to A, E the midpoint of AB; children
    0 = (B, D, C), 1 = (B, D, E), 2 = (A, D, E).
    """
    dx, dy = cx + (ax - cx) / 3.0, cy + (ay - cy) / 3.0
    if digit == 0:
        return bx, by, dx, dy, cx, cy
    ex, ey = 0.5 * (ax + bx), 0.5 * (ay + by)
    if digit == 1:
        return bx, by, dx, dy, ex, ey
    return ax, ay, dx, dy, ex, ey


# ----------------------------------------------------------------------------
# Loops for the checked forward / inverse of snyder (below) and ivea (any orientation)
# ----------------------------------------------------------------------------
def face_loops(forward_unit, inverse_unit, name: str) -> tuple[Loops, Loops]:
    """The batch loops over one projection's per-point maps (Snyder's, IVEA's).

    ``forward_rad(n, lat, lng, centres, frames, face, x, y)`` and ``inverse_deg(n, face, x, y, frames, lat, lng)``;
    ``name`` keeps each projection's compiled code in its own cache entries.
    """

    def _forward_rad(lat, lng, centres, frames, face, x, y):
        for i in prange(lat.shape[0]):
            cl, sl = math.cos(lat[i]), math.sin(lat[i])
            face[i], x[i], y[i] = forward_unit(centres, frames, cl * math.cos(lng[i]), cl * math.sin(lng[i]), sl)

    def _inverse_deg(face, x, y, frames, lat, lng):
        for i in prange(face.shape[0]):
            px, py, pz = inverse_unit(frames, face[i], x[i], y[i])
            lat[i], lng[i] = math.degrees(math.atan2(pz, math.hypot(px, py))), math.degrees(math.atan2(py, px))

    _forward_rad.__qualname__, _inverse_deg.__qualname__ = f"{name}_forward_rad", f"{name}_inverse_deg"
    return loops(_forward_rad), loops(_inverse_deg)


forward_rad, inverse_deg = face_loops(forward_unit, inverse_unit, "snyder")


def write_jump_file() -> None:
    """Rewrite the shipped jump table from :func:`jump_constants` (after a change to split26)."""
    table, packed, maps = jump_constants()
    np.savez_compressed(JUMP_FILE, table=table, packed=packed, maps=maps)
