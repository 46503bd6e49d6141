"""The parameters of a zone query (OGC API - DGGS Part 1, §12, the *Zone Query* class) and its paging.

- ``parent-zone`` (/req/zone-query/parent-zone): only the zones inside that zone;
- ``subset`` with ``subset-crs`` (/req/zone-query/subset, /req/zone-query/subset-crs), in the syntax of
  OGC API - Common Part 2 and Coverages: ``Lat(lo:hi)``, ``Lon(lo:hi)`` (trims) or ``Lat(v)`` (a slice),
  ``*`` for an open end, several separated by commas or in several ``subset`` parameters; ``Lon(lo:hi)``
  with ``lo > hi`` crosses the antimeridian, as ``bbox`` does;
- ``bbox-crs`` and ``subset-crs``: CRS84 only (its URI, https or http, or the CURIE ``[OGC:CRS84]``);
- ``bbox`` and ``subset`` together are a 400 (one spatial filter per request);
- ``limit`` and ``offset``: a page of the list, with ``next`` and ``prev`` links (/rec/zone-query/paging);
- ``geometry`` of GeoJSON features: ``zone-region`` (the default, also ``vectorized``), ``zone-centroid``
  (a Point) or ``none`` (a null geometry).

Examples
--------
>>> parse_subset(["Lat(35:60),Lon(-10:30)"])
(-10.0, 35.0, 30.0, 60.0)
>>> parse_subset(["Lon(170:-170)"])
(170.0, -90.0, -170.0, 90.0)
>>> check_geometry(None), check_geometry("zone-centroid")
('zone-region', 'zone-centroid')
"""

from __future__ import annotations

import json
import math
import re
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
from fastapi import Depends, Query

import dggs

from .dggrs import CRS84
from .errors import BadRequest
from .params import parse_zone

__all__ = ["CRS84_NAMES", "check_crs", "parse_subset", "parent_range", "check_geometry", "geometry_texts",
           "page_links", "GEOMETRIES", "ZoneQuery", "ZONE_QUERY", "CRS_QUERY"]

#: The names of CRS84 that ``bbox-crs`` and ``subset-crs`` take.
CRS84_NAMES = frozenset({CRS84, CRS84.replace("http://", "https://"), "[OGC:CRS84]", "OGC:CRS84"})

#: ``geometry`` values (the standard's enumeration; ``vectorized`` is the zone region for zones).
GEOMETRIES = ("zone-region", "vectorized", "zone-centroid", "none")

_NUMBER = r"[^():,\s]+"
_TERM = rf"\s*([A-Za-z][\w.-]*)\s*\(\s*({_NUMBER})\s*(?::\s*({_NUMBER})\s*)?\)\s*"
_TERMS = re.compile(rf"{_TERM}(?:,{_TERM})*")
_ONE = re.compile(_TERM)
_AXES = {"lat": ("Lat", -90.0, 90.0), "lon": ("Lon", -180.0, 180.0)}
#: Half the height or width given to a slice (a subset with one value): about 0.1 mm.
_SLICE = 1e-9


def check_crs(name: str, value: str | None) -> None:
    """400 unless ``value`` is None or names CRS84 (/req/zone-query/bbox-crs, /req/zone-query/subset-crs).

    Raises
    ------
    BadRequest
        Naming the parameter and the CRS it does not support.
    """
    if value is not None and value.strip() not in CRS84_NAMES:
        raise BadRequest(f"{name} {value!r} is not supported; the only CRS is {CRS84} (or [OGC:CRS84])")


def _bound(axis: str, text: str, raw: str, lo: float, hi: float, star: float) -> float:
    if text == "*":
        return star
    try:
        value = float(text)
    except ValueError:
        raise BadRequest(f"subset {raw!r}: {text!r} is not a number (nor '*') for axis {axis}") from None
    if not math.isfinite(value) or not lo <= value <= hi:
        raise BadRequest(f"subset {raw!r}: {axis} {text} is outside {lo:g}..{hi:g}")
    return value


def parse_subset(values: Sequence[str]) -> tuple[float, float, float, float] | None:
    """The ``subset`` parameters as a box ``w, s, e, n`` in CRS84 degrees (None without any).

    Raises
    ------
    BadRequest
        For a malformed subset, an axis other than Lat and Lon (named), an axis given twice, a number
        out of range or a latitude trim whose low end is above its high end.
    """
    ranges: dict[str, tuple[float, float]] = {}
    for raw in values:
        if not _TERMS.fullmatch(raw):
            raise BadRequest(f"subset {raw!r} must be axis(low:high) or axis(value), e.g. Lat(35:60),Lon(-10:30)")
        for m in _ONE.finditer(raw):
            name, first, second = m.group(1), m.group(2), m.group(3)
            if name.lower() not in _AXES:
                raise BadRequest(f"subset {raw!r}: unknown axis {name!r}; the axes of CRS84 are Lat and Lon")
            axis, lo, hi = _AXES[name.lower()]
            if axis in ranges:
                raise BadRequest(f"subset {raw!r}: axis {axis} is given more than once")
            low = _bound(axis, first, raw, lo, hi, lo)
            high = low if second is None and first != "*" else _bound(axis, second or "*", raw, lo, hi, hi)
            if second is None:  # a slice: the zones on that parallel or meridian
                low, high = max(lo, low - _SLICE), min(hi, high + _SLICE)
            if axis == "Lat" and low > high:
                raise BadRequest(f"subset {raw!r}: Lat low {low:g} is above high {high:g}")
            if low == high:
                raise BadRequest(f"subset {raw!r}: {axis} low and high are equal (an empty range)")
            ranges[axis] = (low, high)
    if not ranges:
        return None
    s, n = ranges.get("Lat", (-90.0, 90.0))
    w, e = ranges.get("Lon", (-180.0, 180.0))
    return (w, s, e, n)


