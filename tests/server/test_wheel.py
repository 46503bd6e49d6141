"""Issue 17 item 20: a wheel built from a clone carries the web map's MapLibre files.

Built for real with pip from a copy of the tracked files (no ``static/vendor``),
then read as the zip it is; the files the page loads must be in it.
"""

from __future__ import annotations

import shutil
import subprocess
import sys
import warnings
import zipfile
from pathlib import Path

import pytest

from dggs.server import _build
from dggs.server.vendor import VENDOR

ROOT = Path(__file__).resolve().parents[2]
SERVER = ROOT / "dggs" / "server"


def _tracked_copy(target: Path) -> None:
    names = subprocess.run(["git", "ls-files", "-z", "--cached", "--others", "--exclude-standard"], cwd=ROOT, capture_output=True, check=True).stdout
    for name in filter(None, names.decode().split("\0")):
        source = ROOT / name
        if source.is_file():
            (target / name).parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(source, target / name)


@pytest.mark.slow
def test_a_wheel_built_from_a_clone_serves_a_whole_map(tmp_path):
    src = tmp_path / "src"
    _tracked_copy(src)
    assert not (src / "dggs/server/static/vendor").exists()
    if (SERVER / "node_modules").is_dir():  # what `npm ci` left (else the build runs npm itself)
        shutil.copytree(SERVER / "node_modules", src / "dggs/server/node_modules", symlinks=True)
    out = tmp_path / "out"
    subprocess.run(
        [sys.executable, "-m", "pip", "wheel", "-q", "--no-deps", "-w", str(out), str(src)],
        check=True, capture_output=True, timeout=600,
    )
    (wheel,) = out.glob("dggs-*.whl")
    with zipfile.ZipFile(wheel) as archive:
        sizes = {info.filename: info.file_size for info in archive.infolist()}
    geography = [f"vendor/{name}" for name in _build.GEOGRAPHY.values() if not name.endswith("LICENSE")]
    for name in (*VENDOR, "vendor/maplibre-gl/maplibre-gl-worker.mjs", *geography):
        assert sizes.get(f"dggs/server/static/{name}", 0) > 5_000, name
    assert not [name for name in sizes if name.endswith(".map") or "-dev." in name]  # 19 MB the page never loads
    if shutil.which("clang") and Path("/usr/lib/wasm32-wasi/libc.a").is_file():  # built by make wasm (issue 34)
        assert sizes.get("dggs/server/static/vendor/dggs/dggs.wasm", 0) > 100_000
        assert sizes.get("dggs/server/static/vendor/dggs/dggs.js", 0) > 5_000
    assert sizes.get("dggs/server/static/cells_layer.js", 0) > 5_000  # the globe's WebGL layer, beside app.js


def test_without_npm_the_build_goes_on_with_a_warning(tmp_path, monkeypatch):
    (tmp_path / "static").mkdir()
    monkeypatch.setattr(_build.shutil, "which", lambda name: None)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        assert _build.vendor_maplibre(tmp_path) is False
    assert any("MapLibre GL JS not found" in str(w.message) for w in caught)
    assert not (tmp_path / "static" / "vendor").exists()


def test_the_build_copies_what_npm_installed(tmp_path):
    dist = tmp_path / "node_modules" / "maplibre-gl" / "dist"
    dist.mkdir(parents=True)
    for name in ("maplibre-gl.mjs", "maplibre-gl.css"):
        (dist / name).write_text("x")
    assert _build.vendor_maplibre(tmp_path) is True
    assert (tmp_path / "static/vendor/maplibre-gl/maplibre-gl.mjs").read_text() == "x"


def _js_tree(root: Path, wasm: bool) -> Path:
    (root / "js/src").mkdir(parents=True)
    (root / "js/src/dggs.js").write_text("export {}")
    if wasm:
        (root / "js/dist").mkdir(parents=True)
        (root / "js/dist/dggs.wasm").write_bytes(b"\0asm")
    server = root / "dggs" / "server"
    (server / "static").mkdir(parents=True)
    return server


def test_the_build_copies_the_js_package(tmp_path):
    """Issue 34: the WebAssembly core and its module go into static/vendor/dggs, where the page loads them."""
    server = _js_tree(tmp_path, wasm=True)
    assert _build.vendor_dggs_js(server) is True
    assert (server / "static/vendor/dggs/dggs.wasm").read_bytes() == b"\0asm"
    assert (server / "static/vendor/dggs/dggs.js").read_text() == "export {}"


def test_without_the_wasm_the_build_goes_on_with_a_warning(tmp_path, monkeypatch):
    server = _js_tree(tmp_path, wasm=False)
    monkeypatch.setattr(_build.shutil, "which", lambda name: None)  # no toolchain: nothing is built
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        assert _build.vendor_dggs_js(server) is False
    assert any("will read GeoJSON" in str(w.message) for w in caught)
    assert not (server / "static" / "vendor").exists()
