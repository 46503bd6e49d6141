"""dggs.storage: points binned into equal-area cells, stored in SQLite.

The store is a thin layer over SQLite and sqlite-utils: ingest points from
CSV, GeoJSON, dicts, arrays or a DataFrame in atomic, resumable batches, then
count, roll up and select them by cell.  See ``docs/storage.md``.

Examples
--------
>>> from dggs.storage import CellStore
>>> with CellStore(":memory:") as store:
...     _ = store.ingest_points([51.5, 51.6], [-0.1, -0.2], level=7, values={"n": [1, 2]})
...     [row["sum"] for row in store.aggregate(0, "n", ("sum",))]
[3]
"""

from __future__ import annotations

from .atomic import atomic_write
from .datasets import DatasetError, list_datasets
from .errors import BadRowError, RejectedRowsWarning
from .ingest import IngestOptions, IngestResult
from .schema import SCHEMA_VERSION
from .store import STATS, CellStore

__all__ = [
    "CellStore",
    "DatasetError",
    "list_datasets",
    "IngestOptions",
    "IngestResult",
    "atomic_write",
    "BadRowError",
    "RejectedRowsWarning",
    "SCHEMA_VERSION",
    "STATS",
]
