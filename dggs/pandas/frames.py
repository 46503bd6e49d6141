"""The frame side of the ``df.dggs`` accessor: where its cells and coordinates come from, and errors naming rows.

Shared by :mod:`dggs.pandas` (the accessor) and :mod:`dggs.pandas.join`.
"""

from __future__ import annotations

import re
import sys
from typing import Any, NoReturn

import numpy as np
import pandas as pd
from pandas.core.groupby import SeriesGroupBy  # importable so in pandas 2.0 (pandas.api.typing has it from 2.1)

from dggs.errors import CoordinateError, DggsValueError
from dggs.index.hierarchy import get_level, is_valid_cell

__all__ = ["Cells", "ColumnError", "CrsError", "check_agg", "first_true", "in_wgs84", "one_column", "frame_coordinates", "geometry_name", "geopandas_module", "is_geo", "row_label"]

_CELL_COLUMN = re.compile(r"^cell_\d+$")


class ColumnError(DggsValueError):
    """A column the accessor needs is not in the frame (or the choice is ambiguous)."""


class CrsError(DggsValueError):
    """A geometry's CRS has no transformation to WGS84 (EPSG:4326), the grid's coordinates."""


def in_wgs84(geoms: Any) -> Any:
    """A GeoSeries in EPSG:4326: reprojected from its CRS (pyproj, through ``GeoSeries.to_crs``).

    A series without a CRS is taken as lng/lat degrees, as shapely geometries are.

    Raises
    ------
    CrsError
        The CRS has no transformation to EPSG:4326 (another body, a local engineering CRS).
    """
    crs = geoms.crs
    if crs is None or crs.equals("EPSG:4326"):
        return geoms
    from pyproj.exceptions import CRSError, ProjError

    try:
        return geoms.to_crs("EPSG:4326")
    except (CRSError, ProjError) as exc:
        raise CrsError(f"the geometry's CRS {crs.name!r} ({crs.to_string()}) has no transformation to EPSG:4326") from exc


def geopandas_module() -> Any:
    """geopandas, imported on first use (the 'pandas' extra), or an ImportError naming the extra."""
    try:
        import geopandas
    except ImportError as exc:  # pragma: no cover - exercised only without geopandas
        raise ImportError("this method needs geopandas: pip install 'dggs[pandas]'") from exc
    return geopandas


def is_geo(frame: pd.DataFrame) -> bool:
    """A GeoDataFrame with an active geometry column."""
    gpd = sys.modules.get("geopandas")
    if gpd is None or not isinstance(frame, gpd.GeoDataFrame):
        return False
    return geometry_name(frame) in frame.columns


def geometry_name(frame: Any) -> Any:
    """The name of a GeoDataFrame's active geometry column (None without one)."""
    return getattr(frame, "active_geometry_name", None)


def one_column(frame: pd.DataFrame, name: Any) -> pd.Series:
    """Column ``name``, which must be in the frame exactly once.

    Raises
    ------
    ColumnError
        ``name`` is not a column, or several columns have that name.
    """
    try:
        hash(name)
    except TypeError:  # a list or an array: no label of a column (pandas raises a raw TypeError on it)
        raise ColumnError(f"column {name!r} is not a column label (a str or another hashable label)") from None
    times = int((frame.columns == name).sum()) if name in frame.columns else 0
    if times == 0:
        raise ColumnError(f"column {name!r} is not in the frame (columns: {list(frame.columns)})")
    if times > 1:
        raise ColumnError(f"column {name!r} appears {times} times in the frame: rename the copies")
    column: pd.Series = frame[name]
    return column


def _agg_function(spec: Any, column: Any = None) -> None:
    """A function ``groupby(...).agg`` takes: a callable, or the name of a method of SeriesGroupBy."""
    where = f" for column {column!r}" if column is not None else ""
    if isinstance(spec, (list, tuple)):
        for one in spec:
            _agg_function(one, column)
    elif isinstance(spec, str):
        if spec.startswith("_") or not callable(getattr(SeriesGroupBy, spec, None)):
            raise DggsValueError(f"aggregation {spec!r}{where} is not a pandas groupby function (e.g. 'sum', 'mean')")
    elif not callable(spec):
        raise DggsValueError(f"aggregation {spec!r}{where} is neither a function nor a function's name")


