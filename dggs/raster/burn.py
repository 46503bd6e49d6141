"""Cells back onto a raster grid: :func:`cells_to_raster` (part of :mod:`dggs.raster`).

``mode="center"`` gives each pixel the value of the cell holding the pixel's
centre (the centres put in WGS84, then :func:`dggs.latlng_to_cell`);
``mode="area"`` the mean of the cells the pixel meets, each weighted by the
area it shares with the pixel: the pixel is cut along the cells' edges as
:func:`dggs.raster.raster_to_cells` cuts it, the same edge points and the
same error bound (docs/raster.md).  Pixels meeting no given cell (or only
cells whose value is NaN) get ``nodata``.
"""

from __future__ import annotations

import os
from typing import Any

import numpy as np

from dggs.errors import DggsValueError, LevelMismatchError
from dggs.index._checks import is_choice
from dggs.index._convert import cells_in, id_name
from dggs.index.hierarchy import get_level
from dggs.index.points import latlng_to_cell
from dggs.raster.blocks import each_block
from dggs.raster.grid import to_wgs84
from dggs.raster.source import RasterError, RasterSource, open_raster

__all__ = ["cells_to_raster", "BURN_MODES", "MAX_PIXELS"]

#: The modes of :func:`cells_to_raster`.
BURN_MODES = ("center", "area")
#: Most pixels :func:`cells_to_raster` makes (4 GB of float64): larger grids are refused before allocating.
MAX_PIXELS = 500_000_000


def cells_to_raster(
    cells: Any,
    values: Any,
    *,
    like: Any = None,
    transform: Any = None,
    shape: tuple[int, int] | None = None,
    crs: Any = "EPSG:4326",
    mode: str = "center",
    nodata: float = np.nan,
    path: str | os.PathLike[str] | None = None,
    block_size: int = 512,
) -> Any:
    """Cell values drawn onto a raster grid: the way back of :func:`dggs.raster.raster_to_cells`.

    Parameters
    ----------
    cells : ids in any container
        Cells of one level (string or integer ids), each once.
    values : array_like
        One number per cell (NaN: no value).
    like : str, path or xarray.DataArray, optional
        A raster whose grid (CRS, transform, rows and columns) to copy.
    transform, shape, crs : affine.Affine, (rows, cols), CRS, optional
        The grid, without ``like``: its affine transform, size and CRS (default WGS84 lng/lat).
    mode : {"center", "area"}
        ``"center"``: the value of the cell holding the pixel's centre;
        ``"area"``: the mean of the cells the pixel meets, weighted by the area each shares with it.
    nodata : float
        The value of pixels without a cell (default NaN).
    path : str or path, optional
        Also write the raster there as a GeoTIFF (float64, ``nodata`` set), whole or not at all.
    block_size : int
        Pixels a block side (the grid is cut a block at a time, on all cores).

    Returns
    -------
    numpy.ndarray or xarray.DataArray
        (rows, cols) float64; a DataArray on ``like``'s y and x (with its CRS) when ``like`` is one.

    Raises
    ------
    InvalidCellError, LevelMismatchError
        A bad id; cells of several levels.
    DggsValueError
        Values not one per cell, a cell given twice, an unknown ``mode``, a missing or doubly given grid,
        a ``nodata`` that is not a number.
    RasterError
        ``like`` cannot be read, or has no CRS; the grid's CRS has no transformation to WGS84; the grid
        has more than :data:`MAX_PIXELS` pixels (refused before anything is allocated).
    StorageError
        ``path`` cannot be written (nothing is written then).

    Examples
    --------
    >>> import numpy as np, dggs
    >>> from affine import Affine
    >>> grid = Affine(0.01, 0, 10.0, 0, -0.01, 50.0)  # 0.01° pixels from (10°E, 50°N)
    >>> cell = dggs.latlng_to_cell(49.99, 10.01, 6)
    >>> out = cells_to_raster([cell], [7.0], transform=grid, shape=(2, 2))
    >>> out.tolist()
    [[7.0, 7.0], [7.0, 7.0]]
    """
    if not is_choice(mode, BURN_MODES):
        raise DggsValueError(f"mode {mode!r} is not one of {', '.join(BURN_MODES)}")
    if isinstance(block_size, bool) or not isinstance(block_size, int) or block_size < 1:
        raise DggsValueError(f"block_size must be a whole number of pixels >= 1, not {block_size!r}")
    ids, vals, level = _cells(cells, values)
    grid = _grid_of(like, transform, shape, crs)
    pixels = grid.height * grid.width
    if pixels > MAX_PIXELS:
        raise RasterError(
            f"a grid of {grid.height:,} x {grid.width:,} is {pixels:,} pixels ({pixels * 8 / 2**30:,.1f} GiB of "
            f"float64), over the limit of {MAX_PIXELS:,}: draw it in windows (smaller transform= and shape=)"
        )
    if isinstance(nodata, (bool, np.bool_)) or not isinstance(nodata, (int, float, np.integer, np.floating)):
        raise DggsValueError(f"nodata {nodata!r} must be a number (the value of pixels no cell gives one)")
    fill = float(nodata)
    out = np.full((grid.height, grid.width), fill)
    if ids.size:
        work = _centres if mode == "center" else _areas
        transformer = to_wgs84(grid.crs)
        blocks = each_block(grid, block_size, lambda block: work(grid, transformer, block, ids, vals, level))
        for part in blocks:
            if part is not None:
                row, col, data = part
                out[row : row + data.shape[0], col : col + data.shape[1]] = np.where(np.isnan(data), fill, data)
    if path is not None:
        _write(path, out, grid, fill)
    if hasattr(like, "dims") and hasattr(like, "rio"):
        return _like_array(like, out, fill)
    return out


