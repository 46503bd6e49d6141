"""The way out and back: ``raster_to_cells(to="xarray")`` for xdggs, and ``cells_to_raster`` (issue 19).

Referees: xdggs's own decoder (and the pandas table, which test_raster_to_cells.py
checks against independent oracles); for ``cells_to_raster``, the raster we
started from (a round trip at a fine level), a constant field, and
``dggs.latlng_to_cell`` of each pixel's centre worked out here one pixel at a time.
"""

from __future__ import annotations

import numpy as np
import pytest

pytest.importorskip("rasterio")
import rasterio  # noqa: E402
from affine import Affine  # noqa: E402
from rasterio.transform import from_origin  # noqa: E402

import dggs  # noqa: E402
from dggs.raster import RasterError, cells_to_raster, raster_to_cells  # noqa: E402

from .helpers import field, write  # noqa: E402

WGS84_GRID = from_origin(10.0, 50.0, 0.1, 0.1)


def test_xarray_output_decodes_with_xdggs_and_holds_the_pandas_values(tmp_path):
    xdggs = pytest.importorskip("xdggs")
    import dggs.xdggs  # noqa: F401 - registers the grid

    path = write(tmp_path / "v.tif", field(12, 15, bands=2), crs="EPSG:4326", transform=WGS84_GRID)
    table = raster_to_cells(path, 8, as_str=True)
    ds = raster_to_cells(path, 8, as_str=True, to="xarray")
    assert ds["cell_ids"].dtype == np.uint64 and ds["cell_ids"].dims == ("cells",)
    assert ds["cell_ids"].attrs == {"grid_name": dggs.xdggs.GRID_NAME, "level": 8}
    decoded = xdggs.decode(ds)
    assert decoded.dggs.grid_info.level == 8
    for name in ("band_1", "band_2", "coverage"):
        assert np.array_equal(decoded[name].to_numpy(), table[name].to_numpy())
    assert decoded["cell"].to_numpy().tolist() == table["cell"].tolist()
    lat, lng = dggs.cell_to_latlng(table["cell_id"].to_numpy().astype(np.uint64))
    assert np.allclose(decoded.dggs.cell_centers().latitude, lat)
    one = decoded.dggs.sel_latlon(float(lat[3]), float(lng[3]))
    assert float(one["band_1"]) == table["band_1"].iloc[3]
    centre = raster_to_cells(path, 8, mode="center", band=1, to="xarray")
    assert set(centre.data_vars) == {"value"} and xdggs.decode(centre).dggs.grid_info.level == 8
    with pytest.raises(dggs.DggsValueError, match="to='polars'"):
        raster_to_cells(path, 8, to="polars")


def test_round_trip_raster_cells_raster_at_a_fine_level(tmp_path):
    data = field(20, 30, seed=3)[0].astype(np.float64)
    data[2, 3] = np.nan
    path = write(tmp_path / "r.tif", data, crs="EPSG:4326", transform=WGS84_GRID)
    cells = raster_to_cells(path, 14, mode="center")  # cells of 0.08 km², pixels of 80 km²
    back = cells_to_raster(cells["cell_id"], cells["value"], like=path)
    assert np.array_equal(back, data, equal_nan=True)
    grid = cells_to_raster(cells["cell_id"], cells["value"], transform=WGS84_GRID, shape=(20, 30))
    assert np.array_equal(grid, back, equal_nan=True)


def test_center_is_the_cell_under_each_pixel_centre(tmp_path):
    transform = from_origin(1.0e6, 6.5e6, 20_000.0, 20_000.0)
    from shapely.geometry import box

    ids = np.asarray(dggs.polygon_to_cells(box(8.0, 48.0, 10.0, 52.0), 7, as_int=True))  # the raster's west half
    values = np.arange(ids.size, dtype=np.float64)
    out = cells_to_raster(ids, values, transform=transform, shape=(9, 11), crs="EPSG:3857", nodata=-1.0)
    import pyproj

    to = pyproj.Transformer.from_crs("EPSG:3857", "EPSG:4326", always_xy=True)
    lookup = dict(zip(ids.tolist(), values.tolist(), strict=True))
    for r in range(9):
        for c in range(11):
            lng, lat = to.transform(*(transform @ (c + 0.5, r + 0.5)))
            assert out[r, c] == lookup.get(dggs.latlng_to_cell(lat, lng, 7, as_int=True), -1.0)
    assert (out == -1.0).any() and (out >= 0).any()


