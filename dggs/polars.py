"""dggs verbs on polars columns: ``pl.col("cell").dggs.cell_to_parent(5)``, and polars in, polars out.

Every dggs function already takes a polars Series and gives one back (of the
same name); this module adds a ``dggs`` namespace to polars expressions (and
Series), for use inside ``select``, ``with_columns``, ``filter`` and lazy
queries, as polars-h3 and h3ronpy.polars do for H3.  Importing it registers
the namespace (``import dggs.polars``); ``import dggs`` alone never imports polars.

Each method runs the module-level function of the same name on the column's
batches (``Expr.map_batches``, element-wise, so it is safe in ``over`` and
``group_by`` contexts) and declares its output type, so lazy queries know
their schema.  Ids may be strings or 64-bit integers; id outputs keep the
input's type.

Examples
--------
>>> import polars as pl
>>> import dggs.polars
>>> df = pl.DataFrame({"cell": ["C401", "B100"]})
>>> df.select(pl.col("cell").dggs.cell_to_parent().alias("parent"), pl.col("cell").dggs.get_level())["parent"].to_list()
['C40', 'B10']
>>> df.select(dggs.polars.latlng_to_cell(pl.lit(51.05), pl.lit(-114.07), 3))["cell"].to_list()
['F200']
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np
import polars as pl

# Imported whole before any batch runs: polars runs the batches on its own threads, and a module another thread
# is still importing (pyarrow imports pandas lazily) would be seen half-initialised by the converters.
import pyarrow  # noqa: F401

import dggs

try:
    import pandas  # noqa: F401
except ImportError:  # pragma: no cover - pandas is optional for polars users
    pass

__all__ = ["DggsExpr", "DggsSeries", "latlng_to_cell", "VERBS"]

_LATLNG = pl.Struct({"lat": pl.Float64, "lng": pl.Float64})


def _same(expr: pl.Expr) -> Any:
    return pl.dtype_of(expr)


def _center_child(s: pl.Series, level: int | None) -> pl.Series:
    """:func:`dggs.cell_to_center_child`, ``level=None`` one level down from each cell.

    (Of a whole array, ``level=None`` is one below the array's finest cell; polars cuts a column into
    batches as it likes, so here each cell goes one level down, as a single id does.)
    """
    if level is not None or len(s) == 0:
        return dggs.cell_to_center_child(s, level)
    levels = np.asarray(dggs.get_level(s).to_numpy())
    out = s.clone()
    for lv in np.unique(levels).tolist():
        at = np.flatnonzero(levels == lv)
        out.scatter(at, dggs.cell_to_center_child(s.gather(at), lv + 1))
    return out


def _cell_areas(s: pl.Series, unit: str) -> Any:
    """:func:`dggs.cell_area` of ids only, checked as cells first.

    ``cell_area`` reads a small integer as a level: a column of 0, 1 gave the mean areas of levels 0 and 1.
    """
    dggs.get_level(s)  # raises InvalidCellError naming the first value that is no cell id
    return dggs.cell_area(s, unit)


#: The verbs of the namespace: name -> (function of a Series and the arguments, output type of the input expr).
VERBS: dict[str, tuple[Callable[..., Any], Callable[[pl.Expr], Any]]] = {
    "str_to_int": (lambda s: dggs.str_to_int(s).cast(pl.UInt64), lambda e: pl.UInt64),
    "int_to_str": (lambda s: dggs.int_to_str(s).cast(pl.String), lambda e: pl.String),
    "is_valid_cell": (dggs.is_valid_cell, lambda e: pl.Boolean),
    "get_level": (dggs.get_level, lambda e: pl.Int64),
    "get_face": (dggs.get_face, lambda e: pl.Int64),
    "cell_area": (lambda s, unit="m^2": _cell_areas(s, unit), lambda e: pl.Float64),
    "cell_to_parent": (lambda s, level=None: dggs.cell_to_parent(s, level), _same),
    "cell_to_center_child": (lambda s, level=None: _center_child(s, level), _same),
    "cell_to_latlng": (lambda s: pl.struct(*(pl.lit(v).alias(k) for k, v in zip(("lat", "lng"), dggs.cell_to_latlng(s), strict=True)), eager=True),
                       lambda e: _LATLNG),
    "cell_to_polygon": (lambda s, densify=None: dggs.cell_to_polygon(s, densify), lambda e: pl.Binary),
    "grid_disk": (lambda s, k=1: dggs.grid_disk(s, k), lambda e: pl.dtype_of(e).wrap_in_list()),
    "grid_ring": (lambda s, k=1: dggs.grid_ring(s, k), lambda e: pl.dtype_of(e).wrap_in_list()),
}


def _batch(fn: Callable[..., Any], args: tuple, name: str) -> Callable[[pl.Series], pl.Series]:
    def run(s: pl.Series) -> pl.Series:
        out = fn(s, *args)
        return out.rename(name) if isinstance(out, pl.Series) else out

    return run


@pl.api.register_expr_namespace("dggs")
class DggsExpr:
    """``pl.col(...).dggs``: the dggs verbs on an expression of cell ids (see :data:`VERBS`).

    Examples
    --------
    >>> pl.DataFrame({"cell": ["C401"]}).select(pl.col("cell").dggs.grid_disk(1))["cell"].list.len().to_list()
    [4]
    """

    def __init__(self, expr: pl.Expr) -> None:
        self._expr = expr

    def _map(self, verb: str, *args: Any) -> pl.Expr:
        fn, dtype = VERBS[verb]
        name = self._expr.meta.output_name(raise_if_undetermined=False) or ""
        return self._expr.map_batches(_batch(fn, args, name), return_dtype=dtype(self._expr), is_elementwise=True)

    def str_to_int(self) -> pl.Expr:
        """:func:`dggs.str_to_int`: string ids to their 64-bit integer form (``UInt64``)."""
        return self._map("str_to_int")

    def int_to_str(self) -> pl.Expr:
        """:func:`dggs.int_to_str`: integer ids to their string form."""
        return self._map("int_to_str")

    def is_valid_cell(self) -> pl.Expr:
        """:func:`dggs.is_valid_cell` (never raises; ``Boolean``)."""
        return self._map("is_valid_cell")

    def get_level(self) -> pl.Expr:
        """:func:`dggs.get_level` (``Int64``)."""
        return self._map("get_level")

    def get_face(self) -> pl.Expr:
        """:func:`dggs.get_face` (``Int64``)."""
        return self._map("get_face")

    def cell_area(self, unit: str = "m^2") -> pl.Expr:
        """:func:`dggs.cell_area` in ``unit`` (``Float64``)."""
        return self._map("cell_area", unit)

    def cell_to_parent(self, level: int | None = None) -> pl.Expr:
        """:func:`dggs.cell_to_parent` at ``level`` (default one up), in the ids' own type."""
        return self._map("cell_to_parent", level)

    def cell_to_center_child(self, level: int | None = None) -> pl.Expr:
        """:func:`dggs.cell_to_center_child` at ``level`` (default one down)."""
        return self._map("cell_to_center_child", level)

    def cell_to_latlng(self) -> pl.Expr:
        """:func:`dggs.cell_to_latlng` as a struct ``{lat, lng}`` (degrees)."""
        return self._map("cell_to_latlng")

    def cell_to_polygon(self, densify: int | None = None) -> pl.Expr:
        """:func:`dggs.cell_to_polygon` as WKB (``Binary``, the bytes :mod:`dggs.arrow` writes)."""
        return self._map("cell_to_polygon", densify)

    def grid_disk(self, k: int = 1) -> pl.Expr:
        """:func:`dggs.grid_disk`: the cells within ``k`` steps, a list per row."""
        return self._map("grid_disk", k)

    def grid_ring(self, k: int = 1) -> pl.Expr:
        """:func:`dggs.grid_ring`: the cells exactly ``k`` steps away, a list per row."""
        return self._map("grid_ring", k)


