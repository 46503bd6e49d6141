"""OGC API - Features Part 1 (core, GeoJSON, OAS 3.0) beside OGC API - DGGS, on the same collection.

The store's non-empty zones of one level are the collection's features, so GIS clients that speak OGC API -
Features (GDAL's OGCAPI driver and so QGIS, OWSLib, ...) read the data without knowing DGGS:

- ``/collections/{collectionId}/items`` (/req/core/fc-op): a GeoJSON FeatureCollection of a page of the zones
  at ``zone-level`` (default: the stored level) holding rows, in id order.  Each Feature has the zone id as its
  ``id``, the zone's polygon (a MultiPolygon across the antimeridian; the server's cached zone geometry) and as
  properties ``zoneID``, ``level``, ``count`` and ``{column}_sum``, ``_mean``, ``_min``, ``_max`` of every
  numeric column: zone data's properties at depth 0.  ``bbox`` (/req/core/fc-bbox-response: the zones whose
  polygon meets it; ``w > e`` crosses the antimeridian), ``limit`` (default 100, at most the server's
  ``max_features``; a larger one is taken as the maximum, /req/core/fc-limit-response-1) and ``offset``,
  with ``numberMatched``, ``numberReturned`` and a ``next`` link while features remain
  (/rec/core/fc-next-1); ``datetime`` is checked and, as no zone has a temporal geometry, matches every
  feature (/req/core/fc-time-response part C); ``properties=a,b`` keeps only those properties.
- ``/collections/{collectionId}/items/{featureId}`` (/req/core/f-op): one zone of any level up to the stored
  one, as a Feature with the same properties; 404 for a zone without rows or an id that is not a zone.

Unknown query parameters are a 400 naming them (:mod:`.strictparams`, /req/core/query-param-unknown).

Examples
--------
>>> parse_datetime("2020-01-01T00:00:00Z/..")
'2020-01-01T00:00:00Z/..'
>>> parse_properties("count,pop_sum", ["zoneID", "level", "count", "pop_sum"])
['count', 'pop_sum']
"""

from __future__ import annotations

import datetime as dt
from typing import Any

import numpy as np
import orjson
from fastapi import Depends, FastAPI, Query, Request
from fastapi.responses import Response

import dggs

from .dggrs import CRS84
from .errors import BadRequest, NotFound, TooManyZones
from .geojson import GEOJSON, clean, feature_collection
from .params import Context, base_url, check_collection, check_level, negotiate, parse_bbox
from .reader import cells_meeting_bbox, covers_world
from .strictparams import refuse_unknown
from .zonequery import check_crs

__all__ = ["register", "CONFORMANCE", "DEFAULT_LIMIT", "STATS", "level_table", "parse_datetime", "parse_properties"]

_FEATURES = "http://www.opengis.net/spec/ogcapi-features-1/1.0/conf/"
#: The OGC API - Features Part 1 classes met (``html`` is not: no HTML encoding of the features).
CONFORMANCE = [_FEATURES + "core", _FEATURES + "geojson", _FEATURES + "oas30"]
#: Features in a page when no ``limit`` is given.
DEFAULT_LIMIT = 100
#: Statistics of each numeric column, the properties ``{column}_{stat}`` (as zone data has them).
STATS = ("sum", "mean", "min", "max")


