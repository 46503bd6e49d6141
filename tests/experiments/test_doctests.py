"""The docstring examples of every experiments module run (tests/docs/test_docs.py covers the library's)."""

from __future__ import annotations

import doctest
import importlib
import pkgutil

import pytest

import dggs.experiments

MODULES = sorted(m.name for m in pkgutil.iter_modules(dggs.experiments.__path__))


@pytest.mark.parametrize("name", MODULES)
def test_doctests(name):
    module = importlib.import_module(f"dggs.experiments.{name}")
    result = doctest.testmod(module, optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    assert result.failed == 0