def _cells(cells: Any, values: Any) -> tuple[np.ndarray, np.ndarray, int]:
    """Ids sorted, their values, their one level."""
    ids, _ = cells_in(cells)
    ids = ids.reshape(-1)
    try:
        vals = np.asarray(values, dtype=np.float64).reshape(-1)
    except (TypeError, ValueError):
        raise DggsValueError(f"values must be numbers, one per cell, not {type(values).__name__}") from None
    if vals.shape[0] != ids.shape[0]:
        raise DggsValueError(f"{vals.shape[0]} values for {ids.shape[0]} cells: give one value per cell")
    if ids.size == 0:
        return ids, vals, 0
    levels = np.asarray(get_level(ids))
    if (levels != levels[0]).any():
        other = int(np.flatnonzero(levels != levels[0])[0])
        raise LevelMismatchError(f"cell {id_name(ids[other])!r} is of level {int(levels[other])}, the first "
                                 f"{id_name(ids[0])!r} of level {int(levels[0])}: give cells of one level")
    order = np.argsort(ids, kind="stable")
    ids, vals = ids[order], vals[order]
    twice = np.flatnonzero(ids[1:] == ids[:-1])
    if twice.size:
        raise DggsValueError(f"cell {id_name(ids[twice[0]])!r} is given twice: give each cell once")
    return ids, vals, int(levels[0])


def _grid_of(like: Any, transform: Any, shape: Any, crs: Any) -> RasterSource:
    """The target grid as a RasterSource whose blocks are all valid (no data read)."""
    if like is not None:
        if transform is not None or shape is not None:
            raise DggsValueError("give the grid as like= or as transform= and shape=, not both")
        src = open_raster(like)
        transform, rows, cols, crs = src.transform, src.height, src.width, src.crs
    else:
        if transform is None or shape is None:
            raise DggsValueError("give the grid: like= (a raster or DataArray), or transform= and shape=")
        try:
            rows, cols = (int(n) for n in shape)
            ok = rows >= 1 and cols >= 1 and (rows, cols) == tuple(shape)
        except (TypeError, ValueError):
            ok = False
        if not ok:
            raise DggsValueError(f"shape must be (rows, cols), two whole numbers >= 1, not {shape!r}")
        if not all(hasattr(transform, k) for k in "abcdef"):
            raise DggsValueError(f"transform must be an affine.Affine, not {type(transform).__name__}")
        from pyproj import CRS
        from pyproj.exceptions import CRSError

        try:
            crs = CRS.from_user_input(crs)
        except CRSError as exc:
            raise RasterError(f"crs {crs!r} is not a CRS pyproj knows ({exc})") from None

    def read(row: int, col: int, n_rows: int, n_cols: int) -> tuple[np.ndarray, np.ndarray]:
        return np.zeros((1, n_rows, n_cols)), np.ones((n_rows, n_cols), dtype=bool)

    return RasterSource("grid", crs, transform, rows, cols, [1], [None], 0, 0, read, np.float64)


