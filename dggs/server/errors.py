"""Errors of the server as JSON problem documents (RFC 7807, the OGC API exception schema).

OGC API - Common (and DGGS Part 1's ``openapi/schemas/common-core/exception.yaml``)
describe an error by ``type`` (required), ``title``, ``status``, ``detail``.  Every
error the server returns has all four, with media type ``application/problem+json``;
``detail`` names the bad value.

- :class:`ApiError` and its subclasses are raised by the handlers;
- every :class:`dggs.DggsError` raised while answering (a bad cell id, a level out of
  range, an unknown column) is a 400;
- FastAPI's own validation errors (a query parameter that is not an integer) are a 400
  naming the parameter and the value, not FastAPI's 422;
- unknown routes are a 404 in the same shape; a method a route does not take is a 405 with an
  ``Allow`` header (RFC 9110, section 15.5.6), and HEAD is taken wherever GET is (section 9.3.2:
  :func:`head_as_get`);
- a store file deleted, truncated or damaged while serving (a :class:`dggs.StorageError`, or a raw
  ``sqlite3.Error`` that got past the reader) is a 503 naming the file.

Examples
--------
>>> err = BadRequest("zone-level 99 is out of range 0..28")
>>> err.status, err.problem()["type"]
(400, 'urn:dggs:error:invalid-parameter')
"""

from __future__ import annotations

import sqlite3
from typing import Any

__all__ = [
    "ApiError",
    "BadRequest",
    "NotFound",
    "NotAcceptable",
    "TooManyZones",
    "problem",
    "install_handlers",
    "head_as_get",
    "PROBLEM_JSON",
]

#: Media type of error bodies (RFC 7807).
PROBLEM_JSON = "application/problem+json"

_TYPES = {
    400: ("urn:dggs:error:invalid-parameter", "Invalid parameter"),
    404: ("urn:dggs:error:not-found", "Not found"),
    405: ("urn:dggs:error:method-not-allowed", "Method not allowed"),
    406: ("urn:dggs:error:not-acceptable", "Not acceptable"),
    413: ("urn:dggs:error:too-many-zones", "Too many zones"),
    500: ("urn:dggs:error:server-error", "Server error"),
    503: ("urn:dggs:error:store-unavailable", "Store unavailable"),
}


def problem(status: int, detail: str) -> dict[str, Any]:
    """The problem document for ``status`` with ``detail``.

    Examples
    --------
    >>> problem(404, "no collection 'x'")["title"]
    'Not found'
    """
    kind, title = _TYPES.get(status, ("urn:dggs:error:http-%d" % status, "HTTP error"))
    return {"type": kind, "title": title, "status": status, "detail": detail}


class ApiError(Exception):
    """An HTTP error answered as a problem document."""

    status = 500

    def __init__(self, detail: str) -> None:
        super().__init__(detail)
        self.detail = detail

    def problem(self) -> dict[str, Any]:
        """The JSON body."""
        return problem(self.status, self.detail)


class BadRequest(ApiError):
    """400: a query parameter or path part is not valid (it is named in the detail)."""

    status = 400


class NotFound(ApiError):
    """404: no such collection, DGGRS or route."""

    status = 404


class NotAcceptable(ApiError):
    """406: no representation the client accepts."""

    status = 406


class TooManyZones(ApiError):
    """413: the answer would hold more zones than the server's limit."""

    status = 413


def install_handlers(app: Any) -> None:
    """Register the exception handlers on a FastAPI ``app``."""
    from fastapi.exceptions import RequestValidationError
    from fastapi.responses import JSONResponse
    from starlette.exceptions import HTTPException as StarletteHTTPException

    from dggs.errors import DggsError, StorageError

    def respond(status: int, detail: str, headers: Any = None) -> JSONResponse:
        return JSONResponse(problem(status, detail), status_code=status, media_type=PROBLEM_JSON, headers=headers)

    async def on_sqlite(request: Any, exc: Exception) -> JSONResponse:
        from dggs.storage.connection import translate

        path = str(request.app.state.ctx.reader.path)
        return respond(503, str(translate(exc, path)))

    async def on_api_error(request: Any, exc: Exception) -> JSONResponse:
        assert isinstance(exc, ApiError)
        return respond(exc.status, exc.detail)

    async def on_dggs_error(request: Any, exc: Exception) -> JSONResponse:
        # A broken or vanished store file is the server's problem, not the client's.
        if isinstance(exc, StorageError):
            return respond(503, str(exc))
        return respond(400, str(exc))

    async def on_validation(request: Any, exc: Exception) -> JSONResponse:
        assert isinstance(exc, RequestValidationError)
        parts = []
        for err in exc.errors():
            loc = [str(p) for p in err.get("loc", ()) if p not in ("query", "path", "body")]
            name = ".".join(loc) or "request"
            given = err.get("input")
            parts.append(f"parameter {name!r} = {given!r}: {err.get('msg', 'invalid')}")
        return respond(400, "; ".join(parts) or "invalid request")

    async def on_http(request: Any, exc: Exception) -> JSONResponse:
        assert isinstance(exc, StarletteHTTPException)
        detail = exc.detail if isinstance(exc.detail, str) else str(exc.detail)
        headers = dict(exc.headers or {})
        if exc.status_code == 404 and detail == "Not Found":
            detail = f"no resource at {request.url.path}; the landing page / lists the resources"
        if exc.status_code == 405:
            allowed = [m.strip() for m in headers.get("Allow", "GET").split(",") if m.strip()]
            if "GET" in allowed and "HEAD" not in allowed:
                allowed.append("HEAD")  # head_as_get answers it
            headers["Allow"] = ", ".join(allowed)
            detail = f"{request.method} is not allowed on {request.url.path}; allowed: {headers['Allow']}"
        return respond(exc.status_code, detail, headers or None)

    app.add_exception_handler(ApiError, on_api_error)
    app.add_exception_handler(DggsError, on_dggs_error)
    app.add_exception_handler(RequestValidationError, on_validation)
    app.add_exception_handler(StarletteHTTPException, on_http)
    app.add_exception_handler(sqlite3.Error, on_sqlite)


def head_as_get(app: Any) -> Any:
    """ASGI middleware: answer HEAD on every route as GET, with the GET's headers and no body.

    RFC 9110, section 9.3.2: a general-purpose server supports HEAD, the same answer as GET without
    the content.  FastAPI's ``@app.get`` routes take GET alone (Starlette adds HEAD only to its own
    routes), so HEAD is passed on as GET and the body dropped here.

    Examples
    --------
    >>> async def inner(scope, receive, send):
    ...     await send({"type": "http.response.start", "status": 200, "headers": []})
    ...     await send({"type": "http.response.body", "body": scope["method"].encode()})
    >>> sent = []
    >>> async def send(message):
    ...     sent.append(message)
    >>> import asyncio
    >>> asyncio.run(head_as_get(inner)({"type": "http", "method": "HEAD"}, None, send))
    >>> sent[1]["body"]
    b''
    """

    async def middleware(scope: Any, receive: Any, send: Any) -> None:
        if scope.get("type") != "http" or scope.get("method") != "HEAD":
            await app(scope, receive, send)
            return

        async def send_no_body(message: Any) -> None:
            if message.get("type") == "http.response.body":
                message = {**message, "body": b""}
            await send(message)

        await app({**scope, "method": "GET"}, receive, send_no_body)

    return middleware
