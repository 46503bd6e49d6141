# codec: string <-> id parsers and formatters (libdggs/src/codec.c), and the single-id string entries of
# index/_kernel/scalar.py, which take the Python str itself (read in place, no numpy array for one id).

from libc.stdint cimport int32_t, uint16_t
from cpython.unicode cimport (PyUnicode_1BYTE_KIND, PyUnicode_2BYTE_KIND, PyUnicode_DATA, PyUnicode_GET_LENGTH,
                              PyUnicode_KIND)

import numpy as np

cdef extern from "Python.h":
    object PyUnicode_FromKindAndData(int kind, const void *buffer, Py_ssize_t size)

cdef extern from "codec.h" nogil:
    bint dggs_ok(uint64_t cell)
    uint64_t dggs_parse_span_u8(const uint8_t *buf, int64_t start, int64_t end)
    uint64_t dggs_parse_span_u16(const uint16_t *buf, int64_t start, int64_t end)
    uint64_t dggs_parse_span_u32(const uint32_t *buf, int64_t start, int64_t end)
    uint64_t dggs_parse_span_i64(const int64_t *buf, int64_t start, int64_t end)
    int64_t dggs_parse_codes_u8(const uint8_t *codes, int64_t n, int64_t width, uint64_t *out)
    int64_t dggs_parse_codes_u32(const uint32_t *codes, int64_t n, int64_t width, uint64_t *out)
    int64_t dggs_parse_codes_i64(const int64_t *codes, int64_t n, int64_t width, uint64_t *out)
    int64_t dggs_parse_arrow32(const uint8_t *data, int64_t data_len, const int32_t *offsets,
                               const uint8_t *validity, int64_t validity_len, int64_t offset, int64_t n,
                               uint64_t *out)
    int64_t dggs_parse_arrow64(const uint8_t *data, int64_t data_len, const int64_t *offsets,
                               const uint8_t *validity, int64_t validity_len, int64_t offset, int64_t n,
                               uint64_t *out)
    int64_t dggs_parse_joined_u8(const uint8_t *data, int64_t m, int64_t n, uint64_t *out, int64_t *pieces)
    int64_t dggs_parse_joined_u32(const uint32_t *data, int64_t m, int64_t n, uint64_t *out, int64_t *pieces)
    int64_t dggs_parse_joined_i64(const int64_t *data, int64_t m, int64_t n, uint64_t *out, int64_t *pieces)
    int64_t dggs_check_ints(const uint64_t *ids, int64_t n)
    void dggs_valid_ints(const uint64_t *ids, int64_t n, uint8_t *out)
    int dggs_max_level(const uint64_t *ids, int64_t n, int64_t *bad)
    void dggs_fill_codes_u8(const uint64_t *ids, int64_t n, uint8_t *out, int64_t width)
    void dggs_fill_codes_u32(const uint64_t *ids, int64_t n, uint32_t *out, int64_t width)
    int dggs_format_one(uint64_t cell, char *buf)

cdef extern from "hierarchy.h" nogil:
    int64_t dggs_parent_of(int64_t cell, int level)


cdef inline int _codec_level(int64_t level) noexcept nogil:
    """A parent level for dggs_parent_of, with the same answers for every int64: negative is one level up, and
    past the deepest level (29 or more) no cell has a parent there."""
    return -1 if level < 0 else (<int>level if level <= 29 else 29)


cdef object _codec_codes(codes, int ndim):
    """``codes`` (any integer dtype) as a C-contiguous uint8, uint16, uint32 or int64 array (values kept)."""
    a = np.ascontiguousarray(codes)
    if a.ndim != ndim:
        raise ValueError(f"expected a {ndim}-d array of character codes, got {a.ndim}-d")
    if a.dtype.kind not in "iu":
        raise TypeError(f"character codes must be integers, not {a.dtype}")
    if a.dtype == np.uint8 or a.dtype == np.uint32:
        return a
    return a.astype(np.int64)  # any other integer codes, each read as an int64 (uint64 wraps, as np.int64 does)


