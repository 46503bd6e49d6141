"""The standard's own files as the server tests' referee: OGC API - DGGS Part 1's bundled OpenAPI and schemas.

The files are ``ogcapi-dggs-1.bundled.json``, ``dggs-json.json`` and ``dggrs-definition-proposed.json`` of
opengeospatial/ogcapi-discrete-global-grid-systems (commit 539f23e), read from ``../shared/ref/ogcapi-dggs/``
beside the repository, never copied into it.  Without that folder (a CI clone may lack it) every check made
with :func:`validate` skips its test, saying where it looked, and :func:`conforms` answers ``False`` so that a
test's other checks still run.

The bundled OpenAPI is read as published and then corrected in memory where the standard's own files are
defective (:func:`corrected`; the deviations are numbered in ``test_conformance_ogc``'s docstring, each with a
test showing the published file rejecting what the standard requires).  Documents are validated against the
OpenAPI 3.0 schemas with ``openapi-schema-validator`` (the validator openapi-core uses), so the standard's
``nullable`` means what it means there; the DGGRS definition against its own JSON Schema file (draft 2019-09).
"""

from __future__ import annotations

import copy
import json
from functools import cache
from pathlib import Path
from typing import Any

import pytest

from .conftest import DGGRS

REF = Path(__file__).resolve().parents[2] / ".." / "shared" / "ref" / "ogcapi-dggs"
BUNDLED = REF / "ogcapi-dggs-1.bundled.json"
#: Whether the standard's files are there.
AVAILABLE = BUNDLED.is_file()
WHY = f"the standard's bundled OpenAPI is not at {BUNDLED.resolve()} (../shared/ref)"
#: Marks a test that checks nothing but the standard's schemas.
requires_standard = pytest.mark.skipif(not AVAILABLE, reason=WHY)

HOST = "http://testserver"
OPENAPI_30 = "application/vnd.oai.openapi+json;version=3.0"


def raw_standard() -> dict[str, Any]:
    """The bundled OpenAPI as published."""
    return json.loads(BUNDLED.read_text(encoding="utf-8"))  # type: ignore[no-any-return]


def geometry_schemas(doc: dict[str, Any]) -> list[dict[str, Any]]:
    """The standard's own GeoJSON Polygon and MultiPolygon geometry schemas (from its FeatureCollection)."""
    feature = doc["components"]["schemas"]["FeatureCollection"]["properties"]["features"]["items"]
    options = feature["properties"]["geometry"]["oneOf"]
    return [o for o in options if o["title"] in ("GeoJSON Polygon", "GeoJSON MultiPolygon")]


def ok_content(doc: dict[str, Any], path: str) -> dict[str, Any]:
    """The content of the 200 response of ``GET path`` (the shared response component it refers to)."""
    ok = doc["paths"][path]["get"]["responses"]["200"]
    if "$ref" in ok:
        ok = doc["components"]["responses"][ok["$ref"].rsplit("/", 1)[-1]]
    return ok["content"]  # type: ignore[no-any-return]


@cache
def corrected() -> dict[str, Any]:
    """The bundled OpenAPI with the deviations of ``test_conformance_ogc``'s docstring corrected."""
    doc = raw_standard()
    doc["servers"] = [{"url": HOST}]
    schemas = doc["components"]["schemas"]
    schemas["extent"] = schemas["extent"]["allOf"][0]  # deviation 1
    # deviation 2: the zone's Feature (the application/geo+json zone information) moves to its own schema
    # with a Polygon or MultiPolygon geometry; zone-info's geometry is the bare geometry
    feature = copy.deepcopy(schemas["zone-info"]["properties"]["geometry"]["allOf"][1])
    feature["properties"]["geometry"] = {"oneOf": geometry_schemas(doc)}
    schemas["zone-feature"] = feature
    schemas["zone-info"]["properties"]["geometry"] = {"oneOf": geometry_schemas(doc)}
    geo = doc["paths"]["/dggs/{dggrsId}/zones/{zoneId}"]["get"]["responses"]["200"]["content"]["application/geo+json"]
    geo["schema"]["allOf"][1] = {"$ref": "#/components/schemas/zone-feature"}
    # deviation 5: the bundled file is the example server's API; its path parameters enumerate that server's
    # DGGRSs and collections.  An implementation's own definition lists its own: this server's.
    schemas["all-dggrs"] = {"type": "string", "enum": [DGGRS, "DGGS-Split26-IVEA"]}
    schemas["all-collections"] = {"type": "string", "enum": ["sample"]}
    zones = ok_content(doc, "/dggs/{dggrsId}/zones")
    zones["application/x-binary"] = {"schema": {"type": "string", "format": "binary"}}  # deviation 6
    doc["components"]["parameters"]["f-zoneData"]["schema"]["enum"].append("ubjson")  # deviation 7
    data = ok_content(doc, "/dggs/{dggrsId}/zones/{zoneId}/data")
    data["application/ubjson"] = copy.deepcopy(data["application/json"])
    return doc


