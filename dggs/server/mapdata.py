"""The JSON behind the web map: ``/map/layers`` and ``/map/cells`` (not part of the OGC standard).

The contract the front end (``static/index.html``) relies on:

- ``GET /map/layers`` gives ``{"collection", "stored_level", "levels": [0..L], "columns": {name: SQL type},
  "numeric_columns", "bbox": [w, s, e, n], "count", "max_zones", "dggrs"}``; ``max_zones`` is the most
  features ``/map/cells`` returns, ``dggrs`` the DGGRS the store's data are served under (its zone information).
- ``GET /map/cells?level=L&bbox=w,s,e,n&column=C&stat=count|sum|mean|min|max`` gives a GeoJSON
  FeatureCollection, one feature per non-empty cell at level ``L`` whose polygon meets the bbox (``w > e``
  crosses the antimeridian), with properties ``zone_id``, ``level``, ``area_km2``, ``count`` and ``value``
  (the statistic of the column, or the count without a column).
- ``GET /map/cells?...&f=uint64`` gives the same cells as ids for the page to draw with the WebAssembly core
  (js/): the zone-uint64 list (a little-endian uint64 count n, then the n ids) followed by the n counts and the
  n values as little-endian float64 (NaN for no value), 24 bytes a cell instead of GeoJSON's hundreds.

The roll-up of a level is cached until the store changes (:class:`~dggs.server.reader.StoreReader`) and
cell geometries are cached for good, so panning the map re-reads nothing.

Examples
--------
>>> from fastapi.testclient import TestClient
>>> from dggs.server.app import create_app
>>> from dggs.storage import CellStore
>>> import tempfile, os
>>> path = os.path.join(tempfile.mkdtemp(), "towns.db")
>>> with CellStore(path) as s:
...     _ = s.ingest_points([51.05, 51.06, -33.9], [-114.07, -114.08, 151.2], 5, {"pop": [3, 4, 5]})
>>> with TestClient(create_app(path)) as client:
...     client.get("/map/layers").json()["levels"]
...     cells = client.get("/map/cells", params={"level": 1, "column": "pop", "stat": "sum"}).json()
...     [(f["properties"]["zone_id"], f["properties"]["value"]) for f in cells["features"]]
[0, 1, 2, 3, 4, 5]
[('F2', 7), ('S4', 5)]
"""

from __future__ import annotations

from typing import Any

import numpy as np
from fastapi import Depends, FastAPI, Query, Request
from fastapi.responses import JSONResponse, Response

import dggs

from .dggrs import dggrs_of
from .encodings import UINT64
from .errors import BadRequest, TooManyZones
from .geojson import GEOJSON, clean, feature_collection
from .params import Context, check_collection, check_level, negotiate, parse_bbox
from .reader import cells_meeting_bbox, covers_world
from .strictparams import refuse_unknown

__all__ = ["register", "MAP_STATS"]

#: Statistics the map can show.
MAP_STATS = ("count", "sum", "mean", "min", "max")


def layers(ctx: Context) -> dict[str, Any]:
    """What the map can show (``/map/layers``)."""
    summary = ctx.reader.summary()
    stored = summary.level
    return {
        "collection": ctx.reader.collection_id,
        "stored_level": stored,
        "levels": [] if stored is None else list(range(stored + 1)),
        "columns": summary.columns,
        "numeric_columns": summary.numeric_columns,
        "bbox": list(summary.bbox) if summary.bbox is not None else [-180.0, -90.0, 180.0, 90.0],
        "count": summary.count,
        "max_zones": ctx.max_features,
        "dggrs": dggrs_of(ctx.reader.projection),  # the popup's zone information: the grid the cells are drawn on
    }


