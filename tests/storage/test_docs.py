"""Docstring examples of dggs.storage run; docs/storage.md covers the API and CLI."""

from __future__ import annotations

import doctest
import importlib
import inspect
from pathlib import Path

import pytest

import dggs
from dggs.storage import CellStore
from dggs.storage.cli import register

DOC = Path(__file__).resolve().parents[2] / "docs" / "storage.md"
MODULES = [
    "dggs.storage",
    "dggs.storage.schema",
    "dggs.storage.errors",
    "dggs.storage.readers",
    "dggs.storage.readers_geojson",
    "dggs.storage.readers_arrays",
    "dggs.storage.producer",
    "dggs.storage.ingest",
    "dggs.storage.store",
    "dggs.storage.datasets",
    "dggs.storage.scoped",
    "dggs.storage.ingester",
    "dggs.storage.exporter",
    "dggs.storage.connection",
    "dggs.storage.sources",
    "dggs.storage.inputs",
    "dggs.storage.convert",
    "dggs.storage.queries",
    "dggs.storage.atomic",
    "dggs.storage.cli",
    "dggs.storage.demo",
    "dggs.storage.plot",
]


@pytest.mark.parametrize("name", MODULES)
def test_doctests(name):
    module = importlib.import_module(name)
    result = doctest.testmod(
        module,
        extraglobs={"CellStore": CellStore, "dggs": dggs},
        optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE,
    )
    assert result.failed == 0


PUBLIC = [n for n, f in inspect.getmembers(CellStore) if not n.startswith("_") and (callable(f) or isinstance(f, property))]


@pytest.mark.parametrize("name", PUBLIC)
def test_public_methods_documented_with_examples(name):
    doc = inspect.getdoc(getattr(CellStore, name)) or ""
    assert len(doc) > 30, name
    assert name in DOC.read_text(), f"docs/storage.md does not mention {name}"


def test_every_command_documented():
    import click

    group = click.Group()
    register(group)
    text = DOC.read_text()
    for name, command in group.commands.items():
        assert f"dggs {name}" in text, name
        assert command.help and len(command.help) > 40


DATA = Path(__file__).resolve().parents[2] / "examples" / "data"


def _blocks(text: str) -> list[tuple[str, str]]:
    """Fenced code blocks of a Markdown text as (language, code), in order."""
    blocks, lang, lines = [], None, []
    for line in text.splitlines():
        if line.startswith("```"):
            if lang is None:
                lang, lines = line[3:].strip(), []
            else:
                blocks.append((lang, "\n".join(lines)))
                lang = None
        elif lang is not None:
            lines.append(line)
    assert lang is None, "unclosed code block"
    return blocks


@pytest.mark.slow  # 14 s here: every docs/storage.md block
def test_every_code_block_in_the_docs_runs_as_written(tmp_path):
    import os
    import re
    import shutil
    import subprocess
    import sys

    for sample in DATA.iterdir():
        shutil.copy(sample, tmp_path / sample.name)
    env = {**os.environ, "PATH": f"{Path(sys.executable).parent}{os.pathsep}{os.environ.get('PATH', '')}"}
    blocks = _blocks(DOC.read_text())
    assert {lang for lang, _ in blocks} <= {"python", "console"}, "every block must be runnable"
    ran = 0
    for i, (lang, code) in enumerate(blocks):
        if lang == "python":
            script = tmp_path / f"block{i}.py"
            script.write_text(code)
            proc = subprocess.run([sys.executable, str(script)], cwd=tmp_path, capture_output=True, text=True, env=env)
            assert proc.returncode == 0, f"block {i}:\n{code}\n{proc.stderr}"
            ran += 1
            continue
        for line in code.splitlines():
            assert line.startswith("$ "), line
            command = line[2:]
            expect = re.search(r"# exit (\d+)", command)
            proc = subprocess.run(command, shell=True, cwd=tmp_path, capture_output=True, text=True, env=env)
            assert proc.returncode == (int(expect.group(1)) if expect else 0), f"{command}\n{proc.stdout}{proc.stderr}"
            assert "Traceback" not in proc.stderr
            ran += 1
    assert ran >= 10
