"""The jobs of :mod:`dggs.spark`: the roll-up and GeoParquet written by Spark's executors by coarse parent cell.

:func:`write_geoparquet` repartitions the frame by each row's parent id, so
each Spark partition holds whole parents, and each executor turns its Arrow
batches into :func:`dggs.arrow.cells_to_table` tables, one per parent,
written with :func:`dggs.arrow.write_geoparquet` (whole or not at all) to
``path/face=X/parent=P/part-<partition>.parquet``.  Only ids and values cross
the shuffle; the geometry is built where it is written.
"""

from __future__ import annotations

import functools
import os
from collections.abc import Iterator, Sequence
from typing import Any

import numpy as np
import pyarrow as pa

from dggs.errors import DggsValueError
from dggs.index._checks import check_level

__all__ = ["rollup", "write_geoparquet", "write_batches", "write_partitioned"]

_STATS = ("count", "sum", "mean", "min", "max")


_PARENT = "__dggs_parent"


def write_batches(batches: Iterator[Any], path: str, cell: str, level: int, densify: int | None) -> Iterator[Any]:
    """Write one partition's Arrow batches (with the parent column) as GeoParquet; yield one row: rows written.

    Rows with a NULL cell are skipped.

    Raises
    ------
    DggsValueError
        A bad id, or a column named like one the output adds (from :func:`dggs.arrow.cells_to_table`).
    """
    from dggs.arrow import cells_to_table
    from dggs.arrow import write_geoparquet as write_file

    chunks = list(batches)
    if not chunks:
        return
    table = pa.Table.from_batches(chunks)
    table = table.filter(table.column(cell).is_valid())
    try:
        from pyspark import TaskContext

        ctx = TaskContext.get()
        part = ctx.partitionId() if ctx is not None else 0
    except ImportError:  # pragma: no cover - runs inside Spark
        part = 0
    parents = np.asarray(table.column(_PARENT).to_numpy(), dtype=object)
    props = table.drop_columns([_PARENT, cell])
    for parent in np.unique(parents):
        rows = pa.array(np.flatnonzero(parents == parent))
        out = cells_to_table(table.column(cell).take(rows), props.take(rows), densify)
        if cell != "cell":
            out = out.rename_columns([cell if c == "cell" else c for c in out.column_names])
        folder = os.path.join(path, f"face={parent[0]}", *([f"parent={parent}"] if level > 0 else []))
        os.makedirs(folder, exist_ok=True)
        write_file(out, os.path.join(folder, f"part-{part:05d}.parquet"))
    yield pa.RecordBatch.from_arrays([pa.array([table.num_rows], pa.int64())], names=["rows"])


def write_partitioned(df: Any, parent: Any, path: str, cell: str, level: int, densify: int | None) -> int:
    """Repartition ``df`` by the string column ``parent`` and write each partition's parents; return the rows."""
    from pyspark.sql import functions as F

    os.makedirs(path, exist_ok=True)
    keyed = df.withColumn(_PARENT, parent).repartition(_PARENT)
    written = keyed.mapInArrow(functools.partial(write_batches, path=path, cell=cell, level=level, densify=densify),
                               "rows long")
    total = written.agg(F.sum("rows")).first()
    return int(total[0] or 0) if total is not None else 0


def rollup(df: Any, level: int, cell: str = "cell", values: Sequence[str] = (),
           stats: Sequence[str] = _STATS) -> Any:
    """Roll rows up to their cells' ancestors at ``level``: ``GROUP BY dggs_cell_to_parent(cell, level)``.

    Parameters
    ----------
    df : pyspark.sql.DataFrame
        With a column ``cell`` of int64 or string ids at levels >= ``level``.
    level : int
    cell : str, default "cell"
    values : sequence of str
        Columns to summarise with ``stats`` (``count`` is always given).
    stats : sequence of {"count", "sum", "mean", "min", "max"}

    Returns
    -------
    pyspark.sql.DataFrame
        Columns ``cell`` (ids of the kind given, at ``level``), ``count`` and
        ``<value>_<stat>`` for every value and stat but count.

    Raises
    ------
    LevelError
        If ``level`` is outside 0..MAX_LEVEL.
    DggsValueError
        If a stat is unknown or a column is missing.

    Examples
    --------
    >>> rollup(spark.createDataFrame([("C401", 1.0)], "cell string, n double"), 1, values=["n"],
    ...        stats=["sum"]).collect()  # doctest: +SKIP
    [Row(cell='C4', count=1, n_sum=1.0)]
    """
    from pyspark.sql import functions as F

    from dggs.spark.columns import cell_to_parent, cell_to_parent_str

    level = check_level(level)
    bad = [s for s in stats if s not in _STATS]
    if bad:
        raise DggsValueError(f"stat {bad[0]!r} is not one of {', '.join(_STATS)}")
    for name in (cell, *values):
        if name not in df.columns:
            raise DggsValueError(f"column {name!r} is not in the dataframe (columns: {df.columns})")
    kind = dict(df.dtypes)[cell]
    parent = cell_to_parent_str if kind == "string" else cell_to_parent
    aggs = [F.count(F.lit(1)).alias("count")]
    funcs = {"sum": F.sum, "mean": F.mean, "min": F.min, "max": F.max}
    aggs += [funcs[s](v).alias(f"{v}_{s}") for v in values for s in stats if s != "count"]
    out = df.groupBy(parent(cell, level).alias("cell")).agg(*aggs)
    return out


def write_geoparquet(df: Any, path: str, level: int = 1, cell: str = "cell", densify: int | None = 16) -> int:
    """Write GeoParquet 1.1 files partitioned by each cell's ancestor at ``level``; return the rows written.

    The rows are repartitioned so that each ancestor's rows are in one Spark
    partition, and each executor writes, with pyarrow,
    ``path/face=X/parent=P/part-<partition>.parquet`` (``path/face=X/...``
    at level 0): the files of :func:`dggs.arrow.cells_to_table` (string
    ``cell``, int64 ``cell_id``, the other columns, ``bbox``, WKB
    ``geometry``).  :func:`dggs.dask.read_parquet` (``faces=`` reads only
    some faces), DuckDB's ``read_parquet(path || '/**/*.parquet',
    hive_partitioning = true)`` and geopandas read them.  ``path`` must be a
    folder every executor can write (a shared or local file system).

    Raises
    ------
    LevelError
        If ``level`` is outside 0..MAX_LEVEL.
    DggsValueError
        If the ``cell`` column is missing, or a column is named ``cell_id``, ``bbox``, ``geometry``,
        ``face`` or ``parent``.
    """
    from dggs.spark.columns import cell_to_parent_str

    level = check_level(level)
    if cell not in df.columns:
        raise DggsValueError(f"column {cell!r} is not in the dataframe (columns: {df.columns})")
    for name in ("cell_id", "bbox", "geometry", "face", "parent"):
        if name in df.columns and name != cell:
            raise DggsValueError(f"column {name!r} would clash with a column the GeoParquet output adds; rename it")
    return write_partitioned(df, cell_to_parent_str(cell, level), os.path.abspath(path), cell, level, densify)
