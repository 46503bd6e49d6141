"""The DataFrame column forms of :mod:`dggs.spark`'s SQL functions: ``df.withColumn("cell", latlng_to_cell("lat", "lng", 12))``.

Each takes column names or Columns (literals where a value is constant) and calls the Arrow UDF that
:func:`dggs.spark.register` registers under the SQL name.
"""

from __future__ import annotations

from typing import Any

from pyspark.sql import Column
from pyspark.sql import functions as F

from dggs.spark.session import arrow_udf_of, check_on_invalid


def _col(value: Any) -> Any:
    """A column name or Column as a Column; anything else as a literal."""
    if isinstance(value, Column):
        return value
    if isinstance(value, str):
        return F.col(value)
    return F.lit(value)


def _lit(value: Any) -> Any:
    return value if isinstance(value, Column) else F.lit(value)


def _call(name: str, on_invalid: str, *args: Any) -> Any:
    return arrow_udf_of(name, check_on_invalid(on_invalid))(*args)


def latlng_to_cell(lat: Any, lng: Any, level: Any, *, on_invalid: str = "raise") -> Any:
    """Column of the int64 id of the cell at ``level`` holding each (lat, lng) (``dggs_latlng_to_cell``).

    ``lat``/``lng`` are column names or Columns, ``level`` an int or a Column.

    Raises
    ------
    DggsValueError
        If ``on_invalid`` is unknown (bad rows raise, when the job runs, :class:`dggs.CoordinateError`
        or :class:`dggs.LevelError` naming the row; see :func:`spark_errors`).

    Examples
    --------
    >>> df.withColumn("cell", latlng_to_cell("lat", "lng", 12))  # doctest: +SKIP
    """
    return _call("dggs_latlng_to_cell", on_invalid, _col(lat), _col(lng), _col(level))


def latlng_to_cell_str(lat: Any, lng: Any, level: Any, *, on_invalid: str = "raise") -> Any:
    """As :func:`latlng_to_cell`, giving string ids (``dggs_latlng_to_cell_str``)."""
    return _call("dggs_latlng_to_cell_str", on_invalid, _col(lat), _col(lng), _col(level))


def cell_to_parent(cell: Any, level: Any, *, on_invalid: str = "raise") -> Any:
    """Column of each cell's ancestor at ``level`` as an int64 id (``dggs_cell_to_parent``)."""
    return _call("dggs_cell_to_parent", on_invalid, _col(cell), _col(level))


def cell_to_parent_str(cell: Any, level: Any, *, on_invalid: str = "raise") -> Any:
    """As :func:`cell_to_parent`, giving string ids (``dggs_cell_to_parent_str``)."""
    return _call("dggs_cell_to_parent_str", on_invalid, _col(cell), _col(level))


def cell_to_children(cell: Any, level: Any, *, on_invalid: str = "raise") -> Any:
    """Column of arrays of each cell's descendants at ``level`` (``dggs_cell_to_children``)."""
    return _call("dggs_cell_to_children", on_invalid, _col(cell), _col(level))


def cell_to_latlng(cell: Any, *, on_invalid: str = "raise") -> Any:
    """Column of structs ``(lat, lng)``, each cell's centre (``dggs_cell_to_latlng``)."""
    return _call("dggs_cell_to_latlng", on_invalid, _col(cell))


def cell_to_boundary_wkb(cell: Any, *, on_invalid: str = "raise") -> Any:
    """Column of WKB (Multi)Polygons in lng/lat, each cell's boundary (``dggs_cell_to_boundary_wkb``)."""
    return _call("dggs_cell_to_boundary_wkb", on_invalid, _col(cell))


def grid_disk(cell: Any, k: Any, *, on_invalid: str = "raise") -> Any:
    """Column of arrays of the cells within ``k`` edge steps, sorted (``dggs_grid_disk``)."""
    return _call("dggs_grid_disk", on_invalid, _col(cell), _col(k))


def grid_path_cells(a: Any, b: Any, *, on_invalid: str = "raise") -> Any:
    """Column of arrays: a shortest path of edge neighbours from ``a`` to ``b``, both included (``dggs_grid_path_cells``)."""
    return _call("dggs_grid_path_cells", on_invalid, _col(a), _col(b))


def cells_to_polygons_wkb(cells: Any, *, on_invalid: str = "raise") -> Any:
    """Column of WKB outlines of each row's array of cells (``dggs_cells_to_polygons_wkb``; e.g. of ``collect_list``)."""
    return _call("dggs_cells_to_polygons_wkb", on_invalid, _col(cells))


def polygon_to_cells(wkb: Any, level: Any, mode: Any = "center", *, on_invalid: str = "raise") -> Any:
    """Column of arrays of the cells filling each WKB polygon (``dggs_polygon_to_cells``).

    ``wkb`` is a column name or Column (or WKB bytes), ``mode`` one of
    ``"center"``, ``"contains"``, ``"overlaps"`` (a literal) or a Column.
    """
    return _call("dggs_polygon_to_cells", on_invalid, _col(wkb), _col(level), _lit(mode))


def cell_area(cell: Any, *, on_invalid: str = "raise") -> Any:
    """Column of each cell's area in m² on WGS84 (``dggs_cell_area``)."""
    return _call("dggs_cell_area", on_invalid, _col(cell))


def get_level(cell: Any, *, on_invalid: str = "raise") -> Any:
    """Column of each cell's level (``dggs_get_level``)."""
    return _call("dggs_get_level", on_invalid, _col(cell))


def is_valid_cell(cell: Any) -> Any:
    """Column of booleans: is each id a well-formed cell (never raises; ``dggs_is_valid_cell``)."""
    return _call("dggs_is_valid_cell", "raise", _col(cell))


def str_to_int(cell: Any, *, on_invalid: str = "raise") -> Any:
    """Column of int64 ids (``dggs_str_to_int``)."""
    return _call("dggs_str_to_int", on_invalid, _col(cell))


def int_to_str(cell: Any, *, on_invalid: str = "raise") -> Any:
    """Column of string ids (``dggs_int_to_str``)."""
    return _call("dggs_int_to_str", on_invalid, _col(cell))
