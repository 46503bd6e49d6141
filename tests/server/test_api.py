"""The OGC API - DGGS server: every response against the standard's schemas, every number against the store."""

from __future__ import annotations

import doctest
import importlib
import json
import re
import subprocess
import sys
import time
import urllib.request
from collections import defaultdict
from pathlib import Path

import jsonschema
import numpy as np
import pytest
import shapely
from hypothesis import given
from hypothesis import strategies as st
from shapely.geometry import Point, box, shape

import dggs
from dggs.geometry.icosahedron import ISEA
from dggs.server.reader import map_densify
from dggs.storage import CellStore

from .conftest import DGGRS, LEVEL, make_client
from .map_contract import validate_map
from .serving import free_port
from .standard import conforms, requires_standard, validate

ROOT = f"/dggs/{DGGRS}"
COLL = f"/collections/sample/dggs/{DGGRS}"


def stored_cells(points, level):
    """Brute force: the cell of every raw point at ``level``."""
    return np.asarray(dggs.latlng_to_cell(points.lat, points.lng, level))


# -- every endpoint against the standard's schemas (tests/server/standard.py) -------------

ENDPOINTS = [
    ("/?f=json", "landing"),
    ("/", "landing"),
    ("/conformance", "conformance"),
    ("/collections", "collections"),
    ("/collections/sample", "collection"),
    ("/dggs", "dggrs-list"),
    ("/collections/sample/dggs", "dggrs-list"),
    (ROOT, "dggrs"),
    (COLL, "dggrs"),
    (f"{ROOT}/definition", "dggrs-definition"),
    (f"{COLL}/definition", "dggrs-definition"),
    (f"{ROOT}/zones/C401", "zone-info"),
    (f"{COLL}/zones/A", "zone-info"),
    (f"{ROOT}/zones/T5222", "zone-info"),
    (f"{ROOT}/zones/C4/data?zone-depth=2", "dggs-json"),
    (f"{COLL}/zones/C4/data?zone-depth=0-2", "dggs-json"),
    (f"{ROOT}/zones/C4/data", "dggs-json"),
    (f"{ROOT}/zones/C4/data?zone-depth=1&f=geojson", "geojson"),
    (f"{ROOT}/zones/C401/info-is-not-a-route", "exception"),
    (f"{ROOT}/zones?zone-level=3", "zone-list"),
    (f"{COLL}/zones?zone-level=4&compact-zones=false&bbox=-10,30,20,60", "zone-list"),
    (f"{ROOT}/zones?zone-level=3&f=geojson", "geojson"),
    (f"{ROOT}/zones/C401?f=geojson", "feature"),
    ("/dggs/nope", "exception"),
    (f"{ROOT}/zones/X9", "exception"),
]


@requires_standard
@pytest.mark.parametrize(("url", "schema"), ENDPOINTS)
def test_every_endpoint_matches_its_schema(client, url, schema):
    res = client.get(url)
    assert res.status_code == (200 if schema != "exception" else res.status_code)
    validate(res.json(), schema)


@pytest.mark.parametrize("url", ["/map/layers", "/map/cells?level=3",
                                 "/map/cells?level=4&bbox=170,-40,-170,40&column=temp&stat=mean"])
def test_the_map_json_meets_its_contract(client, url):
    validate_map(client.get(url).json(), "map-layers" if url == "/map/layers" else "map-cells")


# Documents the standard's schemas reject: each shows that the referee can fail.  One case of the old
# hand-written schemas cannot be expressed with the standard's files: an exception without ``status`` or
# ``detail`` is valid there (its exception schema requires only ``type``); test_errors checks this server's own
# promise of all four members instead.
@requires_standard
@pytest.mark.parametrize(
    ("document", "schema"),
    [
        ({"title": "no links"}, "landing"),
        ({"conformsTo": "core"}, "conformance"),
        ({"collections": []}, "collections"),
        ({"id": "x", "title": "x", "links": []}, "dggrs"),  # no description, no defaultDepth
        ({"dggrs": [{"id": "x"}]}, "dggrs-list"),  # an item without title and links
        ({"dggh": {}, "zirs": {}}, "dggrs-definition"),  # no subZoneOrder
        ({"dggrs": "x", "zoneId": "A", "values": {}}, "dggs-json"),  # no depths
        ({"zones": [1, 2]}, "zone-list"),
        ({"dggrs": "http://a/b", "zoneId": "A", "depths": [0], "values": {"v": [{"data": ["a"]}]}}, "dggs-json"),
        ({"dggrs": "http://a/b", "zoneId": "A", "depths": [-1], "values": {}}, "dggs-json"),
        ({"id": "A", "links": [{"href": "x"}]}, "zone-info"),  # a link without rel
        ({"type": "FeatureCollection", "features": [{"type": "Feature", "geometry": {"type": "Point"}}]}, "geojson"),
        ({"title": "x", "status": 400}, "exception"),
    ],
)
def test_a_wrong_document_fails_the_schema(document, schema):
    with pytest.raises(jsonschema.ValidationError):
        validate(document, schema)


