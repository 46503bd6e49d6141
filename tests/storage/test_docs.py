"""Docstring examples of dggs.storage run; docs/storage.md covers the API and CLI."""

from __future__ import annotations

import doctest
import importlib
import inspect
from pathlib import Path

import pytest

from dggs.storage import CellStore
from dggs.storage.cli import register

DOC = Path(__file__).resolve().parents[2] / "docs" / "storage.md"
MODULES = [
    "dggs.storage",
    "dggs.storage.schema",
    "dggs.storage.errors",
    "dggs.storage.readers",
    "dggs.storage.ingest",
    "dggs.storage.store",
    "dggs.storage.cli",
    "dggs.storage.demo",
    "dggs.storage.plot",
]


@pytest.mark.parametrize("name", MODULES)
def test_doctests(name):
    module = importlib.import_module(name)
    result = doctest.testmod(module, optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
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
