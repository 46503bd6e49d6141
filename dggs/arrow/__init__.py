"""Cells as Apache Arrow geometry: WKB and GeoArrow arrays, GeoParquet 1.1 tables.

Every dggs function already takes and returns pyarrow arrays of ids.  This
module adds the geometry side without a Python loop per cell:

* :func:`cells_to_geoarrow` gives the cells' polygons as a pyarrow array,
  WKB (``binary``) or native GeoArrow (``polygon`` / ``multipolygon``
  nested lists of ``struct<x, y>``).  Ordinary cells' WKB is written
  straight from the kernel's boundary arrays with numpy (one fixed-size
  record per cell); only the few cells that touch a pole or cross the
  antimeridian go through shapely.
* :func:`cells_to_table` gives a GeoParquet 1.1 table: ``cell`` (string id),
  ``cell_id`` (int64 id), any property columns, a ``bbox`` covering struct
  and a WKB ``geometry`` column, with the ``geo`` schema metadata.  Both the
  ``bbox`` group and ``geometry`` are ``required``, and a cell split at the
  antimeridian has ``xmin=-180, xmax=180``, so that readers comparing the
  fields as they are lose no row (:mod:`dggs.arrow.geoparquet`).
* :func:`write_geoparquet` writes such a table whole or not at all.
* :func:`bbox_filter` (pyarrow) and :func:`bbox_sql` (DuckDB) select the rows
  whose ``bbox`` meets a box, honouring ``xmin > xmax``.

Coordinates are (lng, lat) degrees on WGS84, i.e. OGC:CRS84, the GeoParquet
default, so the ``geo`` metadata leaves ``crs`` out.

Examples
--------
>>> import pyarrow as pa
>>> from dggs.arrow import cells_to_geoarrow, cells_to_table
>>> wkb = cells_to_geoarrow(pa.array(["C401", "C402"]))
>>> wkb.type, len(wkb)
(DataType(binary), 2)
>>> import shapely
>>> shapely.from_wkb(wkb.to_numpy(zero_copy_only=False))[0].geom_type
'Polygon'
>>> cells_to_table(["C401"], {"n": [3]}).column_names
['cell', 'cell_id', 'n', 'bbox', 'geometry']
"""

from __future__ import annotations

import functools
import json
import os
import re
from collections.abc import Mapping
from typing import Any

import numpy as np

from dggs.arrow.formats import EXPORT_FORMATS, export_format
from dggs.arrow.geoparquet import (
    BBOX_TYPE,
    GEOPARQUET_VERSION,
    bbox_filter,
    bbox_sql,
    covering_bounds,
    file_bbox,
    geo_metadata,
    split_box,
    widen_wrapped,
)
from dggs.errors import DggsValueError
from dggs.index._checks import check_densify
from dggs.index._convert import cells_in
from dggs.index._densify import DRAW_TOLERANCE, edge_points_metadata
from dggs.index._shapes import geoarrow, wkb
from dggs.index.ids import int_to_str

try:
    import pyarrow as pa
except ImportError as exc:  # pragma: no cover - pyarrow is in every extra that needs this module
    raise ImportError("dggs.arrow needs pyarrow: pip install pyarrow") from exc

__all__ = [
    "cells_to_geoarrow",
    "cells_to_table",
    "geo_metadata",
    "geoarrow_field",
    "write_geoparquet",
    "write_cells",
    "export_format",
    "EXPORT_FORMATS",
    "to_geodataframe",
    "GEOPARQUET_VERSION",
    "bbox_filter",
    "bbox_sql",
    "split_box",
]

_ENCODINGS = ("wkb", "geoarrow")


def _check_encoding(encoding: str) -> str:
    if encoding not in _ENCODINGS:
        raise DggsValueError(f"encoding {encoding!r} is not one of {', '.join(map(repr, _ENCODINGS))}")
    return encoding


