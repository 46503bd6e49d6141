"""The per-cell verbs of the ``df.dggs`` accessor, as broad as h3pandas's (issue 36), in dggs's names.

Each method is one vectorized call of the module-level function it is named
after, on the frame's cell column (``column=None``: the only ``cell_<level>``
column, else the index), and returns a new frame with the same index and
rows plus the answer's column(s); ``explode=True`` gives one row per cell of
a list answer instead.  A bad id raises the function's typed error naming
the row label.  :class:`CellVerbs` is mixed into :class:`dggs.pandas.DggsAccessor`.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pandas as pd

from dggs.errors import DggsValueError, InvalidCellError, LevelError, LevelMismatchError
from dggs.index._checks import check_level
from dggs.index.grid import grid_disk, grid_ring
from dggs.index.hierarchy import (
    cell_to_center_child,
    cell_to_children,
    cell_to_parent,
    get_face,
    get_level,
    is_valid_cell,
)
from dggs.index.measure import cell_area
from dggs.index.paths import line_to_cells
from dggs.index.points import cell_to_latlng
from dggs.pandas.frames import Cells, ColumnError, geometry_name, geopandas_module, in_wgs84, is_geo, row_label

__all__ = ["CellVerbs"]

_ERRORS = (InvalidCellError, LevelMismatchError)


def _explode(frame: pd.DataFrame, lists: list[Any], name: str) -> pd.DataFrame:
    """One row per element of each row's list (the row's other columns repeated, its index label kept)."""
    counts = np.fromiter((len(x) for x in lists), dtype=np.int64, count=len(lists))
    out = frame.iloc[np.repeat(np.arange(len(frame)), counts)]
    flat = [v for x in lists for v in x]
    return out.assign(**{name: pd.Series(flat, index=out.index, dtype=object if not flat or isinstance(flat[0], str) else np.uint64)})


def _cell_areas(ids: Any, unit: str) -> Any:
    """:func:`dggs.cell_area` of ids only, checked as cells first.

    ``cell_area`` reads a small integer as a level: an index 0, 1, ... of a frame without a cell column gave the
    mean areas of levels 0, 1, ...
    """
    get_level(ids)  # raises InvalidCellError naming the first value that is no cell id
    return cell_area(ids, unit)


class CellVerbs:
    """The accessor's per-cell verbs (h3pandas's names in the docs' table, docs/pandas.md)."""

    _df: pd.DataFrame

    def aggregate(self, level: int, agg: Any = None, column: str | None = None) -> pd.DataFrame:
        """Roll the frame up to ``level``: defined by :class:`dggs.pandas.DggsAccessor`, which these verbs join."""
        raise NotImplementedError

    def _call(self, fn: Any, column: str | None, *args: Any, level: int | None = None) -> tuple[Cells, Any]:
        cells = Cells(self._df, column)
        try:
            return cells, fn(cells.ids, *args) if len(self._df) else np.array([], dtype=object)
        except _ERRORS as exc:
            cells.reraise(exc, level)

    def get_level(self, column: str | None = None) -> pd.DataFrame:
        """The frame with a column ``level``: :func:`dggs.get_level` of each row's cell.

        Examples
        --------
        >>> import dggs.pandas
        >>> pd.DataFrame({"cell_3": ["C401", "B10"]}).dggs.get_level()["level"].tolist()
        [3, 2]
        """
        _, out = self._call(get_level, column)
        return self._df.assign(level=np.asarray(out, dtype=np.int64))

    def get_face(self, column: str | None = None) -> pd.DataFrame:
        """The frame with a column ``face``: :func:`dggs.get_face` (0..19, the icosahedron face; h3's base cell)."""
        _, out = self._call(get_face, column)
        return self._df.assign(face=np.asarray(out, dtype=np.int64))

    def is_valid_cell(self, column: str | None = None) -> pd.DataFrame:
        """The frame with a bool column ``is_valid``: :func:`dggs.is_valid_cell` (never raises)."""
        cells = Cells(self._df, column)
        return self._df.assign(is_valid=np.asarray(is_valid_cell(cells.ids), dtype=bool))

    def cell_area(self, unit: str = "km^2", column: str | None = None) -> pd.DataFrame:
        """The frame with a column ``cell_area``: :func:`dggs.cell_area` in ``unit`` (default km^2, as h3pandas)."""
        _, out = self._call(lambda ids: _cell_areas(ids, unit), column)
        return self._df.assign(cell_area=np.asarray(out, dtype=float))

    def cell_to_latlng(self, column: str | None = None) -> pd.DataFrame:
        """The frame with columns ``lat`` and ``lng``: :func:`dggs.cell_to_latlng`, each cell's centre (degrees)."""
        _, out = self._call(cell_to_latlng, column)
        lat, lng = (np.asarray(v, dtype=float) for v in out) if len(self._df) else (np.zeros(0), np.zeros(0))
        return self._df.assign(lat=lat, lng=lng)

    def cell_to_point(self, column: str | None = None) -> Any:
        """A GeoDataFrame (EPSG:4326) whose geometry is each cell's centre point (h3pandas's ``h3_to_geo``).

        Examples
        --------
        >>> import pandas as pd, dggs.pandas
        >>> g = pd.DataFrame({"cell_3": ["C401"]}).dggs.cell_to_point()
        >>> g.geom_type.tolist(), g.crs.to_epsg()
        (['Point'], 4326)
        """
        gpd = geopandas_module()
        frame = self.cell_to_latlng(column)
        data = pd.DataFrame(self._df)
        if is_geo(self._df):
            data = data.drop(columns=[geometry_name(self._df)])
        points = gpd.points_from_xy(frame["lng"], frame["lat"], crs="EPSG:4326")
        return gpd.GeoDataFrame(data, geometry=gpd.GeoSeries(points, index=self._df.index), crs="EPSG:4326")

    def cell_to_parent(self, level: int | None = None, column: str | None = None) -> pd.DataFrame:
        """The frame with each cell's parent (:func:`dggs.cell_to_parent`) in a column ``cell_<level>``.

        ``level=None``: one level up from each cell, in a column ``parent``.

        Examples
        --------
        >>> import pandas as pd, dggs.pandas
        >>> pd.DataFrame({"cell_3": ["C401"]}).dggs.cell_to_parent(1)["cell_1"].tolist()
        ['C4']
        """
        level = None if level is None else check_level(level)
        _, out = self._call(lambda ids: cell_to_parent(ids, level), column, level=level)
        return self._df.assign(**{"parent" if level is None else f"cell_{level}": np.asarray(out)})

    def cell_to_center_child(self, level: int | None = None, column: str | None = None) -> pd.DataFrame:
        """The frame with each cell's centre child (:func:`dggs.cell_to_center_child`) in a column ``cell_<level>``.

        ``level=None``: one level down from each cell, in a column ``center_child``.
        """
        if level is None:
            cells = Cells(self._df, column)
            try:
                out = [cell_to_center_child(c) for c in np.asarray(cells.ids).tolist()]  # one down from each cell
            except _ERRORS as exc:
                cells.reraise(exc)
            return self._df.assign(center_child=np.asarray(out) if out else np.array([], dtype=object))
        level = check_level(level)
        _, out = self._call(lambda ids: cell_to_center_child(ids, level), column)
        return self._df.assign(**{f"cell_{level}": np.asarray(out)})

    def cell_to_children(self, level: int, column: str | None = None) -> pd.DataFrame:
        """One row per child at ``level`` of each row's cell (:func:`dggs.cell_to_children`).

        The children are in a column ``cell_<level>``; the row's other columns and index label are repeated.

        Examples
        --------
        >>> import pandas as pd, dggs.pandas
        >>> pd.DataFrame({"cell_3": ["C401"], "v": [1]}).dggs.cell_to_children(4)["cell_4"].tolist()
        ['C4010', 'C4011', 'C4012']
        """
        level = check_level(level)
        cells = Cells(self._df, column)
        ids = np.asarray(cells.ids)
        try:
            lists = [list(cell_to_children(c, level)) for c in ids.tolist()]
        except _ERRORS as exc:
            cells.reraise(exc, None)
        return _explode(self._df, lists, f"cell_{level}")

    def _disk(self, fn: Any, name: str, k: int, column: str | None, explode: bool) -> pd.DataFrame:
        cells = Cells(self._df, column)
        try:
            rows = fn(list(np.asarray(cells.ids).tolist()), k) if len(self._df) else []
        except _ERRORS as exc:
            cells.reraise(exc)
        lists = [list(r) for r in rows]
        if explode:
            return _explode(self._df, lists, name)
        return self._df.assign(**{name: pd.Series(lists, index=self._df.index, dtype=object)})

    def grid_disk(self, k: int = 1, column: str | None = None, explode: bool = False) -> pd.DataFrame:
        """Each cell's :func:`dggs.grid_disk` (the cells within ``k`` steps) as a list column ``grid_disk``.

        ``explode=True``: one row per disk cell instead (h3pandas's ``k_ring``).

        Examples
        --------
        >>> import pandas as pd, dggs.pandas
        >>> len(pd.DataFrame({"cell_3": ["C401"]}).dggs.grid_disk(1)["grid_disk"].iloc[0])
        4
        """
        return self._disk(grid_disk, "grid_disk", k, column, explode)

    def grid_ring(self, k: int = 1, column: str | None = None, explode: bool = False) -> pd.DataFrame:
        """Each cell's :func:`dggs.grid_ring` (the cells exactly ``k`` steps away) as a list column ``grid_ring``.

        ``explode=True``: one row per ring cell instead (h3pandas's ``hex_ring``).
        """
        return self._disk(grid_ring, "grid_ring", k, column, explode)

    def linetrace(self, level: int, explode: bool = False, as_int: bool = False) -> Any:
        """The cells along each (Multi)LineString feature of a GeoDataFrame, in order (:func:`dggs.line_to_cells`).

        A list column ``cell_<level>``, or one row per cell with ``explode=True`` (h3pandas's ``linetrace``);
        a geometry with a CRS is reprojected to EPSG:4326 first.

        Raises
        ------
        ColumnError
            The frame is no GeoDataFrame.
        DggsValueError
            A geometry that is no (Multi)LineString (names the row).
        """
        level = check_level(level)
        df = self._df
        if not is_geo(df):
            raise ColumnError("linetrace needs a GeoDataFrame with an active geometry column")
        lists: list[Any] = []
        for i, geom in enumerate(in_wgs84(df.geometry).array):
            if geom is None or geom.is_empty:
                lists.append([])
                continue
            if geom.geom_type not in ("LineString", "MultiLineString"):
                raise DggsValueError(f"row {row_label(df, i)}: a {geom.geom_type} is not a LineString or MultiLineString")
            lists.append(np.asarray(line_to_cells(geom, level, as_int)).tolist())
        name = f"cell_{level}"
        if explode:
            return _explode(df, lists, name)
        return df.assign(**{name: pd.Series(lists, index=df.index, dtype=object)})

    def disk_smoothing(self, k: int = 1, columns: Any = None, column: str | None = None) -> pd.DataFrame:
        """Spread each row's numbers evenly over its cell's ``grid_disk(k)`` and sum them per cell.

        h3pandas's ``k_ring_smoothing`` (uniform weights): a row of value ``v``
        whose disk holds ``n`` cells gives ``v / n`` to each of them, so each
        column's total is kept.  ``columns``: the numeric columns to spread (default
        every numeric column but the cells').  Returns a frame indexed by cell
        (index name ``cell``), sorted.

        Examples
        --------
        >>> import pandas as pd, dggs.pandas
        >>> out = pd.DataFrame({"cell_3": ["C401"], "v": [4.0]}).dggs.disk_smoothing(1)
        >>> out["v"].tolist(), float(out["v"].sum())
        ([1.0, 1.0, 1.0, 1.0], 4.0)
        """
        cells = Cells(self._df, column)
        data = pd.DataFrame(self._df)
        if columns is None:
            columns = [c for c in data.select_dtypes("number").columns if c != cells.column]
        missing = [c for c in columns if c not in data.columns]
        if missing:
            raise ColumnError(f"columns {missing} are not in the frame (columns: {list(data.columns)})")
        disks = self.grid_disk(k, column)["grid_disk"].tolist()
        sizes = np.fromiter((len(d) for d in disks), dtype=np.int64, count=len(disks))
        spread = data[list(columns)].to_numpy(dtype=float) / np.maximum(sizes, 1)[:, None]
        flat = [c for d in disks for c in d]
        out = pd.DataFrame(np.repeat(spread, sizes, axis=0), columns=list(columns))
        out.insert(0, "cell", flat)
        return out.groupby("cell", sort=True).sum()

    def resample(self, level: int, agg: Any = None, divide: Any = (), column: str | None = None) -> pd.DataFrame:
        """The frame resampled to ``level``: rolled up to coarser cells, or split into finer ones.

        Coarser: :meth:`aggregate` with ``agg``.  Finer: each row becomes its
        children (:func:`dggs.cell_to_children`), the row's values copied, or
        divided evenly among the children for the ``divide`` columns (counts,
        sums: quantities that add up).

        Returns a frame indexed by the cells at ``level`` (index name ``cell_<level>``).

        Raises
        ------
        LevelError
            ``level`` outside 0..MAX_LEVEL, or cells at several levels, some finer and some coarser than it.

        Examples
        --------
        >>> import pandas as pd, dggs.pandas
        >>> df = pd.DataFrame({"cell_3": ["C401"], "pop": [9.0], "density": [2.0]})
        >>> df.dggs.resample(4, divide=["pop"]).to_dict()
        {'pop': {'C4010': 3.0, 'C4011': 3.0, 'C4012': 3.0}, 'density': {'C4010': 2.0, 'C4011': 2.0, 'C4012': 2.0}}
        """
        level = check_level(level)
        cells = Cells(self._df, column)
        try:
            levels = np.asarray(get_level(cells.ids)) if len(self._df) else np.zeros(0, dtype=np.int64)
        except _ERRORS as exc:
            cells.reraise(exc)
        if not (levels < level).any():
            return self.aggregate(level, agg, column)
        if (levels > level).any():
            raise LevelError(f"cells at levels {sorted(set(levels.tolist()))}: resample to {level} goes up for some and "
                             "down for others; resample each level apart")
        name = f"cell_{level}"
        out = self.cell_to_children(level, column)
        counts = out.groupby(level=0, sort=False)[name].transform("size").to_numpy() if len(out) else np.zeros(0)
        for c in divide:
            if c not in out.columns:
                raise ColumnError(f"column {c!r} to divide is not in the frame (columns: {list(self._df.columns)})")
            out = out.assign(**{c: out[c].to_numpy(dtype=float) / counts})
        drop = [cells.column] if cells.column is not None else []
        if is_geo(out):
            drop.append(geometry_name(out))
        return pd.DataFrame(out.drop(columns=drop)).set_index(name)


