"""The compiled polygon fill's pieces: the footprint bound, the centres, the exact crossing parity.

- every point of a cell's boundary (densified) lies within ``RHO[level]`` of
  its footprint centre on the authalic sphere, and inside the lng/lat
  ellipse the fill derives from it (within its latitudes at a pole), at
  levels 0-28;
- the two constants of the bound hold: the inverse projection's largest scale
  factor (sampled on a face) and WGS84's largest d(lat)/d(authalic lat);
- the centres computed from carried corners are bit for bit those of
  ``dggs.cell_to_latlng``;
- the parity says 1 or 0 exactly where GEOS's ``contains_xy`` says True or
  False, and -1 (undecided) only on or beside an edge: on vertices, on edges,
  on horizontal edges;
- the rings split from a polygon's coordinates are shapely's, and the side
  recorded for each empty bucket is GEOS's at its centre.
"""

from __future__ import annotations

import math

import numpy as np
import shapely
from hypothesis import given, settings
from hypothesis import strategies as st

import dggs
from dggs.geometry import kernel as gk
from dggs.index._kernel import fill as kfill
from dggs.index._kernel import polygon as kpoly
from dggs.index.polyfill import _edge_index


def carried(cell: int):
    """Face and the corners (A, B, C) as the fill carries them down: the level-1 triangle, then child_corners."""
    c = np.uint64(cell)
    face = int((c >> np.uint64(57)) & np.uint64(31))  # the id layout of docs/grid.md
    level = dggs.get_level(cell)
    if level == 0:
        return face, tuple(kfill._FACE.ravel())
    t = tuple(kfill._L1[int((c >> np.uint64(54)) & np.uint64(7)) - 1].ravel())
    for lv in range(2, level + 1):
        t = gk.child_corners(*t, int((c >> np.uint64(2 * (28 - lv))) & np.uint64(3)) - 1)
    return face, t


def sample_cells(level: int, n: int, seed: int) -> np.ndarray:
    rng = np.random.default_rng(seed)
    lat = np.r_[np.degrees(np.arcsin(rng.uniform(-1, 1, n))), 90.0, -90.0, 89.9999, 0.0, 58.2825, -58.2825]
    lng = np.r_[rng.uniform(-180, 180, n), 0.0, 0.0, 45.0, 180.0, 11.25, -168.75]
    return np.unique(dggs.latlng_to_cell(lat, lng, level, as_int=True))


def test_every_boundary_point_lies_in_the_footprint():
    worst_arc = worst_ellipse = 0.0
    for level in [*range(0, 13), 16, 20, 24, 28]:
        cells = sample_cells(level, 400, level)
        rings = np.asarray(dggs.cell_to_boundary(cells, densify=8))  # (n, points, 2): lat, lng
        for cell, ring in zip(cells.tolist(), rings, strict=True):
            face, t = carried(cell)
            lat, lng, ux, uy, uz = kfill.footprint(face, level, *t)
            u = np.array([ux, uy, uz]) / math.sqrt(ux * ux + uy * uy + uz * uz)
            points = np.array([gk.geodetic_to_unit(p[0], p[1]) for p in ring])
            worst_arc = max(worst_arc, np.arccos(np.clip(points @ u, -1.0, 1.0)).max() / kfill.RHO[level])
            a, lam = kfill.ellipse(level, ux, uy, uz)
            if lam > 0:  # else a pole's cap, bounded by its latitudes: a is the arc's bound on them
                dlng = (ring[:, 1] - lng + 180.0) % 360.0 - 180.0
                worst_ellipse = max(worst_ellipse, (((ring[:, 0] - lat) / a) ** 2 + (dlng / lam) ** 2).max())
            else:
                assert np.abs(ring[:, 0] - lat).max() <= a
    assert 0.9 < worst_arc <= 1.0 and 0.9 < worst_ellipse <= 1.0, (worst_arc, worst_ellipse)


def test_the_constants_of_the_bound_hold():
    # the inverse projection's scale: finite differences in random directions at random points of a face
    rng = np.random.default_rng(3)
    corners = kfill._FACE
    w = rng.dirichlet(np.ones(3), 4000)
    xy = w @ corners
    angle = rng.uniform(0, np.pi, 4000)
    h = 1e-7
    largest = 0.0
    for (x, y), t in zip(xy, angle, strict=True):
        p = np.array(gk.inverse_unit(gk.ISEA_FRAMES, 0, x, y))
        q = np.array(gk.inverse_unit(gk.ISEA_FRAMES, 0, x + h * math.cos(t), y + h * math.sin(t)))
        largest = max(largest, np.linalg.norm(q - p) / h)
    assert 1.15 < largest < kfill.K_INV
    # geodetic against authalic latitude
    lat = np.linspace(-89.99, 89.99, 20001)
    beta = np.array([math.degrees(math.atan2(u[2], math.hypot(u[0], u[1])))
                     for u in (gk.geodetic_to_unit(v, 0.0) for v in lat)])
    assert 1.004 < (np.diff(lat) / np.diff(beta)).max() < kfill.K_LAT


