"""Bin a CSV of points into equal-area cells, then query the store.

Writes ``stations.csv`` (made-up weather stations) and ``stations.db`` in the
current directory.  Run it twice: the second run finds the file already
ingested and stores nothing new.
"""

import csv
import random

import dggs
from dggs.storage import CellStore

# 1. Some input: 5,000 stations scattered around a few cities.
random.seed(1)
cities = {"London": (51.51, -0.13), "Nairobi": (-1.29, 36.82), "Lima": (-12.05, -77.04)}
with open("stations.csv", "w", newline="") as fh:
    writer = csv.writer(fh)
    writer.writerow(["station", "lat", "lng", "temp_c"])
    for i in range(5_000):
        name, (lat, lng) = random.choice(list(cities.items()))
        writer.writerow([f"{name}-{i}", lat + random.gauss(0, 1), lng + random.gauss(0, 1),
                         round(random.gauss(15, 6), 1)])

# 2. Bin them at level 9 (cells of about 1,900 km^2) and store them.
with CellStore("stations.db") as store:
    result = store.ingest_csv("stations.csv", lat="lat", lng="lng",
                              values=["station", "temp_c"], level=9)
    print(result.summary())

    # 3. Query: how many stations in the level-4 cell around London?
    london = dggs.latlng_to_cell(51.51, -0.13, 4)
    print(f"cell {london} ({dggs.cell_area(4, unit='km^2'):,.0f} km^2) holds {store.count(london)} stations")

    # 4. The stations in London's own level-9 cell, and the warmest of them.
    here = store.get(dggs.latlng_to_cell(51.51, -0.13, 9))
    warmest = max(here, key=lambda row: row["temp_c"])
    print(f"{len(here)} stations in London's level-9 cell; warmest {warmest['station']} at {warmest['temp_c']} C")

    # 5. Mean temperature per level-3 cell, busiest first.
    for row in store.aggregate(3, "temp_c", ("count", "mean"), order_by="count", limit=3):
        print(f"  {row['cell']}: {row['count']:5d} stations, mean {row['mean']:.1f} C")
