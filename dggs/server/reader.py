"""Read access to the served cell store: a bounded pool of read-only connections, cached roll-ups.

The server never writes.  Each read (:meth:`StoreReader.snapshot`) takes a
read-only :class:`~dggs.storage.CellStore` from the reader's bounded pool
(:mod:`dggs.server.pool`) and gives it back when it ends (a nested snapshot on
the same thread uses the same store): connections belong to the reader, not to
worker threads, which come and go (issue 32).
Every answer reads in one SQLite read transaction (:meth:`StoreReader.snapshot`):
an ingest running at the same time commits whole batches in WAL mode, and a
reader sees the store before or after a batch, never half of one.

Roll-ups of a level (:meth:`StoreReader.level_data`) are cached with the
store's *modification marker*: the ``updated`` time in ``meta`` (set by
``Connection.touch()`` in the same transaction as every ingest batch and source
deletion) together with the ingest progress of every source (``rows_done``
changes with each batch, even two batches in the same second; the source ids
change when one is deleted or added).  Marker and data are read in the same
transaction, so a cached roll-up always belongs to the marker it is filed with,
and a concurrent ingest invalidates it.  While an ingest commits batch after
batch, a roll-up younger than ``refresh`` seconds is still served (a
consistent snapshot of the store at most that old, never half a batch), and one
thread recomputes it while the others wait for its answer, so a busy server
does not recompute the same roll-up once per request.

Cell geometries never change, so their GeoJSON text is cached by cell id.

Examples
--------
>>> from dggs.storage import CellStore
>>> import tempfile, os
>>> path = os.path.join(tempfile.mkdtemp(), "x.db")
>>> with CellStore(path) as s:
...     _ = s.ingest_points([1.0, 2.0], [3.0, 4.0], 4, {"v": [1, 2]})
>>> reader = StoreReader(path)
>>> data = reader.level_data(0, "v", "sum")
>>> data.ids.tolist(), data.counts.tolist(), data.values
(['C'], [2], [3])
>>> reader.close()
"""

from __future__ import annotations

import contextlib
import math
import os
import sqlite3
import threading
import time
from collections import OrderedDict
from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

import dggs
from dggs.errors import StorageError
from dggs.storage import CellStore
from dggs.storage.connection import translate

from .pool import POOL_IDLE, StorePool

__all__ = ["StoreReader", "LevelData", "Summary", "map_densify", "cells_meeting_bbox", "POOL_IDLE"]

#: At most this many roll-ups are kept (each is one level, column and statistic).
CACHE_ENTRIES = 32
#: At most this many cell geometries are kept (about 1 kB each).
GEOMETRY_ENTRIES = 300_000


def map_densify(level: int) -> int:
    """Points added per curved edge in the map's and the data's GeoJSON (few, for speed).

    Examples
    --------
    >>> [map_densify(level) for level in (0, 3, 9)]
    [8, 4, 2]
    """
    return 8 if level <= 2 else 4 if level <= 5 else 2


@dataclass(frozen=True)
class Summary:
    """What the store holds, read in one snapshot."""

    marker: tuple[Any, ...]
    level: int | None
    columns: dict[str, str]
    count: int
    bbox: tuple[float, float, float, float] | None
    created: str | None
    updated: str | None

    @property
    def numeric_columns(self) -> list[str]:
        """Value columns holding numbers (INTEGER or REAL)."""
        return [c for c, t in self.columns.items() if t in ("INTEGER", "REAL")]


@dataclass(frozen=True)
class LevelData:
    """The non-empty cells at one level, in id order, with row counts and a statistic of a column."""

    level: int
    ids: np.ndarray  # str ids, sorted
    counts: np.ndarray  # int64
    values: list[Any]  # the statistic per cell (the count without a column)
    lat: np.ndarray  # cell centres, degrees
    lng: np.ndarray

    def __len__(self) -> int:
        return int(self.ids.shape[0])


