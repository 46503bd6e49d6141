"""Cell ids: the string form, the 64-bit integer form, and the converters between them.

String ids: a face letter ``A``..``T`` (level 0, PROJ's faces 0..19), a digit
``0``..``5`` for the level-1 triangle, then one digit ``0``..``2`` per further
level; ``"C401"`` is a level-3 cell on face 2.  ``level = len(id) - 1``, the
parent is a prefix, sorting orders cells depth-first.

Integer ids (:mod:`dggs.index._kernel.bits`, docs/grid.md): 64 bits with the
same order, the descendants of a cell one integer range, and level, parent
and children bit operations.  Every id is a positive int64, so it fits
SQLite, Parquet, Arrow and DuckDB integer columns as it is.
:func:`str_to_int` and :func:`int_to_str` convert, losslessly, any container.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ._checks import check_level
from ._convert import CELL, Entry, Op, apply
from ._kernel import scalar as ks
from ._kernel.bits import MAX_LEVEL

__all__ = ["MAX_LEVEL", "FACE_LETTERS", "check_level", "int_to_str", "str_to_int"]

#: The level-0 cells' letters, in face order.
FACE_LETTERS = "ABCDEFGHIJKLMNOPQRST"


def _same(ids: np.ndarray) -> np.ndarray:
    return ids


# a lone id goes through the core's codec (a valid id is its answer unchanged, or its other form); a miss takes
# the general path, which raises naming it
_TO_INT = Op(many=_same, out=CELL, form="int", one_str=Entry(ks.parse_one), one_int=Entry(ks.int_if_valid))
_TO_STR = Op(many=_same, out=CELL, form="str", nulls=True, one_str=Entry(ks.str_if_valid),
             one_int=Entry(ks.format_one))


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
    return apply(_TO_INT, ids)


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
    return apply(_TO_STR, ids)
