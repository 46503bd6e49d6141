"""The one path every verb takes: ids in, the kernel, the same kind out; and the one single-id fast path.

A verb checks its arguments, then hands its ids to :func:`apply` with an
:class:`Op`: ``many`` runs the compiled kernel over a flat ``uint64`` array
(and raises, naming the id, for data it cannot take), ``out`` says how the
result goes back into the container that came in.  An op may also have
``one``, a compiled single-id entry of the same kernel: a lone plain ``str``
or ``int`` id then skips the containers altogether (a few hundred
nanoseconds instead of a few microseconds).  ``one_str`` and ``one_int``,
compiled :class:`Entry` points that take the lone ``str`` or ``int`` itself
and give the finished answer, skip the Python string codec as well.  ``one`` answers a miss (the
null id 0, NaN, an empty array) for anything it cannot answer, and the id
then takes the general path, which explains it.  Since every check happens
in the verb before :func:`apply` and both paths run the same kernel, a
scalar and a one-element container cannot give different answers.

Examples
--------
>>> import numpy as np
>>> from dggs.index._kernel import hierarchy
>>> LEVELS = Op(many=hierarchy.levels, out=VALUE)
>>> apply(LEVELS, "C401"), apply(LEVELS, ["C401", "C4"])
(3, [3, 1])
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field, replace
from functools import partial
from typing import Any

import numpy as np

from dggs.errors import DggsValueError

from .._kernel.scalar import Lone, lone_apply, lone_apply_points
from . import strings
from .cells_in import cells_in
from .cells_out import cells_out, cells_out_flat
from .coords import coords_in
from .kind import Kind, as_form
from .values import values_out

__all__ = [
    "CELL", "FLAT", "ROWS", "VALUE", "VALUES", "Entry", "Op", "apply", "apply_pair", "apply_points", "lone_id", "pair", "pair_kind",
]

#: One id per input id (a parent): the input's container, of ids.
CELL = "cell"
#: A row of ids per input id (neighbours, a disk), padded with the null id; one id gives a list.
ROWS = "rows"
#: Ids not aligned with the input (children, a compacted set): a flat container of the input's kind.
FLAT = "flat"
#: Values per input id (a level, an area, a centre): the input's container, of values; a tuple of arrays
#: gives a tuple of containers.
VALUE = "value"
#: A row of values per input id (a cell's vertex ids): as VALUE, but one id gives a list.
VALUES = "values"

_INT64_END = 1 << 63
_PLAIN_NUMBERS = (float, int)


class Entry:
    """A compiled single-id entry point of the core (:mod:`dggs._core`), called as it is.

    The binding's functions take the lone ``str``, ``int`` or float point themselves (no type dispatch, no
    array), so ``entry.call`` is the function itself; the class names the role in an :class:`Op`, which binds
    its entries once into a compiled :class:`~dggs.index._kernel.scalar.Lone` (the core's own entries are then
    run by :func:`~dggs.index._kernel.scalar.lone` without a Python call between).

    Parameters
    ----------
    kernel : callable
        The compiled function.

    Examples
    --------
    >>> from dggs.index._kernel import scalar
    >>> Entry(scalar.parent_str).call("C401", -1)
    'C40'
    """

    __slots__ = ("call",)

    def __init__(self, kernel: Callable[..., Any]) -> None:
        self.call: Callable[..., Any] = kernel


@dataclass(frozen=True)
class Op:
    """A verb's kernel: ``many`` over an array of ids, optionally ``one`` for a lone id, and how it goes out.

    ``form`` gives ids out in that form (``"str"`` or ``"int"``) instead of the
    input's, as the id converters do; ``nulls`` accepts the null id 0 in a numpy
    array of integer ids (the padding of disk rows).  A ``one`` of a
    :data:`VALUE` op answers None (or NaN) for a miss.  ``one_str`` / ``one_int``
    (ops whose ``out`` is :data:`CELL` or :data:`VALUE`) take a lone ``str`` /
    positive int64 id, or for :func:`apply_points` a point of floats giving that
    form of id, and answer the final value, or a miss ("", 0, NaNs).
    """

    many: Callable[..., Any]
    out: str = CELL
    one: Callable[..., Any] | None = None
    form: str | None = None
    nulls: bool = False
    one_str: Entry | None = None
    one_int: Entry | None = None
    #: The entries bound for the compiled lone-id dispatch (None without entries).
    lone: Lone | None = field(init=False, default=None, repr=False, compare=False)

    def __post_init__(self) -> None:
        if self.one_str is not None or self.one_int is not None:
            lone = Lone(None if self.one_str is None else self.one_str.call,
                        None if self.one_int is None else self.one_int.call)
            object.__setattr__(self, "lone", lone)


def lone_id(obj: Any) -> int:
    """The id of a plain ``str`` that is a valid id, or a plain positive int64 (not yet validated), else 0.

    The single-id fast path: a few hundred nanoseconds, no numpy.  An op's
    ``one`` validates an int itself (a miss sends it down the general path).
    """
    t = type(obj)
    if t is str:
        return strings.parse_str(obj)
    if t is int and 0 < obj < _INT64_END:
        return int(obj)
    return 0


def _missed(r: Any) -> bool:
    if isinstance(r, tuple):
        return bool(r[0] != r[0])  # NaN
    if isinstance(r, np.ndarray):
        return r.size == 0
    return not r


def _lone_out(r: Any, out: str, as_str: bool) -> Any:
    if out == CELL:
        return strings.format_int(int(r)) if as_str else int(r)
    if out in (ROWS, FLAT):
        return [strings.format_int(c) for c in r.tolist()] if as_str else r.tolist()
    return r


def _out(res: Any, kind: Kind, out: str) -> Any:
    if out == CELL:
        return cells_out(res, kind)
    if out == ROWS:
        return cells_out(res, kind, res.shape[1:])
    if out == FLAT:
        return cells_out_flat(res, kind)
    if isinstance(res, tuple):
        return tuple(values_out(r, kind, r.shape[1:]) for r in res)
    return values_out(res, kind, res.shape[1:], rows=out == VALUES)


def _apply(op: Op, cells: Any, *args: Any) -> Any:
    """:func:`apply` past the compiled entries, which missed or are none: ``op.one``, then the containers."""
    one = op.one
    if one is not None:  # the single-id fast path, written out (each extra Python call costs 60-100 ns here)
        t = type(cells)
        v = strings.parse_str(cells) if t is str else cells if t is int and 0 < cells < _INT64_END else 0
        if v:
            r: Any = one(v, *args)
            out = op.out
            as_str = t is str if op.form is None else op.form == "str"
            if out is CELL:
                if r:
                    return strings.format_int(r) if as_str else int(r)
            elif out is ROWS or out is FLAT:
                if r.size:
                    return [strings.format_int(c) for c in r.tolist()] if as_str else r.tolist()
            elif r is not None and (r[0] == r[0] if type(r) is tuple else r == r):
                return r  # a value (a number, a pair of floats); None or NaN is a miss (a tuple equals itself)
    ids, kind = cells_in(cells, nulls=op.nulls)
    return _out(op.many(ids, *args), as_form(kind, op.form) if op.form else kind, op.out)


#: Run ``op`` over ids in any container, giving back the same kind (the compiled entries first, as one C call,
#: then :func:`_apply`).
apply: Callable[..., Any] = partial(lone_apply, _apply)
apply.__doc__ = """Run ``op`` over ids in any container, giving back the same kind.

    Parameters
    ----------
    op : Op
        The kernel and how its result goes out.
    cells : str, int, sequence, numpy array, pandas Series or pyarrow (Chunked)Array
        Ids of either form.
    *args
        Checked arguments for the kernel, after the ids.

    Returns
    -------
    object
        As ``op.out`` says, in the container that came in.

    Raises
    ------
    InvalidCellError
        An id is malformed (the message names it and its index).
    """


def pair_kind(ka: Kind, kb: Kind, shape: tuple[int, ...]) -> Kind:
    """The kind of an answer about pairs: a scalar for two scalars, else the first container of the result's shape.

    Where broadcasting made a shape neither had, a list stays a list and
    anything else becomes a numpy array.
    """
    if ka.scalar and kb.scalar:
        return ka
    for k in (ka, kb):
        if not k.scalar and k.shape == shape:
            return k
    first = kb if ka.scalar else ka
    if first.container in ("list", "tuple"):
        return replace(first, shape=shape)
    return Kind("numpy", first.form, shape)


def pair(a: Any, b: Any) -> tuple[np.ndarray, np.ndarray, Kind]:
    """Ids of two containers broadcast against each other (numpy's rules), and the answer's kind.

    Raises
    ------
    InvalidCellError
        A malformed id in either.
    DggsValueError
        The shapes do not broadcast (the message names both sizes and shapes).
    """
    ia, ka = cells_in(a)
    ib, kb = cells_in(b)
    sa, sb = ka.shape, kb.shape
    if sa == sb:
        return ia, ib, pair_kind(ka, kb, sa)
    try:
        shape = np.broadcast_shapes(sa, sb)
    except ValueError:
        raise DggsValueError(f"cannot pair {ia.shape[0]} cells (shape {sa}) with {ib.shape[0]} cells (shape {sb})") from None
    ia = np.ascontiguousarray(np.broadcast_to(ia.reshape(sa), shape)).reshape(-1)
    ib = np.ascontiguousarray(np.broadcast_to(ib.reshape(sb), shape)).reshape(-1)
    return ia, ib, pair_kind(ka, kb, shape)


def apply_pair(op: Op, a: Any, b: Any, *args: Any) -> Any:
    """Run ``op`` over pairs of ids (element-wise, shapes broadcast), giving back the first container's kind.

    ``op.one`` (if any) takes two plain ids; ``op.many`` two aligned arrays.

    Raises
    ------
    InvalidCellError
        A malformed id in either.
    DggsValueError
        The shapes do not broadcast.
    """
    if op.one is not None:
        va, vb = lone_id(a), lone_id(b)
        if va and vb:
            r = op.one(va, vb, *args)
            if not _missed(r):
                return _lone_out(r, op.out, type(a) is str)
    ia, ib, kind = pair(a, b)
    return _out(op.many(ia, ib, *args), kind, op.out)


def _apply_points(op: Op, lat: Any, lng: Any, *args: Any) -> Any:
    """:func:`apply_points` past the compiled entry, which missed or is none: ``op.one``, then the containers."""
    one = op.one
    if one is not None and type(lat) in _PLAIN_NUMBERS and type(lng) in _PLAIN_NUMBERS:
        try:
            r = one(float(lat), float(lng), *args)  # an id (0: a point the general path explains)
        except OverflowError:  # an int too large for a float: the general path names it
            r = 0
        if r:
            return int(r) if op.form == "int" else strings.format_int(r)
    lat_f, lng_f, kind = coords_in(lat, lng)
    return _out(op.many(lat_f, lng_f, *args), as_form(kind, op.form or "str"), op.out)


#: Run ``op`` over points (the compiled entry first, as one C call, then :func:`_apply_points`).
apply_points: Callable[..., Any] = partial(lone_apply_points, _apply_points)
apply_points.__doc__ = """Run ``op`` over points, giving back ids (or values) in the container the coordinates came in.

    ``op.one_str`` or ``op.one_int`` (if any) takes a point of two Python floats and gives the
    id in that form; ``op.one`` (if any) takes one (lat, lng) pair of Python floats and gives an
    id (``op.out`` is :data:`CELL`); ``op.many`` takes two flat float64 arrays.

    Raises
    ------
    CoordinateError
        Coordinates that are not numbers, or shapes that do not broadcast
        (``op.many`` names points off the globe).
    """
