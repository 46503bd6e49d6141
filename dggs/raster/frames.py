"""Partials finished into the table of :func:`dggs.raster.raster_to_cells`, and that table as xarray.

:func:`weighted_frame` turns the partials of a whole raster (added up over
its blocks, in memory or in a store) into one row per cell; :func:`center_frame`
the cells and values of ``mode="center"``; :func:`to_xarray` a table into an
xdggs-ready Dataset.  The one place the output columns are named, so that a
store ingest and ``raster_to_cells`` give the same rows, to the last bit.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from dggs.index.ids import int_to_str
from dggs.index.measure import cell_area
from dggs.raster.stats import Partials

__all__ = ["value_names", "weighted_frame", "center_frame", "to_xarray", "GRID_NAME"]

#: The grid's name in xdggs (:data:`dggs.xdggs.GRID_NAME`, which imports xdggs: repeated here, checked by a test).
GRID_NAME = "dggs_split26"


def value_names(bands: list[int]) -> list[str]:
    """``["value"]`` for one band, else ``band_<n>`` each.

    Examples
    --------
    >>> value_names([1]), value_names([1, 3])
    (['value'], ['band_1', 'band_3'])
    """
    return ["value"] if len(bands) == 1 else [f"band_{b}" for b in bands]


def weighted_frame(parts: Partials, bands: list[int], level: int, mode: str, as_str: bool) -> Any:
    """One row per cell with data: ``cell_id``, [``cell``], the values of ``mode``, ``coverage``."""
    import pandas as pd

    keep = parts.covered > 0
    cells = parts.cells[keep]
    columns: dict[str, Any] = {"cell_id": cells.astype(np.int64)}
    if as_str:
        columns["cell"] = np.asarray(int_to_str(cells), dtype=object)
    covered = parts.covered[keep]
    if mode in ("mode", "fractions"):
        columns.update(_classes(parts, cells, covered, mode))
    else:
        for i, name in enumerate(value_names(bands)):
            if mode == "mean":
                columns[name] = parts.sums[i][keep] / covered
            elif mode == "sum":
                columns[name] = parts.sums[i][keep]
            elif mode == "min":
                columns[name] = parts.low[i][keep]
            elif mode == "max":
                columns[name] = parts.high[i][keep]
            else:
                columns[name] = parts.count[keep]
    # a cell's pieces add up to its area within the pieces' tolerance (docs/raster.md): never more than whole
    columns["coverage"] = np.minimum(covered / float(cell_area(level, unit="m^2")), 1.0)
    return pd.DataFrame(columns)


def _classes(parts: Partials, cells: np.ndarray, covered: np.ndarray, mode: str) -> dict[str, Any]:
    """``value`` (the class covering most, ties to the lowest) or one ``class_<v>`` share column a class."""
    c = parts.classes
    values, klass = np.unique(c["value"], return_inverse=True)
    row = np.searchsorted(cells, c["cell"])
    ok = (row < cells.shape[0]) & (cells[np.minimum(row, cells.shape[0] - 1)] == c["cell"])
    table = np.zeros((cells.shape[0], values.shape[0]))
    np.add.at(table, (row[ok], klass[ok]), c["area"][ok])
    if mode == "mode":
        return {"value": values[np.argmax(table, axis=1)] if values.size else np.empty(0)}
    return {f"class_{_label(v)}": table[:, j] / covered for j, v in enumerate(values.tolist())}


def _label(value: Any) -> str:
    return str(int(value)) if float(value).is_integer() else str(value)


def center_frame(cells: np.ndarray, values: np.ndarray, bands: list[int], as_str: bool) -> Any:
    """``mode="center"``: one row per cell (any order in), in id order: ``cell_id``, [``cell``], the values."""
    import pandas as pd

    order = np.argsort(cells, kind="stable")
    cells, values = cells[order], values[:, order]
    columns: dict[str, Any] = {"cell_id": cells.astype(np.int64)}
    if as_str:
        columns["cell"] = np.asarray(int_to_str(cells), dtype=object)
    for i, name in enumerate(value_names(bands)):
        columns[name] = values[i]
    return pd.DataFrame(columns)


def to_xarray(frame: Any, level: int) -> Any:
    """A table of ``raster_to_cells`` as an ``xarray.Dataset`` that ``xdggs.decode`` reads.

    Dimension ``cells``; coordinate ``cell_ids`` (uint64) with the grid's
    attributes (``grid_name``, ``level``; :mod:`dggs.xdggs`), and ``cell``
    (the string ids) if the table has them; one variable per other column.
    """
    import xarray as xr

    ids = frame["cell_id"].to_numpy().astype(np.uint64)
    coords: dict[str, Any] = {"cell_ids": ("cells", ids, {"grid_name": GRID_NAME, "level": int(level)})}
    if "cell" in frame:
        coords["cell"] = ("cells", frame["cell"].to_numpy(dtype=str))
    data = {name: ("cells", frame[name].to_numpy()) for name in frame.columns if name not in ("cell_id", "cell")}
    ds = xr.Dataset(data, coords=coords)
    if "coverage" in ds:
        ds["coverage"].attrs["long_name"] = "share of the cell's area under pixels with data"
    return ds
