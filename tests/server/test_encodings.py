"""The binary encodings (zone-uint64, DGGS-UBJSON) and content negotiation (406) on every route.

- /req/zone-uint64/content: the ``application/x-binary`` zone list is decoded here with numpy (a little-endian
  uint64 count, then the ids) and compared with the JSON list of the same query, its text ids converted to
  integers by ``dggs.str_to_int``; the count is checked against the body's length.
- /req/data-ubjson/content: the ``application/ubjson`` zone data is decoded with py-ubjson and compared with
  the DGGS-JSON document of the same request.
- OGC API - Common /req/core/http: every route answers 406, with the standard's exception body naming the
  Accept header, when that header names no media type the route offers; ``*/*``, ``type/*``, ``q`` weights
  and the ``f`` parameter behave on every route as on the zone routes.
"""

from __future__ import annotations

import numpy as np
import pytest

import dggs

from .conftest import DGGRS
from .test_errors import check

ROOT = f"/dggs/{DGGRS}"
COLL = f"/collections/sample/dggs/{DGGRS}"
BINARY = "application/x-binary"

QUERIES = [
    {"zone-level": 0},
    {"zone-level": 4},
    {"zone-level": 6, "compact-zones": "false"},
    {"zone-level": 6},  # compacted: zones of several levels
    {"zone-level": 5, "parent-zone": dggs.latlng_to_cell(45.0, 7.0, 2)},
    {"zone-level": 5, "bbox": "170,-40,-170,40"},
    {"zone-level": 5, "subset": "Lat(35:60),Lon(-10:30)"},
    {"zone-level": 6, "compact-zones": "false", "limit": 17, "offset": 30},
    {"zone-level": 3, "parent-zone": "J1"},  # no data there: an empty list
]


def decode_uint64(body: bytes) -> list[int]:
    """The ids of a zone-uint64 body, checking its count against its length."""
    assert len(body) % 8 == 0 and len(body) >= 8
    words = np.frombuffer(body, dtype="<u8")
    assert int(words[0]) == len(words) - 1  # the count, then exactly that many ids
    return [int(v) for v in words[1:]]


@pytest.mark.parametrize("prefix", [ROOT, COLL])
@pytest.mark.parametrize("query", QUERIES, ids=lambda q: "&".join(f"{k}={v}" for k, v in q.items()))
def test_uint64_zone_list_is_the_json_list_as_integers(client, prefix, query):
    listed = client.get(f"{prefix}/zones", params=query).json()["zones"]
    expected = [int(v) for v in dggs.str_to_int(listed)] if listed else []
    by_f = client.get(f"{prefix}/zones", params={**query, "f": "uint64"})
    by_accept = client.get(f"{prefix}/zones", params=query, headers={"accept": BINARY})
    for res in (by_f, by_accept):
        assert res.status_code == 200 and res.headers["content-type"] == BINARY
        assert decode_uint64(res.content) == expected
    assert query.get("zone-level") != 4 or len(expected) > 10  # not a trivially empty comparison


def test_uint64_ids_are_the_zones_uint64_ids(client):
    ids = decode_uint64(client.get(f"{ROOT}/zones", params={"zone-level": 2, "f": "uint64"}).content)
    text = client.get(f"{ROOT}/zones", params={"zone-level": 2}).json()["zones"]
    for zone, value in zip(text[:5], ids[:5], strict=True):  # the uint64Id of zone information
        assert client.get(f"{ROOT}/zones/{zone}").json()["uint64Id"] == str(value)


def test_uint64_zone_list_honours_the_limits_and_bad_input(client, small_client):
    check(small_client.get(f"{ROOT}/zones", params={"compact-zones": "false", "f": "uint64"}), 413, "10")
    check(client.get(f"{ROOT}/zones", params={"f": "uint64", "subset": "Foo(1:2)"}), 400, "Foo")
    check(client.get(f"{ROOT}/zones/C4/data", params={"f": "uint64"}), 400, "'uint64'")  # a zone list format only
    check(client.get(f"{ROOT}/zones/C4", headers={"accept": BINARY}), 406, BINARY)


def grid_md_uint64(zone: str) -> int:
    """A zone's 64-bit id written from docs/grid.md's bit table, by hand (not by ``dggs.str_to_int``).

    Bit 62 the marker, bits 61-57 the face, 56-54 the level-1 digit + 1, then for level k = 2..28 the digit + 1
    at bits 2(28-k)+1..2(28-k).
    """
    value = (1 << 62) | ((ord(zone[0]) - ord("A")) << 57)
    if len(zone) > 1:
        value |= (int(zone[1]) + 1) << 54
    for k, digit in enumerate(zone[2:], start=2):
        value |= (int(digit) + 1) << (2 * (28 - k))
    return value


def test_grid_md_oracle_matches_its_own_example():
    assert grid_md_uint64("C401") == 4996743786567565312  # docs/grid.md's worked example


@pytest.mark.parametrize(("lat", "lng"), [(90.0, 0.0), (-90.0, 0.0), (0.0, 180.0), (0.0, -180.0), (10.0, 179.9999),
                                          (58.282525588539, 11.25), (45.0, 7.0)])
