"""A plain pip install (issue 17, item 20): no MapLibre files, no xarray, the source tree on the path."""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from click.testing import CliRunner

from dggs.cli import main
from dggs.server import vendor

from .conftest import make_client

ROOT = Path(__file__).resolve().parents[2]
tomllib = pytest.importorskip("tomllib")  # Python 3.11 and later


def _page_folder(tmp_path: Path) -> Path:
    """The web map's folder as a wheel built without ``make static`` has it: no vendor/."""
    folder = tmp_path / "static"
    shutil.copytree(vendor.STATIC_FOLDER, folder, ignore=shutil.ignore_patterns("vendor"))
    return folder


def test_the_page_without_maplibre_says_what_is_missing(store_path, tmp_path):
    with make_client(store_path, static=_page_folder(tmp_path)) as client:
        page = client.get("/", headers={"accept": "text/html"})
        assert page.status_code == 200 and page.headers["content-type"].startswith("text/html")
        assert 'href="http://testserver/api.html"' in page.text  # the landing page's links, usable
        assert "Loading" not in page.text and "<script" not in page.text  # not the page that waits forever
        assert "MapLibre" in page.text and "make static" in page.text and "docs/serve.md" in page.text
        assert client.get("/?f=json").json()["links"]  # the API itself answers


def test_serve_warns_in_one_line_when_maplibre_is_missing(store_path, tmp_path, monkeypatch):
    import uvicorn

    monkeypatch.setattr(vendor, "STATIC_FOLDER", _page_folder(tmp_path))
    monkeypatch.setattr(uvicorn, "run", lambda *a, **k: None)
    res = CliRunner().invoke(main, ["serve", str(store_path), "--port", "8765"])
    assert res.exit_code == 0, res.output
    warnings = [line for line in res.stderr.splitlines() if line.startswith("warning:")]
    assert len(warnings) == 1 and "make static" in warnings[0] and "MapLibre" in warnings[0]


def test_serve_does_not_warn_with_maplibre(store_path, monkeypatch):
    import uvicorn

    if vendor.missing_vendor():
        pytest.skip("this checkout has no static/vendor (make static)")
    monkeypatch.setattr(uvicorn, "run", lambda *a, **k: None)
    res = CliRunner().invoke(main, ["serve", str(store_path), "--port", "8765"])
    assert res.exit_code == 0 and "warning" not in res.stderr


def test_the_serve_extra_has_what_the_serve_docs_import():
    extras = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]["optional-dependencies"]
    names = {req.split(">")[0].split("[")[0].strip() for req in extras["serve"]}
    assert {"fastapi", "uvicorn", "httpx"} <= names  # docs/serve.md runs fastapi.testclient (httpx)
    assert "fastapi.testclient" in (ROOT / "docs" / "serve.md").read_text()


def test_xdggs_without_xarray_names_the_extra():
    code = "import sys; sys.modules['xarray'] = None; import dggs.xdggs"
    res = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert res.returncode != 0
    last = res.stderr.strip().splitlines()[-1]
    assert last.startswith("ImportError") and "pip install 'dggs[xarray]'" in last and "xarray" in last, last


def test_the_source_tree_without_an_install_says_why(tmp_path):
    # Python in the repository root with a non-editable install: the bare dggs/ folder comes first on the
    # path, and index/ is dggs.index only through the install's package-dir mapping.  -S leaves out the
    # site folder (and with it this venv's editable finder), so only the source tree is there.
    code = "import sys; sys.path.insert(0, ''); import dggs; dggs.latlng_to_cell"
    res = subprocess.run([sys.executable, "-S", "-c", code], cwd=ROOT, capture_output=True, text=True,
                         timeout=120)
    assert res.returncode != 0
    last = res.stderr.strip().splitlines()[-1]
    assert last.startswith("ImportError:") and "source folder" in last and "pip install -e ." in last, last
    assert str(ROOT / "dggs") in last