def test_a_wrong_map_document_fails_its_contract():
    for document, name in (({"collection": "x"}, "map-layers"),
                           ({"type": "FeatureCollection", "features": [{"type": "Feature", "geometry": None,
                                                                        "properties": {"zone_id": "A"}}]}, "map-cells")):
        with pytest.raises(jsonschema.ValidationError):
            validate_map(document, name)


def test_collection_routes_answer_as_the_root_ones(client):
    for tail in ("/zones?zone-level=2", "/zones/C4/data?zone-depth=1", "/zones/C401"):
        a, b = client.get(ROOT + tail).json(), client.get(COLL + tail).json()
        for doc in (a, b):
            doc.pop("links", None)
            doc.pop("linkTemplates", None)
            doc.pop("dggrs", None)
        assert a == b


# -- landing page, conformance, OpenAPI, web map page ---------------------------


def test_landing_links_and_conformance(client):
    links = {link["rel"]: link["href"] for link in client.get("/").json()["links"]}
    for rel in ("self", "service-desc", "conformance", "data", "http://www.opengis.net/def/rel/ogc/1.0/dggrs-list"):
        assert rel in links
    for href in links.values():
        assert client.get(href.replace("http://testserver", "")).status_code == 200
    classes = client.get("/conformance").json()["conformsTo"]
    for name in ("core", "data-retrieval", "zone-query", "data-json", "data-geojson", "zone-geojson"):
        assert f"https://www.opengis.net/spec/ogcapi-dggs-1/1.0/conf/{name}" in classes
    assert "http://www.opengis.net/spec/ogcapi-common-1/1.0/conf/core" in classes


def test_openapi_lists_the_routes(client):
    # /req/oas30/oas-definition-1: OpenAPI 3.0, as the declared oas30 class and the service-desc link say
    from openapi_spec_validator import OpenAPIV30SpecValidator

    res = client.get("/api")
    api = res.json()
    assert api["openapi"] == "3.0.3" and res.headers["content-type"] == "application/vnd.oai.openapi+json;version=3.0"
    OpenAPIV30SpecValidator(api).validate()  # raises on any 3.1-only construct (a {"type": "null"})
    service = [link for link in client.get("/").json()["links"] if link["rel"] == "service-desc"]
    assert [link["type"] for link in service] == [res.headers["content-type"]]
    assert "422" not in json.dumps(api["paths"])  # the server answers a bad parameter with a 400
    for path in ("/conformance", "/dggs/{dggrsId}/zones/{zoneId}/data", "/map/cells",
                 "/collections/{collectionId}/dggs/{dggrsId}/zones"):
        assert path in api["paths"], path
    assert client.get("/api.html").status_code == 200