@pl.api.register_series_namespace("dggs")
class DggsSeries:
    """``series.dggs``: the verbs of :class:`DggsExpr` on a Series (each is the module-level function).

    Examples
    --------
    >>> pl.Series("cell", ["C401"]).dggs.get_level().to_list()
    [3]
    """

    def __init__(self, series: pl.Series) -> None:
        self._series = series

    def __getattr__(self, verb: str) -> Callable[..., pl.Series]:
        if verb not in VERBS:
            raise AttributeError(f"polars Series have no dggs verb {verb!r}; the verbs are {', '.join(VERBS)}")

        def call(*args: Any) -> pl.Series:
            expr = DggsExpr(pl.lit(self._series))
            return pl.select(getattr(expr, verb)(*args)).to_series()

        return call


def _degrees(s: pl.Series, name: str) -> pl.Series:
    """A coordinate column as Float64, or a CoordinateError naming its first value.

    polars' own cast raised its raw InvalidOperationError on text, and read booleans as 0 and 1.
    """
    if not s.dtype.is_numeric():
        first = next((v for v in s.to_list() if v is not None), None)
        lat_or_lng = "latitude" if name == "lat" else "longitude"
        raise dggs.CoordinateError(f"{lat_or_lng} {first!r} is not a number (a {s.dtype} column)")
    return s.cast(pl.Float64)


def latlng_to_cell(lat: str | pl.Expr, lng: str | pl.Expr, level: int, as_int: bool = False) -> pl.Expr:
    """:func:`dggs.latlng_to_cell` of two columns (names or expressions), as an expression named ``cell``.

    Examples
    --------
    >>> pl.DataFrame({"lat": [0.0], "lng": [0.0]}).select(latlng_to_cell("lat", "lng", 2))["cell"].to_list()
    ['C32']
    """
    lat_e, lng_e = (pl.col(c) if isinstance(c, str) else c for c in (lat, lng))

    def run(s: pl.Series) -> pl.Series:
        lat_s, lng_s = (_degrees(s.struct.field(f), f) for f in ("lat", "lng"))
        return dggs.latlng_to_cell(lat_s, lng_s, level, as_int).rename("cell")

    both = pl.struct(lat_e.alias("lat"), lng_e.alias("lng"))
    return both.map_batches(run, return_dtype=pl.UInt64 if as_int else pl.String, is_elementwise=True).alias("cell")
