"""A cell wholly under a raster is wholly covered (issue 32 item 2): the pieces of its pixels add up to its area.

The referee is the grid's own equal-area property, not the cutting code: every cell of a level has the area
``dggs.cell_area(level)`` (the ellipsoid's area over the number of cells), so the densities of a raster of ones
summed per cell (``mode="sum", density=True``: the covered area in m²) must give it back wherever the raster
covers the cell.  A global 1-degree raster at level 5 puts cells on every kind of place the cut has to get right:
the poles (pixels drawn with a hundred points an edge), the faces' centres and the rays from them where
Snyder's plane kinks, and the borders between tiles of 32 pixels drawn with different numbers of points.
"""

from __future__ import annotations

import numpy as np
import pytest

pytest.importorskip("rasterio")
import math  # noqa: E402

import rasterio  # noqa: E402
from rasterio.transform import from_origin  # noqa: E402

import dggs  # noqa: E402
from dggs.geometry import kernel as gk  # noqa: E402
from dggs.geometry.authalic import WGS84  # noqa: E402
from dggs.raster import raster_to_cells  # noqa: E402

#: The bound docs/raster.md states for a cell wholly under the raster (its covered share against 1).
WHOLE_CELL = 1e-6


@pytest.fixture(scope="module")
def global_ones(tmp_path_factory):
    path = tmp_path_factory.mktemp("exact") / "ones.tif"
    with rasterio.open(path, "w", driver="GTiff", height=180, width=360, count=1, dtype="float64",
                       crs="EPSG:4326", transform=from_origin(-180, 90, 1, 1)) as dst:
        dst.write(np.ones((1, 180, 360)))
    return path


def test_every_cell_of_a_global_raster_is_covered_to_its_area(global_ones):
    level = 5
    table = raster_to_cells(global_ones, level, mode="sum", density=True)
    assert len(table) == dggs.get_num_cells(level)
    share = table["value"].to_numpy() / dggs.cell_area(level, unit="m^2")
    err = np.abs(share - 1.0)
    worst = table["cell_id"].to_numpy()[np.argmax(err)]
    assert err.max() < WHOLE_CELL, f"{dggs.int_to_str(int(worst))}: covered share {share[np.argmax(err)]!r}"
    assert (err > 1e-8).mean() < 0.02  # 2,622 of 9,720 cells were off by more than 1e-8 (2,590 below 1)
    assert table["coverage"].min() > 1.0 - WHOLE_CELL



# ---- an independent formulation of the kernel's arcs (numpy, over the grid lines rather than round each pixel):
# the area between each pair of chords and its arc, a third of their triangle, to the cell of the middle point


def _point_frames(lat: np.ndarray, lng: np.ndarray) -> tuple[np.ndarray, ...]:
    """Per point (WGS84 degrees): its face-plane ``x``, ``y`` on its face and its sector ``3 face + s``.

    As the kernel finds them (``pixels.c``: the nearest face, Snyder's forward on it, ``dggs_pixels_region``).
    """
    beta = WGS84.geodetic_to_authalic(np.radians(lat))
    lam = np.radians(lng)
    n = beta.size
    face, x, y = np.empty(n, np.int64), np.empty(n), np.empty(n)
    gk.forward_rad(n, beta, lam, gk.ISEA_CENTRES, gk.ISEA_FRAMES, face, x, y)
    cb = np.cos(beta)
    u = np.stack([cb * np.cos(lam), cb * np.sin(lam), np.sin(beta)], axis=1)
    frames = gk.ISEA_FRAMES[face]
    north, east = np.einsum("ij,ij->i", frames[:, 1], u), np.einsum("ij,ij->i", frames[:, 2], u)
    half = 0.5 * math.sqrt(3.0)
    first = (east >= 0.0) & (-0.5 * east - half * north < 0.0) & ~((east == 0.0) & (north < 0.0))
    third = (east < 0.0) & (-0.5 * east + half * north >= 0.0)
    sector = 3 * face + np.where(first, 0, np.where(third, 2, 1))
    return x, y, sector


def _segments(x: np.ndarray, y: np.ndarray, sector: np.ndarray) -> np.ndarray:
    """Signed area of each triangle (p[2i], p[2i+1], p[2i+2]) along the last axis; 0 across a kink of the plane.

    Archimedes: a parabolic arc through the three points bounds, with the two chords, a third of that
    triangle's area (the segment under the long chord is 4/3 of it).
    """
    a, m, b = (slice(0, -2, 2), slice(1, -1, 2), slice(2, None, 2))
    twice = (x[..., m] - x[..., a]) * (y[..., b] - y[..., a]) - (x[..., b] - x[..., a]) * (y[..., m] - y[..., a])
    smooth = (sector[..., a] == sector[..., m]) & (sector[..., m] == sector[..., b])
    out: np.ndarray = np.where(smooth, 0.5 * twice, 0.0)
    return out


