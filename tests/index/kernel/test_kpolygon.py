"""The compiled circle-against-polygon test of polygon fill, against shapely (GEOS) on random polygons.

``hit``: the circle meets the polygon (GEOS ``dwithin`` of the point and the
polygon); ``inside``: it lies wholly inside (the point inside and farther than
``r`` from the boundary).  Circles within 1e-9 of a tie are left out: there the
two may round differently, and polygon fill's radii carry a 1.5x margin.
"""

from __future__ import annotations

import numpy as np
import shapely
from hypothesis import given, settings
from hypothesis import strategies as st

from dggs.index.polyfill import _edge_index, _near


@st.composite
def polygons(draw):
    """Star-shaped polygons round random centres, some with a hole, some in two parts."""
    rng = np.random.default_rng(draw(st.integers(0, 2**32 - 1)))
    parts = []
    for _ in range(draw(st.integers(1, 2))):
        n = int(rng.integers(3, 400))
        cx, cy = rng.uniform(-150, 150), rng.uniform(-60, 60)
        t = np.sort(rng.uniform(0, 2 * np.pi, n))
        rad = rng.uniform(2, 10, n)
        shell = np.c_[cx + rad * np.cos(t), cy + rad * np.sin(t)]
        hole = None
        if rng.random() < 0.5:
            k = np.linspace(0, 2 * np.pi, 9)[:-1]
            hole = [np.c_[cx + 0.8 * np.cos(k), cy + 0.8 * np.sin(k)]]
        parts.append(shapely.make_valid(shapely.Polygon(shell, hole)))  # a star of 400 points can self-touch
    return shapely.make_valid(shapely.union_all(parts))


@settings(deadline=None, max_examples=60)
@given(polygons(), st.integers(0, 2**32 - 1))
def test_hits_and_insides_equal_geos(poly, seed):
    rng = np.random.default_rng(seed)
    minx, miny, maxx, maxy = poly.bounds
    n = 2000
    x = rng.uniform(minx - 3, maxx + 3, n)
    y = rng.uniform(miny - 3, maxy + 3, n)
    r = np.where(rng.random(n) < 0.2, 0.0, 10.0 ** rng.uniform(-3, 0.5, n))
    hit, inside = _near(poly, x, y, r, {}, "flat")
    points = shapely.points(x, y)
    gap = shapely.distance(poly.boundary, points)
    centre_in = shapely.contains_xy(poly, x, y)
    clear = np.abs(gap - r) > 1e-9
    assert (hit == (centre_in | (gap <= r)))[clear].all()
    assert (inside == (centre_in & (gap > r)))[clear].all()
    assert clear.mean() > 0.99


def test_a_polygon_with_no_edges_has_no_index():
    assert _edge_index(shapely.Polygon()) is None
    hit, inside = _near(shapely.Polygon(), np.zeros(3), np.zeros(3), np.ones(3), {}, "flat")
    assert not hit.any() and not inside.any()
