"""Read CSV files with pyarrow's streaming reader (:func:`pyarrow.csv.open_csv`).

pyarrow parses the text (quotes, quoted newlines, delimiters, encodings) and
hands back record batches of strings; this module turns them into
:class:`~dggs.storage.readers.RawBatch` es of exactly ``batch_size`` input
records, and keeps what the store promises about CSV input:

* every input record (a blank line included) counts once, in file order, so
  a resumed ingest skips exactly the records committed before;
* each entry knows its record number and the physical line it starts on
  (quoted newlines counted), for error messages and table ``rejects``;
* a record with too few fields is a bad entry, not a parse error; one with
  too many keeps its leading fields, as before;
* a quoted field that runs to the end of the file, or over
  :data:`~dggs.storage.readers.MAX_FIELD_LINES` lines, raises
  :class:`~dggs.storage.errors.BadRowError` naming the line its record starts
  on, after the batches before it;
* values stay text (integers exact, see :mod:`dggs.storage.convert`) unless
  every coordinate and every value column of a batch parses as a number of
  its known type, in which case the batch is handed over as numpy arrays.
"""

from __future__ import annotations

import codecs
import csv
import io
from collections.abc import Iterator, Mapping, Sequence
from pathlib import Path
from typing import Any

import numpy as np

from dggs.errors import DggsValueError

from . import readers
from .readers import RawBatch
from .readers_csv_chunks import Chunk as _Chunk
from .readers_csv_chunks import is_utf8 as _is_utf8
from .readers_csv_chunks import rebatch as _rebatch

__all__ = ["csv_header", "csv_batches"]

#: Bytes pyarrow parses at a time.
BLOCK_SIZE = 1 << 20


def _options(delimiter: str, encoding: str, handler: Any = None, names: Sequence[str] | None = None) -> dict:
    import pyarrow as pa
    import pyarrow.csv as pacsv

    read = pacsv.ReadOptions(
        use_threads=False,
        block_size=BLOCK_SIZE,
        encoding="utf8" if _is_utf8(encoding) else encoding,
    )
    parse = pacsv.ParseOptions(
        delimiter=delimiter,
        quote_char='"',
        double_quote=True,
        escape_char=False,
        newlines_in_values=True,
        ignore_empty_lines=False,
        invalid_row_handler=handler,
    )
    convert = pacsv.ConvertOptions(
        column_types={name: pa.string() for name in names or ()},
        strings_can_be_null=False,
        quoted_strings_can_be_null=False,
        null_values=[],
        check_utf8=True,
    )
    return {"read_options": read, "parse_options": parse, "convert_options": convert}


def _not_text(path: str | Path, encoding: str, line: int, reason: str) -> DggsValueError:
    return DggsValueError(
        f"{path} is not {encoding} text (after line {line}: {reason}); "
        "pass the file's encoding, e.g. encoding='latin-1'"
    )


def _arrow_error(path: str | Path, encoding: str, line: int, exc: Exception) -> DggsValueError:
    text = str(exc)
    if "straddl" in text:  # a record longer than pyarrow's block
        return DggsValueError(
            f"{path}, line {line + 1}: a record longer than {BLOCK_SIZE >> 20} MiB "
            "(a field that long is most likely an unclosed quote or not CSV at all)"
        )
    if "UTF8" in text or "UTF-8" in text or isinstance(exc, UnicodeDecodeError):
        return _not_text(path, encoding, line, "invalid UTF8 data" if "UTF8" in text else text)
    return DggsValueError(f"{path} is not a readable CSV file (after line {line}): {text}")