def _lookup(ids: np.ndarray, vals: np.ndarray, cell: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Where each cell is among ``ids`` with a value (a mask), and that value (NaN elsewhere)."""
    at = np.minimum(np.searchsorted(ids, cell), ids.shape[0] - 1)
    found = ids[at] == cell
    value = np.where(found, vals[at], np.nan)
    return ~np.isnan(value), value


def _centres(grid: RasterSource, transformer: Any, block: Any, ids: np.ndarray, vals: np.ndarray,
             level: int) -> tuple[int, int, np.ndarray]:
    rows, cols = block.shape
    r, c = np.mgrid[0:rows, 0:cols].astype(np.float64)
    t = grid.transform
    x = t.a * (c + block.col + 0.5) + t.b * (r + block.row + 0.5) + t.c
    y = t.d * (c + block.col + 0.5) + t.e * (r + block.row + 0.5) + t.f
    if transformer is not None:
        x, y = (np.asarray(v, dtype=np.float64) for v in transformer.transform(x, y, errcheck=False))
    lng = (x.ravel() + 180.0) % 360.0 - 180.0  # a grid in longitudes 0..360 too
    lat = y.ravel()
    ok = np.isfinite(lat) & np.isfinite(lng) & (np.abs(lat) <= 90.0)
    cell = np.zeros(lat.shape[0], dtype=np.uint64)
    if ok.any():
        cell[ok] = np.asarray(latlng_to_cell(lat[ok], lng[ok], level, as_int=True), dtype=np.uint64)
    _, value = _lookup(ids, vals, cell)
    return block.row, block.col, value.reshape(rows, cols)


def _areas(grid: RasterSource, transformer: Any, block: Any, ids: np.ndarray, vals: np.ndarray,
           level: int) -> tuple[int, int, np.ndarray]:
    from dggs.raster.pieces import block_pieces  # the pieces raster_to_cells cuts

    rows, cols = block.shape
    pixel, cell, area, _ = block_pieces(grid, transformer, block, level)
    has, value = _lookup(ids, vals, cell)
    weight = np.bincount(pixel[has], weights=area[has], minlength=rows * cols)
    total = np.bincount(pixel[has], weights=area[has] * value[has], minlength=rows * cols)
    with np.errstate(invalid="ignore", divide="ignore"):
        mean = np.where(weight > 0, total / weight, np.nan)
    return block.row, block.col, mean.reshape(rows, cols)


def _write(path: str | os.PathLike[str], data: np.ndarray, grid: RasterSource, nodata: float) -> None:
    """A GeoTIFF, written under a temporary name and renamed over ``path`` when whole."""
    import rasterio

    from dggs.storage.atomic import atomic_path

    with atomic_path(path) as tmp:
        with rasterio.open(tmp, "w", driver="GTiff", height=data.shape[0], width=data.shape[1], count=1,
                           dtype="float64", crs=grid.crs.to_wkt(), transform=grid.transform, nodata=nodata,
                           compress="deflate") as dst:
            dst.write(data[None])


def _like_array(like: Any, data: np.ndarray, nodata: float) -> Any:
    """``data`` as a DataArray on ``like``'s grid (its y and x coordinates and CRS)."""
    import xarray as xr

    y, x = like.rio.y_dim, like.rio.x_dim
    out = xr.DataArray(data, dims=(y, x), coords={y: like[y].values, x: like[x].values}, name="value")
    return out.rio.write_crs(like.rio.crs).rio.write_nodata(nodata, encoded=False)
