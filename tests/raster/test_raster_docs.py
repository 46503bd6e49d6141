"""The example script makes the sample rasters and figures docs/raster.md shows (the modules' doctests: tests/docs)."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

pytest.importorskip("rasterio")

ROOT = Path(__file__).resolve().parents[2]
@pytest.mark.slow  # 7 s here: bins and draws two rasters
def test_the_example_writes_the_sample_rasters_and_the_figures(tmp_path):
    proc = subprocess.run([sys.executable, str(ROOT / "examples" / "raster_example.py"), "--data", str(tmp_path),
                           "--figures", str(tmp_path)], capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr
    for name in ("europe_elevation.tif", "europe_landcover.tif"):  # the files docs/raster.md reads: its output
        assert (tmp_path / name).read_bytes() == (ROOT / "examples" / "data" / name).read_bytes()
    for name in ("raster-mean.png", "raster-classes.png"):
        assert (tmp_path / name).stat().st_size > 10_000 and (ROOT / "docs" / name).exists()