def cells_to_geoarrow(cells: Any, densify: int | None = 0, encoding: str = "wkb") -> pa.Array:
    """The cells' polygons (lng, lat; split at the antimeridian) as a pyarrow geometry array.

    Parameters
    ----------
    cells : str, int or array_like of ids (list, numpy, pandas, pyarrow)
        Cell ids, flattened in order.
    densify : int or None, default 0
        Points added along each curved edge; None gives
        :func:`dggs.cell_to_polygon`'s area-exact default per level.
    encoding : {"wkb", "geoarrow"}
        ``"wkb"``: a ``binary`` array of little-endian ISO WKB (``large_binary``
        past 2 GiB), the same bytes as ``shapely.to_wkb(dggs.cell_to_polygon(cells, densify))``.
        ``"geoarrow"``: native GeoArrow, ``list<list<struct<x, y>>>``
        (``geoarrow.polygon``), or one more list level
        (``geoarrow.multipolygon``) if any cell crosses the antimeridian,
        as ``geopandas`` does.  :func:`geoarrow_field` gives the field with
        the extension name for either.

    Returns
    -------
    pyarrow.Array
        One geometry per cell, no nulls.

    Raises
    ------
    InvalidCellError, DggsValueError
        A bad id, densify or encoding.

    Examples
    --------
    >>> cells_to_geoarrow(["C401"], encoding="geoarrow").type
    ListType(list<item: list<item: struct<x: double, y: double>>>)
    """
    _check_encoding(encoding)
    if densify is not None:
        densify = check_densify(densify)
    ids, _ = cells_in(cells)
    ids = ids.reshape(-1)
    if encoding == "wkb":
        return wkb(ids, densify)[0]
    return geoarrow(ids, densify)[0]


def geoarrow_field(name: str = "geometry", encoding: str = "wkb", cells: Any = None, densify: int | None = 0) -> pa.Field:
    """A pyarrow field for a geometry column, with its GeoArrow extension name and CRS.

    ``encoding="wkb"`` gives ``geoarrow.wkb``; for ``"geoarrow"`` pass the
    ``cells`` (and ``densify``) to learn whether they need
    ``geoarrow.multipolygon`` rather than ``geoarrow.polygon``.

    Examples
    --------
    >>> geoarrow_field().metadata[b"ARROW:extension:name"]
    b'geoarrow.wkb'

    Raises
    ------
    DggsValueError
        An unknown ``encoding``, or ``encoding="geoarrow"`` without the ``cells``.
    InvalidCellError
        A malformed id among the ``cells``.
    """
    _check_encoding(encoding)
    if encoding == "wkb":
        return pa.field(name, pa.binary(), nullable=False, metadata=_geoarrow_metadata("geoarrow.wkb"))
    if cells is None:
        raise DggsValueError('geoarrow_field(encoding="geoarrow") needs the cells, to tell polygon from multipolygon')
    ids, _ = cells_in(cells)
    arr, ext = geoarrow(ids.reshape(-1), densify if densify is None else check_densify(densify))
    return pa.field(name, arr.type, nullable=False, metadata=_geoarrow_metadata(ext))


@functools.lru_cache(maxsize=1)
def _crs84_projjson() -> dict[str, Any]:
    import pyproj

    return pyproj.CRS.from_user_input("OGC:CRS84").to_json_dict()


def _geoarrow_metadata(extension: str) -> dict[bytes, bytes]:
    """A GeoArrow field's metadata: the extension name and the CRS as PROJJSON.

    The GeoArrow spec's "Extension metadata": ``crs`` a PROJJSON object with ``crs_type`` ``"projjson"``
    (here OGC:CRS84, lng/lat on WGS84); ``edges`` left out means planar, as the WKB's are.
    """
    meta = {"crs": _crs84_projjson(), "crs_type": "projjson"}
    return {b"ARROW:extension:name": extension.encode(), b"ARROW:extension:metadata": json.dumps(meta).encode()}


def _bbox_array(bounds: np.ndarray) -> pa.StructArray:
    return pa.StructArray.from_arrays([pa.array(bounds[:, i]) for i in range(4)], fields=list(BBOX_TYPE))


