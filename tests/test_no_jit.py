"""numba and llvmlite are gone from the runtime (issue 31): the grid is the compiled C core, dggs._core.

A fresh process imports every module of the grid, the store, the server and the integrations, and runs a verb
of every part of the core (points, hierarchy, grid, polygon fill, lines, dissolve, edges, local (i, j), raster
pixels, both projections); neither numba nor llvmlite may be loaded afterwards.  The source check makes the same
point without running anything: no module of the package names numba.
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

PROBE = r"""
import importlib, sys
import numpy as np
from shapely.geometry import LineString, box
import dggs
for name in ("dggs.index", "dggs.storage", "dggs.arrow", "dggs.cli", "dggs.geometry.snyder", "dggs.geometry.ivea",
             "dggs.pandas", "dggs.duckdb", "dggs.dask", "dggs.xdggs", "dggs.raster", "dggs.spark", "dggs.server.app"):
    try:
        importlib.import_module(name)
    except ImportError as exc:  # an optional extra that is not installed
        if not (exc.name or "").split(".")[0] in {"pandas", "geopandas", "duckdb", "dask", "xdggs", "xarray",
                                                  "rasterio", "rioxarray", "pyspark", "fastapi", "uvicorn"}:
            raise
for grid in (dggs.Grid("ISEA"), dggs.Grid("IVEA")):
    c = grid.latlng_to_cell(51.05, -114.07, 9)
    grid.cell_to_latlng(c), grid.cell_to_boundary(c), grid.cell_to_polygon(c)
    grid.polygon_to_cells(box(-114.5, 50.8, -113.5, 51.3), 8)
    grid.line_to_cells(LineString([(-114.07, 51.05), (-113.49, 53.55)]), 8)
    grid.cells_to_polygons(grid.grid_disk(c, 2))
    grid.directed_edge_to_boundary(grid.origin_to_directed_edges(c)[0])
dggs.cell_to_parent(c, 3), dggs.cell_to_children(c), dggs.compact_cells(dggs.cell_to_children("C4", 3))
dggs.grid_distance(c, dggs.grid_ring(c, 3)[0]), dggs.grid_path_cells(c, dggs.grid_ring(c, 3)[0])
dggs.cell_to_local_ij(c, dggs.grid_disk(c, 1)[0]), dggs.cell_to_vertexes(c), dggs.str_to_int(c)
lat, lng = np.random.default_rng(1).uniform(-90, 90, 20000), np.random.default_rng(2).uniform(-180, 180, 20000)
dggs.latlng_to_cell(lat, lng, 12, as_int=True)
from dggs.index._pixels import *  # noqa: the raster kernel's floor
print(sorted(m for m in ("numba", "llvmlite") if m in sys.modules))
"""


def test_no_jit_is_loaded_by_the_grid_the_store_the_server_or_the_integrations():
    env = {k: v for k, v in os.environ.items() if not k.startswith(("NUMBA_", "DGGS_"))}
    proc = subprocess.run([sys.executable, "-c", PROBE], env=env, capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr[-3000:]
    assert proc.stdout.strip().splitlines()[-1] == "[]"


def test_no_module_of_the_package_names_numba():
    named = []
    for folder in ("dggs", "index", "storage"):
        for path in (ROOT / folder).rglob("*.py"):
            if re.search(r"^\s*(import numba|from numba|import llvmlite|from llvmlite)", path.read_text(), re.M):
                named.append(str(path.relative_to(ROOT)))
    assert named == []


def test_numba_is_not_a_runtime_dependency():
    text = (ROOT / "pyproject.toml").read_text()
    runtime = text[text.index("dependencies = ["):text.index("]", text.index("dependencies = ["))]
    assert "numpy" in runtime
    assert not re.search(r"numba|llvmlite", runtime)