def check_agg(agg: Any, columns: pd.Index, key: Any) -> None:
    """Check an ``agg`` for :meth:`DggsAccessor.aggregate` before pandas runs it.

    pandas answers an unknown function name with AttributeError and an unknown
    column with KeyError; this names the bad value in a typed error instead.

    Raises
    ------
    ColumnError
        A dict key that is not one of the aggregated columns (the cell column ``key`` is not one).
    DggsValueError
        A function that is neither callable nor a groupby function's name.
    """
    if not isinstance(agg, dict):
        _agg_function(agg)
        return
    for column, spec in agg.items():
        if column not in columns:
            what = "the cell column, the groupby key" if column == key else "not a column of the frame"
            raise ColumnError(f"aggregation column {column!r} is {what} (columns: {list(columns)})")
        _agg_function(spec, column)


def frame_coordinates(frame: pd.DataFrame, name: str) -> np.ndarray:
    """Column ``name`` as float64 (missing values as NaN); CoordinateError naming a non-numeric row.

    Raises
    ------
    ColumnError
        ``name`` is not a column, or appears more than once.
    CoordinateError
        A value that is not a number (names the row).
    """
    col = one_column(frame, name)
    complex_ = pd.api.types.is_complex_dtype(col.dtype)  # to float64 would drop the imaginary part, silently
    if pd.api.types.is_numeric_dtype(col.dtype) and not pd.api.types.is_bool_dtype(col.dtype) and not complex_:
        numbers: np.ndarray = col.to_numpy(dtype=np.float64, na_value=np.nan)  # pandas is untyped here
        return numbers
    values = pd.to_numeric(col, errors="coerce") if not complex_ else col
    not_numbers = (bool, np.bool_, complex, np.complexfloating, bytes, bytearray)  # as the core: no booleans, ...
    bad = values.isna() & col.notna() | col.map(lambda v: isinstance(v, not_numbers)).astype(bool)
    if bad.any():
        i = int(np.flatnonzero(bad.to_numpy())[0])
        raise CoordinateError(f"{name} {col.iloc[i]!r} in row {row_label(frame, i)} is not a number")
    coerced: np.ndarray = values.to_numpy(dtype=np.float64, na_value=np.nan)
    return coerced


def row_label(frame_or_index: Any, i: int) -> str:
    """The repr of row ``i``'s label, numpy scalars as plain Python values."""
    index = frame_or_index.index if hasattr(frame_or_index, "columns") else frame_or_index
    label = index[i]
    return repr(label.item() if isinstance(label, np.generic) else label)


def first_true(mask: np.ndarray) -> int | None:
    """The position of the first ``True`` of ``mask``, or ``None``."""
    hits = np.flatnonzero(mask)
    return int(hits[0]) if hits.size else None


def column_ids(values: pd.Series) -> np.ndarray:
    """A column (or index) of ids as numpy, exactly: strings as objects, integers as integers.

    A nullable integer column (``UInt64``, ``Int64``, ``uint64[pyarrow]``) with a missing value goes as
    objects (Python ints and None), never through float64, which rounds every 64-bit id (and then an error
    would name a valid neighbour as ``4.99e+18`` instead of the missing value, at the wrong row).
    """
    dt = values.dtype
    if dt == np.dtype("O") or isinstance(dt, pd.StringDtype):
        return values.to_numpy(dtype=object)
    if isinstance(dt, pd.api.extensions.ExtensionDtype) and dt.kind in "iu":
        if values.isna().any():
            return values.to_numpy(dtype=object, na_value=None)
        return values.to_numpy(dtype=np.uint64 if dt.kind == "u" else np.int64)
    return values.to_numpy()


class Cells:
    """The cell ids a method reads: a column or the index, with its values and labels."""

    def __init__(self, frame: pd.DataFrame, column: str | None):
        if column is None:
            found = [c for c in frame.columns if isinstance(c, str) and _CELL_COLUMN.match(c)]
            if len(found) > 1:
                raise ColumnError(f"several cell columns {found}: pass column=")
            column = found[0] if found else None
        self.column = column
        self.labels = frame.index
        self.values = one_column(frame, column) if column is not None else frame.index.to_series()
        self.ids: Any = column_ids(self.values)
        self.where = f"column {column!r}" if column is not None else "the index (no cell_<level> column; pass column=)"

    def reraise(self, exc: DggsValueError, level: int | None = None) -> NoReturn:
        """Raise ``exc`` again, naming the row label of the first bad id."""
        bad = first_true(~np.asarray(is_valid_cell(self.ids), dtype=bool))
        if bad is None and level is not None:
            bad = first_true(np.asarray(get_level(self.ids)) < level)
        if bad is None:
            raise exc
        raise type(exc)(f"{exc} (row {row_label(self.labels, bad)}, {self.where})") from exc
