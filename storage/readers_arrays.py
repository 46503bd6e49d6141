"""Read iterables of dicts and equal-length arrays as batches.

Lengths and shapes are checked up front (:func:`check_arrays`), before an
ingest registers its source.
"""

from __future__ import annotations

import itertools
from collections.abc import Iterable, Iterator, Mapping, Sequence
from functools import partial
from typing import Any

import numpy as np

from dggs.errors import DggsValueError

from .crs import transform_points
from .readers import RawBatch, _skip

__all__ = ["records_batches", "array_batches", "check_arrays", "cell_order", "ordered_cells", "orderable"]


def _dict_at(items: Sequence[Mapping[str, Any]], i: int) -> dict[str, Any]:
    return dict(items[i])


def records_batches(
    records: Iterable[Mapping[str, Any]],
    lat: str,
    lng: str,
    values: Sequence[str],
    batch_size: int,
    skip: int = 0,
) -> Iterator[RawBatch]:
    """Stream an iterable of mappings (dicts, sqlite rows...) as batches."""
    iterator = iter(records)
    _skip(iterator, skip)
    done = skip
    while True:
        chunk = list(itertools.islice(iterator, batch_size))
        if not chunk:
            return
        bad: dict[int, tuple[str | None, Any, str]] = {}
        for i, item in enumerate(chunk):
            if isinstance(item, Mapping):
                continue
            if hasattr(item, "keys"):  # sqlite3.Row and other dict-likes
                try:
                    chunk[i] = {key: item[key] for key in item.keys()}
                    continue
                except (TypeError, KeyError, IndexError):
                    pass
            bad[i] = (None, item, "is not a mapping (dict)")
            chunk[i] = {}
        yield RawBatch(
            consumed=len(chunk),
            rows=range(done + 1, done + len(chunk) + 1),
            lines=None,
            lat=[item.get(lat) for item in chunk],
            lng=[item.get(lng) for item in chunk],
            values={name: [item.get(name) for item in chunk] for name in values},
            text=False,
            record=partial(_dict_at, chunk),
            bad=bad,
        )
        done += len(chunk)


def as_column(col: Any) -> np.ndarray:
    """``col`` as a numpy array; a pandas nullable column holding NA as objects, its NA kept.

    numpy reads ``pd.array([2**53 + 1, pd.NA], dtype="Int64")`` as float64
    (the int rounded, the NA a NaN); as objects the ints stay exact and the
    NA is named as ``<NA>`` (:func:`dggs.storage.convert.is_missing` makes it NULL).
    """
    dtype = getattr(col, "dtype", None)
    if dtype is not None and not isinstance(dtype, np.dtype) and hasattr(col, "isna") and bool(col.isna().any()):
        objs: np.ndarray = col.to_numpy(dtype=object)  # a pandas Series or ExtensionArray
        return objs
    return np.asarray(col)


def check_arrays(lat: Any, lng: Any, values: Mapping[str, Any]) -> tuple[np.ndarray, np.ndarray, dict[str, np.ndarray]]:
    """Return lat, lng and value columns as 1-d arrays of one length.

    Raises
    ------
    DggsValueError
        Naming the column, if one is not 1-d (a scalar counts as one value)
        or differs in length from ``lat``.
    """
    out = {}
    for name, col in {"lat": lat, "lng": lng, **values}.items():
        try:
            arr = as_column(col)
        except ValueError as exc:  # ragged nested lists
            raise DggsValueError(f"column {name!r} is not a flat sequence of values ({exc})") from None
        if arr.ndim > 1:
            raise DggsValueError(
                f"column {name!r} has shape {arr.shape}: give one value per point (a 1-d array)"
            )
        out[name] = arr.reshape(-1)
    n = len(out["lat"])
    for name, arr in out.items():
        if len(arr) != n:
            raise DggsValueError(f"column {name!r} has {len(arr)} values but lat has {n}")
    lat_a, lng_a = out.pop("lat"), out.pop("lng")
    return lat_a, lng_a, out


def orderable(lat: np.ndarray, lng: np.ndarray) -> bool:
    """True if :func:`cell_order` can sort these coordinates (numeric arrays of two or more points)."""
    return lat.dtype.kind in "fiu" and lng.dtype.kind in "fiu" and len(lat) > 1


