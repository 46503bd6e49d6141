"""Landing page, conformance, collections and DGGRS resources (OGC API - Common, DGGS Part 1 §7, §14, §15).

- ``/`` landing page (OGC API - Common Part 1, ``openapi/schemas/common-core/landingPage.yaml``);
  a browser (``Accept: text/html``) gets the web map instead, or, when it is not installed, the landing
  page as HTML with its links;
- ``/conformance`` the classes implemented (``confClasses.yaml``);
- ``/collections`` and ``/collections/{collectionId}`` (Common Part 2, ``collections.yaml``,
  ``collectionDesc.yaml``): one collection, the store, named after its file;
- ``.../dggs`` the DGGRS list (/req/core/dggrs-list), ``.../dggs/{dggrsId}`` its description
  (/req/core/dggrs-description), ``.../dggs/{dggrsId}/definition`` the definition (Annex B);
- ``/robots.txt`` keeping crawlers out of the zones (/rec/core/robots-txt).

Examples
--------
>>> [c.rsplit("/", 1)[-1] for c in CONFORMANCE if "dggs" in c][:4]
['core', 'data-retrieval', 'data-custom-depths', 'zone-query']
"""

from __future__ import annotations

import html
from pathlib import Path
from typing import Any

from fastapi import FastAPI, Query, Request
from fastapi.responses import FileResponse, HTMLResponse, JSONResponse, PlainTextResponse, Response
from pydantic import BaseModel

from .dggrs import CRS84, DGGRS_IDS, REL, definition, description, dggrs_of, item
from .dggrs import link as _link
from .encodings import HAS_UBJSON
from .features import CONFORMANCE as FEATURES_CONFORMANCE
from .features import DEFAULT_LIMIT
from .models import Collection, Collections, DggrsList, LandingPage, json_response
from .params import Context, base_url, check_collection, check_data_dggrs, check_dggrs, negotiate
from .vendor import VENDOR_HELP, missing_vendor

__all__ = ["register", "CONFORMANCE"]

_DGGS = "https://www.opengis.net/spec/ogcapi-dggs-1/1.0/conf/"
_COMMON = "http://www.opengis.net/spec/ogcapi-common-1/1.0/conf/"

#: The conformance classes implemented (core/sections/clause_2_conformance.adoc and the requirements classes).
CONFORMANCE = [
    _COMMON + "core",
    _COMMON + "landing-page",
    _COMMON + "json",
    _COMMON + "oas30",
    "http://www.opengis.net/spec/ogcapi-common-2/1.0/conf/collections",
    _DGGS + "core",  # /dggs, /dggs/{dggrsId}, zone information
    _DGGS + "data-retrieval",  # .../zones/{zoneId}/data
    _DGGS + "data-custom-depths",  # zone-depth: d, lo-hi, a,b,c
    _DGGS + "zone-query",  # .../zones with zone-level, compact-zones, bbox
    _DGGS + "root-dggs",  # /dggs at the root
    _DGGS + "collection-dggs",  # /collections/{collectionId}/dggs
    _DGGS + "data-json",  # DGGS-JSON
    _DGGS + "data-geojson",  # zone data as GeoJSON
    _DGGS + "zone-geojson",  # zone lists as GeoJSON
    _DGGS + "zone-uint64",  # zone lists as 64-bit integers (application/x-binary)
] + ([_DGGS + "data-ubjson"] if HAS_UBJSON else []) + FEATURES_CONFORMANCE  # DGGS-UBJSON with py-ubjson


def landing(ctx: Context, request: Request) -> LandingPage:
    """The landing page (OGC API - Common, /req/landing-page; /req/root-dggs/dggs)."""
    base = base_url(request)
    cid = ctx.reader.collection_id
    return LandingPage.model_validate({
        "title": f"dggs: {cid}",
        "description": (
            f"OGC API - DGGS over the cell store {ctx.reader.path.name}: points binned into equal-area "
            f"triangular zones ({dggrs_of(ctx.reader.projection)}), rolled up to any coarser level; "
            f"zone information also on {', '.join(d for d in DGGRS_IDS if d != dggrs_of(ctx.reader.projection))}."
        ),
        "links": [
            _link(f"{base}/?f=json", "self", title="This document"),
            _link(f"{base}/api", "service-desc", "application/vnd.oai.openapi+json;version=3.0", "OpenAPI"),
            _link(f"{base}/api.html", "service-doc", "text/html", "API documentation"),
            _link(f"{base}/conformance", "conformance", title="Conformance classes"),
            _link(f"{base}/conformance", REL + "conformance", title="Conformance classes"),
            _link(f"{base}/collections", "data", title="Collections"),
            _link(f"{base}/collections", REL + "data", title="Collections"),
            _link(f"{base}/dggs", REL + "dggrs-list", title="DGGRS list"),
            _link(f"{base}/map/layers", "related", title="Web map layers"),
        ],
    })