class StoreReader:
    """The served store, read-only, with a bounded pool of connections and caches.

    Parameters
    ----------
    path : str or Path
        The cell store file.  Opened once here, so a missing or corrupt file
        raises :class:`dggs.StorageError` at start-up, not at the first request.
    refresh : float, default 0
        Seconds a cached roll-up is served after the store changed (0: every
        change is seen at once).
    """

    def __init__(self, path: str | os.PathLike[str], refresh: float = 0.0, dataset: str | None = None,
                 collection_id: str | None = None) -> None:
        self.path = Path(path)
        self.refresh = float(refresh)
        self.dataset = dataset  # a named dataset of the file (storage/datasets.py); None: the default one
        self._flights: dict[tuple[Any, ...], threading.Lock] = {}
        self.collection_id = collection_id or (self.path.stem if dataset is None else dataset)
        self._local = threading.local()  # .store, .depth: the store this thread holds and its snapshot nesting
        self._lock = threading.Lock()
        self._pool = StorePool(self.path, dataset=dataset)
        self._cache: OrderedDict[tuple[Any, ...], Any] = OrderedDict()
        self._geometry: dict[str, tuple[Any, str]] = {}
        with self.snapshot() as (store, _marker):
            store.level  # noqa: B018 - validates meta (raises StorageError naming the file)
            #: The projection the store's points were binned with, and its grid (draws and locates the cells).
            self.projection: str = store.projection
        self.grid = dggs.Grid(self.projection)

    # -- connections --------------------------------------------------------

    def store(self) -> CellStore:
        """Return the read-only store this thread holds in a :meth:`snapshot` (or one from the pool).

        Outside a snapshot the store is taken from the pool and given back at
        once: use it within :meth:`snapshot`, which holds it for the read.
        """
        held = getattr(self._local, "store", None)
        if held is not None:
            return held
        store = self._pool.take()
        self._pool.give(store)
        return store

    def open_connections(self) -> int:
        """How many read-only stores the reader has open (idle and held), for tests and monitoring."""
        return self._pool.open_count()

    def close(self) -> None:
        """Close every idle store now, and every held one when its read ends."""
        self._pool.close()

    @contextlib.contextmanager
    def snapshot(self) -> Iterator[tuple[CellStore, tuple[Any, ...]]]:
        """One read transaction: yield the store and its modification marker.

        Raises
        ------
        StorageError
            If the store file is gone, damaged, or changed under an immutable reader while it was read
            (naming the file: the server answers 503).
        """
        outer = getattr(self._local, "store", None) is None
        if outer:
            self._local.store = self._pool.take()
        store: CellStore = self._local.store
        marker: tuple[Any, ...] | None = None
        try:
            with store._store.snapshot():
                marker = self._marker(store)
                yield store, marker
        except (sqlite3.Error, OSError, StorageError) as exc:
            with self._lock:  # nothing computed in a failed read stays cached
                for key in [k for k, entry in self._cache.items() if marker is not None and entry[0] == marker]:
                    del self._cache[key]
            raise translate(exc, str(self.path)) from exc
        finally:
            if outer:  # the outermost snapshot of this thread gives the store back
                self._local.store = None
                self._pool.give(store)

    @staticmethod
    def _marker(store: CellStore) -> tuple[Any, ...]:
        conn = store.conn
        updated = conn.execute("SELECT value FROM meta WHERE key = 'updated'").fetchone()
        progress = tuple(conn.execute("SELECT id, rows_done, complete FROM sources ORDER BY id"))
        return (updated[0] if updated else None, progress)

    def _lookup(self, key: tuple[Any, ...], marker: tuple[Any, ...]) -> Any:
        """The cached value of ``key`` if it belongs to ``marker`` or is younger than ``refresh``."""
        with self._lock:
            entry = self._cache.get(key)
            if entry is None:
                return None
            self._cache.move_to_end(key)
        filed, value, stamp = entry
        if filed == marker or time.monotonic() - stamp < self.refresh:
            return value
        return None

    def _cached(self, key: tuple[Any, ...], marker: tuple[Any, ...], compute: Any) -> Any:
        """``compute()`` once per key and marker; concurrent callers of one key wait for one computation."""
        found = self._lookup(key, marker)
        if found is not None:
            return found
        with self._lock:
            gate = self._flights.setdefault(key, threading.Lock())
        with gate:
            found = self._lookup(key, marker)  # computed by another thread meanwhile
            if found is not None:
                return found
            value = compute()
            with self._lock:
                self._cache[key] = (marker, value, time.monotonic())
                self._cache.move_to_end(key)
                while len(self._cache) > CACHE_ENTRIES:
                    self._cache.popitem(last=False)
            return value

    # -- what the store holds -----------------------------------------------

    def summary(self) -> Summary:
        """Level, columns, row count and bounding box of the points (cached per marker)."""
        with self.snapshot() as (store, marker):

            def compute() -> Summary:
                meta = store.meta
                row = store.conn.execute(
                    "SELECT min(lng), min(lat), max(lng), max(lat) FROM "
                    "(SELECT lng, lat FROM points UNION ALL SELECT lng, lat FROM points_pending)"
                ).fetchone()
                bbox = None if row is None or row[0] is None else tuple(float(v) for v in row)
                return Summary(
                    marker=marker,
                    level=store.level,
                    columns=store.columns,
                    count=store.count(),
                    bbox=bbox,  # type: ignore[arg-type]
                    created=meta.get("created"),
                    updated=meta.get("updated"),
                )

            return self._cached(("summary",), marker, compute)  # type: ignore[no-any-return]

    def level_data(self, level: int, column: str | None = None, stat: str = "count") -> LevelData:
        """The non-empty cells at ``level`` with counts and ``stat`` of ``column`` (cached per marker).

        Raises
        ------
        DggsValueError
            For a level finer than the stored one, an unknown column or stat
            (from :meth:`CellStore.aggregate`, naming the value).
        """
        with self.snapshot() as (store, marker):

            def compute() -> LevelData:
                stats = ("count",) if column is None or stat == "count" else ("count", stat)
                rows = store.aggregate(level, column, stats, progress=False)  # no bars in a server
                ids = np.array([r["cell"] for r in rows], dtype=str) if rows else np.array([], dtype="<U1")
                counts = np.array([r["count"] for r in rows], dtype=np.int64)
                values = [r[stats[-1]] for r in rows]
                if len(ids):
                    lat, lng = self.grid.cell_to_latlng(ids)
                else:
                    lat, lng = np.array([]), np.array([])
                return LevelData(level, ids, counts, values, np.asarray(lat), np.asarray(lng))

            return self._cached(("level", level, column, stat), marker, compute)  # type: ignore[no-any-return]

    def rollup(self, zone: str, level: int, column: str | None, stats: Sequence[str]) -> list[dict[str, Any]]:
        """``store.aggregate(level, column, stats, cell=zone)`` in one snapshot (not cached)."""
        with self.snapshot() as (store, _marker):
            rows: list[dict[str, Any]] = store.aggregate(level, column, tuple(stats), cell=zone, progress=False)
            return rows

    # -- geometry -----------------------------------------------------------

    def geometries(self, ids: np.ndarray) -> tuple[np.ndarray, list[str]]:
        """Shapely polygons (lng/lat) and their GeoJSON text for cells, with few points per edge.

        Coordinates are rounded to 1e-6 degrees (about 0.1 m).
        """
        import shapely

        missing = [c for c in ids.tolist() if c not in self._geometry]
        if missing:
            arr = np.array(missing, dtype=str)
            levels = np.char.str_len(arr) - 1
            polys = np.empty(len(missing), dtype=object)
            for level in np.unique(levels):
                sel = np.flatnonzero(levels == level)
                polys[sel] = self.grid.cell_to_polygon(arr[sel], densify=map_densify(int(level)))
            polys = shapely.transform(polys, lambda xy: np.round(xy, 6))
            texts = shapely.to_geojson(polys)
            with self._lock:
                if len(self._geometry) + len(missing) > GEOMETRY_ENTRIES:
                    self._geometry.clear()
                for cell, poly, text in zip(missing, polys, texts, strict=True):
                    self._geometry[cell] = (poly, str(text))
        pairs = [self._geometry.get(c) or self._compute_one(c) for c in ids.tolist()]
        return np.array([p[0] for p in pairs], dtype=object), [p[1] for p in pairs]

    def _compute_one(self, cell: str) -> tuple[Any, str]:
        # Only when another thread cleared the cache between our fill and our read.
        import shapely

        poly = shapely.transform(self.grid.cell_to_polygon(cell, densify=map_densify(len(cell) - 1)),
                                 lambda xy: np.round(xy, 6))
        return poly, str(shapely.to_geojson(poly))


