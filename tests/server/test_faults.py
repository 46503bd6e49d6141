"""The server when its store breaks under it, HEAD and 405, and a read-only open that leaves the folder alone.

Issue 17, item 15.  The store faults run against a real ``dggs serve`` process on 127.0.0.1 (the
process's own threads and connections, not the in-process test client), truncating or deleting the
store file while it serves.
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import time
import urllib.error
import urllib.request
from collections.abc import Iterator
from pathlib import Path

import pytest

from dggs.server.reader import StoreReader
from dggs.storage import CellStore

from .conftest import DGGRS, LEVEL, make_client
from .serving import free_port
from .standard import conforms

EXE = Path(sys.executable).parent / "dggs"
ROUTES = ["/collections", "/collections/sample", f"/dggs/{DGGRS}/zones?zone-level=1",
          f"/dggs/{DGGRS}/zones/C4/data?zone-depth=1", "/map/layers", f"/map/cells?level={LEVEL}"]



def _get(url: str, method: str = "GET") -> tuple[int, str, bytes]:
    """Status, content type and body of ``url`` (an error status is an answer too)."""
    req = urllib.request.Request(url, method=method)
    try:
        with urllib.request.urlopen(req, timeout=30) as res:
            return res.status, res.headers.get("content-type", ""), res.read()
    except urllib.error.HTTPError as exc:
        return exc.code, exc.headers.get("content-type", ""), exc.read()


@pytest.fixture
def served(tmp_path, store_path) -> Iterator[tuple[str, Path, subprocess.Popen[str]]]:
    """A ``dggs serve`` process over a private copy of the store: (base url, store path, process)."""
    if not EXE.exists():
        pytest.skip("the dggs script is not installed next to this Python")
    path = tmp_path / "sample.db"
    shutil.copy(store_path, path)
    port = free_port()
    proc = subprocess.Popen([str(EXE), "serve", str(path), "--port", str(port)],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    url = f"http://127.0.0.1:{port}"
    deadline = time.monotonic() + 120
    while True:
        try:
            with urllib.request.urlopen(url + "/conformance", timeout=5):
                break
        except OSError as exc:
            if proc.poll() is not None or time.monotonic() > deadline:
                proc.kill()
                raise AssertionError(f"dggs serve did not answer: {proc.communicate()[1]}") from exc
            time.sleep(0.2)
    try:
        yield url, path, proc
    finally:
        proc.terminate()
        proc.communicate(timeout=30)


def _all_unavailable(url: str, path: Path) -> None:
    for route in ROUTES:
        status, kind, body = _get(url + route)
        assert status == 503, (route, status, body[:300])
        assert kind.startswith("application/problem+json"), (route, kind)
        doc = json.loads(body)
        conforms(doc, "exception")  # the standard's exception schema, when ../shared is there
        assert doc["status"] == 503 and str(path) in doc["detail"], (route, doc)


@pytest.mark.parametrize("damage", ["truncate-0", "truncate-half", "delete", "garbage"])
def test_a_store_damaged_while_serving_is_503_naming_it(served, damage):
    url, path, proc = served
    for route in ROUTES:  # every route read once: connections open, roll-ups cached
        assert _get(url + route)[0] == 200, route
    size = path.stat().st_size
    if damage == "delete":
        path.unlink()
    elif damage == "garbage":
        path.write_bytes(os.urandom(size))
    else:
        with open(path, "r+b") as fh:
            fh.truncate(0 if damage == "truncate-0" else size // 2)
    _all_unavailable(url, path)
    proc.terminate()
    _, err = proc.communicate(timeout=30)
    assert "Traceback" not in err and "sqlite3" not in err, err


@pytest.mark.parametrize("route", ROUTES + ["/", "/conformance", "/api"])
def test_head_answers_as_get_without_a_body(client, route):
    got, head = client.get(route), client.head(route)
    assert head.status_code == got.status_code == 200, (route, head.status_code, head.text[:200])
    assert head.headers["content-type"] == got.headers["content-type"]
    assert head.content == b""


def test_head_of_a_bad_request_is_the_same_error(client):
    res = client.head(f"/dggs/{DGGRS}/zones/Z9")
    assert res.status_code == 400 and res.headers["content-type"].startswith("application/problem+json")


@pytest.mark.parametrize("method", ["POST", "PUT", "DELETE", "PATCH"])
def test_405_carries_allow(client, method):
    res = client.request(method, "/map/layers")
    assert res.status_code == 405
    assert {m.strip() for m in res.headers["allow"].split(",")} == {"GET", "HEAD"}
    assert res.headers["content-type"].startswith("application/problem+json")
    assert method in res.json()["detail"]


def test_head_against_a_real_server(served):
    url, _path, _proc = served
    status, kind, body = _get(url + "/collections", "HEAD")
    assert (status, body) == (200, b"") and kind.startswith("application/json")


def _side_files(folder: Path) -> list[str]:
    return sorted(p.name for p in folder.iterdir() if p.name.endswith(("-wal", "-shm")))


def test_a_quiet_read_only_open_leaves_the_folder_untouched(tmp_path, store_path):
    path = tmp_path / "quiet.db"
    shutil.copy(store_path, path)
    before = path.read_bytes()
    with CellStore(path, create=False, readonly=True) as store:
        assert store.count() > 0
        assert _side_files(tmp_path) == []
    assert _side_files(tmp_path) == [] and path.read_bytes() == before


def test_a_quiet_server_leaves_the_folder_untouched(tmp_path, store_path):
    path = tmp_path / "quiet.db"
    shutil.copy(store_path, path)
    with make_client(path) as client:
        for route in ROUTES:
            assert client.get(route.replace("/collections/sample", "/collections/quiet")).status_code == 200
        assert _side_files(tmp_path) == []
    assert _side_files(tmp_path) == []


def test_a_read_only_server_sees_an_ingest_that_starts_after_it(tmp_path, store_path):
    path = tmp_path / "grow.db"
    shutil.copy(store_path, path)
    reader = StoreReader(path)
    try:
        before = reader.summary().count
        with CellStore(path) as store:
            store.ingest_points([1.0, 2.0, 3.0], [4.0, 5.0, 6.0], LEVEL, {"pop": [1, 2, 3]})
            assert reader.summary().count == before + 3  # the writer still open: its -wal is there
        assert reader.summary().count == before + 3  # the writer closed: merged into the file
        with CellStore(path) as store:
            store.ingest_points([7.0], [8.0], LEVEL, {"pop": [4]})
        assert reader.summary().count == before + 4  # a whole ingest between two reads
    finally:
        reader.close()