def oas30_validate(schema: dict[str, Any], document: Any, doc: dict[str, Any] | None = None, *,
                  formats: bool = False) -> None:
    """Validate ``document`` against an OpenAPI 3.0 schema of the standard ($refs resolved in ``doc``).

    ``formats`` also checks the schema's ``format`` (``date-time``, ...) with the OpenAPI 3.0 format checker.
    """
    from openapi_schema_validator import OAS30Validator, oas30_format_checker
    from referencing import Registry, Resource
    from referencing.jsonschema import DRAFT4

    root = doc if doc is not None else corrected()
    registry: Registry[Any] = Registry().with_resource("urn:standard", Resource(root, DRAFT4))
    text = json.dumps(schema).replace('"#/components/', '"urn:standard#/components/')
    checker = oas30_format_checker if formats else None
    OAS30Validator(json.loads(text), registry=registry, format_checker=checker).validate(document)


def _component(name: str) -> Any:
    return lambda doc: doc["components"]["schemas"][name]


def _response(path: str, media: str = "application/json") -> Any:
    return lambda doc: ok_content(doc, path)[media]["schema"]


#: Each kind of document the server sends, and where the standard defines it (in the corrected bundled OpenAPI).
SCHEMAS = {
    "landing": _component("landingPage"),  # Common: /req/landing-page/root-success
    "conformance": _component("confClasses"),  # Common: /req/core/conformance-success
    "collections": _component("collections"),  # Common Part 2
    "collection": _component("collectionDesc"),  # Common Part 2
    "dggrs-list": _response("/dggs"),  # /req/core/dggrs-list (an inline schema of the DGGSList response)
    "dggrs": _component("dggrs"),  # /req/core/dggrs-description
    "zone-info": _component("zone-info"),  # /req/core/zone-info
    "feature": _component("zone-feature"),  # zone information as GeoJSON (deviation 2)
    "zone-list": _response("/dggs/{dggrsId}/zones"),  # /req/zone-query/zones-list (inline in ZonesList)
    "dggs-json": _component("dggs-json"),  # /req/data-json/content, as OpenAPI 3.0 (deviation 3)
    "geojson": _component("FeatureCollection"),  # /req/data-geojson/content, /req/zone-geojson/content
    "exception": _component("exception"),  # Common: the exception schema (deviation 4: problem+json)
}


def definition_schema() -> dict[str, Any]:
    """The standard's DGGRS definition JSON Schema file (draft 2019-09; informative, Annex B)."""
    return json.loads((REF / "dggrs-definition-proposed.json").read_text(encoding="utf-8"))  # type: ignore[no-any-return]


def validate(document: Any, name: str) -> None:
    """Validate ``document`` against the standard's schema for ``name``; skips the test without the files.

    ``name`` is a key of :data:`SCHEMAS` or ``"dggrs-definition"`` (the standard's definition schema file).
    Raises ``jsonschema.ValidationError`` when the document does not meet the standard.
    """
    if not AVAILABLE:
        pytest.skip(WHY)
    if name == "dggrs-definition":
        import jsonschema

        schema = definition_schema()
        jsonschema.Draft201909Validator(schema, format_checker=jsonschema.FormatChecker()).validate(document)
        return
    oas30_validate(SCHEMAS[name](corrected()), document)


def conforms(document: Any, name: str) -> bool:
    """:func:`validate` when the standard's files are there (then ``True``), else ``False`` without a check.

    For tests that check more than the schema: their other assertions run without ``../shared`` too.
    """
    if not AVAILABLE:
        return False
    validate(document, name)
    return True
