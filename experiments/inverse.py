"""The inverse Snyder methods that only the thesis uses (chapter 4): Newton and the polynomial.

:func:`dggs.geometry.snyder.inverse` is the exact closed form.  The thesis
inverts Snyder's eq. 8 for the spherical azimuth ``Az`` by Newton-Raphson
(thesis eqs. 3.8-3.9, from ``Az0 = Az'``), proposes a polynomial start
(§4.1.2) and the polynomial alone (§4.1.3).  They live here, beside the
experiments that measure them (:mod:`dggs.experiments.chapter4`,
``benchmarks/bench_snyder.py``).

Methods: ``"closed"`` (the library's), ``"newton"``, ``"newton-poly"``,
``"poly"``.

Examples
--------
>>> from dggs.geometry import snyder
>>> face, x, y = snyder.forward(10.0, 20.0)
>>> [round(v, 9) for v in inverse(face, x, y, method="newton")]
[10.0, 20.0]
>>> lat, lng, it = inverse(face, x, y, method="newton-poly", return_iterations=True)
>>> it <= 3
True
"""

from __future__ import annotations

import math
from functools import lru_cache

import numpy as np

from dggs.errors import DggsValueError
from dggs.experiments import numpy_snyder
from dggs.geometry import snyder
from dggs.geometry.icosahedron import ISEA, Orientation, xyz_to_latlng
from dggs.geometry.snyder import G_ARC, G

__all__ = ["METHODS", "polynomial", "newton", "az_poly", "inverse_xyz", "inverse"]

#: Inverse methods: the exact closed form, Snyder's Newton-Raphson, Newton from
#: a polynomial start (thesis §4.1.2) and the polynomial alone (thesis §4.1.3).
METHODS = ("closed", "newton", "newton-poly", "poly")

_SECTOR = 2 * math.pi / 3
_SIN_G, _COS_G = math.sin(G), math.cos(G)
_COS_SMALL_G = math.cos(G_ARC)


def _check_options(degree, tol, max_iter) -> None:
    """Reject a polynomial degree, Newton tolerance or iteration cap that cannot work, naming it."""
    if isinstance(degree, (bool, np.bool_)) or not isinstance(degree, (int, np.integer)) or not 1 <= degree <= 9:
        raise DggsValueError(f"degree {degree!r} must be an integer 1..9")
    if (
        isinstance(tol, (bool, np.bool_))
        or not isinstance(tol, (int, float, np.integer, np.floating))
        or not math.isfinite(tol)
        or tol <= 0
    ):
        raise DggsValueError(f"tol {tol!r} must be a finite number > 0 (radians)")
    if isinstance(max_iter, (bool, np.bool_)) or not isinstance(max_iter, (int, np.integer)) or max_iter < 1:
        raise DggsValueError(f"max_iter {max_iter!r} must be an integer >= 1")


def newton(area: np.ndarray, az0: np.ndarray, tol: float, max_iter: int):
    """Snyder's Newton-Raphson for Az (thesis eqs. 3.8-3.9), all points at once.

    Returns ``(az, iterations)``; a point stops once its step is below ``tol``.
    """
    az = az0.copy()
    iterations = np.zeros(az.shape, dtype=np.int64)
    active = np.arange(az.size)
    for _ in range(max_iter):
        if active.size == 0:
            break
        a = az[active]
        sa, ca = np.sin(a), np.cos(a)
        cos_h = sa * (_SIN_G * _COS_SMALL_G) - ca * _COS_G
        h = np.arccos(np.clip(cos_h, -1.0, 1.0))
        f = area[active] - (a + G + h - math.pi)
        fprime = (ca * (_SIN_G * _COS_SMALL_G) + sa * _COS_G) / np.sqrt(1.0 - cos_h * cos_h) - 1.0
        step = f / fprime
        az[active] = a - step
        iterations[active] += 1
        active = active[np.abs(step) > tol]
    return az, iterations


@lru_cache(maxsize=8)
def polynomial(degree: int = 3) -> np.ndarray:
    """Least-squares polynomial Az ~ P(Az') over Az' in [0, 60] degrees (thesis §4.1.2).

    Coefficients, highest power first (for :func:`numpy.polyval`), in radians.
    The fit uses the exact closed form on 4,001 Chebyshev-spaced azimuths; the
    other half of the 120-degree sector follows by symmetry about 60 degrees.

    Examples
    --------
    >>> polynomial(1).shape
    (2,)
    """
    if not 1 <= degree <= 9:
        raise DggsValueError(f"polynomial degree {degree!r} is out of range 1..9")
    half = math.pi / 3
    t = 0.5 * half * (1 - np.cos(np.linspace(0.0, math.pi, 4001)))
    az = numpy_snyder.az_closed(numpy_snyder.area_from_planar(np.sin(t), np.cos(t)))
    coeffs = np.polyfit(t, az, degree)
    coeffs.setflags(write=False)
    return coeffs


