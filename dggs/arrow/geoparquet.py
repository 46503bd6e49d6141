"""GeoParquet 1.1 rules for the tables of :mod:`dggs.arrow`: the ``geo`` metadata, the ``bbox`` covering, filters.

Every GeoParquet file dggs writes (``CellStore.export``, ``dggs export``,
:mod:`dggs.arrow`, :mod:`dggs.dask`, ``dggs bin-raster --parquet``) is a
:func:`dggs.arrow.cells_to_table` table, so these rules are kept here once:

* The ``geometry`` column and the ``bbox`` covering group are both
  ``required`` in the Parquet schema (no row lacks either): GeoParquet 1.1
  §"Bounding Box Columns": "The repetition of a bounding box column MUST
  match the geometry column's repetition".
* Per-row bounds are plain ``xmin <= xmax`` boxes that every reader can
  compare field by field: a cell split at the antimeridian (a MultiPolygon
  with parts at +180 and -180) gets ``[-180, ymin, 180, ymax]``
  (:func:`widen_wrapped`), as geopandas' own writer gives it.  The RFC 7946
  §5.2 form, ``xmin > xmax``, is what GeoParquet 1.1 §"Bounding Box
  Columns" points to, but geopandas' ``read_parquet(bbox=...)``, a pyarrow
  dataset filter and a DuckDB ``WHERE`` written as the spec's example
  compare the fields as they are and so lost every such row (issue 36:
  0 of the 24 level-3 cells a box at (170, -20, -170, 20) meets).  Widened,
  a row is read by every query at its latitudes: a few extra rows, none lost,
  and still one row per cell, so a join or a count on the id is unchanged.
* The file's ``bbox`` keeps RFC 7946 §5.2 (``xmin > xmax`` when the cells
  wrap): it is one value, for a map's extent, and it filters no row.
* :func:`bbox_filter` and :func:`bbox_sql` are filters that also honour
  ``xmin > xmax`` rows (files from dggs before this layout) and a query box
  across the antimeridian (``box[0] > box[2]``).

Examples
--------
>>> import numpy as np
>>> lng_extent(np.array([170.0, -180.0]), np.array([180.0, -170.0]))  # two parts of a split cell
(170.0, -170.0)
>>> lng_extent(np.array([-180.0]), np.array([180.0]))
(-180.0, 180.0)
"""

from __future__ import annotations

import numbers
from typing import Any

import numpy as np

from dggs.errors import DggsValueError

__all__ = ["GEOPARQUET_VERSION", "BBOX_TYPE", "bbox_filter", "bbox_sql", "covering_bounds", "file_bbox",
           "geo_metadata", "lng_extent", "split_box", "widen_wrapped"]

GEOPARQUET_VERSION = "1.1.0"
_FIELDS = ("xmin", "ymin", "xmax", "ymax")


def _bbox_type() -> Any:
    import pyarrow as pa

    # GeoParquet 1.1 §"Bounding Box Columns": a group of 4 DOUBLE fields named and ordered xmin, ymin,
    # xmax, ymax; never null, as the geometry is never null.
    return pa.struct([pa.field(name, pa.float64(), nullable=False) for name in _FIELDS])


BBOX_TYPE = _bbox_type()


def geo_metadata(geometry_types: Any, bbox: Any = None, column: str = "geometry", covering: str | None = "bbox") -> dict:
    """The GeoParquet 1.1 ``geo`` metadata of a table with one WKB column in OGC:CRS84.

    ``crs`` is left out: GeoParquet 1.1 §"crs": "If the crs key does not exist, all coordinates
    [...] MUST use longitude, latitude based on the WGS84 datum" (OGC:CRS84), which they do.
    ``edges`` is ``"planar"`` (straight lines between the densified points in lng/lat) and
    ``orientation`` ``"counterclockwise"`` (every exterior ring is, GeoParquet 1.1 §"orientation").

    Examples
    --------
    >>> geo_metadata(["Polygon"])["columns"]["geometry"]["covering"]["bbox"]["xmin"]
    ['bbox', 'xmin']
    """
    col: dict[str, Any] = {"encoding": "WKB", "geometry_types": sorted(set(geometry_types)),
                           "edges": "planar", "orientation": "counterclockwise"}
    if bbox is not None:
        col["bbox"] = [float(v) for v in bbox]
    if covering:
        # GeoParquet 1.1 §"bbox covering encoding": [column, field] paths, one column for all four
        col["covering"] = {"bbox": {k: [covering, k] for k in _FIELDS}}
    return {"version": GEOPARQUET_VERSION, "primary_column": column, "columns": {column: col}}


