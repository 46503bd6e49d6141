"""The :class:`Ingester`: rows of every kind of input into one store (``CellStore`` delegates ``ingest*``, ``merge``).

Each method builds one :class:`~dggs.storage.ingest.IngestOptions` (checked before the store is touched) and hands
it to :mod:`dggs.storage.inputs`.  The docstrings are the public methods' (``CellStore`` shows them), with examples.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Iterable, Mapping, Sequence
from typing import Any

from . import inputs, readers
from .connection import Connection, guarded
from .ingest import MERGE_ROWS, IngestOptions, IngestResult

__all__ = ["Ingester"]

Progress = Callable[[int], Any] | bool
Values = Sequence[str] | Mapping[str, Any]


class Ingester:
    """Ingests into ``store`` (a :class:`~dggs.storage.connection.Connection`), merging past ``merge_rows`` pending."""

    def __init__(self, store: Connection, merge_rows: int = MERGE_ROWS) -> None:
        self._store = store
        self.path, self.timeout = store.path, store.timeout  # named by the errors of guarded
        self.merge_rows = merge_rows

    def ingest(self, source: Any, **kwargs: Any) -> IngestResult:
        """Ingest a file path (CSV, GeoJSON, GeoPackage...), DataFrame or iterable of dicts.

        Dispatches on a path's extension to :meth:`ingest_csv` (``.csv``,
        ``.tsv``, ``.txt``), :meth:`ingest_geojson` (``.geojson``, ``.json``)
        or :meth:`ingest_vector` (``.gpkg``, ``.shp``, ``.fgb``, ``.parquet``),
        otherwise to
        :meth:`ingest_dataframe` or :meth:`ingest_records`.

        Raises
        ------
        StorageError
            If a path's extension names no format read here (or the file is missing).
        DggsValueError, BadRowError, LevelMismatchError
            As the method dispatched to raises them.

        Examples
        --------
        >>> with CellStore() as store:
        ...     store.ingest([{"lat": 1.0, "lng": 2.0}], level=3).rows_inserted
        1
        """
        if isinstance(source, (str, os.PathLike)):
            kind = readers.sniff_kind(source)
            if kind == "csv":
                return self.ingest_csv(source, **kwargs)
            if kind == "vector":
                return self.ingest_vector(source, **kwargs)
            return self.ingest_geojson(source, **kwargs)
        if type(source).__name__ == "DataFrame" and hasattr(source, "columns"):
            return self.ingest_dataframe(source, **kwargs)
        return self.ingest_records(source, **kwargs)

    @guarded
    def ingest_csv(
        self,
        path: str | os.PathLike[str],
        lat: str = "lat",
        lng: str = "lng",
        values: Values = (),
        level: int | None = None,
        *,
        crs: Any = None,
        batch_size: int = 10_000,
        on_error: str = "fail",
        replace: bool = False,
        delimiter: str = ",",
        encoding: str = "utf-8",
        progress: Progress | None = None,
    ) -> IngestResult:
        r"""Bin the rows of a CSV file (with a header row), streaming it in batches.

        Each batch of ``batch_size`` rows is committed whole or not at all.
        The file is identified by its content (SHA-256): ingesting it again
        resumes after the rows already committed, or does nothing if it was
        ingested completely.

        Parameters
        ----------
        path : str or Path
            CSV file with a header row.
        lat, lng : str
            Names of the coordinate columns (latitude and longitude, degrees);
            with a projected ``crs``, the northing (y) and easting (x).
        values : list of str or dict
            Value columns to keep; a dict gives their types (``int``,
            ``float``, ``str`` or SQL ``"INTEGER"``, ``"REAL"``, ``"TEXT"``),
            otherwise they are guessed from the first batch.  Empty fields are
            stored as NULL.
        level : int, optional
            Level to bin at; default the store's level, or 12 for a new store.
        crs : str or pyproj.CRS, optional
            CRS of the coordinates (default WGS84 lat/lng), e.g. ``"EPSG:3857"``.
        batch_size : int, default 10000
            Rows per transaction.
        on_error : {"fail", "skip"}, default "fail"
            ``"fail"`` stops at the first bad row with a :class:`BadRowError`
            (earlier batches stay committed); ``"skip"`` stores the good rows,
            keeps the bad ones in table ``rejects`` and warns.
        replace : bool, default False
            Delete what an earlier ingest of this file stored, then ingest it.
        delimiter : str, default ","
            Field separator.
        encoding : str, default "utf-8"
            Text encoding of the file (a UTF-8 byte-order mark is skipped).
        progress : bool or callable, optional
            A bar on stderr with the total and an ETA: ``None`` (default) on
            a terminal once the ingest has run 2 s, ``True`` always, ``False``
            never; or a callable, called with the
            number of input rows after each batch.

        Returns
        -------
        IngestResult

        Raises
        ------
        BadRowError
            On a bad row with ``on_error="fail"``.
        LevelMismatchError
            If the store holds another level.
        DggsValueError
            If a column is missing or named badly.

        Examples
        --------
        >>> import os, tempfile
        >>> path = os.path.join(tempfile.mkdtemp(), "pts.csv")
        >>> with open(path, "w") as fh:
        ...     _ = fh.write("lat,lng,pop\n51.5,-0.12,9000000\n40.7,-74.0,8000000\n")
        >>> with CellStore() as store:
        ...     store.ingest_csv(path, values=["pop"], level=5).rows_inserted
        2
        """
        options = IngestOptions(batch_size, on_error, replace, crs, progress)
        return inputs.ingest_csv(
            self._store, path, lat, lng, values, level, options,
            delimiter=delimiter, encoding=encoding, merge_rows=self.merge_rows,
        )

    @guarded
    def ingest_geojson(
        self,
        path: str | os.PathLike[str],
        values: Values | None = None,
        level: int | None = None,
        *,
        batch_size: int = 10_000,
        on_error: str = "fail",
        replace: bool = False,
        progress: Progress | None = None,
    ) -> IngestResult:
        """Bin the features of a GeoJSON file (WGS84 lng/lat, RFC 7946).

        Points are stored as they are; a Polygon or MultiPolygon is stored
        as one row per cell at ``level`` whose centre lies inside it, each
        carrying the feature's properties (so sum a per-area value with care:
        every cell gets the whole value).  ``values=None`` keeps every
        property seen in the first batch.  Other parameters as
        :meth:`ingest_csv`; progress counts features.

        Raises
        ------
        BadRowError, LevelError, LevelMismatchError
            As :meth:`ingest_csv`: a bad row with ``on_error="fail"``, a bad ``level`` or another stored level.
        DggsValueError
            If the file is not GeoJSON or a value column is named badly.
        StorageError
            If the file is missing.

        Examples
        --------
        >>> import json, os, tempfile
        >>> path = os.path.join(tempfile.mkdtemp(), "p.geojson")
        >>> fc = {"type": "FeatureCollection", "features": [{"type": "Feature",
        ...       "geometry": {"type": "Point", "coordinates": [2.35, 48.85]},
        ...       "properties": {"name": "Paris"}}]}
        >>> with open(path, "w") as fh:
        ...     json.dump(fc, fh)
        >>> with CellStore() as store:
        ...     _ = store.ingest_geojson(path, level=4)
        ...     store.descendants(dggs.latlng_to_cell(48.85, 2.35, 1))[0]["name"]
        'Paris'
        """
        options = IngestOptions(batch_size, on_error, replace, None, progress)
        return inputs.ingest_geojson(self._store, path, values, level, options, merge_rows=self.merge_rows)

    @guarded
    def ingest_vector(
        self,
        path: str | os.PathLike[str],
        layer: str | int | None = None,
        values: Values | None = None,
        level: int | None = None,
        *,
        crs: Any = None,
        batch_size: int = 10_000,
        on_error: str = "fail",
        replace: bool = False,
        progress: Progress | None = None,
    ) -> IngestResult:
        """Bin the features of a GeoPackage, Shapefile, FlatGeobuf or GeoParquet layer.

        Read in batches through pyogrio (GDAL), which is the optional extra
        ``dggs[vector]``.  Points, MultiPoints, Polygons and MultiPolygons
        are stored as :meth:`ingest_geojson` stores them.  Coordinates are
        transformed to WGS84 from the layer's CRS (``crs`` overrides it, for
        a file that names none or names it wrongly).  ``layer`` is a name or
        index (default: the first layer).  ``values=None`` keeps every
        attribute field.  Other parameters as :meth:`ingest_csv`; progress
        and row numbers count features.

        Raises
        ------
        BadRowError, LevelError, LevelMismatchError
            As :meth:`ingest_csv`: a bad row with ``on_error="fail"``, a bad ``level`` or another stored level.
        DggsValueError
            If the layer cannot be read, its CRS is unknown, or a value column is not one of its fields.
        StorageError
            If the file is missing or pyogrio is not installed.

        Examples
        --------
        >>> import os, tempfile
        >>> import geopandas as gpd  # doctest: +SKIP
        >>> from shapely.geometry import Point  # doctest: +SKIP
        >>> path = os.path.join(tempfile.mkdtemp(), "p.gpkg")  # doctest: +SKIP
        >>> gpd.GeoDataFrame({"v": [1]}, geometry=[Point(2.35, 48.85)], crs=4326).to_file(path)  # doctest: +SKIP
        >>> CellStore().ingest_vector(path, level=5).rows_inserted  # doctest: +SKIP
        1
        """
        options = IngestOptions(batch_size, on_error, replace, crs, progress)
        return inputs.ingest_vector(self._store, path, layer, values, level, options, merge_rows=self.merge_rows)

    @guarded
    def ingest_records(
        self,
        records: Iterable[Mapping[str, Any]],
        lat: str = "lat",
        lng: str = "lng",
        values: Values = (),
        level: int | None = None,
        *,
        source: str | None = None,
        crs: Any = None,
        batch_size: int = 10_000,
        on_error: str = "fail",
        replace: bool = False,
        progress: Progress | None = None,
    ) -> IngestResult:
        """Bin an iterable of dicts (e.g. rows from a database or JSON lines).

        Without ``source`` each call is a new, independent ingest.  Give a
        ``source`` name to make it resumable: calling again with the same
        name and the same records skips those already committed.  Other
        parameters as :meth:`ingest_csv`.

        Raises
        ------
        BadRowError, LevelError, LevelMismatchError
            As :meth:`ingest_csv`: a bad row with ``on_error="fail"``, a bad ``level`` or another stored level.
        DggsValueError
            If ``records`` is not an iterable of dicts or a value column is named badly.

        Examples
        --------
        >>> with CellStore() as store:
        ...     rows = [{"lat": 0.5, "lng": 0.5, "v": 1}, {"lat": 0.6, "lng": 0.5, "v": 2}]
        ...     store.ingest_records(rows, values=["v"], level=3, source="demo").rows_inserted
        ...     store.ingest_records(rows, values=["v"], level=3, source="demo").already_complete
        2
        True
        """
        options = IngestOptions(batch_size, on_error, replace, crs, progress, source)
        return inputs.ingest_records(self._store, records, lat, lng, values, level, options, merge_rows=self.merge_rows)

    @guarded
    def ingest_points(
        self,
        lat: Any,
        lng: Any,
        level: int | None = None,
        values: Mapping[str, Any] | None = None,
        *,
        types: Mapping[str, Any] | None = None,
        source: str | None = None,
        crs: Any = None,
        batch_size: int = 100_000,
        on_error: str = "fail",
        replace: bool = False,
        progress: Progress | None = None,
        cells: Any = None,
    ) -> IngestResult:
        """Bin points given as arrays (numpy, lists): the fastest way in.

        Parameters
        ----------
        lat, lng : array_like
            Latitudes and longitudes in degrees (or y and x in ``crs``).
        level : int, optional
            As in :meth:`ingest_csv`.
        values : dict of array_like, optional
            Value columns, each as long as ``lat``; types follow the dtypes
            unless given in ``types``.
        types : dict, optional
            SQL types of value columns, overriding the dtypes.
        source : str, optional
            Name that makes the ingest resumable (see :meth:`ingest_records`).
        crs, batch_size, on_error, replace, progress
            As in :meth:`ingest_csv` (default batch 100,000 rows).
        cells : array_like, optional
            The points' cells at ``level`` (str or int ids, valid, binned before on the store's grid, as
            ``sjoin_cells(cells=)`` takes them): stored as given, not binned again (tests/storage/test_ordered_ingest.py).

        Raises
        ------
        BadRowError, LevelError, LevelMismatchError
            As :meth:`ingest_csv`: a bad row with ``on_error="fail"``, a bad ``level`` or another stored level.
        InvalidCellError, LevelMismatchError, DggsValueError
            A given cell not valid or not of ``level`` (naming it); an array not flat or not as long as ``lat``.

        Examples
        --------
        >>> import numpy as np
        >>> with CellStore() as store:
        ...     r = store.ingest_points(np.array([10.0, 20.0]), np.array([30.0, 40.0]), 4,
        ...                             values={"temp": np.array([21.5, 19.0])})
        ...     store.columns, store.count()
        ({'temp': 'REAL'}, 2)
        """
        options = IngestOptions(batch_size, on_error, replace, crs, progress, source)
        return inputs.ingest_points(self._store, lat, lng, level, values, types, options, merge_rows=self.merge_rows,
                                    cells=cells)

    @guarded
    def ingest_dataframe(
        self,
        df: Any,
        lat: str = "lat",
        lng: str = "lng",
        values: Values | None = None,
        level: int | None = None,
        *,
        types: Mapping[str, Any] | None = None,
        source: str | None = None,
        crs: Any = None,
        batch_size: int = 100_000,
        on_error: str = "fail",
        replace: bool = False,
        progress: Progress | None = None,
        cells: str | None = None,
    ) -> IngestResult:
        """Bin the rows of a pandas DataFrame (``values=None``: every other column).

        Keyword arguments are those of :meth:`ingest_points`; ``cells`` names a column of cells binned before.

        Raises
        ------
        BadRowError, LevelError, LevelMismatchError
            As :meth:`ingest_csv`: a bad row with ``on_error="fail"``, a bad ``level`` or another stored level.
        DggsValueError
            If the ``lat`` or ``lng`` column is missing or a value column is named badly.

        Examples
        --------
        >>> import pandas as pd  # doctest: +SKIP
        >>> df = pd.DataFrame({"lat": [1.0], "lng": [2.0], "v": [3]})  # doctest: +SKIP
        >>> CellStore().ingest_dataframe(df, level=3).rows_inserted  # doctest: +SKIP
        1
        """
        options = IngestOptions(batch_size, on_error, replace, crs, progress, source)
        return inputs.ingest_dataframe(
            self._store, df, lat, lng, values, level, types, options, merge_rows=self.merge_rows, cells=cells
        )

    @guarded
    def merge(self) -> None:
        """Move pending rows into the indexed ``points`` table (one transaction).

        Ingest does this by itself; call it after an interrupted ingest you
        will not resume, to make queries as fast as they can be.

        Raises
        ------
        StorageError
            If the store is read-only, or a pending row would be stored twice.
        """
        with self._store.transaction():
            self._store.merge_pending()