def csv_header(path: str | Path, delimiter: str = ",", encoding: str = "utf-8") -> list[str]:
    """Return the header of a CSV file (its first record), read by pyarrow.

    Parses a prefix of the file with :func:`pyarrow.csv.read_csv`, which
    finishes its work before returning (a streaming reader dropped after one
    block could leave a read-ahead task behind).

    Raises
    ------
    DggsValueError
        If the file is empty, is not text in ``encoding``, or pyarrow cannot parse it.
    """
    import pyarrow as pa
    import pyarrow.csv as pacsv

    size = 1 << 16
    while True:
        with open(path, "rb") as fh:
            data = fh.read(size)
        whole = len(data) < size
        if not _is_utf8(encoding):
            try:
                text = codecs.getincrementaldecoder(encoding)().decode(data, final=whole)
            except UnicodeDecodeError as exc:
                raise _not_text(path, encoding, 0, exc.reason) from exc
            data = text.encode("utf-8")
        end = 0
        table = None
        while table is None:  # the header's first line, and more if a quoted name runs on
            end = data.find(b"\n", end) + 1 or len(data)
            if end == len(data) and not whole:
                break
            head = data[:end]
            if whole and end == len(data) and not head.endswith((b"\n", b"\r")):
                head += b"\n"  # a header-only file without its final newline is still a header
            try:
                table = pacsv.read_csv(pa.BufferReader(head), **_options(delimiter, "utf-8", lambda row: "skip"))
            except (pa.ArrowInvalid, UnicodeDecodeError) as exc:
                if "Empty CSV file" in str(exc) and whole and end == len(data):
                    raise DggsValueError(f"{path} is empty (no header row)") from None
                if end == len(data):
                    raise _arrow_error(path, encoding, 0, exc) from exc
        if table is None:
            size *= 4
            continue
        try:
            return list(table.schema.names)
        except UnicodeDecodeError as exc:  # the header is not UTF-8: the input file, not the store
            utf16 = data.startswith((codecs.BOM_UTF16_LE, codecs.BOM_UTF16_BE))
            hint = "; it looks like UTF-16: pass encoding='utf-16'" if utf16 else ""
            raise _not_text(path, encoding, 0, exc.reason + hint) from None


def _may_have_blank_lines(path: str | Path) -> bool:
    """True if the file holds an empty line (it may be inside a quoted field)."""
    tail = b""
    with open(path, "rb") as fh:
        while block := fh.read(1 << 22):
            text = tail + block
            if b"\n\n" in text or b"\n\r\n" in text or b"\r\r" in text:
                return True
            tail = block[-2:]
    return False


class _Lines:
    """Forward-only access to a file's physical lines (to tell blank lines from ``,,``)."""

    def __init__(self, path: str | Path) -> None:
        self.fh = open(path, "rb")  # noqa: SIM115 - closed by close()
        self.at = 0  # lines read so far
        self.text = b""

    def get(self, number: int) -> bytes:
        while self.at < number:
            self.text = self.fh.readline()
            self.at += 1
        return self.text

    def close(self) -> None:
        self.fh.close()


