"""Zone routes of OGC API - DGGS Part 1: zone information, zone data, zone queries.

Each route is served twice: under ``/dggs/{dggrsId}`` (the API's own DGGRS, the
*Root DGGS* class, §14) and under ``/collections/{collectionId}/dggs/{dggrsId}``
(the *Collection DGGS* class, §15); both read the one store.

- ``.../zones/{zoneId}`` — zone information (§7.3, /req/core/zone-info), JSON or a GeoJSON Feature;
- ``.../zones/{zoneId}/data`` — the store's rows rolled up to the sub-zones (§8,
  /req/data-retrieval/zone-data; ``zone-depth`` of §10, /req/data-custom-depths/zone-depth),
  as DGGS-JSON (§16, /req/data-json/content), DGGS-UBJSON (/req/data-ubjson/content) or GeoJSON
  (/req/data-geojson/content);
- ``.../zones`` — the zones holding data (§12, /req/zone-query/zones-list), JSON, GeoJSON
  (/req/zone-geojson/content) or 64-bit integers (/req/zone-uint64/content), with ``zone-level``,
  ``parent-zone``, ``compact-zones``, ``bbox`` or ``subset``, ``limit`` and ``offset``.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from fastapi import Depends, FastAPI, Query, Request
from fastapi.responses import JSONResponse, Response

import dggs

from .dggrs import CRS84, DEFAULT_DEPTH, DGGRS_ID, REL, zone_count
from .encodings import HAS_UBJSON, UBJSON, UINT64, dggs_ubjson, uint64_zone_list
from .errors import BadRequest, TooManyZones
from .features import parse_properties
from .geojson import GEOJSON, clean, feature_collection
from .models import ZoneInfo, json_response
from .params import (
    Context,
    base_url,
    check_collection,
    check_data_dggrs,
    check_dggrs,
    check_level,
    negotiate,
    parse_bbox,
    parse_depths,
    parse_zone,
)
from .reader import LevelData, cells_meeting_bbox
from .stats import zone_statistics
from .strictparams import refuse_unknown
from .zonequery import (
    CRS_QUERY,
    ZONE_QUERY,
    ZoneQuery,
    check_crs,
    check_geometry,
    geometry_texts,
    page_links,
    parent_range,
    parse_subset,
)

__all__ = ["register", "STATS", "sub_zone_count"]

#: Statistics of each numeric column in zone data (property ``{column}_{stat}``).
STATS = ("sum", "mean", "min", "max")
#: The formats of zone data: DGGS-JSON, GeoJSON and, with py-ubjson installed, DGGS-UBJSON.
DATA_FORMATS = ("json", "geojson", "ubjson") if HAS_UBJSON else ("json", "geojson")


def sub_zone_count(level: int, depth: int) -> int:
    """Sub-zones of a level-``level`` zone at relative ``depth`` (6 below a face, then 3 per level).

    Examples
    --------
    >>> sub_zone_count(0, 2), sub_zone_count(5, 2)
    (18, 9)
    """
    return zone_count(level + depth) // zone_count(level)


def _prefix(collection: str | None) -> str:
    return "" if collection is None else f"/collections/{collection}"


def _links(request: Request, collection: str | None, zone: str | None = None,
           dggrs_id: str = DGGRS_ID) -> list[dict[str, Any]]:
    base = base_url(request)
    dggrs = f"{base}{_prefix(collection)}/dggs/{dggrs_id}"
    links = [
        {"href": str(request.url), "rel": "self", "type": "application/json"},
        {"href": dggrs, "rel": REL + "dggrs", "type": "application/json"},
        {"href": f"{dggrs}/definition", "rel": REL + "dggrs-definition", "type": "application/json"},
    ]
    if collection is not None:
        links.append({"href": f"{base}/collections/{collection}", "rel": REL + "geodata",
                      "type": "application/json"})
    if zone is not None:
        links.append({"href": f"{dggrs}/zones/{zone}", "rel": REL + "dggrs-zone-info", "type": "application/json"})
    return links


# -- zone information ---------------------------------------------------------


def zone_info(ctx: Context, request: Request, collection: str | None, zone: str, f: str | None,
              dggrs_id: str = DGGRS_ID) -> Response:
    """Zone information (/req/core/zone-info, /rec/core/zone-info) on ``dggrs_id``'s grid (data: its own only)."""
    import shapely
    from shapely.geometry import mapping

    fmt = negotiate(request, f)
    level = dggs.get_level(zone)
    base = base_url(request)
    dggrs = f"{base}{_prefix(collection)}/dggs/{dggrs_id}"
    grid = dggs.Grid(check_dggrs(dggrs_id))
    serves_data = grid.projection == ctx.reader.projection
    poly = grid.cell_to_polygon(zone)
    lat, lng = grid.cell_to_latlng(zone)
    parent = dggs.cell_to_parent(zone) if level > 0 else None
    children = dggs.cell_to_children(zone) if level < dggs.MAX_LEVEL else []
    neighbors = dggs.edge_neighbors(zone)
    links = _links(request, collection, None, dggrs_id)[:3]
    if serves_data:
        links.append({"href": f"{dggrs}/zones/{zone}/data", "rel": REL + "dggrs-zone-data",
                      "type": "application/json", "title": "Data of the zone (DGGS-JSON)"})
    if parent is not None:
        links.append({"href": f"{dggrs}/zones/{parent}", "rel": REL + "dggrs-zone-parent", "type": "application/json"})
    links += [{"href": f"{dggrs}/zones/{c}", "rel": REL + "dggrs-zone-child", "type": "application/json"}
              for c in children]
    links += [{"href": f"{dggrs}/zones/{c}", "rel": REL + "dggrs-zone-neighbor", "type": "application/json"}
              for c in neighbors]
    info: dict[str, Any] = {
        "id": zone,
        "level": level,
        "shapeType": "triangle",
        "crs": CRS84,
        "centroid": [float(lng), float(lat)],
        "bbox": [float(v) for v in shapely.bounds(poly)],
        "areaMetersSquare": float(dggs.cell_area(level)),
        "uint64Id": str(dggs.str_to_int(zone)),
        "parent": parent,
        "children": list(children),
        "neighbors": list(neighbors),
        "geometry": mapping(poly),
        "links": links,
    }
    with ctx.reader.snapshot():  # one read transaction: all numbers from the same state of the store
        summary = ctx.reader.summary()
        if serves_data and summary.level is not None and level <= summary.level:
            # /rec/core/zone-info: summary statistics of each numeric field within the zone.
            rows = ctx.reader.rollup(zone, level, None, ("count",))
            info["dataCount"] = int(rows[0]["count"]) if rows else 0
            info["statistics"] = zone_statistics(ctx.reader, zone, level, summary.numeric_columns)
    if fmt == "geojson":
        props = {k: v for k, v in info.items() if k not in ("id", "geometry")}
        feature = {"type": "Feature", "id": zone, "geometry": info["geometry"], "properties": {"zoneID": zone, **props}}
        return JSONResponse(feature, media_type=GEOJSON)
    return json_response(ZoneInfo.model_validate(info))  # the standard's members, none misspelt (models.py)


