"""The :class:`RollupKeeper`: which roll-ups a store keeps current, ``keep_rollups`` and ``rollup_levels``.

:class:`~dggs.storage.CellStore` owns one and delegates to it; the table and
its rules are in :mod:`dggs.storage.rollup_keep`.  The docstrings are the
public methods' (``CellStore`` shows them), examples included.
"""

from __future__ import annotations

from collections.abc import Iterable

from dggs.errors import StorageError

from .connection import Connection, guarded
from .rollup_keep import check_levels, keep, kept_levels

__all__ = ["RollupKeeper"]


class RollupKeeper:
    """``keep_rollups`` and ``rollup_levels`` of one open store (:class:`~dggs.storage.connection.Connection`)."""

    def __init__(self, store: Connection) -> None:
        self._store = store
        self.path, self.timeout = store.path, store.timeout  # named by the errors of guarded

    @property
    @guarded
    def rollup_levels(self) -> tuple[int, ...]:
        """The levels whose roll-ups the store keeps, finest first (``()``: none)."""
        return kept_levels(self._store.conn)

    @guarded
    def keep_rollups(self, levels: int | Iterable[int]) -> tuple[int, ...]:
        """Keep the roll-ups of ``levels`` in the file, current through every ingest; return the levels.

        A roll-up reads every row of the store (about 1 s a million rows).  A
        store keeping a level holds, per non-empty cell of it, the row count
        and each numeric column's non-NULL count, sum, min and max (a REAL
        column's sum kept exactly), written with each ingest batch in its
        transaction.  :meth:`aggregate`, :meth:`export` and the server then
        read those: a kept level's cells, or a coarser level regrouped from the
        nearest finer kept one.  Answers are exactly what the rows give (a REAL
        sum the correctly rounded one); what the partials cannot give exactly
        (integer sums reaching 2**53) is still read from the rows.

        The levels replace those kept before; the partials are built from the
        stored rows now (one pass a level), in one transaction.  ``[]`` stops
        keeping any.  Rows written with raw SQL (``store.db``) are not seen by
        the partials: call this again after such writes (:meth:`check` finds
        the difference).  A store keeping roll-ups is schema version 3, which
        a dggs that does not keep exact REAL sums does not open.

        Parameters
        ----------
        levels : int or iterable of int
            Levels 0..the stored level (any level before the first ingest; an
            ingest at a coarser level then refuses).

        Returns
        -------
        tuple of int
            The kept levels, finest first.

        Raises
        ------
        LevelError
            A level that is not a whole number 0..MAX_LEVEL.
        LevelMismatchError
            A level finer than the stored level.
        StorageError
            The store is open read-only.

        Examples
        --------
        >>> from dggs.storage import CellStore
        >>> with CellStore() as store:
        ...     _ = store.ingest_points([1.0, 1.1, -40.0], [2.0, 2.1, 100.0], 9, {"pop": [5, 7, 1]})
        ...     store.keep_rollups([6, 3])
        ...     [(r["cell"], r["sum"]) for r in store.aggregate(1, "pop", ("sum",))]
        (6, 3)
        [('C3', 12), ('R3', 1)]
        """
        if self._store.readonly:
            raise StorageError(f"{self._store.path} is open read-only: roll-ups cannot be kept")
        chosen = check_levels(levels if not isinstance(levels, (str, bytes)) else [levels], self._store.level)
        with self._store.transaction():
            chosen = check_levels(chosen, self._store.level)  # again in the transaction: a writer may have come
            keep(self._store.conn, chosen)
            self._store.touch()
        return chosen
