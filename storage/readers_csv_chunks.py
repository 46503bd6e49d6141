"""Cut the record chunks of :mod:`dggs.storage.readers_csv` into RawBatches.

Counting records and physical lines, dropping the records a resumed ingest
committed before, refusing unclosed quotes, and handing values over as text
or, when every column of a batch parses as its known numeric type, as numpy
arrays.
"""

from __future__ import annotations

import csv
import io
from collections.abc import Iterator, Mapping
from pathlib import Path
from typing import Any

import numpy as np

from . import readers
from .errors import BadRowError
from .readers import RawBatch

__all__ = ["Chunk", "is_utf8", "rebatch"]


def is_utf8(encoding: str) -> bool:
    """Whether ``encoding`` names UTF-8 (with or without a byte-order mark)."""
    return encoding.lower().replace("_", "-") in ("utf-8", "utf8", "utf-8-sig")


class Chunk:
    """Consecutive input records as string columns, with per-record extras."""

    __slots__ = ("columns", "bad", "blank", "newlines", "fields")

    def __init__(
        self,
        columns: list[Any],
        bad: list[str | None] | None,
        blank: np.ndarray | None,
        newlines: np.ndarray,
        fields: list[list[str] | None] | None = None,
    ) -> None:
        self.columns = columns  # pyarrow string arrays, one per header column
        self.bad = bad  # per record: reason it is malformed, or None
        self.blank = blank  # per record: True for a blank line
        self.newlines = newlines  # per record: newlines inside its fields
        self.fields = fields

    def __len__(self) -> int:
        return len(self.newlines)


def _unclosed(path: str | Path, line: int, to_eof: bool) -> BadRowError:
    where = "to the end of the file" if to_eof else f"over more than {readers.MAX_FIELD_LINES:,} lines"
    return BadRowError(
        str(path), 0, line, None, None,
        f"a quoted field opened on this line runs {where}: a closing quote (\") is missing",
        hint="the batches before it are stored; close the quote and run the same command again",
    )


def _open_quote_at_end(path: str | Path, line: int, delimiter: str, encoding: str) -> bool:
    """True if the text from physical ``line`` to the end of the file ends inside a quoted field."""
    with open(path, "rb") as fh:
        for _ in range(line - 1):
            if not fh.readline():
                return False
        tail = fh.read()
    text = tail.decode("utf-8" if is_utf8(encoding) else encoding, errors="replace")
    try:
        for _ in csv.reader(io.StringIO(text, newline=""), delimiter=delimiter, strict=True):
            pass
    except csv.Error as exc:
        return "unexpected end of data" in str(exc)
    return False


def rebatch(
    chunks: Iterator[Chunk],
    path: str | Path,
    header: list[str],
    wanted: list[str],
    index: list[int],
    batch_size: int,
    skip: int,
    header_lines: int,
    types: Mapping[str, str],
    delimiter: str,
    encoding: str,
) -> Iterator[RawBatch]:
    """Cut record chunks into RawBatches of ``batch_size`` records after ``skip``.

    Raises
    ------
    BadRowError
        If a quoted field is not closed (before the next record, or before the end of the file).
    """
    import pyarrow as pa

    pending: list[Chunk] = []
    count = 0  # records pending
    done = 0  # records before the pending ones
    line = header_lines  # lines before the pending ones
    exhausted = False
    it = iter(chunks)
    while True:
        while count <= batch_size + (skip - done if done < skip else 0) and not exhausted:
            chunk = next(it, None)
            if chunk is None:
                exhausted = True
                break
            pending.append(chunk)
            count += len(chunk)
        if not count:
            return
        merged = _concat(pending)
        pending = []
        if done < skip:  # resume: drop the records committed before
            drop = min(skip - done, count)
            line += int(drop + merged.newlines[:drop].sum())
            merged = _slice(merged, drop, count - drop)
            done += drop
            count -= drop
            if not count:
                continue
        take = min(batch_size, count)
        head = _slice(merged, 0, take)
        if take < count:
            pending = [_slice(merged, take, count - take)]
        # a field over the line limit, or running to the end of the file
        limit = readers.MAX_FIELD_LINES
        over = np.flatnonzero(head.newlines > limit)
        starts = line + 1 + np.concatenate(([0], np.cumsum(1 + head.newlines)[:-1])).astype(np.int64)
        if len(over):
            raise _unclosed(path, int(starts[over[0]]), False)
        if exhausted and take == count and head.newlines[-1] > 0 and _open_quote_at_end(
            path, int(starts[-1]), delimiter, encoding
        ):
            raise _unclosed(path, int(starts[-1]), True)
        yield _raw_batch(head, header, wanted, index, done, starts, types, pa)
        done += take
        line += int(take + head.newlines.sum())
        count -= take


