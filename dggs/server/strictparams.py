"""Query parameters a data route does not take are a 400 naming them, never silently ignored.

OGC API - Features Part 1 /req/core/query-param-unknown: "The server SHALL respond with a response with the
status code 400, if the request URI includes a query parameter that is not specified in the API definition."
A client that asked for ``filter=sum>10`` and got every zone would believe it had a filter.  The parameters a
route takes are read from the route itself (its FastAPI query parameters, with their aliases: the same list
the OpenAPI document at ``/api`` gives), so the check and the API definition cannot disagree.

Parameters that OGC API - DGGS, Features or their extensions define but this server does not implement are
named as such (``filter``, ``datetime``, ``properties`` where not implemented, ``crs``, ...), with what the
route takes instead.

Examples
--------
>>> NOT_IMPLEMENTED["filter"]
'CQL2 filters are not implemented'
"""

from __future__ import annotations

from typing import Any

from fastapi import Request

from .errors import BadRequest

__all__ = ["refuse_unknown", "route_parameters", "NOT_IMPLEMENTED"]

#: Parameters of the OGC APIs (DGGS Part 1's bundled OpenAPI, Features Parts 1-4, Common Part 2, CQL2) that a
#: route may not implement here, and why they matter: refused by name with a 400 where a route lacks them.
NOT_IMPLEMENTED = {
    "filter": "CQL2 filters are not implemented",
    "filter-lang": "CQL2 filters are not implemented",
    "filter-crs": "CQL2 filters are not implemented",
    "datetime": "the data have no time",
    "properties": "property selection is not implemented on this resource",
    "exclude-properties": "property selection is not implemented",
    "collections": "this server has one collection, the store",
    "crs": "the only CRS is CRS84",
    "bbox-crs": "the only CRS is CRS84",
    "profile": "profiles are not implemented",
    "values-offset": "values are not scaled",
    "values-scale": "values are not scaled",
    "subset": "subsetting is not implemented on this resource",
    "sortby": "sorting is not implemented",
    "q": "text search is not implemented",
    "ids": "selection by ids is not implemented",
    "skipGeometry": "geometry is always returned",
}

_CACHE: dict[int, frozenset[str]] = {}


def route_parameters(route: Any) -> frozenset[str]:
    """The query parameter names (aliases) that ``route`` and its dependencies declare."""
    key = id(route)
    found = _CACHE.get(key)
    if found is None:
        names: set[str] = set()
        stack = [route.dependant]
        while stack:
            dependant = stack.pop()
            names.update(str(p.alias) for p in dependant.query_params)
            stack.extend(dependant.dependencies)
        found = _CACHE[key] = frozenset(names)
    return found


async def refuse_unknown(request: Request) -> None:
    """Raise a 400 naming every query parameter the matched route does not take (a FastAPI dependency).

    Asynchronous so that FastAPI runs it on the event loop: a plain function would take a worker thread per
    request on top of the handler's.

    Raises
    ------
    BadRequest
        For the first such parameter, naming it, saying why when it is a standard one not implemented
        here, and listing the parameters the route takes.
    """
    route = request.scope.get("route")
    if route is None or not hasattr(route, "dependant"):
        return
    allowed = route_parameters(route)
    unknown = [name for name in dict.fromkeys(request.query_params.keys()) if name not in allowed]
    if not unknown:
        return
    name = unknown[0]
    takes = ", ".join(sorted(allowed)) or "none"
    why = NOT_IMPLEMENTED.get(name)
    others = f" (also {', '.join(map(repr, unknown[1:]))})" if len(unknown) > 1 else ""
    if why is not None:
        raise BadRequest(f"query parameter {name!r} is not supported here: {why}{others}; this resource takes: "
                         f"{takes}")
    raise BadRequest(f"unknown query parameter {name!r}{others}; this resource takes: {takes}")
