"""The :class:`Exporter`: a store's roll-ups as GeoJSON, Arrow and files.

:class:`~dggs.storage.CellStore` owns one and delegates ``to_geojson``,
``to_arrow`` and ``export`` to it.  Every method rolls the store up as
:meth:`CellStore.aggregate` does (:func:`dggs.storage.rollup_query.aggregate`)
and writes whole files only (a temporary name renamed over the target).  The
docstrings are the public methods' (``CellStore`` shows them), examples included.
"""

from __future__ import annotations

import json
import os
from collections.abc import Sequence
from typing import Any

import dggs

from . import queries, rollup_query
from .atomic import atomic_write, refuse_store
from .connection import Connection, guarded
from .errors import StorageError
from .progress import Bar, Progress
from .rollup_memo import state

#: The exports' default ``tolerance``, metres between each drawn edge and the true edge: the grid's drawing
#: tolerance (``dggs.index._densify.DRAW_TOLERANCE``, equal by test), written here so that opening a store
#: loads no grid (``dggs --help`` must start without it).
DRAW_TOLERANCE = 10.0

__all__ = ["Exporter"]


class Exporter:
    """``to_geojson``, ``to_arrow`` and ``export`` of one open store (:class:`~dggs.storage.connection.Connection`).

    It remembers the last ``to_arrow`` table and the file state it was built from.
    """

    def __init__(self, store: Connection) -> None:
        self._store = store
        self.path, self.timeout = store.path, store.timeout  # named by the errors of guarded
        self._last_table: tuple[tuple, Any] | None = None  # the last to_arrow table and what it was built from

    def _rollup(self, level: int, column: str | None, stats: Sequence[str]) -> list[dict[str, Any]]:
        """The rows of ``store.aggregate(level, column, stats, progress=False)``."""
        rows: list[dict[str, Any]] = rollup_query.aggregate(
            self._store, level, column, stats, cell=None, order_by=None, descending=True, limit=None
        )
        return rows

    def _columns(self, level: int, column: str | None, stats: Sequence[str]) -> tuple[Any, Any]:
        """The roll-up as columns: the ids (pyarrow strings) and the stats (a pyarrow Table), no dict per cell.

        Typed as the dicts' lists would be typed by ``pa.array``, so the files keep their schema: a column
        holding only NULLs (or none at all) is of pyarrow's null type.  A roll-up whose values are not of
        its column's type (raw SQL writes) comes as dicts, as before.
        """
        import pyarrow as pa

        try:
            table = rollup_query.aggregate(self._store, level, column, stats, cell=None, order_by=None,
                                           descending=True, limit=None, as_table=True)
        except StorageError:
            rows = self._rollup(level, column, stats)
            return [row["cell"] for row in rows], queries.stat_columns(rows, stats)
        props = table.drop_columns(["cell"])
        for at, name in enumerate(props.column_names):
            if props.column(name).null_count == props.num_rows:
                props = props.set_column(at, name, pa.nulls(props.num_rows))
        return table.column("cell"), props

    @guarded
    def to_geojson(
        self,
        level: int,
        column: str | None = None,
        path: str | os.PathLike[str] | None = None,
        stats: Sequence[str] | None = None,
        densify: int | None = None,
        *,
        tolerance: Any = DRAW_TOLERANCE,
    ) -> dict[str, Any]:
        """Roll up to ``level`` and return (and write) a GeoJSON FeatureCollection.

        One Polygon feature per non-empty cell, with properties ``cell`` and
        the stats (default count, sum, mean, min, max of ``column``).
        ``tolerance`` (metres between each drawn edge and the true edge, default
        10, files sized for drawing; or ``"exact"``, geodesic areas within 1e-6
        of the cells') chooses the points per edge unless ``densify`` fixes
        them; the choice is the collection's ``"dggs"`` member.

        Raises
        ------
        LevelError, LevelMismatchError
            If ``level`` is out of range or finer than the stored level.
        DggsValueError
            If a stat is unknown or needs a numeric ``column``.
        StorageError
            If ``path`` cannot be written, or is the store itself (or its ``-wal``/``-shm``).

        Examples
        --------
        >>> with dggs.storage.CellStore() as store:
        ...     _ = store.ingest_points([1.0], [2.0], 4, {"v": [3.0]})
        ...     fc = store.to_geojson(2, "v")
        ...     fc["features"][0]["properties"]["sum"]
        3.0
        """
        if path is not None:
            refuse_store(path, self.path)
        rows = self._rollup(level, column, queries.export_stats(column, stats))
        collection = self._draw_geojson(rows, densify, tolerance)
        if path is not None:
            with atomic_write(path) as fh:
                json.dump(collection, fh)
        return collection

    def _draw_geojson(self, rows: list[dict[str, Any]], densify: int | None, tolerance: Any) -> dict[str, Any]:
        """The FeatureCollection of rolled-up ``rows``, drawn on the store's grid."""
        cells = [row["cell"] for row in rows]
        props = [{k: v for k, v in row.items() if k != "cell"} for row in rows]
        if self._store.projection == "ISEA":
            collection: dict[str, Any] = dggs.cells_to_geojson(
                cells, properties=props, densify=densify, tolerance=tolerance
            )
        else:  # drawn with the grid the cells were binned on (storage/projection.py)
            collection = _grid_geojson(self._store.projection, cells, props, densify, tolerance)
        return collection

    @guarded
    def to_arrow(
        self,
        level: int,
        column: str | None = None,
        stats: Sequence[str] | None = None,
        densify: int | None = None,
        *,
        tolerance: Any = DRAW_TOLERANCE,
        rows: list[dict[str, Any]] | None = None,
    ) -> Any:
        """Roll up to ``level`` and return a GeoParquet-ready pyarrow Table (needs pyarrow).

        ``densify`` and ``tolerance`` as :meth:`to_geojson`; the choice is the schema
        metadata's ``dggs`` key (JSON). ``rows``: the roll-up, when the caller has it already (:meth:`export`).

        One row per non-empty cell: ``cell`` (string id), ``cell_id`` (int64
        id), the stats (default count, sum, mean, min, max of ``column``),
        ``bbox`` (struct xmin, ymin, xmax, ymax) and ``geometry`` (WKB
        polygons in lng/lat, OGC:CRS84), with GeoParquet 1.1 ``geo`` metadata
        (:func:`dggs.arrow.cells_to_table`).

        Raises
        ------
        LevelError, LevelMismatchError
            If ``level`` is out of range or finer than the stored level.
        DggsValueError
            If a stat is unknown or needs a numeric ``column``.

        Examples
        --------
        >>> with dggs.storage.CellStore() as store:
        ...     _ = store.ingest_points([1.0, 1.1], [2.0, 2.1], 4, {"v": [3.0, 4.0]})
        ...     table = store.to_arrow(2, "v", ("count", "sum"))
        ...     table.column_names, table.column("sum").to_pylist()
        (['cell', 'cell_id', 'count', 'sum', 'bbox', 'geometry'], [7.0])
        """
        return self._arrow(level, queries.export_stats(column, stats), column, densify, tolerance, rows)

    def _arrow(self, level: int, stats: Sequence[str], column: str | None, densify: int | None, tolerance: Any,
               rows: list[dict[str, Any]] | None = None, bar: Bar | None = None) -> Any:
        """The work of :meth:`to_arrow` (``stats`` checked); ``bar`` told when the roll-up is done."""
        from dggs.arrow import cells_to_table

        # An analyst exports one roll-up in several formats: the last table is remembered while the file
        # is unchanged (the roll-up memo's file state), so the second format neither rolls up nor draws again.
        conn, version, changes = state(self._store.conn)
        key = (level, column, tuple(stats), densify, tolerance)
        last = self._last_table
        if last is not None and last[0] == (*key, conn, version, changes):
            if bar is not None:
                bar.update(1)
            return last[1]
        if rows is None:
            cells, props = self._columns(level, column, stats)
        else:
            cells, props = [row["cell"] for row in rows], queries.stat_columns(rows, stats)
        if bar is not None:
            bar.update(1)
            bar.stage(f"exporting: drawing {len(cells):,} cells")
        table = cells_to_table(cells, props, densify, tolerance=tolerance)
        if self._store.projection != "ISEA":  # drawn with the grid the cells were binned on
            table = _grid_geometry(table, self._store.projection, densify, tolerance)
        # as the memo keeps it: others' commits as of before the roll-up, this connection's own changes
        # after it (a roll-up's temporary tables count as changes; nothing else writes meanwhile)
        self._last_table = ((*key, conn, version, self._store.conn.total_changes), table)
        return table

    @guarded
    def export(
        self,
        path: str | os.PathLike[str],
        level: int,
        column: str | None = None,
        stats: Sequence[str] | None = None,
        *,
        format: str | None = None,
        densify: int | None = None,
        tolerance: Any = DRAW_TOLERANCE,
        progress: Progress = None,
    ) -> int:
        """Roll up to ``level`` and write the cells with their stats to a file; return the cell count.

        ``format`` is ``"geojson"`` (RFC 7946, no extra needed),
        ``"geoparquet"`` (GeoParquet 1.1, see :meth:`to_arrow`; needs
        pyarrow), ``"gpkg"`` or ``"fgb"`` (through geopandas and pyogrio);
        by default it follows the extension of ``path`` (``.geojson``,
        ``.json``, ``.parquet``, ``.geoparquet``, ``.gpkg``, ``.fgb``).  The
        file is written under a temporary name and renamed over ``path``
        when complete: an error leaves the old file (or none).

        ``tolerance`` sizes the file to its use: metres between each drawn
        edge and the true edge (default 10: files near H3's size, for
        drawing), or ``"exact"``: each polygon's geodesic area within 1e-6 of
        its cell's (for measuring areas in another tool); ``densify`` fixes the
        points per edge instead.  GeoJSON and GeoParquet record the choice
        (the ``"dggs"`` member; the ``dggs`` schema metadata key).

        ``progress`` shows the three steps (rolling up, drawing the cells,
        writing) on stderr with the time each takes: ``None`` (default) on a
        terminal once the export has run 2 s, ``True`` always, ``False`` never;
        a callable is given 1 as each step ends (:mod:`dggs.storage.progress`).

        Raises
        ------
        DggsValueError
            An unknown format or extension, or bad level/column/stats
            (as :meth:`aggregate`).
        StorageError
            If the file cannot be written, or is the store itself (or its
            ``-wal``/``-shm`` file, through any link).

        Examples
        --------
        >>> import os, tempfile
        >>> out = os.path.join(tempfile.mkdtemp(), "cells.geojson")
        >>> with dggs.storage.CellStore() as store:
        ...     _ = store.ingest_points([1.0, 50.0], [2.0, 60.0], 4)
        ...     store.export(out, 1), store.export(out, 1, tolerance="exact")
        (2, 2)
        """
        from dggs.arrow.formats import export_format  # here: dggs.arrow loads the grid, which `dggs --help` must not

        fmt = export_format(path, format)
        refuse_store(path, self.path)
        with Bar(progress, total=3, unit="steps", desc="exporting: rolling up") as bar, bar.heartbeat():
            stats = queries.export_stats(column, stats)
            if fmt == "geojson":
                rows = self._rollup(level, column, stats)
                bar.update(1)
                bar.stage(f"exporting: drawing {len(rows):,} cells")
                collection = self._draw_geojson(rows, densify, tolerance)
                bar.update(1)
                bar.stage("exporting: writing")
                with atomic_write(path) as fh:
                    json.dump(collection, fh)
                bar.update(1)
                return len(rows)
            from dggs.arrow import write_cells

            table = self._arrow(level, stats, column, densify, tolerance, bar=bar)  # as columns, no dict a cell
            bar.update(1)
            bar.stage("exporting: writing")
            write_cells(table, path, fmt)
            bar.update(1)
        return int(table.num_rows)


