"""String <-> 64-bit integer cell id codec: compiled C, libdggs/src/codec.c (arrays in and out).

The integer layout is in :mod:`dggs.index._kernel.bits`; a string id is a face
letter ``A``..``T``, a level-1 digit ``0``..``5``, then one digit ``0``..``2``
per further level (at most 29 characters).  Strings reach the kernels as 2-D
character codes (a zero-copy ``uint32`` view of a numpy ``U`` array, ``uint8``
for ``S``; trailing NULs mean a shorter id), as Arrow buffers (data, offsets,
validity) or NUL-joined.  Parsers write the null id 0 for an invalid entry and
return the index of the first one (or -1), so callers can raise naming it.
The containers around these kernels, and the pure-Python scalar codec, are
in :mod:`dggs.index._convert.strings`.
"""

from __future__ import annotations

from dggs._core import check_ints, fill_codes, max_level, parse_arrow, parse_codes, parse_joined, valid_ints

from .bits import MAX_LEVEL

__all__ = [
    "MAX_CHARS",
    "check_ints",
    "fill_codes",
    "max_level",
    "parse_arrow",
    "parse_codes",
    "parse_joined",
    "valid_ints",
]

#: Longest string id: a face letter and MAX_LEVEL digits.
MAX_CHARS = MAX_LEVEL + 1
