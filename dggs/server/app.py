"""The ASGI application of ``dggs serve``: OGC API - DGGS (Part 1) and the web map over one cell store.

Examples
--------
>>> from fastapi.testclient import TestClient
>>> from dggs.storage import CellStore
>>> import tempfile, os
>>> path = os.path.join(tempfile.mkdtemp(), "demo.db")
>>> with CellStore(path) as s:
...     _ = s.ingest_points([51.05, 48.85], [-114.07, 2.35], 6, {"pop": [1, 2]})
>>> app = create_app(path)
>>> with TestClient(app) as client:
...     client.get("/collections").json()["collections"][0]["id"]
...     client.get("/dggs/DGGS-Split26-ISEA/zones", params={"zone-level": 0}).json()["zones"]
'demo'
['C', 'F']
"""

from __future__ import annotations

import contextlib
import os
from collections.abc import AsyncIterator
from pathlib import Path
from typing import Any

from fastapi import FastAPI, Request

from . import features, mapdata, ogc, zones
from .errors import head_as_get, install_handlers
from .params import Context
from .reader import StoreReader
from .vendor import STATIC_FOLDER

__all__ = ["create_app", "MAX_ZONES", "MAX_FEATURES", "REFRESH", "STATIC", "OPENAPI_30"]

#: Default limit on the zones of one zone listing (``.../zones``).
MAX_ZONES = 100_000
#: Default limit on the features of ``/map/cells`` and on the sub-zone values of zone data.
MAX_FEATURES = 50_000
#: Default seconds a roll-up may lag a store that an ingest is writing to (see StoreReader).
REFRESH = 2.0
#: Media type of ``/api`` (the landing page's ``service-desc`` link says the same).
OPENAPI_30 = "application/vnd.oai.openapi+json;version=3.0"
#: The web map's files (written by the front end; served at ``/static`` and ``/``).
STATIC = STATIC_FOLDER


def create_app(
    store_path: str | os.PathLike[str],
    *,
    max_zones: int = MAX_ZONES,
    max_features: int = MAX_FEATURES,
    static: str | os.PathLike[str] | None = None,
    refresh: float = REFRESH,
) -> FastAPI:
    """Build the server's ASGI app over the cell store at ``store_path`` (opened read-only).

    Parameters
    ----------
    store_path : str or Path
        A cell store file (:class:`dggs.storage.CellStore`).  Each of its
        datasets is a collection: the default one's id is the file's stem
        (``demo.db`` -> ``demo``), a named one's its name.
    max_zones : int, default 100,000
        Most zones one zone listing returns (HTTP 413 beyond).
    max_features : int, default 50,000
        Most features of ``/map/cells``, and most sub-zones of one zone-data
        request (HTTP 413 beyond).
    static : path, optional
        The web map's folder (default: ``dggs/server/static``).
    refresh : float, default 2.0
        While an ingest writes to the store, roll-ups (the map's cells, zone
        listings, the row count) are recomputed at most this often and may lag
        the store by as much: a consistent earlier snapshot, never half a batch.
        0 shows every committed batch at once.

    Raises
    ------
    StorageError
        If the file is missing, not a SQLite database or not a cell store.
    DggsValueError
        For a limit below 1 or a negative ``refresh``.
    """
    from dggs.errors import DggsValueError

    for name, value in (("max_zones", max_zones), ("max_features", max_features)):
        if isinstance(value, bool) or not isinstance(value, int) or value < 1:
            raise DggsValueError(f"{name} must be a whole number >= 1, not {value!r}")
    if isinstance(refresh, bool) or not isinstance(refresh, (int, float)) or not refresh >= 0:
        raise DggsValueError(f"refresh must be a number of seconds >= 0, not {refresh!r}")
    reader = StoreReader(store_path, refresh=refresh)
    readers = {reader.collection_id: reader}
    try:
        from dggs.storage import list_datasets

        for name in [d["name"] for d in list_datasets(store_path)][1:]:  # each named dataset is a collection too
            cid = name if name not in readers else f"{name}-dataset"  # a dataset named as the file: set apart
            readers[cid] = StoreReader(store_path, refresh=refresh, dataset=name, collection_id=cid)
    except BaseException:
        for one in readers.values():
            one.close()
        raise
    ctx = Context(reader=reader, max_zones=max_zones, max_features=max_features, readers=readers)
    folder = Path(static) if static is not None else STATIC

    @contextlib.asynccontextmanager
    async def lifespan(app: Any) -> AsyncIterator[None]:
        yield
        for one in readers.values():
            one.close()

    app = FastAPI(
        title=f"dggs: {reader.collection_id}",
        description=(
            "OGC API - DGGS (Part 1) and OGC API - Features (Part 1) over a cell store of equal-area triangular zones "
            "(Split (2:6) on the icosahedron: DGGS-Split26-ISEA, Snyder's equal-area projection, and "
            "DGGS-Split26-IVEA, the vertex-oriented great circle one; the store's data under the DGGRS they "
            "were binned with), and the JSON of its web map."
        ),
        version=_version(),
        openapi_url=None,  # served by _serve_openapi_30 as OpenAPI 3.0
        docs_url=None,
        redoc_url=None,
        lifespan=lifespan,
    )
    app.state.ctx = ctx
    _serve_openapi_30(app)
    install_handlers(app)
    ogc.register(app, ctx, folder)
    zones.register(app, ctx)
    features.register(app, ctx)
    mapdata.register(app, ctx)
    if folder.is_dir():
        from fastapi.staticfiles import StaticFiles

        app.mount("/static", StaticFiles(directory=folder), name="static")
    app.add_middleware(_HeadAsGet)
    return app


def _serve_openapi_30(app: FastAPI) -> None:
    """Serve ``/api`` as OpenAPI 3.0 (the ``oas30`` class declared; see :mod:`.openapi30`) and its viewer.

    The media type is the one the landing page's ``service-desc`` link names (/req/oas30/oas-impl-1).
    """
    from fastapi.openapi.docs import get_swagger_ui_html
    from fastapi.openapi.utils import get_openapi
    from fastapi.responses import HTMLResponse, JSONResponse

    from .openapi30 import to_openapi_30
    from .params import negotiate

    def openapi() -> dict[str, Any]:
        if app.openapi_schema is None:
            doc = get_openapi(title=app.title, version=app.version, description=app.description, routes=app.routes)
            app.openapi_schema = to_openapi_30(doc)
        return app.openapi_schema

    app.openapi = openapi  # type: ignore[method-assign]

    @app.get("/api", include_in_schema=False)
    def api(request: Request, f: str | None = None) -> JSONResponse:
        negotiate(request, None if f in (None, "json") else f, ("openapi",))  # f=json names the JSON too
        return JSONResponse(app.openapi(), media_type=OPENAPI_30)

    @app.get("/api.html", include_in_schema=False)
    def api_html(request: Request) -> HTMLResponse:
        negotiate(request, None, ("html",))
        return get_swagger_ui_html(openapi_url="/api", title=f"{app.title} - API")


class _HeadAsGet:
    """:func:`head_as_get` in the form ``add_middleware`` takes (a class called with the app)."""

    def __init__(self, app: Any) -> None:
        self.app = head_as_get(app)

    async def __call__(self, scope: Any, receive: Any, send: Any) -> None:
        await self.app(scope, receive, send)


def _version() -> str:
    import dggs

    return str(getattr(dggs, "__version__", "0"))