def edge_corrections(
    hlat: np.ndarray, hlng: np.ndarray, vlat: np.ndarray, vlng: np.ndarray, k: int, valid: np.ndarray, level: int
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(pixel, cell, area)``: what each pixel's chords leave out, in the cell where they leave it (planar units).

    Each edge of an even ``k`` is taken in pairs of chords; the area between the curved edge and a pair is a
    third of the triangle the pair makes (:func:`_segments`), given to the cell of the pair's middle point.
    An edge between two pixels is one arc: the area one pixel's chords leave out its neighbour's take in, in
    the same cell, so a cell's covered area is its pixels' true area whatever the points either pixel drew
    its edges with.  Pairs across a kink of the plane (the kernel cuts them at the kink) are left as drawn.
    """
    rows, cols = valid.shape
    empty = (np.zeros(0, np.int64), np.zeros(0, np.uint64), np.zeros(0))
    if k < 2 or k % 2 or not valid.any():
        return empty
    hx, hy, hs = (a.reshape(hlat.shape) for a in _point_frames(hlat.ravel(), hlng.ravel()))
    vx, vy, vs = (a.reshape(vlat.shape) for a in _point_frames(vlat.ravel(), vlng.ravel()))
    # orientation of each pixel's ring (top edge left to right, then down its right edge) in the face planes:
    # that of its corners on the sphere (Snyder's projection keeps it), from two triangles (one may be a pole's)
    beta, lam = WGS84.geodetic_to_authalic(np.radians(hlat[:, ::k])), np.radians(hlng[:, ::k])
    u = np.stack([np.cos(beta) * np.cos(lam), np.cos(beta) * np.sin(lam), np.sin(beta)], axis=-1)
    tl, tr, br, bl = u[:-1, :-1], u[:-1, 1:], u[1:, 1:], u[1:, :-1]
    turn = np.einsum("...i,...i->...", np.cross(tr - tl, br - tl) + np.cross(br - tl, bl - tl), tl)
    sign = np.where(turn > 0.0, 1.0, -1.0).ravel()
    th = _segments(hx, hy, hs)  # (rows + 1, cols k / 2): along each line of constant row, left to right
    tv = _segments(vx.T, vy.T, vs.T)  # (cols + 1, rows k / 2): along each line of constant column, downwards
    mh = np.asarray(dggs.latlng_to_cell(hlat[:, 1::2], hlng[:, 1::2], level, as_int=True), np.uint64)  # middle points' cells
    mv = np.asarray(dggs.latlng_to_cell(vlat[1::2], vlng[1::2], level, as_int=True), np.uint64).T
    half = k // 2
    col_of = np.arange(cols * half) // half
    row_of = np.arange(rows * half) // half
    parts = []
    for t, mid, line_pixel, gets in (
        (th[:-1], mh[:-1], np.arange(rows)[:, None] * cols + col_of[None, :], 1.0),  # top edges, as drawn
        (th[1:], mh[1:], np.arange(rows)[:, None] * cols + col_of[None, :], -1.0),  # bottom edges, reversed
        (tv[1:].T, mv[1:].T, row_of[:, None] * cols + np.arange(cols)[None, :], 1.0),  # right edges, downwards
        (tv[:-1].T, mv[:-1].T, row_of[:, None] * cols + np.arange(cols)[None, :], -1.0),  # left edges, upwards
    ):
        pixel = line_pixel.ravel()
        area = gets * t.ravel() / 3.0
        keep = (area != 0.0) & valid.ravel()[pixel]
        parts.append((pixel[keep], mid.ravel()[keep], area[keep] * sign[pixel[keep]]))
    pixel, cell, area = (np.concatenate([p[i] for p in parts]) for i in range(3))
    return pixel, cell, area


def _with_corrections(
    pixel: np.ndarray, cell: np.ndarray, area: np.ndarray, cp: np.ndarray, cc: np.ndarray, ca: np.ndarray
) -> np.ndarray:
    """``area`` with each correction (pixel ``cp``, cell ``cc``, area ``ca``) added to that pixel's piece in that cell.

    ``pixel`` comes grouped (each pixel's pieces together, in pixel order, as the kernel gives them).  A
    correction whose cell holds no piece of its pixel (its point on a cell's edge or corner), or that would
    leave a piece below zero, goes to the pixel's largest piece.
    """
    area = area.copy()
    if not cp.size:
        return area
    counts = np.bincount(pixel, minlength=int(max(pixel.max(), cp.max())) + 1)
    start = np.concatenate([[0], np.cumsum(counts)[:-1]])
    where = np.full(cp.size, -1, np.int64)
    one = counts[cp] == 1  # most pixels lie in one cell: their one piece (if the cell is that piece's)
    where[one] = start[cp[one]]
    where[one & (cell[np.minimum(where, area.size - 1)] != cc)] = -1
    rest = np.nonzero(counts[cp] > 1)[0]
    most = int(counts[cp[rest]].max()) if rest.size else 0
    if most <= 24:  # a few pieces a pixel: look at each in turn
        for j in range(most):
            if not rest.size:
                break
            idx = start[cp[rest]] + j
            hit = (j < counts[cp[rest]]) & (cell[np.minimum(idx, area.size - 1)] == cc[rest])
            where[rest[hit]] = idx[hit]
            rest = rest[~hit]
    else:  # many: by sorting (pixel, cell) keys
        cells, inv = np.unique(np.concatenate([cell, cc[rest]]), return_inverse=True)
        n = np.uint64(cells.size)
        key = pixel.astype(np.uint64) * n + inv[: cell.size].astype(np.uint64)
        ckey = cp[rest].astype(np.uint64) * n + inv[cell.size:].astype(np.uint64)
        order = np.argsort(key, kind="stable")
        at = order[np.minimum(np.searchsorted(key, ckey, sorter=order), key.size - 1)]
        where[rest] = np.where(key[at] == ckey, at, -1)
    lost = np.nonzero(where < 0)[0]
    for i in lost:  # rare: onto the pixel's largest piece
        where[i] = _largest_piece(area, int(start[cp[i]]), int(counts[cp[i]]))
    area += np.bincount(where, weights=ca, minlength=area.size)
    low = np.nonzero(area < 0.0)[0]
    for i in low:  # a sliver's correction larger than the sliver: back, and onto the largest piece
        p = int(pixel[i])
        area[_largest_piece(area, int(start[p]), int(counts[p]))] += area[i]
        area[i] = 0.0
    return area


def _largest_piece(area: np.ndarray, start: int, count: int) -> int:
    """The index of the largest of the pieces ``start .. start + count``."""
    return start + int(np.argmax(area[start:start + count]))


@pytest.mark.parametrize(("deg", "lat0", "lng0", "k", "level"), [
    (1.0, 89.0, -180.0, 30, 5),  # the top rows round the north pole
    (0.5, 30.0, 0.0, 8, 7),
    (0.01, 50.0, 5.0, 2, 15),  # cells the size of the pixels
    (0.1, 40.0, 60.0, 4, 9),
    (1.0, -60.0, 170.0, 6, 4),  # across the antimeridian
    (2.0, 70.0, -60.0, 12, 3),  # face centres and the rays from them
])
def test_the_kernels_arcs_are_the_grid_lines_arcs(deg, lat0, lng0, k, level):
    """The kernel's pieces with arcs against its chord pieces plus this module's arcs, computed line by line."""
    from affine import Affine

    from dggs.index._kernel import pixels as kpx
    from dggs.raster.grid import edge_grid

    rows, cols = 10, 12
    grid = [np.ascontiguousarray(g) for g in edge_grid(None, Affine(deg, 0, lng0, 0, -deg, lat0), 0, 0, rows, cols, k)]
    valid = np.ones((rows, cols), bool)
    valid[3, 4] = valid[0, 0] = False
    pixel, cell, area, _ = kpx.grid_pieces(*grid, k, valid, level)
    got_pixel, got_cell, got, _ = kpx.grid_pieces(*grid, k, valid, level, arcs=True)
    assert np.array_equal(got_pixel, pixel) and np.array_equal(got_cell, cell)
    want = _with_corrections(pixel, cell, area, *edge_corrections(*grid, k, valid, level))
    assert np.abs(want - area).max() > 1e-8 * area.max()  # the arcs are there to be found
    assert np.abs(got - want).max() < 1e-9 * area.max()


def test_a_pixels_area_is_the_closed_form_one():
    """Lat/lng pixels against their area on the authalic sphere, R² (λ2 - λ1)(sin β1 - sin β2) (no cutting code)."""
    from affine import Affine

    from dggs.index._pixels import pixel_pieces
    from dggs.raster.grid import edge_grid

    radius2 = WGS84.area / (4.0 * np.pi)
    for deg, lat0, lng0, k, bound in ((0.1, 50.0, 5.0, 2, 1e-9), (0.01, 89.9, 5.0, 2, 1e-8), (0.1, 30.0, 40.0, 4, 1e-9)):
        n = 8
        beta = WGS84.geodetic_to_authalic(np.radians(lat0 - deg * np.arange(n + 1)))
        exact = radius2 * np.radians(deg) * (np.sin(beta[:-1]) - np.sin(beta[1:]))
        grid = edge_grid(None, Affine(deg, 0, lng0, 0, -deg, lat0), 0, 0, n, n, k)
        total = pixel_pieces(*grid, k, np.ones((n, n), bool), 10)[3].reshape(n, n)
        assert np.abs(total / exact[:, None] - 1.0).max() < bound, (deg, lat0)