def collection(ctx: Context, request: Request) -> Collection:
    """The store as a collection (``collectionDesc.yaml``; /req/collection-dggs/dggs)."""
    base = base_url(request)
    summary = ctx.reader.summary()
    cid = ctx.reader.collection_id
    href = f"{base}/collections/{cid}"
    bbox = list(summary.bbox) if summary.bbox is not None else [-180.0, -90.0, 180.0, 90.0]
    out: dict[str, Any] = {
        "id": cid,
        "title": cid,
        "description": (
            f"{summary.count} points binned into level-{summary.level} zones"
            f"{'' if not summary.columns else ' with values ' + ', '.join(summary.columns)}."
            if summary.level is not None else "An empty store: no points binned yet."
        ),
        "extent": {"spatial": {"bbox": [bbox], "crs": CRS84}},
        "crs": [CRS84],
        "storageCrs": CRS84,
        "itemType": "feature",  # OGC API - Features: the items are GeoJSON features (the zones holding data)
        "links": [
            _link(href, "self"),
            _link(f"{base}/collections", "collection", title="All collections"),
            _link(f"{href}/dggs", REL + "dggrs-list", title="DGGRS list of this collection"),
            _link(f"{href}/dggs/{dggrs_of(ctx.reader.projection)}/zones", REL + "dggrs-zone-query",
                  title="Zones holding data"),
            # /req/core/fc-md-items-links (OGC API - Features): the features, as GeoJSON
            _link(f"{href}/items", "items", "application/geo+json",
                  f"The zones holding data as features, level {summary.level}, {DEFAULT_LIMIT} a page"),
            # the features' property types, which GDAL reads (describedby) instead of guessing from 20 features
            _link(f"{href}/schema.xsd", "describedby", "application/xml", "The features' properties (XML Schema)"),
        ],
    }
    if summary.updated:
        out["updated"] = summary.updated
    if summary.created:
        out["created"] = summary.created
    return Collection.model_validate(out)


def dggrs_list(ctx: Context, request: Request, collection_id: str | None) -> DggrsList:
    """The DGGRS list (``rDGGRSList.yaml``; /req/core/dggrs-list).

    At the root every DGGRS served (zone information on each); a collection lists the one DGGRS its
    data were binned with (``CellStore.projection``), the only one under which it has zone data.
    """
    base = base_url(request)
    prefix = "" if collection_id is None else f"/collections/{collection_id}"
    links = [_link(f"{base}{prefix}/dggs", "self")]
    if collection_id is None:
        links.append(_link(f"{base}/", REL + "dataset", title="Landing page"))
    else:
        links.append(_link(f"{base}/collections/{collection_id}", REL + "geodata", title=collection_id))
    ids = list(DGGRS_IDS) if collection_id is None else [dggrs_of(ctx.reader.projection)]
    return DggrsList.model_validate({"links": links, "dggrs": [item(base, prefix, d) for d in ids]})


_LANDING_HTML = """<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>{title}</title></head>
<body><h1>{title}</h1><p>{description}</p>
<p id="status" role="alert">{why}</p>
<ul>
{links}
</ul>
</body></html>
"""


def landing_html(document: LandingPage, why: str) -> str:
    """The landing page ``document`` as HTML for a browser when the web map cannot be shown, saying ``why``.

    Every link of the JSON landing page is a link here (title, relation and media type shown).

    Examples
    --------
    >>> link = {"href": "/api", "rel": "service-desc", "title": "OpenAPI"}
    >>> doc = LandingPage.model_validate({"title": "t", "description": "d", "links": [link]})
    >>> '<a href="/api">OpenAPI</a>' in landing_html(doc, "no map")
    True
    """
    items = "\n".join(
        f'<li><a href="{html.escape(link.href)}">{html.escape(link.title or link.href)}</a> '
        f'({html.escape(link.rel)}{", " + html.escape(link.type) if link.type else ""})</li>'
        for link in document.links
    )
    return _LANDING_HTML.format(title=html.escape(document.title or ""), description=html.escape(document.description or ""),
                                why=html.escape(why), links=items)


_NO_PAGE = "The web map is not part of this server (its static folder has no index.html); the API answers below."


_F = Query(None, description="json (the only format here; overrides the Accept header)")


def _json(request: Request, f: str | None, body: Any) -> Response:
    """``body`` (a dict or a model) as JSON, the one format of the metadata resources.

    400 for another ``f``, 406 for an Accept header without JSON (OGC API - Common /req/core/http).
    """
    negotiate(request, f, ("json",))
    return json_response(body) if isinstance(body, BaseModel) else JSONResponse(body)