def cells_to_table(
    cells: Any, properties: Mapping[str, Any] | Any = None, densify: int | None = None, *, tolerance: Any = DRAW_TOLERANCE
) -> pa.Table:
    """A GeoParquet 1.1 table of cells: ids, properties, ``bbox`` covering and WKB ``geometry``.

    Parameters
    ----------
    cells : str, int or array_like of ids
        One row per id, in order.
    properties : dict of columns, pyarrow Table or pandas DataFrame, optional
        Extra columns, one value per cell (placed after the ids).
    densify : int or None
        Points per curved edge; by default as many as ``tolerance`` needs (as :func:`dggs.cells_to_geojson`).
    tolerance : float or "exact", default 10.0
        Metres between each drawn edge and the true edge, or ``"exact"`` for geodesic areas within 1e-6
        of the cells' (:func:`dggs.cell_to_polygon`'s default).  Written into the schema metadata's
        ``dggs`` key (JSON) beside ``geo``.

    Returns
    -------
    pyarrow.Table
        Columns ``cell`` (string id), ``cell_id`` (int64 id, same order),
        the properties, ``bbox`` (struct xmin, ymin, xmax, ymax) and
        ``geometry`` (WKB); schema metadata ``geo`` as GeoParquet 1.1.

    Raises
    ------
    DggsValueError
        A property column without one value per cell, or named like a
        column this function writes.

    Examples
    --------
    >>> t = cells_to_table(["C401", "C402"], {"n": [1, 2]})
    >>> t.num_rows, t.column("cell_id").type
    (2, DataType(int64))
    >>> json.loads(t.schema.metadata[b"dggs"])
    {'edge_points': 'tolerance', 'tolerance_m': 10.0}
    """
    if densify is not None:
        densify = check_densify(densify)
    drawn = edge_points_metadata(densify, tolerance)
    ids, _ = cells_in(cells)
    ids = ids.reshape(-1)
    n = ids.shape[0]
    geometry, bounds, types = wkb(ids, densify, None, tolerance)
    columns: dict[str, Any] = {
        "cell": pa.array(int_to_str(ids) if n else np.empty(0, dtype=str), type=pa.string()),
        "cell_id": pa.array(ids.astype(np.int64), type=pa.int64()),
    }
    if properties is not None:
        if isinstance(properties, pa.Table):
            props: dict[str, Any] = {name: properties.column(name) for name in properties.column_names}
        elif hasattr(properties, "columns") and hasattr(properties, "to_numpy"):  # a pandas DataFrame
            props = {str(name): pa.array(properties[name], from_pandas=True) for name in properties.columns}
        else:
            props = dict(properties)
        for name, values in props.items():
            if name in ("cell", "cell_id", "bbox", "geometry"):
                raise DggsValueError(f"property {name!r} clashes with a column of the table; rename it")
            arr = values if isinstance(values, (pa.Array, pa.ChunkedArray)) else pa.array(values)
            if len(arr) != n:
                raise DggsValueError(f"property {name!r} has {len(arr)} values for {n} cells")
            columns[name] = arr
    bounds = covering_bounds(geometry, bounds)  # RFC 7946 §5: xmin > xmax across the antimeridian
    columns["bbox"] = _bbox_array(widen_wrapped(bounds))  # ... and -180..180 in the rows (dggs.arrow.geoparquet)
    columns["geometry"] = geometry
    table = pa.table(columns)
    fields = [table.schema.field(i) for i in range(table.num_columns)]
    # GeoParquet 1.1 §"Bounding Box Columns": "The repetition of a bounding box column MUST match the
    # geometry column's repetition": both required, as no cell lacks either.
    fields[-2] = pa.field("bbox", BBOX_TYPE, nullable=False)
    # Tagged as GeoArrow too (geoarrow.wkb with the CRS as PROJJSON), so GeoDataFrame.from_arrow, DuckDB
    # and lonboard find the geometry in the table itself, not only in a file's "geo" metadata.
    fields[-1] = pa.field("geometry", geometry.type, nullable=False, metadata=_geoarrow_metadata("geoarrow.wkb"))
    meta = {b"geo": json.dumps(geo_metadata(types, file_bbox(bounds))).encode(), b"dggs": json.dumps(drawn).encode()}
    return table.cast(pa.schema(fields, metadata=meta))



#: Cells per Parquet row group of :func:`write_geoparquet`: cells in id order are near each other, so each row
#: group's ``bbox`` statistics cover a small area and a reader filtering by bbox skips the others (GeoParquet 1.1
#: "Bounding Box Columns"); one group per file would let nothing be skipped.
ROW_GROUP_CELLS = 8192


def write_geoparquet(table: pa.Table, path: str | os.PathLike[str], **kwargs: Any) -> None:
    """Write a table of :func:`cells_to_table` to a GeoParquet file, whole or not at all.

    The file is written under a temporary name in the same folder and
    renamed over ``path`` when complete.  ``kwargs`` go to
    ``pyarrow.parquet.write_table`` (default compression zstd, and row groups
    of :data:`ROW_GROUP_CELLS` cells so that the bbox covering's statistics can prune).

    Raises
    ------
    StorageError
        If the file cannot be written; ``path`` is then untouched.
    """
    import pyarrow.parquet as pq

    if b"geo" not in (table.schema.metadata or {}):
        raise DggsValueError("the table has no 'geo' metadata: build it with dggs.arrow.cells_to_table")
    from dggs.storage.atomic import atomic_path

    kwargs.setdefault("compression", "zstd")
    kwargs.setdefault("row_group_size", ROW_GROUP_CELLS)
    with atomic_path(path, keep_name=True) as tmp:
        pq.write_table(table, tmp, **kwargs)


