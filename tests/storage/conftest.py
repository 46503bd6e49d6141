"""Fixtures for the storage tests."""

from __future__ import annotations

import numpy as np
import pytest

from dggs.storage import CellStore


@pytest.fixture
def rng():
    return np.random.default_rng(12345)


@pytest.fixture
def store():
    with CellStore(":memory:") as s:
        yield s


@pytest.fixture
def db_path(tmp_path):
    return tmp_path / "cells.db"