def test_browser_gets_the_web_map_page_when_installed(store_path, tmp_path):
    static = tmp_path / "static"
    static.mkdir()
    with make_client(store_path, static=static) as c:  # no index.html: the landing page as HTML, never a 406
        landing = c.get("/?f=json").json()
        for req in ({"headers": {"accept": "text/html,application/xhtml+xml,*/*;q=0.8"}},  # a browser's
                    {"headers": {"accept": "text/html"}}, {"params": {"f": "html"}}):
            res = c.get("/", **req)
            assert res.status_code == 200 and res.headers["content-type"].startswith("text/html"), req
            hrefs = set(re.findall(r'<a href="([^"]+)"', res.text))
            assert hrefs == {link["href"] for link in landing["links"]}  # every link of the landing page
            assert "index.html" in res.text  # and why there is no map
        for href in hrefs:  # each one usable
            assert c.get(href.replace("http://testserver", "")).status_code == 200, href
        assert c.get("/", headers={"accept": "application/json"}).json() == landing
    (static / "index.html").write_text("<!doctype html><title>map</title>")
    (static / "app.js").write_text("// js")
    (static / "vendor" / "maplibre-gl").mkdir(parents=True)
    for name in ("maplibre-gl.mjs", "maplibre-gl.css"):
        (static / "vendor" / "maplibre-gl" / name).write_text("/* vendor */")
    with make_client(store_path, static=static) as c:
        page = c.get("/", headers={"accept": "text/html,application/xhtml+xml,*/*;q=0.8"})
        assert page.headers["content-type"].startswith("text/html") and "<title>map</title>" in page.text
        assert c.get("/", headers={"accept": "application/json"}).json()["links"]
        assert c.get("/?f=json", headers={"accept": "text/html"}).json()["links"]
        assert c.get("/static/app.js").text == "// js"


_OTHER_TYPES = ["application/json", "application/xhtml+xml", "application/xml", "image/webp", "image/png",
                "*/*", "text/*", "application/*", "text/plain"]


@given(others=st.lists(st.tuples(st.sampled_from(_OTHER_TYPES), st.sampled_from(["", ";q=0.9", ";q=0.5", ";q=0"])),
                       max_size=4),
       html_q=st.sampled_from(["", ";q=1", ";q=0.8", ";q=0.1"]), at=st.integers(0, 4))
def test_a_browser_at_the_root_never_gets_a_406(tmp_path_factory, store_path, others, html_q, at):
    # an Accept naming text/html with q > 0 (anywhere, with anything else) gets an answer at /, map or not
    static = tmp_path_factory.mktemp("nomap")
    parts = [m + q for m, q in others]
    parts.insert(min(at, len(parts)), "text/html" + html_q)
    with make_client(store_path, static=static) as c:
        res = c.get("/", headers={"accept": ", ".join(parts)})
    assert res.status_code == 200, parts
    assert res.headers["content-type"].split(";")[0] in ("text/html", "application/json")


def test_collection_extent_is_the_points_bbox(client, points):
    bbox = client.get("/collections/sample").json()["extent"]["spatial"]["bbox"][0]
    assert bbox == pytest.approx([points.lng.min(), points.lat.min(), points.lng.max(), points.lat.max()])


# -- the DGGRS ----------------------------------------------------------------


def test_dggrs_description_states_the_grid(client):
    doc = client.get(ROOT).json()
    assert doc["id"] == DGGRS and doc["maxRefinementLevel"] == LEVEL
    rels = {link["rel"] for link in doc["links"]}
    assert {"self", "http://www.opengis.net/def/rel/ogc/1.0/dggrs-definition"} <= rels
    templates = {t["rel"] for t in doc["linkTemplates"]}
    assert "http://www.opengis.net/def/rel/ogc/1.0/dggrs-zone-info" in templates
    orientation = doc["definition"]["dggh"]["parameters"]["orientation"]
    assert orientation["authalicLatitude"] == pytest.approx(ISEA.lat, abs=1e-12)
    assert orientation["longitude"] == 11.25 and orientation["azimuth"] == 0
    assert orientation["latitude"] == pytest.approx(58.397145907431, abs=1e-9)  # ISEA3H example's geodetic value
    levels = doc["levels"]
    assert [row["level"] for row in levels] == list(range(dggs.MAX_LEVEL + 1))
    earth = float(dggs.cell_area(0)) * 20
    for row in levels:
        count = 20 if row["level"] == 0 else 20 * 6 * 3 ** (row["level"] - 1)
        assert row["zones"] == count
        assert row["areaMetersSquare"] == pytest.approx(earth / count, rel=1e-12)
        assert row["areaMetersSquare"] == float(dggs.cell_area(row["level"]))


# -- zone information -----------------------------------------------------------


