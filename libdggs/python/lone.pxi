# lone: the single-id fast path of index/_convert/apply.py as one C call. An Op's compiled entries (``one_str``,
# ``one_int``) are bound once into a ``Lone``; ``lone(d, obj, args)`` then takes the lone plain str or positive
# int64 id, picks the entry by the object's type and runs it, the core's functions called directly (no Python
# call between), and answers the entry's answer, or None for a miss (an object it does not take, or the entry's
# "", 0 or NaNs), which sends the id down the general path. An entry this file does not know is called as the
# Python function it is, with the same answer.

from cpython.long cimport PyLong_AsLongLongAndOverflow
from libc.math cimport isnan

cdef extern from "bits.h" nogil:
    int DGGS_MAX_LEVEL

cdef enum:
    LONE_NONE = 0       # no entry for this type
    LONE_CALL = 1       # a Python function: called as it is
    LONE_PARENT = 2     # parent_str / parent_of (the level, -1 for one up, is the one argument)
    LONE_CENTRE = 3     # centre_str / centre_of
    LONE_ID = 4         # parse_one (a str's int id) / int_if_valid (the int itself)
    LONE_STR = 5        # str_if_valid (the str itself) / format_one (an int's string)
    LONE_POINT = 6      # point_str / one_point: a point (two floats) and a level


def str_if_valid(str s not None):
    """``s`` itself if it is a string id, else "" (the array codec's parser, reading the str in place)."""
    return s if _codec_parse_str(s) else ""


def int_if_valid(int64_t cell):
    """``cell`` if it is a well-formed id (as an int64), else 0."""
    return cell if dggs_ok(<uint64_t>cell) else 0


cdef int _lone_code(object f, bint as_str):
    if f is None:
        return LONE_NONE
    if f is (parent_str if as_str else parent_of):
        return LONE_PARENT
    if f is (centre_str if as_str else centre_of):
        return LONE_CENTRE
    if f is (parse_one if as_str else int_if_valid):
        return LONE_ID
    if f is (str_if_valid if as_str else format_one):
        return LONE_STR
    if f is (point_str if as_str else one_point):
        return LONE_POINT
    return LONE_CALL


cdef class Lone:
    """An Op's single-id entries bound for :func:`lone`: ``one_str`` for a lone str, ``one_int`` for a lone int."""

    cdef readonly object one_str, one_int
    cdef int str_code, int_code

    def __init__(self, one_str, one_int):
        self.one_str, self.one_int = one_str, one_int
        self.str_code = _lone_code(one_str, True)
        self.int_code = _lone_code(one_int, False)


cdef inline int64_t _lone_level(tuple args) except? -2:
    if len(args) != 1:
        raise TypeError(f"expected one level argument, got {len(args)}")
    return <int64_t>args[0]


cdef object _lone_call(object f, object obj, tuple args):
    cdef Py_ssize_t n = len(args)
    r = f(obj) if n == 0 else f(obj, args[0]) if n == 1 else f(obj, *args)
    if type(r) is tuple:
        return None if r[0] != r[0] else r
    return r if r else None


def lone(Lone d not None, obj, tuple args not None):
    """The answer of ``d``'s entry for a lone plain ``str`` or positive int64 ``obj``, or None for a miss."""
    return _lone(d, obj, args)


cdef object _lone(Lone d, object obj, tuple args):
    cdef type t = type(obj)
    cdef int code, overflow = 0
    cdef long long v = 0
    cdef uint64_t c
    cdef int64_t level
    cdef double lat, lng
    if t is str:
        code = d.str_code
        if code == LONE_NONE:
            return None
        if code == LONE_CALL:
            return _lone_call(d.one_str, obj, args)
        c = _codec_parse_str(<str>obj)
        if c == 0:
            return None
        if code == LONE_PARENT:
            level = _lone_level(args)
            s = _codec_format(<uint64_t>dggs_parent_of(<int64_t>c, _codec_level(level)))
            return s if s else None
        if code == LONE_CENTRE:
            dggs_centre_of(POINTS_ISEA, <int64_t>c, &lat, &lng)
            return None if isnan(lat) else (lat, lng)
        if code == LONE_ID:
            return c
        if code == LONE_STR:
            return obj
        return _lone_call(d.one_str, obj, args)
    if t is not int:
        return None
    code = d.int_code
    if code == LONE_NONE:
        return None
    v = PyLong_AsLongLongAndOverflow(obj, &overflow)
    if overflow or v <= 0:
        return None
    if code == LONE_CALL:
        return _lone_call(d.one_int, obj, args)
    if code == LONE_PARENT:
        level = _lone_level(args)
        if level < -1:
            level = -1
        elif level > 29:
            level = 29
        c = <uint64_t>dggs_parent_of(<int64_t>v, <int>level)
        return c if c else None
    if code == LONE_CENTRE:
        dggs_centre_of(POINTS_ISEA, <int64_t>v, &lat, &lng)
        return None if isnan(lat) else (lat, lng)
    if code == LONE_ID:
        return obj if dggs_ok(<uint64_t>v) else None
    if code == LONE_STR:
        s = _codec_format(<uint64_t>v)
        return s if s else None
    return _lone_call(d.one_int, obj, args)


def lone_point(Lone d not None, lat, lng, tuple args not None):
    """The id of the cell holding a point of two plain floats, in the form of ``d``'s one entry, or None."""
    return _lone_point(d, lat, lng, args)


cdef object _lone_point(Lone d, object lat, object lng, tuple args):
    cdef uint64_t c
    cdef int code = d.str_code if d.str_code != LONE_NONE else d.int_code
    if type(lat) is not float or type(lng) is not float or code == LONE_NONE:
        return None
    if code == LONE_POINT:
        c = dggs_one_point(POINTS_ISEA, <double>lat, <double>lng, <int>_lone_level(args))
        if c == 0:
            return None
        return _codec_format(c) if d.str_code != LONE_NONE else c
    f = d.one_str if d.str_code != LONE_NONE else d.one_int
    r = f(lat, lng, *args)
    return r if r else None



def lone_apply(general, op, cells, *args):
    """``op``'s compiled entries for a lone id (:func:`lone`), else ``general(op, cells, *args)``.

    apply's fast path as one C call (index/_convert/apply.py binds ``general``, its general path): ``op.lone``
    is the op's :class:`Lone`, or None for an op without entries.
    """
    d = op.lone
    if d is not None:
        r = _lone(<Lone?>d, cells, args)
        if r is not None:
            return r
    return general(op, cells, *args)


def lone_apply_points(general, op, lat, lng, *args):
    """As :func:`lone_apply` for a point (:func:`lone_point`), else ``general(op, lat, lng, *args)``."""
    d = op.lone
    if d is not None:
        r = _lone_point(<Lone?>d, lat, lng, args)
        if r is not None:
            return r
    return general(op, lat, lng, *args)


def plain_level(general, level, name="level"):
    """``level`` itself if it is a plain int 0..28 (MAX_LEVEL), else ``general(level, name)``, which checks it."""
    cdef int overflow = 0
    cdef long long v
    if type(level) is int:
        v = PyLong_AsLongLongAndOverflow(level, &overflow)
        if not overflow and 0 <= v <= DGGS_MAX_LEVEL:
            return level
    return general(level, name)
