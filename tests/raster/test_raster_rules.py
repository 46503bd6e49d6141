"""Rasters: the rules issue 32 found broken (items 3, 7 and 8), each against a reference built without the binning.

- min / max / count take the pixels sharing positive area with a cell (docs/raster.md), not those touching it
  at a point: at both poles, against the pixels a dense sample of points in the cell lands in (latlng_to_cell);
- "center" reads a raster laid out 0..360 or 170..190 as the same globe as one laid out -180..180;
- xarray: unevenly spaced coordinates are refused, ``lat``/``lon`` dimensions are understood;
- +-inf pixels are refused like every other ingest; rows centred on +-90 keep their on-globe halves;
- ``nodata=`` still honours the raster's own mask band; a CRS with no way to WGS84 is a RasterError;
- a failed ``dggs bin-raster`` leaves no store behind; a huge ``cells_to_raster`` shape is refused before
  any allocation; bad ``nodata``, ``window``, ``band`` are typed errors.
"""

from __future__ import annotations

import numpy as np
import pytest

pytest.importorskip("rasterio")
import rasterio  # noqa: E402
from rasterio.transform import from_origin  # noqa: E402

import dggs  # noqa: E402
from dggs.raster import RasterError, cells_to_raster, raster_to_cells  # noqa: E402

from .helpers import write  # noqa: E402

GLOBAL = from_origin(-180.0, 90.0, 1.0, 1.0)


@pytest.fixture(scope="module")
def polar_tables(tmp_path_factory):
    """min, max and count at level 4 of the polar caps (10 rows each) of a global 1-degree lat/lng raster whose
    value is its pixel's index in the global raster (row * 360 + col)."""
    folder = tmp_path_factory.mktemp("rules")
    index = np.arange(180 * 360, dtype=np.float64).reshape(180, 360)
    tables = {}
    for name, rows, top in (("north", slice(0, 10), 90.0), ("south", slice(170, 180), -80.0)):
        path = write(folder / f"{name}.tif", index[rows], crs="EPSG:4326", transform=from_origin(-180.0, top, 1.0, 1.0))
        for mode in ("min", "max", "count"):
            tables[name, mode] = raster_to_cells(path, 4, mode=mode, as_str=True).set_index("cell")["value"]
    return tables


def _pixels_meeting(cell: str, rows: range, n: int = 24) -> set[int]:
    """The pixels (row * 360 + col) an n x n sample of points inside them puts in ``cell``: shared area."""
    fr = (np.arange(n) + 0.5) / n
    r, c = np.meshgrid(np.array(rows), np.arange(360), indexing="ij")
    r, c = r.ravel(), c.ravel()
    lat = (90.0 - r[:, None, None] - fr[None, :, None]) + 0 * fr[None, None, :]
    lng = (-180.0 + c[:, None, None] + fr[None, None, :]) + 0 * fr[None, :, None]
    inside = np.asarray(dggs.latlng_to_cell(lat.ravel(), lng.ravel(), 4)).reshape(r.size, n * n) == cell
    hit = inside.any(axis=1)
    return set((r[hit] * 360 + c[hit]).tolist())


@pytest.mark.parametrize("cell,rows", [("A5000", range(0, 9)), ("Q5000", range(171, 180)), ("R1000", range(171, 180))])
def test_min_max_count_take_pixels_with_positive_shared_area_at_both_poles(polar_tables, cell, rows):
    """A top (bottom) row pixel that touches a polar cell only at the pole shares no area: it is not counted."""
    meeting = _pixels_meeting(cell, rows)
    cap = "north" if rows.start == 0 else "south"
    assert dggs.get_level(cell) == 4 and max(abs(lat) for lat, _ in dggs.cell_to_boundary(cell)) > 89.9
    got = {m: polar_tables[cap, m][cell] for m in ("min", "max", "count")}
    assert int(got["min"]) == min(meeting) and int(got["max"]) == max(meeting)
    # a sample of points can miss a sliver of positive area, never count a pixel touching at a point only
    assert len(meeting) <= int(got["count"]) <= len(meeting) + 3


# -- item 7: "center" on rasters laid out past 180 ------------------------------------------------------------


def _rolled(tmp_path, west: float, name: str):
    """The same global raster as a -180..180 one (value = longitude of the pixel's west edge, as -180..179), laid
    out from ``west``."""
    cols = (np.arange(360) + west + 180.0) % 360.0 - 180.0
    data = np.repeat(cols[None, :], 180, axis=0) + 1000.0 * np.arange(180)[:, None]
    return write(tmp_path / name, data, crs="EPSG:4326", transform=from_origin(west, 90.0, 1.0, 1.0))


