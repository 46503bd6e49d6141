"""Projected rasters cut cell by cell in their own plane (issue 35, dggs.raster.plane) against independent oracles.

None of them uses the plane cut under test (libdggs/src/pixels_plane.c, dggs/raster/plane.py):

* the pixel-by-pixel cut (:func:`dggs.raster.pieces.pixel_block_pieces`: each pixel's edges taken to lat/lng by
  pyproj and clipped along the cells' edges in Snyder's face planes): every (pixel, cell) piece of the two within
  2e-5 of its pixel's area (each is within ``TOLERANCE``, 1e-5, of the true piece);
* each pixel's geodesic area (:class:`pyproj.Geod`, its edges drawn with 64 points): a valid pixel's pieces add
  up to it within 1e-6;
* exactextract's coverage fractions of the cells drawn as polygons, in an equal-area CRS (where a pixel's share
  of planar area is its share of true area).
CRSs: UTM (mid and high latitude), Lambert azimuthal equal-area round the north pole and centred on icosahedron
vertices, polar stereographic round the south pole, EPSG:6933 across the antimeridian, web mercator, Mollweide.
Each case also asserts the plane cut took the block (a refusal would leave the pixel path, and nothing tested).
"""

from __future__ import annotations

from collections import defaultdict
from types import SimpleNamespace

import numpy as np
import pyproj
import pytest
from affine import Affine
from hypothesis import assume, example, given, settings
from hypothesis import strategies as st

import dggs
from dggs.raster.grid import TOLERANCE
from dggs.raster.pieces import pixel_block_pieces
from dggs.raster.plane import plane_block_pieces
from dggs.raster.source import Block

from ..strategies import examples, special_points

GEOD = pyproj.Geod(ellps="WGS84")


def transformer(crs: str) -> pyproj.Transformer:
    return pyproj.Transformer.from_crs(crs, "EPSG:4326", always_xy=True)


def geodesic_areas(tr: pyproj.Transformer, t: Affine, rows: int, cols: int, n: int = 64) -> np.ndarray:
    """Each pixel's geodesic area (m²), its edges drawn with n points in the CRS."""
    s = np.linspace(0.0, 1.0, n, endpoint=False)
    dc = np.concatenate([s, 0 * s + 1, 1 - s, 0 * s])
    dr = np.concatenate([0 * s, s, 0 * s + 1, 1 - s])
    out = np.empty(rows * cols)
    for p in range(rows * cols):
        r, c = divmod(p, cols)
        lng, lat = tr.transform(t.c + t.a * (c + dc), t.f + t.e * (r + dr))
        out[p] = abs(GEOD.polygon_area_perimeter(lng, lat)[0])
    return out


def by_pair(pixel: np.ndarray, cell: np.ndarray, area: np.ndarray) -> dict[tuple[int, int], float]:
    out: dict[tuple[int, int], float] = defaultdict(float)
    for p, c, a in zip(pixel.tolist(), cell.tolist(), area.tolist(), strict=True):
        out[(p, c)] += a
    return out


def plane_cut(crs: str, t: Affine, valid: np.ndarray, level: int) -> tuple[np.ndarray, ...]:
    """The plane cut's pieces, asserting it took the block and its basic invariants."""
    tr = transformer(crs)
    block = Block(0, 0, np.zeros((1, *valid.shape)), valid)
    got = plane_block_pieces(SimpleNamespace(transform=t), tr, block, level)
    assert got is not None, "the plane cut refused the block"
    pixel, cell, area, split = got
    assert not split and (area > 0).all() and (dggs.get_level(cell) == level).all()
    assert valid.ravel()[pixel].all()  # no piece in a pixel without data
    return pixel, cell, area