def register(app: FastAPI, ctx: Context, static: Path) -> None:
    """Add the landing page, conformance, collections and DGGRS routes."""
    page = static / "index.html"

    @app.get("/", tags=["Capabilities"], summary="Landing page (the web map for a browser)")
    def root(request: Request, f: str | None = Query(None, description="json for the landing page, html for the "
                                                                           "web map (or the landing page as HTML "
                                                                           "when the map is not installed)")) -> Response:
        # /req/landing-page/root-success: JSON, or for a client preferring text/html (a browser) the web map's
        # page; without the map, the landing page as HTML with its links and the reason, never a 406 or a
        # page that waits forever for MapLibre.
        if negotiate(request, f, ("json", "html")) == "html":
            if not page.is_file():
                return HTMLResponse(landing_html(landing(ctx, request), _NO_PAGE))
            if missing_vendor(static):
                return HTMLResponse(landing_html(landing(ctx, request), VENDOR_HELP + "."))
            return FileResponse(page, media_type="text/html")
        return json_response(landing(ctx, request))

    @app.get("/conformance", tags=["Capabilities"], summary="Conformance classes")
    def conformance(request: Request, f: str | None = _F) -> Response:
        return _json(request, f, {"conformsTo": CONFORMANCE})

    @app.get("/collections", tags=["Collections"], summary="Collections (the store's datasets)")
    def collections(request: Request, f: str | None = _F) -> Response:
        negotiate(request, f, ("json",))
        base = base_url(request)
        every = [collection(check_collection(ctx, cid), request) for cid in (ctx.readers or [None])]
        return json_response(Collections.model_validate({
            "links": [_link(f"{base}/collections", "self")], "collections": every,
            "numberMatched": len(every), "numberReturned": len(every)}))

    @app.get("/collections/{collectionId}", tags=["Collections"], summary="The collection")
    def one_collection(request: Request, collectionId: str, f: str | None = _F) -> Response:
        return _json(request, f, collection(check_collection(ctx, collectionId), request))

    def described(request: Request, collection_id: str | None, dggrs_id: str) -> dict[str, Any]:
        one = check_collection(ctx, collection_id)
        serves_data = check_dggrs(dggrs_id) == one.reader.projection
        if collection_id is not None and not serves_data:
            check_data_dggrs(one, dggrs_id)  # 404: the collection's data are under the other DGGRS
        prefix = "" if collection_id is None else f"/collections/{collection_id}"
        return description(base_url(request), prefix, one.reader.summary().level, collection_id, dggrs_id,
                           serves_data)

    @app.get("/dggs", tags=["DGGS"], summary="DGGRS list")
    def dggs_root(request: Request, f: str | None = _F) -> Response:
        return _json(request, f, dggrs_list(ctx, request, None))

    @app.get("/dggs/{dggrsId}", tags=["DGGS"], summary="DGGRS description")
    def dggrs_root(request: Request, dggrsId: str, f: str | None = _F) -> Response:
        return _json(request, f, described(request, None, dggrsId))

    @app.get("/dggs/{dggrsId}/definition", tags=["DGGS"], summary="DGGRS definition (Annex B schema)")
    def dggrs_definition(request: Request, dggrsId: str, f: str | None = _F) -> Response:
        check_dggrs(dggrsId)
        return _json(request, f, definition(dggrsId))

    @app.get("/collections/{collectionId}/dggs", tags=["Collection DGGS"], summary="DGGRS list of the collection")
    def dggs_collection(request: Request, collectionId: str, f: str | None = _F) -> Response:
        return _json(request, f, dggrs_list(check_collection(ctx, collectionId), request, collectionId))

    @app.get("/collections/{collectionId}/dggs/{dggrsId}", tags=["Collection DGGS"], summary="DGGRS description")
    def dggrs_collection(request: Request, collectionId: str, dggrsId: str, f: str | None = _F) -> Response:
        return _json(request, f, described(request, collectionId, dggrsId))

    @app.get("/collections/{collectionId}/dggs/{dggrsId}/definition", tags=["Collection DGGS"],
             summary="DGGRS definition (Annex B schema)")
    def dggrs_collection_definition(request: Request, collectionId: str, dggrsId: str,
                                    f: str | None = _F) -> Response:
        check_data_dggrs(check_collection(ctx, collectionId), dggrsId)
        return _json(request, f, definition(dggrsId))

    @app.get("/robots.txt", include_in_schema=False)
    def robots(request: Request) -> PlainTextResponse:
        negotiate(request, None, ("text",))
        return PlainTextResponse("User-agent: *\nDisallow: */dggs/*/zones/*\n")