def _concat(chunks: list[Chunk]) -> Chunk:
    import pyarrow as pa

    if len(chunks) == 1:
        return chunks[0]
    width = len(chunks[0].columns)
    columns = [pa.concat_arrays([c.columns[j] for c in chunks]) for j in range(width)]
    lengths = [len(c) for c in chunks]
    bad = None
    if any(c.bad is not None for c in chunks):
        bad = [r for c, n in zip(chunks, lengths, strict=True) for r in (c.bad if c.bad is not None else [None] * n)]
    blank = None
    if any(c.blank is not None for c in chunks):
        blank = np.concatenate([c.blank if c.blank is not None else np.zeros(n, bool)
                                for c, n in zip(chunks, lengths, strict=True)])
    fields = None
    if any(c.fields is not None for c in chunks):
        fields = [f for c, n in zip(chunks, lengths, strict=True)
                  for f in (c.fields if c.fields is not None else [None] * n)]
    return Chunk(columns, bad, blank, np.concatenate([c.newlines for c in chunks]), fields)


def _slice(chunk: Chunk, start: int, n: int) -> Chunk:
    return Chunk(
        [c.slice(start, n) for c in chunk.columns],
        chunk.bad[start : start + n] if chunk.bad is not None else None,
        chunk.blank[start : start + n] if chunk.blank is not None else None,
        chunk.newlines[start : start + n],
        chunk.fields[start : start + n] if chunk.fields is not None else None,
    )


def _numeric(col: Any, kind: str) -> np.ndarray | None:
    """``col`` (strings) as float64 or int64, or None if any entry does not parse."""
    import pyarrow as pa

    try:
        out = col.cast(pa.int64() if kind == "INTEGER" else pa.float64())
    except (pa.ArrowInvalid, pa.ArrowNotImplementedError):
        return None
    if out.null_count:
        return None
    return np.asarray(out.to_numpy(zero_copy_only=False))


def _raw_batch(
    chunk: Chunk,
    header: list[str],
    wanted: list[str],
    index: list[int],
    done: int,
    starts: np.ndarray,
    types: Mapping[str, str],
    pa: Any,
) -> RawBatch:
    n = len(chunk)
    keep = None
    if chunk.blank is not None:
        keep = np.flatnonzero(~chunk.blank)
    picked = [chunk.columns[i] for i in index]
    if keep is not None:
        taken = pa.array(keep)
        picked = [c.take(taken) for c in picked]
    value_names = wanted[2:]
    simple = chunk.bad is None and chunk.fields is None and keep is None
    numeric = None
    if simple and all(types.get(v) in ("INTEGER", "REAL") for v in value_names):
        kinds = ["REAL", "REAL", *(types[v] for v in value_names)]
        arrays = []
        for col, kind in zip(picked, kinds, strict=True):
            arr = _numeric(col, kind)
            if arr is None:
                break
            arrays.append(arr)
        else:
            numeric = arrays
    positions = keep.tolist() if keep is not None else range(n)
    rows = [done + 1 + p for p in positions] if keep is not None else range(done + 1, done + n + 1)
    lines = starts[keep].tolist() if keep is not None else starts.tolist()
    all_columns = chunk.columns
    fields = chunk.fields

    def record(i: int) -> dict:
        p = positions[i]
        own = fields[p] if fields is not None else None
        if own is not None:
            return dict(zip(header, own, strict=False))  # a bad row may have more or fewer fields than the header
        return {name: all_columns[j][p].as_py() for j, name in enumerate(header)}

    bad: dict[int, tuple[str | None, Any, str]] = {}
    if chunk.bad is not None:
        for i, p in enumerate(positions):
            reason = chunk.bad[p]
            if reason is not None:
                bad[i] = (None, fields[p] if fields is not None else None, reason)
    if numeric is not None:
        return RawBatch(
            consumed=n, rows=rows, lines=lines, lat=numeric[0], lng=numeric[1],
            values=dict(zip(value_names, numeric[2:], strict=True)), text=False, record=record,
        )
    texts = [c.to_pylist() for c in picked]
    return RawBatch(
        consumed=n, rows=rows, lines=lines, lat=texts[0], lng=texts[1],
        values=dict(zip(value_names, texts[2:], strict=True)), text=True, record=record, bad=bad,
    )