@pytest.mark.parametrize("block_size", [512, 100])
def test_center_reads_a_0_360_raster_as_the_same_globe(tmp_path, block_size):
    ref = raster_to_cells(_rolled(tmp_path, -180.0, "ref.tif"), 6, mode="center")
    got = raster_to_cells(_rolled(tmp_path, 0.0, "east.tif"), 6, mode="center", block_size=block_size)
    assert len(ref) == dggs.get_num_cells(6)
    assert got["cell_id"].tolist() == ref["cell_id"].tolist()
    assert np.array_equal(got["value"].to_numpy(), ref["value"].to_numpy())


def test_center_reads_a_170_190_raster_on_both_sides_of_180(tmp_path):
    data = np.arange(20 * 20, dtype=np.float64).reshape(20, 20)
    east = raster_to_cells(write(tmp_path / "a.tif", data, crs="EPSG:4326", transform=from_origin(170.0, 10.0, 1.0, 1.0)),
                           5, mode="center", as_str=True)
    lat, lng = dggs.cell_to_latlng(east["cell"].tolist())
    lng = np.asarray(lng)
    assert (lng < -170).any() and (lng > 170).any()
    cols = np.floor((lng % 360.0) - 170.0).astype(int)
    rows = np.floor(10.0 - np.asarray(lat)).astype(int)
    assert np.array_equal(east["value"].to_numpy(), data[rows, cols])
    mean = raster_to_cells(write(tmp_path / "b.tif", np.ones((20, 20)), crs="EPSG:4326",
                                 transform=from_origin(170.0, 10.0, 1.0, 1.0)), 5, mode="mean")
    assert set(east["cell_id"]) <= set(mean["cell_id"])


# -- item 7: xarray --------------------------------------------------------------------------------------------


def test_unevenly_spaced_xarray_coordinates_are_refused():
    xr = pytest.importorskip("xarray")
    pytest.importorskip("rioxarray")
    y = np.array([50.0, 40.0, 10.0, 0.0])  # uneven: a pixel per label cannot be drawn from one affine transform
    x = np.array([0.5, 1.5, 2.5])
    arr = xr.DataArray(np.ones((4, 3)), dims=("y", "x"), coords={"y": y, "x": x}).rio.write_crs("EPSG:4326")
    with pytest.raises(RasterError, match="evenly spaced"):
        raster_to_cells(arr, 4)


@pytest.mark.parametrize("ydim,xdim", [("lat", "lon"), ("latitude", "longitude")])
def test_lat_lon_dimension_names_are_understood(ydim, xdim):
    xr = pytest.importorskip("xarray")
    pytest.importorskip("rioxarray")
    data = np.random.default_rng(3).random((6, 8))
    coords_y, coords_x = 10.0 - np.arange(6) - 0.5, 20.0 + np.arange(8) + 0.5
    ref = xr.DataArray(data, dims=("y", "x"), coords={"y": coords_y, "x": coords_x}).rio.write_crs("EPSG:4326")
    named = xr.DataArray(data, dims=(ydim, xdim), coords={ydim: coords_y, xdim: coords_x}).rio.write_crs("EPSG:4326")
    assert raster_to_cells(named, 6).equals(raster_to_cells(ref, 6))


# -- item 8 ----------------------------------------------------------------------------------------------------


@pytest.mark.parametrize("bad", [np.inf, -np.inf])
def test_infinite_pixels_are_refused_by_every_path(tmp_path, bad):
    data = np.ones((4, 4))
    data[2, 1] = bad
    path = write(tmp_path / "inf.tif", data, crs="EPSG:4326", transform=from_origin(0.0, 4.0, 1.0, 1.0))
    with pytest.raises(RasterError, match="inf"):
        raster_to_cells(path, 5)
    with pytest.raises(RasterError, match="inf"):
        raster_to_cells(path, 5, mode="center")
    from dggs.storage import CellStore

    with CellStore(tmp_path / "s.db") as store, pytest.raises(RasterError, match="inf"):
        store.ingest_raster(path, 5)
    # as nodata, infinity is no data: refused only as a value
    masked = write(tmp_path / "inf_nodata.tif", data, crs="EPSG:4326", transform=from_origin(0.0, 4.0, 1.0, 1.0),
                   nodata=bad)
    assert raster_to_cells(masked, 5, mode="count")["value"].sum() >= 15


def test_rows_centred_on_the_poles_keep_their_on_globe_halves(tmp_path):
    """ERA5's layout: 181 rows centred on 90, 89, ..., -90; the edges at +-90.5 lie past the poles.  Here its
    polar caps (11 rows from each pole): each pixel's value is shared out over its part on the globe."""
    for name, top in (("north", 90.5), ("south", -79.5)):
        path = write(tmp_path / f"{name}.tif", np.ones((11, 360)), crs="EPSG:4326", transform=from_origin(-0.5, top, 1.0, 1.0))
        table = raster_to_cells(path, 3, mode="sum")
        assert abs(table["value"].sum() - 11 * 360) < 1e-6, name


