"""Rasters for the tests of tests/raster: GeoTIFFs written with rasterio, and a store's rows read back."""

from __future__ import annotations

import numpy as np
import rasterio
from rasterio.transform import from_origin

import dggs
from dggs.storage.schema import quote

EA = from_origin(4.0e6, 3.0e6, 3000.0, 3000.0)  # 3 km pixels in EPSG:3035 (equal-area, Europe)


def write(path, data, crs="EPSG:3035", transform=EA, nodata=None):
    """A GeoTIFF of ``data`` (rows, cols) or (bands, rows, cols)."""
    data = np.asarray(data)
    if data.ndim == 2:
        data = data[None]
    with rasterio.open(path, "w", driver="GTiff", height=data.shape[1], width=data.shape[2], count=data.shape[0],
                       dtype=data.dtype, crs=crs, transform=transform, nodata=nodata) as dst:
        dst.write(data)
    return path


def field(rows, cols, seed=1, bands=1):
    """A smooth field with noise, float32, (bands, rows, cols)."""
    rng = np.random.default_rng(seed)
    r, c = np.mgrid[0:rows, 0:cols]
    out = [np.sin(r / 7.0 + b) * 40 + np.cos(c / 9.0) * 30 + rng.random((rows, cols)) * 10 for b in range(bands)]
    return np.stack(out).astype(np.float32)


def stored(conn, columns):
    """The store's rows as {column: array} in cell order, ``cell_id`` (int) first; class labels spelt as stored."""
    names = [c.replace("-", "m").replace(".", "_") for c in columns]
    sql = "SELECT cell, " + ", ".join(quote(n) for n in names) + " FROM all_points ORDER BY cell"
    rows = conn.execute(sql).fetchall()
    out = {"cell_id": np.array([dggs.str_to_int(r[0]) for r in rows], dtype=np.int64)}
    for k, column in enumerate(columns):
        out[column] = np.array([r[k + 1] for r in rows], dtype=np.float64)
    return out


def same_rows(conn, frame):
    """Whether the store holds exactly ``frame``'s rows: ids and every value, to the last bit."""
    columns = [c for c in frame.columns if c not in ("cell_id", "cell")]
    got = stored(conn, columns)
    if not np.array_equal(got["cell_id"], frame["cell_id"].to_numpy()):
        return False
    return all(np.array_equal(got[c], frame[c].to_numpy(dtype=np.float64), equal_nan=True) for c in columns)