def test_centres_from_carried_corners_are_dggs_centres():
    for level in (0, 1, 2, 5, 9, 14, 21, 28):
        cells = sample_cells(level, 300, 100 + level)
        lat, lng = dggs.cell_to_latlng(cells)
        mine = np.array([kfill.centre(face, level, *t)[:2] for face, t in map(carried, cells.tolist())])
        assert mine[:, 0].tolist() == lat.tolist() and mine[:, 1].tolist() == lng.tolist()


@st.composite
def polygons(draw):
    """Polygons on a coarse lattice (exact edges, points exactly on them), some with a hole, some in parts."""
    rng = np.random.default_rng(draw(st.integers(0, 2**32 - 1)))
    parts = []
    for _ in range(draw(st.integers(1, 3))):
        x0, y0 = rng.integers(-170, 160), rng.integers(-80, 70)
        pts = np.c_[x0 + rng.integers(0, 12, 8), y0 + rng.integers(0, 12, 8)].astype(float)
        parts.append(shapely.convex_hull(shapely.multipoints(pts)))
    geom = shapely.union_all([p for p in parts if p.geom_type == "Polygon"] or [shapely.box(0, 0, 1, 1)])
    if rng.random() < 0.5 and geom.geom_type == "Polygon":
        c = geom.centroid
        geom = geom.difference(shapely.box(c.x - 0.5, c.y - 0.5, c.x + 0.5, c.y + 0.5))
    return geom


@settings(deadline=None, max_examples=40)
@given(polygons(), st.integers(0, 2**32 - 1))
def test_parity_is_exact(poly, seed):
    rng = np.random.default_rng(seed)
    x0, y0, x1, y1, frame, start, items, empty = _edge_index(poly)
    minx, miny, maxx, maxy = poly.bounds
    # points anywhere, on the lattice (vertices, edges, horizontal edges), on edges' midpoints, and 1 ulp off them
    grid = np.c_[rng.integers(math.floor(minx) - 1, math.ceil(maxx) + 2, 400),
                 rng.integers(math.floor(miny) - 1, math.ceil(maxy) + 2, 400)].astype(float)
    mids = np.c_[(x0 + x1) / 2, (y0 + y1) / 2]
    points = np.r_[np.c_[rng.uniform(minx - 1, maxx + 1, 600), rng.uniform(miny - 1, maxy + 1, 600)], grid, mids,
                   np.nextafter(mids, np.inf), np.c_[x0, y0]]
    got = np.array([kpoly.parity(px, py, x0, y0, x1, y1, frame, start, items, empty) for px, py in points])
    want = shapely.contains_xy(poly, points[:, 0], points[:, 1])
    sure = got >= 0
    assert (got[sure] == want[sure]).all()
    on_edge = shapely.intersects_xy(poly.boundary, points[:, 0], points[:, 1])
    assert (got[on_edge] == -1).all()  # a point on an edge or a vertex is never guessed
    gap = shapely.distance(poly.boundary, shapely.points(points[~sure]))
    assert (gap < 1e-12).all()  # undecided only on or beside an edge
    assert sure.mean() > 0.5


def test_rings_split_from_coordinates_are_shapely_rings():
    donut = shapely.Point(0, 0).buffer(10).difference(shapely.Point(1, 1).buffer(3))
    geom = shapely.union_all([donut, shapely.box(20, 20, 21, 21), shapely.box(21, 21, 22, 22)])  # two touch
    x0, y0, x1, y1, closed = kpoly.ring_edges(shapely.get_coordinates(geom))
    rings = shapely.get_rings(shapely.get_parts(geom))
    want = np.concatenate([np.c_[c[:-1], c[1:]] for c in map(shapely.get_coordinates, rings)])
    assert closed and np.c_[x0, y0, x1, y1].tolist() == want.tolist()
    assert not kpoly.ring_edges(np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]]))[4]  # never closes


@settings(deadline=None, max_examples=20)
@given(polygons())
def test_each_empty_bucket_knows_its_side(poly):
    x0, y0, x1, y1, frame, start, items, empty = _edge_index(poly)
    side = int(frame[4])
    rows, cols = np.divmod(np.arange(side * side), side)
    blank = np.flatnonzero(np.diff(start) == 0)
    x = frame[0] + (cols[blank] + 0.5) * frame[2]
    y = frame[1] + (rows[blank] + 0.5) * frame[3]
    assert ((empty[blank] % (side + 1)) == cols[blank]).all()  # an empty bucket is its own stop
    assert ((empty[blank] > side) == shapely.contains_xy(poly, x, y)).all()
