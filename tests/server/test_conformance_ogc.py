"""Every route and parameter of the server, validated against the standard's own bundled OpenAPI.

The referee is ``ogcapi-dggs-1.bundled.json`` of opengeospatial/ogcapi-discrete-global-grid-systems
(commit 539f23e), read from ``../shared/ref/ogcapi-dggs/`` beside the repository (never copied into it):
openapi-core checks each request against the standard's operation (path, parameter names and types) and
each response against the operation's response for its status and media type.  Without the reference
folder the module is skipped, saying where it looked.

Deviations of the standard's own files, corrected in memory before validating (each has a test showing
the uncorrected schema rejecting a document the standard itself requires or shows):

1. ``extent`` (Common Part 2) is ``allOf`` of the spatial/temporal schema and an ``anyOf`` whose
   ``additionalProperties`` apply to every member, ``spatial`` included, and require ``interval`` and
   ``definition``/``trs``/``vrs``: a plain ``{"spatial": {"bbox": [[-180, -90, 180, 90]]}}`` fails.  Only
   the first branch (the spatial and temporal extent) is kept.
2. ``zone-info`` ``geometry`` is a GeoJSON *Feature* with a Polygon, while Annex C's example (and every
   client) has a bare geometry, and a zone across the antimeridian needs a MultiPolygon: the geometry is
   checked against the standard's own GeoJSON Polygon and MultiPolygon geometry schemas instead.
3. The DGGS-JSON schema (``dggs-json.json``) declares JSON Schema draft 2020-12 but writes OpenAPI 3.0's
   ``nullable`` for the data values, so a strict 2020-12 validator rejects the ``null`` that
   /req/data-json/content requires for an empty sub-zone.  Here it is validated as the bundled OpenAPI
   3.0 schema (where ``nullable`` is meant), and as draft 2020-12 with ``null`` removed from the data.
5. The bundled file is the example server's definition: its ``dggrsId`` and ``collectionId`` path
   parameters enumerate that server's ids.  They are replaced by this server's (as its own definition would).
4. Errors: the bundled responses list ``application/json`` for exceptions; the server sends RFC 7807's
   ``application/problem+json`` (what OGC API - Common's exception schema is), and the body is validated
   against the standard's ``exception`` schema.
6. Zone lists: the ``f`` parameter of zone queries lists ``uint64`` and the standard has the ``zone-uint64``
   class (/req/zone-uint64/content, ``application/x-binary``), but the zone query's 200 response names no
   ``application/x-binary`` content.  It is added as the binary string the OpenAPI gives its other binary
   encodings (``image/png``); the layout itself is checked by brute force in ``test_encodings``.
7. Zone data: the standard has the ``data-ubjson`` class (/req/data-ubjson/content, ``application/ubjson``)
   but the zone data operation lists neither ``f=ubjson`` nor ``application/ubjson``.  Both are added, the
   response with the DGGS-JSON schema: the UBJSON body is decoded (py-ubjson) and validated as DGGS-JSON.
"""

from __future__ import annotations

import copy
import json
from functools import cache
from typing import Any

import pytest

from .conftest import DGGRS
from .standard import (
    HOST,
    OPENAPI_30,
    REF,
    corrected,
    geometry_schemas,
    oas30_validate,
    raw_standard,
    requires_standard,
)

pytestmark = requires_standard

ROOT = f"/dggs/{DGGRS}"
COLL = f"/collections/sample/dggs/{DGGRS}"


def _loads(data: bytes, **media_parameters: str) -> Any:
    return json.loads(data)  # the media type's parameters (version=3.0) say nothing about the JSON


def _ubjson(data: bytes, **media_parameters: str) -> Any:
    import ubjson

    return ubjson.loadb(data)


def _binary(data: bytes, **media_parameters: str) -> Any:
    return data.hex()  # a string, as the schema's binary format has it


@cache
def referee() -> Any:
    from openapi_core import Config, OpenAPI

    json_types = (OPENAPI_30, OPENAPI_30.split(";")[0], "application/geo+json")  # JSON under their own types
    config = Config(extra_media_type_deserializers={**dict.fromkeys(json_types, _loads),
                                                    "application/ubjson": _ubjson, "application/x-binary": _binary})
    return OpenAPI.from_dict(copy.deepcopy(corrected()), config=config)


