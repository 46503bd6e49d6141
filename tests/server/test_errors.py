"""Bad input gets 400, unknown things 404, too much 413: a JSON problem document naming the value."""

from __future__ import annotations

import socket
import subprocess
import sys
from pathlib import Path

import pytest
from click.testing import CliRunner

from dggs.cli import main

from .conftest import DGGRS, LEVEL
from .standard import conforms

ROOT = f"/dggs/{DGGRS}"
COLL = f"/collections/sample/dggs/{DGGRS}"


def check(res, status: int, *named: str) -> dict:
    assert res.status_code == status, res.text
    assert res.headers["content-type"].startswith("application/problem+json")
    body = res.json()
    conforms(body, "exception")  # the standard's exception schema, when ../shared is there
    # docs/serve.md's own promise beyond the standard's schema (which requires only type): all four members
    assert all(isinstance(body[k], str) for k in ("type", "title", "detail")) and body["status"] == status
    for text in named:
        assert text in body["detail"], (text, body["detail"])
    return body


@pytest.mark.parametrize("zone", ["Z1", "A9", "c401", "A" + "0" * 40, "A06", "C4x"])
@pytest.mark.parametrize("tail", ["", "/data"])
def test_bad_zone_ids(client, zone, tail):
    check(client.get(f"{ROOT}/zones/{zone}{tail}"), 400, repr(zone))
    check(client.get(f"{COLL}/zones/{zone}{tail}"), 400, repr(zone))


@pytest.mark.parametrize(("level", "named"), [("-1", "-1"), ("29", "29"), (str(LEVEL + 1), "stored level"),
                                              ("abc", "'abc'"), ("1.5", "'1.5'")])
def test_levels_out_of_range(client, level, named):
    check(client.get(f"{ROOT}/zones", params={"zone-level": level}), 400, "zone-level", named)
    check(client.get("/map/cells", params={"level": level}), 400, "level", named)


def test_map_cells_needs_a_level(client):
    check(client.get("/map/cells"), 400, "level")


@pytest.mark.parametrize("bbox", ["1,2,3", "a,b,c,d", "0,10,20,5", "-200,0,10,10", "0,-95,10,10", "5,0,5,10",
                                  "nan,0,1,1", "1,2,3,4,5", ""])
def test_bad_bbox(client, bbox):
    check(client.get("/map/cells", params={"level": 2, "bbox": bbox}), 400, "bbox", repr(bbox))
    check(client.get(f"{ROOT}/zones", params={"zone-level": 2, "bbox": bbox}), 400, "bbox", repr(bbox))


def test_bbox_crs_is_crs84_only(client):
    query = {"zone-level": 2, "bbox": "0,0,10,10"}
    want = client.get(f"{ROOT}/zones", params=query).json()["zones"]
    assert want == ["C3", "H2"]
    for crs in ("http://www.opengis.net/def/crs/OGC/1.3/CRS84", "[OGC:CRS84]"):
        assert client.get(f"{ROOT}/zones", params={**query, "bbox-crs": crs}).json()["zones"] == want
    check(client.get(f"{ROOT}/zones", params={**query, "bbox-crs": "EPSG:3857"}), 400, "bbox-crs", "'EPSG:3857'")


@pytest.mark.parametrize("depth", ["-1", "a", "3-1", "1,x", "", "1-", str(LEVEL)])
def test_bad_zone_depth(client, depth):
    check(client.get(f"{ROOT}/zones/C4/data", params={"zone-depth": depth}), 400, "zone-depth", repr(depth))


def test_zone_finer_than_the_stored_level_has_no_data(client):
    zone = "C4" + "0" * LEVEL
    check(client.get(f"{ROOT}/zones/{zone}/data"), 400, repr(zone), "stored level")


@pytest.mark.parametrize(("params", "named"), [
    ({"column": "nope"}, "'nope'"),
    ({"column": "name"}, "'name'"),  # text: no numbers to show
    ({"column": "pop", "stat": "median"}, "'median'"),
    ({"stat": "sum"}, "'sum'"),  # a stat of nothing
])
def test_unknown_column_or_stat(client, params, named):
    check(client.get("/map/cells", params={"level": 2, **params}), 400, named)


@pytest.mark.parametrize("value", ["maybe", "2"])
def test_bad_compact_zones_and_limit(client, value):
    check(client.get(f"{ROOT}/zones", params={"compact-zones": value}), 400, "compact-zones", repr(value))
    check(client.get(f"{ROOT}/zones", params={"limit": "0"}), 400, "limit", "0")
    check(client.get(f"{ROOT}/zones", params={"limit": "ten"}), 400, "limit", "'ten'")


def test_bad_format(client):
    check(client.get(f"{ROOT}/zones/C4/data", params={"f": "xml"}), 400, "'xml'")
    check(client.get(f"{ROOT}/zones", headers={"accept": "image/png"}), 406, "image/png")


