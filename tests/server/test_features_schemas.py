"""OGC API - Features responses of a real ``dggs serve`` process, validated against the standards' own schemas.

Referee (issue 36, "the OGC Features OpenAPI fragments validate the responses"): OGC API - Features Part 1's
own fragments (``featureCollectionGeoJSON.yaml``, ``featureGeoJSON.yaml``, ``link.yaml``, ...) are not on this
machine and no package installs them, but OGC API - DGGS Part 1's bundled OpenAPI (``standard.py``) carries
the same components: ``FeatureCollection`` (its ``features`` items are the GeoJSON Feature), ``link``,
``numberMatched``, ``numberReturned``, ``timeStamp``, and Common Part 2's ``collections`` and
``collectionDesc``.  The page and feature schemas below are those components assembled the way the Features
fragments assemble them (a page is a FeatureCollection with ``links``, ``timeStamp``, ``numberMatched`` and
``numberReturned``; a feature is a Feature with ``links``), nothing added.  ``format`` is checked too
(``timeStamp`` is an RFC 3339 date-time).

Besides the schemas: every link object anywhere in a response is checked against ``link``, a zone's geometry
against the standard's GeoJSON Polygon and MultiPolygon schemas, and ``numberReturned`` against the features
returned (/req/core/fc-numberReturned).  ``test_the_referee_can_fail`` shows each check rejecting a broken copy
of a real response.
"""

from __future__ import annotations

import copy
from collections.abc import Iterator
from functools import cache
from typing import Any

import httpx
import pytest
from jsonschema import ValidationError

from dggs.storage import CellStore

from .serving import serving
from .standard import corrected, geometry_schemas, oas30_validate, requires_standard
from .test_features_clients import COLLECTION

pytestmark = requires_standard

ITEMS = f"/collections/{COLLECTION}/items"
_LINKS = {"type": "array", "items": {"$ref": "#/components/schemas/link"}}


@cache
def schemas() -> dict[str, dict[str, Any]]:
    """The Features documents' schemas, from the corrected bundled OpenAPI's components."""
    doc = corrected()
    components = doc["components"]["schemas"]
    feature = copy.deepcopy(components["FeatureCollection"]["properties"]["features"]["items"])
    feature["properties"]["links"] = _LINKS  # featureGeoJSON.yaml: a Feature with links
    page = copy.deepcopy(components["FeatureCollection"])
    page["properties"]["features"]["items"] = feature
    page["properties"].update(  # featureCollectionGeoJSON.yaml
        links=_LINKS,
        timeStamp={"$ref": "#/components/schemas/timeStamp"},
        numberMatched={"$ref": "#/components/schemas/numberMatched"},
        numberReturned={"$ref": "#/components/schemas/numberReturned"},
    )
    return {
        "page": page,
        "feature": feature,
        "zone-geometry": {"oneOf": geometry_schemas(doc)},
        "link": components["link"],
        "collections": components["collections"],
        "collection": components["collectionDesc"],
    }


def check(document: Any, name: str) -> None:
    """Validate ``document`` against :func:`schemas`'s ``name`` (formats included)."""
    oas30_validate(schemas()[name], document, formats=True)


def links_in(document: Any) -> Iterator[Any]:
    """Every member of every ``links`` array, at any depth of ``document``."""
    if isinstance(document, dict):
        for key, value in document.items():
            if key == "links" and isinstance(value, list):
                yield from value
            yield from links_in(value)
    elif isinstance(document, list):
        for value in document:
            yield from links_in(value)


def check_links(document: Any) -> int:
    """Validate every link object of ``document`` against ``link``; the number checked."""
    found = list(links_in(document))
    for link in found:
        check(link, "link")
    return len(found)


def check_page(page: dict[str, Any]) -> None:
    check(page, "page")
    assert page["numberReturned"] == len(page["features"])  # /req/core/fc-numberReturned
    for feature in page["features"]:
        check(feature["geometry"], "zone-geometry")
    assert check_links(page) >= 2  # self and collection at least


def check_feature(feature: dict[str, Any]) -> None:
    check(feature, "feature")
    check(feature["geometry"], "zone-geometry")
    assert check_links(feature) >= 2


@pytest.fixture(scope="module")
def url(store_path):
    with serving(store_path) as base:
        yield base


def get(url: str, path: str, **params: Any) -> dict[str, Any]:
    res = httpx.get(url + path, params=params, timeout=60)
    assert res.status_code == 200, res.text
    assert res.headers["content-type"].startswith("application/geo+json" if "/items" in path else "application/json")
    return res.json()  # type: ignore[no-any-return]


ITEMS_CASES = [
    {},
    {"limit": 1},
    {"limit": 7, "offset": 5},
    {"limit": 100_000},  # more than the server's maximum: taken as the maximum
    {"zone-level": 0},
    {"zone-level": 3, "limit": 20, "offset": 3},
    {"bbox": "0,40,15,50", "limit": 30},
    {"bbox": "0,40,15,50", "zone-level": 4, "properties": "count,pop_sum"},
    {"bbox": "-180,-90,180,90", "limit": 5},
    {"properties": "zoneID"},
    {"properties": "temp_mean,level", "zone-level": 2},
    {"datetime": "2020-01-01T00:00:00Z/..", "limit": 3},
    {"f": "json", "limit": 2},
]


