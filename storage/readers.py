"""Readers that cut an input into :class:`RawBatch` es of column values.

Each reader streams its input (a CSV file is never held in memory whole),
can skip the records already committed by an earlier, interrupted run, and
reports row (and, for CSV, line) numbers for error messages.  Converting and
checking values is left to :mod:`dggs.storage.ingest`.  The readers:
:mod:`~dggs.storage.readers_csv` (pyarrow), :mod:`~dggs.storage.readers_geojson`,
:mod:`~dggs.storage.readers_vector` (pyogrio: GeoPackage, Shapefile,
FlatGeobuf; GeoParquet through pyarrow) and :mod:`~dggs.storage.readers_arrays`.
"""

from __future__ import annotations

import collections
import itertools
import os
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from dggs.errors import DggsValueError, StorageError

#: A column of raw values: a list, tuple or numpy array.
Column = Any

__all__ = ["RawBatch", "check_columns", "count_csv_rows", "sniff_kind", "MAX_FIELD_LINES"]


@dataclass
class RawBatch:
    """Unconverted column values of one batch of input records.

    Attributes
    ----------
    consumed : int
        Input records this batch accounts for (the source's progress advances
        by this much when the batch is committed).
    rows : list of int
        1-based input record number of each entry (a polygon feature gives
        several entries with the same number).
    lines : list of int or None
        File line of each entry, when known.
    lat, lng : sequence
        Raw coordinates (y and x in the input CRS).
    values : dict
        Raw value columns.
    text : bool
        True if values are raw text (CSV) to be parsed.
    bad : dict
        Entries already known to be bad: position -> (column, value, reason).
    cells : list or None
        Cell ids already known (polygon cells), ``""`` where not.
    parts : list or None
        Index of each entry within its record (points of a MultiPoint,
        cells of a polygon); None means all 0.
    located : numpy uint64 array or None
        Integer ids of the entries' cells at the ingest's level, binned already from these coordinates
        in the same way (:func:`~dggs.storage.readers_arrays.cell_order` sorts by them), meaningful where
        the coordinates are good: :func:`~dggs.storage.convert.prepare` bins none again.
    record : callable
        ``record(i)`` gives entry ``i`` as a dict, for the rejects table.
    """

    consumed: int
    rows: Sequence[int]
    lines: Sequence[int] | None
    lat: Column
    lng: Column
    values: dict[str, Column]
    text: bool
    record: Callable[[int], dict]
    bad: dict[int, tuple[str | None, Any, str]] = field(default_factory=dict)
    cells: Sequence[str] | None = None
    parts: Sequence[int] | None = None
    located: Any = None

    def __len__(self) -> int:
        return len(self.rows)


def _skip(iterator: Iterator[Any], n: int) -> None:
    collections.deque(itertools.islice(iterator, n), maxlen=0)


def check_columns(path: str | Path, header: Sequence[str], wanted: Sequence[str]) -> None:
    """Raise DggsValueError naming the columns of ``wanted`` missing from ``header``.

    Raises
    ------
    DggsValueError
        If a column of ``wanted`` is not in ``header``.
    """
    missing = [name for name in wanted if name not in header]
    if missing:
        have = f"its header is {', '.join(map(repr, header))}" if len(header) else "it has no columns at all"
        raise DggsValueError(f"{path} has no column(s) {', '.join(map(repr, missing))}; {have}")


#: Lines a quoted CSV field may span before it is taken for an unclosed quote.
MAX_FIELD_LINES = 10_000


def count_csv_rows(path: str | Path) -> int:
    """Count data rows of a CSV file quickly (newlines, less the header).

    Used for progress bars; quoted fields with newlines make it an upper bound.
    """
    count = 0
    last = b"\n"
    with open(path, "rb") as fh:
        while block := fh.read(1 << 20):
            count += block.count(b"\n")
            last = block[-1:]
    if last != b"\n":
        count += 1
    return max(count - 1, 0)


def sniff_kind(path: str | os.PathLike[str]) -> str:
    """Return ``"csv"``, ``"geojson"`` or ``"vector"`` (read by pyogrio) from a file's name.

    Raises
    ------
    StorageError
        For other extensions.
    """
    suffix = Path(path).suffix.lower()
    if suffix in (".csv", ".tsv", ".txt"):
        return "csv"
    if suffix in (".geojson", ".json"):
        return "geojson"
    if suffix in (".gpkg", ".shp", ".fgb", ".parquet", ".geoparquet"):
        return "vector"
    raise StorageError(
        f"cannot tell the format of {path}: expected .csv, .tsv, .txt, .geojson, .json, "
        ".gpkg, .shp, .fgb or .parquet"
    )