def _grid_geojson(projection: str, cells: list[str], props: list[dict[str, Any]],
                  densify: int | None, tolerance: Any) -> dict[str, Any]:
    """A FeatureCollection as :func:`dggs.cells_to_geojson` gives, the cells drawn on ``Grid(projection)``."""
    import shapely
    from shapely.geometry import mapping

    polys = dggs.Grid(projection).cell_to_polygon(cells, densify=densify, tolerance=tolerance) if cells else []
    polys = shapely.orient_polygons(polys, exterior_cw=False) if cells else []
    features = [
        {"type": "Feature", "id": cell, "geometry": mapping(poly),
         "properties": {"cell": cell, "level": len(cell) - 1, **row}}
        for cell, poly, row in zip(cells, polys, props, strict=True)
    ]
    from dggs.index._densify import edge_points_metadata

    return {"type": "FeatureCollection", "dggs": edge_points_metadata(densify, tolerance), "features": features}


def _grid_geometry(table: Any, projection: str, densify: int | None, tolerance: Any) -> Any:
    """``table`` (of :func:`dggs.arrow.cells_to_table`) with its cells drawn on ``Grid(projection)``.

    Its ``geometry`` (counter-clockwise WKB), ``bbox`` (split cells -180..180, as dggs.arrow writes them)
    and ``geo`` metadata are replaced.
    """
    import json

    import numpy as np
    import pyarrow as pa
    import shapely

    from dggs.arrow.geoparquet import BBOX_TYPE, covering_bounds, file_bbox, geo_metadata, widen_wrapped

    cells = np.asarray(table.column("cell").to_pylist(), dtype=str)
    grid = dggs.Grid(projection)
    polys = grid.cell_to_polygon(cells, densify=densify, tolerance=tolerance) if len(cells) else np.empty(0, object)
    polys = shapely.orient_polygons(polys, exterior_cw=False)
    geometry = pa.array(shapely.to_wkb(polys, byte_order=1, output_dimension=2).tolist(), type=pa.binary())
    bounds = covering_bounds(geometry, shapely.bounds(polys).reshape(-1, 4))
    bbox = pa.StructArray.from_arrays([pa.array(widen_wrapped(bounds)[:, i]) for i in range(4)], fields=list(BBOX_TYPE))
    names = table.column_names
    table = table.set_column(names.index("bbox"), table.schema.field("bbox"), bbox)
    table = table.set_column(names.index("geometry"), table.schema.field("geometry"), geometry)
    meta = dict(table.schema.metadata or {})
    meta[b"geo"] = json.dumps(geo_metadata({g.geom_type for g in polys}, file_bbox(bounds))).encode()
    return table.replace_schema_metadata(meta)
