"""The served OpenAPI document, as OpenAPI 3.0 (OGC API - Common Part 1, /req/oas30/oas-definition-1).

FastAPI writes OpenAPI 3.1.0, but the conformance class the server declares (and the landing page's
``service-desc`` link, ``application/vnd.oai.openapi+json;version=3.0``) is OpenAPI 3.0.  This module
turns FastAPI's document into a 3.0.3 one:

- 3.1's ``anyOf: [X, {"type": "null"}]`` becomes 3.0's ``X`` with ``nullable: true``;
- FastAPI's 422 validation response (the server never sends one: a bad parameter is a 400) is replaced
  by the errors the server does send, 400, 404, 406 and 413, each an OGC API exception
  (``application/problem+json``, schema ``exception`` of OGC API - Common), and FastAPI's own validation
  schemas are dropped.

Examples
--------
>>> doc = {"openapi": "3.1.0", "paths": {"/x": {"get": {"parameters": [{"name": "n", "in": "query",
...        "schema": {"anyOf": [{"type": "integer"}, {"type": "null"}], "title": "N"}}], "responses": {}}}}}
>>> out = to_openapi_30(doc)
>>> out["openapi"], out["paths"]["/x"]["get"]["parameters"][0]["schema"]
('3.0.3', {'title': 'N', 'type': 'integer', 'nullable': True})
"""

from __future__ import annotations

import copy
from typing import Any

from .errors import PROBLEM_JSON

__all__ = ["to_openapi_30", "EXCEPTION_SCHEMA"]

#: OGC API - Common's ``exception.yaml`` (RFC 7807); this server always sends the four first members.
EXCEPTION_SCHEMA: dict[str, Any] = {
    "type": "object",
    "required": ["type"],
    "properties": {
        "type": {"type": "string"},
        "title": {"type": "string"},
        "status": {"type": "integer"},
        "detail": {"type": "string"},
        "instance": {"type": "string"},
    },
}

_ERRORS = {
    "400": "A parameter is not valid (named in the detail)",
    "404": "No such collection, DGGRS or resource",
    "406": "None of the media types in Accept is offered",
    "413": "More zones than the server's limit",
}


def _nullable(node: Any) -> Any:
    if isinstance(node, list):
        return [_nullable(v) for v in node]
    if not isinstance(node, dict):
        return node
    node = {k: _nullable(v) for k, v in node.items()}
    options = node.get("anyOf")
    if isinstance(options, list) and {"type": "null"} in options:
        rest = [o for o in options if o != {"type": "null"}]
        del node["anyOf"]
        if len(rest) == 1:
            node.update(rest[0])
        elif rest:
            node["anyOf"] = rest
        node["nullable"] = True
    return node


def to_openapi_30(doc: dict[str, Any]) -> dict[str, Any]:
    """FastAPI's OpenAPI 3.1 document ``doc`` as OpenAPI 3.0.3 (a new document; ``doc`` is unchanged)."""
    out: dict[str, Any] = _nullable(copy.deepcopy(doc))
    out["openapi"] = "3.0.3"
    ref = {"$ref": "#/components/schemas/Exception"}
    for item in out.get("paths", {}).values():
        for operation in item.values():
            responses = operation.setdefault("responses", {})
            responses.pop("422", None)
            for status, description in _ERRORS.items():
                responses.setdefault(status, {"description": description,
                                              "content": {PROBLEM_JSON: {"schema": dict(ref)}}})
    schemas = out.setdefault("components", {}).setdefault("schemas", {})
    schemas.pop("HTTPValidationError", None)
    schemas.pop("ValidationError", None)
    schemas["Exception"] = copy.deepcopy(EXCEPTION_SCHEMA)
    return out