def cells(ctx: Context, level: int, bbox_raw: str | None, column: str | None, stat: str, fmt: str = "geojson") -> Response:
    """The non-empty cells at ``level`` meeting ``bbox`` as GeoJSON, or as ids (``fmt="uint64"``; ``/map/cells``).

    Raises
    ------
    BadRequest
        If ``stat`` is unknown, ``column`` is not a numeric column, a stat other than count
        lacks a column, or ``level`` or ``bbox`` is not valid.
    TooManyZones
        If more than the server's ``max_features`` cells hold data in ``bbox``.
    """
    summary = ctx.reader.summary()
    check_level("level", level, summary.level)
    bbox = parse_bbox(bbox_raw) if bbox_raw is not None else (-180.0, -90.0, 180.0, 90.0)
    if stat not in MAP_STATS:
        raise BadRequest(f"stat {stat!r} is not one of {', '.join(MAP_STATS)}")
    if column is not None and column not in summary.numeric_columns:
        known = ", ".join(summary.numeric_columns) or "(none)"
        raise BadRequest(f"column {column!r} is not a numeric column of {ctx.reader.collection_id}; "
                         f"numeric columns: {known}")
    if column is None and stat != "count":
        raise BadRequest(f"stat {stat!r} needs a column; numeric columns: "
                         f"{', '.join(summary.numeric_columns) or '(none)'}")
    if summary.level is None:
        if fmt == "uint64":
            return Response(np.zeros(1, dtype="<u8").tobytes(), media_type=UINT64)
        return Response(feature_collection([], [], [], {"numberReturned": 0}), media_type=GEOJSON)
    data = ctx.reader.level_data(level, column, stat)
    if fmt == "uint64" and (bbox is None or covers_world(bbox)) and len(data) <= ctx.max_features:
        # the whole world as ids: no polygon to build (the page draws them)
        return Response(ids_body(data.ids, data.counts, list(data.values)), media_type=UINT64)
    found = cells_meeting_bbox(ctx.reader, data, bbox, ctx.max_features)
    if found is None:
        where, smaller = (
            (f"in bbox {bbox_raw!r}", "a smaller bbox") if bbox_raw is not None else ("in the whole store", "give a bbox")
        )
        raise TooManyZones(f"more than {ctx.max_features} cells of level {level} hold data {where}; "
                           f"use a coarser level or {smaller}")
    index, _, texts = found
    if fmt == "uint64":
        values = [data.values[i] for i in index.tolist()]
        return Response(ids_body(data.ids[index], data.counts[index], values), media_type=UINT64)
    area = float(dggs.cell_area(level, "km^2"))
    ids = data.ids[index].tolist()
    counts = data.counts[index].tolist()
    props = [
        {"zone_id": z, "level": level, "area_km2": area, "count": n, "value": clean(data.values[i])}
        for z, n, i in zip(ids, counts, index.tolist(), strict=True)
    ]
    return Response(feature_collection(ids, texts, props, {"numberReturned": len(ids)}), media_type=GEOJSON)


def ids_body(ids: np.ndarray, counts: np.ndarray, values: list[Any]) -> bytes:
    """/map/cells?f=uint64's body: count, ids (uint64), counts, values (float64, NaN for none), little-endian.

    Examples
    --------
    >>> body = ids_body(np.array(["C4", "B20"]), np.array([3, 1]), [2.5, None])
    >>> n = int(np.frombuffer(body[:8], "<u8")[0])
    >>> dggs.int_to_str(np.frombuffer(body[8:8 + 8 * n], "<u8").tolist()), np.frombuffer(body[8 + 8 * n:], "<f8").tolist()
    (['C4', 'B20'], [3.0, 1.0, 2.5, nan])
    """
    n = len(ids)
    head = np.array([n], dtype="<u8").tobytes()
    zone_ids = np.asarray(dggs.str_to_int(np.asarray(ids, dtype=str)) if n else np.empty(0), dtype="<u8")
    vals = np.array([np.nan if v is None else float(v) for v in values], dtype="<f8")
    return head + zone_ids.tobytes() + np.asarray(counts, dtype="<f8").tobytes() + vals.tobytes()


#: ``?collection=`` of the map's routes: a dataset of the store (``map/layers`` lists them) [default: the default one].
_COLLECTION = Query(None, description="A collection (a dataset of the store; map/layers lists them) "
                                      "[default: the store's default dataset]")


def register(app: FastAPI, ctx: Context) -> None:
    """Add ``/map/layers`` and ``/map/cells``."""

    @app.get("/map/layers", tags=["Web map"], summary="What the web map can show")
    def map_layers(request: Request, collection: str | None = _COLLECTION) -> JSONResponse:
        negotiate(request, None, ("json",))
        body = layers(check_collection(ctx, collection))
        body["collections"] = list(ctx.readers or [ctx.reader.collection_id])  # the store's datasets, default first
        return JSONResponse(body)

    @app.get("/map/cells", tags=["Web map"], dependencies=[Depends(refuse_unknown)], summary="Non-empty cells of a level in a bbox (GeoJSON, or ids)",
             response_class=Response, responses={200: {"content": {GEOJSON: {}, UINT64: {}}}})
    def map_cells(
        request: Request,
        level: int = Query(..., description="Level 0..stored level"),
        bbox: str | None = Query(None, description="w,s,e,n (degrees; w > e crosses 180); default the world"),
        column: str | None = Query(None, description="A numeric column; default: the row count"),
        stat: str = Query("count", description="count, sum, mean, min or max of the column"),
        f: str | None = Query(None, description="geojson (default) or uint64: ids, counts and values, binary"),
        collection: str | None = _COLLECTION,
    ) -> Response:
        fmt = negotiate(request, f, ("geojson", "json", "uint64"))  # GeoJSON is JSON too
        return cells(check_collection(ctx, collection), level, bbox, column, stat, "uint64" if fmt == "uint64" else "geojson")