def check(client: Any, url: str, headers: dict[str, str] | None = None) -> Any:
    """GET ``url`` and validate request and response against the standard's operation for the path."""
    from openapi_core.testing import MockRequest, MockResponse

    res = client.get(url, headers=headers or {})
    path, _, query = url.partition("?")
    args: dict[str, Any] = {}
    for pair in filter(None, query.split("&")):
        key, _, value = pair.partition("=")
        args.setdefault(key, []).append(value)
    request = MockRequest(HOST, "get", path, args={k: ",".join(v) for k, v in args.items()},
                          headers=headers or {})
    media = res.headers["content-type"].split(";")[0]
    if res.status_code >= 400:  # deviation 4: problem+json, the standard's exception schema
        assert media == "application/problem+json", url
        oas30_validate(corrected()["components"]["schemas"]["exception"], res.json())
        return res
    if path != "/api":
        referee().validate_request(request)  # the standard's parameter names, types and styles
    content_type = OPENAPI_30 if path == "/api" else media
    referee().validate_response(request, MockResponse(res.content, res.status_code, content_type=content_type))
    return res


# Every route, and every parameter of each (under both the root and the collection prefix).
ROUTES = ["/", "/?f=json", "/conformance", "/api", "/collections", "/collections/sample", "/dggs",
          "/collections/sample/dggs"]
for _prefix in (ROOT, COLL):
    ROUTES += [
        _prefix,
        f"{_prefix}/zones/C401",
        f"{_prefix}/zones/A",
        f"{_prefix}/zones/C401?f=geojson",
        f"{_prefix}/zones/C4/data",
        f"{_prefix}/zones/C4/data?zone-depth=2",
        f"{_prefix}/zones/C52/data?zone-depth=0-2",
        f"{_prefix}/zones/C52/data?zone-depth=0,2&f=geojson",
        f"{_prefix}/zones/C52/data?zone-depth=1&f=geojson&geometry=zone-centroid",
        f"{_prefix}/zones",
        f"{_prefix}/zones?zone-level=3",
        f"{_prefix}/zones?zone-level=4&compact-zones=false",
        f"{_prefix}/zones?zone-level=4&bbox=-10,30,20,60",
        f"{_prefix}/zones?zone-level=4&bbox=170,-40,-170,40&bbox-crs=http://www.opengis.net/def/crs/OGC/1.3/CRS84",
        f"{_prefix}/zones?zone-level=5&parent-zone=C52",
        f"{_prefix}/zones?zone-level=5&subset=Lat(35:60),Lon(-10:30)",
        f"{_prefix}/zones?zone-level=5&subset=Lat(35:60)&subset-crs=[OGC:CRS84]",
        f"{_prefix}/zones?zone-level=5&compact-zones=false&limit=20",
        f"{_prefix}/zones?zone-level=5&compact-zones=false&limit=20&offset=40",
        f"{_prefix}/zones?zone-level=3&f=geojson",
        f"{_prefix}/zones?zone-level=3&f=geojson&geometry=zone-centroid",
        f"{_prefix}/zones?zone-level=3&f=geojson&geometry=none",
        f"{_prefix}/zones?zone-level=4&f=uint64",
        f"{_prefix}/zones?zone-level=5&parent-zone=C52&compact-zones=false&limit=20&offset=5&f=uint64",
        f"{_prefix}/zones/C52/data?zone-depth=0-2&f=ubjson",
    ]
IVEA_ROOT, IVEA_COLL = ROOT.replace("ISEA", "IVEA"), COLL.replace("ISEA", "IVEA")
# The second DGGRS over this ISEA store: described, and zone information drawn on IVEA; no data under it.
ROUTES += [IVEA_ROOT, f"{IVEA_ROOT}/zones/C401", f"{IVEA_ROOT}/zones/A?f=geojson"]
ERRORS = [
    "/collections/nope", "/dggs/nope", f"{ROOT}/zones/X9", f"{ROOT}/zones/C4/data?zone-depth=x",
    f"{ROOT}/zones?subset=Foo(1:2)", f"{ROOT}/zones?subset=Lat(1:2)&bbox=0,0,1,1", f"{ROOT}/zones?bbox-crs=EPSG:3857",
    f"{ROOT}/zones?geometry=hexagon", f"{ROOT}/zones?parent-zone=X9",
    f"{IVEA_ROOT}/zones/C4/data", f"{IVEA_ROOT}/zones?zone-level=3", IVEA_COLL, f"{IVEA_COLL}/zones/C4/data",
    f"{IVEA_COLL}/zones/C401",
]
#: Every route over a store binned on IVEA, under DGGS-Split26-IVEA (and the data routes of ISEA refused).
IVEA_ROUTES = [url.replace(ROOT, IVEA_ROOT).replace(COLL, IVEA_COLL) for url in ROUTES if IVEA_ROOT not in url]
IVEA_ERRORS = [f"{ROOT}/zones/C4/data", f"{ROOT}/zones", COLL, f"{COLL}/zones?zone-level=3", f"{COLL}/zones/C401"]


