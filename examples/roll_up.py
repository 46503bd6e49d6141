"""Roll binned points up the hierarchy: the same points, coarser and coarser cells.

Cell ids are prefixes of their descendants, so a roll-up to level L is a
GROUP BY on the first L + 1 characters, done in SQL.  Every level's counts
add up to the same total, and each cell's count is the sum of its children's.
"""

import numpy as np

import dggs
from dggs.storage import CellStore

rng = np.random.default_rng(7)
n = 20_000
lat = np.degrees(np.arcsin(rng.uniform(-1, 1, n)))  # uniform on the sphere
lng = rng.uniform(-180, 180, n)
rain = rng.gamma(2.0, 10.0, n)

with CellStore("rollup.db") as store:
    store.ingest_points(lat, lng, level=8, values={"rain_mm": rain}, source="rain gauges")
    print(f"{store.count():,} points stored at level {store.level}")
    print("level  cells  km^2/cell  mean points/cell  total")
    for level in range(0, 6):
        rows = store.aggregate(level, "rain_mm", ("count", "sum"))
        total = sum(r["count"] for r in rows)
        area = dggs.cell_area(level, unit="km^2")
        print(f"{level:5d}  {len(rows):5d}  {area:9,.0f}  {total / len(rows):16.1f}  {total}")

    # A parent's count is the sum of its children's counts.
    parent = store.aggregate(1, stats=("count",), order_by="count", limit=1)[0]
    children = store.aggregate(2, stats=("count",), cell=parent["cell"])
    print(f"{parent['cell']}: {parent['count']} = " + " + ".join(str(c["count"]) for c in children))
    assert parent["count"] == sum(c["count"] for c in children)