#: GDAL drivers of the formats :func:`write_cells` writes through pyogrio.
_DRIVERS = {"geojson": "GeoJSON", "gpkg": "GPKG", "fgb": "FlatGeobuf"}
def to_geodataframe(table: pa.Table) -> Any:
    """A GeoDataFrame (EPSG:4326 axis order lng, lat) of a :func:`cells_to_table` table, without ``bbox``."""
    import geopandas

    frame = table.drop_columns([c for c in ("bbox", "geometry") if c in table.column_names]).to_pandas()
    geometry = geopandas.GeoSeries.from_wkb(table.column("geometry").to_numpy(zero_copy_only=False), crs="OGC:CRS84")
    return geopandas.GeoDataFrame(frame, geometry=geometry.values, crs="OGC:CRS84")


def write_cells(table: pa.Table, path: str | os.PathLike[str], format: str | None = None) -> str:
    """Write a :func:`cells_to_table` table as GeoParquet, or through pyogrio as GeoJSON, GeoPackage or FlatGeobuf.

    ``format`` is ``"geoparquet"``, ``"geojson"``, ``"gpkg"`` or ``"fgb"``;
    by default the extension of ``path`` tells (``.parquet``,
    ``.geoparquet``, ``.geojson``, ``.json``, ``.gpkg``, ``.fgb``).

    The file is written under a temporary name and renamed over ``path``
    when complete.  GeoParquet needs only pyarrow; the GDAL formats need
    geopandas and pyogrio.  Returns the format written.

    Raises
    ------
    DggsValueError
        An unknown format, or a path whose extension names none.
    StorageError
        The file cannot be written (``path`` is untouched).
    """
    from dggs.storage.atomic import atomic_path, writer_error

    format = export_format(path, format)
    if format == "geoparquet":
        write_geoparquet(table, path)
        return format
    import pyogrio
    from pyogrio.errors import DataLayerError, DataSourceError

    layer = re.sub(r"\W", "_", os.path.splitext(os.path.basename(os.fspath(path)))[0]) or "cells"
    kinds = _geometry_types(table)
    if format in ("gpkg", "fgb") and kinds <= {"Polygon", "MultiPolygon"}:
        # The WKB column goes to GDAL as it is, 3x faster than through shapely geometries and a
        # GeoDataFrame; one layer type, so with a cell split at the antimeridian every cell becomes a
        # MultiPolygon (as geopandas' promote_to_multi does).
        out = table.drop_columns(["bbox"]) if "bbox" in table.column_names else table
        kind = "Polygon" if kinds <= {"Polygon"} else "MultiPolygon"
        if kind == "MultiPolygon":
            at = out.column_names.index("geometry")
            out = out.set_column(at, out.schema.field("geometry"), _as_multipolygons(out.column("geometry")))
        with atomic_path(path, keep_name=True) as tmp:
            try:
                pyogrio.write_arrow(out, tmp, layer=layer, driver=_DRIVERS[format], geometry_name="geometry",
                                    geometry_type=kind, crs="OGC:CRS84")
            except (DataSourceError, DataLayerError) as exc:
                raise writer_error(path, tmp, exc) from exc
        return format
    frame = to_geodataframe(table)
    multi = format in ("gpkg", "fgb") and "MultiPolygon" in set(frame.geom_type)
    with atomic_path(path, keep_name=True) as tmp:
        try:
            frame.to_file(tmp, driver=_DRIVERS[format], engine="pyogrio", layer=layer, promote_to_multi=multi)
        except (DataSourceError, DataLayerError) as exc:  # GDAL's failures, a full disk among them
            raise writer_error(path, tmp, exc) from exc
    return format


#: The WKB header of a little-endian MultiPolygon of one polygon: byte order 1, type 6, one part.
_ONE_PART_MULTIPOLYGON = bytes([1, 6, 0, 0, 0, 1, 0, 0, 0])


def _as_multipolygons(wkb: Any) -> pa.Array:
    """WKB Polygons wrapped as one-part MultiPolygons (OGC simple features: the polygon's record follows).

    Written by hand, and kept: 1.3 us a cell against 2.6 us for geoarrow-pyarrow's as_geoarrow +
    as_wkb and 14 us for shapely's from_wkb + multipolygons + to_wkb, the same bytes
    (100,000 level-10 cells at densify=16, benchmarks/bench_handwritten.py).
    """
    blobs = wkb.to_pylist()
    kind = [(b[1] if b[0] == 1 else b[4]) if b is not None else 0 for b in blobs]  # the type's low byte
    return pa.array([_ONE_PART_MULTIPOLYGON + b if k == 3 else b for b, k in zip(blobs, kind, strict=True)],
                    type=wkb.type)


def _geometry_types(table: pa.Table) -> set[str]:
    """The geometry types the table's GeoParquet metadata declares ({"Unknown"} if it declares none)."""
    meta = (table.schema.metadata or {}).get(b"geo")
    if meta is None:
        return {"Unknown"}
    return set(json.loads(meta)["columns"]["geometry"].get("geometry_types") or ["Unknown"])
