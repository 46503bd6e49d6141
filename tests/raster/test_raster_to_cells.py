"""``dggs.raster.raster_to_cells`` against referees no one here wrote (issue 19).

* mass: ``"sum"`` of counts gives back the raster's total, of densities its
  integral (value x pixel area, pixel areas from pyproj.Geod);
* ``"mean"``: a brute-force oracle, every pixel cut into sub-pixels weighted by
  their own geodesic area and given to the cell of their centre;
* exactextract's coverage fractions of the same cells drawn as polygons, in an
  equal-area CRS where the two definitions agree;
* rasters in EPSG:4326, EPSG:3857 and a polar stereographic CRS, nodata, a
  1-pixel raster, a raster inside one cell, and bad input.
"""

from __future__ import annotations

import numpy as np
import pyproj
import pytest

pytest.importorskip("rasterio")
import rasterio  # noqa: E402
from rasterio.transform import from_origin  # noqa: E402

import dggs  # noqa: E402
from dggs.raster import MODES, RasterError, raster_to_cells  # noqa: E402

GEOD = pyproj.Geod(ellps="WGS84")


def write(path, data, crs="EPSG:4326", transform=None, nodata=None):
    data = np.asarray(data)
    if data.ndim == 2:
        data = data[None]
    transform = transform or from_origin(10.0, 50.0, 0.1, 0.1)
    with rasterio.open(path, "w", driver="GTiff", height=data.shape[1], width=data.shape[2], count=data.shape[0],
                       dtype=data.dtype, crs=crs, transform=transform, nodata=nodata) as dst:
        dst.write(data)
    return path


def pixel_areas(transform, rows, cols, crs="EPSG:4326", n=64):
    """Each pixel's geodesic area (its edges drawn with n points in the raster's CRS, through pyproj)."""
    to = pyproj.Transformer.from_crs(crs, "EPSG:4326", always_xy=True)
    t = np.linspace(0, 1, n, endpoint=False)
    dr = np.concatenate([0 * t, t, 1 + 0 * t, 1 - t])
    dc = np.concatenate([t, 1 + 0 * t, 1 - t, 0 * t])
    out = np.empty((rows, cols))
    for r in range(rows):
        for c in range(cols):
            x, y = transform @ (c + dc, r + dr)
            lng, lat = to.transform(x, y)
            out[r, c] = abs(GEOD.polygon_area_perimeter(lng, lat)[0])
    return out


@pytest.mark.parametrize("level", [4, 7, 11])
def test_sum_of_counts_and_of_densities_is_the_rasters_total(tmp_path, level):
    rng = np.random.default_rng(level)
    data = rng.random((12, 17)) * 100
    data[0, :3] = -1.0
    path = write(tmp_path / "r.tif", data, nodata=-1.0)
    valid = data != -1.0
    counts = raster_to_cells(path, level, mode="sum")
    assert abs(counts["value"].sum() / data[valid].sum() - 1) < 1e-12
    density = raster_to_cells(path, level, mode="sum", density=True)
    integral = (data * pixel_areas(from_origin(10.0, 50.0, 0.1, 0.1), 12, 17))[valid].sum()
    assert abs(density["value"].sum() / integral - 1) < 1e-7
    assert (counts["cell_id"].diff().dropna() > 0).all() and (dggs.get_level(counts["cell_id"].to_numpy()) == level).all()


def test_a_global_rasters_integral_to_1e_9(tmp_path):
    """Densities times area over the whole globe against the exact areas of lat/lng pixels on the ellipsoid
    (R² dλ (sin β₁ - sin β₂), β the authalic latitude from pyproj's ellipsoid, not dggs's series)."""
    rng = np.random.default_rng(4)
    d = 3.0
    data = rng.random((60, 120))
    path = write(tmp_path / "globe.tif", data, transform=from_origin(-180.0, 90.0, d, d))
    table = raster_to_cells(path, 4, mode="sum", density=True)
    ellps = pyproj.Geod(ellps="WGS84")
    e2 = ellps.es
    q = lambda phi: (1 - e2) * (np.sin(phi) / (1 - e2 * np.sin(phi) ** 2)  # noqa: E731 - Snyder 1987 eq. 3-12
                                - np.log((1 - np.sqrt(e2) * np.sin(phi)) / (1 + np.sqrt(e2) * np.sin(phi)))
                                / (2 * np.sqrt(e2)))
    edges = np.radians(90.0 - d * np.arange(61))
    rows = ellps.a**2 / 2 * np.radians(d) * np.abs(q(edges[:-1]) - q(edges[1:]))  # each row's pixel area
    integral = (data * rows[:, None]).sum()
    assert abs(table["value"].sum() / integral - 1) < 1e-9


