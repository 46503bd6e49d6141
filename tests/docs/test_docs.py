"""Docstring examples run, every public function is documented, README stays true."""

from __future__ import annotations

import doctest
import importlib
import inspect
import re
from pathlib import Path

import pytest

import dggs

ROOT = Path(__file__).resolve().parents[2]
MODULES = [
    "dggs",
    "dggs.errors",
    "dggs.geometry.authalic",
    "dggs.geometry.icosahedron",
    "dggs.geometry.snyder",
    "dggs.geometry.split26",
    "dggs.index.ids",
    "dggs.index.points",
    "dggs.index.hierarchy",
    "dggs.index.grid",
    "dggs.index.measure",
    "dggs.index.polyfill",
    "dggs.index.vertex",
    "dggs.index.lines",
    "dggs.index._convert.apply",
    "dggs.index._kernel.scalar",
    "dggs.storage.exporter",
    "dggs.arrow.formats",
]
try:  # the optional arrow extra
    import pyarrow  # noqa: F401

    MODULES += ["dggs.arrow", "dggs.arrow.geoparquet"]
except ImportError:
    pass
try:  # the optional dask extra
    import dask.dataframe  # noqa: F401

    MODULES.append("dggs.dask")
except ImportError:
    pass
try:  # the optional raster extra
    import rasterio  # noqa: F401

    MODULES += ["dggs.raster", "dggs.raster.blocks", "dggs.raster.frames", "dggs.raster.burn", "dggs.raster.parquet",
                "dggs.raster.grid", "dggs.raster.pieces", "dggs.raster.center", "dggs.index._pixels", "dggs.storage.raster_ingest",
                "dggs.storage.raster_ingester"]
except ImportError:
    pass


@pytest.mark.parametrize("name", MODULES)
def test_doctests(name):
    module = importlib.import_module(name)
    result = doctest.testmod(module, optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    assert result.failed == 0


@pytest.mark.parametrize("name", [n for n in dggs.__all__ if callable(getattr(dggs, n)) and not isinstance(getattr(dggs, n), type)])
def test_public_functions_have_examples_and_docs(name):
    doc = inspect.getdoc(getattr(dggs, name)) or ""
    assert len(doc) > 40
    assert ">>>" in doc, f"{name} has no example"


def test_readme_shows_exactly_the_two_setup_commands_and_ci_runs_one():
    readme = (ROOT / "README.md").read_text()
    setup = readme.split("## Set-up", 1)[1].split("```sh", 1)[1].split("```", 1)[0]
    commands = [line.split("#")[0].strip() for line in setup.strip().splitlines()]
    assert commands == ["make demo", "make test"]
    ci = (ROOT / ".ci" / "run").read_text()
    assert re.search(r"^make test-all$", ci, re.M)


def test_readme_example_cell_is_real():
    readme = (ROOT / "README.md").read_text()
    m = re.search(r"dggs.latlng_to_cell\(51.05, -114.07, 9\)\s+# '(\w+)'", readme)
    assert m and m.group(1) == dggs.latlng_to_cell(51.05, -114.07, 9)


def test_readme_usage_block_runs():
    readme = (ROOT / "README.md").read_text()
    block = readme.split("## Use", 1)[1].split("```python", 1)[1].split("```", 1)[0]
    namespace: dict = {}
    exec(compile(block, "README.md", "exec"), namespace)  # noqa: S102 - our own README
    assert len(namespace["ids"]) == 10**6 and namespace["ids"].dtype == "uint64"
    assert (namespace["parents"] == dggs.str_to_int(dggs.cell_to_parent(dggs.int_to_str(namespace["ids"]), 6))).all()
    m = re.search(r"dggs.str_to_int\(cell\)\s+# (\d+)", readme)
    assert m and int(m.group(1)) == dggs.str_to_int(dggs.latlng_to_cell(51.05, -114.07, 9))


# --------------------------------------------------------------------------
# Every code block in README.md and docs/*.md runs as written
# (docs/storage.md's blocks are tested with the storage package).
# --------------------------------------------------------------------------

DOCS = [ROOT / "README.md", *sorted(p for p in (ROOT / "docs").glob("*.md") if p.name != "storage.md")]
_FENCE = re.compile(r"^```(\w*)\n(.*?)^```", re.M | re.S)


def _blocks(lang: str) -> list:
    found = []
    for path in DOCS:
        for i, m in enumerate(_FENCE.finditer(path.read_text())):
            assert m.group(1), f"{path.name}: block {i} has no language tag (python and sh blocks run; text is output)"
            if m.group(1) == lang:
                found.append(pytest.param(m.group(2), id=f"{path.name}-{i}"))
    return found


@pytest.fixture
def docs_dir(tmp_path, monkeypatch):
    """A temporary working directory holding the sample files the docs name (examples/data/)."""
    (tmp_path / "examples").mkdir()
    (tmp_path / "examples" / "data").symlink_to(ROOT / "examples" / "data", target_is_directory=True)
    monkeypatch.chdir(tmp_path)
    return tmp_path


def test_docs_have_code_blocks():
    assert len(_blocks("python")) >= 2 and len(_blocks("sh")) >= 3


@pytest.mark.parametrize("path", [p for p in DOCS if "```python" in p.read_text()], ids=lambda p: p.name)
def test_python_blocks_run(path, docs_dir):
    """A page's python blocks, in order, in one namespace (a page reads as one session)."""
    namespace: dict = {"__name__": "__doc_page__"}
    for i, m in enumerate(_FENCE.finditer(path.read_text())):
        if m.group(1) == "python":
            exec(compile(m.group(2), f"{path.name} block {i}", "exec"), namespace)  # noqa: S102 - our own docs


# README.md's CLI tour (38 s here) and docs/experiments.md's tables (23 s) run in make test-all.
SLOW_SH = {"README.md-3", "experiments.md-0"}


@pytest.mark.parametrize("code", [pytest.param(*p.values, id=p.id, marks=pytest.mark.slow) if p.id in SLOW_SH else p for p in _blocks("sh")])
def test_sh_blocks_run(code, docs_dir, monkeypatch):
    """Each ``dggs ...`` line, in order, through click's CliRunner; ``cmake``/``ctest`` lines (the C library on its
    own) run as written in the repository, with the venv's cmake; other lines (make) are the Makefile's.

    ``dggs serve`` runs up to the point where it would start listening: the store is opened and the app
    built, and uvicorn is handed the app (a server that runs until stopped has its own tests in tests/server).
    """
    import shlex

    import uvicorn
    from click.testing import CliRunner

    from dggs.cli import main

    served = []
    monkeypatch.setattr(uvicorn, "run", lambda app, **kwargs: served.append((app, kwargs)))
    for line in code.splitlines():
        args = shlex.split(line, comments=True)
        if args and args[0] in ("cmake", "ctest"):
            import os
            import subprocess
            import sys

            env = {**os.environ, "PATH": f"{Path(sys.executable).parent}{os.pathsep}{os.environ['PATH']}"}
            done = subprocess.run(["bash", "-c", line], cwd=ROOT, env=env, capture_output=True, text=True, timeout=900)
            assert done.returncode == 0, (line, done.stdout[-2000:], done.stderr[-2000:])
            continue
        if not args or args[0] != "dggs":
            assert not args or args[0] == "make", line
            continue
        res = CliRunner().invoke(main, args[1:])
        assert res.exit_code == 0, (line, res.output, res.exception)
        assert res.output.strip(), line
        if args[1] == "serve":
            assert served and served[-1][1]["host"] == "127.0.0.1", line
