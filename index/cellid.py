"""Cell ids: strings, one character per level, a parent's id a prefix of its children's.

Format: a face letter ``A``..``T`` (level 0, PROJ's faces 0..19), then one
digit ``0``..``5`` for the level-1 triangle, then one digit ``0``..``2`` per
further level.  ``"C401"`` is a level-3 cell on face 2.  So:

* ``level = len(id) - 1``; the parent at level ``l`` is ``id[:l + 1]``;
* sorting ids orders cells depth-first (each cell right before its
  descendants), and the descendants of ``c`` are exactly the ids in
  ``[c, c + "~")``: a range scan in SQLite;
* ids use only upper-case letters and digits (safe in URLs, file names, and
  case-insensitive stores).

Arrays of ids are numpy ``U`` arrays; they are built and parsed through a
zero-copy ``uint32`` view of the characters, never a Python loop per cell.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from dggs.errors import InvalidCellError, LevelError

__all__ = ["MAX_LEVEL", "FACE_LETTERS", "encode", "decode", "levels", "Decoded", "valid_mask", "as_id_array", "check_level"]

#: Deepest level: 40 (cells of about 1 mm^2 on the Earth).  Point location
#: and cell corners stay consistent to about 1e-6 of a cell's size there.
MAX_LEVEL = 40
FACE_LETTERS = "ABCDEFGHIJKLMNOPQRST"
_ORD_A = ord("A")
_ORD_0 = ord("0")


def check_level(level, name: str = "level") -> int:
    """Return ``level`` as an int, or raise :class:`LevelError` naming it."""
    if isinstance(level, (bool, np.bool_)) or not isinstance(level, (int, np.integer)):
        raise LevelError(f"{name} {level!r} must be an integer 0..{MAX_LEVEL}")
    if not 0 <= level <= MAX_LEVEL:
        raise LevelError(f"{name} {level!r} is out of range 0..{MAX_LEVEL}")
    return int(level)


def encode(face: np.ndarray, digits: np.ndarray, out: np.ndarray | None = None) -> np.ndarray:
    """Ids (``U`` array) of cells given faces (N,) and digits (N, level).

    With ``out`` (an (N, level + 1) uint32 view of a ``U`` array), the
    characters are written there instead.
    """
    n, level = digits.shape
    codes = np.empty((n, level + 1), dtype=np.uint32) if out is None else out
    codes[:, 0] = face
    codes[:, 0] += _ORD_A
    codes[:, 1:] = digits
    codes[:, 1:] += _ORD_0
    return codes.view(f"<U{level + 1}").reshape(n)


def as_id_array(cells) -> tuple[np.ndarray, bool]:
    """Cells as a 1-d ``U`` array, and whether the input was a single id."""
    if isinstance(cells, str):
        return np.array([cells]), True
    if isinstance(cells, np.ndarray) and cells.dtype.kind == "U":
        return cells.ravel(), False
    try:
        arr = np.asarray(list(cells) if not isinstance(cells, np.ndarray) else cells)
    except TypeError:
        raise InvalidCellError(f"{cells!r} is not a cell id (a string such as 'C401')") from None
    if arr.size == 0:
        return np.array([], dtype="<U1"), False
    if arr.dtype.kind != "U":
        bad = next((c for c in arr.ravel() if not isinstance(c, str)), arr.ravel()[0])
        raise InvalidCellError(f"{bad!r} is not a cell id (a string such as 'C401')")
    return arr.ravel(), False


class Decoded(NamedTuple):
    """Parsed ids: face (N,), level (N,), level-1 digit (N,), later digits (N, L - 1)."""

    face: np.ndarray
    level: np.ndarray
    l1: np.ndarray
    digits: np.ndarray


def _codes(ids: np.ndarray) -> np.ndarray:
    width = ids.dtype.itemsize // 4
    return np.ascontiguousarray(ids).view(np.uint32).reshape(ids.shape[0], width)


def _char_table(width: int) -> np.ndarray:
    """(width, 129) booleans: may character code c (128 = anything else) stand at position i?"""
    table = np.zeros((width, 129), dtype=bool)
    table[0, _ORD_A : _ORD_A + 20] = True  # face letter, never empty
    if width > 1:
        table[1, _ORD_0 : _ORD_0 + 6] = True  # level-1 digit
        table[1, 0] = True  # (or the end)
    for i in range(2, min(width, MAX_LEVEL + 1)):
        table[i, _ORD_0 : _ORD_0 + 3] = True
        table[i, 0] = True
    for i in range(MAX_LEVEL + 1, width):
        table[i, 0] = True  # longer than MAX_LEVEL + 1 characters: invalid
    return table


def valid_mask(ids: np.ndarray) -> np.ndarray:
    """Boolean mask of the well-formed ids in a ``U`` array (never raises).

    One table lookup per character (position x character code) and a check
    that the characters present form a prefix (no embedded NULs).
    """
    n = ids.shape[0]
    if n == 0:
        return np.zeros(0, dtype=bool)
    codes = _codes(ids)
    width = codes.shape[1]
    small = np.minimum(codes, 128).astype(np.uint8)
    if width <= MAX_LEVEL + 1 and small.all():
        # common case, ids of one length: a range check per position
        lo, hi = _char_bounds(width)
        return ((small >= lo) & (small <= hi)).all(axis=1)
    ok = _char_table(width)[np.arange(width), small].all(axis=1)
    if width > 1:
        nul = small == 0
        ok &= ~(nul[:, :-1] & ~nul[:, 1:]).any(axis=1)
    return ok


def all_valid(ids: np.ndarray) -> bool:
    """Whether every id in a ``U`` array is well formed (never raises).

    The common case (ids of one length, all valid) needs no per-row
    reduction: one flat check of every character against its position's range.
    """
    if ids.shape[0] == 0:
        return True
    codes = _codes(ids)
    width = codes.shape[1]
    small = np.minimum(codes, 128).astype(np.uint8)
    if width <= MAX_LEVEL + 1 and small.all():
        lo, hi = _char_bounds(width)
        return not ((small < lo) | (small > hi)).any()
    return bool(valid_mask(ids).all())


def _char_bounds(width: int) -> tuple[np.ndarray, np.ndarray]:
    """Lowest and highest character code allowed at each position (no NULs)."""
    lo = np.full(width, _ORD_0, dtype=np.uint8)
    hi = np.full(width, _ORD_0 + 2, dtype=np.uint8)
    lo[0], hi[0] = _ORD_A, _ORD_A + 19
    if width > 1:
        hi[1] = _ORD_0 + 5
    return lo, hi


def levels(ids: np.ndarray) -> np.ndarray:
    """Levels of a ``U`` array of ids, checking them; raises :class:`InvalidCellError`."""
    if not all_valid(ids):
        decode(ids)  # raises, naming the first bad id
    width = ids.dtype.itemsize // 4
    codes = _codes(ids)
    if ids.size and codes[:, -1].all():  # all full width
        return np.full(ids.shape[0], width - 1, dtype=np.intp)
    return np.count_nonzero(codes, axis=1) - 1


def decode(ids: np.ndarray) -> Decoded:
    """Parse a ``U`` array of ids; raise :class:`InvalidCellError` naming the first bad one."""
    if not all_valid(ids):
        ok = valid_mask(ids)
        i = int(np.flatnonzero(~ok)[0])
        raise InvalidCellError(
            f"{str(ids[i])!r} at index {i} is not a valid cell id: expected a face letter A-T, "
            f"a digit 0-5, then up to {MAX_LEVEL - 1} digits 0-2"
        )
    codes = _codes(ids)
    n, width = codes.shape
    level = np.count_nonzero(codes, axis=1) - 1
    face = (codes[:, 0] - _ORD_A).astype(np.intp)
    if width > 1:
        l1 = np.where(level >= 1, codes[:, 1].astype(np.intp) - _ORD_0, 0)
    else:
        l1 = np.zeros(n, dtype=np.intp)
    if width > 2:
        digits = np.where(codes[:, 2:] > 0, codes[:, 2:] - _ORD_0, 0).astype(np.uint8)
    else:
        digits = np.zeros((n, 0), dtype=np.uint8)
    return Decoded(face, level, l1, digits)