def test_area_keeps_a_constant_constant_and_weighs_by_shared_area():
    transform = from_origin(5.0, 47.0, 0.05, 0.05)
    ids = np.asarray(dggs.polygon_to_cells(dggs.cell_to_polygon(dggs.latlng_to_cell(46.5, 5.5, 5)), 9, as_int=True))
    flat = cells_to_raster(ids, np.full(ids.size, 3.25), transform=transform, shape=(16, 16), mode="area")
    inside = ~np.isnan(flat)
    assert inside.sum() > 50 and np.allclose(flat[inside], 3.25, rtol=0, atol=1e-12)
    assert np.isnan(flat).any()  # pixels meeting no given cell: nodata
    ramp = cells_to_raster(ids, dggs.cell_to_latlng(ids)[1], transform=transform, shape=(16, 16), mode="area")
    lng = 5.0 + 0.05 * (np.arange(16) + 0.5)
    full = ~np.isnan(ramp).any(axis=0)
    assert np.allclose(ramp[:, full].mean(axis=0), lng[full], atol=0.05)  # the cells' longitudes, by area
    centre = cells_to_raster(ids, np.full(ids.size, 3.25), transform=transform, shape=(16, 16))
    assert set(np.unique(centre[~np.isnan(centre)])) == {3.25}


def test_like_a_dataarray_gives_a_dataarray_and_path_writes_a_geotiff(tmp_path):
    rioxarray = pytest.importorskip("rioxarray")
    path = write(tmp_path / "g.tif", field(10, 12)[0], crs="EPSG:3035")
    like = rioxarray.open_rasterio(path)
    cells = raster_to_cells(like, 12, mode="mean")
    out = cells_to_raster(cells["cell_id"].to_numpy(), cells["value"], like=like, mode="area",
                          path=tmp_path / "back.tif", nodata=-9.0)
    assert out.dims == ("y", "x") and out.rio.crs == like.rio.crs and out.shape == (10, 12)
    assert np.array_equal(out["x"].values, like["x"].values)
    with rasterio.open(tmp_path / "back.tif") as src:
        assert src.crs == like.rio.crs and src.transform == like.rio.transform() and src.nodata == -9.0
        assert np.array_equal(src.read(1), out.values)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["back.tif", "g.tif"]  # no temporary file left


def test_bad_input_names_the_value(tmp_path):
    grid = {"transform": Affine(0.1, 0, 0, 0, -0.1, 1), "shape": (2, 2)}
    with pytest.raises(dggs.LevelMismatchError, match="of level 3"):
        cells_to_raster(["C401", "C40"], [1, 2], **grid)
    with pytest.raises(dggs.DggsValueError, match="given twice"):
        cells_to_raster(["C401", "C401"], [1, 2], **grid)
    with pytest.raises(dggs.DggsValueError, match="1 values for 2 cells"):
        cells_to_raster(["C401", "C402"], [1], **grid)
    with pytest.raises(dggs.InvalidCellError):
        cells_to_raster(["C4x"], [1], **grid)
    with pytest.raises(dggs.DggsValueError, match="mode 'nearest'"):
        cells_to_raster(["C401"], [1], mode="nearest", **grid)
    with pytest.raises(dggs.DggsValueError, match="give the grid"):
        cells_to_raster(["C401"], [1], shape=(2, 2))
    with pytest.raises(dggs.DggsValueError, match="not both"):
        cells_to_raster(["C401"], [1], like=tmp_path / "x.tif", **grid)
    with pytest.raises(dggs.DggsValueError, match="shape must be"):
        cells_to_raster(["C401"], [1], transform=grid["transform"], shape=(0, 2))
    with pytest.raises(RasterError, match="no raster file"):
        cells_to_raster(["C401"], [1], like=tmp_path / "x.tif")
    with pytest.raises(RasterError, match="not a CRS"):
        cells_to_raster(["C401"], [1], crs="EPSG:0", **grid)
    assert np.isnan(cells_to_raster([], [], **grid)).all()
