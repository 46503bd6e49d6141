"""Build step: the web map's MapLibre GL JS files go into every wheel built from a clone.

So do its geography (Natural Earth's countries from ``world-atlas``, TopoJSON) and ``topojson-client``,
which reads them in the page. They are npm dependencies (``package.json`` and its lock file beside this module),
never committed; ``make static`` copies them into ``static/vendor``.  A wheel built
without that step would serve a map stuck at "Loading...", so building the package
(``pip install .``, ``python -m build``, ``pip wheel``) copies them in first: from
``node_modules`` if ``npm ci`` ran, else by running ``npm ci`` when npm is there.
Without npm the build goes on with a warning (and ``dggs serve`` warns at start-up).
Editable installs are left alone: they read the source folder, where ``make static``
puts the files.

The globe draws its cells from ids with the grid's C core compiled to WebAssembly: the JS package's module and
``.wasm`` (``js/``, ``make wasm``) go into ``static/vendor/dggs`` likewise, built first where the toolchain
(clang with Debian's wasi-libc) is installed; without them the page reads the server's GeoJSON instead.

Setuptools runs :class:`BuildPy` in place of its ``build_py`` (``tool.setuptools.cmdclass``
in pyproject.toml); it needs nothing but the standard library and setuptools.
"""

from __future__ import annotations

import shutil
import subprocess
import warnings
from pathlib import Path

from setuptools.command.build_py import build_py

__all__ = ["BuildPy", "vendor_maplibre", "vendor_dggs_js"]

_HERE = Path(__file__).parent
_WANTED = ("maplibre-gl.mjs", "maplibre-gl.css")
#: The page's other npm files: node_modules path -> static/vendor path (as ``make static`` copies them).
GEOGRAPHY = {
    "world-atlas/countries-50m.json": "world-atlas/countries-50m.json",
    "world-atlas/LICENSE": "world-atlas/LICENSE",
    "topojson-client/dist/topojson-client.min.js": "topojson-client/topojson-client.min.js",
    "topojson-client/LICENSE": "topojson-client/LICENSE",
}


def vendor_maplibre(server: Path = _HERE) -> bool:
    """Fill ``static/vendor`` from npm's ``node_modules`` (running ``npm ci`` if needed).

    MapLibre's ``dist`` folder, then the ``GEOGRAPHY`` files (the map works without them, with no land drawn).

    Returns whether the MapLibre files are there afterwards.
    """
    vendor = server / "static" / "vendor"
    target = vendor / "maplibre-gl"
    modules = server / "node_modules"
    if all((target / name).is_file() for name in _WANTED) and all((vendor / v).is_file() for v in GEOGRAPHY.values()):
        return True
    dist = modules / "maplibre-gl" / "dist"
    complete = dist.is_dir() and all((modules / name).is_file() for name in GEOGRAPHY)
    if not complete and shutil.which("npm") and (server / "package-lock.json").is_file():
        command = ["npm", "ci", "--prefix", str(server), "--no-audit", "--no-fund", "--loglevel=error"]
        if subprocess.run(command, check=False).returncode != 0:
            warnings.warn("npm ci failed: the wheel's web map will lack MapLibre GL JS", stacklevel=2)
    if not dist.is_dir():
        warnings.warn("MapLibre GL JS not found (needs npm): the wheel's web map will not load", stacklevel=2)
        return False
    shutil.rmtree(target, ignore_errors=True)
    shutil.copytree(dist, target)
    missing = [name for name in GEOGRAPHY if not (modules / name).is_file()]
    if missing:
        warnings.warn(f"not in node_modules: {', '.join(missing)}: the wheel's web map will draw no land", stacklevel=2)
    for name, copy in GEOGRAPHY.items():
        if name not in missing:
            (vendor / copy).parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(modules / name, vendor / copy)
    return True


#: The JS package's files the page loads: repository path -> static/vendor path (as ``make static-wasm``).
DGGS_JS = {"js/src/dggs.js": "dggs/dggs.js", "js/dist/dggs.wasm": "dggs/dggs.wasm"}


def vendor_dggs_js(server: Path = _HERE) -> bool:
    """Copy the JS package (its module and the C core as WebAssembly) into ``static/vendor/dggs``.

    The ``.wasm`` is built first (``make wasm``) if it is missing and the toolchain is installed (nothing is
    installed here). Returns whether both files are there afterwards; the page reads GeoJSON without them.
    """
    root = server.parents[1]
    vendor = server / "static" / "vendor"
    wasm = root / "js" / "dist" / "dggs.wasm"
    toolchain = shutil.which("clang") and Path("/usr/lib/wasm32-wasi/libc.a").is_file()
    if not wasm.is_file() and toolchain and shutil.which("make") and (root / "Makefile").is_file():
        subprocess.run(["make", "-C", str(root), "--no-print-directory", "wasm"], check=False)
    missing = [name for name in DGGS_JS if not (root / name).is_file()]
    if missing:
        warnings.warn(f"not built: {', '.join(missing)} (make wasm): the wheel's web map will read GeoJSON", stacklevel=2)
        return False
    for name, copy in DGGS_JS.items():
        (vendor / copy).parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(root / name, vendor / copy)
    return True


class BuildPy(build_py):
    """Setuptools' ``build_py``, with the web map's MapLibre files put in place first."""

    def run(self) -> None:  # noqa: D102 - setuptools' own command
        if not getattr(self, "editable_mode", False):
            vendor_maplibre()
            vendor_dggs_js()
        super().run()
