"""polars Series through the converters: read as Arrow, answered as Arrow, handed back as a polars Series.

polars is never imported here: a value is a polars Series only if polars is
already in ``sys.modules`` (whoever made the Series imported it), so a user
without polars pays nothing.  The Series goes in through ``Series.to_arrow``
(polars' own Arrow export, no copy for numbers) and the answer, built by the
pyarrow path of :mod:`.cells_out` or :mod:`.values`, comes back through
``polars.Series(name, array)``, keeping the input's name.

Examples
--------
>>> import polars as pl
>>> import dggs
>>> dggs.cell_to_parent(pl.Series("cell", ["C401", "B100"])).to_list()
['C40', 'B10']
"""

from __future__ import annotations

import sys
from typing import Any

__all__ = ["is_polars_series", "polars_out", "series_to_arrow"]


def is_polars_series(obj: Any) -> bool:
    """Whether ``obj`` is a polars Series (without importing polars)."""
    pl = sys.modules.get("polars")
    return pl is not None and isinstance(obj, pl.Series)


def series_to_arrow(s: Any) -> Any:
    """A polars Series as a pyarrow Array (one chunk; strings as ``large_string``, categoricals as dictionaries)."""
    import pyarrow as pa

    arr = s.to_arrow()
    return arr.combine_chunks() if isinstance(arr, pa.ChunkedArray) else arr


def polars_out(arr: Any, name: Any) -> Any:
    """A pyarrow answer as a polars Series named ``name`` (lists stay lists, fixed-size lists become ``Array``)."""
    return sys.modules["polars"].Series("" if name is None else str(name), arr)