def check(crs: str, t: Affine, valid: np.ndarray, level: int) -> None:
    """The plane cut against the pixel cut (pieces) and the geodesic pixel areas (sums)."""
    rows, cols = valid.shape
    pixel, cell, area = plane_cut(crs, t, valid, level)
    tr = transformer(crs)
    exact = geodesic_areas(tr, t, rows, cols)
    total = np.bincount(pixel, weights=area, minlength=rows * cols)
    ok = valid.ravel()
    assert np.all(np.abs(total[ok] / exact[ok] - 1) < 1e-6), np.max(np.abs(total[ok] / exact[ok] - 1))
    old = pixel_block_pieces(SimpleNamespace(transform=t), tr, Block(0, 0, np.zeros((1, rows, cols)), valid), level)
    new_pairs, old_pairs = by_pair(pixel, cell, area), by_pair(*old[:3])
    for key in set(new_pairs) | set(old_pairs):
        diff = abs(new_pairs.get(key, 0.0) - old_pairs.get(key, 0.0)) / exact[key[0]]
        assert diff < 2 * TOLERANCE, (key[0], dggs.int_to_str(key[1]), new_pairs.get(key), old_pairs.get(key))


def around(crs: str, lat: float, lng: float, d: float, rows: int, cols: int) -> Affine:
    """A north-up grid of d-unit pixels in crs centred on (lat, lng)."""
    x, y = pyproj.Transformer.from_crs("EPSG:4326", crs, always_xy=True).transform(lng, lat)
    return Affine(d, 0.0, x - d * cols / 2, 0.0, -d, y + d * rows / 2)


CASES = {  # crs, grid, level: cells of about 3 to 60 pixels
    "utm 33N at 54N": ("EPSG:32633", Affine(5000.0, 0, 480000.0, 0, -5000.0, 6000000.0), 9),
    "utm 35N at 78N, near the zone's edge": ("EPSG:32635", Affine(5000.0, 0, 700000.0, 0, -5000.0, 8700000.0), 9),
    "laea round the north pole": ("EPSG:3575", Affine(4000.0, 0, -16000.0, 0, -4000.0, 14000.0), 9),
    "polar stereographic round the south pole": ("EPSG:3031", Affine(4000.0, 0, -14000.0, 0, 4000.0, -18000.0), 9),
    "EPSG:6933 across the antimeridian": ("EPSG:6933", Affine(5000.0, 0, 17367530.45 - 16000.0, 0, -5000.0, 3e6), 9),
    "web mercator at 60N": ("EPSG:3857", Affine(8000.0, 0, 1.0e6, 0, -8000.0, 8.4e6), 9),
    "mollweide at 40S": ("ESRI:54009", Affine(5000.0, 0, 2.0e6, 0, 5000.0, -4.8e6), 9),
}


@pytest.mark.parametrize("name", list(CASES))
def test_plane_cut_matches_the_pixel_cut_and_geodesic_areas(name):
    crs, t, level = CASES[name]
    valid = np.ones((7, 8), bool)
    valid[2, 3] = valid[5, 0] = False  # nodata pixels get no pieces; their neighbours are unchanged
    check(crs, t, valid, level)


@pytest.mark.parametrize("lat, lng", special_points()[6:18])
def test_plane_cut_at_icosahedron_vertices(lat, lng):
    """A 6 x 6 grid of 4 km pixels in an equal-area CRS centred on each icosahedron vertex (cells' kinks)."""
    crs = f"+proj=laea +lat_0={lat} +lon_0={lng} +ellps=WGS84 +units=m +no_defs"
    check(crs, around(crs, lat, lng, 4000.0, 6, 6), np.ones((6, 6), bool), 9)


CRSS = ["EPSG:32633", "EPSG:3575", "EPSG:6933", "EPSG:3857", "EPSG:3035", "EPSG:3031"]
PLACES = {"EPSG:32633": (54.0, 15.0), "EPSG:3575": (85.0, 10.0), "EPSG:6933": (-30.0, 100.0),
          "EPSG:3857": (40.0, -60.0), "EPSG:3035": (50.0, 10.0), "EPSG:3031": (-80.0, 30.0)}


