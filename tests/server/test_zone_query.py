"""The Zone Query class's SHALLs (OGC API - DGGS Part 1, §12), against brute force over the raw points.

Expected values never come from the server: the zones are the raw points binned here with
``dggs.latlng_to_cell``, their ancestors by ``dggs.cell_to_parent``, and the polygons tested with shapely.
"""

from __future__ import annotations

import numpy as np
import pytest
import shapely
from shapely.geometry import box

import dggs
from dggs.server.reader import map_densify

from .conftest import DGGRS, LEVEL

ROOT = f"/dggs/{DGGRS}"
COLL = f"/collections/sample/dggs/{DGGRS}"
CRS84 = "http://www.opengis.net/def/crs/OGC/1.3/CRS84"


def stored(points, level):
    """The level-``level`` zones holding at least one raw point (brute force)."""
    cells = np.asarray(dggs.latlng_to_cell(points.lat, points.lng, LEVEL))
    return set(np.asarray(dggs.cell_to_parent(cells, level)).astype(str).tolist())


def meeting(points, level, w, s, e, n):
    """Stored zones whose polygon (as the server draws it) meets the box (``w > e`` crosses 180°)."""
    boxes = [box(w, s, e, n)] if w < e else [box(w, s, 180, n), box(-180, s, e, n)]
    out = set()
    for cell in stored(points, level):
        poly = shapely.transform(dggs.cell_to_polygon(cell, densify=map_densify(level)), lambda xy: np.round(xy, 6))
        if any(poly.intersects(b) for b in boxes):
            out.add(cell)
    return out


def zones(client, **params):
    res = client.get(f"{ROOT}/zones", params={k.replace("_", "-"): v for k, v in params.items()})
    assert res.status_code == 200, res.text
    return res.json()


def bad(client, fragment, **params):
    """A 400 with an OGC exception body whose detail names ``fragment`` (the bad value)."""
    res = client.get(f"{ROOT}/zones", params={k.replace("_", "-"): v for k, v in params.items()})
    assert res.status_code == 400, res.text
    assert res.headers["content-type"].startswith("application/problem+json")
    body = res.json()
    assert body["status"] == 400 and body["type"] and fragment in body["detail"], body
    return body


# -- /req/zone-query/parent-zone ----------------------------------------------


PARENTS = ["J1", dggs.latlng_to_cell(45.0, 7.0, 2), dggs.latlng_to_cell(45.0, 7.0, 4), dggs.latlng_to_cell(-30, -179.9999, 0)]


@pytest.mark.parametrize("parent", PARENTS)
def test_parent_zone_returns_only_zones_inside_it(client, points, parent):
    plevel = dggs.get_level(parent)
    want = {z for z in stored(points, 5) if dggs.cell_to_parent(z, plevel) == parent}
    doc = zones(client, zone_level=5, parent_zone=parent, compact_zones="false")
    assert set(doc["zones"]) == want and len(doc["zones"]) == len(want)
    assert all(dggs.cell_to_parent(z, plevel) == parent for z in doc["zones"])
    compact = zones(client, zone_level=5, parent_zone=parent)["zones"]  # compacted: the same region
    assert set(dggs.uncompact_cells(compact, 5) if compact else []) == want
    assert all(dggs.get_level(z) >= plevel and z.startswith(parent) for z in compact)


def test_parent_zone_of_the_issue_is_not_ignored(client, points):
    everywhere = zones(client, zone_level=5, compact_zones="false")["zones"]
    inside = zones(client, zone_level=5, parent_zone="J1", compact_zones="false")["zones"]
    assert len(inside) < len(everywhere) and all(z.startswith("J1") for z in inside)


def test_parent_zone_with_bbox_is_both_filters(client, points):
    parent = dggs.latlng_to_cell(45.0, 7.0, 2)
    want = {z for z in meeting(points, 5, 0, 40, 10, 48) if z.startswith(parent)}
    doc = zones(client, zone_level=5, parent_zone=parent, bbox="0,40,10,48", compact_zones="false")
    assert set(doc["zones"]) == want and want


@pytest.mark.parametrize(("parent", "fragment"), [("X9", "'X9'"), ("C4012", "'C4012'"), ("", "''")])
def test_a_bad_parent_zone_is_a_400_naming_it(client, parent, fragment):
    bad(client, fragment, zone_level=3, parent_zone=parent)


# -- /req/zone-query/subset, /req/zone-query/subset-crs -------------------------


SUBSETS = [
    (["Lat(35:60),Lon(-10:30)"], (-10, 35, 30, 60)),
    (["Lat(35:60)", "Lon(-10:30)"], (-10, 35, 30, 60)),  # two subset parameters
    (["Lon(170:-170)"], (170, -90, -170, 90)),  # across the antimeridian
    (["Lat(80:*)"], (-180, 80, 180, 90)),
    (["lat(40:50),lon(*:5)"], (-180, 40, 5, 50)),
]


@pytest.mark.parametrize(("subset", "bbox"), SUBSETS)
def test_subset_restricts_the_zones_to_the_box(client, points, subset, bbox):
    want = meeting(points, 4, *bbox)
    res = client.get(f"{ROOT}/zones", params=[("zone-level", 4), ("compact-zones", "false")]
                     + [("subset", s) for s in subset])
    assert res.status_code == 200, res.text
    assert set(res.json()["zones"]) == want and want


