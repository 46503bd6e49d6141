"""OGC API - Features items read by the clients themselves from a real ``dggs serve`` process on 127.0.0.1.

Referees (issue 36): GDAL's OGC API - Features driver (``OAPIF``, through pyogrio's bundled GDAL) lists the
collection as a layer and reads every feature, with and without a bbox; OWSLib's ``Features`` reads the
conformance, the collection and pages of items.  Expected values are brute force over the raw points of the
test store (``dggs.latlng_to_cell`` and numpy group-bys), and expected bbox results the zones whose polygon
(``dggs.cell_to_polygon``, as the server draws it) meets the box, as ``test_api`` checks the zone query.
"""

from __future__ import annotations

import json
import urllib.request
from typing import Any

import numpy as np
import pytest
import shapely
import shapely.geometry
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

import dggs
from dggs.storage import CellStore
from tests.server.conftest import LEVEL
from tests.server.test_api import brute_force_bbox
from tests.strategies import examples

from .serving import serving

COLLECTION = "sample"  # the stem of conftest's sample.db
FEATURES_CORE = "http://www.opengis.net/spec/ogcapi-features-1/1.0/conf/core"





@pytest.fixture(scope="module")
def url(store_path):
    with serving(store_path) as base:
        yield base


def truth(points, level: int = LEVEL) -> dict[str, dict[str, Any]]:
    """Each zone holding points at ``level``: its row count and the sum, mean, min and max of pop and temp."""
    cells = np.asarray(dggs.latlng_to_cell(points.lat, points.lng, level)).astype(str)
    out: dict[str, dict[str, Any]] = {}
    for cell in np.unique(cells):
        sel = cells == cell
        row: dict[str, Any] = {"count": int(sel.sum())}
        for name, values in (("pop", points.pop[sel]), ("temp", points.temp[sel])):
            row |= {f"{name}_sum": values.sum(), f"{name}_mean": values.mean(), f"{name}_min": values.min(),
                    f"{name}_max": values.max()}
        out[str(cell)] = row
    return out


def _same_values(got: dict[str, Any], want: dict[str, Any], zone: str) -> None:
    for key, value in want.items():
        assert got[key] == pytest.approx(value, rel=1e-12, abs=1e-9), (zone, key)


# -- GDAL ---------------------------------------------------------------------


def _gdal(url: str) -> str:
    import pyogrio

    assert "OAPIF" in pyogrio.list_drivers(), "pyogrio's GDAL has no OGC API - Features driver (OAPIF)"
    return f"OAPIF:{url}"


def test_gdal_lists_the_collection_as_a_layer(url):
    import pyogrio

    layers = pyogrio.list_layers(_gdal(url))
    assert [name for name, _ in layers] == [COLLECTION]
    info = pyogrio.read_info(_gdal(url), layer=COLLECTION)
    assert {"zoneID", "level", "count", "pop_sum", "temp_mean"} <= set(info["fields"])


def test_gdal_reads_every_feature_with_its_values(url, points):
    import pyogrio

    df = pyogrio.read_dataframe(_gdal(url), layer=COLLECTION)
    want = truth(points)
    assert len(df) == len(want) and set(df["zoneID"]) == set(want)  # GDAL followed every next link
    assert df["zoneID"].is_unique
    for row in df.itertuples(index=False):
        assert row.level == LEVEL
        _same_values(row._asdict(), want[row.zoneID], row.zoneID)
        assert row.geometry.is_valid and row.geometry.geom_type in ("Polygon", "MultiPolygon")
    # the polygons are the zones: each holds the centre of its zone
    lat, lng = dggs.cell_to_latlng(np.asarray(df["zoneID"], dtype=str))
    assert shapely.intersects(np.asarray(df.geometry), shapely.points(lng, lat)).all()


@pytest.mark.parametrize("bbox", [(-10.0, 30.0, 20.0, 60.0), (100.0, -5.0, 100.5, -4.5), (-180.0, 80.0, 180.0, 90.0)])
def test_gdal_bbox_reads_the_zones_meeting_the_box(url, points, bbox):
    import pyogrio

    df = pyogrio.read_dataframe(_gdal(url), layer=COLLECTION, bbox=bbox)
    assert set(df["zoneID"]) == brute_force_bbox(points, LEVEL, bbox)