# -- zone data ----------------------------------------------------------------


def zone_data(ctx: Context, request: Request, collection: str | None, zone: str, depth: str | None,
              f: str | None, geometry: str | None = None, dggrs_id: str = DGGRS_ID,
              properties: str | None = None) -> Response:
    """Sub-zone roll-ups of ``zone`` at each depth (DGGS-JSON, DGGS-UBJSON, GeoJSON), under the data's DGGRS only.

    ``properties`` (comma-separated; a parameter of the standard's zone data operation)
    keeps only those properties; one the data do not have is a 400 naming it.
    """
    check_data_dggrs(ctx, dggrs_id)
    fmt = negotiate(request, f, DATA_FORMATS)
    mode = check_geometry(geometry)
    with ctx.reader.snapshot():  # one read transaction: every value from the same state of the store
        return _zone_data(ctx, request, collection, zone, depth, fmt, mode, dggrs_id, properties)


def _zone_data(ctx: Context, request: Request, collection: str | None, zone: str, depth: str | None,
               fmt: str, mode: str, dggrs_id: str, wanted: str | None = None) -> Response:
    summary = ctx.reader.summary()
    stored = summary.level
    level = dggs.get_level(zone)
    if stored is not None and level > stored:
        raise BadRequest(f"zoneId {zone!r} is at level {level}, finer than the stored level {stored}; "
                         f"data exists for zones of levels 0..{stored}")
    deepest = dggs.MAX_LEVEL - level if stored is None else stored - level
    depths = parse_depths(depth, default=min(DEFAULT_DEPTH, deepest))
    if depths[-1] > deepest:
        raise BadRequest(f"zone-depth {depth!r} goes below the stored level {stored}: for zone {zone!r} "
                         f"(level {level}) the deepest is {deepest}")
    total = sum(sub_zone_count(level, d) for d in depths)
    if total > ctx.max_features:
        raise TooManyZones(f"zone-depth {depth!r} of zone {zone!r} gives {total} sub-zones, more than this "
                           f"server's limit of {ctx.max_features}; ask for a smaller zone-depth or a finer zone")
    columns = summary.numeric_columns
    props = ["count"] + [f"{c}_{s}" for c in columns for s in STATS]
    selected = parse_properties(wanted, props)  # checked before any roll-up is read
    per_depth: list[tuple[int, list[str], dict[str, list[Any]]]] = []
    for d in depths:
        subs = [zone] if d == 0 else list(dggs.cell_to_children(zone, level + d))
        where = {c: i for i, c in enumerate(subs)}
        data: dict[str, list[Any]] = {p: [None] * len(subs) for p in props}
        data["count"] = [0] * len(subs)
        for row in ctx.reader.rollup(zone, level + d, None, ("count",)):
            data["count"][where[row["cell"]]] = int(row["count"])
        for c in columns:
            for row in ctx.reader.rollup(zone, level + d, c, STATS):
                i = where[row["cell"]]
                for s in STATS:
                    data[f"{c}_{s}"][i] = clean(row[s])
        per_depth.append((d, subs, data))
    if selected is not None:
        props = selected
    if fmt == "geojson":
        ids: list[str] = []
        geoms: list[str] = []
        properties: list[dict[str, Any]] = []
        for d, subs, data in per_depth:
            texts = geometry_texts(ctx.reader, subs, mode)
            ids += subs
            geoms += texts
            for i, sub in enumerate(subs):
                properties.append({"zoneID": sub, "depth": d, "level": level + d,
                                   **{p: data[p][i] for p in props}})
        extra = {"dggrs": f"{base_url(request)}{_prefix(collection)}/dggs/{dggrs_id}", "zoneId": zone,
                 "depths": depths, "numberReturned": len(ids), "links": _links(request, collection, zone, dggrs_id)}
        return Response(feature_collection(ids, geoms, properties, extra), media_type=GEOJSON)
    count = {"type": "integer", "title": "rows in the sub-zone"}
    described: dict[str, Any] = {"count": count}
    for c in columns:
        for s in STATS:
            described[f"{c}_{s}"] = {"type": "number", "title": f"{s} of {c} in the sub-zone"}
    schema: dict[str, Any] = {"type": "object", "properties": {p: described[p] for p in props}}
    values = {
        p: [{"depth": d, "shape": {"count": len(subs), "subZones": len(subs)}, "data": data[p]}
            for d, subs, data in per_depth]
        for p in props
    }
    links = _links(request, collection, zone, dggrs_id)
    body = {
        "dggrs": f"{base_url(request)}{_prefix(collection)}/dggs/{dggrs_id}",
        "zoneId": zone,
        "depths": depths,
        "schema": schema,
        "values": values,
        "links": links,
    }
    if fmt == "ubjson":  # /req/data-ubjson/content: the DGGS-JSON document in UBJSON
        links[0]["type"] = UBJSON  # the self link
        return Response(dggs_ubjson(body), media_type=UBJSON)
    return JSONResponse(body)