@pytest.mark.parametrize("zone", ["A", "C401", "T5222", "K1", dggs.latlng_to_cell(0.0, 180.0, 4)])
def test_zone_info_is_the_grid_api(client, reference, points, zone):
    info = client.get(f"{ROOT}/zones/{zone}").json()
    level = dggs.get_level(zone)
    assert info["id"] == zone and info["level"] == level
    assert info["areaMetersSquare"] == float(dggs.cell_area(zone))
    assert info["parent"] == (dggs.cell_to_parent(zone) if level else None)
    assert info["children"] == list(dggs.cell_to_children(zone))
    assert info["neighbors"] == list(dggs.edge_neighbors(zone))
    lat, lng = dggs.cell_to_latlng(zone)
    assert info["centroid"] == pytest.approx([lng, lat])
    assert shape(info["geometry"]).buffer(1e-9).contains(Point(lng, lat))
    rels = [link["rel"].rsplit("/", 1)[-1] for link in info["links"]]
    assert rels.count("dggrs-zone-child") == len(info["children"]) and "dggrs" in rels and "dggrs-zone-data" in rels
    rows = reference.aggregate(level, "pop", ("count", "min", "max", "mean"), cell=zone)
    assert info["dataCount"] == (rows[0]["count"] if rows else 0)
    if rows:
        # stdDev from the raw points, binned here (the population standard deviation of the rows under it)
        cells = np.asarray(dggs.latlng_to_cell(points.lat, points.lng, LEVEL)).astype(str)
        under = points.pop[np.char.startswith(cells, zone)]
        assert info["statistics"]["pop"] == {"minimum": rows[0]["min"], "maximum": rows[0]["max"],
                                             "average": pytest.approx(rows[0]["mean"]),
                                             "stdDev": pytest.approx(float(np.std(under)), rel=1e-9)}


# -- zone data ----------------------------------------------------------------------


@pytest.mark.parametrize(("zone", "depth"), [("C4", "2"), ("A", "1"), ("K", "0-2"), ("F2", "0,3")])
def test_zone_data_equals_the_store_aggregates(client, reference, zone, depth):
    doc = client.get(f"{ROOT}/zones/{zone}/data", params={"zone-depth": depth}).json()
    level = dggs.get_level(zone)
    depths = doc["depths"]
    assert depths == ([int(d) for d in depth.split(",")] if "," in depth
                      else list(range(int(depth[0]), int(depth[-1]) + 1)))
    stats = ("sum", "mean", "min", "max")
    assert set(doc["values"]) == {"count"} | {f"{c}_{s}" for c in ("pop", "temp") for s in stats}
    for i, d in enumerate(depths):
        subs = [zone] if d == 0 else list(dggs.cell_to_children(zone, level + d))
        for entries in doc["values"].values():
            entry = entries[i]
            assert entry["depth"] == d and entry["shape"] == {"count": len(subs), "subZones": len(subs)}
            assert len(entry["data"]) == len(subs)
        for column in ("pop", "temp"):
            rows = {r["cell"]: r for r in reference.aggregate(level + d, column, cell=zone)}
            for s in ("sum", "mean", "min", "max"):
                got = doc["values"][f"{column}_{s}"][i]["data"]
                want = [rows[c][s] if c in rows else None for c in subs]
                assert got == pytest.approx(want)
        counts = doc["values"]["count"][i]["data"]
        assert counts == [rows[c]["count"] if c in rows else 0 for c in subs]


def test_zone_data_equals_a_brute_force_sum_over_the_raw_points(client, points):
    zone, depth = "C4", 3
    level = dggs.get_level(zone) + depth
    sums: dict[str, int] = defaultdict(int)
    counts: dict[str, int] = defaultdict(int)
    parents = dggs.cell_to_parent(stored_cells(points, LEVEL), level).tolist()
    for cell, pop in zip(parents, points.pop.tolist(), strict=True):
        sums[cell] += pop
        counts[cell] += 1
    doc = client.get(f"{ROOT}/zones/{zone}/data?zone-depth={depth}").json()
    subs = list(dggs.cell_to_children(zone, level))
    assert doc["values"]["pop_sum"][0]["data"] == [sums[c] if c in sums else None for c in subs]
    assert doc["values"]["count"][0]["data"] == [counts.get(c, 0) for c in subs]
    assert sum(doc["values"]["count"][0]["data"]) == sum(v for c, v in counts.items() if c.startswith(zone)) > 0


