"""DGGS-Split26-IVEA beside DGGS-Split26-ISEA (issue 23): a real ``dggs serve`` process on 127.0.0.1.

The store holds one point at the IVEA centre of every level-5 zone, binned on IVEA
(``CellStore(projection="IVEA")``), so every zone of levels 0..5 holds data and a zone's sub-zone
counts follow from the hierarchy alone (3 per level, 6 below a face).  Geometry is checked against
``dggs.Grid("IVEA")`` and shapely; zone lists against ``Grid("IVEA").polygon_to_cells`` and the
hierarchy; the definitions against the standard's DGGRS definition schema (tests/server/standard.py).
"""

from __future__ import annotations

import json
import urllib.error
import urllib.request
from pathlib import Path
from typing import Any

import numpy as np
import pytest
import shapely
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from shapely.geometry import shape

import dggs
from dggs.server.reader import map_densify
from dggs.storage import CellStore
from tests.server.conftest import make_client
from tests.server.serving import serving
from tests.server.standard import conforms
from tests.strategies import cells, examples

IVEA_ID, ISEA_ID = "DGGS-Split26-IVEA", "DGGS-Split26-ISEA"
IVEA = dggs.Grid("IVEA")
LEVEL = 5
#: Zones at the north pole, the south pole, on the antimeridian, at an icosahedron vertex, anywhere.
ZONES = ["A4", "Q40", "C401", "F2201", "K3", "T5", "J012"]



@pytest.fixture(scope="module")
def ivea_store(tmp_path_factory) -> Path:
    path = tmp_path_factory.mktemp("ivea") / "ivea.db"
    cells = dggs.uncompact_cells(list("ABCDEFGHIJKLMNOPQRST"), LEVEL)
    lat, lng = IVEA.cell_to_latlng(np.asarray(cells))
    with CellStore(path, projection="IVEA") as store:
        store.ingest_points(lat, lng, LEVEL, {"v": np.ones(len(cells))})
    return path


@pytest.fixture(scope="module")
def url(ivea_store):
    with serving(ivea_store) as base:
        yield base


def get(url: str) -> Any:
    with urllib.request.urlopen(url, timeout=30) as res:
        return json.load(res)


def status(url: str) -> tuple[int, Any]:
    try:
        with urllib.request.urlopen(url, timeout=30) as res:
            return res.status, json.load(res)
    except urllib.error.HTTPError as exc:
        return exc.code, json.loads(exc.read())


def test_both_dggrs_listed(url):
    listed = get(f"{url}/dggs")
    assert [d["id"] for d in listed["dggrs"]] == [ISEA_ID, IVEA_ID]
    conforms(listed, "dggrs-list")
    # the collection lists the DGGRS its data were binned with
    collection = get(f"{url}/collections/ivea/dggs")
    assert [d["id"] for d in collection["dggrs"]] == [IVEA_ID]


@pytest.mark.parametrize("dggrs", [IVEA_ID, ISEA_ID])
def test_definitions_meet_the_standard(url, dggrs):
    definition = get(f"{url}/dggs/{dggrs}/definition")
    conforms(definition, "dggrs-definition")
    description = get(f"{url}/dggs/{dggrs}")
    conforms(description, "dggrs")
    assert description["id"] == dggrs and description["definition"] == definition
    rels = {link["rel"].rsplit("/", 1)[-1] for link in description["links"]}
    assert ("dggrs-zone-query" in rels) == (dggrs == IVEA_ID)  # zone data only where the data were binned
    projection = definition["dggh"]["definition"]["projection"]
    assert ("great circle" in projection) == (dggrs == IVEA_ID)
    assert ("Snyder" in projection) == (dggrs == ISEA_ID)


@pytest.mark.parametrize("zone", ZONES)
def test_zone_geometry_is_the_grid_s(url, zone):
    info = get(f"{url}/dggs/{IVEA_ID}/zones/{zone}")
    conforms(info, "zone-info")
    want = IVEA.cell_to_polygon(zone)
    got = shape(info["geometry"])
    assert got.symmetric_difference(want).area <= 1e-9 * max(want.area, 1e-12)
    lat, lng = IVEA.cell_to_latlng(zone)
    assert info["centroid"] == pytest.approx([lng, lat], abs=1e-12)
    # every level-5 zone holds one point: the count is the number of its level-5 descendants
    assert info["dataCount"] == len(dggs.uncompact_cells([zone], LEVEL))
    isea = get(f"{url}/dggs/{ISEA_ID}/zones/{zone}")  # zone information on the other grid: its own shape
    assert shape(isea["geometry"]).symmetric_difference(dggs.cell_to_polygon(zone)).area <= 1e-9 * want.area
    assert "dataCount" not in isea  # the data are not binned on ISEA


