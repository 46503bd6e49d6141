"""The five ways in: CSV, GeoJSON, records, arrays, DataFrame.

Each function checks everything it can about its input (columns, shapes,
encoding, options) *before* the source is registered in the store, then
hands batches to :func:`dggs.storage.ingest.run_ingest`.
"""

from __future__ import annotations

import os
import uuid
from collections.abc import Iterable, Iterator, Mapping, Sequence, Sized
from pathlib import Path
from typing import Any

from dggs.errors import DggsValueError

from . import prechecks, readers, readers_arrays, readers_csv, readers_geojson, readers_vector
from .connection import Connection
from .crs import make_transformer
from .ingest import IngestOptions, IngestResult, run_ingest
from .projection import grid_locate
from .readers import RawBatch
from .sources import file_info, find_earlier_version

__all__ = ["ingest_csv", "ingest_geojson", "ingest_vector", "ingest_records", "ingest_points", "ingest_dataframe"]

Values = Sequence[str] | Mapping[str, Any] | None

# checked before the store is touched; the CLI's `dggs bin` runs them before it creates the store
check_csv, value_spec = prechecks.check_csv, prechecks.value_spec


def dtype_type(column: Any) -> str | None:
    """Return the SQL type implied by an array's dtype, or None (object arrays, lists)."""
    kind = getattr(column, "dtype", None)
    kind = kind.kind if kind is not None else None
    return {"i": "INTEGER", "u": "INTEGER", "b": "INTEGER", "f": "REAL", "U": "TEXT", "S": "TEXT"}.get(kind or "")


def _identity(store: Connection, kind: str, file: Path, name: str, replace: bool) -> dict[str, Any]:
    info = file_info(file)
    return find_earlier_version(store, kind, name, file, info, replace)


def ingest_csv(
    store: Connection,
    path: str | os.PathLike[str],
    lat: str,
    lng: str,
    values: Values,
    level: int | None,
    options: IngestOptions,
    *,
    delimiter: str = ",",
    encoding: str = "utf-8",
    merge_rows: int,
) -> IngestResult:
    """Ingest the CSV file ``path`` into ``store`` (the work of :meth:`dggs.storage.CellStore.ingest_csv`).

    Raises
    ------
    DggsValueError, StorageError
        As :func:`dggs.storage.prechecks.check_csv` says, before anything is stored.
    """
    file, names, declared = check_csv(path, lat, lng, values, delimiter, encoding)  # before the source is registered
    level = store.resolve_level(level)
    info = _identity(store, "csv", file, str(path), options.replace)
    batch_size = options.batch_size
    return run_ingest(
        store,
        key=f"file:{info['sha256']}",
        kind="csv",
        name=str(path),
        params={"format": "csv", "lat": lat, "lng": lng, "values": names, "delimiter": delimiter},
        batches=lambda skip, types: readers_csv.csv_batches(
            file, lat, lng, names, batch_size, skip, delimiter, types, encoding
        ),
        level=level,
        declared=declared,
        options=options,
        merge_rows=merge_rows,
        file_info=info,
        total=lambda: readers.count_csv_rows(file),
    )


def ingest_geojson(
    store: Connection,
    path: str | os.PathLike[str],
    values: Values,
    level: int | None,
    options: IngestOptions,
    *,
    merge_rows: int,
) -> IngestResult:
    """Ingest the GeoJSON file ``path`` (the work of :meth:`dggs.storage.CellStore.ingest_geojson`).

    Raises
    ------
    DggsValueError
        If ``options.crs`` is set (GeoJSON is WGS84 by definition) or the file is not GeoJSON.
    StorageError
        If ``path`` does not exist.
    """
    batch_size = options.batch_size
    file, features, names, declared = prechecks.check_geojson(path, values, options.crs, batch_size)
    level = store.resolve_level(level)
    info = _identity(store, "geojson", file, str(path), options.replace)
    return run_ingest(
        store,
        key=f"file:{info['sha256']}",
        kind="geojson",
        name=str(path),
        params={"format": "geojson", "values": names},
        batches=lambda skip, types: readers_geojson.geojson_batches(
            features, names, level, batch_size, skip, store.projection),
        level=level,
        declared=declared,
        options=options,
        merge_rows=merge_rows,
        file_info=info,
        total=lambda: len(features),
    )