def test_zone_data_default_depth_is_clamped_to_the_stored_level(client):
    assert client.get(f"{ROOT}/zones/C4/data").json()["depths"] == [3]
    assert client.get(f"{ROOT}/zones/C4012/data").json()["depths"] == [LEVEL - 4]


def test_zone_data_as_geojson(client, reference):
    for how in ({"params": {"f": "geojson", "zone-depth": "2"}},
                {"params": {"zone-depth": "2"}, "headers": {"accept": "application/geo+json"}}):
        res = client.get(f"{ROOT}/zones/C4/data", **how)
        assert res.headers["content-type"].startswith("application/geo+json")
        doc = res.json()
        subs = list(dggs.cell_to_children("C4", 3))
        assert [f["id"] for f in doc["features"]] == subs
        rows = {r["cell"]: r for r in reference.aggregate(3, "pop", cell="C4")}
        for feature in doc["features"]:
            z = feature["id"]
            assert feature["properties"]["zoneID"] == z
            assert feature["properties"]["pop_sum"] == (rows[z]["sum"] if z in rows else None)
            lat, lng = dggs.cell_to_latlng(z)
            assert shape(feature["geometry"]).contains(Point(lng, lat))
    assert client.get(f"{ROOT}/zones/C4/data", headers={"accept": "application/json"}).headers[
        "content-type"].startswith("application/json")


# -- zone query ---------------------------------------------------------------------


@pytest.mark.parametrize("level", [0, 2, 4, LEVEL])
def test_zones_are_the_parents_of_stored_cells(client, points, level):
    want = sorted(set(dggs.cell_to_parent(stored_cells(points, LEVEL), level).tolist()))
    doc = client.get(f"{ROOT}/zones", params={"zone-level": level, "compact-zones": "false"}).json()
    assert doc["zones"] == want
    assert doc["numberMatched"] == doc["numberReturned"] == len(want)
    assert doc["returnedAreaMetersSquare"] == pytest.approx(len(want) * float(dggs.cell_area(level)))


def test_zones_default_level_is_the_stored_level_compacted(client, points):
    doc = client.get(f"{ROOT}/zones").json()
    cells = sorted(set(stored_cells(points, LEVEL).tolist()))
    assert set(doc["zones"]) == set(dggs.compact_cells(cells))


@pytest.mark.parametrize("level", [3, 5, LEVEL])
def test_compact_zones_equals_compact_cells(client, points, level):
    full = sorted(set(dggs.cell_to_parent(stored_cells(points, LEVEL), level).tolist()))
    compact = list(dggs.compact_cells(full))
    assert len(compact) < len(full)  # the dense cluster makes complete sets of children
    doc = client.get(f"{ROOT}/zones", params={"zone-level": level}).json()  # compact-zones defaults to true
    assert sorted(doc["zones"]) == sorted(compact)
    assert [len(z) for z in doc["zones"]] == sorted(len(z) for z in doc["zones"])  # coarser first
    assert doc["returnedAreaMetersSquare"] == pytest.approx(len(full) * float(dggs.cell_area(level)), rel=1e-9)


def brute_force_bbox(points, level, bbox):
    """Cells of ``level`` holding data whose polygon (as the server draws it) meets the bbox."""
    w, s, e, n = bbox
    boxes = [box(w, s, e, n)] if w < e else [box(w, s, 180, n), box(-180, s, e, n)]
    found = set()
    for cell in set(dggs.cell_to_parent(stored_cells(points, LEVEL), level).tolist()):
        poly = shapely.transform(dggs.cell_to_polygon(cell, densify=map_densify(level)), lambda xy: np.round(xy, 6))
        if any(poly.intersects(b) for b in boxes):
            found.add(cell)
    return found


BBOXES = [(-10.0, 30.0, 20.0, 60.0), (170.0, -40.0, -170.0, 40.0), (-180.0, 80.0, 180.0, 90.0),
          (-180.0, -90.0, -170.0, -60.0), (100.0, -5.0, 100.5, -4.5)]


