"""The transformer from an input's CRS to WGS84 longitude and latitude, and the checked transform."""

from __future__ import annotations

from typing import Any

import numpy as np

from dggs.errors import DggsValueError

__all__ = ["make_transformer", "transform_points"]


def make_transformer(crs: Any) -> Any:
    """Return a pyproj transformer from ``crs`` to WGS84 (x, y order), or None if there is nothing to do.

    Raises
    ------
    DggsValueError
        If pyproj does not know the CRS.

    Examples
    --------
    >>> make_transformer("EPSG:4326") is None
    True
    >>> t = make_transformer("EPSG:3857")
    >>> [round(v, 6) for v in t.transform(0.0, 0.0)]
    [0.0, 0.0]
    """
    if crs is None:
        return None
    from pyproj import CRS, Transformer
    from pyproj.exceptions import CRSError

    try:
        source = CRS.from_user_input(crs)
    except CRSError as exc:
        raise DggsValueError(f"unknown CRS {crs!r}: {exc}") from exc
    if source == CRS.from_epsg(4326) or source == CRS.from_user_input("OGC:CRS84"):
        return None
    return Transformer.from_crs(source, CRS.from_epsg(4326), always_xy=True)


def transform_points(transformer: Any, lat: np.ndarray, lng: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """WGS84 (lat, lng) of points given as (y, x) in the transformer's CRS, and which could not be.

    The third array marks finite points that do not transform back to
    themselves: pyproj clamps what lies outside a projection's domain
    (EPSG:3857's (1e20, 1e20) gives lat 90), so such a point was never in
    the CRS.  Points that are not finite are transformed as (0, 0) and not
    marked: their own check names them.
    """
    ok = np.isfinite(lat) & np.isfinite(lng)
    x0, y0 = np.where(ok, lng, 0.0), np.where(ok, lat, 0.0)
    x, y = transformer.transform(x0, y0)
    bx, by = transformer.transform(x, y, direction="INVERSE")
    with np.errstate(invalid="ignore"):
        back = np.isclose(bx, x0, rtol=1e-9, atol=1e-6) & np.isclose(by, y0, rtol=1e-9, atol=1e-6)
    lng, lat = np.asarray(x, dtype=np.float64), np.asarray(y, dtype=np.float64)
    failed: np.ndarray = ok & ~(np.isfinite(lat) & np.isfinite(lng) & back)
    return lat, lng, failed