def test_nodata_argument_still_honours_the_mask_band(tmp_path):
    path = tmp_path / "masked.tif"
    data = np.full((1, 10, 10), 5.0)
    data[0, 0, 0] = -1.0
    with rasterio.open(path, "w", driver="GTiff", height=10, width=10, count=1, dtype="float64", crs="EPSG:4326",
                       transform=from_origin(0.0, 10.0, 1.0, 1.0)) as dst:
        dst.write(data)
        mask = np.full((10, 10), 255, dtype=np.uint8)
        mask[:, 5:] = 0  # the east half has no data, by the mask band
        dst.write_mask(mask)
    plain = raster_to_cells(path, 4, mode="count")["value"].sum()
    given = raster_to_cells(path, 4, mode="count", nodata=-1.0)["value"].sum()
    with rasterio.open(path) as src:
        assert src.read_masks(1)[:, 5:].max() == 0  # the mask is there
    assert given < plain  # the mask still applies, and -1 is no data too
    assert raster_to_cells(path, 4, mode="max", nodata=-1.0)["value"].max() == 5.0


LOCAL_CS = 'LOCAL_CS["a local grid",LOCAL_DATUM["site",0],UNIT["metre",1],AXIS["x",EAST],AXIS["y",NORTH]]'


def test_a_crs_with_no_transformation_to_wgs84_is_a_raster_error(tmp_path):
    path = write(tmp_path / "local.tif", np.ones((3, 3)), crs=rasterio.crs.CRS.from_wkt(LOCAL_CS),
                 transform=from_origin(0.0, 30.0, 10.0, 10.0))
    for mode in ("mean", "center"):
        with pytest.raises(RasterError, match="WGS84"):
            raster_to_cells(path, 4, mode=mode)
    from dggs.storage import CellStore

    with CellStore(tmp_path / "l.db") as store, pytest.raises(RasterError, match="WGS84"):
        store.ingest_raster(path, 4)
    with pytest.raises(RasterError, match="WGS84"):
        cells_to_raster(["C401"], [1.0], crs=LOCAL_CS, transform=from_origin(0.0, 30.0, 10.0, 10.0), shape=(3, 3))


def test_cells_to_raster_refuses_a_huge_shape_before_allocating():
    with pytest.raises(dggs.DggsValueError, match="1,000,000,000,000"):
        cells_to_raster(["C401"], [1.0], crs="EPSG:4326", transform=GLOBAL, shape=(10**6, 10**6))


def test_bad_nodata_window_band_are_typed_errors(tmp_path):
    path = write(tmp_path / "g.tif", np.ones((4, 4)), crs="EPSG:4326", transform=from_origin(0.0, 4.0, 1.0, 1.0))
    for kwargs, word in [({"nodata": "abc"}, "nodata"), ({"nodata": [1, 2]}, "nodata"), ({"window": (0, 0, "a", 2)}, "window"),
                         ({"window": 5}, "window"), ({"window": (0, 0, None, 2)}, "window"), ({"band": "1"}, "band"),
                         ({"band": 1.5}, "band"), ({"band": [[1]]}, "band")]:
        with pytest.raises(RasterError, match=word):
            raster_to_cells(path, 4, **kwargs)


@pytest.mark.parametrize("args", [["missing.tif", "--level", "4"], ["good.tif", "--level", "29"], ["good.tif", "--level", "4", "--band", "3"],
                                  ["inf.tif", "--level", "4"]])
def test_a_failed_bin_raster_leaves_no_store(tmp_path, args, monkeypatch):
    from click.testing import CliRunner

    from dggs.cli import main

    monkeypatch.chdir(tmp_path)
    write(tmp_path / "good.tif", np.ones((4, 4)), crs="EPSG:4326", transform=from_origin(0.0, 4.0, 1.0, 1.0))
    bad = np.ones((4, 4))
    bad[0, 0] = np.inf
    write(tmp_path / "inf.tif", bad, crs="EPSG:4326", transform=from_origin(0.0, 4.0, 1.0, 1.0))
    res = CliRunner().invoke(main, ["bin-raster", *args, "--db", "out.db"])
    assert res.exit_code == 1, res.output
    assert "Traceback" not in res.output
    assert not (tmp_path / "out.db").exists()


def test_bin_raster_with_a_local_crs_is_one_line(tmp_path, monkeypatch):
    from click.testing import CliRunner

    from dggs.cli import main

    monkeypatch.chdir(tmp_path)
    write(tmp_path / "local.tif", np.ones((3, 3)), crs=rasterio.crs.CRS.from_wkt(LOCAL_CS), transform=from_origin(0.0, 30.0, 10.0, 10.0))
    res = CliRunner().invoke(main, ["bin-raster", "local.tif", "--level", "4", "--db", "out.db"])
    assert res.exit_code == 1 and "Traceback" not in res.output and len(res.output.strip().splitlines()) <= 2, res.output
    assert not (tmp_path / "out.db").exists()