def lng_extent(lo: np.ndarray, hi: np.ndarray) -> tuple[float, float]:
    """The smallest longitude range covering every range ``[lo[i], hi[i]]`` (``lo > hi`` wraps over +-180).

    The largest gap on the circle between the ranges is left out: if it is
    not the one across the antimeridian, the range returned wraps
    (``xmin > xmax``, RFC 7946 §5.2); with no gap it is ``(-180, 180)``
    (RFC 7946 §5.3, a cell round a pole).  Ties keep the range that does not wrap.
    """
    lo, hi = np.asarray(lo, dtype=float).ravel(), np.asarray(hi, dtype=float).ravel()
    if lo.size == 0:
        raise DggsValueError("lng_extent needs at least one longitude range")
    wrap = lo > hi
    starts = np.concatenate([lo[~wrap], lo[wrap], np.full(int(wrap.sum()), -180.0)])
    ends = np.concatenate([hi[~wrap], np.full(int(wrap.sum()), 180.0), hi[wrap]])
    order = np.argsort(starts, kind="stable")
    starts, ends = starts[order], ends[order]
    reach = np.maximum.accumulate(ends)
    inner = starts[1:] - reach[:-1]  # the gap before each range (positive: uncovered)
    outer = starts[0] + 360.0 - reach[-1]  # the gap across the antimeridian
    if inner.size and inner.max() > max(outer, 0.0):
        k = int(np.argmax(inner))
        return float(starts[k + 1]), float(reach[k])
    if outer <= 0.0:
        return -180.0, 180.0
    return float(starts[0]), float(reach[-1])


def covering_bounds(geometry: Any, bounds: np.ndarray) -> np.ndarray:
    """Per-row bounds (N, 4) with the rows that span -180..180 given their true longitude range.

    ``bounds`` are shapely's planar bounds of the WKB ``geometry`` (a pyarrow
    binary array); a cell split at the antimeridian has parts at both ends,
    so its planar bounds span every longitude.  Those few rows are parsed and
    given :func:`lng_extent` of their parts (GeoParquet 1.1 §"Bounding Box
    Columns": "the values follow the GeoJSON specification (RFC 7946,
    section 5), which also describes how to represent the bbox for
    geometries that cross the antimeridian").
    """
    import shapely

    out = np.array(bounds, dtype=float, copy=True)
    rows = np.flatnonzero((out[:, 0] <= -180.0) & (out[:, 2] >= 180.0)) if out.size else np.empty(0, np.int64)
    if rows.size == 0:
        return out
    geoms = shapely.from_wkb(geometry.take(rows).to_numpy(zero_copy_only=False))
    parts, owner = shapely.get_parts(geoms, return_index=True)
    part_bounds = shapely.bounds(parts)
    for k, row in enumerate(rows):
        mine = part_bounds[owner == k]
        out[row, 0], out[row, 2] = lng_extent(mine[:, 0], mine[:, 2])
    return out


def widen_wrapped(bounds: np.ndarray) -> np.ndarray:
    """The rows of :func:`covering_bounds` that wrap (``xmin > xmax``) widened to ``xmin=-180, xmax=180``.

    This is the ``bbox`` column dggs writes: a reader comparing the fields as
    they are (``xmin <= box_xmax and xmax >= box_xmin``, GeoParquet 1.1's own
    example) then keeps a cell split at the antimeridian for every query at its
    latitudes, rather than for none.

    Examples
    --------
    >>> widen_wrapped(np.array([[170.0, -5.0, -170.0, 5.0], [1.0, 2.0, 3.0, 4.0]])).tolist()
    [[-180.0, -5.0, 180.0, 5.0], [1.0, 2.0, 3.0, 4.0]]
    """
    out = np.array(bounds, dtype=float, copy=True)
    if out.size:
        wrap = out[:, 0] > out[:, 2]
        out[wrap, 0], out[wrap, 2] = -180.0, 180.0
    return out


def split_box(box: Any) -> list[tuple[float, float, float, float]]:
    """A query box as one or two plain boxes: ``xmin > xmax`` (across the antimeridian) becomes its two sides.

    geopandas' ``read_parquet(bbox=...)`` and the plain comparisons of a
    pyarrow or DuckDB filter take ``xmin <= xmax`` only; read each box this
    gives and concatenate (the rows are disjoint unless a cell meets both).

    Raises
    ------
    DggsValueError
        As :func:`bbox_filter`.

    Examples
    --------
    >>> split_box((170, -20, -170, 20))
    [(170.0, -20.0, 180.0, 20.0), (-180.0, -20.0, -170.0, 20.0)]
    """
    x0, y0, x1, y1 = _check_box(box)
    if x0 <= x1:
        return [(x0, y0, x1, y1)]
    return [(x0, y0, 180.0, y1), (-180.0, y0, x1, y1)]