def cell_order(lat: np.ndarray, lng: np.ndarray, level: int, transformer: Any, locate: Any = None) -> np.ndarray:
    """The permutation that puts the points in cell id order (the arrays must be :func:`orderable`).

    :func:`ordered_cells` gives the ids too.
    """
    return ordered_cells(lat, lng, level, transformer, locate)[0]


def ordered_cells(
    lat: np.ndarray, lng: np.ndarray, level: int, transformer: Any, locate: Any = None, ids: Any = None
) -> tuple[np.ndarray, np.ndarray]:
    """The permutation that puts the points in cell id order, and their integer ids in that order.

    The ids (uint64) are 0 where a point cannot be binned; :func:`array_batches` hands them to each
    batch (``RawBatch.located``), so that the points are binned once, not again by ``prepare``.
    ``ids``: the points' ids given by the caller (binned before, checked): then none is binned here.

    Only speed depends on it: rows inserted in key order walk the clustered
    table once instead of sorting in SQLite (three times slower than numpy's
    sort).  Points that cannot be binned go first; ties keep input order.
    The order is a pure function of the input, so a resumed ingest skips the
    same rows it committed before.  Integer ids sort as their strings do.
    """
    import dggs

    y, x = lat.astype(np.float64), lng.astype(np.float64)
    ok = np.isfinite(y) & np.isfinite(x)
    if transformer is not None:  # the transform prepare() makes, so both find the same bad rows
        y, x, failed = transform_points(transformer, y, x)
        ok &= ~failed
    with np.errstate(invalid="ignore"):
        ok &= (np.abs(y) <= 90) & (np.abs(x) <= 180)
    good = np.flatnonzero(ok)
    locate = dggs.latlng_to_cell if locate is None else locate  # the store's grid's
    if ids is not None:
        keys = np.asarray(ids, dtype=np.uint64)[good]
    else:
        keys = np.asarray(locate(y[good], x[good], level, as_int=True), dtype=np.uint64)
    # An id of level L leaves its low 2 * (28 - L) bits zero: with the position in them, a plain sort
    # (8x faster than argsort) gives the stable order.
    free = 2 * (dggs.MAX_LEVEL - level)
    low = np.uint64((1 << free) - 1)
    if len(good) <= (1 << free) and not (keys & low).any():
        packed = np.sort(keys | np.arange(len(good), dtype=np.uint64))
        ranked = good[(packed & low).astype(np.intp)]
        sorted_keys = packed & ~low
    else:
        by_key = np.argsort(keys, kind="stable")
        ranked, sorted_keys = good[by_key], keys[by_key]
    # The points that cannot be binned first: with on_error="fail" the first batch fails and nothing is
    # stored, so that fixing them (which would change the order) and ingesting again resumes from row 0.
    bad = np.flatnonzero(~ok)
    return np.concatenate([bad, ranked]), np.concatenate([np.zeros(len(bad), dtype=np.uint64), sorted_keys])


def array_batches(
    lat: Any,
    lng: Any,
    values: Mapping[str, Any],
    batch_size: int,
    skip: int = 0,
    order: np.ndarray | None = None,
    located: np.ndarray | None = None,
) -> Iterator[RawBatch]:
    """Slice equal-length arrays (numpy, lists, pandas columns) into batches, in ``order`` if given.

    ``located``: the points' ids in that order (:func:`ordered_cells`), handed to each batch.

    Raises
    ------
    DggsValueError
        If the arrays differ in length.
    """
    lat_a, lng_a, cols = check_arrays(lat, lng, values)
    n = len(lat_a)
    for start in range(skip, n, batch_size):
        stop = min(start + batch_size, n)
        take: Any = slice(start, stop) if order is None else order[start:stop]
        batch_cols = {name: col[take] for name, col in cols.items()}
        batch_lat, batch_lng = lat_a[take], lng_a[take]

        def record(
            i: int, _lat: np.ndarray = batch_lat, _lng: np.ndarray = batch_lng, _cols: dict[str, np.ndarray] = batch_cols
        ) -> dict[str, Any]:
            out = {"lat": _lat[i], "lng": _lng[i], **{k: v[i] for k, v in _cols.items()}}
            return {k: (v.item() if hasattr(v, "item") else v) for k, v in out.items()}

        yield RawBatch(
            consumed=stop - start,
            rows=range(start + 1, stop + 1) if order is None else (take + 1).tolist(),
            lines=None,
            lat=batch_lat,
            lng=batch_lng,
            values=batch_cols,
            text=False,
            record=record,
            located=None if located is None else located[start:stop],
        )