def parent_range(ids: np.ndarray, raw: str, level: int) -> slice:
    """The slice of the sorted zone ids ``ids`` (all at ``level``) inside the zone ``raw``.

    A zone's descendants are the ids in ``[parent, parent + "~")`` (the ids' prefix order), so this is
    two binary searches (/req/zone-query/parent-zone).

    Raises
    ------
    BadRequest
        If ``raw`` is not a zone id, or is finer than ``level``.

    Examples
    --------
    >>> parent_range(np.array(["C00", "C01", "C10", "D00"]), "C0", 2)
    slice(0, 2, None)
    """
    try:
        parent = parse_zone(raw)
    except BadRequest as exc:
        raise BadRequest(f"parent-zone: {exc.detail}") from None
    if dggs.get_level(parent) > level:
        raise BadRequest(f"parent-zone {raw!r} is at level {dggs.get_level(parent)}, finer than "
                         f"zone-level {level}; use a parent-zone of level 0..{level}")
    lo = int(np.searchsorted(ids, parent, side="left"))
    hi = int(np.searchsorted(ids, parent + "~", side="left"))
    return slice(lo, hi)


def check_geometry(value: str | None) -> str:
    """The ``geometry`` parameter, ``zone-region`` by default.

    Raises
    ------
    BadRequest
        For a value outside the standard's enumeration.
    """
    if value is None:
        return "zone-region"
    if value not in GEOMETRIES:
        raise BadRequest(f"geometry {value!r} is not one of {', '.join(GEOMETRIES)}")
    return "zone-region" if value == "vectorized" else value


def geometry_texts(reader: Any, zones: Sequence[str], mode: str) -> list[str]:
    """GeoJSON geometry text of each zone: its region, its centroid (a Point) or ``null``."""
    if mode == "none":
        return ["null"] * len(zones)
    if mode == "zone-centroid":
        if not len(zones):
            return []
        lat, lng = reader.grid.cell_to_latlng(np.array(zones, dtype=str))
        return [json.dumps({"type": "Point", "coordinates": [round(float(x), 7), round(float(y), 7)]})
                for x, y in zip(np.atleast_1d(lng), np.atleast_1d(lat), strict=True)]
    _, texts = reader.geometries(np.array(zones, dtype=str))
    return list(texts)


def page_links(request: Any, offset: int, limit: int | None, returned: int, matched: int,
               media: str) -> list[dict[str, Any]]:
    """``next`` and ``prev`` links of a page (``offset`` replaced in the request's own URL)."""
    if limit is None:
        return []
    links = []
    if offset + returned < matched:
        href = str(request.url.include_query_params(offset=offset + returned))
        links.append({"href": href, "rel": "next", "type": media, "title": "Next page"})
    if offset > 0:
        href = str(request.url.include_query_params(offset=max(0, offset - limit)))
        links.append({"href": href, "rel": "prev", "type": media, "title": "Previous page"})
    return links


@dataclass(frozen=True)
class ZoneQuery:
    """The parameters of a zone query, as given (checked by :func:`zones_list`)."""

    zone_level: int | None = None
    bbox: str | None = None
    bbox_crs: str | None = None
    compact: bool = True
    limit: int | None = None
    offset: int = 0
    parent: str | None = None
    subset: tuple[str, ...] = ()
    subset_crs: str | None = None
    geometry: str | None = None
    crs: str | None = None


#: The ``crs`` parameter of the zone query and zone data (the standard's): only CRS84, the one CRS served.
CRS_QUERY = Query(None, description="CRS of the GeoJSON geometries: only CRS84 (the default)")


def _zone_query(
    zone_level: int | None = Query(None, alias="zone-level", description="Level of the zones (default: stored)"),
    bbox: str | None = Query(None, description="w,s,e,n in CRS84 degrees (w > e crosses the antimeridian)"),
    bbox_crs: str | None = Query(None, alias="bbox-crs", description="CRS of bbox: only CRS84 (the default)"),
    compact_zones: bool = Query(True, alias="compact-zones", description="Complete sets of children as parent"),
    limit: int | None = Query(None, description="Return at most this many zones (a page; see offset)"),
    offset: int = Query(0, description="Skip this many zones (paging; the next link gives it)"),
    parent_zone: str | None = Query(None, alias="parent-zone", description="Only zones inside this zone"),
    subset: list[str] | None = Query(None, description="Lat(lo:hi),Lon(lo:hi) in CRS84 degrees; not with bbox"),
    subset_crs: str | None = Query(None, alias="subset-crs", description="CRS of subset: only CRS84"),
    geometry: str | None = Query(None, description="GeoJSON geometry: zone-region (default), vectorized, "
                                                           "zone-centroid or none"),
    crs: str | None = CRS_QUERY,
) -> ZoneQuery:
    return ZoneQuery(zone_level, bbox, bbox_crs, compact_zones, limit, offset, parent_zone,
                     tuple(subset or ()), subset_crs, geometry, crs)


#: The zone query's parameters as one FastAPI dependency (a :class:`ZoneQuery`).
ZONE_QUERY = Depends(_zone_query)