@pytest.mark.parametrize("url", ["/collections/other", "/collections/other/dggs", f"/collections/other/dggs/{DGGRS}",
                                 f"/collections/other/dggs/{DGGRS}/zones", f"/collections/other/dggs/{DGGRS}/zones/C4"])
def test_unknown_collection(client, url):
    check(client.get(url), 404, "'other'")


@pytest.mark.parametrize("url", ["/dggs/H3", "/dggs/H3/zones", "/dggs/H3/zones/C4/data", "/collections/sample/dggs/H3",
                                 "/dggs/H3/definition"])
def test_unknown_dggrs(client, url):
    check(client.get(url), 404, "'H3'")


@pytest.mark.parametrize("url", ["/nothing", "/map", "/dggs/x/y/z/w/v", "/static/missing.js"])
def test_unknown_routes(client, url):
    check(client.get(url), 404)


def test_post_is_not_allowed(client):
    check(client.post("/map/layers"), 405)


def test_too_many_zones_is_413_before_any_geometry(small_client):
    body = check(small_client.get("/map/cells", params={"level": 4}), 413, "10", "coarser level")
    assert "bbox" in body["detail"]
    check(small_client.get(f"{ROOT}/zones", params={"zone-level": 5, "compact-zones": "false"}), 413, "10",
          "coarser zone-level")
    check(small_client.get(f"{ROOT}/zones", params={"zone-level": 5, "bbox": "-180,-90,180,90"}), 413, "10")
    check(small_client.get(f"{ROOT}/zones/C4/data", params={"zone-depth": "3"}), 413, "27", "10")
    # within the limits the same server answers
    assert small_client.get("/map/cells", params={"level": 0, "bbox": "0,0,10,10"}).status_code == 200
    assert small_client.get(f"{ROOT}/zones", params={"zone-level": 5, "limit": 10}).status_code == 200
    assert small_client.get(f"{ROOT}/zones/C4/data", params={"zone-depth": "2"}).status_code == 200


def test_too_many_cells_without_a_bbox_says_the_whole_store_not_bbox_none(small_client):
    body = check(small_client.get("/map/cells", params={"level": 4}), 413, "10", "in the whole store", "give a bbox")
    assert "None" not in body["detail"]
    body = check(small_client.get("/map/cells", params={"level": 4, "bbox": "-180,-90,180,90"}), 413, "in bbox '-180")
    assert "smaller bbox" in body["detail"]


def test_bad_limits_of_the_factory(store_path):
    from dggs.errors import DggsValueError
    from dggs.server.app import create_app

    with pytest.raises(DggsValueError, match="max_zones"):
        create_app(store_path, max_zones=0)


# -- the command line -------------------------------------------------------------


def one_line_error(res, *named: str) -> None:
    assert res.exit_code == 1, res.output
    lines = res.output.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("Error: "), res.output
    assert "Traceback" not in res.output
    for text in named:
        assert text in lines[0]


def test_cli_missing_store(tmp_path):
    missing = tmp_path / "missing.db"
    one_line_error(CliRunner().invoke(main, ["serve", str(missing)]), str(missing))


@pytest.mark.parametrize("content", [b"not a database at all", b"SQLite format 3\x00" + b"\x01" * 200])
def test_cli_corrupt_store(tmp_path, content):
    bad = tmp_path / "bad.db"
    bad.write_bytes(content)
    one_line_error(CliRunner().invoke(main, ["serve", str(bad)]), str(bad))


def test_cli_port_in_use(store_path):
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        sock.listen(1)
        port = sock.getsockname()[1]
        one_line_error(CliRunner().invoke(main, ["serve", str(store_path), "--port", str(port)]), str(port))


def test_cli_without_the_serve_extra(store_path, monkeypatch):
    monkeypatch.setitem(sys.modules, "uvicorn", None)  # import uvicorn now raises ImportError
    one_line_error(CliRunner().invoke(main, ["serve", str(store_path)]), "pip install 'dggs[serve]'")


def test_cli_bad_port_is_a_usage_error(store_path):
    res = CliRunner().invoke(main, ["serve", str(store_path), "--port", "70000"])
    assert res.exit_code == 2 and "70000" in res.output and "Traceback" not in res.output


def test_cli_error_in_a_real_process_is_one_line_on_stderr(tmp_path):
    exe = Path(sys.executable).parent / "dggs"
    if not exe.exists():
        pytest.skip("the dggs script is not installed next to this Python")
    res = subprocess.run([str(exe), "serve", str(tmp_path / "nope.db")], capture_output=True, text=True, timeout=120)
    assert res.returncode == 1
    assert res.stderr.strip().splitlines() == [f"Error: no cell store at {tmp_path / 'nope.db'}"]


def test_import_dggs_does_not_import_fastapi():
    code = "import sys, dggs, dggs.cli; sys.exit('fastapi' in sys.modules or 'uvicorn' in sys.modules)"
    assert subprocess.run([sys.executable, "-c", code], timeout=120).returncode == 0