@pytest.mark.parametrize("level", [3, 4])
@pytest.mark.parametrize("box", [(-20.0, 30.0, 15.0, 55.0), (170.0, -40.0, -165.0, -10.0), (-180.0, 70.0, 180.0, 90.0),
                                 (10.0, -10.0, 40.0, 5.0)])
def test_zone_list_in_a_bbox(url, box, level):
    w, s, e, n = box
    found = get(f"{url}/dggs/{IVEA_ID}/zones?zone-level={level}&compact-zones=false&bbox={w},{s},{e},{n}")
    conforms(found, "zone-list")
    pieces = [shapely.box(w, s, e, n)] if w < e else [shapely.box(w, s, 180, n), shapely.box(-180, s, e, n)]
    want: set[str] = set()
    for piece in pieces:  # every zone holds data: the zones meeting the box are all of them
        want |= set(IVEA.polygon_to_cells(piece, level, mode="overlaps").tolist())
    assert len(want) > 20
    assert set(found["zones"]) == want
    assert len(found["zones"]) == len(want)  # each once


@pytest.mark.parametrize("parent", ["A", "C4", "Q40", "T51"])
def test_zone_list_in_a_parent(url, parent):
    found = get(f"{url}/dggs/{IVEA_ID}/zones?zone-level=4&compact-zones=false&parent-zone={parent}")
    assert sorted(found["zones"]) == sorted(dggs.uncompact_cells([parent], 4))


def test_zone_list_subset_is_the_bbox(url):
    by_subset = get(f"{url}/dggs/{IVEA_ID}/zones?zone-level=3&compact-zones=false&subset=Lat(30:55),Lon(-20:15)")
    by_bbox = get(f"{url}/dggs/{IVEA_ID}/zones?zone-level=3&compact-zones=false&bbox=-20,30,15,55")
    assert by_subset["zones"] == by_bbox["zones"]


@pytest.mark.parametrize("zone", ["C4", "A40", "Q402"])
def test_data_served_under_ivea(url, zone):
    data = get(f"{url}/dggs/{IVEA_ID}/zones/{zone}/data?zone-depth=1-2")
    conforms(data, "dggs-json")
    assert data["dggrs"].endswith(IVEA_ID)
    counts = {entry["depth"]: entry["data"] for entry in data["values"]["count"]}
    below = LEVEL - len(zone) + 1  # levels from the zone's children down to the stored level
    assert counts[1] == [3 ** (below - 1)] * 3
    assert counts[2] == [3 ** (below - 2)] * 9
    features = get(f"{url}/collections/ivea/dggs/{IVEA_ID}/zones/{zone}/data?zone-depth=1&f=geojson")
    for feature in features["features"]:  # the sub-zones drawn on IVEA, as lightly densified as the map's
        want = IVEA.cell_to_polygon(feature["id"], densify=map_densify(len(feature["id"]) - 1))
        assert shape(feature["geometry"]).symmetric_difference(want).area < 1e-5 * want.area


@pytest.mark.parametrize("path", [f"/dggs/{ISEA_ID}/zones/C4/data", f"/dggs/{ISEA_ID}/zones",
                                  f"/collections/ivea/dggs/{ISEA_ID}/zones/C4/data",
                                  f"/collections/ivea/dggs/{ISEA_ID}", f"/collections/ivea/dggs/{ISEA_ID}/zones/C4"])
def test_data_refused_under_isea(url, path):
    code, body = status(url + path)
    assert code == 404
    assert IVEA_ID in body["detail"] and "IVEA" in body["detail"]
    conforms(body, "exception")


def test_an_isea_store_refuses_ivea_data(store_path):
    client = make_client(store_path)
    assert client.get(f"/dggs/{ISEA_ID}/zones/C4/data").status_code == 200
    res = client.get(f"/dggs/{IVEA_ID}/zones/C4/data")
    assert res.status_code == 404 and ISEA_ID in res.json()["detail"]
    assert client.get(f"/dggs/{IVEA_ID}/zones", params={"zone-level": 2}).status_code == 404
    info = client.get(f"/dggs/{IVEA_ID}/zones/C4").json()
    assert shape(info["geometry"]).symmetric_difference(IVEA.cell_to_polygon("C4")).area < 1e-9
    assert [d["id"] for d in client.get("/dggs").json()["dggrs"]] == [ISEA_ID, IVEA_ID]
    assert [d["id"] for d in client.get(f"/collections/{store_path.stem}/dggs").json()["dggrs"]] == [ISEA_ID]