def file_bbox(bounds: np.ndarray) -> list[float] | None:
    """The file's ``bbox`` (GeoParquet 1.1 §"bbox", RFC 7946 §5) over per-row bounds; None without rows."""
    if bounds.shape[0] == 0:
        return None
    ymin, ymax = float(bounds[:, 1].min()), float(bounds[:, 3].max())
    if (bounds[:, 0] > bounds[:, 2]).any():  # some row crosses the antimeridian
        xmin, xmax = lng_extent(bounds[:, 0], bounds[:, 2])
    else:
        xmin, xmax = float(bounds[:, 0].min()), float(bounds[:, 2].max())
    return [xmin, ymin, xmax, ymax]


def _check_box(box: Any) -> tuple[float, float, float, float]:
    """(xmin, ymin, xmax, ymax) as floats, or a DggsValueError naming ``box``.

    Text, bytes, bools, non-numbers, numbers too large for a float and any other count than four are refused,
    not read as numbers (a str or bytes of four characters iterates to four values).
    """
    bad = DggsValueError(f"a bbox is 4 finite numbers (xmin, ymin, xmax, ymax), not {box!r}")
    if isinstance(box, (str, bytes, bytearray, dict)) or not np.iterable(box):
        raise bad
    items = list(box)
    if len(items) != 4 or not all(isinstance(v, numbers.Real) and not isinstance(v, (bool, np.bool_)) for v in items):
        raise bad
    try:
        values = tuple(float(v) for v in items)
    except (OverflowError, TypeError, ValueError):
        raise bad from None
    if not all(np.isfinite(values)):
        raise bad
    x0, y0, x1, y1 = values
    if not (-180.0 <= x0 <= 180.0 and -180.0 <= x1 <= 180.0 and -90.0 <= y0 <= y1 <= 90.0):
        raise DggsValueError(f"bbox {box!r} is outside lng -180..180, lat -90..90 (or ymin > ymax)")
    return x0, y0, x1, y1


def bbox_filter(box: Any, column: str = "bbox") -> Any:
    """A pyarrow filter for the rows whose ``bbox`` covering meets ``box``, honouring ``xmin > xmax``.

    ``box`` is (xmin, ymin, xmax, ymax) in degrees; ``xmin > xmax`` asks for
    a box across the antimeridian.  Pass it as ``filters=`` to
    ``geopandas.read_parquet`` or ``filter=`` to a pyarrow dataset.  On the
    files dggs writes now, a plain box gives the rows ``read_parquet(bbox=box)``
    gives; the filter also reads older files, whose split cells have
    ``xmin > xmax`` rows, and boxes across the antimeridian in one go.

    Raises
    ------
    DggsValueError
        ``box`` is not 4 finite numbers within lng -180..180, lat -90..90.

    Examples
    --------
    >>> type(bbox_filter((-5, -5, 5, 5))).__name__
    'Expression'
    """
    import pyarrow.compute as pc

    x0, y0, x1, y1 = _check_box(box)
    f = {name: pc.field((column, name)) for name in _FIELDS}
    rows_wrap = f["xmin"] > f["xmax"]
    if x0 <= x1:
        lng = (~rows_wrap & (f["xmin"] <= x1) & (f["xmax"] >= x0)) | (rows_wrap & ((f["xmin"] <= x1) | (f["xmax"] >= x0)))
    else:  # a box across the antimeridian meets every row that wraps
        lng = rows_wrap | (f["xmax"] >= x0) | (f["xmin"] <= x1)
    return lng & (f["ymin"] <= y1) & (f["ymax"] >= y0)


def bbox_sql(box: Any, column: str = "bbox") -> str:
    """The SQL condition of :func:`bbox_filter` (DuckDB: ``WHERE`` it in ``read_parquet(...)``).

    Raises
    ------
    DggsValueError
        As :func:`bbox_filter`.

    Examples
    --------
    >>> "bbox.xmin > bbox.xmax" in bbox_sql((-5, -5, 5, 5))
    True
    """
    x0, y0, x1, y1 = _check_box(box)
    c = '"' + column.replace('"', '""') + '"' if not column.isidentifier() else column
    xmin, ymin, xmax, ymax = (f"{c}.{name}" for name in _FIELDS)
    if x0 <= x1:
        lng = (f"(({xmin} <= {xmax} AND {xmin} <= {x1!r} AND {xmax} >= {x0!r}) OR "
               f"({xmin} > {xmax} AND ({xmin} <= {x1!r} OR {xmax} >= {x0!r})))")
    else:
        lng = f"({xmin} > {xmax} OR {xmax} >= {x0!r} OR {xmin} <= {x1!r})"
    return f"({lng} AND {ymin} <= {y1!r} AND {ymax} >= {y0!r})"
