"""Export cells with their statistics as GeoJSON, and draw them on a world map.

Writes ``quakes.db``, ``quakes-cells.geojson`` and, if matplotlib is installed
(``pip install 'dggs[plot]'``), ``quakes-map.png``.
"""

import json

import numpy as np

from dggs.storage import CellStore

# Made-up earthquakes along a few arcs.
rng = np.random.default_rng(11)
arcs = [((-60, -70), (10, -80)), ((35, 140), (60, 160)), ((-40, 175), (-10, 165)), ((30, 60), (40, 100))]
lat, lng = [], []
for (lat0, lng0), (lat1, lng1) in arcs:
    t = rng.uniform(0, 1, 3_000)
    lat.append(lat0 + t * (lat1 - lat0) + rng.normal(0, 1.5, t.size))
    lng.append(lng0 + t * (lng1 - lng0) + rng.normal(0, 1.5, t.size))
lat, lng = np.concatenate(lat), (np.concatenate(lng) + 180) % 360 - 180
magnitude = np.round(np.minimum(rng.exponential(0.8, lat.size) + 3, 9.5), 1)

with CellStore("quakes.db") as store:
    store.ingest_points(lat, lng, level=8, values={"magnitude": magnitude}, source="quakes")

    collection = store.to_geojson(4, "magnitude", "quakes-cells.geojson")
    print(f"wrote quakes-cells.geojson: {len(collection['features'])} cells")
    print(json.dumps(collection["features"][0]["properties"]))

    try:
        from dggs.storage.plot import plot_cells

        rows = store.aggregate(4, "magnitude", ("count", "max"))
        plot_cells([r["cell"] for r in rows], [r["max"] for r in rows], "quakes-map.png",
                   title="Largest magnitude per level-4 cell", label="magnitude")
        print("wrote quakes-map.png")
    except ImportError:
        print("no matplotlib: skipped the map")
