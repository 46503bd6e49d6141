"""String ids in and out of containers, around the compiled codec; the pure-Python scalar codec.

numpy ``U``/``S`` arrays reach the kernels of :mod:`dggs.index._kernel.codec`
as zero-copy views of their character codes, pyarrow string arrays as their
buffers, lists of Python strings NUL-joined.  The scalar helpers
(:func:`parse_str`, :func:`format_int`, :func:`valid_int`) are pure Python and
table driven: a few hundred nanoseconds a call, no numpy.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from .._kernel.bits import FACE_SHIFT, L1_SHIFT, MAX_LEVEL
from .._kernel.codec import fill_codes, max_level, parse_arrow, parse_codes, parse_joined

__all__ = [
    "arrow_strings", "format_int", "format_u8", "format_u32", "parse_arrow_array", "parse_chars", "parse_pystrings",
    "parse_str", "valid_id", "valid_int", "level_of", "face_of",
]  # fmt: skip

_LOW_BITS = (1 << L1_SHIFT) - 1  # the level-2..28 fields
_DIGIT_LOW = sum(1 << (2 * j) for j in range(MAX_LEVEL - 1))  # low bit of each 2-bit field


def _format(ids: np.ndarray, dtype: Any) -> tuple[np.ndarray, int]:
    ids = np.ascontiguousarray(ids, dtype=np.uint64).reshape(-1)
    deepest, bad = max_level(ids)
    if bad >= 0:
        return np.zeros((ids.shape[0], 1), dtype=dtype), bad
    out = np.empty((ids.shape[0], max(deepest + 1, 1)), dtype=dtype)
    fill_codes(ids, out)
    return out, -1


def format_u32(ids: np.ndarray) -> tuple[np.ndarray, int]:
    """Character codes (uint32, ``(N, max level + 1)``) of ids; view as ``U{width}``.

    The null id 0 gives an empty string.  Returns ``(codes, first_bad)``; when
    an id is not well formed, ``first_bad`` is its index (and codes are zeros).
    """
    return _format(ids, np.uint32)


def format_u8(ids: np.ndarray) -> tuple[np.ndarray, int]:
    """Like :func:`format_u32`, as uint8 codes (view as ``S{width}``)."""
    return _format(ids, np.uint8)


# --------------------------------------------------------------------------
# numpy and Arrow containers
# --------------------------------------------------------------------------


def parse_chars(flat: np.ndarray) -> tuple[np.ndarray, int]:
    """Parse a 1-d numpy ``U`` or ``S`` array through a zero-copy view of its codes.

    Returns ``(ids, first_bad)`` as :func:`parse_codes`.
    """
    n = flat.shape[0]
    wide = flat.dtype.kind == "U"
    width = flat.dtype.itemsize // (4 if wide else 1)
    if width == 0 or n == 0:  # ``U0``: only empty strings
        return np.zeros(n, dtype=np.uint64), (0 if n else -1)
    if not flat.dtype.isnative:
        flat = flat.astype(flat.dtype.newbyteorder("="))
    codes = np.ascontiguousarray(flat).view(np.uint32 if wide else np.uint8).reshape(n, width)
    ids, bad = parse_codes(codes)
    return ids, int(bad)


def parse_arrow_array(arr: Any, pa: Any) -> tuple[np.ndarray, int]:
    """Parse one pyarrow string (or binary) Array from its buffers; nulls are invalid.

    ``pa`` is the pyarrow module.  Returns ``(ids, first_bad)``.
    """
    n = len(arr)
    t = arr.type
    large = pa.types.is_large_string(t) or pa.types.is_large_binary(t)
    if n == 0:
        return np.zeros(0, dtype=np.uint64), -1
    validity, off_buf, data_buf = arr.buffers()[:3]
    offsets = np.frombuffer(off_buf, dtype=np.int64 if large else np.int32)
    data = np.frombuffer(data_buf, dtype=np.uint8) if data_buf is not None else np.zeros(0, dtype=np.uint8)
    bits = np.frombuffer(validity, dtype=np.uint8) if validity is not None and arr.null_count else np.zeros(0, dtype=np.uint8)
    ids, bad = parse_arrow(data, offsets, bits, arr.offset, n)
    return ids, int(bad)


def arrow_strings(ids: np.ndarray, pa: Any, large: bool = False) -> tuple[Any, int]:
    """``(array, first_bad)``: a pyarrow ``string`` (``large_string``) Array of ids, the null id 0 as a null.

    ``pa`` is the pyarrow module; ``array`` is None when an id is not well formed.

    Raises
    ------
    OverflowError
        Over 2**31 characters of ids for 32-bit offsets (``large`` takes any number).
    """
    ids = np.ascontiguousarray(ids, dtype=np.uint64).reshape(-1)
    codes, bad = format_u8(ids)
    if bad >= 0:
        return None, bad
    n, width = codes.shape
    if not large and n * width >= 2**31:
        raise OverflowError("too many ids for 32-bit Arrow offsets; use large_string")
    off_type = np.int64 if large else np.int32
    if codes[:, -1].all():  # ids of one level: the codes are the data buffer as they are
        data, offsets = codes.reshape(-1), np.arange(0, n * width + 1, width, dtype=off_type)
    else:
        data, offsets = codes[codes != 0], np.zeros(n + 1, dtype=off_type)
        np.cumsum(np.count_nonzero(codes, axis=1), out=offsets[1:])
    nulls = ids == 0
    n_null = int(nulls.sum())
    valid = pa.py_buffer(np.packbits(~nulls, bitorder="little")) if n_null else None
    buffers = [valid, pa.py_buffer(offsets), pa.py_buffer(data)]
    return pa.Array.from_buffers(pa.large_string() if large else pa.string(), n, buffers, null_count=n_null), -1


def parse_pystrings(items: Any) -> tuple[np.ndarray, int] | None:
    """Parse a sequence of Python ``str`` (or ``bytes``) in one pass over their NUL-joined codes.

    Returns ``(ids, first_bad)``, or None if an element is of another type.
    """
    try:
        if len(items) and isinstance(items[0], bytes):
            data = np.frombuffer(b"\x00".join(items), dtype=np.uint8)
        else:
            text = "\x00".join(items)
            wide = not text.isascii()
            data = np.frombuffer(text.encode("utf-32-le" if wide else "ascii", "surrogatepass"), dtype=np.uint32 if wide else np.uint8)
    except TypeError:
        return None
    ids, bad, pieces = parse_joined(data, len(items))
    if pieces != len(items):  # an element holds a NUL itself: one by one
        ids = np.array([parse_str(x if isinstance(x, str) else x.decode("ascii", "replace")) for x in items], dtype=np.uint64)
        zero = np.flatnonzero(ids == 0)
        bad = zero[0] if zero.size else -1
    return ids, int(bad)


# --------------------------------------------------------------------------
# Scalar helpers (pure Python, table driven)
# --------------------------------------------------------------------------

_FACES = "ABCDEFGHIJKLMNOPQRST"
#: "C" -> id of face C; "C4" -> id of its level-1 cell 4.
_HEAD_ID: dict[str, int] = {}
#: id >> 54 (sign, marker, face, level-1 code) -> the first one or two characters.
_HEAD_STR: dict[int, str] = {}
for _f, _letter in enumerate(_FACES):
    _base = (1 << 62) | (_f << FACE_SHIFT)
    _HEAD_ID[_letter] = _base
    _HEAD_STR[_base >> L1_SHIFT] = _letter
    for _d in range(6):
        _HEAD_ID[_letter + str(_d)] = _base | ((_d + 1) << L1_SHIFT)
        _HEAD_STR[(_base >> L1_SHIFT) | (_d + 1)] = _letter + str(_d)
#: The 27 two-bit fields of levels 2..28 in four chunks, from the top: 7, 7, 7 and 6 fields.  Per chunk,
#: a list from its bits to its digits ("" for no digit; None where a filled field follows an empty one)
#: and a dict back, so one id is a few look-ups each way.
_CHUNK_WIDTHS = (7, 7, 7, 6)


def _chunk_tables(width: int) -> tuple[list[str | None], dict[str, int]]:
    to_str: list[str | None] = [None] * (1 << (2 * width))
    to_bits: dict[str, int] = {"": 0}
    to_str[0] = ""
    for m in range(1, width + 1):
        for prefix in [t for t in to_bits if len(t) == m - 1]:
            for d in range(3):
                t = prefix + str(d)
                bits = to_bits[prefix] | ((d + 1) << (2 * (width - m)))
                to_bits[t], to_str[bits] = bits, t
    return to_str, to_bits


(_S0, _B0), (_S1, _B1), (_S2, _B2), (_S3, _B3) = (_chunk_tables(w) for w in _CHUNK_WIDTHS)
del _f, _letter, _base, _d


def parse_str(s: str) -> int:
    """Integer id of a string id, or 0 if it is not valid (never raises for a str).

    Seven digits at a time through dict look-ups (which only hold valid digit
    strings, so any other character, a space or a NUL gives 0).
    """
    head = _HEAD_ID.get(s[:2])
    if head is None:
        return 0
    n = len(s)
    if n <= 2:
        return head
    a = _B0.get(s[2:9])
    if a is None:
        return 0
    if n <= 9:
        return head | (a << 40)
    b = _B1.get(s[9:16])
    if b is None:
        return 0
    if n <= 16:
        return head | (a << 40) | (b << 26)
    c = _B2.get(s[16:23])
    d = _B3.get(s[23:])
    if c is None or d is None:
        return 0
    return head | (a << 40) | (b << 26) | (c << 12) | d


def format_int(c: int) -> str | None:
    """String id of an integer id, or None if it is not well formed (never raises for an int)."""
    head = _HEAD_STR.get(c >> L1_SHIFT)
    if head is None:  # negative, too big, no marker, face >= 20 or level-1 code 7
        return None
    low = c & _LOW_BITS
    if not low:
        return head
    if len(head) == 1:  # digits below an empty level 1
        return None
    a = _S0[low >> 40]
    rest = low & 0xFF_FFFF_FFFF
    if not rest:
        return None if a is None else head + a
    b = _S1[rest >> 26]
    if a is None or b is None or len(a) < 7:  # a hole: an empty field above a filled one
        return None
    rest &= 0x3FF_FFFF
    if not rest:
        return head + a + b
    c2 = _S2[rest >> 12]
    if c2 is None or len(b) < 7:
        return None
    rest &= 0xFFF
    if not rest:
        return head + a + b + c2
    d = _S3[rest]
    if d is None or len(c2) < 7:
        return None
    return head + a + b + c2 + d


def valid_int(c: int) -> bool:
    """Whether a Python int is a well-formed id (never raises for an int)."""
    if (c >> L1_SHIFT) not in _HEAD_STR:
        return False
    low = c & _LOW_BITS
    if not low:
        return True
    if not (c >> L1_SHIFT) & 7:
        return False
    m = (low | (low >> 1)) & _DIGIT_LOW
    return m == _DIGIT_LOW & ~((m & -m) - 1)


def valid_id(c: int) -> int:
    """``c`` if it is a well-formed id, else 0 (never raises for an int)."""
    return c if valid_int(c) else 0


def level_of(c: int) -> int | None:
    """Level of an integer id, or None if it is not well formed (never raises for an int)."""
    if not valid_int(c):
        return None
    low = c & _LOW_BITS
    if low:  # the lowest filled 2-bit field: level 28 is bits 0-1
        return MAX_LEVEL - ((low & -low).bit_length() - 1) // 2
    return 1 if (c >> L1_SHIFT) & 7 else 0


def face_of(c: int) -> int | None:
    """Face (0..19) of an integer id, or None if it is not well formed (never raises for an int)."""
    return (c >> FACE_SHIFT) & 31 if valid_int(c) else None
