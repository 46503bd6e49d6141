"""Pydantic models of the OGC documents the server builds most: landing page, collections, DGGRS list, zone info.

Each model states the members of the standard's schema (OGC API - Common ``landingPage.yaml``,
``collectionDesc.yaml``, ``collections.yaml``; OGC API - DGGS ``rDGGRSList.yaml``, ``dggrs-item.yaml``,
``zone-info.yaml``) with this server's additions, and forbids any other member, so a builder cannot send a
misspelt one.  :func:`json_response` serialises a model without the members the builder left unset (an
explicit ``None``, like a level-0 zone's ``parent``, stays ``null``).

Measured (``benchmarks/bench_handwritten_server.py``): building a document as a model and serialising it
with ``model_dump_json`` cost 9-30 µs more than a dict and ``json.dumps`` in one run and at most 160 µs in
another (the zone information is faster in both, pydantic's serialiser writing its geometry's floats quicker),
against a request's 57 ms median under load (bench_serve.py): 0.3 % at worst, so the documents are models.

Examples
--------
>>> page = LandingPage.model_validate({"title": "t", "links": [{"href": "http://h/", "rel": "self",
...                                                             "type": "application/json"}]})
>>> json_response(page).body
b'{"title":"t","links":[{"href":"http://h/","rel":"self","type":"application/json"}]}'
>>> LandingPage.model_validate({"links": [{"href": "http://h/"}]})  # a link without rel
Traceback (most recent call last):
...
pydantic_core._pydantic_core.ValidationError: 1 validation error for LandingPage
...
"""

from __future__ import annotations

from typing import Any

from fastapi.responses import Response
from pydantic import BaseModel, ConfigDict

__all__ = ["Link", "LandingPage", "Collection", "Collections", "DggrsItem", "DggrsList", "ZoneStatistics",
           "ZoneInfo", "json_response"]


class _Model(BaseModel):
    model_config = ConfigDict(extra="forbid")


class Link(_Model):
    """A link (``common-core/link.yaml``): ``href`` and ``rel`` required."""

    href: str
    rel: str
    type: str | None = None
    title: str | None = None


class LandingPage(_Model):
    """The landing page (``common-core/landingPage.yaml``)."""

    title: str | None = None
    description: str | None = None
    links: list[Link]


class Spatial(_Model):
    """The spatial extent: one bbox (w, s, e, n) and its CRS."""

    bbox: list[list[float]]
    crs: str | None = None


class Extent(_Model):
    """A collection's extent (``common-geodata/extent.yaml``, its spatial part)."""

    spatial: Spatial


class Collection(_Model):
    """One collection (``common-geodata/collectionDesc.yaml``)."""

    id: str
    title: str | None = None
    description: str | None = None
    extent: Extent | None = None
    crs: list[str] | None = None
    storageCrs: str | None = None
    itemType: str | None = None
    updated: str | None = None
    created: str | None = None
    links: list[Link]


class Collections(_Model):
    """The collections (``common-geodata/collections.yaml``)."""

    links: list[Link]
    collections: list[Collection]
    numberMatched: int | None = None
    numberReturned: int | None = None


class DggrsItem(_Model):
    """An entry of the DGGRS list (``dggs-core/dggrs-item.yaml``)."""

    id: str
    title: str
    uri: str | None = None
    links: list[Link]


class DggrsList(_Model):
    """The DGGRS list (``rDGGRSList.yaml``)."""

    links: list[Link] | None = None
    dggrs: list[DggrsItem]


class ZoneStatistics(_Model):
    """Summary statistics of one field in a zone (``zone-info.yaml``'s ``statistics``)."""

    minimum: float | None = None
    maximum: float | None = None
    average: float | None = None
    stdDev: float | None = None


class Geometry(_Model):
    """A GeoJSON Polygon or MultiPolygon (the zone's region)."""

    type: str
    coordinates: list[Any]


class ZoneInfo(_Model):
    """Zone information (``dggs-core/zone-info.yaml``, and this server's parent, children, neighbours, ids)."""

    id: str
    level: int
    shapeType: str
    crs: str
    centroid: list[float]
    bbox: list[float]
    areaMetersSquare: float
    uint64Id: str
    parent: str | None
    children: list[str]
    neighbors: list[str]
    geometry: Geometry
    links: list[Link]
    dataCount: int | None = None
    statistics: dict[str, ZoneStatistics] | None = None


def json_response(model: BaseModel, media_type: str = "application/json") -> Response:
    """``model`` as a JSON response, without the members left unset."""
    return Response(model.model_dump_json(exclude_unset=True), media_type=media_type)