# -- zone query ---------------------------------------------------------------


def zones_list(ctx: Context, request: Request, collection: str | None, q: ZoneQuery, f: str | None,
               dggrs_id: str = DGGRS_ID) -> Response:
    """The zones at ``zone-level`` holding data: a page of them, inside ``parent-zone``, in ``bbox`` or ``subset``.

    Compacted unless ``compact-zones=false``; ``limit`` zones from ``offset``.  Only under the DGGRS the
    store's data were binned with (its grid draws the zones met by ``bbox``).

    Raises
    ------
    BadRequest
        For an unsupported ``bbox-crs`` or ``subset-crs``, ``bbox`` with ``subset``, an unknown subset axis,
        a ``limit`` below 1, a negative ``offset``, or another parameter that is not valid (named).
    TooManyZones
        If more zones hold data than the server's ``max_zones`` limit allows.
    NotFound
        Under the DGGRS the store's data were not binned with (naming the one they were).
    """
    check_data_dggrs(ctx, dggrs_id)
    fmt = negotiate(request, f, ("json", "geojson", "uint64"))
    geometry = check_geometry(q.geometry)
    check_crs("bbox-crs", q.bbox_crs)  # /req/zone-query/bbox-crs
    check_crs("subset-crs", q.subset_crs)  # /req/zone-query/subset-crs
    check_crs("crs", q.crs)
    bbox = parse_bbox(q.bbox)
    subset = parse_subset(q.subset)  # /req/zone-query/subset
    if bbox is not None and subset is not None:
        raise BadRequest(f"bbox {q.bbox!r} and subset {','.join(q.subset)!r} may not be used together; give one")
    box, named = (bbox, f"bbox {q.bbox!r}") if bbox is not None else (subset, f"subset {','.join(q.subset)!r}")
    stored = ctx.reader.summary().level
    level = check_level("zone-level", (stored or 0) if q.zone_level is None else q.zone_level, stored)
    if q.limit is not None and q.limit < 1:
        raise BadRequest(f"limit {q.limit} must be at least 1")
    if q.offset < 0:
        raise BadRequest(f"offset {q.offset} must be at least 0")
    data = ctx.reader.level_data(level)
    if q.parent is not None:  # /req/zone-query/parent-zone
        part = parent_range(data.ids, q.parent, level)
        data = LevelData(level, data.ids[part], data.counts[part], data.values[part], data.lat[part],
                         data.lng[part])
    if box is None:
        zones = data.ids.tolist()
    else:
        found = cells_meeting_bbox(ctx.reader, data, box, ctx.max_zones)
        if found is None:
            raise TooManyZones(f"more than {ctx.max_zones} zones of zone-level {level} hold data near "
                               f"{named}; use a coarser zone-level or a smaller box")
        zones = data.ids[found[0]].tolist()
    if q.compact and zones:
        # /rec/zone-json/zone-order: coarser zones first.
        zones = sorted((str(z) for z in dggs.compact_cells(zones)), key=lambda z: (len(z), z))
    matched = len(zones)
    if q.limit is not None or q.offset:
        zones = zones[q.offset:None if q.limit is None else q.offset + q.limit]
    cap = ctx.max_features if fmt == "geojson" else ctx.max_zones
    if len(zones) > cap:
        raise TooManyZones(f"{len(zones)} zones of zone-level {level} hold data, more than this server's limit "
                           f"of {cap}; use a coarser zone-level, a smaller bbox, compact-zones or limit")
    if fmt == "uint64":  # /req/zone-uint64/content: count then ids, little-endian uint64
        return Response(uint64_zone_list(zones), media_type=UINT64)
    levels = np.char.str_len(np.array(zones, dtype=str)) - 1 if zones else np.array([], dtype=int)
    per_level = zip(*np.unique(levels, return_counts=True), strict=True)
    area = float(sum(float(dggs.cell_area(int(lv))) * int(n) for lv, n in per_level))
    media = GEOJSON if fmt == "geojson" else "application/json"
    links = _links(request, collection, None, dggrs_id) + page_links(request, q.offset, q.limit, len(zones), matched, media)
    templates = [{"uriTemplate": f"{base_url(request)}{_prefix(collection)}/dggs/{dggrs_id}/zones/{{zoneId}}/data",
                  "rel": REL + "dggrs-zone-data", "type": "application/json"}]
    if fmt == "geojson":
        texts = geometry_texts(ctx.reader, zones, geometry)
        props = [{"zoneID": z, "level": len(z) - 1} for z in zones]
        extra = {"numberMatched": matched, "numberReturned": len(zones), "returnedAreaMetersSquare": area,
                 "links": links}
        return Response(feature_collection(zones, texts, props, extra), media_type=GEOJSON)
    return JSONResponse({"zones": zones, "returnedAreaMetersSquare": area, "numberMatched": matched,
                         "numberReturned": len(zones), "links": links, "linkTemplates": templates})