@pytest.fixture(scope="module")
def ivea_client(tmp_path_factory, points):
    import numpy as np

    from dggs.server.app import create_app
    from dggs.storage import CellStore

    from .conftest import LEVEL, TestClient

    path = tmp_path_factory.mktemp("ivea") / "sample.db"
    with CellStore(path, projection="IVEA") as store:
        store.ingest_points(points.lat, points.lng, LEVEL,
                            {"pop": points.pop, "temp": points.temp, "name": np.array(["p"] * len(points.lat))})
    with TestClient(create_app(path)) as c:
        yield c


@pytest.mark.parametrize("url", IVEA_ROUTES)
def test_every_ivea_route_validates_against_the_standard(ivea_client, url):
    assert check(ivea_client, url).status_code == 200


@pytest.mark.parametrize("url", IVEA_ERRORS)
def test_isea_data_routes_of_an_ivea_store_are_the_standards_exception(ivea_client, url):
    assert check(ivea_client, url).status_code == 404


@pytest.mark.parametrize("url", ROUTES)
def test_every_route_and_parameter_validates_against_the_standard(client, url):
    assert check(client, url).status_code == 200


@pytest.mark.parametrize("url", ERRORS)
def test_every_error_is_the_standards_exception(client, url):
    assert check(client, url).status_code in (400, 404)


def test_not_acceptable_is_the_standards_exception(client):
    assert check(client, f"{ROOT}/zones", {"accept": "image/png"}).status_code == 406


def test_the_referee_can_fail(client):
    from openapi_core.testing import MockRequest, MockResponse

    request = MockRequest(HOST, "get", f"{ROOT}/zones")
    for body in ({"zones": [1, 2]}, {"links": []}):  # ids are strings; zones is required
        with pytest.raises(Exception, match="nvalid|alidation"):
            referee().validate_response(request, MockResponse(json.dumps(body).encode()))


def test_the_referee_checks_the_binary_encodings(client):
    # deviations 6 and 7 add the media types, and the UBJSON is validated as DGGS-JSON: a UBJSON body without
    # the required members fails, and neither binary type is accepted where the standard does not list it.
    import ubjson
    from openapi_core.testing import MockRequest, MockResponse

    data = MockRequest(HOST, "get", f"{ROOT}/zones/C4/data")
    with pytest.raises(Exception, match="nvalid|alidation"):
        referee().validate_response(data, MockResponse(ubjson.dumpb({"zoneId": 4}), content_type="application/ubjson"))
    body = client.get(f"{ROOT}/zones?f=uint64").content
    with pytest.raises(Exception, match="not found|nvalid|alidation"):
        referee().validate_response(data, MockResponse(body, content_type="application/x-binary"))
    zones = MockRequest(HOST, "get", f"{ROOT}/zones")
    referee().validate_response(zones, MockResponse(body, content_type="application/x-binary"))


# -- the deviations of the standard's own files --------------------------------------------


def test_deviation_1_the_published_extent_rejects_a_plain_bbox():
    import jsonschema

    doc = raw_standard()
    plain = {"spatial": {"bbox": [[-180.0, -90.0, 180.0, 90.0]]}}
    with pytest.raises(jsonschema.ValidationError):
        oas30_validate(doc["components"]["schemas"]["extent"], plain, doc)
    oas30_validate(corrected()["components"]["schemas"]["extent"], plain)


def test_deviation_2_zone_info_geometry_is_a_bare_geometry(client):
    import jsonschema

    info = client.get(f"{ROOT}/zones/C401").json()
    doc = raw_standard()
    with pytest.raises(jsonschema.ValidationError):
        oas30_validate(doc["components"]["schemas"]["zone-info"]["properties"]["geometry"], info["geometry"], doc)
    oas30_validate({"oneOf": geometry_schemas(doc)}, info["geometry"], doc)


def test_deviation_3_dggs_json_nullable_under_draft_2020_12(client):
    import jsonschema

    schema = json.loads((REF / "dggs-json.json").read_text(encoding="utf-8"))
    body = client.get(f"{ROOT}/zones/C4/data?zone-depth=3").json()
    values = [v for entries in body["values"].values() for e in entries for v in e["data"]]
    assert None in values  # empty sub-zones: null (/req/data-json/content)
    validator = jsonschema.Draft202012Validator(schema)
    assert not validator.is_valid(body)  # the defect: 2020-12 does not know nullable
    for entries in body["values"].values():
        for e in entries:
            e["data"] = [v for v in e["data"] if v is not None]
    validator.validate(body)  # the rest of the document meets the published schema