def ingest_vector(
    store: Connection,
    path: str | os.PathLike[str],
    layer: str | int | None,
    values: Values,
    level: int | None,
    options: IngestOptions,
    *,
    merge_rows: int,
) -> IngestResult:
    """Ingest the features of a vector file's ``layer`` (the work of :meth:`dggs.storage.CellStore.ingest`).

    Raises
    ------
    DggsValueError
        If the layer cannot be read or a value column is not one of its fields.
    StorageError
        If ``path`` does not exist.
    """
    file, names, declared, crs = prechecks.check_vector(path, layer, values, options.crs)  # before registering
    level = store.resolve_level(level)
    name = str(path) if layer is None else f"{path}:{layer}"
    info = _identity(store, "vector", file, name, options.replace)
    batch_size = options.batch_size
    return run_ingest(
        store,
        key=f"file:{info['sha256']}" + ("" if layer is None else f":{layer}"),
        kind="vector",
        name=name,
        params={"format": "vector", "layer": layer, "values": names},
        batches=lambda skip, types: readers_vector.vector_batches(
            file, layer, names, level, batch_size, skip, crs, store.projection
        ),
        level=level,
        declared=declared,
        options=IngestOptions(
            options.batch_size, options.on_error, options.replace, None, options.progress, options.source
        ),
        merge_rows=merge_rows,
        file_info=info,
        total=lambda: readers_vector.feature_count(file, layer),
    )


def ingest_records(
    store: Connection,
    records: Iterable[Mapping[str, Any]],
    lat: str,
    lng: str,
    values: Values,
    level: int | None,
    options: IngestOptions,
    *,
    merge_rows: int,
) -> IngestResult:
    """Ingest an iterable of dicts into ``store`` (the work of :meth:`dggs.storage.CellStore.ingest_records`).

    Raises
    ------
    DggsValueError
        If ``records`` is a string, bytes or a single mapping instead of an iterable of dicts.
    """
    if isinstance(records, (str, bytes, Mapping)):
        raise DggsValueError(f"records must be an iterable of dicts, not {type(records).__name__}")
    level = store.resolve_level(level)
    names, declared = value_spec(values)
    source, batch_size = options.source, options.batch_size
    return run_ingest(
        store,
        key=f"records:{source}" if source is not None else f"records:{uuid.uuid4().hex}",
        kind="records",
        name=source if source is not None else "<records>",
        params={"format": "records", "lat": lat, "lng": lng, "values": names},
        batches=lambda skip, types: readers_arrays.records_batches(records, lat, lng, names, batch_size, skip),
        threaded=False,  # the iterable may belong to this thread (a sqlite3 cursor...)
        level=level,
        declared=declared,
        options=options,
        merge_rows=merge_rows,
        total=lambda: len(records) if isinstance(records, Sized) else None,
    )