@settings(max_examples=examples(20), deadline=None)
@given(st.sampled_from(CRSS), st.floats(-2.0, 2.0), st.floats(-2.0, 2.0), st.sampled_from([1000.0, 3000.0, 9000.0]),
       st.integers(1, 6), st.integers(1, 6), st.integers(0, 2), st.integers(0, 2**36 - 1))
@example("EPSG:3575", 5.0, 0.0, 3000.0, 4, 4, 0, 0)  # round the north pole
@example("EPSG:3031", -10.0, 0.0, 3000.0, 4, 4, 1, 5)  # round the south pole
@example("EPSG:6933", 0.0, 80.0, 9000.0, 3, 5, 0, 7)  # across the antimeridian (180E)
def test_each_pixel_is_shared_out_whole(crs, dlat, dlng, d, rows, cols, finer, mask):
    """Property: all pieces positive, none in a pixel without data, each valid pixel's pieces add up to its area."""
    lat, lng = PLACES[crs]
    lat = max(-90.0, min(90.0, lat + dlat))
    lng = (lng + dlng + 180.0) % 360.0 - 180.0
    t = around(crs, lat, lng, d, rows, cols)
    valid = ((mask >> np.arange(rows * cols)) & 1).astype(bool).reshape(rows, cols) | (np.arange(rows * cols) == 0
                                                                                      ).reshape(rows, cols)
    # the level whose cells hold 3 to 10 pixels, or finer ones (down to ~0.3 of that: the plane cut's smallest)
    level = max(0, min(28, round(np.log(dggs.cell_area(0, "m^2") / (5 * d * d)) / np.log(3)) + finer))
    tr = transformer(crs)
    got = plane_block_pieces(SimpleNamespace(transform=t), tr, Block(0, 0, np.zeros((1, rows, cols)), valid), level)
    assume(got is not None)  # cells under 2 pixels: the pixel cut's job
    pixel, cell, area, _ = got
    assert (area > 0).all() and valid.ravel()[pixel].all()
    exact = geodesic_areas(tr, t, rows, cols)
    total = np.bincount(pixel, weights=area, minlength=rows * cols)
    assert np.all(np.abs(total[valid.ravel()] / exact[valid.ravel()] - 1) < 1e-6)


def test_coverage_agrees_with_exactextract_in_equal_area_crss(tmp_path):
    """exactextract's coverage fraction of each pixel by each cell (drawn as a dense polygon put in the CRS), in
    LAEA round the north pole and EPSG:6933: a pixel's share of planar area is its share of true area there."""
    exactextract = pytest.importorskip("exactextract")
    gpd = pytest.importorskip("geopandas")
    rasterio = pytest.importorskip("rasterio")
    for crs, t in [("EPSG:3575", Affine(4000.0, 0, 60000.0, 0, -4000.0, 84000.0)),
                   ("EPSG:6933", Affine(5000.0, 0, 1.0e6, 0, -5000.0, 5.0e6))]:
        rows, cols, level = 12, 14, 9
        path = tmp_path / "ea.tif"
        with rasterio.open(path, "w", driver="GTiff", height=rows, width=cols, count=1, dtype="float64", crs=crs,
                           transform=t) as dst:
            dst.write(np.ones((1, rows, cols)))
        pixel, cell, area = plane_cut(crs, t, np.ones((rows, cols), bool), level)
        share = by_pair(pixel, cell, area / geodesic_areas(transformer(crs), t, rows, cols)[pixel])
        cells = np.unique(cell)
        shapes = gpd.GeoDataFrame(geometry=dggs.cell_to_polygon(cells, densify=64), crs="EPSG:4326").to_crs(crs)
        theirs = exactextract.exact_extract(str(path), shapes, ["cell_id", "coverage"], output="pandas")
        seen = set()
        for i, c in enumerate(cells.tolist()):
            for p, f in zip(theirs["cell_id"][i], theirs["coverage"][i], strict=True):
                seen.add((int(p), c))
                assert abs(share.get((int(p), c), 0.0) - f) < 1e-4, (crs, int(p), dggs.int_to_str(c), f)
        assert all(v < 1e-4 for k, v in share.items() if k not in seen)