def test_uint64_zone_list_layout_per_the_requirement(client, lat, lng):
    # /req/zone-uint64/content, each part: a first 64-bit count of the zones returned, then one 64-bit integer per
    # zone; the DGGRS's own 64-bit ids (docs/grid.md's layout, encoded here by hand); little endian (read byte
    # by byte, not through numpy's dtype).  Pinned at the poles, the antimeridian and an icosahedron vertex.
    parent = dggs.latlng_to_cell(lat, lng, 2)
    query = {"zone-level": 6, "parent-zone": parent, "compact-zones": "false"}
    listed = client.get(f"{ROOT}/zones", params=query).json()["zones"]
    body = client.get(f"{ROOT}/zones", params={**query, "f": "uint64"}).content
    words = [int.from_bytes(body[i:i + 8], "little") for i in range(0, len(body), 8)]
    assert len(body) == 8 * (1 + len(listed)) and words[0] == len(listed)
    assert words[1:] == [grid_md_uint64(z) for z in listed]
    assert parent != dggs.latlng_to_cell(45.0, 7.0, 2) or len(listed) > 5  # the cluster: a real comparison


@pytest.mark.parametrize("prefix", [ROOT, COLL])
@pytest.mark.parametrize(("zone", "depth"), [("C4", "2"), ("C52", "0-3"), ("A", "0,2"), (None, "1")])
def test_ubjson_zone_data_is_the_dggs_json_document(client, points, prefix, zone, depth):
    ubjson = pytest.importorskip("ubjson")
    zone = zone or dggs.latlng_to_cell(points.lat[20], points.lng[20], 3)
    url = f"{prefix}/zones/{zone}/data"
    document = client.get(url, params={"zone-depth": depth}).json()
    by_f = client.get(url, params={"zone-depth": depth, "f": "ubjson"})
    by_accept = client.get(url, params={"zone-depth": depth}, headers={"accept": "application/ubjson"})
    for res in (by_f, by_accept):
        assert res.status_code == 200 and res.headers["content-type"] == "application/ubjson"
        decoded = ubjson.loadb(res.content)
        self_link = decoded["links"].pop(0)  # the one difference: the self link names this request
        assert self_link == {"href": str(res.url), "rel": "self", "type": "application/ubjson"}
        assert decoded == {**document, "links": document["links"][1:]}
    values = [v for entries in document["values"].values() for e in entries for v in e["data"]]
    assert any(isinstance(v, float) for v in values)  # floats went through (float64: equal, not rounded)
    assert depth != "0-3" or None in values  # and the nulls of empty sub-zones


# -- 406 and negotiation on every route ---------------------------------------------------------------

#: Every route, a media type it offers, and one it does not.
ROUTES = [
    ("/", "application/json"),
    ("/conformance", "application/json"),
    ("/api", "application/vnd.oai.openapi+json;version=3.0"),
    ("/api.html", "text/html"),
    ("/collections", "application/json"),
    ("/collections/sample", "application/json"),
    ("/dggs", "application/json"),
    ("/collections/sample/dggs", "application/json"),
    (ROOT, "application/json"),
    (COLL, "application/json"),
    (f"{ROOT}/definition", "application/json"),
    (f"{COLL}/definition", "application/json"),
    (f"{ROOT}/zones/C4", "application/geo+json"),
    (f"{COLL}/zones/C4", "application/json"),
    (f"{ROOT}/zones/C4/data?zone-depth=1", "application/geo+json"),
    (f"{COLL}/zones/C4/data?zone-depth=1", "application/json"),
    (f"{ROOT}/zones?zone-level=2", BINARY),
    (f"{COLL}/zones?zone-level=2", "application/geo+json"),
    ("/map/layers", "application/json"),
    ("/map/cells?level=1", "application/geo+json"),
    ("/robots.txt", "text/plain"),
]


@pytest.mark.parametrize(("url", "offered"), ROUTES, ids=[r[0] for r in ROUTES])
def test_every_route_answers_406_for_what_it_cannot_give(client, url, offered):
    for accept in ("image/png", "text/csv, image/*;q=0.9", f"{offered};q=0, image/png"):
        check(client.get(url, headers={"accept": accept}), 406, repr(accept))
    for accept in (offered, "*/*", f"image/png, {offered};q=0.5", f"{offered.split('/')[0]}/*", "", f"{offered.upper()}"):
        res = client.get(url, headers={"accept": accept})
        assert res.status_code == 200, (accept, res.text)
    assert client.get(url, headers={"accept": offered}).headers["content-type"].split(";")[0] == offered.split(";")[0]


@pytest.mark.parametrize("url", ["/conformance", "/collections", "/dggs", f"{ROOT}/definition", f"{COLL}"])
def test_f_overrides_accept_on_the_metadata_routes(client, url):
    sep = "&" if "?" in url else "?"
    res = client.get(f"{url}{sep}f=json", headers={"accept": "image/png"})  # f wins over the header
    assert res.status_code == 200 and res.headers["content-type"] == "application/json"
    check(client.get(f"{url}{sep}f=xml"), 400, "'xml'")
    check(client.get(f"{url}{sep}f=html"), 400, "'html'")  # no HTML for these resources


def test_the_preferred_type_wins_by_q(client):
    url = f"{ROOT}/zones?zone-level=1"
    res = client.get(url, headers={"accept": "application/json;q=0.5, application/x-binary;q=0.9"})
    assert res.headers["content-type"] == BINARY
    res = client.get(url, headers={"accept": "application/json, application/x-binary;q=0.9"})
    assert res.headers["content-type"] == "application/json"
    res = client.get(url, headers={"accept": "application/*"})  # the route's first application/ type
    assert res.headers["content-type"] == "application/json"