def test_gdal_reads_64_bit_sums_that_its_first_page_does_not_show(tmp_path):
    # GDAL types the fields from the collection's describedby schema (else from a first page of 20 features,
    # which made a sum of 5e9 further on a 32-bit field clamped to 2147483647)
    import pyogrio

    cells = np.asarray(dggs.uncompact_cells(["A", "B"], 3))
    lat, lng = dggs.cell_to_latlng(cells)
    big = np.arange(len(cells)) >= 30  # the first 30 zones in id order hold 1, the rest 5e9
    path = tmp_path / "big.db"
    with CellStore(path) as store:
        store.ingest_points(lat, lng, 3, {"pop": np.where(big, 5_000_000_000, 1), "v": np.where(big, 0.5, 1.0)})
    with serving(path) as base:
        df = pyogrio.read_dataframe(_gdal(base), layer="big")
    df = df.set_index("zoneID").loc[np.sort(cells)]
    assert df["pop_sum"].tolist() == np.where(big[np.argsort(cells)], 5_000_000_000, 1).tolist()
    assert str(df["pop_sum"].dtype) == "int64" and str(df["count"].dtype) == "int64"
    assert df["v_mean"].tolist() == np.where(big[np.argsort(cells)], 0.5, 1.0).tolist()


# -- OWSLib -------------------------------------------------------------------


def test_owslib_reads_the_collection_and_its_items(url, points):
    from owslib.ogcapi.features import Features

    api = Features(url)
    assert FEATURES_CORE in api.conformance()["conformsTo"]
    assert [c["id"] for c in api.collections()["collections"]] == [COLLECTION]
    assert any(link["rel"] == "items" and link["type"] == "application/geo+json"
               for link in api.collection(COLLECTION)["links"])
    want = truth(points)
    seen: list[str] = []
    offset = 0
    while True:  # pages of 500 (offset as the next link gives it)
        page = api.collection_items(COLLECTION, limit=500, offset=offset)
        assert page["numberMatched"] == len(want) and page["numberReturned"] == len(page["features"]) <= 500
        for feature in page["features"]:
            assert feature["id"] == feature["properties"]["zoneID"]
            _same_values(feature["properties"], want[feature["id"]], feature["id"])
        seen += [f["id"] for f in page["features"]]
        nxt = [link["href"] for link in page["links"] if link["rel"] == "next"]
        if not nxt:
            break
        assert f"offset={offset + 500}" in nxt[0]
        offset += 500
    assert sorted(seen) == seen and set(seen) == set(want) and len(seen) == len(want)