def _newlines(columns: list[Any]) -> np.ndarray:
    import pyarrow.compute as pc

    n = len(columns[0]) if columns else 0
    total = np.zeros(n, dtype=np.int64)
    for col in columns:
        if pc.any(pc.match_substring(col, "\n")).as_py():
            total += pc.count_substring(col, "\n").to_numpy(zero_copy_only=False)
    return total


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
    """Stream a CSV file with a header row as batches of ``batch_size`` records.

    The records after the first ``skip`` ones are read with
    :func:`pyarrow.csv.open_csv`.  Blank lines count as consumed records but
    give no entries.

    Raises
    ------
    DggsValueError
        If a named column is not in the header, or the text is not in
        ``encoding``.
    BadRowError
        For a quoted field that never closes.
    """
    import pyarrow as pa
    import pyarrow.compute as pc
    import pyarrow.csv as pacsv

    header = csv_header(path, delimiter, encoding)
    wanted = [lat, lng, *values]
    readers.check_columns(path, header, wanted)
    for name in dict.fromkeys(wanted):
        if header.count(name) > 1:
            raise DggsValueError(
                f"{path} has column {name!r} twice in its header ({', '.join(map(repr, header))}); "
                "rename one of them"
            )
    index = [header.index(name) for name in wanted]
    need = max(index) + 1
    types = types if types is not None else {}
    header_lines = 1 + sum(name.count("\n") for name in header)
    invalid: list[tuple[int, str]] = []  # (record number incl. header, text) of malformed records

    def handler(row: Any) -> str:
        invalid.append((int(row.number) if row.number is not None else -1, row.text))
        return "skip"

    blanks = _may_have_blank_lines(path)
    line_file = _Lines(path) if blanks else None
    try:
        reader = pacsv.open_csv(path, **_options(delimiter, encoding, handler, header))
    except (pa.ArrowInvalid, UnicodeDecodeError) as exc:
        if line_file is not None:
            line_file.close()
        if "Empty CSV file" in str(exc):  # the header (read above) without a final newline: no rows
            return
        raise _arrow_error(path, encoding, 0, exc) from exc
    state = {"record": 0, "line": header_lines}  # records and lines read so far

    def chunks() -> Iterator[_Chunk]:
        """Records in file order, malformed ones put back in their place."""
        pos = 0  # invalid rows consumed
        while True:
            try:
                batch = reader.read_next_batch()
            except StopIteration:
                batch = None
            except (pa.ArrowInvalid, UnicodeDecodeError) as exc:
                raise _arrow_error(path, encoding, state["line"], exc) from exc
            columns = list(batch.columns) if batch is not None else [pa.array([], pa.string())] * len(header)
            n = len(columns[0]) if columns else 0
            start = state["record"] + 1  # number of the next record (1-based, data only)
            if pos == len(invalid):
                if n:
                    chunk = _Chunk(columns, None, None, _newlines(columns))
                    state["record"] += n
                    yield chunk
                if batch is None:
                    return
                continue
            # Interleave the malformed records, by number, with the parsed ones.
            pieces: list[_Chunk] = []
            taken = 0
            record = start
            while taken < n or (pos < len(invalid) and (batch is None or invalid[pos][0] - 1 == record)):
                if pos < len(invalid) and (invalid[pos][0] - 1 == record or taken == n):
                    number, text = invalid[pos]
                    pos += 1
                    fields = next(csv.reader(io.StringIO(text), delimiter=delimiter), []) if text else []
                    reason = None
                    if len(fields) < need:
                        reason = f"has {len(fields)} fields, expected at least {need}"
                    padded = (fields + [""] * len(header))[: len(header)]
                    pieces.append(
                        _Chunk(
                            [pa.array([v], pa.string()) for v in padded],
                            [reason],
                            None,
                            np.array([text.count("\n")], dtype=np.int64),
                            [fields],
                        )
                    )
                    record += 1
                    continue
                # parsed records up to the next malformed one
                upto = n
                if pos < len(invalid):
                    if invalid[pos][0] - 1 < record:  # pyarrow did not number it: cannot place it
                        raise DggsValueError(
                            f"{path}, after line {state['line']}: cannot place the malformed record "
                            f"{invalid[pos][1][:80]!r}"
                        )
                    upto = min(n, taken + (invalid[pos][0] - 1 - record))
                part = [c.slice(taken, upto - taken) for c in columns]
                pieces.append(_Chunk(part, None, None, _newlines(part)))
                record += upto - taken
                taken = upto
            for piece in pieces:
                state["record"] += len(piece)
                yield piece
            if batch is None:
                return

    def records() -> Iterator[_Chunk]:
        """Chunks with blank lines marked; lines tracked in ``state``."""
        for chunk in chunks():
            if line_file is not None:
                empty = np.ones(len(chunk), dtype=bool)
                for col in chunk.columns:
                    empty &= np.asarray(pc.utf8_length(col).to_numpy(zero_copy_only=False)) == 0
                if chunk.bad is not None:
                    empty &= np.array([b is None for b in chunk.bad])
                if empty.any():
                    line0 = chunk_line0[0]
                    starts = line0 + 1 + np.concatenate(([0], np.cumsum(1 + chunk.newlines)[:-1]))
                    for i in np.flatnonzero(empty).tolist():
                        if line_file.get(int(starts[i])).strip(b"\r\n") != b"":
                            empty[i] = False
                    chunk.blank = empty if empty.any() else None
            chunk_line0[0] += int(len(chunk) + chunk.newlines.sum())
            state["line"] = chunk_line0[0]
            yield chunk

    chunk_line0 = [header_lines]
    try:
        yield from _rebatch(
            records(), path, header, wanted, index, batch_size, skip, header_lines, types, delimiter, encoding
        )
    finally:
        reader.close()
        if line_file is not None:
            line_file.close()