def test_mean_matches_a_supersampled_oracle(tmp_path):
    rng = np.random.default_rng(5)
    data = rng.random((6, 8)) * 10
    t = from_origin(-3.3, 41.7, 0.25, 0.25)
    path = write(tmp_path / "m.tif", data, transform=t)
    level = 8
    got = raster_to_cells(path, level, mode="mean").set_index("cell_id")
    n = 60  # sub-pixels a side, each weighted by its own geodesic area, given to the cell of its centre
    sub = from_origin(-3.3, 41.7, 0.25 / n, 0.25 / n)
    areas = pixel_areas(sub, 6 * n, 8 * n, n=2)
    rows, cols = np.mgrid[0 : 6 * n, 0 : 8 * n]
    x, y = sub @ (cols + 0.5, rows + 0.5)
    ids = dggs.latlng_to_cell(y.ravel(), x.ravel(), level, as_int=True).astype(np.int64)
    vals = data[rows // n, cols // n].ravel()
    weight = areas.ravel()
    errors = []
    for cell, row in got.iterrows():
        sel = ids == cell
        want = (vals[sel] * weight[sel]).sum() / weight[sel].sum()
        errors.append(abs(row["value"] - want))
    assert max(errors) < 0.05 and np.mean(errors) < 0.01  # the oracle's own error: O(1/n) at the cells' edges
    assert set(np.unique(ids).tolist()) == set(got.index.tolist())


@pytest.mark.parametrize("crs, transform", [
    ("EPSG:3857", from_origin(1.0e6, 6.5e6, 5000.0, 5000.0)),
    ("EPSG:3413", from_origin(-2.0e5, 3.0e5, 10000.0, 10000.0)),  # polar stereographic north, round the pole
    ("EPSG:4326", from_origin(175.0, -10.0, 0.5, 0.5)),  # across the antimeridian
])
def test_any_crs_conserves_mass_and_covers_what_it_should(tmp_path, crs, transform):
    rng = np.random.default_rng(1)
    data = rng.random((30, 24))
    path = write(tmp_path / "c.tif", data, crs=crs, transform=transform)
    table = raster_to_cells(path, 6, mode="sum", density=True)
    integral = (data * pixel_areas(transform, 30, 24, crs=crs, n=16)).sum()
    assert abs(table["value"].sum() / integral - 1) < 1e-6
    assert ((table["coverage"] > 0) & (table["coverage"] <= 1.0)).all()
    mean = raster_to_cells(path, 6, mode="mean")
    assert mean["value"].between(data.min(), data.max()).all()


def test_modes_min_max_count_mode_fractions_and_center(tmp_path):
    data = np.array([[1, 1, 2, 2], [1, 3, 3, 2], [4, 4, 4, 4]], dtype=np.int16)
    path = write(tmp_path / "k.tif", data, transform=from_origin(20.0, 10.0, 0.05, 0.05))
    level = 9
    frac = raster_to_cells(path, level, mode="fractions")
    shares = frac.filter(like="class_")
    assert list(shares.columns) == ["class_1", "class_2", "class_3", "class_4"]
    assert np.allclose(shares.sum(axis=1), 1.0)
    mode = raster_to_cells(path, level, mode="mode").set_index("cell_id")["value"]
    assert (mode == shares.set_axis(frac["cell_id"]).idxmax(axis=1).str[6:].astype(int)).all()
    low = raster_to_cells(path, level, mode="min").set_index("cell_id")["value"]
    high = raster_to_cells(path, level, mode="max").set_index("cell_id")["value"]
    count = raster_to_cells(path, level, mode="count").set_index("cell_id")["value"]
    assert (low <= high).all() and count.sum() >= data.size and (count >= 1).all()
    centre = raster_to_cells(path, level, mode="center", as_str=True)
    assert "coverage" not in centre and set(centre["value"].unique()) <= {1, 2, 3, 4}
    lat, lng = dggs.cell_to_latlng(centre["cell"].tolist())
    rows = np.floor((10.0 - np.asarray(lat)) / 0.05).astype(int)
    cols = np.floor((np.asarray(lng) - 20.0) / 0.05).astype(int)
    assert (centre["value"].to_numpy() == data[rows, cols]).all()  # the pixel under each centre


def test_nodata_partly_covered_cells_and_fully_masked_cells(tmp_path):
    data = np.ones((20, 20), dtype=np.float32)
    data[:, :10] = np.nan
    path = write(tmp_path / "n.tif", data, transform=from_origin(0.0, 1.0, 0.05, 0.05))
    table = raster_to_cells(path, 6, mode="mean")
    assert np.allclose(table["value"], 1.0) and (table["coverage"] < 1).all()
    whole = raster_to_cells(write(tmp_path / "w.tif", np.ones((20, 20), np.float32),
                                  transform=from_origin(0.0, 1.0, 0.05, 0.05)), 6, mode="sum", density=True)
    half = raster_to_cells(path, 6, mode="sum", density=True)
    assert 0.45 < half["value"].sum() / whole["value"].sum() < 0.55
    empty = raster_to_cells(write(tmp_path / "e.tif", np.full((3, 3), -5.0), nodata=-5.0), 6)
    assert len(empty) == 0 and list(empty.columns) == ["cell_id", "value", "coverage"]


def test_one_pixel_and_a_raster_inside_one_cell(tmp_path):
    one = write(tmp_path / "1.tif", np.array([[7.0]]), transform=from_origin(30.0, 20.0, 2.0, 2.0))
    cells = raster_to_cells(one, 8, mode="sum")
    assert abs(cells["value"].sum() - 7.0) < 1e-12 and len(cells) > 10
    tiny = write(tmp_path / "t.tif", np.arange(4.0).reshape(2, 2), transform=from_origin(30.001, 20.001, 1e-4, 1e-4))
    inside = raster_to_cells(tiny, 3, mode="mean")
    assert len(inside) == 1 and abs(inside["value"].iloc[0] - 1.5) < 1e-6
    assert inside["coverage"].iloc[0] < 1e-6


def test_multiple_bands_one_column_each(tmp_path):
    data = np.stack([np.full((4, 4), 1.0), np.full((4, 4), 2.0), np.full((4, 4), 3.0)])
    path = write(tmp_path / "b.tif", data)
    table = raster_to_cells(path, 7, mode="mean", band=[1, 3])
    assert list(table.columns) == ["cell_id", "band_1", "band_3", "coverage"]
    assert np.allclose(table["band_1"], 1.0) and np.allclose(table["band_3"], 3.0)


def test_xarray_input_equals_the_file(tmp_path):
    rioxarray = pytest.importorskip("rioxarray")
    data = np.random.default_rng(2).random((8, 9))
    path = write(tmp_path / "x.tif", data)
    array = rioxarray.open_rasterio(path)
    assert raster_to_cells(array, 8).equals(raster_to_cells(path, 8))
    assert raster_to_cells(array.sel(band=1), 8, mode="center").equals(raster_to_cells(path, 8, mode="center"))


def test_bad_input_is_a_typed_error_naming_it(tmp_path):
    good = write(tmp_path / "g.tif", np.ones((2, 2)))
    with pytest.raises(RasterError, match="no raster file"):
        raster_to_cells(tmp_path / "missing.tif", 5)
    (tmp_path / "junk.tif").write_bytes(b"not a tiff at all")
    with pytest.raises(RasterError, match="junk.tif is not a raster"):
        raster_to_cells(tmp_path / "junk.tif", 5)
    (tmp_path / "text.csv").write_text("a,b\n1,2\n")
    with pytest.raises(RasterError, match="not a raster|no CRS"):
        raster_to_cells(tmp_path / "text.csv", 5)
    nocrs = tmp_path / "nocrs.tif"
    with rasterio.open(nocrs, "w", driver="GTiff", height=2, width=2, count=1, dtype="float64") as dst:
        dst.write(np.ones((1, 2, 2)))
    with pytest.raises(RasterError, match="no CRS"):
        raster_to_cells(nocrs, 5)
    with pytest.raises(RasterError, match="band 2 is out of range"):
        raster_to_cells(good, 5, band=2)
    with pytest.raises(RasterError, match="outside"):
        raster_to_cells(good, 5, window=(0, 0, 3, 3))
    with pytest.raises(dggs.LevelError):
        raster_to_cells(good, 29)
    with pytest.raises(dggs.DggsValueError, match="mode 'median'"):
        raster_to_cells(good, 5, mode="median")
    with pytest.raises(RasterError, match="file path or an xarray"):
        raster_to_cells(np.ones((2, 2)), 5)
    assert set(MODES) == {"center", "mean", "sum", "min", "max", "count", "mode", "fractions"}


def test_mean_and_coverage_agree_with_exactextract_in_an_equal_area_crs(tmp_path):
    """exactextract weighs a pixel by the share of its planar area a polygon covers; in an equal-area CRS
    that is the share of its true area, our definition.  The cells go to it as polygons (cell_to_polygon,
    dense, put in the raster's CRS); what differs is only their drawing (chords, well below 1e-4)."""
    exactextract = pytest.importorskip("exactextract")
    gpd = pytest.importorskip("geopandas")
    rng = np.random.default_rng(9)
    data = rng.random((40, 50)) * 100
    crs = "EPSG:3035"  # Lambert azimuthal equal-area, Europe
    transform = from_origin(4.0e6, 3.0e6, 2000.0, 2000.0)
    path = write(tmp_path / "ea.tif", data, crs=crs, transform=transform)
    level = 11
    ours = raster_to_cells(path, level, mode="mean")
    inside = ours[ours["coverage"] > 0.999].head(60)  # whole cells, and some at the edges below
    edge = ours[(ours["coverage"] > 0.05) & (ours["coverage"] < 0.95)].head(30)
    picked = inside._append(edge) if hasattr(inside, "_append") else inside
    cells = picked["cell_id"].to_numpy().astype(np.uint64)
    shapes = gpd.GeoDataFrame(geometry=dggs.cell_to_polygon(cells, densify=64), crs="EPSG:4326").to_crs(crs)
    theirs = exactextract.exact_extract(str(path), shapes, ["mean", "count"], output="pandas")
    merged = picked.reset_index(drop=True).join(theirs)  # one row a feature, in order
    assert len(merged) == len(picked) and merged["mean"].notna().all()
    assert np.allclose(merged["value"], merged["mean"], rtol=0, atol=1e-3)
    cell_pixels = dggs.cell_area(level, "m^2") / 2000.0**2
    assert np.allclose(merged["coverage"], merged["count"] / cell_pixels, rtol=0, atol=1e-4)
