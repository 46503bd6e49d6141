"""Readers that cut an input into :class:`RawBatch` es of column values.

Each reader streams its input (a CSV file is never held in memory whole),
can skip the records already committed by an earlier, interrupted run, and
reports row (and, for CSV, line) numbers for error messages.  Converting and
checking values is left to :mod:`dggs.storage.ingest`.
"""

from __future__ import annotations

import collections
import csv
import itertools
import operator
import os
from collections.abc import Callable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from dggs.errors import DggsValueError, StorageError

from .errors import BadRowError

#: A column of raw values: a list, tuple or numpy array.
Column = Any

__all__ = ["RawBatch", "csv_batches", "check_columns", "csv_header", "count_csv_rows", "sniff_kind"]


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

    def __len__(self) -> int:
        return len(self.rows)


def _skip(iterator: Iterator[Any], n: int) -> None:
    collections.deque(itertools.islice(iterator, n), maxlen=0)


def _codec(encoding: str) -> str:
    """UTF-8 input may start with a byte-order mark: skip it."""
    return "utf-8-sig" if encoding.lower().replace("_", "-") in ("utf-8", "utf8") else encoding


def csv_header(path: str | Path, delimiter: str = ",", encoding: str = "utf-8") -> list[str]:
    """Return the header of a CSV file (its first row)."""
    with open(path, newline="", encoding=_codec(encoding)) as fh:
        try:
            return next(csv.reader(fh, delimiter=delimiter))
        except StopIteration:
            raise DggsValueError(f"{path} is empty (no header row)") from None
        except UnicodeDecodeError as exc:
            raise _not_text(path, encoding, 0, exc) from exc
        except csv.Error as exc:
            raise DggsValueError(f"{path} is not a readable CSV file: {exc}") from exc


def check_columns(path: str | Path, header: Sequence[str], wanted: Sequence[str]) -> None:
    """Raise DggsValueError naming the columns of ``wanted`` missing from ``header``."""
    missing = [name for name in wanted if name not in header]
    if missing:
        raise DggsValueError(
            f"{path} has no column(s) {', '.join(map(repr, missing))}; "
            f"its header is {', '.join(map(repr, header))}"
        )


#: Lines a quoted CSV field may span before it is taken for an unclosed quote.
MAX_FIELD_LINES = 10_000


def _unclosed_quote(path: str | Path, lines: list[str], first_line: int, delimiter: str, to_eof: bool) -> BadRowError:
    """The error for a quoted field that never closes: names the line where its record starts."""
    reader = csv.reader(lines, delimiter=delimiter, strict=True)
    start = first_line + 1
    try:
        for _ in reader:
            start = first_line + reader.line_num + 1
    except csv.Error:
        pass
    where = "to the end of the file" if to_eof else f"over more than {MAX_FIELD_LINES:,} lines"
    return BadRowError(
        str(path), 0, start, None, None,
        f"a quoted field opened on this line runs {where}: a closing quote (\") is missing",
        hint="the batches before it are stored; close the quote and run the same command again",
    )


def csv_batches(
    path: str | Path,
    lat: str,
    lng: str,
    values: Sequence[str],
    batch_size: int,
    skip: int = 0,
    delimiter: str = ",",
    types: Mapping[str, str] | None = None,
    encoding: str = "utf-8",
) -> Iterator[RawBatch]:
    """Stream a CSV file with a header row as batches of column values.

    Reads ``batch_size`` records at a time.  A chunk without quote characters
    whose value columns are all known (in ``types``, a live mapping) to be
    numeric is parsed by numpy's C reader; any other chunk, or one that numpy
    refuses, goes through the :mod:`csv` module, which finds the bad rows.
    Both give the same values.  Blank lines count as consumed records but give
    no entries.

    Raises
    ------
    DggsValueError
        If a named column is not in the header, or the text is not in
        ``encoding``.
    """
    header = csv_header(path, delimiter, encoding)
    wanted = [lat, lng, *values]
    check_columns(path, header, wanted)
    index = [header.index(name) for name in wanted]
    types = types if types is not None else {}
    with open(path, newline="", encoding=_codec(encoding)) as fh:
        head = csv.reader(fh, delimiter=delimiter)
        line = 0
        try:
            next(head)
            _skip(head, skip)
        except UnicodeDecodeError as exc:
            raise _not_text(path, encoding, head.line_num, exc) from exc
        line = head.line_num  # lines consumed so far
        done = skip
        while True:
            try:
                lines = list(itertools.islice(fh, batch_size))
            except UnicodeDecodeError as exc:
                raise _not_text(path, encoding, line, exc) from exc
            if not lines:
                return
            text = "".join(lines)
            if '"' in text:
                extra = 0
                while text.count('"') % 2:  # a quoted field runs on: finish it
                    more = next(fh, None)
                    if more is None or extra >= MAX_FIELD_LINES:
                        if _open_at_end(lines, delimiter):
                            raise _unclosed_quote(path, lines, line, delimiter, more is None)
                        break
                    extra += 1
                    lines.append(more)
                    text += more
            batch = None
            if '"' not in text and all(types.get(v) in ("INTEGER", "REAL") for v in values):
                batch = _numeric_chunk(lines, index, header, wanted, types, delimiter, done, line)
            if batch is None:
                batch = _csv_chunk(lines, index, header, wanted, delimiter, done, line, path)
            done += batch.consumed
            line += len(lines)
            yield batch


