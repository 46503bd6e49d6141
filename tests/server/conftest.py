"""Fixtures of the server tests: a real store file with points at the poles, on the antimeridian and random."""

from __future__ import annotations

import shutil
import warnings
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("fastapi")
pytest.importorskip("httpx")

with warnings.catch_warnings():  # starlette's TestClient warns about httpx itself
    warnings.simplefilter("ignore")
    from fastapi.testclient import TestClient

from dggs.server.app import create_app  # noqa: E402
from dggs.storage import CellStore  # noqa: E402

#: Level the test store bins at.
LEVEL = 6
DGGRS = "DGGS-Split26-ISEA"


@dataclass
class Points:
    """The raw points of the test store (for brute-force checks)."""

    lat: np.ndarray
    lng: np.ndarray
    pop: np.ndarray
    temp: np.ndarray


def make_points(n: int = 3000, seed: int = 7) -> Points:
    rng = np.random.default_rng(seed)
    special_lat = [90.0, 90.0, -90.0, -89.9, 0.0, 0.0, 10.0, -30.0, 65.0, 89.99, -60.0]
    special_lng = [0.0, 45.0, 0.0, 120.0, 180.0, -180.0, 179.9999, -179.9999, 180.0, -179.5, 179.0]
    # uniform on the sphere, plus a dense cluster so that some parents are complete (compaction)
    lat = np.degrees(np.arcsin(rng.uniform(-1, 1, n)))
    lng = rng.uniform(-180, 180, n)
    cluster_lat = rng.uniform(40, 50, 4000)
    cluster_lng = rng.uniform(0, 15, 4000)
    lat = np.concatenate([special_lat, lat, cluster_lat])
    lng = np.concatenate([special_lng, lng, cluster_lng])
    pop = rng.integers(0, 1000, lat.shape[0])
    temp = np.round(rng.normal(15, 10, lat.shape[0]), 3)
    return Points(lat, lng, pop, temp)


@pytest.fixture(scope="session")
def points() -> Points:
    return make_points()


@pytest.fixture(scope="session")
def store_path(tmp_path_factory, points) -> Path:
    path = tmp_path_factory.mktemp("server") / "sample.db"
    names = np.array([f"p{i}" for i in range(points.lat.shape[0])], dtype=object)
    with CellStore(path) as store:
        store.ingest_points(points.lat, points.lng, LEVEL, {"pop": points.pop, "temp": points.temp, "name": names})
    return path


@pytest.fixture(scope="session")
def client(store_path):
    with TestClient(create_app(store_path)) as c:
        yield c


@pytest.fixture(scope="session")
def small_client(store_path):
    """A server with tiny limits (10 zones, 10 features), for the 413 answers."""
    with TestClient(create_app(store_path, max_zones=10, max_features=10)) as c:
        yield c


@pytest.fixture
def store_copy(tmp_path, store_path) -> Path:
    """A private copy of the store that a test may write to."""
    path = tmp_path / "copy.db"
    shutil.copy(store_path, path)
    return path


@pytest.fixture(scope="session")
def reference(store_path):
    """The store opened read-only by the test itself (for independent aggregates)."""
    with CellStore(store_path, create=False, readonly=True) as store:
        yield store


def make_client(path: Path, **kwargs) -> TestClient:
    return TestClient(create_app(path, **kwargs))