@pytest.mark.parametrize("bbox", BBOXES)
@pytest.mark.parametrize("level", [2, 5])
def test_bbox_filter_equals_a_brute_force_intersection(client, points, bbox, level):
    want = brute_force_bbox(points, level, bbox)
    text = ",".join(str(v) for v in bbox)
    doc = client.get(f"{ROOT}/zones", params={"zone-level": level, "compact-zones": "false", "bbox": text}).json()
    assert set(doc["zones"]) == want
    cells = client.get("/map/cells", params={"level": level, "bbox": text}).json()
    assert {f["properties"]["zone_id"] for f in cells["features"]} == want


def test_zone_list_limit_and_geojson(client):
    full = client.get(f"{ROOT}/zones?zone-level=4&compact-zones=false").json()
    part = client.get(f"{ROOT}/zones?zone-level=4&compact-zones=false&limit=5").json()
    assert part["zones"] == full["zones"][:5] and part["numberMatched"] == full["numberMatched"]
    geo = client.get(f"{ROOT}/zones?zone-level=4&compact-zones=false", headers={"accept": "application/geo+json"})
    assert geo.headers["content-type"].startswith("application/geo+json")
    features = geo.json()["features"]
    assert [f["properties"]["zoneID"] for f in features] == full["zones"]
    for f in features:
        lat, lng = dggs.cell_to_latlng(f["id"])
        assert shape(f["geometry"]).contains(Point(lng, lat))


# -- the web map's JSON -------------------------------------------------------------


def test_map_layers_contract(client, points):
    doc = client.get("/map/layers").json()
    assert doc == {
        "collection": "sample",
        "stored_level": LEVEL,
        "levels": list(range(LEVEL + 1)),
        "columns": {"pop": "INTEGER", "temp": "REAL", "name": "TEXT"},
        "numeric_columns": ["pop", "temp"],
        "bbox": pytest.approx([points.lng.min(), points.lat.min(), points.lng.max(), points.lat.max()]),
        "count": points.lat.shape[0],
        "max_zones": 50_000,
        "dggrs": "DGGS-Split26-ISEA",
        "collections": ["sample"],  # the store's datasets: its default one alone
    }


@pytest.mark.parametrize(("column", "stat"), [(None, "count"), ("pop", "sum"), ("temp", "mean"), ("pop", "min"),
                                              ("temp", "max"), ("pop", "count")])
def test_map_cells_values_equal_the_store(client, reference, column, stat):
    level = 3
    params = {"level": level, "bbox": "-180,-90,180,90", "stat": stat}
    if column:
        params["column"] = column
    doc = client.get("/map/cells", params=params).json()
    rows = {r["cell"]: r for r in reference.aggregate(level, column, ("count", stat) if column else ("count",))}
    assert {f["properties"]["zone_id"] for f in doc["features"]} == set(rows)
    area = float(dggs.cell_area(level, "km^2"))
    for f in doc["features"]:
        p = f["properties"]
        row = rows[p["zone_id"]]
        assert p["level"] == level and p["area_km2"] == area and p["count"] == row["count"]
        assert p["value"] == pytest.approx(row[stat] if column else row["count"])
        lat, lng = dggs.cell_to_latlng(p["zone_id"])
        assert shape(f["geometry"]).contains(Point(lng, lat))


def test_map_cells_antimeridian_and_poles_make_valid_geometry(client):
    doc = client.get("/map/cells", params={"level": 2, "bbox": "170,-90,-170,90"}).json()
    kinds = {f["geometry"]["type"] for f in doc["features"]}
    assert "MultiPolygon" in kinds  # cells across 180 are split
    for f in doc["features"]:
        geom = shape(f["geometry"])
        assert geom.is_valid and -180 <= geom.bounds[0] and geom.bounds[2] <= 180


def test_map_cells_are_rolled_up_once_per_store_state(store_copy, monkeypatch):
    """Repeated map requests reuse the cached roll-up (speed itself is measured by benchmarks/bench_serve.py)."""
    calls = []
    real = CellStore.aggregate

    def counting(self, *args, **kwargs):
        calls.append(args[0])
        return real(self, *args, **kwargs)

    monkeypatch.setattr(CellStore, "aggregate", counting)
    with make_client(store_copy, refresh=0) as c:
        for _ in range(3):
            for level in range(LEVEL + 1):
                got = c.get("/map/cells", params={"level": level, "column": "pop", "stat": "sum"})
                assert got.status_code == 200
    assert sorted(calls) == list(range(LEVEL + 1))  # one roll-up per level, not one per request


