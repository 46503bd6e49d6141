"""pandas and GeoPandas accessor: ``df.dggs``.

Optional extra: ``pip install 'dggs[pandas]'`` (pandas; GeoPandas for the
methods that make or read geometries).  Importing this module registers a
``dggs`` accessor on every :class:`pandas.DataFrame` (and so on every
:class:`geopandas.GeoDataFrame`); ``import dggs`` alone never imports pandas.

Each method is one vectorized call of the plain function it is named after,
keeps the frame's index and returns a new frame:

* :meth:`DggsAccessor.latlng_to_cell` adds a cell column from lat/lng columns;
* :meth:`DggsAccessor.cell_to_geometry` makes a GeoDataFrame of cell polygons;
* :meth:`DggsAccessor.aggregate` rolls rows up to a coarser level;
* :meth:`DggsAccessor.polyfill` gives the cells of each polygon feature;
* :meth:`DggsAccessor.sjoin_cells` joins points to polygon features through
  their cells (:mod:`dggs.pandas.join`).

Methods that read cells take ``column=None`` to mean: the only column named
``cell_<level>`` if there is exactly one, else the index.  Bad input raises
the library's typed errors (all :class:`dggs.DggsValueError`), naming the row
label; a missing column raises :class:`ColumnError`.  Geometries with a CRS
are reprojected to EPSG:4326 (pyproj); a CRS without a transformation raises
:class:`CrsError`.

Examples
--------
>>> import pandas as pd
>>> import dggs.pandas  # registers df.dggs
>>> df = pd.DataFrame({"lat": [51.05, -33.9], "lng": [-114.07, 18.4]}, index=["yyc", "cpt"])
>>> df.dggs.latlng_to_cell(9)["cell_9"].tolist()
['F200021102', 'H511012121']
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from dggs.errors import CoordinateError, DggsValueError, InvalidCellError, LevelMismatchError
from dggs.index._checks import check_level, is_choice
from dggs.index._many import each
from dggs.index.hierarchy import cell_to_parent
from dggs.index.points import cell_to_polygon, latlng_to_cell
from dggs.index.polyfill import polygon_to_cells

try:  # the optional extra
    import pandas as pd
except ImportError as exc:  # pragma: no cover - exercised only without the extra
    raise ImportError("dggs.pandas needs the 'pandas' extra: pip install 'dggs[pandas]'") from exc

from dggs.pandas import join as _join  # noqa: E402 - after the extra's check
from dggs.pandas.cells import CellVerbs  # noqa: E402
from dggs.pandas.frames import (  # noqa: E402
    Cells,
    ColumnError,
    CrsError,
    check_agg,
    first_true,
    frame_coordinates,
    geometry_name,
    geopandas_module,
    in_wgs84,
    is_geo,
    row_label,
)

__all__ = ["DggsAccessor", "ColumnError", "CrsError"]

_MODES = ("center", "contains", "overlaps")


@pd.api.extensions.register_dataframe_accessor("dggs")
class DggsAccessor(CellVerbs):
    """The ``df.dggs`` accessor (registered by ``import dggs.pandas``; the per-cell verbs: :mod:`dggs.pandas.cells`)."""

    def __init__(self, frame: pd.DataFrame):
        self._df = frame

    # ------------------------------------------------------------------ points
    def latlng_to_cell(
        self,
        level: int,
        lat: str = "lat",
        lng: str = "lng",
        column: str | None = None,
        as_int: bool = False,
    ) -> pd.DataFrame:
        """The frame with a column of the cell at ``level`` holding each row's point.

        Parameters
        ----------
        level : int
            Subdivision level, 0..MAX_LEVEL.
        lat, lng : str
            Columns of latitude and longitude (WGS84 degrees).  A GeoDataFrame
            of points that has neither column uses its geometry (x = lng, y = lat),
            reprojected from its CRS to EPSG:4326 first.
        column : str, optional
            Name of the new column (default ``f"cell_{level}"``); an existing
            column of that name is replaced.
        as_int : bool
            Integer ids (uint64) instead of strings.

        Returns
        -------
        DataFrame (GeoDataFrame for a GeoDataFrame), same index and rows.

        Raises
        ------
        ColumnError
            ``lat`` or ``lng`` is not a column, or is a column more than once.
        CrsError
            The geometry's CRS has no transformation to EPSG:4326 (names the CRS).
        CoordinateError
            A missing, non-numeric or out-of-range coordinate (names the row).
        LevelError
            ``level`` outside 0..MAX_LEVEL.

        Examples
        --------
        >>> import pandas as pd
        >>> import dggs.pandas
        >>> df = pd.DataFrame({"lat": [51.05, 90.0], "lng": [-114.07, 0.0], "n": [1, 2]})
        >>> df.dggs.latlng_to_cell(5)
             lat     lng  n  cell_5
        0  51.05 -114.07  1  F20002
        1  90.00    0.00  2  A50000
        >>> df.dggs.latlng_to_cell(5, as_int=True, column="id")["id"].tolist()
        [5392427235078569984, 4725753752739381248]
        """
        level = check_level(level)
        df = self._df
        name = column if column is not None else f"cell_{level}"
        if lat not in df.columns and lng not in df.columns and is_geo(df):
            geom = in_wgs84(df.geometry)
            if len(df) and not (geom.geom_type == "Point").all():
                raise ColumnError(f"no columns {lat!r}, {lng!r} and the geometry is not all points")
            lat_a = np.asarray(geom.y, dtype=np.float64)
            lng_a = np.asarray(geom.x, dtype=np.float64)
            names = ("geometry y", "geometry x")
        else:
            lat_a, lng_a = frame_coordinates(df, lat), frame_coordinates(df, lng)
            names = (lat, lng)
        try:
            ids = latlng_to_cell(lat_a, lng_a, level, as_int=as_int) if len(df) else np.array([], dtype=np.uint64)
        except CoordinateError as exc:
            bad = first_true(~np.isfinite(lat_a) | ~np.isfinite(lng_a) | (np.abs(lat_a) > 90.0))
            if bad is None:
                raise
            what = names[0] if not np.isfinite(lat_a[bad]) or abs(lat_a[bad]) > 90 else names[1]
            raise CoordinateError(f"{exc} (row {row_label(df, bad)}, column {what!r})") from exc
        values = pd.Series(
            ids if as_int else np.asarray(ids, dtype=object), index=df.index, dtype=None if as_int else "str"
        )
        return df.assign(**{name: values})

    # --------------------------------------------------------------- geometry
    def cell_to_geometry(self, column: str | None = None, densify: int | None = None) -> Any:
        """A GeoDataFrame (EPSG:4326) whose geometry is each row's cell polygon.

        One vectorized :func:`dggs.cell_to_polygon` call; cells that cross the
        antimeridian are MultiPolygons split at 180 degrees.

        Parameters
        ----------
        column : str, optional
            Column of cell ids (str or int).  Default: the only ``cell_<level>``
            column if there is exactly one, else the index.
        densify : int, optional
            Points per curved edge (see :func:`dggs.cell_to_polygon`).

        Returns
        -------
        GeoDataFrame
            The same rows, index and columns; the geometry column ``geometry``
            (a GeoDataFrame's old active geometry is replaced).

        Raises
        ------
        ColumnError
            ``column`` is not in the frame.
        InvalidCellError
            A malformed or missing id (names the row).

        Examples
        --------
        >>> import pandas as pd
        >>> import dggs.pandas
        >>> g = pd.DataFrame({"cell_3": ["C401", "C402"], "n": [1, 2]}).dggs.cell_to_geometry()
        >>> g.crs.to_epsg(), g.geom_type.tolist()
        (4326, ['Polygon', 'Polygon'])
        """
        gpd = geopandas_module()
        df = self._df
        cells = Cells(df, column)
        try:
            polys = cell_to_polygon(cells.ids, densify=densify) if len(df) else np.array([], dtype=object)
        except InvalidCellError as exc:
            cells.reraise(exc)
        data = pd.DataFrame(df)
        if is_geo(df):
            data = data.drop(columns=[geometry_name(df)])
        geometry = gpd.GeoSeries(np.asarray(polys, dtype=object), index=df.index, crs="EPSG:4326")
        return gpd.GeoDataFrame(data, geometry=geometry, crs="EPSG:4326")

    # ----------------------------------------------------------------- roll-up
    def aggregate(self, level: int, agg: Any = None, column: str | None = None) -> pd.DataFrame:
        """Roll rows up to their parent cells at a coarser ``level``.

        :func:`dggs.cell_to_parent` on the cell ids, then a pandas groupby on
        the parents.

        Parameters
        ----------
        level : int
            Target level (not finer than any cell).
        agg : str, list, dict or callable, optional
            Anything :meth:`pandas.core.groupby.DataFrameGroupBy.agg` takes,
            applied to the other columns (a GeoDataFrame's geometry is dropped).
            Default: the number of rows per parent, in a column ``count``.
        column : str, optional
            Column of cell ids (str or int).  Default: the only ``cell_<level>``
            column if there is exactly one, else the index.

        Returns
        -------
        DataFrame indexed by the parent cells (sorted, index name ``f"cell_{level}"``).
        Call ``.dggs.cell_to_geometry()`` on it for the parents' polygons.

        Raises
        ------
        ColumnError
            ``column`` is not in the frame (or appears twice), or a key of a dict ``agg`` is not a
            column aggregated.
        DggsValueError
            A function in ``agg`` that is neither callable nor the name of a groupby function.
        InvalidCellError, LevelMismatchError
            A malformed id, or a cell coarser than ``level`` (names the row).

        Examples
        --------
        >>> import pandas as pd
        >>> import dggs.pandas
        >>> df = pd.DataFrame({"cell_4": ["C4012", "C4021", "D0000"], "pop": [1, 2, 5]})
        >>> df.dggs.aggregate(2, {"pop": "sum"})
                pop
        cell_2
        C40       3
        D00       5
        >>> df.dggs.aggregate(0)
                count
        cell_0
        C           2
        D           1
        """
        level = check_level(level)
        df = self._df
        cells = Cells(df, column)
        try:
            parents = cell_to_parent(cells.ids, level) if len(df) else cells.ids
        except (InvalidCellError, LevelMismatchError) as exc:
            cells.reraise(exc, level)
        key = pd.Series(np.asarray(parents), index=df.index, name=f"cell_{level}")
        if key.dtype == object:
            key = key.astype("str")
        drop = [cells.column] if cells.column is not None else []
        if is_geo(df):
            drop.append(geometry_name(df))
        data = pd.DataFrame(df).drop(columns=drop)
        if agg is None:
            out = data.groupby(key, sort=True).size().to_frame("count")
        else:
            check_agg(agg, data.columns, cells.column)
            out = data.groupby(key, sort=True).agg(agg)
            if isinstance(out, pd.Series):
                out = out.to_frame()
        out.index.name = f"cell_{level}"
        return out

    # ---------------------------------------------------------------- polyfill
    def polyfill(
        self,
        level: int,
        mode: str = "center",
        explode: bool = True,
        column: str | None = None,
        as_int: bool = False,
        max_cells: int | None = None,
        progress: bool | Callable[[int], Any] | None = None,
    ) -> Any:
        """The cells of each (Multi)Polygon feature of a GeoDataFrame.

        :func:`dggs.polygon_to_cells` per feature, the features side by side
        on all cores (``DGGS_THREADS=1`` keeps to one): polygons across the
        antimeridian (longitudes beyond 180, or split at 180) and around a
        pole are filled correctly.

        Parameters
        ----------
        level : int
            Level of the cells.
        mode : {"center", "contains", "overlaps"}
            The cells whose centres lie in the polygon, that lie wholly in
            it, or that touch it (:func:`dggs.polygon_to_cells`; holes
            respected).
        explode : bool
            One row per cell per feature, the feature's index and attributes
            repeated (features without cells give no row).  ``False`` keeps
            one row per feature with a list of its cells.
        column : str, optional
            Name of the new column (default ``f"cell_{level}"``).
        as_int : bool
            Integer ids (uint64) instead of strings.
        max_cells : int, optional
            Limit per feature (see :func:`dggs.polygon_to_cells`).
        progress : bool or callable, optional
            A bar of the features filled on stderr: ``None`` (default) on a
            terminal once the fill has run 2 s, ``True`` always, ``False``
            never; a callable is given the features done
            (:mod:`dggs.storage.progress`).

        Returns
        -------
        GeoDataFrame
            The feature geometry is kept; ``.dggs.cell_to_geometry()`` swaps
            it for the cells' polygons.  A frame in another CRS is filled in
            EPSG:4326 coordinates.

        Raises
        ------
        DggsValueError
            A geometry that is not a (Multi)Polygon (names the row) or an
            unknown ``mode``.
        ColumnError
            A frame without an active geometry column (a :class:`DggsValueError`).
        CrsError
            The geometry's CRS has no transformation to EPSG:4326 (names the CRS).
        TooManyCellsError
            A feature would have more than ``max_cells`` cells.

        Examples
        --------
        >>> import geopandas as gpd
        >>> from shapely.geometry import box
        >>> import dggs.pandas
        >>> gdf = gpd.GeoDataFrame({"name": ["a", "b"]}, geometry=[box(0, 0, 10, 10), box(170, -5, 190, 5)])
        >>> cells = gdf.dggs.polyfill(4)
        >>> cells.groupby("name").size().to_dict()
        {'a': 7, 'b': 18}
        >>> cells.dggs.cell_to_geometry().geom_type.iloc[0]
        'Polygon'
        """
        level = check_level(level)
        if not is_choice(mode, _MODES):
            raise DggsValueError(f"mode {mode!r} is not one of {', '.join(_MODES)}")
        df = self._df
        if not is_geo(df):
            raise ColumnError("polyfill needs a GeoDataFrame with an active geometry column")
        geoms = in_wgs84(df.geometry).array
        name = column if column is not None else f"cell_{level}"
        polygons = ("Polygon", "MultiPolygon")
        rows = [i for i, g in enumerate(geoms) if g is not None and not g.is_empty and g.geom_type in polygons]
        # the features' fills on all cores (DGGS_THREADS), each result or error in row order
        from dggs.storage.progress import Bar

        with Bar(progress, total=len(rows), unit="polygons", desc="filling") as bar:
            outcomes = each(lambda g: polygon_to_cells(g, level, mode, as_int, max_cells), geoms[rows], bar.update)
        filled = dict(zip(rows, outcomes, strict=False))  # the outcomes stop at the first error
        found: list[np.ndarray] = []
        for i, geom in enumerate(geoms):
            if geom is None or geom.is_empty:
                found.append(np.array([], dtype=np.uint64 if as_int else object))
                continue
            if geom.geom_type not in polygons:
                raise DggsValueError(f"row {row_label(df, i)}: a {geom.geom_type} is not a Polygon or MultiPolygon")
            if isinstance(filled[i], DggsValueError):
                raise type(filled[i])(f"{filled[i]} (row {row_label(df, i)})") from filled[i]
            if isinstance(filled[i], BaseException):
                raise filled[i]
            found.append(filled[i])
        if not explode:
            return df.assign(**{name: pd.Series([c.tolist() for c in found], index=df.index, dtype=object)})
        counts = np.array([c.shape[0] for c in found], dtype=np.int64)
        out = df.iloc[np.repeat(np.arange(len(df)), counts)]
        ids = np.concatenate(found) if found else np.array([], dtype=np.uint64 if as_int else object)
        values = pd.Series(
            ids.astype(np.uint64) if as_int else ids.astype(object), index=out.index, dtype=None if as_int else "str"
        )
        return out.assign(**{name: values})

    #: :func:`dggs.pandas.join.sjoin_cells`, written and tested in its own module
    sjoin_cells = _join.sjoin_cells