def test_owslib_reads_one_feature_at_any_level(url, points):
    from owslib.ogcapi.features import Features

    api = Features(url)
    for level in (0, 3, LEVEL):
        want = truth(points, level)
        zone = sorted(want)[len(want) // 2]
        feature = api.collection_item(COLLECTION, zone)
        assert feature["id"] == zone and feature["properties"]["level"] == level
        _same_values(feature["properties"], want[zone], zone)
        page = api.collection_items(COLLECTION, **{"zone-level": level, "limit": 10_000})
        assert {f["id"] for f in page["features"]} == set(want)


# -- the GeoJSON itself (read by the json module, no client) -----------------


def get(url: str) -> tuple[int, Any, Any]:
    try:
        with urllib.request.urlopen(url, timeout=30) as res:
            return res.status, res.headers, json.load(res)
    except urllib.error.HTTPError as exc:
        return exc.code, exc.headers, json.loads(exc.read())


def test_items_paging_links_and_counts(url, points):
    want = truth(points)
    status, headers, doc = get(f"{url}/collections/{COLLECTION}/items?limit=7&offset=14")
    assert status == 200 and headers["Content-Type"] == "application/geo+json"
    assert doc["type"] == "FeatureCollection" and doc["numberMatched"] == len(want) and doc["numberReturned"] == 7
    assert [f["id"] for f in doc["features"]] == sorted(want)[14:21]
    rels = {link["rel"]: link["href"] for link in doc["links"]}
    assert {"self", "next", "prev", "collection"} <= set(rels)
    assert get(rels["next"])[2]["features"][0]["id"] == sorted(want)[21]
    assert get(rels["prev"])[2]["features"][0]["id"] == sorted(want)[7]
    last = get(f"{url}/collections/{COLLECTION}/items?limit=7&offset={len(want) - 3}")[2]
    assert last["numberReturned"] == 3 and "next" not in {link["rel"] for link in last["links"]}


def test_a_missing_feature_is_a_404(url, points):
    empty = next(c for c in dggs.cell_to_children("A", LEVEL) if c not in truth(points))
    for zone in (empty, "nope", "A" + "0" * 40):
        status, _, body = get(f"{url}/collections/{COLLECTION}/items/{zone}")
        assert status == 404 and zone in body["detail"]
    assert get(f"{url}/collections/other/items")[0] == 404


def test_openapi_lists_the_features_routes(client):
    # /req/oas30/oas-definition-1 with the Features routes: GDAL reads /api for the items' parameters
    from openapi_spec_validator import OpenAPIV30SpecValidator

    api = client.get("/api").json()
    OpenAPIV30SpecValidator(api).validate()
    for path, names in (("/collections/{collectionId}/items", {"bbox", "limit", "offset", "datetime", "zone-level",
                                                                "properties", "crs", "bbox-crs", "f"}),
                        ("/collections/{collectionId}/items/{featureId}", {"properties", "crs", "f"})):
        op = api["paths"][path]["get"]
        assert {p["name"] for p in op["parameters"] if p["in"] == "query"} == names, path
        assert "application/geo+json" in op["responses"]["200"]["content"], path
    conformance = client.get("/conformance").json()["conformsTo"]
    assert {FEATURES_CORE, FEATURES_CORE.replace("core", "geojson"), FEATURES_CORE.replace("core", "oas30")} <= set(conformance)
    assert FEATURES_CORE.replace("core", "html") not in conformance


# -- properties over the store (in process) ------------------------------------

_SPECIAL = [(90.0, 0.0), (-90.0, 0.0), (0.0, 180.0), (0.0, -180.0), (10.0, 179.9999), (65.0, 180.0),
            (58.282525588539, 11.25)]  # the poles, the antimeridian, an icosahedron vertex (ISEA)


@settings(max_examples=examples(40), deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(st.integers(min_value=0, max_value=10_000), st.integers(min_value=0, max_value=LEVEL))
@example(0, 0).via("the north pole's face")
@example(1, LEVEL).via("the north pole")
@example(2, LEVEL).via("the south pole")
@example(4, 3).via("on the antimeridian")
@example(9, LEVEL).via("near the antimeridian")
def test_one_feature_is_the_brute_force_roll_up_of_its_points(client, points, which, level):
    n = len(points.lat)
    lat, lng = float(points.lat[which % n]), float(points.lng[which % n])
    zone = str(dggs.latlng_to_cell(lat, lng, level))
    inside = np.asarray(dggs.latlng_to_cell(points.lat, points.lng, level)).astype(str) == zone
    res = client.get(f"/collections/{COLLECTION}/items/{zone}")
    assert res.status_code == 200 and res.headers["content-type"] == "application/geo+json"
    feature = res.json()
    assert feature["type"] == "Feature" and feature["id"] == zone and feature["properties"]["level"] == level
    assert feature["properties"]["count"] == int(inside.sum())
    assert feature["properties"]["pop_sum"] == int(points.pop[inside].sum())
    assert feature["properties"]["temp_max"] == pytest.approx(float(points.temp[inside].max()))
    poly = shapely.geometry.shape(feature["geometry"])
    centre_lat, centre_lng = dggs.cell_to_latlng(zone)  # (a pole is a segment of the planar ring: its centre)
    assert poly.is_valid and poly.intersects(shapely.points(float(centre_lng), float(centre_lat)))


@pytest.mark.parametrize("bbox", [(170.0, -40.0, -170.0, 40.0), (-180.0, -90.0, -170.0, -60.0)])
def test_items_bbox_across_the_antimeridian_and_at_a_pole(client, points, bbox):
    text = ",".join(str(v) for v in bbox)
    doc = client.get(f"/collections/{COLLECTION}/items", params={"bbox": text, "limit": 10_000}).json()
    want = brute_force_bbox(points, LEVEL, bbox)
    assert {f["id"] for f in doc["features"]} == want and doc["numberMatched"] == len(want)