def test_concurrent_ingest_invalidates_the_cache(store_copy):
    with make_client(store_copy, refresh=0) as c:
        before = c.get("/map/cells?level=0").json()
        total = sum(f["properties"]["count"] for f in before["features"])
        with CellStore(store_copy) as writer:  # another writer while the server runs
            writer.ingest_points([1.0, 1.0, -45.0], [2.0, 2.0, 100.0], LEVEL, {"pop": [1, 2, 3], "temp": [1.0] * 3,
                                                                               "name": ["a", "b", "c"]})
            after = c.get("/map/cells?level=0").json()
            assert sum(f["properties"]["count"] for f in after["features"]) == total + 3
            assert c.get("/map/layers").json()["count"] == total + 3
            writer.delete_source(2)
        again = c.get("/map/cells?level=0").json()
        assert sum(f["properties"]["count"] for f in again["features"]) == total


def test_a_busy_store_is_rolled_up_at_most_once_per_refresh(store_copy, monkeypatch):
    """With refresh > 0 a roll-up is served for that long after a change, and computed once for many callers."""
    import threading

    from dggs.server import reader as reader_module

    calls = []
    real = CellStore.aggregate

    def counting(self, *args, **kwargs):
        calls.append(args[0])
        time.sleep(0.2)  # long enough for the other threads to arrive while it runs
        return real(self, *args, **kwargs)

    monkeypatch.setattr(CellStore, "aggregate", counting)
    extra = {"pop": [1], "temp": [1.0], "name": ["x"]}
    with make_client(store_copy, refresh=3600) as c:
        total = c.get("/map/layers").json()["count"]
        assert c.get("/map/cells?level=1").status_code == 200 and calls == [1]
        with CellStore(store_copy) as writer:
            writer.ingest_points([1.0], [2.0], LEVEL, extra)
        counts = []
        threads = [threading.Thread(target=lambda: counts.append(
            sum(f["properties"]["count"] for f in c.get("/map/cells?level=1").json()["features"])))
            for _ in range(4)]
        for t in threads:
            t.start()
        for t in threads:
            t.join()
        assert calls == [1] and counts == [total] * 4  # the earlier snapshot, within the hour
    reader = reader_module.StoreReader(store_copy, refresh=0)
    try:
        results = []
        threads = [threading.Thread(target=lambda: results.append(int(reader.level_data(2).counts.sum())))
                   for _ in range(4)]
        for t in threads:
            t.start()
        for t in threads:
            t.join()
        assert results == [total + 1] * 4 and calls.count(2) == 1  # four callers, one computation
    finally:
        reader.close()


# -- a real process -----------------------------------------------------------------



