"""The transformer from an input's CRS to WGS84 longitude and latitude."""

from __future__ import annotations

from typing import Any

from dggs.errors import DggsValueError

__all__ = ["make_transformer"]


def make_transformer(crs: Any) -> Any:
    """Return a pyproj transformer from ``crs`` to WGS84 (x, y order), or None.

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
    if source == CRS.from_epsg(4326):
        return None
    return Transformer.from_crs(source, CRS.from_epsg(4326), always_xy=True)
