"""Summary statistics of a zone for its zone information (/rec/core/zone-info, ``statistics``).

The standard's ``zone-info`` schema gives each numeric field ``minimum``, ``maximum``, ``average`` and
``stdDev``.  The first three come from the store's roll-up; the standard deviation (of the population:
every row under the zone, NULLs left out) is computed here in a second pass over the zone's rows, the mean
subtracted before squaring so that large values keep their precision.  The rows of a zone are one index
range of the clustered ``points`` table (``cell >= zone AND cell < zone || '~'``).

Examples
--------
>>> from dggs.storage import CellStore
>>> import tempfile, os
>>> from dggs.server.reader import StoreReader
>>> path = os.path.join(tempfile.mkdtemp(), "x.db")
>>> with CellStore(path) as s:
...     _ = s.ingest_points([1.0, 1.0, 1.0], [3.0, 3.0, 3.0], 4, {"v": [1, 2, 6]})
>>> reader = StoreReader(path)
>>> zone = dggs.latlng_to_cell(1.0, 3.0, 0)
>>> stats = zone_statistics(reader, zone, 0, ["v"])
>>> stats["v"]["average"], round(stats["v"]["stdDev"], 6)
(3.0, 2.160247)
>>> reader.close()
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import dggs  # noqa: F401 - used by the doctest
from dggs.storage.schema import quote

from .geojson import clean

__all__ = ["zone_statistics"]


def zone_statistics(reader: Any, zone: str, level: int, columns: Sequence[str]) -> dict[str, dict[str, Any]]:
    """``minimum``, ``maximum``, ``average`` and ``stdDev`` of each numeric column under ``zone``.

    Columns with no value under the zone are left out.  Call inside ``reader.snapshot()`` for one state.
    """
    out: dict[str, dict[str, Any]] = {}
    for column in columns:
        found = reader.rollup(zone, level, column, ("min", "max", "mean"))
        if not found or found[0]["mean"] is None:
            continue
        r = found[0]
        mean = float(r["mean"])
        c = quote(column)
        sql = (
            f"SELECT avg(({c} - :m) * ({c} - :m)) FROM (SELECT {c} FROM points WHERE cell >= :z AND cell < :z || '~'"
            f" UNION ALL SELECT {c} FROM points_pending WHERE cell >= :z AND cell < :z || '~')"
        )
        with reader.snapshot() as (store, _marker):
            (variance,) = store.conn.execute(sql, {"m": mean, "z": zone}).fetchone()
        std = math.sqrt(variance) if variance is not None and variance > 0 else 0.0
        out[column] = {"minimum": clean(r["min"]), "maximum": clean(r["max"]), "average": clean(r["mean"]),
                       "stdDev": clean(std)}
    return out
