"""A bounded pool of read-only stores: the server's SQLite connections belong to it, not to worker threads.

The server answers in anyio's worker threads, which retire after 10 s idle; a store opened per thread and
kept in a list stayed open after its thread was gone, one descriptor (three beside a writer) per retired
thread, until the server answered 503 "Too many open files" (issue 32).  A read takes a store from the pool
(:meth:`StorePool.take`, opening one if none is idle) and gives it back when it ends
(:meth:`StorePool.give`); at most :data:`POOL_IDLE` idle stores are kept, the rest closed.  The stores are
opened with ``check_same_thread=False`` (sqlite3's flag) so that one thread after another may use them,
never two at once.

Examples
--------
>>> import os, tempfile
>>> from dggs.storage import CellStore
>>> path = os.path.join(tempfile.mkdtemp(), "x.db")
>>> CellStore(path).close()
>>> pool = StorePool(path)
>>> a, b = pool.take(), pool.take()
>>> pool.give(a); pool.give(b); pool.open_count()
2
>>> pool.close(); pool.open_count()
0
"""

from __future__ import annotations

import contextlib
import os
import threading

from dggs.storage import CellStore

__all__ = ["POOL_IDLE", "StorePool"]

#: Most idle read-only stores the pool keeps open between reads (more are closed when given back).
POOL_IDLE = 8


class StorePool:
    """Read-only stores of one file, lent to one thread at a time; closes what it does not keep."""

    def __init__(self, path: str | os.PathLike[str], idle: int = POOL_IDLE, dataset: str | None = None) -> None:
        self.path, self.idle_max, self.dataset = path, idle, dataset
        self._lock = threading.Lock()
        self._idle: list[CellStore] = []  # stores given back, newest last
        self._busy: set[CellStore] = set()  # stores lent now
        self._closed = False

    def take(self) -> CellStore:
        """An idle store, or a new one (an immutable reader opens itself again once a writer appears)."""
        with self._lock:
            store = self._idle.pop() if self._idle else None
            if store is not None:
                self._busy.add(store)
                return store
        store = CellStore(self.path, create=False, readonly=True, check_same_thread=False, dataset=self.dataset)
        with self._lock:
            self._busy.add(store)
        return store

    def give(self, store: CellStore) -> None:
        """Take a store back: kept idle while there is room and the pool is open, else closed."""
        with self._lock:
            self._busy.discard(store)
            keep = not self._closed and len(self._idle) < self.idle_max
            if keep:
                self._idle.append(store)
        if not keep:
            with contextlib.suppress(Exception):
                store.close()

    def open_count(self) -> int:
        """Stores open now: idle and lent."""
        with self._lock:
            return len(self._idle) + len(self._busy)

    def close(self) -> None:
        """Close every idle store now; a lent one is closed when it is given back."""
        with self._lock:
            self._closed = True
            idle, self._idle = self._idle, []
        for store in idle:
            with contextlib.suppress(Exception):
                store.close()
