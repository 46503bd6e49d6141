"""Scale-out on Dask: bin and roll up data larger than one machine.

Optional extra: ``pip install 'dggs[dask]'``.  The same code runs on a laptop
(threads or a ``LocalCluster``) or on a remote ``dask.distributed`` scheduler:
dggs adds a cell column per partition with ``map_partitions`` (vectorized
numpy inside), rolls cells up to any coarser level by id prefix (a string
slice, so no geometry is needed), and writes Parquet partitioned by base
cell (face letter) so that later queries read only the faces they need.

When to use which:

* :class:`dggs.storage.CellStore` (SQLite): one machine, up to a few hundred
  million rows, interactive queries (prefix range scans, disks, polygons),
  crash-safe incremental ingest.
* Dask + Parquet: data that does not fit one machine or one disk, batch
  roll-ups, a cluster you already run.  Load the rolled-up result into a
  CellStore for interactive use.

Examples
--------
>>> import pandas as pd, dask.dataframe as dd
>>> from dggs.dask import add_cells, aggregate
>>> pdf = pd.DataFrame({"lat": [51.05, 51.06, -33.9], "lng": [-114.07, -114.08, 18.4], "n": [1.0, 2.0, 5.0]})
>>> ddf = add_cells(dd.from_pandas(pdf, npartitions=2), level=9)
>>> aggregate(ddf, 3, "n", stats=("count", "sum")).compute().sort_index()["sum"].tolist()
[3.0, 5.0]
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from typing import Any

import numpy as np

from dggs.errors import DggsValueError
from dggs.index._checks import check_level
from dggs.index.ids import int_to_str
from dggs.index.points import latlng_to_cell

try:  # the optional extra
    import dask.dataframe as dd
    import pandas as pd
except ImportError as exc:  # pragma: no cover - exercised only without the extra
    raise ImportError("dggs.dask needs the 'dask' extra: pip install 'dggs[dask]'") from exc

__all__ = ["add_cells", "aggregate", "to_parquet", "read_parquet", "cells_partition"]

_STATS = ("count", "sum", "mean", "min", "max")
_STRING = "string"  # pandas' string dtype: what Dask and Parquet carry natively


def cells_partition(df: pd.DataFrame, level: int, lat: str, lng: str, column: str) -> pd.DataFrame:
    """Add a ``column`` of cell ids to one pandas partition (vectorized).

    Raises
    ------
    CoordinateError
        If a coordinate is NaN, infinite or out of range (names the index).
    """
    out = df.copy()
    ids = latlng_to_cell(df[lat].to_numpy(np.float64), df[lng].to_numpy(np.float64), level) if len(df) else []
    out[column] = pd.Series(ids, index=df.index, dtype=_STRING)
    return out


def add_cells(ddf: dd.DataFrame, level: int, lat: str = "lat", lng: str = "lng", column: str = "cell") -> dd.DataFrame:
    """A dask DataFrame with a cell-id column for each row's (lat, lng) at ``level``.

    Raises
    ------
    DggsValueError
        A missing coordinate column (bad coordinates raise
        :class:`dggs.CoordinateError` when the partition is computed).
    """
    level = check_level(level)
    for col in (lat, lng):
        if col not in ddf.columns:
            raise DggsValueError(f"column {col!r} is not in the dataframe (columns: {list(ddf.columns)})")
    meta = ddf._meta.assign(**{column: pd.Series([], dtype=_STRING)})
    out: dd.DataFrame = ddf.map_partitions(cells_partition, level, lat, lng, column, meta=meta)
    return out


def aggregate(
    ddf: dd.DataFrame,
    level: int,
    column: str | None = None,
    stats: Sequence[str] = _STATS,
    cell: str = "cell",
) -> dd.DataFrame:
    """Roll rows up to cells at a coarser ``level`` (id prefixes) with summary stats.

    Parameters
    ----------
    ddf : dask DataFrame
        With a cell-id column (see :func:`add_cells`) at a level >= ``level``.
    level : int
        Target level.
    column : str, optional
        Value column to summarise; without it only ``count`` is computed.
    stats : sequence of {"count", "sum", "mean", "min", "max"}

    Returns
    -------
    dask DataFrame indexed by cell id at ``level``, one column per stat.

    Raises
    ------
    DggsValueError
        If a stat is unknown, or the ``cell`` or ``column`` column is not in the frame.
    LevelError
        If ``level`` is outside ``0..MAX_LEVEL``.
    """
    level = check_level(level)
    bad = [s for s in stats if s not in _STATS]
    if bad:
        raise DggsValueError(f"stat {bad[0]!r} is not one of {', '.join(_STATS)}")
    if cell not in ddf.columns:
        raise DggsValueError(f"column {cell!r} is not in the dataframe")
    parent = ddf[cell].str.slice(0, level + 1)
    if column is None:
        grouped = ddf.assign(_one=1).assign(_parent=parent).groupby("_parent")["_one"].count()
        counts: dd.DataFrame = grouped.to_frame("count")
        return counts
    if column not in ddf.columns:
        raise DggsValueError(f"column {column!r} is not in the dataframe (columns: {list(ddf.columns)})")
    out: dd.DataFrame = ddf.assign(_parent=parent).groupby("_parent")[column].agg(list(stats))
    out.index = out.index.rename("cell")
    return out


def _write_faces(pdf: pd.DataFrame, path: str, cell: str, part: int, densify: int | None, kwargs: dict) -> int:
    """Write one partition as GeoParquet files ``path/face=X/part.{part}.parquet``; return the rows written."""
    from dggs.arrow import cells_to_table, write_geoparquet

    if not len(pdf):
        return 0
    ids = pdf[cell]
    if ids.dtype.kind in "iu":
        ids = pd.Series(int_to_str(ids.to_numpy(np.uint64)), index=pdf.index)
    faces = ids.astype(str).str.slice(0, 1).to_numpy()
    props = pdf.drop(columns=[cell])
    for face in np.unique(faces):
        rows = np.flatnonzero(faces == face)
        table = cells_to_table(pdf[cell].iloc[rows].to_numpy(), props.iloc[rows].reset_index(drop=True), densify)
        if cell != "cell":
            table = table.rename_columns([cell if c == "cell" else c for c in table.column_names])
        folder = os.path.join(path, f"face={face}")
        os.makedirs(folder, exist_ok=True)
        write_geoparquet(table, os.path.join(folder, f"part.{part}.parquet"), **kwargs)
    return len(pdf)


def to_parquet(
    ddf: dd.DataFrame, path: str, cell: str = "cell", *, geometry: bool = True, densify: int | None = 16,
    **kwargs: Any,
) -> None:
    """Write Parquet partitioned by base cell (``face=A`` ... ``face=T`` folders).

    With ``geometry`` (the default) every file is GeoParquet 1.1, written by
    pyarrow from each partition (:func:`dggs.arrow.cells_to_table`): the
    string id column ``cell``, an int64 ``cell_id`` column, the other
    columns, a ``bbox`` covering struct and a WKB ``geometry`` column (the
    cell polygon, ``densify`` points per curved edge), with ``geo``
    metadata; each file is written under a temporary name and renamed when
    complete.  ``geopandas.read_parquet(path)``, DuckDB's
    ``read_parquet(path || '/*/*.parquet', hive_partitioning = true)`` and
    :func:`read_parquet` read it.  ``kwargs`` go to
    ``pyarrow.parquet.write_table``.  A frame indexed by cell (the output of
    :func:`aggregate`) is written with its index as the ``cell`` column.

    ``geometry=False`` writes plain Parquet through Dask (``kwargs`` go to
    ``dask.dataframe.to_parquet``).

    Raises
    ------
    DggsValueError
        If the ``cell`` column is missing, or (with ``geometry``) a column is named like one the
        GeoParquet output adds (``cell_id``, ``bbox``, ``geometry``, ``face``).
    """
    if cell not in ddf.columns and ddf.index.name == cell:
        ddf = ddf.reset_index()
    if cell not in ddf.columns:
        raise DggsValueError(f"column {cell!r} is not in the dataframe")
    if not geometry:
        ddf.assign(face=ddf[cell].astype(str).str.slice(0, 1)).to_parquet(path, partition_on=["face"], **kwargs)
        return
    for name in ("cell_id", "bbox", "geometry", "face"):
        if name in ddf.columns and name != cell:
            raise DggsValueError(f"column {name!r} would clash with a column GeoParquet output adds; rename it")
    import dask

    os.makedirs(path, exist_ok=True)
    parts = ddf.to_delayed()
    write = dask.delayed(_write_faces, pure=False)
    dask.compute(*(write(part, path, cell, i, densify, kwargs) for i, part in enumerate(parts)))


def read_parquet(path: str, faces: Sequence[str] | None = None, **kwargs: Any) -> dd.DataFrame:
    """Read what :func:`to_parquet` wrote, optionally only some base cells (faces)."""
    filters = [("face", "in", list(faces))] if faces else None
    ddf: dd.DataFrame = dd.read_parquet(path, filters=filters, **kwargs)
    return ddf
