"""Chapter 4, Table 4.1: least-squares polynomial fits of ``Az`` against ``Az'`` over a sector.

How the thesis's table is reproduced (sample size, radians, the full
120-degree sector, area-spaced ``Az'``) is told in
:mod:`dggs.experiments.chapter4`.
"""

from __future__ import annotations

import statistics
from dataclasses import dataclass
from functools import lru_cache
from typing import Any

import numpy as np

from dggs.experiments import numpy_snyder
from dggs.experiments.chapter4_constants import _HALF, _SECTOR, _SECTOR_AREA, THESIS_TABLE_4_1
from dggs.geometry import snyder

__all__ = ["implied_sample_size", "exact_az", "sector_samples", "SectorFit", "fit_sector", "fit_table"]


# ----------------------------------------------------------------------------
# Table 4.1: polynomial fits of Az against Az'
# ----------------------------------------------------------------------------
def implied_sample_size() -> int:
    """Sample size implied by thesis Table 4.1: the median over degrees of ``SS/var + p``.

    gnuplot reports ``var = SS / (N - p)`` with ``p = degree + 1`` parameters.
    Degree 2's pair (N about 5,587) is an outlier; the median ignores it.

    Examples
    --------
    >>> implied_sample_size()
    5871
    """
    ns = [round(ss / var) + d + 1 for d, (ss, var) in THESIS_TABLE_4_1.items()]
    return int(statistics.median(ns))


def exact_az(ap: np.ndarray) -> np.ndarray:
    """Exact spherical azimuth ``Az`` of planar azimuths ``Az'`` in [0, 120] degrees (radians).

    The closed form (Snyder 1992 eqs. 6-7 solved for Az; thesis chapter 4): what Newton converges to.
    """
    ap = np.asarray(ap, dtype=float)
    return numpy_snyder.az_closed(numpy_snyder.area_from_planar(np.sin(ap), np.cos(ap)))


def sector_samples(n: int, sampling: str = "area") -> np.ndarray:
    """``n`` planar azimuths ``Az'`` (radians) for fitting ``Az ~ P(Az')``.

    Parameters
    ----------
    n : int
        Number of samples.
    sampling : {"area", "uniform", "half"}
        ``"area"``: the full 120-degree sector at equal steps of the area swept
        from the vertex (midpoint rule), i.e. ``Az'`` distributed like the
        points of a face; ``"uniform"``: equally spaced over the full sector;
        ``"half"``: equally spaced over 0-60 degrees (the library's range).

    Returns
    -------
    ndarray
        Planar azimuths in radians, increasing.
    """
    if sampling == "area":
        # Swept planar area A = A_G (equal-area map); eq. 8 gives Az' of A.
        area = (np.arange(n) + 0.5) / n * _SECTOR_AREA
        rt2 = (snyder.R_PRIME * snyder.TAN_G) ** 2
        return np.arctan2(2.0 * area, rt2 - 2.0 * snyder.COT_THETA * area)
    if sampling == "uniform":
        return np.linspace(0.0, _SECTOR, n)
    if sampling == "half":
        return np.linspace(0.0, _HALF, n)
    raise ValueError(f"sampling {sampling!r} is not one of area, uniform, half")


@dataclass(frozen=True)
class SectorFit:
    """A least-squares polynomial ``Az ~ P(Az')`` over a sector (radians).

    Attributes
    ----------
    degree : int
        Polynomial degree.
    coeffs : ndarray
        Coefficients, highest power first, in the variable ``(Az' - centre) / scale``.
    centre, scale : float
        Affine change of variable (for conditioning; it does not change the fit).
    half : bool
        True for a 0-60 degree fit used with the mirror ``Az(120 - a) = 120 - Az(a)``.
    ss, var : float
        Sum of squares of residuals and ``ss / (n - degree - 1)``.
    n : int
        Number of samples.
    """

    degree: int
    coeffs: np.ndarray
    centre: float
    scale: float
    half: bool
    ss: float
    var: float
    n: int

    def __call__(self, ap: np.ndarray) -> np.ndarray:
        """``Az`` of planar azimuths ``Az'`` reduced to [0, 120) degrees (radians)."""
        ap = np.asarray(ap, dtype=float)
        if not self.half:
            return np.polyval(self.coeffs, (ap - self.centre) / self.scale)
        upper = ap > _HALF
        t = np.where(upper, _SECTOR - ap, ap)
        az = np.polyval(self.coeffs, (t - self.centre) / self.scale)
        return np.where(upper, _SECTOR - az, az)


@lru_cache(maxsize=64)
def fit_sector(degree: int, n: int | None = None, sampling: str = "area") -> SectorFit:
    """Fit ``Az ~ P(Az')`` of ``degree`` by least squares (thesis §4.1.2).

    Parameters
    ----------
    degree : int
        1..9.
    n : int, optional
        Samples (default: :func:`implied_sample_size`).
    sampling : str
        See :func:`sector_samples`.

    Returns
    -------
    SectorFit
    """
    n = implied_sample_size() if n is None else n
    ap = sector_samples(n, sampling)
    az = exact_az(ap)
    lo, hi = float(ap.min()), float(ap.max())
    centre, scale = 0.5 * (lo + hi), 0.5 * (hi - lo)
    t = (ap - centre) / scale
    vander = np.vander(t, degree + 1)
    coeffs, *_ = np.linalg.lstsq(vander, az, rcond=None)
    resid = az - vander @ coeffs
    ss = float(resid @ resid)
    coeffs.setflags(write=False)
    return SectorFit(degree, coeffs, centre, scale, sampling == "half", ss, ss / (n - degree - 1), n)


def fit_table(n: int | None = None) -> list[dict[str, Any]]:
    """Rows of our Table 4.1: SS and variance for degrees 1-7, three samplings.

    ``ss``/``var`` use the full-sector, area-spaced sample (our reproduction);
    ``ss_uniform`` equally spaced ``Az'`` over the full sector; ``ss_half``
    equally spaced over 0-60 degrees.
    """
    rows = []
    for d in range(1, 8):
        f = fit_sector(d, n, "area")
        rows.append({
            "degree": d,
            "ss": f.ss,
            "var": f.var,
            "ss_uniform": fit_sector(d, n, "uniform").ss,
            "ss_half": fit_sector(d, n, "half").ss,
            "thesis_ss": THESIS_TABLE_4_1[d][0],
            "thesis_var": THESIS_TABLE_4_1[d][1],
        })
    return rows