@pytest.mark.parametrize("params", ITEMS_CASES, ids=lambda p: "&".join(f"{k}={v}" for k, v in p.items()) or "none")
def test_items_pages_validate(url, params):
    page = get(url, ITEMS, **params)
    check_page(page)
    assert page["features"], "the case should return features"


def test_an_empty_page_validates(url):
    whole = get(url, ITEMS, limit=1)
    page = get(url, ITEMS, offset=whole["numberMatched"], limit=10)
    assert page["features"] == [] and page["numberReturned"] == 0
    check_page(page)


@pytest.mark.parametrize("level", [6, 2, 0])
def test_pages_across_the_antimeridian_validate(url, level):
    page = get(url, ITEMS, bbox="170,-20,-170,20", **{"zone-level": level})
    check_page(page)
    kinds = {f["geometry"]["type"] for f in page["features"]}
    assert "MultiPolygon" in kinds, kinds  # a zone split at 180 is in the page


def test_every_page_reached_by_next_links_validates(url):
    page = get(url, ITEMS, bbox="-20,30,30,60", limit=50)
    pages = 1
    check_page(page)
    while nxt := [link["href"] for link in page["links"] if link["rel"] == "next"]:
        res = httpx.get(nxt[0], timeout=60)
        assert res.status_code == 200, res.text
        page = res.json()
        check_page(page)
        pages += 1
    assert pages >= 3  # the cluster (conftest) fills several pages


@pytest.mark.parametrize("params", [{}, {"properties": "count"}, {"f": "json"}])
def test_single_features_validate(url, params):
    seen: set[str] = set()
    for level in (0, 2, 6):
        page = get(url, ITEMS, bbox="170,-20,-170,20", limit=3, **{"zone-level": level})
        page["features"] += get(url, ITEMS, bbox="0,85,10,90", limit=2, **{"zone-level": level})["features"]
        for zone in page["features"]:
            feature = get(url, f"{ITEMS}/{zone['id']}", **params)
            check_feature(feature)
            seen.add(feature["geometry"]["type"])
    assert seen == {"Polygon", "MultiPolygon"}


def test_collections_validate(url):
    document = get(url, "/collections")
    check(document, "collections")
    assert COLLECTION in [c["id"] for c in document["collections"]]
    assert check_links(document) >= 3


def test_collection_validates(url):
    document = get(url, f"/collections/{COLLECTION}")
    check(document, "collection")
    assert "items" in [link["rel"] for link in document["links"]]
    assert check_links(document) >= 2


def test_an_empty_store_validates_and_says_so(tmp_path):
    with CellStore(tmp_path / "empty.db"):
        pass
    with serving(tmp_path / "empty.db") as base:
        collections = get(base, "/collections")
        check(collections, "collections")
        check_links(collections)
        collection = get(base, "/collections/empty")
        check(collection, "collection")
        for params in ({}, {"zone-level": 3}, {"bbox": "170,-20,-170,20"}):
            page = get(base, "/collections/empty/items", **params)
            assert page["features"] == [] and page["numberMatched"] == 0
            check_page(page)
        missing = httpx.get(base + "/collections/empty/items/C4", timeout=60)
    assert missing.status_code == 404
    # the description and the 404 said "level-None" and "the stored level None"
    assert "None" not in collection["description"] and "None" not in missing.json()["detail"]


def _broken(document: dict[str, Any], path: tuple[Any, ...], value: Any) -> dict[str, Any]:
    copied = copy.deepcopy(document)
    where = copied
    for key in path[:-1]:
        where = where[key]
    if value is KeyError:
        del where[path[-1]]
    else:
        where[path[-1]] = value
    return copied


def test_the_referee_can_fail(url):
    page = get(url, ITEMS, limit=2)
    feature = get(url, f"{ITEMS}/{page['features'][0]['id']}")
    collections = get(url, "/collections")
    collection = get(url, f"/collections/{COLLECTION}")
    for bad in (
        _broken(page, ("numberMatched",), -1),
        _broken(page, ("numberReturned",), "2"),
        _broken(page, ("timeStamp",), "yesterday"),
        _broken(page, ("links", 0, "href"), KeyError),
        _broken(page, ("features", 0, "type"), "Zone"),
        _broken(page, ("features", 1, "properties"), [1]),
        _broken(page, ("features", 0, "geometry", "coordinates"), [1.0, 2.0]),
        _broken(page, ("features",), KeyError),
    ):
        with pytest.raises((ValidationError, AssertionError)):
            check_page(bad)
    for bad in (_broken(feature, ("geometry",), KeyError), _broken(feature, ("links", 1, "rel"), 3),
                _broken(feature, ("id",), ["A0"])):
        with pytest.raises((ValidationError, AssertionError)):
            check_feature(bad)
    with pytest.raises(ValidationError):
        check(_broken(collections, ("collections", 0, "id"), None), "collections")
    with pytest.raises(ValidationError):
        check(_broken(collection, ("links",), KeyError), "collection")
    with pytest.raises(ValidationError):  # a link anywhere, here inside a collection of the list
        check_links(_broken(collections, ("collections", 0, "links", 0, "title"), 5))