def parse_datetime(raw: str | None) -> str | None:
    """Check ``datetime`` (/req/core/fc-time-response part D): an RFC 3339 instant or an interval.

    An interval is ``start/end`` with ``..`` or nothing for an open end; a date alone stands for its day.

    Raises
    ------
    BadRequest
        For text that is neither, or an interval whose start is after its end.

    Examples
    --------
    >>> parse_datetime("2018-02-12T23:20:50Z")
    '2018-02-12T23:20:50Z'
    >>> parse_datetime("../2018-03-18")
    '../2018-03-18'
    """
    if raw is None:
        return None
    parts = raw.split("/")
    if len(parts) > 2 or all(p in ("", "..") for p in parts):
        raise BadRequest(f"datetime {raw!r} must be an RFC 3339 date-time (2018-02-12T23:20:50Z) or an interval "
                         "start/end with '..' for an open end")
    moments: list[dt.datetime | None] = []
    for part in parts:
        if part in ("", ".."):
            moments.append(None)
            continue
        text = part[:-1] + "+00:00" if part[-1:] in ("Z", "z") else part
        try:
            moment = dt.datetime.fromisoformat(text)
        except ValueError:
            raise BadRequest(f"datetime {raw!r}: {part!r} is not an RFC 3339 date-time (e.g. 2018-02-12T23:20:50Z) "
                             "or date") from None
        moments.append(moment if moment.tzinfo else moment.replace(tzinfo=dt.timezone.utc))
    if len(moments) == 2 and moments[0] is not None and moments[1] is not None and moments[0] > moments[1]:
        raise BadRequest(f"datetime {raw!r}: the interval's start is after its end")
    return raw


def parse_properties(raw: str | None, available: list[str]) -> list[str] | None:
    """The ``properties`` to keep, comma-separated, each one of ``available``; None keeps them all.

    Raises
    ------
    BadRequest
        Naming a property the features do not have.
    """
    if raw is None:
        return None
    names = [p.strip() for p in raw.split(",") if p.strip()]
    unknown = [p for p in names if p not in available]
    if unknown:
        raise BadRequest(f"properties: {', '.join(map(repr, unknown))} not a property of these features; they have "
                         f"{', '.join(available)}")
    return names


def _property_names(ctx: Context) -> list[str]:
    columns = ctx.reader.summary().numeric_columns
    return ["zoneID", "level", "count"] + [f"{c}_{s}" for c in columns for s in STATS]


def level_table(reader: Any, level: int) -> dict[str, Any]:
    """Every zone at ``level`` holding rows, with its row count and :data:`STATS` of every numeric column.

    ``{"ids": sorted str ids, "count": [...], "{column}_{stat}": [...], ...}``, the lists aligned with ``ids``
    (None where a zone has no non-NULL value), read in one snapshot and cached as the reader caches its
    roll-ups (per store state, and ``refresh``).

    Raises
    ------
    DggsValueError
        For a level finer than the stored one (from :meth:`CellStore.aggregate`).
    """
    with reader.snapshot() as (store, marker):

        def compute() -> dict[str, Any]:
            rows = store.aggregate(level, None, ("count",))
            ids = [r["cell"] for r in rows]
            where = {c: i for i, c in enumerate(ids)}
            table: dict[str, Any] = {"ids": np.array(ids, dtype=str) if ids else np.array([], dtype="<U1"),
                                     "count": [int(r["count"]) for r in rows]}
            for column in [c for c, t in store.columns.items() if t in ("INTEGER", "REAL")]:
                for stat in STATS:
                    table[f"{column}_{stat}"] = [None] * len(ids)
                for r in store.aggregate(level, column, STATS):
                    for stat in STATS:
                        table[f"{column}_{stat}"][where[r["cell"]]] = r[stat]
            return table

        # the reader's cache, shared with its roll-ups (one key per level; private to the server package)
        return reader._cached(("features", level), marker, compute)  # type: ignore[no-any-return]


def _links_of_page(request: Request, cid: str, offset: int, limit: int, returned: int, matched: int) -> list[dict[str, Any]]:
    """``self``, ``collection`` and, while features remain, ``next`` (and ``prev`` after the first page)."""
    base = base_url(request)
    links = [
        {"href": str(request.url), "rel": "self", "type": GEOJSON, "title": "This page"},
        {"href": f"{base}/collections/{cid}", "rel": "collection", "type": "application/json", "title": cid},
    ]
    if offset + returned < matched:
        href = str(request.url.include_query_params(offset=offset + returned, limit=limit))
        links.append({"href": href, "rel": "next", "type": GEOJSON, "title": "Next page"})
    if offset > 0:
        href = str(request.url.include_query_params(offset=max(0, offset - limit), limit=limit))
        links.append({"href": href, "rel": "prev", "type": GEOJSON, "title": "Previous page"})
    return links