def az_poly(a: np.ndarray, degree: int) -> np.ndarray:
    """Polynomial Az of planar Az' in [0, 120) degrees, symmetric about 60."""
    coeffs = polynomial(degree)
    upper = a > math.pi / 3
    t = np.where(upper, _SECTOR - a, a)
    az = np.polyval(coeffs, t)
    return np.where(upper, _SECTOR - az, az)


def inverse_xyz(
    face,
    x,
    y,
    orientation: Orientation = ISEA,
    method: str = "closed",
    *,
    degree: int = 3,
    tol: float = 1e-13,
    max_iter: int = 10,
):
    """Unit vectors (N, 3) and Newton iteration counts of face-plane points, by ``method``.

    No checks; see :func:`inverse` for the checked version.
    """
    ap, k, sin_a, cos_a, rho = numpy_snyder.planar_azimuth(x, y)
    area = numpy_snyder.area_from_planar(sin_a, cos_a)
    iterations = np.zeros(ap.shape, dtype=np.int64)
    if method == "closed":
        sin_az, cos_az = numpy_snyder.az_closed_sincos(area)
    else:
        if method == "newton":
            az, iterations = newton(area, ap, tol, max_iter)
        elif method == "newton-poly":
            az, iterations = newton(area, az_poly(ap, degree), tol, max_iter)
        elif method == "poly":
            az = az_poly(ap, degree)
        else:
            raise DggsValueError(f"inverse method {method!r} is not one of {', '.join(METHODS)}")
        sin_az, cos_az = np.sin(az), np.cos(az)
    return numpy_snyder.sector_to_xyz(face, k, sin_az, cos_az, sin_a, cos_a, rho, orientation), iterations


def inverse(
    face,
    x,
    y,
    method: str = "closed",
    orientation: Orientation = ISEA,
    *,
    degree: int = 3,
    tol: float = 1e-13,
    max_iter: int = 10,
    return_iterations: bool = False,
):
    """:func:`dggs.geometry.snyder.inverse` with the thesis's methods (checked input).

    Parameters
    ----------
    face, x, y
        As :func:`dggs.geometry.snyder.inverse`.
    method : {"closed", "newton", "newton-poly", "poly"}
        ``"closed"`` is the exact formula (the library's); ``"newton"`` is
        Snyder's Newton-Raphson from ``Az0 = Az'``; ``"newton-poly"`` starts
        Newton from a polynomial in ``Az'`` of ``degree`` (thesis §4.1.2);
        ``"poly"`` uses the polynomial alone (thesis §4.1.3, approximate: at
        degree 3 about 300 m on average and 1.7 km at worst on the Earth,
        degree 7 about 3.5 m / 17 m).
    orientation : Orientation
        The icosahedron's orientation.
    degree : int
        Polynomial degree for the polynomial methods (1-9).
    tol, max_iter : float, int
        Newton stops when the step is below ``tol`` radians or after
        ``max_iter`` iterations.
    return_iterations : bool
        Also return the number of Newton iterations of each point.

    Raises
    ------
    CoordinateError
        Bad coordinates (as :func:`dggs.geometry.snyder.inverse`).
    DggsValueError
        An unknown ``method``, or a ``degree`` outside 1..9, a ``tol`` that is
        not a finite number > 0, or a ``max_iter`` below 1 (each named).

    Examples
    --------
    >>> lat, lng = inverse(0, 0.0, 0.0, method="poly")
    >>> round(float(lat), 6), round(float(lng), 6)
    (69.094843, -78.75)
    """
    if method not in METHODS:
        raise DggsValueError(f"inverse method {method!r} is not one of {', '.join(METHODS)}")
    _check_options(degree, tol, max_iter)
    face_a, x_a, y_a, shape, scalar = snyder.checked_face_xy(face, x, y)
    xyz, iterations = inverse_xyz(face_a, x_a, y_a, orientation, method, degree=degree, tol=tol, max_iter=max_iter)
    la, lo = xyz_to_latlng(xyz)
    lat, lng = np.degrees(la), np.degrees(lo)
    if scalar:
        pair = (float(lat[0]), float(lng[0]))
        return (*pair, int(iterations[0])) if return_iterations else pair
    arrays = (lat.reshape(shape), lng.reshape(shape))
    return (*arrays, iterations.reshape(shape)) if return_iterations else arrays
