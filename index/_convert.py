"""Cell ids in any container, the same kind out (h3-py's thin converters around one kernel).

:func:`cells_in` takes a ``str`` or ``int`` id, or a list, tuple, numpy array
(``U``, ``S``, object, ``StringDType``, integer), pandas Series or pyarrow
(Chunked)Array of them, and gives one flat ``uint64`` array plus a
:class:`Kind`; the compiled kernel works on the array; :func:`cells_out`
(results aligned with the input) or :func:`cells_out_flat` (results that are
not) rebuild the same kind of container.  numpy and pyarrow arrays are parsed
from their buffers, Python strings in one pass over their NUL-joined text, a
lone ``str`` or ``int`` on a pure-Python fast path.

The pieces: :mod:`dggs.index._convert_kind` (:class:`Kind`, the error naming a
bad id), :mod:`dggs.index._convert_in` (:func:`cells_in`, :func:`is_valid_any`,
:func:`scalar_id`), :mod:`dggs.index._convert_out` (:func:`cells_out`,
:func:`cells_out_flat`); here the public converters :func:`str_to_int` and
:func:`int_to_str`.
"""

from __future__ import annotations

import sys
from dataclasses import replace
from typing import Any

import numpy as np

from . import _codec
from ._convert_in import cells_in  # also re-exported: storage/queries.py imports it from here
from ._convert_kind import _OBJECT, _SCALAR_INT, _SCALAR_STR, _U64, Kind, _fail
from ._convert_out import cells_out

__all__ = ["cells_in", "int_to_str", "str_to_int"]


# --------------------------------------------------------------------------
# Public converters
# --------------------------------------------------------------------------


def _as_form(kind: Kind, form: str) -> Kind:
    """The kind holding the same container in the other form (uint64 / ``U`` / object / ``string``)."""
    if kind.form == form:
        return kind
    if kind.scalar:
        return _SCALAR_INT if form == "int" else _SCALAR_STR
    dt: Any = {"numpy": _U64 if form == "int" else np.dtype("U1"), "pandas": _U64 if form == "int" else _OBJECT}.get(kind.container)
    if kind.container == "arrow":
        pa = sys.modules["pyarrow"]
        dt = pa.uint64() if form == "int" else pa.string()
    return replace(kind, form=form, dtype=dt)


def str_to_int(ids: Any) -> Any:
    """Convert string ids to 64-bit integer ids, keeping the container and shape.

    Parameters
    ----------
    ids : str, int, sequence, numpy array, pandas Series or pyarrow (Chunked)Array
        String ids (integer ids are checked and returned unchanged).

    Returns
    -------
    int, list, numpy.ndarray, pandas.Series or pyarrow (Chunked)Array
        A Python int for a scalar, lists for lists; numpy, pandas and pyarrow
        outputs are uint64.  Numeric order is the string order.

    Raises
    ------
    InvalidCellError
        Naming the first invalid id and its index.

    Examples
    --------
    >>> import dggs
    >>> hex(dggs.str_to_int("C401"))
    '0x4558000000000000'
    >>> dggs.str_to_int(["A", "A0"]) == [1 << 62, (1 << 62) | (1 << 54)]
    True
    >>> import numpy as np
    >>> dggs.str_to_int(np.array(["A", "T5"])).dtype
    dtype('uint64')
    """
    if type(ids) is str:  # the fast path
        v = _codec.parse_str(ids)
        return v if v else _fail(ids, None, "str")
    arr, kind = cells_in(ids)
    return cells_out(arr, _as_form(kind, "int"))


def int_to_str(ids: Any) -> Any:
    """Convert 64-bit integer ids to string ids, keeping the container and shape.

    Parameters
    ----------
    ids : int, str, sequence, numpy array, pandas Series or pyarrow (Chunked)Array
        Integer ids (string ids are checked and returned unchanged).  In a
        numpy array the null id 0 (the padding of :func:`dggs.grid_disk` rows)
        becomes ``""``.

    Returns
    -------
    str, list, numpy.ndarray, pandas.Series or pyarrow (Chunked)Array
        A Python str for a scalar, lists for lists, a ``U`` array for numpy,
        an object Series for pandas, a ``string`` array for pyarrow.

    Raises
    ------
    InvalidCellError
        Naming the first invalid id and its index.

    Examples
    --------
    >>> import dggs
    >>> dggs.int_to_str(0x4558000000000000)
    'C401'
    >>> import numpy as np
    >>> dggs.int_to_str(dggs.str_to_int(np.array([["A", "T5"], ["C401", "B0"]])))
    array([['A', 'T5'],
           ['C401', 'B0']], dtype='<U4')
    """
    if type(ids) is int:  # the fast path
        return _codec.format_int(ids) or _fail(ids, None, "int")
    if isinstance(ids, np.ndarray) and ids.dtype.kind in "iu" and ids.size and not ids.all():
        # the null id 0 (the padding of grid_disk rows) becomes ""
        cells_in(ids[ids != 0])  # raises naming a bad id
        codes, _ = _codec.format_u32(ids.astype(np.uint64).reshape(-1))
        return codes.view(f"<U{codes.shape[1]}").reshape(ids.shape)
    arr, kind = cells_in(ids)
    return cells_out(arr, _as_form(kind, "str"))