def items(ctx: Context, request: Request, cid: str, zone_level: int | None, bbox_raw: str | None,
          limit: int | None, offset: int, datetime: str | None, properties: str | None,
          f: str | None = None, crs: str | None = None, bbox_crs: str | None = None) -> Response:
    """A page of the collection's features (/req/core/fc-response); see the module's docstring."""
    ctx = check_collection(ctx, cid)  # the collection's dataset
    check_crs("crs", crs)  # OGC API - Features Part 2: the collection's one CRS, CRS84, may be named
    check_crs("bbox-crs", bbox_crs)
    negotiate(request, f, ("geojson", "json"))  # GeoJSON is JSON too
    parse_datetime(datetime)  # no zone has a temporal geometry: every one matches (fc-time-response C)
    keep = parse_properties(properties, _property_names(ctx))
    bbox = parse_bbox(bbox_raw)
    if limit is not None and limit < 1:
        raise BadRequest(f"limit {limit} must be at least 1")
    if offset < 0:
        raise BadRequest(f"offset {offset} must be at least 0")
    size = min(DEFAULT_LIMIT if limit is None else limit, ctx.max_features)
    with ctx.reader.snapshot():  # every number from one state of the store
        stored = ctx.reader.summary().level
        level = check_level("zone-level", (stored or 0) if zone_level is None else zone_level, stored)
        table: dict[str, Any] = (level_table(ctx.reader, level) if stored is not None
                                 else {"ids": np.array([], dtype=str), "count": []})
        index = np.arange(len(table["ids"]))
        if bbox is not None and not covers_world(bbox) and len(index):
            found = cells_meeting_bbox(ctx.reader, ctx.reader.level_data(level), bbox, ctx.max_zones)
            if found is None:
                raise TooManyZones(f"more than {ctx.max_zones} zones of zone-level {level} with data meet bbox "
                                   f"{bbox_raw!r}; use a coarser zone-level or a smaller bbox")
            index = found[0]  # level_data and level_table list the same zones in the same (id) order
    matched = len(index)
    page = index[offset:offset + size]
    ids = table["ids"][page].tolist()
    _, texts = ctx.reader.geometries(np.array(ids, dtype=str)) if ids else (None, [])
    names = [n for n in table if n != "ids"]
    props: list[dict[str, Any]] = []
    for i, zone in zip(page.tolist(), ids, strict=True):
        row = {"zoneID": zone, "level": level, **{n: clean(table[n][i]) for n in names}}
        props.append(row if keep is None else {n: row[n] for n in keep})
    extra = {
        "numberMatched": matched,
        "numberReturned": len(ids),
        "timeStamp": dt.datetime.now(dt.timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ"),
        "links": _links_of_page(request, cid, offset, size, len(ids), matched),
    }
    return Response(feature_collection(ids, texts, props, extra), media_type=GEOJSON, headers=_CONTENT_CRS)


def item(ctx: Context, request: Request, cid: str, feature_id: str, properties: str | None,
         f: str | None = None, crs: str | None = None) -> Response:
    """One zone as a Feature (/req/core/f-op, /req/core/f-success); 404 when the zone holds no rows."""
    ctx = check_collection(ctx, cid)  # the collection's dataset
    check_crs("crs", crs)
    negotiate(request, f, ("geojson", "json"))
    keep = parse_properties(properties, _property_names(ctx))
    if not dggs.is_valid_cell(feature_id):
        raise NotFound(f"no feature {feature_id!r}: features are the zones of {ctx.reader.path.name} holding rows, "
                       "by zone id (e.g. 'C401')")
    level = dggs.get_level(feature_id)
    with ctx.reader.snapshot():
        summary = ctx.reader.summary()
        if summary.level is None:
            raise NotFound(f"no feature {feature_id!r}: the store holds no rows")
        if level > summary.level:
            raise NotFound(f"no feature {feature_id!r}: zone level {level} is finer than the stored level "
                           f"{summary.level}")
        counted = ctx.reader.rollup(feature_id, level, None, ("count",))
        if not counted or not counted[0]["count"]:
            raise NotFound(f"no feature {feature_id!r}: the zone holds no rows")
        row: dict[str, Any] = {"zoneID": feature_id, "level": level, "count": int(counted[0]["count"])}
        for column in summary.numeric_columns:
            values = ctx.reader.rollup(feature_id, level, column, STATS)
            for stat in STATS:
                row[f"{column}_{stat}"] = clean(values[0][stat]) if values else None
    _, texts = ctx.reader.geometries(np.array([feature_id], dtype=str))
    base = base_url(request)
    links = [
        {"href": str(request.url), "rel": "self", "type": GEOJSON, "title": "This feature"},
        {"href": f"{base}/collections/{cid}", "rel": "collection", "type": "application/json", "title": cid},
        {"href": f"{base}/collections/{cid}/dggs/{_dggrs(ctx)}/zones/{feature_id}", "rel": "related",
         "type": "application/json", "title": "Zone information"},
    ]
    props = row if keep is None else {n: row[n] for n in keep}
    text = feature_collection([feature_id], texts, [props], {})
    # one Feature: the FeatureCollection writer's feature, with the links beside it
    feature = orjson.loads(text)["features"][0]
    feature["links"] = links
    return Response(orjson.dumps(feature), media_type=GEOJSON, headers=_CONTENT_CRS)


def schema_xsd(ctx: Context, cid: str) -> bytes:
    """The features' properties as a GML application schema (XML Schema), for GDAL's Features driver.

    GDAL types a layer's fields from the collection's ``describedby`` schema, or else from a first page of 20
    features: there a sum beyond 2**31 further on became a 32-bit field clamped to 2147483647.  GDAL reads
    ``xs:long`` as a 64-bit integer (its JSON Schema reading makes every integer 32-bit, so XML it is).
    ``count`` and the sum, min and max of an INTEGER column are ``xs:long``, means and REAL statistics
    ``xs:double``.  Written with :mod:`xml.etree.ElementTree`.
    """
    from xml.etree import ElementTree as ET

    ctx = check_collection(ctx, cid)  # the collection's dataset
    xs, gml = "http://www.w3.org/2001/XMLSchema", "http://www.opengis.net/gml/3.2"
    ET.register_namespace("xs", xs)
    ET.register_namespace("gml", gml)
    ET.register_namespace("dggs", _XSD_NS)
    root = ET.Element(f"{{{xs}}}schema", {"targetNamespace": _XSD_NS, "elementFormDefault": "qualified",
                                          "version": "1.0"})
    ET.SubElement(root, f"{{{xs}}}import", {"namespace": gml})
    ET.SubElement(root, f"{{{xs}}}element", {"name": cid, "type": f"dggs:{cid}Type",
                                              "substitutionGroup": "gml:AbstractFeature"})
    kind = ET.SubElement(root, f"{{{xs}}}complexType", {"name": f"{cid}Type"})
    extension = ET.SubElement(ET.SubElement(kind, f"{{{xs}}}complexContent"), f"{{{xs}}}extension",
                              {"base": "gml:AbstractFeatureType"})
    sequence = ET.SubElement(extension, f"{{{xs}}}sequence")
    fields = [("geometry", "gml:SurfacePropertyType"), ("zoneID", "xs:string"), ("level", "xs:int"),
              ("count", "xs:long")]
    for column, typed in ctx.reader.summary().columns.items():
        if typed in ("INTEGER", "REAL"):
            whole = "xs:long" if typed == "INTEGER" else "xs:double"
            fields += [(f"{column}_{s}", "xs:double" if s == "mean" else whole) for s in STATS]
    for name, typed in fields:
        ET.SubElement(sequence, f"{{{xs}}}element", {"name": name, "type": typed, "minOccurs": "0"})
    return bytes(ET.tostring(root, encoding="utf-8", xml_declaration=True))


#: The target namespace of :func:`schema_xsd`.
_XSD_NS = "urn:dggs:features"


def _dggrs(ctx: Context) -> str:
    from .dggrs import dggrs_of

    return dggrs_of(ctx.reader.projection)


_F = Query(None, description="geojson (or json, the same GeoJSON); overrides the Accept header")
#: Media type of the features' XML Schema.
XSD = "application/xml"
_CRS = Query(None, description="CRS of the geometries: only CRS84, the default (OGC API - Features Part 2)")
#: OGC API - Features Part 2 /req/crs/ogc-crs-header: the CRS of the geometries, in angle brackets.
_CONTENT_CRS = {"Content-Crs": f"<{CRS84}>"}


def _items_query(
    zone_level: int | None = Query(None, alias="zone-level",
                                   description="Level of the zones that are the features (default: the stored level)"),
    bbox: str | None = Query(None, description="w,s,e,n in CRS84 degrees: the zones meeting it (w > e crosses 180)"),
    limit: int | None = Query(None, ge=1, description=f"Features in a page (default {DEFAULT_LIMIT}; a larger value "
                                                      "than the server's maximum is taken as the maximum)"),
    offset: int = Query(0, ge=0, description="Features to skip (the next link gives it)"),
    datetime: str | None = Query(None, description="An RFC 3339 instant or interval; no zone has a time, so every "
                                                   "zone matches (OGC API - Features /req/core/fc-time-response C)"),
    properties: str | None = Query(None, description="Comma-separated properties to keep (default: all)"),
    f: str | None = _F,
    crs: str | None = _CRS,
    bbox_crs: str | None = Query(None, alias="bbox-crs", description="CRS of bbox: only CRS84 (the default)"),
) -> dict[str, Any]:
    return {"zone_level": zone_level, "bbox_raw": bbox, "limit": limit, "offset": offset, "datetime": datetime,
            "properties": properties, "f": f, "crs": crs, "bbox_crs": bbox_crs}


def register(app: FastAPI, ctx: Context) -> None:
    """Add ``/collections/{collectionId}/items`` and ``.../items/{featureId}``."""
    guard = [Depends(refuse_unknown)]
    responses: dict[int | str, dict[str, Any]] = {200: {"content": {GEOJSON: {}}}}

    @app.get("/collections/{collectionId}/items", tags=["Features"], dependencies=guard, response_class=Response,
             responses=responses, summary="The zones holding data as GeoJSON features (OGC API - Features)")
    def get_items(request: Request, collectionId: str, q: dict[str, Any] = Depends(_items_query)) -> Response:
        return items(ctx, request, collectionId, **q)

    @app.get("/collections/{collectionId}/schema.xsd", tags=["Features"], dependencies=guard,
             response_class=Response, responses={200: {"content": {XSD: {}}}},
             summary="The features' properties as a GML application schema (XML Schema)")
    def get_schema(request: Request, collectionId: str) -> Response:
        negotiate(request, None, ("xml",))
        return Response(schema_xsd(ctx, collectionId), media_type=XSD)

    @app.get("/collections/{collectionId}/items/{featureId}", tags=["Features"], dependencies=guard,
             response_class=Response, responses=responses, summary="One zone as a GeoJSON feature")
    def get_item(request: Request, collectionId: str, featureId: str,
                 properties: str | None = Query(None, description="Comma-separated properties to keep"),
                 f: str | None = _F, crs: str | None = _CRS) -> Response:
        return item(ctx, request, collectionId, featureId, properties, f, crs)
