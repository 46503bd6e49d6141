"""Read and prepare batches in a background thread while SQLite writes."""

from __future__ import annotations

import queue
import threading
from collections.abc import Iterator, Mapping
from typing import Any

from .convert import Prepared, prepare, value_types
from .readers import RawBatch
from .rollup_keep import batch_partials

__all__ = ["Producer", "READ_AHEAD"]

#: Input rows the reader thread may prepare ahead of the writer: enough to keep
#: it busy through a merge of pending rows (about 0.6 s per 250,000 rows), so
#: parsing and binning overlap SQLite's work instead of waiting for it.
READ_AHEAD = 200_000


class Producer:
    """Read and prepare batches in a background thread, a few ahead.

    Parsing, checking and binning (Python and numpy) overlap with SQLite
    writing, which releases the GIL.  Only the calling thread touches the
    database; errors in the thread are re-raised in the caller.  With
    ``threaded=False`` the batches are prepared in the caller's thread.
    """

    _DONE = object()

    def __init__(
        self,
        batches: Iterator[RawBatch],
        level: int,
        existing: dict[str, str],
        declared: Mapping[str, str],
        transformer: Any,
        threaded: bool = True,
        name: str = "input",
        batch_size: int = 10_000,
        rollups: tuple[int, ...] = (),
        locate: Any = None,
    ) -> None:
        self._name = name
        self._batches = batches
        self._threaded = threaded
        self._args = (level, transformer, locate)  # locate: the store's grid's latlng_to_cell
        self._rollups = rollups  # kept roll-up levels: each batch's partials are computed here too
        self._types = existing  # the same dict the reader sees
        self._declared = declared
        self._queue: queue.Queue = queue.Queue(maxsize=max(2, min(64, READ_AHEAD // max(batch_size, 1))))
        self._stopped = threading.Event()
        self._thread = threading.Thread(target=self._run, name="dggs-ingest-reader", daemon=True)
        if threaded:
            self._thread.start()

    def _put(self, item: Any) -> bool:
        while not self._stopped.is_set():
            try:
                self._queue.put(item, timeout=0.1)
                return True
            except queue.Full:
                continue
        return False

    def _prepared(self) -> Iterator[tuple[RawBatch, Prepared, dict[str, str], dict[str, str]]]:
        level, transformer, locate = self._args
        for batch in self._batches:
            new = value_types(batch, self._types, self._declared)
            self._types.update(new)
            types = {name: self._types[name] for name in batch.values}
            prepared = prepare(batch, level, types, transformer, locate)
            prepared.partials = batch_partials(prepared.values, prepared.width, types, self._rollups, prepared.ids)
            yield batch, prepared, types, new

    def _run(self) -> None:
        try:
            for item in self._prepared():
                if not self._put(item):
                    return
            self._put(self._DONE)
        except BaseException as exc:  # noqa: BLE001 - handed to the caller
            self._put(exc)

    def __iter__(self) -> Iterator[tuple[RawBatch, Prepared, dict[str, str], dict[str, str]]]:
        if not self._threaded:
            yield from self._prepared()
            return
        while True:
            item = self._queue.get()
            if item is self._DONE:
                return
            if isinstance(item, BaseException):
                raise item
            yield item

    def stop(self) -> None:
        """Ask the thread to finish and wait for it."""
        self._stopped.set()
        if self._threaded:
            self._thread.join(timeout=10)