def test_the_map_draws_and_names_the_store_grid(url):
    layers = get(f"{url}/map/layers")
    assert layers["dggrs"] == IVEA_ID  # the popup's zone information comes from the store's DGGRS
    cells = get(f"{url}/map/cells?level=2&bbox=-30,20,30,60")
    assert cells["features"]
    for feature in cells["features"]:
        zone = feature["properties"]["zone_id"]
        want = IVEA.cell_to_polygon(zone, densify=map_densify(2))
        assert shape(feature["geometry"]).symmetric_difference(want).area < 1e-5 * want.area
        assert feature["properties"]["count"] == len(dggs.uncompact_cells([zone], LEVEL))


# -- properties, in-process (the same app the process serves) ---------------------------------------


@pytest.fixture(scope="module")
def app_client(ivea_store):
    client = make_client(ivea_store)
    with client:
        yield client


@settings(max_examples=examples(40), deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(cells(max_level=14))
def test_any_zone_drawn_on_its_grid(app_client, zone):
    for dggrs, grid in ((IVEA_ID, IVEA), (ISEA_ID, dggs.Grid("ISEA"))):
        info = app_client.get(f"/dggs/{dggrs}/zones/{zone}").json()
        want = grid.cell_to_polygon(zone)
        assert shape(info["geometry"]).symmetric_difference(want).area <= 1e-9 * want.area
        assert info["uint64Id"] == str(dggs.str_to_int(zone))  # the integer form names the same zone
        if dggrs == IVEA_ID and len(zone) - 1 <= LEVEL:
            assert info["dataCount"] == len(dggs.uncompact_cells([zone], LEVEL))
        else:
            assert "dataCount" not in info


@settings(max_examples=examples(20), deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(cells(min_level=0, max_level=3), st.integers(3, 5))
def test_integer_zone_lists_are_the_text_ones(app_client, parent, level):
    level = max(level, len(parent) - 1)
    query = f"/dggs/{IVEA_ID}/zones?zone-level={level}&compact-zones=false&parent-zone={parent}"
    text = app_client.get(query).json()["zones"]
    body = app_client.get(query + "&f=uint64").content
    count = int(np.frombuffer(body[:8], dtype="<u8")[0])
    ints = np.frombuffer(body[8:], dtype="<u8")
    assert count == len(text) == len(dggs.uncompact_cells([parent], level))
    assert [dggs.int_to_str(int(i)) for i in ints] == text


# -- corrupt requests on the IVEA routes (issue 32: the adversarial suite's routes it skipped) ----------------------

_BAD_ZONES = ["Z1", "A9", "c401", "A" + "0" * 40, "A06", "C4x", "%00", "C4.1", "C401:1", "-1", "1e400", "%F0%9F%8C%8D"]
_BAD_QUERIES = ["zone-level=-1", "zone-level=29", "zone-level=abc", "zone-level=1.5", "zone-depth=-3", "zone-depth=x",
                "bbox=1,2,3", "bbox=a,b,c,d", "bbox=0,0,1e400,1", "compact-zones=maybe", "limit=-1", "limit=1e99",
                "f=xml", "properties=nope", "zone-level=2&bbox=179,-10,-179,10"]


def _status_and_type(address: str) -> tuple[int, str]:
    try:
        with urllib.request.urlopen(address, timeout=30) as res:
            res.read()
            return res.status, res.headers.get("content-type", "")
    except urllib.error.HTTPError as exc:
        exc.read()
        return exc.code, exc.headers.get("content-type", "")


@pytest.mark.parametrize("root", [f"/dggs/{IVEA_ID}", f"/collections/ivea/dggs/{IVEA_ID}"])
def test_corrupt_requests_on_the_ivea_routes_are_4xx_problems(url, root):
    problems = []
    for zone in _BAD_ZONES:
        for tail in ("", "/data"):
            code, kind = _status_and_type(f"{url}{root}/zones/{zone}{tail}")
            if not (400 <= code < 500 and kind.startswith("application/problem+json")):
                problems.append((zone, tail, code, kind))
    for query in _BAD_QUERIES:
        for path in ("/zones", "/zones/C4/data"):
            code, kind = _status_and_type(f"{url}{root}{path}?{query}")
            if code >= 500 or (code >= 400 and not kind.startswith("application/problem+json")):
                problems.append((path, query, code, kind))
    assert not problems, problems
