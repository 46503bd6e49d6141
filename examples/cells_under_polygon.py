"""Select the points inside a country outline, via the cells that cover it.

The outline is a rough, hand-made polygon of Australia (lng, lat), built with
shapely.  ``store.within(polygon, level)`` covers it with level-L cells and
reads their points with one index range scan per cell.
"""

import numpy as np
from shapely.geometry import Point, Polygon

import dggs
from dggs.storage import CellStore

australia = Polygon([
    (113.5, -22.0), (114.2, -26.3), (115.0, -34.0), (118.0, -35.0), (123.5, -33.9),
    (129.0, -31.6), (131.0, -31.5), (135.5, -34.8), (138.0, -35.6), (140.5, -38.0),
    (146.3, -39.0), (150.0, -37.5), (153.6, -28.5), (153.0, -25.0), (145.5, -14.5),
    (142.5, -10.7), (141.5, -17.0), (136.7, -12.0), (130.5, -11.3), (126.0, -14.0),
    (122.0, -17.0), (113.5, -22.0),
])

rng = np.random.default_rng(3)
lat = rng.uniform(-45, -5, 10_000)
lng = rng.uniform(105, 160, 10_000)

with CellStore("australia.db") as store:
    store.ingest_points(lat, lng, level=10, source="random points")
    level = 6
    cells = dggs.polygon_to_cells(australia, level)
    inside = store.within(australia, level)
    exact = sum(australia.contains(Point(x, y)) for x, y in zip(lng, lat, strict=True))
    print(f"{len(cells):,} level-{level} cells ({dggs.cell_area(level, unit='km^2'):,.0f} km^2 each) cover the outline")
    print(f"{len(inside):,} points in those cells; {exact:,} strictly inside the polygon")
    print(f"covered area {len(cells) * dggs.cell_area(level, unit='km^2'):,.0f} km^2 "
          "(Australia: about 7.7 million km^2)")