def test_subset_is_not_ignored_and_equals_the_bbox(client, points):
    everywhere = zones(client, zone_level=5, compact_zones="false")["zones"]
    sub = zones(client, zone_level=5, subset="Lat(35:60),Lon(-10:30)", compact_zones="false")["zones"]
    by_box = zones(client, zone_level=5, bbox="-10,35,30,60", compact_zones="false")["zones"]
    assert sub == by_box and 0 < len(sub) < len(everywhere)


def test_a_subset_slice_gives_the_zones_on_that_line(client, points):
    zone = dggs.latlng_to_cell(45.123, 7.456, 5)
    doc = zones(client, zone_level=5, subset="Lat(45.123),Lon(7.456)", compact_zones="false")
    assert zone in doc["zones"] and len(doc["zones"]) <= 3  # the zone of the point (or a shared edge/corner)


@pytest.mark.parametrize("crs", [CRS84, CRS84.replace("http:", "https:"), "[OGC:CRS84]"])
def test_subset_crs_and_bbox_crs_take_crs84(client, crs):
    a = zones(client, zone_level=4, subset="Lat(35:60),Lon(-10:30)", subset_crs=crs)
    b = zones(client, zone_level=4, bbox="-10,35,30,60", bbox_crs=crs)
    assert a["zones"] == b["zones"] == zones(client, zone_level=4, bbox="-10,35,30,60")["zones"]


@pytest.mark.parametrize(
    ("params", "fragment"),
    [
        ({"subset": "Foo(1:2)"}, "'Foo'"),
        ({"subset": "Lat(35:60),Foo(1:2)"}, "'Foo'"),
        ({"subset": "Lat(35:60)", "bbox": "-10,35,30,60"}, "together"),
        ({"subset": "Lat(35:60)", "subset-crs": "http://www.opengis.net/def/crs/EPSG/0/3857"}, "EPSG/0/3857"),
        ({"bbox": "-10,35,30,60", "bbox-crs": "EPSG:4326"}, "'EPSG:4326'"),
        ({"subset": "Lat(60:35)"}, "Lat(60:35)"),
        ({"subset": "Lat(35:95)"}, "95"),
        ({"subset": "Lat(a:b)"}, "'a'"),
        ({"subset": "Lat(1:2),Lat(3:4)"}, "more than once"),
        ({"subset": "Lat 35 60"}, "'Lat 35 60'"),
        ({"geometry": "hexagon"}, "'hexagon'"),
        ({"offset": "-1"}, "-1"),
        ({"limit": "0"}, "limit 0"),
    ],
)
def test_bad_zone_query_parameters_are_400_naming_the_value(client, params, fragment):
    bad(client, fragment, zone_level=3, **params)


# -- paging: limit with next/prev links and offset --------------------------------


def test_limit_pages_through_every_zone_with_next_links(client, points):
    want = zones(client, zone_level=5, compact_zones="false")["zones"]
    got, url, pages = [], f"{ROOT}/zones?zone-level=5&compact-zones=false&limit=150", 0
    while url:
        doc = client.get(url).json()
        assert doc["numberMatched"] == len(want) and doc["numberReturned"] == len(doc["zones"]) <= 150
        rels = {link["rel"]: link["href"] for link in doc["links"]}
        assert ("prev" in rels) == (pages > 0)
        got += doc["zones"]
        url = rels.get("next")
        pages += 1
    assert got == want and pages == -(-len(want) // 150)


def test_prev_link_goes_back_one_page(client):
    doc = zones(client, zone_level=4, compact_zones="false", limit=10, offset=25)
    prev = next(link["href"] for link in doc["links"] if link["rel"] == "prev")
    back = client.get(prev).json()
    full = zones(client, zone_level=4, compact_zones="false")["zones"]
    assert doc["zones"] == full[25:35] and back["zones"] == full[15:25]


# -- geometry=zone-centroid ---------------------------------------------------------


def test_zone_centroid_gives_points_at_the_zone_centres(client):
    res = client.get(f"{ROOT}/zones", params={"zone-level": 3, "geometry": "zone-centroid", "f": "geojson"})
    features = res.json()["features"]
    assert features and all(f["geometry"]["type"] == "Point" for f in features)
    for f in features:
        lat, lng = dggs.cell_to_latlng(f["id"])
        assert f["geometry"]["coordinates"] == pytest.approx([lng, lat], abs=1e-6)
        assert dggs.latlng_to_cell(lat, lng, dggs.get_level(f["id"])) == f["id"]


def test_geometry_none_and_zone_region(client):
    none = client.get(f"{ROOT}/zones?zone-level=2&geometry=none&f=geojson").json()["features"]
    assert none and all(f["geometry"] is None for f in none)
    region = client.get(f"{COLL}/zones?zone-level=2&geometry=zone-region&f=geojson").json()["features"]
    assert all(f["geometry"]["type"] in ("Polygon", "MultiPolygon") for f in region)


def test_zone_data_geometry_zone_centroid(client):
    zone = dggs.latlng_to_cell(45.0, 7.0, 3)
    feats = client.get(f"{ROOT}/zones/{zone}/data?zone-depth=1&f=geojson&geometry=zone-centroid").json()["features"]
    assert [f["id"] for f in feats] == list(dggs.cell_to_children(zone))
    assert all(f["geometry"]["type"] == "Point" for f in feats)
    res = client.get(f"{ROOT}/zones/{zone}/data?zone-depth=1&f=geojson&geometry=pixel")
    assert res.status_code == 400 and "'pixel'" in res.json()["detail"]
