"""The file formats cells are exported to, and the extensions that name them (no heavy imports).

Shared by :mod:`dggs.arrow` (the writers) and :mod:`dggs.storage` (``CellStore.export``,
``dggs export``), which imports it when it exports (importing it loads :mod:`dggs.arrow`, and a store opened
only to query should not).
"""

from __future__ import annotations

import os
from typing import Any

from dggs.errors import DggsValueError

__all__ = ["EXPORT_FORMATS", "EXTENSIONS", "export_format"]

#: The formats cells are written to.
EXPORT_FORMATS = ("geojson", "geoparquet", "gpkg", "fgb")
#: File extensions and the format each names.
EXTENSIONS = {".geojson": "geojson", ".json": "geojson", ".parquet": "geoparquet", ".geoparquet": "geoparquet",
              ".gpkg": "gpkg", ".fgb": "fgb"}


def export_format(path: Any, format: str | None = None) -> str:
    """The format named (checked), or the one the extension of ``path`` implies.

    Raises
    ------
    DggsValueError
        If ``format`` is not one of the export formats, or it is None and the extension of
        ``path`` implies none.

    Examples
    --------
    >>> export_format("cells.parquet"), export_format("cells.out", "gpkg")
    ('geoparquet', 'gpkg')
    """
    if format is not None:
        if format not in EXPORT_FORMATS:
            raise DggsValueError(f"format {format!r} is not one of {', '.join(EXPORT_FORMATS)}")
        return format
    suffix = os.path.splitext(os.fspath(path))[1].lower()
    if suffix not in EXTENSIONS:
        raise DggsValueError(
            f"cannot tell the format of {os.fspath(path)!r} from its extension {suffix or '(none)'!r}: "
            f"give a format ({', '.join(EXPORT_FORMATS)}) or use one of {', '.join(EXTENSIONS)}"
        )
    return EXTENSIONS[suffix]