def parse_codes(codes):
    """Parse a 2-D array of character codes (one id per row, NUL padded).

    Returns ``(ids, first_bad)``: a uint64 array with 0 for every invalid
    row, and the index of the first invalid row or -1.  An empty row is
    invalid; so is a NUL followed by another character.
    """
    a = _codec_codes(codes, 2)
    cdef int64_t n = a.shape[0], width = a.shape[1], bad
    out = np.empty(n, dtype=np.uint64)
    cdef uint64_t[::1] o = out
    cdef const uint8_t[:, ::1] c8
    cdef const uint32_t[:, ::1] c32
    cdef const int64_t[:, ::1] c64
    if n == 0:
        return out, -1
    if width == 0:  # only empty rows
        out[:] = 0
        return out, 0
    if a.dtype == np.uint8:
        c8 = a
        with nogil:
            bad = dggs_parse_codes_u8(&c8[0, 0], n, width, &o[0])
    elif a.dtype == np.uint32:
        c32 = a
        with nogil:
            bad = dggs_parse_codes_u32(&c32[0, 0], n, width, &o[0])
    else:
        c64 = a
        with nogil:
            bad = dggs_parse_codes_i64(&c64[0, 0], n, width, &o[0])
    return out, bad


def parse_arrow(data, offsets, validity, int64_t offset, int64_t n):
    """Parse ``n`` Arrow strings starting at element ``offset``.

    ``data`` is the uint8 character buffer, ``offsets`` the int32 or int64
    offsets buffer and ``validity`` the validity bitmap (an empty array when
    there are no nulls).  Nulls are invalid.  Returns ``(ids, first_bad)``.
    """
    cdef const uint8_t[::1] d = np.ascontiguousarray(data, dtype=np.uint8)
    cdef const uint8_t[::1] v = np.ascontiguousarray(validity, dtype=np.uint8)
    off = np.ascontiguousarray(offsets)
    cdef const int32_t[::1] o32
    cdef const int64_t[::1] o64
    cdef int64_t bad = -1
    if n < 0:
        raise ValueError(f"negative count {n}")
    out = np.empty(n, dtype=np.uint64)
    cdef uint64_t[::1] o = out
    if n == 0:
        return out, -1
    if offset < 0 or off.shape[0] < offset + n + 1:
        raise ValueError(f"{off.shape[0]} offsets do not cover elements {offset}..{offset + n}")
    cdef const uint8_t *dp = &d[0] if d.shape[0] else NULL
    cdef const uint8_t *vp = &v[0] if v.shape[0] else NULL
    if off.dtype == np.int32:
        o32 = off
        with nogil:
            bad = dggs_parse_arrow32(dp, d.shape[0], &o32[0], vp, v.shape[0], offset, n, &o[0])
    else:
        o64 = off.astype(np.int64, copy=False)
        with nogil:
            bad = dggs_parse_arrow64(dp, d.shape[0], &o64[0], vp, v.shape[0], offset, n, &o[0])
    return out, bad


def parse_joined(data, int64_t n):
    r"""Parse ``n`` ids joined by NUL codes (``"\x00".join(strings)``, as codes of any integer dtype).

    Returns ``(ids, first_bad, pieces)``; ``pieces != n`` means an element held a NUL itself
    (the ids are then meaningless).
    """
    a = _codec_codes(data, 1)
    if n < 0:
        raise ValueError(f"negative count {n}")
    out = np.empty(n, dtype=np.uint64)
    cdef uint64_t[::1] o = out
    cdef const uint8_t[::1] c8
    cdef const uint32_t[::1] c32
    cdef const int64_t[::1] c64
    cdef int64_t m = a.shape[0], bad, pieces
    cdef uint64_t *op = &o[0] if n else NULL
    if a.dtype == np.uint8:
        c8 = a
        with nogil:
            bad = dggs_parse_joined_u8(&c8[0] if m else NULL, m, n, op, &pieces)
    elif a.dtype == np.uint32:
        c32 = a
        with nogil:
            bad = dggs_parse_joined_u32(&c32[0] if m else NULL, m, n, op, &pieces)
    else:
        c64 = a
        with nogil:
            bad = dggs_parse_joined_i64(&c64[0] if m else NULL, m, n, op, &pieces)
    return out, bad, pieces


def check_ints(ids):
    """Index of the first id of a uint64 array that is not well formed, or -1."""
    cdef const uint64_t[::1] v = np.ascontiguousarray(ids)
    cdef int64_t bad
    if v.shape[0] == 0:
        return -1
    with nogil:
        bad = dggs_check_ints(&v[0], v.shape[0])
    return bad