# -- routes -------------------------------------------------------------------

_F = Query(None, description="Output format: json (default) or geojson; overrides the Accept header")
_F_DATA = Query(None, description="Output format: json (DGGS-JSON, default), geojson or ubjson (DGGS-UBJSON); "
                                  "overrides the Accept header")
_F_ZONES = Query(None, description="Output format: json (default), geojson or uint64 (application/x-binary: "
                                   "a little-endian uint64 count, then the uint64 zone ids); overrides Accept")
_DEPTH = Query(None, alias="zone-depth", description="Relative depth: d, low-high or a,b,c (default 3)")
_GEOMETRY = Query(None, description="GeoJSON geometry: zone-region (default), vectorized, zone-centroid or none")
_PROPERTIES = Query(None, description="Comma-separated properties to return (default: all), e.g. count,pop_sum")




def register(app: FastAPI, ctx: Context) -> None:
    """Add the zone routes under ``/dggs/{dggrsId}`` and ``/collections/{collectionId}/dggs/{dggrsId}``."""

    def info(request: Request, dggrsId: str, zoneId: str, f: str | None = _F) -> Response:
        check_dggrs(dggrsId)
        return zone_info(ctx, request, None, parse_zone(zoneId), f, dggrsId)

    def data(request: Request, dggrsId: str, zoneId: str, zone_depth: str | None = _DEPTH,
             geometry: str | None = _GEOMETRY, f: str | None = _F_DATA, properties: str | None = _PROPERTIES,
             crs: str | None = CRS_QUERY) -> Response:
        check_dggrs(dggrsId)
        check_crs("crs", crs)
        return zone_data(ctx, request, None, parse_zone(zoneId), zone_depth, f, geometry, dggrsId, properties)

    def zones(request: Request, dggrsId: str, q: ZoneQuery = ZONE_QUERY, f: str | None = _F_ZONES) -> Response:
        check_dggrs(dggrsId)
        return zones_list(ctx, request, None, q, f, dggrsId)

    def c_info(request: Request, collectionId: str, dggrsId: str, zoneId: str, f: str | None = _F) -> Response:
        one = check_collection(ctx, collectionId)
        check_data_dggrs(one, dggrsId)  # a collection offers the DGGRS of its data only
        return zone_info(one, request, collectionId, parse_zone(zoneId), f, dggrsId)

    def c_data(request: Request, collectionId: str, dggrsId: str, zoneId: str, zone_depth: str | None = _DEPTH,
               geometry: str | None = _GEOMETRY, f: str | None = _F_DATA,
               properties: str | None = _PROPERTIES, crs: str | None = CRS_QUERY) -> Response:
        one = check_collection(ctx, collectionId)
        check_dggrs(dggrsId)
        check_crs("crs", crs)
        return zone_data(one, request, collectionId, parse_zone(zoneId), zone_depth, f, geometry, dggrsId,
                         properties)

    def c_zones(request: Request, collectionId: str, dggrsId: str, q: ZoneQuery = ZONE_QUERY,
                f: str | None = _F_ZONES) -> Response:
        one = check_collection(ctx, collectionId)
        check_dggrs(dggrsId)
        return zones_list(one, request, collectionId, q, f, dggrsId)

    for prefix, tag, handlers in (
        ("", "DGGS", (zones, info, data)),
        ("/collections/{collectionId}", "Collection DGGS", (c_zones, c_info, c_data)),
    ):
        root = prefix + "/dggs/{dggrsId}/zones"
        guard = [Depends(refuse_unknown)]  # parameters a route does not take: 400 naming them
        app.add_api_route(root, handlers[0], methods=["GET"], tags=[tag], dependencies=guard,
                          summary="Zones holding data (zone query)")
        app.add_api_route(root + "/{zoneId}", handlers[1], methods=["GET"], tags=[tag], dependencies=guard,
                          summary="Zone information")
        app.add_api_route(root + "/{zoneId}/data", handlers[2], methods=["GET"], tags=[tag], dependencies=guard,
                          summary="Data of a zone's sub-zones (DGGS-JSON or GeoJSON)")