def ingest_points(
    store: Connection,
    lat: Any,
    lng: Any,
    level: int | None,
    values: Mapping[str, Any] | None,
    types: Mapping[str, Any] | None,
    options: IngestOptions,
    *,
    merge_rows: int,
    cells: Any = None,
) -> IngestResult:
    """Ingest coordinate and value arrays (the work of :meth:`dggs.storage.CellStore.ingest_points`).

    Raises
    ------
    DggsValueError
        If the arrays are not one-dimensional or differ in length.
    InvalidCellError, LevelMismatchError
        A given cell that is not a valid id, or not of ``level`` (naming it and its row).
    """
    level = store.resolve_level(level)
    values = dict(values or {})
    value_spec(list(values))
    lat_a, lng_a, cols = readers_arrays.check_arrays(lat, lng, values)  # shapes, before registering
    given = None if cells is None else _given_ids(cells, len(lat_a), level)
    declared: dict[str, Any] = {}
    for name, col in cols.items():
        implied = dtype_type(values[name]) or dtype_type(col)  # a pandas Int64 column with NA comes as objects
        if implied is not None:
            declared[name] = implied
    declared.update(types or {})
    source, batch_size = options.source, options.batch_size
    ordered = readers_arrays.orderable(lat_a, lng_a)

    def batches(skip: int, types: Mapping[str, str]) -> Iterator[RawBatch]:
        # In cell order when the coordinates are numbers, so that the rows go straight into the clustered
        # table in key order (no pending table, no sort in SQLite); computed after the source is known
        # to be incomplete, the same way on a resume.
        locate = grid_locate(store.projection)
        if not ordered:
            return readers_arrays.array_batches(lat_a, lng_a, cols, batch_size, skip, located=given)
        order, located = readers_arrays.ordered_cells(lat_a, lng_a, level, make_transformer(options.crs), locate,
                                                      given)
        return readers_arrays.array_batches(lat_a, lng_a, cols, batch_size, skip, order, located)

    return run_ingest(
        store,
        key=f"arrays:{source}" if source is not None else f"arrays:{uuid.uuid4().hex}",
        kind="arrays",
        name=source if source is not None else "<arrays>",
        params={"format": "arrays", "values": list(values)},
        batches=batches,
        level=level,
        declared=declared,
        options=options,
        merge_rows=merge_rows,
        ordered=ordered,
        total=lambda: len(lat_a),
    )


def ingest_dataframe(
    store: Connection,
    df: Any,
    lat: str,
    lng: str,
    values: Values,
    level: int | None,
    types: Mapping[str, Any] | None,
    options: IngestOptions,
    *,
    merge_rows: int,
    cells: str | None = None,
) -> IngestResult:
    """Ingest the rows of a DataFrame (the work of :meth:`dggs.storage.CellStore.ingest_dataframe`).

    Raises
    ------
    DggsValueError
        If the ``lat``, ``lng`` or ``cells`` column is missing.
    """
    missing = [c for c in (lat, lng, *([] if cells is None else [cells])) if c not in df.columns]
    if missing:
        raise DggsValueError(
            f"DataFrame has no column(s) {', '.join(map(repr, missing))}; "
            f"its columns are {', '.join(map(repr, map(str, df.columns)))}"
        )
    if values is None:
        values = [str(c) for c in df.columns if c not in (lat, lng, cells)]
    names, declared = value_spec(values)
    declared = {**declared, **dict(types or {})}
    return ingest_points(
        store,
        df[lat],
        df[lng],
        level,
        {name: df[name] for name in names},  # columns, not to_numpy(): pandas NA and exact ints kept (as_column)
        declared,
        options,
        merge_rows=merge_rows,
        cells=None if cells is None else df[cells],
    )


def _given_ids(cells: Any, n: int, level: int) -> Any:
    """The points' given cells as integer ids (uint64), each checked to be a valid id of ``level``.

    Raises
    ------
    DggsValueError
        If there is not one cell a point.
    InvalidCellError
        Naming the first id that is not valid.
    LevelMismatchError
        Naming the first id of another level than ``level``, and its row.
    """
    import numpy as np

    import dggs
    from dggs.errors import LevelMismatchError

    column = readers_arrays.as_column(cells)
    if column.ndim != 1 or column.shape[0] != n:
        raise DggsValueError(f"cells has {column.size} values but lat has {n}: give one cell a point")
    ids = np.asarray(dggs.str_to_int(column), dtype=np.uint64) if n else np.zeros(0, dtype=np.uint64)
    levels = np.asarray(dggs.get_level(ids)) if n else np.zeros(0, dtype=np.int64)
    wrong = np.flatnonzero(levels != level)
    if wrong.size:
        at = int(wrong[0])
        raise LevelMismatchError(
            f"cell {column[at]!r} (row {at + 1}) is at level {int(levels[at])}, not the ingest's level {level}"
        )
    return ids