def valid_ints(ids):
    """Boolean mask of the well-formed ids of a uint64 array."""
    cdef const uint64_t[::1] v = np.ascontiguousarray(ids)
    out = np.empty(v.shape[0], dtype=np.bool_)
    cdef uint8_t[::1] o = out.view(np.uint8)
    if v.shape[0]:
        with nogil:
            dggs_valid_ints(&v[0], v.shape[0], &o[0])
    return out


def max_level(ids):
    """``(deepest level, first bad index)`` of a uint64 array; the null id 0 is allowed.

    The deepest level is -1 when there is no id but nulls.
    """
    cdef const uint64_t[::1] v = np.ascontiguousarray(ids)
    cdef int64_t bad = -1
    cdef int level = -1
    if v.shape[0]:
        with nogil:
            level = dggs_max_level(&v[0], v.shape[0], &bad)
    return level, bad


def fill_codes(ids, out):
    """Characters of valid-or-null ids into the rows of ``out``: an empty field gives a NUL."""
    cdef const uint64_t[::1] v = np.ascontiguousarray(ids)
    cdef uint8_t[:, ::1] o8
    cdef uint32_t[:, ::1] o32
    cdef int64_t n = v.shape[0]
    if out.ndim != 2 or out.shape[0] < n:
        raise ValueError(f"out must be 2-d with at least {n} rows")
    if n == 0 or out.shape[1] == 0:
        return None
    if out.dtype == np.uint8:
        o8 = out
        with nogil:
            dggs_fill_codes_u8(&v[0], n, &o8[0, 0], o8.shape[1])
    else:
        o32 = out
        with nogil:
            dggs_fill_codes_u32(&v[0], n, &o32[0, 0], o32.shape[1])
    return None


# ---- the single-id string entries (index/_kernel/scalar.py) ----

cdef inline uint64_t _codec_parse_str(str s):
    """The id of a str (read in place at its own width), or 0 if it is not a string id."""
    cdef Py_ssize_t n = PyUnicode_GET_LENGTH(s)
    cdef int kind = PyUnicode_KIND(s)
    cdef void *data = PyUnicode_DATA(s)
    if kind == PyUnicode_1BYTE_KIND:
        return dggs_parse_span_u8(<const uint8_t *>data, 0, n)
    if kind == PyUnicode_2BYTE_KIND:
        return dggs_parse_span_u16(<const uint16_t *>data, 0, n)
    return dggs_parse_span_u32(<const uint32_t *>data, 0, n)


cdef inline str _codec_format(uint64_t cell):
    """The string of a well-formed id, or "" if it is not one."""
    cdef char buf[32]
    cdef int n = dggs_format_one(cell, buf)
    if n == 0:
        return ""
    return PyUnicode_FromKindAndData(PyUnicode_1BYTE_KIND, buf, n)


def parse_one(str s not None):
    """The id of a string id, or 0 if it is not one (the array codec's parser, reading the str in place)."""
    return _codec_parse_str(s)


def format_one(cell):
    """The string of a well-formed id (as an integer), or "" if it is not one."""
    cdef uint64_t c
    try:
        c = <uint64_t>(<int64_t>cell)
    except OverflowError:
        c = <uint64_t>cell  # 2**63 .. 2**64 - 1 (numba's uint64 argument); never an id
    return _codec_format(c)


def parent_str(str s not None, int64_t level):
    """The ancestor of string id ``s`` at ``level`` (-1: one level up), or "" where there is none."""
    return _codec_format(<uint64_t>dggs_parent_of(<int64_t>_codec_parse_str(s), _codec_level(level)))


def point_str(double lat, double lng, int level):
    """The string id of the level-``level`` cell holding a point; "" for a point not on the globe."""
    return _codec_format(dggs_one_point(POINTS_ISEA, lat, lng, level))


def centre_str(str s not None):
    """The centre (lat, lng) of a string id; NaNs if it is not one."""
    cdef double lat, lng
    dggs_centre_of(POINTS_ISEA, <int64_t>_codec_parse_str(s), &lat, &lng)
    return lat, lng