def test_dggs_serve_runs_as_a_real_server(store_path, tmp_path):
    exe = Path(sys.executable).parent / "dggs"
    if not exe.exists():
        pytest.skip("the dggs script is not installed next to this Python")
    port = free_port()
    proc = subprocess.Popen([str(exe), "serve", str(store_path), "--port", str(port)],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        url = f"http://127.0.0.1:{port}"
        deadline = time.monotonic() + 60
        while True:
            try:
                with urllib.request.urlopen(url + "/conformance", timeout=5) as res:
                    conformance = json.load(res)
                break
            except OSError as exc:
                if proc.poll() is not None or time.monotonic() > deadline:
                    raise AssertionError(
                        f"dggs serve did not answer: {proc.stderr.read() if proc.stderr else ''}"
                    ) from exc
                time.sleep(0.2)
        assert "https://www.opengis.net/spec/ogcapi-dggs-1/1.0/conf/core" in conformance["conformsTo"]
        conforms(conformance, "conformance")
        with urllib.request.urlopen(f"{url}/dggs/{DGGRS}/zones/C4/data?zone-depth=1", timeout=10) as res:
            assert res.headers["content-type"].startswith("application/json")
            data = json.load(res)
            assert data["zoneId"] == "C4" and data["depths"] == [1]
            conforms(data, "dggs-json")
        with urllib.request.urlopen(url + "/map/layers", timeout=10) as res:
            validate_map(json.load(res), "map-layers")
    finally:
        proc.terminate()
        out, _ = proc.communicate(timeout=30)
    assert f"http://127.0.0.1:{port}/" in out


# -- docstring examples ---------------------------------------------------------------


@pytest.mark.parametrize("name", ["app", "dggrs", "encodings", "errors", "geojson", "mapdata", "models", "ogc", "params",
                                  "reader", "vendor", "zones"])
def test_doctests(name):
    module = importlib.import_module(f"dggs.server.{name}")
    result = doctest.testmod(module, optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    assert result.failed == 0 and result.attempted > 0


def test_readers_see_whole_batches_during_an_ingest(store_copy):
    import threading

    batch = 250
    rng = np.random.default_rng(3)
    lat, lng = rng.uniform(-60, 60, 2000), rng.uniform(-180, 180, 2000)
    with make_client(store_copy, refresh=0) as c:
        base = c.get("/map/layers").json()["count"]
        seen = []
        done = threading.Event()

        def ingest():
            try:
                with CellStore(store_copy, merge_rows=600) as writer:
                    writer.ingest_points(lat, lng, LEVEL, {"pop": np.ones(2000, dtype=np.int64)}, batch_size=batch,
                                         progress=lambda n: time.sleep(0.05))  # readers get a look in
            finally:
                done.set()

        thread = threading.Thread(target=ingest)
        thread.start()
        while not done.is_set():
            layers = c.get("/map/layers").json()["count"]
            world = sum(f["properties"]["count"] for f in c.get("/map/cells?level=0").json()["features"])
            seen += [layers, world]
        thread.join()
        seen.append(c.get("/map/layers").json()["count"])
    assert all((n - base) % batch == 0 for n in seen), sorted(set(seen))
    assert len(set(seen)) > 3  # the readers saw the ingest half-way
    assert seen[-1] == base + 2000


def test_an_empty_store_is_served(tmp_path):
    path = tmp_path / "empty.db"
    CellStore(path).close()
    with make_client(path) as c:
        layers = c.get("/map/layers").json()
        validate_map(layers, "map-layers")
        assert layers["stored_level"] is None and layers["levels"] == [] and layers["count"] == 0
        assert c.get(f"{ROOT}/zones").json()["zones"] == []
        assert c.get("/map/cells?level=0").json()["features"] == []
        data = c.get(f"{ROOT}/zones/C4/data?zone-depth=1").json()
        assert data["values"]["count"][0]["data"] == [0, 0, 0]
        collection = c.get("/collections/empty").json()
        assert collection["id"] == "empty"
        conforms(data, "dggs-json")
        conforms(collection, "collection")


def test_zone_info_at_the_finest_level(client):
    zone = dggs.latlng_to_cell(51.05, -114.07, dggs.MAX_LEVEL)
    info = client.get(f"{ROOT}/zones/{zone}").json()
    conforms(info, "zone-info")
    assert info["level"] == dggs.MAX_LEVEL and info["children"] == [] and "statistics" not in info
    assert info["uint64Id"] == str(dggs.str_to_int(zone))


def test_map_cells_as_ids_are_the_geojson_cells(store_path):
    """/map/cells?f=uint64: the same cells, counts and values as the GeoJSON, as ids (the page draws them with the
    WebAssembly core)."""
    with make_client(store_path) as c:
        for params in ({"level": 3}, {"level": 4, "bbox": "170,-40,-170,40", "column": "temp", "stat": "mean"}):
            doc = c.get("/map/cells", params=params).json()
            got = c.get("/map/cells", params={**params, "f": "uint64"})
            assert got.status_code == 200 and got.headers["content-type"] == "application/x-binary"
            body = got.content
            n = int(np.frombuffer(body[:8], "<u8")[0])
            assert len(body) == 8 + 24 * n and n == len(doc["features"]) > 0
            ids = dggs.int_to_str(np.frombuffer(body[8:8 + 8 * n], "<u8").tolist())
            counts = np.frombuffer(body[8 + 8 * n:8 + 16 * n], "<f8").tolist()
            values = np.frombuffer(body[8 + 16 * n:], "<f8").tolist()
            props = [f["properties"] for f in doc["features"]]
            assert ids == [p["zone_id"] for p in props]
            assert counts == [p["count"] for p in props]
            assert [None if np.isnan(v) else v for v in values] == [p["value"] for p in props]
