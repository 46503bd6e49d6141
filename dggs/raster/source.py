"""Rasters read block by block: any file GDAL reads (through rasterio) or an xarray DataArray with a CRS.

:func:`open_raster` checks what the binning needs (a CRS, the bands, the
window) and names what is wrong; :meth:`RasterSource.blocks` yields the
raster in windows of at most ``size`` x ``size`` pixels, each with its data
(bands, rows, cols) and the mask of pixels holding data in every band.
Part of :mod:`dggs.raster` (the optional extra ``raster``).
"""

from __future__ import annotations

import contextlib
import os
from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from dggs.errors import DggsValueError

__all__ = ["RasterError", "RasterSource", "Block", "open_raster"]


class RasterError(DggsValueError):
    """A raster that cannot be binned: missing, not a raster, no CRS, a band or window out of range."""


@dataclass
class Block:
    """One window of a raster: its place, its data (bands, rows, cols) and where every band has data."""

    row: int
    col: int
    data: np.ndarray
    valid: np.ndarray

    @property
    def shape(self) -> tuple[int, int]:
        """(rows, cols)."""
        return self.valid.shape


@dataclass
class RasterSource:
    """A raster's grid (``crs``, affine ``transform``, size), its bands and how to read a window."""

    name: str
    crs: Any
    transform: Any
    height: int
    width: int
    bands: list[int]
    nodata: list[Any]
    row0: int
    col0: int
    reader: Any
    dtype: Any

    def blocks(self, size: int) -> Iterator[Block]:
        """The raster (its window) in blocks of at most ``size`` x ``size`` pixels, row by row."""
        for r in range(0, self.height, size):
            for c in range(0, self.width, size):
                rows, cols = min(size, self.height - r), min(size, self.width - c)
                data, mask = self.reader(self.row0 + r, self.col0 + c, rows, cols)
                yield Block(r, c, data, mask)

    @property
    def pixels(self) -> int:
        """Pixels in the window."""
        return self.height * self.width


def _valid(data: np.ndarray, nodata: Sequence[Any], masks: np.ndarray | None) -> np.ndarray:
    """Pixels holding data in every band: not nodata, not NaN, not masked."""
    ok = np.ones(data.shape[1:], dtype=bool)
    for b in range(data.shape[0]):
        band = data[b]
        if nodata[b] is not None and not (isinstance(nodata[b], float) and np.isnan(nodata[b])):
            ok &= band != nodata[b]
        if band.dtype.kind == "f":  # NaN is never data
            ok &= ~np.isnan(band)
        if masks is not None:
            ok &= masks[b] > 0
    return ok


def _refuse_infinity(data: np.ndarray, valid: np.ndarray, bands: list[int], name: str, row: int, col: int) -> None:
    """Refuse a pixel holding +-inf as data (not nodata, not masked), as every other ingest refuses infinity.

    Raises
    ------
    RasterError
        Naming the raster, the band, the pixel (row, column of the raster) and the value.
    """
    if data.dtype.kind != "f":
        return
    bad = np.isinf(data) & valid[None]
    if bad.any():
        b, r, c = (int(i[0]) for i in np.nonzero(bad))
        raise RasterError(
            f"{name} has {float(data[b, r, c])!r} at row {row + r}, column {col + c} of band {bands[b]}: infinity is "
            "not a value (give it as nodata=, or mask it)"
        )


def _check_nodata(nodata: Any) -> Any:
    """``nodata`` as given when it is None or one real number.

    Raises
    ------
    RasterError
        Anything else (a string, a list, a bool), naming it.
    """
    if nodata is None:
        return None
    if isinstance(nodata, (bool, np.bool_)) or not isinstance(nodata, (int, float, np.integer, np.floating)):
        raise RasterError(f"nodata {nodata!r} must be one number (the value of pixels without data) or None")
    return nodata


def _window(window: Any, height: int, width: int, name: str) -> tuple[int, int, int, int]:
    """``(row_off, col_off, rows, cols)`` of a window: None (the whole raster), a rasterio Window or 4 ints."""
    if window is None:
        return 0, 0, height, width
    parts: tuple[Any, ...]
    if hasattr(window, "row_off"):
        parts = (window.row_off, window.col_off, window.height, window.width)
    else:
        try:
            parts = tuple(window)
        except TypeError:
            parts = ()
    try:
        whole = len(parts) == 4 and all(not isinstance(p, (bool, str, bytes)) and float(p).is_integer() for p in parts)
    except (TypeError, ValueError, OverflowError):
        whole = False
    if not whole:
        raise RasterError(f"window {window!r} of {name} is not (row_off, col_off, height, width) in whole pixels")
    r, c, h, w = (int(p) for p in parts)
    if r < 0 or c < 0 or h < 1 or w < 1 or r + h > height or c + w > width:
        raise RasterError(f"window {window!r} is outside {name} ({height} rows x {width} columns)")
    return r, c, h, w