def _boxes(bbox: tuple[float, float, float, float]) -> list[tuple[float, float, float, float]]:
    """The bbox as one or two boxes in -180..180 (two when it crosses the antimeridian, w > e)."""
    w, s, e, n = bbox
    return [(w, s, e, n)] if w < e else [(w, s, 180.0, n), (-180.0, s, e, n)]


def covers_world(bbox: tuple[float, float, float, float]) -> bool:
    """True for -180,-90,180,90 (nothing to filter)."""
    w, s, e, n = bbox
    return w <= -180 and e >= 180 and s <= -90 and n >= 90


def _candidates(data: LevelData, bbox: tuple[float, float, float, float]) -> np.ndarray:
    """Indexes of cells whose centre is near enough the bbox for the cell to meet it.

    The margin is the hypotenuse of a planar cell of the level's area, as an
    angle: at least 1.4 times the largest centre-to-corner distance at every
    level (measured at levels 0-6: 0.54-0.68 of it).
    """
    if covers_world(bbox):
        return np.arange(len(data))
    area = float(dggs.cell_area(data.level))
    radius = 6371007.1809
    edge = math.sqrt(4 * area / math.sqrt(3)) if data.level == 0 else 2 * math.sqrt(2 * area / math.sqrt(3))
    margin = math.degrees(edge / radius)
    keep = np.zeros(len(data), dtype=bool)
    for w, s, e, n in _boxes(bbox):
        lo, hi = s - margin, n + margin
        near = (data.lat >= lo) & (data.lat <= hi)
        if lo > -90 and hi < 90:
            coslat = math.cos(math.radians(max(abs(lo), abs(hi))))
            ratio = math.sin(math.radians(margin)) / coslat
            if ratio < 1:
                dlng = math.degrees(math.asin(ratio))
                west, east = w - dlng, e + dlng
                lng = data.lng
                inside = (lng >= west) & (lng <= east)
                inside |= (lng + 360 >= west) & (lng + 360 <= east)
                inside |= (lng - 360 >= west) & (lng - 360 <= east)
                near &= inside
        keep |= near
    return np.flatnonzero(keep)


def cells_meeting_bbox(
    reader: StoreReader, data: LevelData, bbox: tuple[float, float, float, float] | None, limit: int
) -> tuple[np.ndarray, np.ndarray, list[str]] | None:
    """Indexes, polygons and GeoJSON text of the cells of ``data`` whose polygon meets ``bbox``.

    Returns None (the caller answers 413) when more than ``limit`` cells meet
    the bbox.  The work is bounded before any geometry is built: cells whose
    centres are near the bbox are counted first, and more than twice
    ``limit`` of them is None straight away; otherwise their polygons are
    built (cached) and tested exactly.
    """
    import shapely

    index = np.arange(len(data)) if bbox is None else _candidates(data, bbox)
    if index.shape[0] > (limit if bbox is None or covers_world(bbox) else 2 * limit):
        return None
    polys, texts = reader.geometries(data.ids[index])
    if bbox is None or covers_world(bbox) or not len(index):
        return index, polys, texts
    hit = np.zeros(len(index), dtype=bool)
    for box in _boxes(bbox):
        hit |= shapely.intersects(polys, shapely.box(*box))
    keep = np.flatnonzero(hit)
    if keep.shape[0] > limit:
        return None
    return index[keep], polys[keep], [texts[i] for i in keep]
