"""The :class:`Querier`: rows and roll-ups read from one store.

:class:`~dggs.storage.CellStore` owns one and delegates ``count``, ``get``,
``descendants``, ``aggregate``, ``within`` and ``disk`` to it; the SQL is
:mod:`~dggs.storage.queries`' and :mod:`~dggs.storage.rollup_query`'.  The
docstrings are the public methods' (``CellStore`` shows them), examples included.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import dggs

from . import queries, rollup_query
from .connection import Connection, guarded
from .progress import Bar, Progress

__all__ = ["Querier"]


class Querier:
    """The queries of one open store (:class:`~dggs.storage.connection.Connection`)."""

    def __init__(self, store: Connection) -> None:
        self._store = store
        self.path, self.timeout = store.path, store.timeout  # named by the errors of guarded

    @guarded
    def count(self, cell: Any = None) -> int:
        """Count stored rows, all of them or those in ``cell`` (at any level).

        Raises
        ------
        InvalidCellError, LevelMismatchError
            For a bad cell or one finer than the stored level.

        Examples
        --------
        >>> with CellStore() as store:
        ...     _ = store.ingest_points([1.0, 1.0], [2.0, 2.0], 3)
        ...     store.count(), store.count(dggs.latlng_to_cell(1.0, 2.0, 0))
        (2, 2)
        """
        return queries.count(self._store, cell)

    @guarded
    def get(self, cell: Any) -> list[dict[str, Any]]:
        """Return the rows stored in one cell at the stored level.

        Raises
        ------
        LevelMismatchError
            If ``cell`` is not at the stored level (see :meth:`descendants`).

        Examples
        --------
        >>> with CellStore() as store:
        ...     _ = store.ingest_points([1.0], [2.0], 3, {"v": [7]})
        ...     [row["v"] for row in store.get(dggs.latlng_to_cell(1.0, 2.0, 3))]
        [7]
        """
        return queries.get(self._store, cell)

    @guarded
    def descendants(self, cell: Any) -> list[dict[str, Any]]:
        """Return the rows in ``cell`` and all its descendants, in id order.

        A range scan on the cell index (``cell >= c AND cell < c || '~'``).

        Raises
        ------
        InvalidCellError, LevelMismatchError
            For a bad cell or one finer than the stored level.

        Examples
        --------
        >>> with CellStore() as store:
        ...     _ = store.ingest_points([1.0, -40.0], [2.0, 100.0], 3)
        ...     len(store.descendants(dggs.latlng_to_cell(1.0, 2.0, 1)))
        1
        """
        return queries.descendants(self._store, cell)

    @guarded
    def aggregate(
        self,
        level: int,
        column: str | None = None,
        stats: Sequence[str] = ("count", "sum", "mean", "min", "max"),
        *, cell: Any = None, order_by: str | None = None, descending: bool = True, limit: int | None = None,
        as_table: bool = False, progress: Progress = None,
    ) -> Any:
        """Roll stored rows up to ``level`` (the stored level or coarser).

        Exact as SQL gives it, but a REAL sum is the correctly rounded sum (``math.fsum``'s), a mean that
        over the non-NULL count; read from kept roll-ups or columns (:mod:`dggs.storage.rollup_query`).

        Parameters
        ----------
        level : int
            Target level, ``0..store.level``.
        column : str, optional
            Value column for sum/mean/min/max; without it only ``count``.
        stats : sequence of str
            Any of ``count`` (rows), ``sum``, ``mean``, ``min``, ``max``
            (NULLs ignored, as SQL does).
        cell : str, optional
            Only roll up rows under this cell.
        order_by, descending, limit : str, bool, int, optional
            A stat to sort by (default the cell id), largest first (default); at most ``limit`` cells.
        as_table : bool, default False
            Columns (a pyarrow Table) instead of dicts: cheaper.
        progress : bool or callable, optional
            Its running time on stderr, as :mod:`dggs.storage.progress` says (default: on a terminal after 2 s).

        Returns
        -------
        list of dict or pyarrow.Table
            ``{"cell": id, "count": n, "sum": ..., ...}`` per non-empty cell, or as columns
            (``count`` int64, ``mean`` float64, the others the column's type).

        Raises
        ------
        LevelMismatchError
            If ``level`` is finer than the stored level.
        DggsValueError
            An unknown column or stat, sum/mean of a text column, a non-bool ``descending``/``as_table``.

        Examples
        --------
        >>> with CellStore() as store:
        ...     _ = store.ingest_points([1.0, 1.1, -40.0], [2.0, 2.1, 100.0], 6,
        ...                             {"pop": [5, 7, 1]})
        ...     top = store.aggregate(1, "pop", ("count", "sum"), order_by="sum", limit=1)
        ...     top[0]["count"], top[0]["sum"]
        (2, 12)
        """
        with Bar(progress, unit="", desc=f"rolling up to level {level}") as bar, bar.heartbeat():
            return rollup_query.aggregate(self._store, level, column, stats, cell, order_by, descending, limit, as_table)

    @guarded
    def within(self, polygon: Any, level: int) -> list[dict[str, Any]]:
        """Return rows in the cells at ``level`` whose centres lie in ``polygon``.

        The polygon (shapely, lng/lat) is covered with cells by
        :func:`dggs.polygon_to_cells`; a finer ``level`` follows its outline
        more closely.

        Raises
        ------
        LevelError, LevelMismatchError
            If ``level`` is out of range or finer than the stored level.
        DggsValueError
            If ``polygon`` is not a shapely (Multi)Polygon.

        Examples
        --------
        >>> from shapely.geometry import box
        >>> with CellStore() as store:
        ...     _ = store.ingest_points([1.0, 50.0], [2.0, 60.0], 5)
        ...     [round(r["lat"]) for r in store.within(box(-10, -10, 10, 10), 3)]
        [1]
        """
        queries.check_query_level(self._store, level)
        cells = dggs.Grid(self._store.projection).polygon_to_cells(polygon, level)
        return queries.rows_under(self._store, list(cells), level)

    @guarded
    def disk(self, cell: Any, k: int) -> list[dict[str, Any]]:
        """Return rows in the cells within ``k`` steps of ``cell`` (:func:`dggs.grid_disk`).

        Raises
        ------
        InvalidCellError
            If ``cell`` is not one valid cell id.
        LevelMismatchError
            If ``cell`` is finer than the stored level.
        DggsValueError
            If ``k`` is not a whole number >= 0.

        Examples
        --------
        >>> with CellStore() as store:
        ...     _ = store.ingest_points([1.0], [2.0], 5)
        ...     len(store.disk(dggs.latlng_to_cell(1.0, 2.0, 5), 1))
        1
        """
        cell = queries.one_cell(cell)
        (level,) = queries.check_cells(self._store, [cell])
        return queries.rows_under(self._store, list(dggs.grid_disk(cell, k)), level)
