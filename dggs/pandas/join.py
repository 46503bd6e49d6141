"""``df.dggs.sjoin_cells``: join points to polygon features through the cells of one level.

The grid's answer to a spatial join, as h3-based pipelines do it: each point
gets its cell at ``level``, each polygon feature its cells at ``level``
(:func:`dggs.polygon_to_cells` in the chosen ``mode``), and the two frames are
joined on equal cell ids, a hash join with no geometry test per pair.  The
result is exact at the cells' resolution:

* ``mode="center"``: a point joins a polygon whose cell set holds the point's
  cell, that is, when the centre of the point's cell lies in the polygon;
* ``mode="overlaps"``: every polygon touching the point's cell joins, so no
  point inside a polygon is missed (candidates, to be refined with an exact
  predicate where needed);
* ``mode="contains"``: only polygons that hold the point's whole cell join, so
  no joined point lies outside its polygon.

Part of the ``dggs.pandas`` accessor (``import dggs.pandas``).
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pandas as pd

from dggs.errors import DggsValueError
from dggs.index._checks import is_choice
from dggs.index.hierarchy import cell_to_parent
from dggs.index.ids import check_level, int_to_str, str_to_int
from dggs.pandas.frames import Cells

__all__ = ["sjoin_cells"]

_HOW = ("inner", "left")


def _suffixed(right: pd.DataFrame, taken: pd.Index, key: str, rsuffix: str) -> pd.DataFrame:
    """The polygons' columns as they join: the index as ``index_{rsuffix}``, clashes with ``_{rsuffix}``.

    As :func:`geopandas.sjoin` names them, but a suffixed name that is itself
    taken is refused rather than duplicated or overwritten (the rule pandas'
    ``merge`` follows since 2.0, raising ``MergeError``).

    Raises
    ------
    DggsValueError
        ``index_{rsuffix}`` or a suffixed polygon column is already a column (names it).
    """
    if isinstance(right.index, pd.MultiIndex):  # one column a level, as geopandas.sjoin keeps them
        index = [n if n is not None else f"index_{rsuffix}{i}" for i, n in enumerate(right.index.names)]
    else:
        right.index.name = None
        index = [f"index_{rsuffix}"]
    clash = [c for c in right.columns if c != key and c in taken]
    names = {c: f"{c}_{rsuffix}" for c in clash}
    final = index + [names.get(c, c) for c in right.columns if c != key]  # the key is joined on
    for name in final:
        if name in taken or final.count(name) > 1:
            raise DggsValueError(
                f"the join would give two columns {name!r} (this frame's {list(taken)}, the polygons' "
                f"{list(right.columns)}): pass another rsuffix than {rsuffix!r}, or rename the column"
            )
    return right.rename(columns=names).reset_index(names=index if len(index) > 1 else index[0])


def sjoin_cells(
    self: Any,
    polygons: Any,
    level: int,
    mode: str = "center",
    how: str = "inner",
    lat: str = "lat",
    lng: str = "lng",
    column: str | None = None,
    rsuffix: str = "right",
    cells: str | None = None,
) -> pd.DataFrame:
    """Join this frame's points to the (Multi)Polygon features of ``polygons`` through their cells.

    Parameters
    ----------
    polygons : GeoDataFrame
        Polygon features (any CRS with a transformation to EPSG:4326; filled there).
    level : int
        The cells' level: the join's resolution (see :func:`dggs.cell_area`).
    mode : {"center", "contains", "overlaps"}
        Which cells a polygon has (module docstring): ``"overlaps"`` never
        misses a point inside a polygon, ``"contains"`` never joins one outside.
    how : {"inner", "left"}
        Keep only joined points, or every point (the polygon's columns empty
        where none joins).
    lat, lng : str
        This frame's coordinate columns (a GeoDataFrame of points may use its
        geometry instead, as :meth:`DggsAccessor.latlng_to_cell` does).
    column : str, optional
        Name of the cell column in the result (default ``f"cell_{level}"``).
    rsuffix : str
        Suffix for polygon columns whose names this frame has too, and for
        the polygons' index, kept as column ``index_{rsuffix}`` (as
        :func:`geopandas.sjoin` names it; a MultiIndex as one column a level,
        named after the level, or ``index_{rsuffix}<i>`` for an unnamed one).  This frame's columns keep their
        names; a suffixed name that is already taken is refused, never
        overwritten.
    cells : str, optional
        A column of the points' cells (str or int ids, ``level`` or finer, as
        binned before): joined through their parents at ``level`` (a bit mask
        a cell) instead of binning ``lat``/``lng`` again (a projection a point).

    Returns
    -------
    DataFrame (GeoDataFrame for a GeoDataFrame of points)
        One row per joined (point, polygon) pair, the point's index kept;
        points in overlapping polygons appear once per polygon.

    Raises
    ------
    DggsValueError
        An unknown ``mode`` or ``how``, bad points or polygons (naming the row), or
        a suffixed column name that is already taken (naming it).
    CrsError
        Points or polygons in a CRS without a transformation to EPSG:4326 (names the CRS).
    ColumnError, InvalidCellError, LevelMismatchError
        ``cells`` is not a column, holds a bad id, or one coarser than ``level`` (naming it).

    Examples
    --------
    >>> import geopandas as gpd
    >>> import pandas as pd
    >>> from shapely.geometry import box
    >>> import dggs.pandas
    >>> points = pd.DataFrame({"lat": [5.0, 45.0, -30.0], "lng": [5.0, 10.0, 150.0]}, index=["a", "b", "c"])
    >>> zones = gpd.GeoDataFrame({"zone": ["west", "east"]}, geometry=[box(0, 0, 20, 50), box(140, -40, 160, -20)])
    >>> joined = points.dggs.sjoin_cells(zones, 6)
    >>> joined["zone"].to_dict()
    {'a': 'west', 'b': 'west', 'c': 'east'}
    >>> points.dggs.sjoin_cells(zones.iloc[:1], 6, how="left")["zone"].isna().tolist()
    [False, False, True]
    >>> binned = points.dggs.latlng_to_cell(12, as_int=True, column="cell")  # ids binned before
    >>> binned.dggs.sjoin_cells(zones, 6, cells="cell")["zone"].to_dict()
    {'a': 'west', 'b': 'west', 'c': 'east'}
    """
    if not is_choice(how, _HOW):
        raise DggsValueError(f"how {how!r} is not one of {', '.join(_HOW)}")
    if not isinstance(polygons, pd.DataFrame):
        raise DggsValueError(f"polygons must be a GeoDataFrame of (Multi)Polygons, not a {type(polygons).__name__}")
    key = column if column is not None else f"cell_{level}"
    if cells is None:
        left = self.latlng_to_cell(level, lat=lat, lng=lng, column=key, as_int=True)
    else:
        level = check_level(level)
        given = Cells(self._df, cells)
        try:
            parents = cell_to_parent(str_to_int(given.ids), level)  # either form in, integer ids out
        except DggsValueError as exc:
            given.reraise(exc, level)  # naming the row label of the first bad id
        left = self._df.assign(**{key: parents})
    filled = polygons.dggs.polyfill(level, mode=mode, column=key, as_int=True)
    right = _suffixed(pd.DataFrame(filled.drop(columns=filled.geometry.name)), left.columns, key, rsuffix)
    row = "_row"  # the points' positions, under a name no polygon column has
    while row in right.columns:
        row += "_"
    pairs = pd.DataFrame({key: left[key].to_numpy(), row: np.arange(len(left))}).merge(
        right, on=key, how=how, sort=False
    )
    rows = pairs.pop(row).to_numpy()
    if rows.shape[0] > 1 and not bool(np.all(rows[1:] >= rows[:-1])):  # pandas keeps the left order: checked
        pairs = pairs.iloc[np.argsort(rows, kind="stable")]
        rows = np.sort(rows, kind="stable")
    out = left.iloc[rows]  # the points' index, columns (and geometry) kept
    extra = {c: pairs[c].array for c in pairs.columns if c != key}  # as they are: no str column made objects
    return out.assign(**extra, **{key: _text(out[key].to_numpy(dtype=np.uint64))})


def _text(ids: np.ndarray) -> Any:
    """String ids as a pandas ``str`` column: from a pyarrow string array on pandas 3 (no Python strings)."""
    if int(pd.__version__.split(".")[0]) >= 3:
        import pyarrow as pa

        return pd.array(int_to_str(pa.array(ids)), dtype="str")
    return pd.array(np.asarray(int_to_str(ids), dtype=object), dtype="str")