def _bands(band: Any, count: int, name: str) -> list[int]:
    if band is None:
        return list(range(1, count + 1))
    if isinstance(band, (int, np.integer)) and not isinstance(band, (bool, np.bool_)):
        chosen = [band]
    elif isinstance(band, (list, tuple, np.ndarray)):
        chosen = list(band)
    else:
        raise RasterError(f"band {band!r} must be a band number (1-based) or a list of them")
    for b in chosen:
        if isinstance(b, (bool, np.bool_)) or not isinstance(b, (int, np.integer)) or not 1 <= b <= count:
            raise RasterError(f"band {b!r} is out of range: {name} has bands 1..{count}")
    if not chosen:
        raise RasterError(f"no band chosen of {name}")
    return [int(b) for b in chosen]


#: GDAL's block cache while dggs reads, unless the user sets GDAL_CACHEMAX: each window is read once, in
#: order, so cached blocks are never read again, and GDAL's default (5 % of the machine's memory) grew a
#: process binning a 1.8 GB raster by 1.2 GB.
BLOCK_CACHE_BYTES = 64 * 2**20


def _small_block_cache() -> Any:
    import rasterio
    from rasterio.env import getenv, hasenv

    if "GDAL_CACHEMAX" in os.environ or (hasenv() and "GDAL_CACHEMAX" in getenv()):
        return contextlib.nullcontext()
    return rasterio.Env(GDAL_CACHEMAX=BLOCK_CACHE_BYTES)


def open_raster(source: Any, band: Any = None, nodata: Any = None, window: Any = None) -> RasterSource:
    """Open a raster file (path) or take an xarray DataArray (with a CRS, through rioxarray).

    Raises
    ------
    RasterError
        A missing file, one GDAL cannot read as a raster, no CRS, a band or window out of range
        (each naming the file and the value).
    """
    nodata = _check_nodata(nodata)
    if hasattr(source, "dims") and hasattr(source, "values"):
        return _from_xarray(source, band, nodata, window)
    import rasterio
    from rasterio.errors import RasterioIOError

    name = os.fspath(source) if isinstance(source, (str, os.PathLike)) else None
    if name is None:
        raise RasterError(f"a raster must be a file path or an xarray DataArray, not a {type(source).__name__}")
    if not os.path.exists(name) and "://" not in name and not name.startswith("/vsi"):
        raise RasterError(f"no raster file {name!r}")
    try:
        with _small_block_cache():
            dataset = rasterio.open(name)
    except RasterioIOError as exc:
        raise RasterError(f"{name} is not a raster GDAL can read ({exc})") from None
    if dataset.crs is None:
        dataset.close()
        raise RasterError(f"{name} has no CRS: set one (e.g. gdal_edit.py -a_srs EPSG:4326) to bin it")
    try:
        bands = _bands(band, dataset.count, name)
        r0, c0, h, w = _window(window, dataset.height, dataset.width, name)
    except RasterError:
        dataset.close()
        raise
    values = [dataset.nodata if nodata is None else nodata] * len(bands)
    # GDAL's mask of a band is its own mask band (per dataset, alpha) or one made from the file's nodata value;
    # nodata= replaces the file's nodata value, never a mask band (docs/raster.md: masks are honoured)
    own_masks = [_real_mask(dataset.mask_flag_enums[b - 1]) for b in bands]
    read_masks = nodata is None or any(own_masks)

    def read(row: int, col: int, rows: int, cols: int) -> tuple[np.ndarray, np.ndarray]:
        from rasterio.windows import Window

        win = Window(col, row, cols, rows)
        try:
            with _small_block_cache():
                data = dataset.read(bands, window=win)
                masks = dataset.read_masks(bands, window=win) if read_masks else None
        except Exception as exc:  # noqa: BLE001 - GDAL's errors on a damaged file: name it
            raise RasterError(f"{name} cannot be read at rows {row}..{row + rows} ({exc})") from None
        if masks is not None and nodata is not None:
            for i, own in enumerate(own_masks):
                if not own:  # made from the file's nodata value, which nodata= replaces
                    masks[i] = 255
        valid = _valid(data, values, masks)
        _refuse_infinity(data, valid, bands, name, row, col)
        return data, valid

    from pyproj import CRS

    crs = CRS.from_user_input(dataset.crs.to_wkt())
    return RasterSource(name, crs, _shifted(dataset.transform, r0, c0), h, w, bands, values, r0, c0, read,
                        dataset.dtypes[0])


