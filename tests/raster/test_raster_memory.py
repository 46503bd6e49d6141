"""GDAL's block cache stays small while dggs reads a raster, unless the user sized it (issue 19's memory)."""

from __future__ import annotations

import pytest

rasterio = pytest.importorskip("rasterio")

from rasterio.env import getenv, hasenv  # noqa: E402

from dggs.raster import source as _raster_source  # noqa: E402


def _cache_while_reading():
    with _raster_source._small_block_cache():
        return getenv().get("GDAL_CACHEMAX") if hasenv() else None


def test_reads_cap_gdals_block_cache(monkeypatch):
    monkeypatch.delenv("GDAL_CACHEMAX", raising=False)
    assert int(_cache_while_reading()) == 64 * 2**20


def test_a_users_cache_size_is_kept(monkeypatch):
    monkeypatch.setenv("GDAL_CACHEMAX", "2000")
    assert _cache_while_reading() is None  # no option of ours: GDAL takes the user's variable
    monkeypatch.delenv("GDAL_CACHEMAX")
    with rasterio.Env(GDAL_CACHEMAX=123456789):
        assert int(_cache_while_reading()) == 123456789
