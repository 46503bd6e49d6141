"""Rasters on equal-area cells: exact area-weighted binning of GeoTIFF, COG, NetCDF and xarray data.

``raster_to_cells(source, level, mode=...)`` reads a raster block by block and
gives one row per cell: its id, the value of each band and the share of the
cell covered by pixels with data.  The weighted modes weigh each pixel by the
true (ellipsoidal) area it shares with the cell, found by cutting the pixel
along the cells' edges in Snyder's face planes, where cells are triangles
with straight edges and areas are true areas (:mod:`dggs.index._pixels`);
``"center"`` takes the pixel under each cell's centre.  docs/raster.md gives
each mode's formula and the error bounds.  Needs the extra ``raster``
(rasterio, rioxarray): ``pip install 'dggs[raster]'``.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from typing import Any

import numpy as np

from dggs.errors import DggsValueError
from dggs.index._checks import check_level, is_choice
from dggs.raster.blocks import each_block, tidy_classes, windows
from dggs.raster.burn import cells_to_raster
from dggs.raster.frames import center_frame, to_xarray, weighted_frame
from dggs.raster.grid import to_wgs84
from dggs.raster.pieces import block_pieces
from dggs.raster.source import RasterError, RasterSource, open_raster
from dggs.raster.stats import Partials, block_partials, combine, shared

__all__ = ["raster_to_cells", "cells_to_raster", "MODES", "OUTPUTS", "RasterError"]

#: The modes of :func:`raster_to_cells`.
MODES = ("center", "mean", "sum", "min", "max", "count", "mode", "fractions")
#: What :func:`raster_to_cells` returns: a pandas DataFrame or an xarray Dataset.
OUTPUTS = ("pandas", "xarray")


def raster_to_cells(
    source: Any,
    level: int,
    *,
    mode: str = "mean",
    band: int | list[int] | None = None,
    nodata: Any = None,
    window: Any = None,
    density: bool = False,
    as_str: bool = False,
    block_size: int = 512,
    progress: bool | Callable[[int], Any] | None = None,
    to: str = "pandas",
) -> Any:
    """The cells of ``level`` under a raster, with each band's value by ``mode`` and their covered share.

    Parameters
    ----------
    source : str, path or xarray.DataArray
        Any raster GDAL reads (GeoTIFF, COG, NetCDF, VRT, ...), in any CRS, or
        a DataArray with a CRS (rioxarray's ``.rio``), dims (band,) y, x.
    level : int
        The cells' level (``dggs.cell_area(level)``).
    mode : str
        ``"mean"`` (default): the mean of the pixels weighted by the area each
        shares with the cell; ``"sum"``: each pixel's value shared out by area
        (counts; with ``density=True`` values per m², times area), so the cells
        add up to the raster's total; ``"min"``, ``"max"``, ``"count"``: of the
        pixels with data that meet the cell; ``"mode"``: the class covering
        most of the cell; ``"fractions"``: each class's share of the covered
        area (one column a class, ``class_<value>``); ``"center"``: the pixel
        under the cell's centre (fast; what other tools do).
    band : int or list of int, optional
        Bands (1-based), default all; ``"mode"`` and ``"fractions"`` take one.
    nodata : number, optional
        The value of pixels without data (default the raster's own).
    window : (row_off, col_off, height, width) or rasterio Window, optional
        Only this part of the raster.
    density : bool
        For ``"sum"``: values are per m² (multiplied by the shared area), not per pixel.
    as_str : bool
        Add the string ids as column ``cell``.
    block_size : int
        Pixels a block side: the raster is read and cut a block at a time, on all cores.
    progress : bool or callable, optional
        A bar of the blocks on stderr: ``None`` (default) on a terminal once the work has run 2 s, ``True``
        always, ``False`` never; a callable is given the blocks done (:mod:`dggs.storage.progress`).
    to : {"pandas", "xarray"}
        ``"xarray"``: the same table as an ``xarray.Dataset`` on dimension
        ``cells``, its ``cell_ids`` coordinate (uint64) carrying the grid's
        attributes, so that ``xdggs.decode`` reads it after ``import dggs.xdggs``.

    Returns
    -------
    pandas.DataFrame or xarray.Dataset
        One row per cell holding data, in id order: ``cell_id`` (int64), ``cell``
        (str, with ``as_str``), ``value`` (one band) or ``band_<n>`` (several),
        or the ``class_<value>`` columns, and ``coverage`` (the share of the
        cell's area under pixels with data; not for ``"center"``).

    Raises
    ------
    RasterError
        A missing or unreadable file, a non-raster, no CRS, a band or window out of range.
    LevelError
        ``level`` is not 0..MAX_LEVEL.
    DggsValueError
        An unknown ``mode`` or ``to``, several bands for ``"mode"``/``"fractions"``, a bad ``block_size``.

    Examples
    --------
    >>> import numpy as np, xarray as xr, rioxarray
    >>> grid = xr.DataArray(np.ones((2, 2)), dims=("y", "x"), coords={"y": [1.5, 0.5], "x": [0.5, 1.5]})
    >>> grid = grid.rio.write_crs("EPSG:4326")
    >>> table = raster_to_cells(grid, 5, mode="sum")
    >>> round(float(table["value"].sum()), 9)
    4.0
    >>> raster_to_cells(grid, 5, to="xarray")["cell_ids"].attrs  # xdggs.decode reads it
    {'grid_name': 'dggs_split26', 'level': 5}
    """
    if to not in OUTPUTS:
        raise DggsValueError(f"to={to!r} is not one of {', '.join(map(repr, OUTPUTS))}")
    level, src = open_checked(source, level, mode, band, nodata, window, block_size)
    from dggs.storage.progress import Bar

    parts = []
    with Bar(progress, total=len(windows(src, block_size)), unit="blocks", desc="binning raster") as bar:
        for part in block_results(src, level, mode, density, block_size):
            if part is not None:
                parts.append(part)
            bar.update(1)
    frame = finish(parts, src.bands, level, mode, as_str)
    return frame if to == "pandas" else to_xarray(frame, level)


def open_checked(source: Any, level: int, mode: str, band: Any, nodata: Any, window: Any, block_size: int) -> tuple[
    int, RasterSource
]:
    """The arguments of :func:`raster_to_cells` checked, and the raster opened (the errors it documents)."""
    level = check_level(level)
    if not is_choice(mode, MODES):
        raise DggsValueError(f"mode {mode!r} is not one of {', '.join(MODES)}")
    if isinstance(block_size, bool) or not isinstance(block_size, int) or block_size < 1:
        raise DggsValueError(f"block_size must be a whole number of pixels >= 1, not {block_size!r}")
    src = open_raster(source, band, nodata, window)
    if mode in ("mode", "fractions") and len(src.bands) != 1:
        raise DggsValueError(f"mode {mode!r} takes one band, not {len(src.bands)}: pass band=")
    return level, src


def block_results(src: RasterSource, level: int, mode: str, density: bool, block_size: int, skip: int = 0) -> Iterator[
    Any
]:
    """Each block's partials (``"center"``: its cells and their values), in block order from block ``skip``.

    None for a block with no cell; :func:`finish` makes the table of them.
    ``CellStore.ingest_raster`` commits them a block at a time.
    """
    transformer = to_wgs84(src.crs)

    def one(block: Any) -> Any:
        if mode == "center":
            return _center_block(src, transformer, block, level, mode, density)
        return tidy_classes(_weighted_block(src, transformer, block, level, mode, density))

    yield from each_block(src, block_size, one, skip)


def finish(parts: list[Any], bands: list[int], level: int, mode: str, as_str: bool) -> Any:
    """The table of :func:`raster_to_cells` from the results of :func:`block_results` (Nones left out)."""
    if mode == "center":
        cells = np.concatenate([p[0] for p in parts]) if parts else np.empty(0, np.uint64)
        values = np.concatenate([p[1] for p in parts], axis=1) if parts else np.empty((len(bands), 0))
        return center_frame(cells, values, bands, as_str)
    return weighted_frame(combine(parts, len(bands)), bands, level, mode, as_str)


def _weighted_block(src: RasterSource, transformer: Any, block: Any, level: int, mode: str, density: bool) -> Partials | None:
    pixel, cell, area, split = block_pieces(src, transformer, block, level)
    if not pixel.size:
        return None
    rows, cols = block.shape
    total = np.bincount(pixel, weights=area, minlength=rows * cols)
    keep = shared(pixel, cell, area, total, _cell_m2(level))  # points and edges in common are no shared area
    if not keep.all():
        pixel, cell, area = pixel[keep], cell[keep], area[keep]
        if not pixel.size:
            return None
    values = block.data.reshape(block.data.shape[0], rows * cols)
    return block_partials(pixel, cell, area, total, values, mode, density, split=split)


def _cell_m2(level: int) -> float:
    from dggs.index.measure import cell_area

    return float(cell_area(level, unit="m^2"))


def _center_block(src: RasterSource, transformer: Any, block: Any, level: int, mode: str, density: bool) -> Any:
    from dggs.raster.center import centre_values

    return centre_values(src, transformer, block, level)