def _real_mask(flags: Any) -> bool:
    """Whether GDAL's mask flags of a band name a mask of its own (a mask band or alpha), not one made from nodata."""
    from rasterio.enums import MaskFlags

    return bool({MaskFlags.per_dataset, MaskFlags.alpha} & set(flags)) and MaskFlags.nodata not in flags


def _shifted(transform: Any, row: int, col: int) -> Any:
    """The affine transform of a window starting at (row, col)."""
    from affine import Affine

    return transform @ Affine.translation(col, row)


def _from_xarray(array: Any, band: Any, nodata: Any, window: Any) -> RasterSource:
    try:
        import rioxarray  # noqa: F401 - registers .rio
    except ImportError as exc:  # pragma: no cover - the raster extra installs it
        raise RasterError("an xarray raster needs rioxarray: pip install 'dggs[raster]'") from exc
    name = f"DataArray {array.name!r}" if array.name is not None else "the DataArray"
    array = _spatial_dims(array, name)
    crs = array.rio.crs
    if crs is None:
        raise RasterError(f"{name} has no CRS: set one with .rio.write_crs('EPSG:4326')")
    for dim in (array.rio.y_dim, array.rio.x_dim):
        _check_even(array, dim, name)
    data = array if "band" in array.dims else array.expand_dims(band=[1])
    extra = [d for d in data.dims if d not in ("band", array.rio.y_dim, array.rio.x_dim)]
    if extra:
        raise RasterError(f"{name} has dimensions {extra} besides band, y and x: select one slice first")
    data = data.transpose("band", array.rio.y_dim, array.rio.x_dim)
    bands = _bands(band, data.sizes["band"], name)
    given = array.rio.nodata if nodata is None else nodata
    values = [given] * len(bands)
    height, width = data.sizes[array.rio.y_dim], data.sizes[array.rio.x_dim]
    r0, c0, h, w = _window(window, height, width, name)

    def read(row: int, col: int, rows: int, cols: int) -> tuple[np.ndarray, np.ndarray]:
        part = data.isel(band=[b - 1 for b in bands], **{array.rio.y_dim: slice(row, row + rows),
                                                         array.rio.x_dim: slice(col, col + cols)})
        block = np.asarray(part.values)
        valid = _valid(block, values, None)
        _refuse_infinity(block, valid, bands, name, row, col)
        return block, valid

    from pyproj import CRS

    transform = _shifted(array.rio.transform(), r0, c0)
    return RasterSource(name, CRS.from_user_input(crs.to_wkt()), transform, h, w, bands, values, r0, c0, read,
                        data.dtype)


#: Dimension names read as (y, x) when rioxarray finds no x and y: the CF names of latitude and longitude.
_LATLON_DIMS = (("lat", "lon"), ("latitude", "longitude"), ("Lat", "Lon"), ("Latitude", "Longitude"), ("LAT", "LON"))


def _spatial_dims(array: Any, name: str) -> Any:
    """``array`` with its spatial dimensions known to rioxarray: x/y, or lat/lon (and spellings) set as them.

    Raises
    ------
    RasterError
        No dimension pair rioxarray or this list knows (naming the dimensions).
    """
    from rioxarray.exceptions import MissingSpatialDimensionError

    try:
        array.rio.y_dim, array.rio.x_dim  # noqa: B018 - raises when rioxarray finds none
        return array
    except MissingSpatialDimensionError:
        pass
    for y, x in _LATLON_DIMS:
        if y in array.dims and x in array.dims:
            return array.rio.set_spatial_dims(x_dim=x, y_dim=y)
    raise RasterError(
        f"{name} has dimensions {list(array.dims)}: no x/y or lat/lon pair to bin; name them, or call "
        ".rio.set_spatial_dims(x_dim=..., y_dim=...)"
    )


#: How far from even a coordinate's steps may be, as a fraction of the step (float32 coordinates' rounding).
EVEN_TOLERANCE = 1e-3


def _check_even(array: Any, dim: str, name: str) -> None:
    """Refuse unevenly spaced coordinates: one affine transform (rioxarray's) cannot draw their pixels.

    Raises
    ------
    RasterError
        Naming the dimension and the first step that differs.
    """
    if dim not in array.coords or array.sizes[dim] < 3:
        return
    values = np.asarray(array[dim].values, dtype=np.float64)
    steps = np.diff(values)
    step = (values[-1] - values[0]) / (values.size - 1)
    off = np.abs(steps - step) > EVEN_TOLERANCE * abs(step)
    if step == 0 or off.any():
        i = int(np.flatnonzero(off)[0]) if off.any() else 0
        raise RasterError(
            f"{name}'s {dim} coordinates are not evenly spaced ({values[i]!r} to {values[i + 1]!r} is a step of "
            f"{steps[i]!r}, the mean step {step!r}): a raster's pixels are one size; regrid it (e.g. .interp) first"
        )