def _open_at_end(lines: list[str], delimiter: str) -> bool:
    """True if parsing ``lines`` ends inside a quoted field."""
    try:
        for _ in csv.reader(lines, delimiter=delimiter, strict=True):
            pass
    except csv.Error as exc:
        return "unexpected end of data" in str(exc)
    return False


def _not_text(path: str | Path, encoding: str, line: int, exc: UnicodeDecodeError) -> DggsValueError:
    return DggsValueError(
        f"{path} is not {encoding} text (after line {line}: {exc.reason}); "
        "pass the file's encoding, e.g. encoding='latin-1'"
    )


def _numeric_chunk(
    lines: list[str],
    index: list[int],
    header: list[str],
    wanted: list[str],
    types: Mapping[str, str],
    delimiter: str,
    done: int,
    line: int,
) -> RawBatch | None:
    """Parse a quote-free, all-numeric chunk with numpy; None if numpy refuses."""
    dtype = [("lat", "f8"), ("lng", "f8")] + [
        (f"v{i}", "i8" if types[name] == "INTEGER" else "f8") for i, name in enumerate(wanted[2:])
    ]
    try:
        parsed = np.loadtxt(
            lines, delimiter=delimiter, usecols=index, dtype=dtype, comments=None, ndmin=1
        )
    except (ValueError, IndexError, OverflowError):
        return None
    if parsed.shape != (len(lines),):
        return None  # blank lines were dropped: let the csv path account for them

    def record(i: int, _lines: list[str] = lines) -> dict:
        return dict(zip(header, _lines[i].rstrip("\r\n").split(delimiter)))

    return RawBatch(
        consumed=len(lines),
        rows=range(done + 1, done + len(lines) + 1),
        lines=range(line + 1, line + len(lines) + 1),
        lat=parsed["lat"],
        lng=parsed["lng"],
        values={name: parsed[f"v{i}"] for i, name in enumerate(wanted[2:])},
        text=False,
        record=record,
    )


def _csv_chunk(
    lines: list[str],
    index: list[int],
    header: list[str],
    wanted: list[str],
    delimiter: str,
    done: int,
    line: int,
    path: str | Path,
) -> RawBatch:
    """Parse a chunk of lines with the csv module, marking malformed rows bad."""
    reader = csv.reader(lines, delimiter=delimiter)
    records: list[list[str]] = []
    rows: list[int] = []
    line_numbers: list[int] = []
    consumed = 0
    try:
        for record in reader:
            consumed += 1
            if record:  # blank lines are not records
                records.append(record)
                rows.append(done + consumed)
                line_numbers.append(line + reader.line_num)
    except csv.Error as exc:
        raise DggsValueError(f"{path}, line {line + reader.line_num}: {exc}") from exc
    need = max(index) + 1
    bad: dict[int, tuple[str | None, Any, str]] = {}
    for i, record in enumerate(records):
        if len(record) < need:
            bad[i] = (None, record, f"has {len(record)} fields, expected at least {need}")
            records[i] = record + [""] * (need - len(record))
    getter = operator.itemgetter(*index)
    columns = list(zip(*map(getter, records))) if records else [()] * len(wanted)

    def record_of(i: int, _records: list[list[str]] = records) -> dict:
        return dict(zip(header, _records[i]))

    # Physical line numbers: a record's last line, less the lines it spans.
    starts = [n - lines_in(r) + 1 for n, r in zip(line_numbers, records)]
    return RawBatch(
        consumed=consumed,
        rows=rows,
        lines=starts,
        lat=columns[0],
        lng=columns[1],
        values=dict(zip(wanted[2:], columns[2:])),
        text=True,
        record=record_of,
        bad=bad,
    )


def lines_in(record: list[str]) -> int:
    """Count the physical lines a parsed CSV record spanned (1 + embedded newlines)."""
    return 1 + sum(field.count("\n") for field in record)


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
    """Return ``"csv"`` or ``"geojson"`` from a file's name.

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
    raise StorageError(f"cannot tell the format of {path}: expected .csv, .tsv, .geojson or .json")
