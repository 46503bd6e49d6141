"""The :class:`Kind` of a container (of ids or coordinates), and the error that names a bad id.

Shared by the input side (:mod:`.cells_in`, :mod:`.coords`) and the output
side (:mod:`.cells_out`, :mod:`.values`) of the converters.
"""

from __future__ import annotations

import math
import sys
from dataclasses import dataclass, field, replace
from typing import Any, NoReturn

import numpy as np

from dggs.errors import InvalidCellError

from .._kernel.bits import MAX_LEVEL
from . import strings

__all__ = ["Kind", "as_form", "fail", "id_name"]

_STR_REASON = f"expected a face letter A-T, a digit 0-5, then up to {MAX_LEVEL - 1} digits 0-2"
_INT_REASON = "not a well-formed 64-bit id (the integer form of a string id, see dggs.str_to_int)"
_TYPE_REASON = "expected a string id such as 'C401' or its 64-bit integer form"
_MISSING_REASON = "a missing value is not a cell id"
_NESTED_REASON = "a sequence here, but nested sequences must all have the same length"
_MIX_REASON = "a container must hold only string ids or only integer ids"
OBJECT, U64, I64 = np.dtype(object), np.dtype(np.uint64), np.dtype(np.int64)
_NESTED = (list, tuple, set, frozenset, np.ndarray)


@dataclass(frozen=True)
class Kind:
    """What came into :func:`cells_in`, and what :func:`cells_out` rebuilds.

    ``container`` is ``'scalar'``, ``'list'``, ``'tuple'``, ``'numpy'``,
    ``'pandas'`` (a Series), ``'pandas-index'``, ``'arrow'`` or ``'polars'`` (a Series: read and
    answered as Arrow, :mod:`.frames`); ``form`` is ``'str'`` or ``'int'``;
    ``shape`` is the input's shape (``()`` for a scalar); ``dtype`` the numpy
    dtype, pandas dtype or pyarrow type; ``index`` and ``name`` a pandas
    Series' own; ``chunked`` whether a pyarrow ChunkedArray came in.
    """

    container: str
    form: str
    shape: tuple[int, ...]
    scalar: bool = False
    dtype: Any = None
    index: Any = field(default=None, compare=False, repr=False)
    name: Any = None
    chunked: bool = False


SCALAR_STR = Kind("scalar", "str", (), True)
SCALAR_INT = Kind("scalar", "int", (), True)


def value_id(x: Any) -> tuple[int, str | None]:
    """(id or 0, form) of a value of any type; form None for a wrong type."""
    if isinstance(x, str):
        return strings.parse_str(x), "str"
    if isinstance(x, (bytes, bytearray, np.bytes_)):
        try:
            return strings.parse_str(x.decode("ascii")), "str"
        except UnicodeDecodeError:
            return 0, "str"
    if isinstance(x, (bool, np.bool_)) or not isinstance(x, (int, np.integer)):
        return 0, None
    x = int(x)
    return (x if strings.valid_int(x) else 0), "int"


def fail(value: Any, index: int | None, form: str | None, shape: tuple[int, ...] = ()) -> NoReturn:
    """Raise InvalidCellError naming ``value`` (at ``index``), with the reason it is not an id.

    Raises
    ------
    InvalidCellError
        Always: naming ``value``, where it was and why it is no id.
    """
    value = value.item() if isinstance(value, np.generic) else value
    f = value_id(value)[1]
    if f is None:
        missing = value is None or value is np.ma.masked or (isinstance(value, float) and math.isnan(value)) or type(value).__name__ == "NAType"
        reason = _MISSING_REASON if missing else _NESTED_REASON if isinstance(value, _NESTED) else _TYPE_REASON
    else:
        reason = _MIX_REASON if form and f != form else _STR_REASON if f == "str" else _INT_REASON
    where = ""
    if index is not None:
        at = index if len(shape) <= 1 else tuple(int(i) for i in np.unravel_index(index, shape))
        where = f" at index {at}"
    raise InvalidCellError(f"{value!r}{where} is not a valid cell id: {reason}")


def as_form(kind: Kind, form: str) -> Kind:
    """The kind holding the same container in the other form (uint64 / ``U`` / object / ``string``)."""
    if kind.form == form:
        return kind
    if kind.scalar:
        return SCALAR_INT if form == "int" else SCALAR_STR
    pandas_dt = U64 if form == "int" else OBJECT
    dt: Any = {"numpy": U64 if form == "int" else np.dtype("U1"), "pandas": pandas_dt, "pandas-index": pandas_dt}.get(
        kind.container
    )
    if kind.container in ("arrow", "polars"):
        pa = sys.modules["pyarrow"]
        dt = pa.uint64() if form == "int" else pa.string()
    return replace(kind, form=form, dtype=dt)


def id_name(cell: Any) -> str:
    """A cell id for an error message: its string form, or the number if it is no id."""
    return strings.format_int(int(cell)) or str(int(cell))