def test_a_block_missing_a_cell_goes_to_the_pixel_cut(monkeypatch):
    """A cell the search missed leaves pixels short: the plane cut refuses the block, block_pieces cuts it pixel by
    pixel (the same pieces as the pixel cut's, to the bit)."""
    import dggs.raster.plane as plane
    from dggs.raster.pieces import block_pieces

    crs, t, level = CASES["utm 33N at 54N"]
    src, tr = SimpleNamespace(transform=t), transformer(crs)
    block = Block(0, 0, np.zeros((1, 7, 8)), np.ones((7, 8), bool))
    lng, lat = tr.transform(t.c + t.a * 4, t.f + t.e * 3.5)
    middle = dggs.latlng_to_cell(lat, lng, level, as_int=True)
    found = plane._candidates

    def without_middle(*args):  # the candidates may be of a coarser level: leave out the one holding the middle
        ids = found(*args)
        return ids[ids != dggs.cell_to_parent(middle, int(dggs.get_level(ids[:1])[0]))]

    monkeypatch.setattr(plane, "_candidates", without_middle)
    assert plane_block_pieces(src, tr, block, level) is None
    got, want = block_pieces(src, tr, block, level), pixel_block_pieces(src, tr, block, level)
    assert all(np.array_equal(a, b) for a, b in zip(got[:3], want[:3], strict=True))


def test_raster_to_cells_takes_the_plane_cut(tmp_path, monkeypatch):
    """Through raster_to_cells on a UTM GeoTIFF with nodata: the plane cut takes every block, "sum" of counts adds
    up to the raster's total, and "mean" is the pixel cut's within 2e-5 of the values' spread."""
    rasterio = pytest.importorskip("rasterio")
    import dggs.raster.pieces as pieces
    from dggs.raster import raster_to_cells

    crs, t, level = CASES["utm 33N at 54N"]
    data = np.random.default_rng(35).integers(1, 100, (1, 30, 40)).astype(np.uint16)
    data[0, 3:6, 10:14] = 0  # nodata
    path = tmp_path / "utm.tif"
    with rasterio.open(path, "w", driver="GTiff", height=30, width=40, count=1, dtype="uint16", crs=crs,
                       transform=t, nodata=0) as dst:
        dst.write(data)
    taken = []
    plane = pieces.plane_block_pieces
    monkeypatch.setattr(pieces, "plane_block_pieces", lambda *a: taken.append(r := plane(*a)) or r)
    summed = raster_to_cells(path, level, mode="sum", block_size=16)
    mean = raster_to_cells(path, level, mode="mean", block_size=16)
    assert taken and all(r is not None for r in taken)
    assert abs(summed["value"].sum() / data.sum() - 1) < 1e-12
    monkeypatch.setattr(pieces, "plane_block_pieces", lambda *a: None)
    old = raster_to_cells(path, level, mode="mean", block_size=16)
    assert np.array_equal(mean["cell_id"], old["cell_id"])
    assert np.allclose(mean["value"], old["value"], rtol=0, atol=2e-5 * 99)
    assert np.allclose(mean["coverage"], old["coverage"], rtol=0, atol=2e-5)


def test_rotated_and_geographic_grids_go_to_the_pixel_cut():
    """The plane cut's rules: an axis-aligned grid in a projected CRS; others are refused (None)."""
    block = Block(0, 0, np.zeros((1, 3, 3)), np.ones((3, 3), bool))
    rotated = Affine(5000.0, 100.0, 480000.0, 100.0, -5000.0, 6000000.0)
    assert plane_block_pieces(SimpleNamespace(transform=rotated), transformer("EPSG:32633"), block, 9) is None
    nad83 = Affine(0.05, 0, -100.0, 0, -0.05, 45.0)
    assert plane_block_pieces(SimpleNamespace(transform=nad83), transformer("EPSG:4269"), block, 9) is None
    assert plane_block_pieces(SimpleNamespace(transform=CASES["utm 33N at 54N"][1]), transformer("EPSG:32633"),
                              block, 9) is not None
