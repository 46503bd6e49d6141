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
- unknown routes are a 404 in the same shape.

Examples
--------
>>> err = BadRequest("zone-level 99 is out of range 0..28")
>>> err.status, err.problem()["type"]
(400, 'urn:dggs:error:invalid-parameter')
"""

from __future__ import annotations

from typing import Any

__all__ = [
    "ApiError",
    "BadRequest",
    "NotFound",
    "NotAcceptable",
    "TooManyZones",
    "problem",
    "install_handlers",
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

    def respond(status: int, detail: str) -> JSONResponse:
        return JSONResponse(problem(status, detail), status_code=status, media_type=PROBLEM_JSON)

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
        if exc.status_code == 404 and detail == "Not Found":
            detail = f"no resource at {request.url.path}; the landing page / lists the resources"
        return respond(exc.status_code, detail)

    app.add_exception_handler(ApiError, on_api_error)
    app.add_exception_handler(DggsError, on_dggs_error)
    app.add_exception_handler(RequestValidationError, on_validation)
    app.add_exception_handler(StarletteHTTPException, on_http)
