"""The df.dggs accessor (dggs.pandas) against the plain functions, on real pandas and GeoPandas frames."""

from __future__ import annotations

import doctest
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

pd = pytest.importorskip("pandas")
gpd = pytest.importorskip("geopandas", reason="the 'pandas' extra (geopandas) is not installed")

import shapely  # noqa: E402
from pyproj import Geod  # noqa: E402
from shapely.geometry import MultiPolygon, Point, Polygon, box  # noqa: E402

import dggs  # noqa: E402
import dggs.pandas  # noqa: E402
from dggs.pandas import ColumnError  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
FORMS = [False, True]  # as_int


def _ids(values, as_int):
    """Plain ids of a column, as Python str or int, for comparisons."""
    return [int(v) for v in values] if as_int else [str(v) for v in values]


@pytest.fixture(scope="module")
def points():
    """Random points on the sphere plus the poles, the antimeridian and points beyond +-180, under shuffled labels."""
    rng = np.random.default_rng(11)
    n = 3000
    lat = np.degrees(np.arcsin(rng.uniform(-1, 1, n)))
    lng = rng.uniform(-180, 180, n)
    special_lat = [90.0, -90.0, 90.0, -90.0, 0.0, 0.0, 45.0, -45.0, 89.9999999, -89.9999999, 10.0, -60.0]
    special_lng = [0.0, 0.0, 123.0, -77.0, 180.0, -180.0, 180.0, -180.0, 179.999999, -179.999999, 540.0, -190.0]
    lat = np.concatenate([lat, special_lat])
    lng = np.concatenate([lng, special_lng])
    labels = [f"r{i}" for i in rng.permutation(lat.shape[0])]
    return pd.DataFrame({"lat": lat, "lng": lng, "pop": rng.integers(0, 1000, lat.shape[0])}, index=labels)


# ---------------------------------------------------------------------------- import


def test_import_dggs_does_not_import_pandas_and_dggs_pandas_registers_the_accessor():
    code = (
        "import sys, dggs\n"
        "assert 'pandas' not in sys.modules and 'geopandas' not in sys.modules, sorted(sys.modules)\n"
        "import pandas as pd\n"
        "assert not hasattr(pd.DataFrame(), 'dggs')\n"
        "import dggs.pandas\n"
        "assert 'geopandas' not in sys.modules\n"
        "assert pd.DataFrame({'lat': [0.0], 'lng': [0.0]}).dggs.latlng_to_cell(2)['cell_2'].tolist() == ['C32']\n"
    )
    subprocess.run([sys.executable, "-c", code], check=True, cwd=ROOT)


def test_doctests():
    import dggs.pandas.join

    for module in (dggs.pandas, dggs.pandas.join):
        result = doctest.testmod(module, optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
        assert result.attempted > 5 and result.failed == 0, module.__name__


def test_docs_pandas_md_python_blocks_run(tmp_path, monkeypatch):
    text = (ROOT / "docs" / "pandas.md").read_text()
    blocks = re.findall(r"^```python\n(.*?)^```", text, re.M | re.S)
    assert len(blocks) >= 3
    monkeypatch.chdir(tmp_path)
    for i, code in enumerate(blocks):
        exec(compile(code, f"docs/pandas.md block {i}", "exec"), {"__name__": "__doc_block__"})  # noqa: S102


# ------------------------------------------------------------------- latlng_to_cell


@pytest.mark.parametrize("as_int", FORMS)
@pytest.mark.parametrize("level", [0, 5, 12, 28])
def test_latlng_to_cell_equals_plain_function(points, level, as_int):
    out = points.dggs.latlng_to_cell(level, as_int=as_int)
    assert out.index.equals(points.index)
    assert list(out.columns) == ["lat", "lng", "pop", f"cell_{level}"]
    pd.testing.assert_frame_equal(out[["lat", "lng", "pop"]], points)
    expected = dggs.latlng_to_cell(points["lat"].to_numpy(), points["lng"].to_numpy(), level, as_int=as_int)
    assert _ids(out[f"cell_{level}"], as_int) == _ids(expected, as_int)
    if as_int:
        assert out[f"cell_{level}"].dtype == np.uint64
    else:
        assert pd.api.types.is_string_dtype(out[f"cell_{level}"].dtype)
    one = points.index[7]
    assert out.loc[one, f"cell_{level}"] == dggs.latlng_to_cell(
        float(points.loc[one, "lat"]), float(points.loc[one, "lng"]), level, as_int=as_int
    )


def test_latlng_to_cell_column_names_and_original_untouched(points):
    frame = points.rename(columns={"lat": "y", "lng": "x"})
    before = frame.copy()
    out = frame.dggs.latlng_to_cell(7, lat="y", lng="x", column="cell")
    pd.testing.assert_frame_equal(frame, before)
    assert "cell" in out and "cell_7" not in out
    assert out["cell"].tolist() == points.dggs.latlng_to_cell(7)["cell_7"].tolist()


def test_latlng_to_cell_of_a_geodataframe_of_points(points):
    gdf = gpd.GeoDataFrame(points[["pop"]], geometry=gpd.points_from_xy(points["lng"], points["lat"]), crs=4326)
    out = gdf.dggs.latlng_to_cell(9)
    assert isinstance(out, gpd.GeoDataFrame) and out.index.equals(points.index)
    assert out["cell_9"].tolist() == points.dggs.latlng_to_cell(9)["cell_9"].tolist()
    with pytest.raises(ColumnError, match="not all points"):
        gpd.GeoDataFrame({"a": [1]}, geometry=[box(0, 0, 1, 1)]).dggs.latlng_to_cell(3)


def test_latlng_to_cell_empty_frame():
    out = pd.DataFrame({"lat": [], "lng": []}, dtype=float).dggs.latlng_to_cell(4, as_int=True)
    assert len(out) == 0 and "cell_4" in out


@pytest.mark.parametrize(
    "lat, lng, error",
    [
        ([10.0, 91.0, 0.0], [0.0, 0.0, 0.0], "latitude 91.0 .*row 'b', column 'lat'"),
        ([10.0, np.nan, 0.0], [0.0, 0.0, 0.0], "row 'b', column 'lat'"),
        ([10.0, 0.0, 0.0], [0.0, 0.0, np.inf], "row 'c', column 'lng'"),
        ([10.0, 0.0, 0.0], [0.0, None, 0.0], "row 'b', column 'lng'"),
        ([10.0, "north", 0.0], [0.0, 0.0, 0.0], "'north' in row 'b'"),
    ],
)
def test_bad_coordinates_raise_coordinate_error_naming_the_row(lat, lng, error):
    frame = pd.DataFrame({"lat": lat, "lng": lng}, index=["a", "b", "c"])
    with pytest.raises(dggs.CoordinateError, match=error):
        frame.dggs.latlng_to_cell(5)


def test_missing_columns_and_bad_level(points):
    with pytest.raises(ColumnError, match="'latitude' is not in the frame") as info:
        points.dggs.latlng_to_cell(5, lat="latitude")
    assert isinstance(info.value, dggs.DggsValueError) and isinstance(info.value, ValueError)
    with pytest.raises(dggs.LevelError):
        points.dggs.latlng_to_cell(29)
    with pytest.raises(ColumnError, match="'nope'"):
        points.dggs.cell_to_geometry(column="nope")
    with pytest.raises(ColumnError, match="'nope'"):
        points.dggs.aggregate(2, column="nope")
    two = points.dggs.latlng_to_cell(5).dggs.latlng_to_cell(6)
    with pytest.raises(ColumnError, match="several cell columns"):
        two.dggs.aggregate(2)


# ----------------------------------------------------------------- cell_to_geometry


@pytest.mark.parametrize("as_int", FORMS)
def test_cell_to_geometry_equals_cell_to_polygon(points, as_int):
    binned = points.dggs.latlng_to_cell(6, as_int=as_int)
    out = binned.dggs.cell_to_geometry()
    assert isinstance(out, gpd.GeoDataFrame) and out.crs.to_epsg() == 4326
    assert out.index.equals(points.index)
    assert list(out.columns) == ["lat", "lng", "pop", "cell_6", "geometry"]
    expected = dggs.cell_to_polygon(binned["cell_6"].to_numpy())
    assert shapely.equals_exact(np.asarray(out.geometry.array, dtype=object), expected, tolerance=0).all()
    assert out.geometry.is_valid.all()
    # cells across the antimeridian are MultiPolygons, as from the plain function
    lng = out.geometry.bounds
    crossing = (lng["minx"] <= -179.0) & (lng["maxx"] >= 179.0) & (out["lat"].abs() < 80)
    assert crossing.any() and (out.geom_type[crossing] == "MultiPolygon").all()


@pytest.mark.parametrize("as_int", FORMS)
def test_cell_to_geometry_from_the_index_and_replacing_a_geometry(as_int):
    cells = dggs.latlng_to_cell(np.array([0.0, 90.0, -90.0, 5.0]), np.array([180.0, 0.0, 0.0, 5.0]), 4, as_int=as_int)
    frame = pd.DataFrame({"v": [1, 2, 3, 4]}, index=pd.Index(cells, name="cell"))
    out = frame.dggs.cell_to_geometry()
    assert out.index.equals(frame.index) and out["v"].tolist() == [1, 2, 3, 4]
    assert shapely.equals_exact(np.asarray(out.geometry.array, dtype=object), dggs.cell_to_polygon(cells), 0).all()
    points = gpd.GeoDataFrame({"cell_4": cells}, geometry=[Point(0, 0)] * 4, crs=4326)
    swapped = points.dggs.cell_to_geometry()
    assert list(swapped.columns) == ["cell_4", "geometry"] and (swapped.geom_type != "Point").all()


def test_cell_to_geometry_areas_equal_cell_area_at_level_5():
    geod = Geod(ellps="WGS84")
    lat = np.array([90.0, -90.0, 0.0, 10.0, -45.0, 60.0, 0.0, 58.2825255885, -26.5650511771])
    lng = np.array([0.0, 0.0, 180.0, -180.0, 179.99, 33.0, 0.0, 11.25, -180.0])
    for as_int in FORMS:
        frame = pd.DataFrame({"lat": lat, "lng": lng}).dggs.latlng_to_cell(5, as_int=as_int)
        out = frame.dggs.cell_to_geometry()
        assert set(out.geom_type) == {"Polygon", "MultiPolygon"}
        for geom in out.geometry:
            area = abs(geod.geometry_area_perimeter(geom)[0])
            assert area == pytest.approx(dggs.cell_area(5), rel=1e-6)


def test_invalid_ids_name_the_row():
    frame = pd.DataFrame({"cell_3": ["C401", "Z999", "C402"]}, index=["p", "q", "r"])
    with pytest.raises(dggs.InvalidCellError, match="row 'q', column 'cell_3'"):
        frame.dggs.cell_to_geometry()
    with pytest.raises(dggs.InvalidCellError, match="row 'q'"):
        frame.dggs.aggregate(1)
    missing = pd.DataFrame({"cell_3": ["C401", None]}, index=["p", "q"])
    with pytest.raises(dggs.InvalidCellError, match="row 'q'"):
        missing.dggs.cell_to_geometry()
    ints = pd.DataFrame({"v": [1]}, index=pd.Index([12345], name="cell"))
    with pytest.raises(dggs.InvalidCellError, match="row 12345, the index"):
        ints.dggs.cell_to_geometry()


# ------------------------------------------------------------------------ aggregate


def _brute_force(cells: list[str], values: list[int], level: int) -> dict[str, tuple[int, int, int]]:
    out: dict[str, list[int]] = {}
    for cell, v in zip(cells, values, strict=True):
        s = out.setdefault(cell[: level + 1], [0, 0, -1])
        s[0] += 1
        s[1] += v
        s[2] = max(s[2], v)
    return {k: (c, t, m) for k, (c, t, m) in out.items()}


@pytest.mark.parametrize("as_int", FORMS)
@pytest.mark.parametrize("level", [0, 3, 6])
def test_aggregate_equals_brute_force_groupby_on_prefixes(points, level, as_int):
    binned = points.dggs.latlng_to_cell(9, as_int=as_int)
    strings = [dggs.int_to_str(int(c)) for c in binned["cell_9"]] if as_int else binned["cell_9"].tolist()
    expected = _brute_force(strings, points["pop"].tolist(), level)

    counted = binned.dggs.aggregate(level)
    assert counted.index.name == f"cell_{level}" and list(counted.columns) == ["count"]
    stats = binned.dggs.aggregate(level, {"pop": ["count", "sum", "max"]})
    assert stats.index.equals(counted.index) and stats.index.is_monotonic_increasing
    keys = [dggs.int_to_str(int(c)) if as_int else c for c in stats.index]
    if as_int:
        assert stats.index.dtype.kind in "iu"
    assert sorted(keys) == sorted(expected)
    for key, (_, row), (_, n) in zip(keys, stats.iterrows(), counted["count"].items(), strict=True):
        assert (row[("pop", "count")], row[("pop", "sum")], row[("pop", "max")]) == expected[key]
        assert n == expected[key][0]


def test_aggregate_chains_and_drops_geometry(points):
    binned = points.dggs.latlng_to_cell(8)
    once = binned.dggs.aggregate(2, {"pop": "sum"}).dggs.aggregate(0, "sum")  # reads the index
    direct = binned.dggs.aggregate(0, {"pop": "sum"})
    pd.testing.assert_frame_equal(once, direct)
    gdf = binned.dggs.cell_to_geometry()
    rolled = gdf.dggs.aggregate(1, {"pop": "sum"})
    assert "geometry" not in rolled and rolled["pop"].sum() == points["pop"].sum()
    drawn = rolled.dggs.cell_to_geometry()
    assert drawn.index.equals(rolled.index) and drawn.geometry.is_valid.all()


def test_aggregate_to_a_finer_level_names_the_row():
    frame = pd.DataFrame({"cell": ["C4012", "C4", "D0000"], "v": [1, 2, 3]}, index=[10, 20, 30])
    with pytest.raises(dggs.LevelMismatchError, match="row 20, column 'cell'"):
        frame.dggs.aggregate(2, column="cell")


# ------------------------------------------------------------------------- polyfill


@pytest.fixture(scope="module")
def features():
    holed = Polygon(box(-30, -30, 30, 30).exterior.coords, [box(-10, -10, 10, 10).exterior.coords])
    split = MultiPolygon([box(170, 50, 180, 60), box(-180, 50, -170, 60)])
    geoms = [
        box(0, 0, 20, 15),
        box(170, -20, 190, -10),  # longitudes beyond 180
        split,  # split at 180
        box(-180, 70, 180, 90),  # north cap
        Polygon([(-180, -90), (180, -90), (180, -75), (-180, -75)]),  # south cap
        holed,
        shapely.Point(3, 3).buffer(0.01),  # no centre inside at level 4
        None,
    ]
    return gpd.GeoDataFrame(
        {"name": list("abcdefgh"), "value": np.arange(8) * 1.5},
        geometry=geoms,
        index=pd.Index([50, 40, 30, 20, 10, 0, -10, -20], name="fid"),
        crs="EPSG:4326",
    )


@pytest.mark.parametrize("as_int", FORMS)
@pytest.mark.parametrize("level", [2, 4])
def test_polyfill_equals_polygon_to_cells_per_feature(features, level, as_int):
    out = features.dggs.polyfill(level, as_int=as_int)
    assert isinstance(out, gpd.GeoDataFrame) and out.index.name == "fid"
    assert list(out.columns) == ["name", "value", "geometry", f"cell_{level}"]
    total = 0
    for fid, row in features.iterrows():
        expected = [] if row.geometry is None else dggs.polygon_to_cells(row.geometry, level, as_int=as_int).tolist()
        got = out.loc[out.index == fid]
        assert _ids(got[f"cell_{level}"], as_int) == _ids(expected, as_int), row["name"]
        assert (got["name"] == row["name"]).all() and (got["value"] == row["value"]).all()
        assert all(g is row.geometry or g.equals(row.geometry) for g in got.geometry)
        total += len(expected)
    assert len(out) == total and total > 0

    lists = features.dggs.polyfill(level, explode=False, as_int=as_int)
    assert lists.index.equals(features.index)
    exploded = out.groupby(level=0, sort=False)[f"cell_{level}"].agg(list)
    for fid, cells in lists[f"cell_{level}"].items():
        assert _ids(cells, as_int) == _ids(exploded.get(fid, []), as_int)


def test_polyfill_covers_the_poles_and_the_antimeridian(features):
    out = features.dggs.polyfill(4)
    north = out.loc[out["name"] == "d", "cell_4"].tolist()
    south = out.loc[out["name"] == "e", "cell_4"].tolist()
    assert dggs.latlng_to_cell(90.0, 0.0, 4) in north and dggs.latlng_to_cell(-90.0, 0.0, 4) in south
    for name in "bc":
        lat, lng = dggs.cell_to_latlng(np.array(out.loc[out["name"] == name, "cell_4"].tolist(), dtype=object))
        assert (lng > 170).any() and (lng < -170).any()
    # the two spellings of a box across 180 fill alike
    across = gpd.GeoDataFrame(geometry=[box(170, 50, 190, 60), features.geometry[30]])
    filled = across.dggs.polyfill(5)
    assert filled.loc[0, "cell_5"].tolist() == filled.loc[1, "cell_5"].tolist()


def test_polyfill_then_cell_to_geometry_gives_the_cells(features):
    tiles = features.dggs.polyfill(3).dggs.cell_to_geometry()
    assert tiles.geometry.is_valid.all()
    expected = dggs.cell_to_polygon(tiles["cell_3"].to_numpy(dtype=object))
    assert shapely.equals_exact(np.asarray(tiles.geometry.array, dtype=object), expected, 0).all()


def test_polyfill_reprojects_another_crs(features):
    mercator = features.iloc[[0, 5]].to_crs("EPSG:3857")
    got = mercator.dggs.polyfill(4)
    expected = [c for g in mercator.to_crs(4326).geometry for c in dggs.polygon_to_cells(g, 4).tolist()]
    assert got["cell_4"].tolist() == expected


def test_polyfill_errors(features, points):
    with pytest.raises(dggs.DggsValueError, match="mode 'overlap'"):
        features.dggs.polyfill(3, mode="overlap")
    with pytest.raises(ColumnError, match="GeoDataFrame"):
        points.dggs.polyfill(3)
    lines = gpd.GeoDataFrame({"a": [1, 2]}, geometry=[box(0, 0, 1, 1), Point(0, 0)], index=["x", "y"])
    with pytest.raises(dggs.DggsValueError, match="row 'y': a Point"):
        lines.dggs.polyfill(3)
    with pytest.raises(dggs.TooManyCellsError, match="row 10"):
        features.loc[[10]].dggs.polyfill(10, max_cells=1000)


# -- sjoin_cells: points to polygon features through their cells ---------------------------------

def _join_fixture():
    rng = np.random.default_rng(11)
    n = 3000
    lat = np.concatenate([np.degrees(np.arcsin(rng.uniform(-1, 1, n))), [90.0, -90.0, 0.0, 0.0, 85.0]])
    lng = np.concatenate([rng.uniform(-180, 180, n), [0.0, 0.0, 180.0, -180.0, 179.99]])
    pts = pd.DataFrame({"lat": lat, "lng": lng, "name": [f"p{i}" for i in range(len(lat))]},
                       index=pd.Index([f"i{i}" for i in range(len(lat))], name="pid"))
    polys = gpd.GeoDataFrame(
        {"name": ["box", "across", "cap", "holed"]},
        geometry=[box(-10, 10, 30, 40), box(170, -20, 190, 20),  # the second crosses the antimeridian
                  box(-180, 75, 180, 90),  # the cap around the north pole
                  Polygon([(-60, -40), (0, -40), (0, 0), (-60, 0)], [[(-40, -30), (-20, -30), (-20, -10), (-40, -10)]])],
        index=pd.Index([10, 20, 30, 40]),
    )
    return pts, polys


@pytest.mark.parametrize("mode", ["center", "contains", "overlaps"])
def test_sjoin_cells_equals_the_plain_functions(mode):
    pts, polys = _join_fixture()
    level = 5
    got = pts.dggs.sjoin_cells(polys, level, mode=mode)
    # brute force with the plain functions: a pair when the point's cell is among the polygon's cells
    cell = dggs.latlng_to_cell(pts["lat"].to_numpy(), pts["lng"].to_numpy(), level)
    want = set()
    for j, geom in zip(polys.index, polys.geometry, strict=True):
        inside = set(dggs.polygon_to_cells(geom, level, mode=mode).tolist())
        want |= {(i, j) for i, c in zip(pts.index, cell, strict=True) if c in inside}
    assert set(zip(got.index, got["index_right"], strict=True)) == want and len(got) == len(want)
    assert got["name"].tolist() == pts.loc[got.index, "name"].tolist()  # this frame's columns, same rows
    assert got["name_right"].tolist() == polys.loc[got["index_right"], "name"].tolist()  # a clash gets the suffix
    assert (got[f"cell_{level}"].to_numpy() == np.asarray(dggs.latlng_to_cell(
        got["lat"].to_numpy(), got["lng"].to_numpy(), level), dtype=object)).all()
    assert list(got.index) == sorted(got.index, key=list(pts.index).index)  # the points' order kept
    # modes bracket the exact join: overlaps misses no point inside, contains joins none outside
    def exact(test):
        return {(i, j) for j, geom in zip(polys.index, polys.geometry, strict=True)
                for i, a, b in zip(pts.index, pts["lat"], pts["lng"], strict=True)
                if test(geom, Point(b, a)) or test(geom, Point(b + 360, a))}

    if mode == "overlaps":
        assert exact(shapely.contains) <= want  # every point strictly inside
    if mode == "contains":
        assert want <= exact(shapely.covers)  # boundary included: the pole is the cap's edge lat = 90 in lng/lat


@pytest.mark.parametrize("as_int", [False, True])
def test_sjoin_cells_through_cells_binned_before_equals_binning_again(as_int):
    pts, polys = _join_fixture()
    binned = pts.dggs.latlng_to_cell(9, column="c9", as_int=as_int)
    binned.loc["i5", "c9"] = dggs.latlng_to_cell(pts.loc["i5", "lat"], pts.loc["i5", "lng"], 5,
                                                 as_int=as_int)  # a cell at the join's level itself
    for how in ("inner", "left"):
        want = pts.dggs.sjoin_cells(polys, 5, how=how)
        got = binned.dggs.sjoin_cells(polys, 5, how=how, cells="c9").drop(columns="c9")
        pd.testing.assert_frame_equal(got, want)
    with pytest.raises(ColumnError, match="'nope'"):
        pts.dggs.sjoin_cells(polys, 5, cells="nope")
    with pytest.raises(dggs.LevelMismatchError, match="parent level 10 is finer than cell"):
        binned.dggs.sjoin_cells(polys, 10, cells="c9").pipe(len)
    bad = binned.assign(c9=binned["c9"].astype(object))
    bad.loc["i3", "c9"] = "Z9" if not as_int else 7
    with pytest.raises(dggs.InvalidCellError):
        bad.dggs.sjoin_cells(polys, 5, cells="c9")


def test_sjoin_cells_left_keeps_every_point_and_checks_arguments():
    pts, polys = _join_fixture()
    left = pts.dggs.sjoin_cells(polys.iloc[:1], 4, how="left", column="c")
    inner = pts.dggs.sjoin_cells(polys.iloc[:1], 4, column="c")
    assert len(left) == len(pts) and list(left.index) == list(pts.index)
    assert left["index_right"].notna().sum() == len(inner)
    with pytest.raises(dggs.DggsValueError, match="how 'outer'"):
        pts.dggs.sjoin_cells(polys, 4, how="outer")
    with pytest.raises(dggs.DggsValueError, match="mode 'near'"):
        pts.dggs.sjoin_cells(polys, 4, mode="near")
    # bad input: a typed error naming the value, never a raw AttributeError
    with pytest.raises(dggs.DggsValueError, match="not a list"):
        pts.dggs.sjoin_cells([box(0, 0, 1, 1)], 4)
    with pytest.raises(ColumnError, match="GeoDataFrame"):
        pts.dggs.sjoin_cells(pd.DataFrame({"x": [1]}), 4)
    with pytest.raises(dggs.DggsValueError, match="row 7: a Point"):
        pts.dggs.sjoin_cells(gpd.GeoDataFrame({"a": [1]}, geometry=[Point(1, 1)], index=[7]), 4)
    with pytest.raises(dggs.LevelError, match="level 29"):
        pts.dggs.sjoin_cells(polys, 29)
    with pytest.raises(dggs.CoordinateError, match="row 'i1', column 'lat'"):
        pts.assign(lat=pts["lat"].where(pts.index != "i1", np.nan)).dggs.sjoin_cells(polys, 4)
    geo_points = gpd.GeoDataFrame({"v": [1]}, geometry=[Point(5.0, 20.0)], crs="EPSG:4326")
    joined = geo_points.dggs.sjoin_cells(polys, 6)
    assert isinstance(joined, gpd.GeoDataFrame) and joined["name"].tolist() == ["box"]


# -- issue 17: coordinates in another CRS, column clashes, typed errors --------------------------

_ENGINEERING = (  # a local engineering CRS: no transformation to WGS84 exists
    'ENGCRS["site grid",EDATUM["site"],CS[Cartesian,2],AXIS["x",east,LENGTHUNIT["metre",1]],'
    'AXIS["y",north,LENGTHUNIT["metre",1]]]'
)


def test_latlng_to_cell_reprojects_points_in_another_crs():
    # 20N 10E in Web Mercator metres, converted by pyproj here (the oracle), not by the accessor
    from pyproj import Transformer

    x, y = Transformer.from_crs(4326, 3857, always_xy=True).transform([10.0, -70.0], [20.0, 45.0])
    gdf = gpd.GeoDataFrame({"v": [1, 2]}, geometry=gpd.points_from_xy(x, y), crs=3857)
    got = gdf.dggs.latlng_to_cell(9)
    assert got["cell_9"].tolist() == dggs.latlng_to_cell([20.0, 45.0], [10.0, -70.0], 9)
    assert got.crs.to_epsg() == 3857 and got.geometry.equals(gdf.geometry)  # the frame's own geometry kept
    # the same points as degrees in another geographic CRS (NAD83 differs from WGS84 by < 2 m)
    nad83 = gpd.GeoDataFrame(geometry=gpd.points_from_xy([10.0, -70.0], [20.0, 45.0]), crs=4269)
    assert nad83.dggs.latlng_to_cell(9)["cell_9"].tolist() == got["cell_9"].tolist()


def test_points_or_polygons_in_a_crs_without_transform_raise_naming_the_crs():
    pts = gpd.GeoDataFrame(geometry=gpd.points_from_xy([10.0], [20.0]), crs=_ENGINEERING)
    with pytest.raises(dggs.pandas.CrsError, match="site grid"):
        pts.dggs.latlng_to_cell(9)
    polys = gpd.GeoDataFrame({"name": ["a"]}, geometry=[box(0, 0, 10, 10)], crs=_ENGINEERING)
    with pytest.raises(dggs.pandas.CrsError, match="site grid"):
        polys.dggs.polyfill(4)
    with pytest.raises(dggs.pandas.CrsError, match="site grid"):
        pd.DataFrame({"lat": [1.0], "lng": [2.0]}).dggs.sjoin_cells(polys, 4)
    assert issubclass(dggs.pandas.CrsError, dggs.DggsValueError)


def test_sjoin_cells_reprojects_projected_points_and_polygons():
    pts, polys = _join_fixture()
    want = pts.dggs.sjoin_cells(polys.iloc[:1], 5)
    geo = gpd.GeoDataFrame(pts[["name"]], geometry=gpd.points_from_xy(pts["lng"], pts["lat"]), crs=4326)
    sel = geo[(geo.geometry.y.abs() < 80)]  # inside Web Mercator's range
    got = sel.to_crs(3857).dggs.sjoin_cells(polys.iloc[:1].set_crs(4326).to_crs(3857), 5)
    assert list(got.index) == [i for i in want.index if i in sel.index]
    assert got["cell_5"].tolist() == want.loc[got.index, "cell_5"].tolist()


def test_sjoin_cells_never_overwrites_a_column_of_either_frame():
    pts = pd.DataFrame({"lat": [5.0, 6.0], "lng": [5.0, 6.0], "name": ["p", "q"], "name_right": ["mine", "too"]})
    polys = gpd.GeoDataFrame({"name": ["box"], "_row": [7]}, geometry=[box(0, 0, 10, 10)], crs=4326)
    # the suffixed name is taken by this frame: refused, naming it (pandas' merge refuses such suffixes too)
    with pytest.raises(dggs.DggsValueError, match="'name_right'"):
        pts.dggs.sjoin_cells(polys, 5)
    got = pts.dggs.sjoin_cells(polys, 5, rsuffix="poly")  # another suffix joins
    assert got["name_right"].tolist() == ["mine", "too"] and got["name"].tolist() == ["p", "q"]
    assert got["name_poly"].tolist() == ["box", "box"] and got["index_poly"].tolist() == [0, 0]
    assert got["_row"].tolist() == [7, 7]  # a polygon column of any name survives the join
    with pytest.raises(dggs.DggsValueError, match="'index_right'"):
        pts.rename(columns={"name_right": "index_right"}).dggs.sjoin_cells(polys, 5)
    # the polygons' own suffixed column clashing with a renamed one is refused too
    with pytest.raises(dggs.DggsValueError, match="'name_right'"):
        pts[["lat", "lng", "name"]].dggs.sjoin_cells(polys.assign(name_right=[1]), 5)


def test_duplicate_columns_raise_column_error_naming_the_column():
    twice = pd.DataFrame([[1.0, 2.0, 3.0]], columns=["lat", "lat", "lng"])
    with pytest.raises(ColumnError, match="'lat' appears 2 times"):
        twice.dggs.latlng_to_cell(3)
    with pytest.raises(ColumnError, match="'lat' appears 2 times"):
        twice.dggs.sjoin_cells(gpd.GeoDataFrame(geometry=[box(0, 0, 1, 1)]), 3)
    cells = pd.DataFrame([["C4012", "C4012", 3.0]], columns=["cell_4", "cell_4", "v"])
    for method in (lambda f: f.dggs.aggregate(2, column="cell_4"), lambda f: f.dggs.cell_to_geometry("cell_4")):
        with pytest.raises(ColumnError, match="'cell_4' appears 2 times"):
            method(cells)


@pytest.mark.parametrize(("agg", "named"), [
    ({"v": "nope"}, "'nope'"),
    ({"zz": "sum"}, "'zz'"),
    ("nope", "'nope'"),
    (["sum", "nope"], "'nope'"),
    ({"v": ["sum", "nope"]}, "'nope'"),
    (3, "3"),
    ({"v": 3}, "3"),
    ({"cell_4": "sum"}, "'cell_4'"),  # the cell column is the key, not a value to aggregate
])
def test_aggregate_with_a_bad_agg_raises_a_typed_error_naming_it(agg, named):
    df = pd.DataFrame({"cell_4": ["C4012", "C4021"], "v": [1, 2]})
    with pytest.raises(dggs.DggsValueError, match=re.escape(named)):
        df.dggs.aggregate(2, agg)


def test_aggregate_good_aggs_still_work():
    df = pd.DataFrame({"cell_4": ["C4012", "C4021", "D0000"], "v": [1, 2, 5], "w": [1.0, 3.0, 5.0]})
    out = df.dggs.aggregate(2, {"v": ["sum", "max"], "w": np.mean})
    assert out[("v", "sum")].tolist() == [3, 5] and out[("w", "mean")].tolist() == [2.0, 5.0]
    assert df.dggs.aggregate(2, "sum")["v"].tolist() == [3, 5]
    assert df.dggs.aggregate(2, ["min", len])[("v", "min")].tolist() == [1, 5]


# -- issue 32 item 11 -------------------------------------------------------------------------------------------


@pytest.mark.parametrize("names", [["k", "n"], [None, None], ["k", None]])
def test_sjoin_cells_keeps_a_multiindex_of_the_polygons_as_geopandas_does(names):
    zones = gpd.GeoDataFrame({"zone": ["west", "east"]}, geometry=[box(0, 0, 20, 50), box(140, -40, 160, -20)],
                             index=pd.MultiIndex.from_tuples([("a", 1), ("b", 2)], names=names), crs="EPSG:4326")
    points = pd.DataFrame({"lat": [5.0, 45.0, -30.0, 70.0], "lng": [5.0, 10.0, 150.0, 100.0]}, index=[7, 8, 9, 6])
    ours = points.dggs.sjoin_cells(zones, 8)
    ref = gpd.sjoin(gpd.GeoDataFrame(points, geometry=gpd.points_from_xy(points.lng, points.lat), crs="EPSG:4326"),
                    zones, predicate="within")
    index_columns = [c for c in ref.columns if c not in points.columns and c not in ("geometry", "zone")]
    assert index_columns == [c for c in ours.columns if c not in points.columns and c not in ("cell_8", "zone")]
    assert ours[index_columns + ["zone"]].sort_index().equals(pd.DataFrame(ref[index_columns + ["zone"]]).sort_index())


@pytest.mark.parametrize("dtype", ["UInt64", "Int64", "uint64[pyarrow]"])
def test_a_missing_id_in_a_nullable_integer_column_is_named_at_its_row(dtype):
    if dtype.endswith("[pyarrow]"):
        pytest.importorskip("pyarrow")
    good = dggs.str_to_int("C401")
    frame = pd.DataFrame({"cell_3": pd.array([good, None, good], dtype=dtype), "x": [1.0, 2.0, 3.0]}, index=[10, 20, 30])
    zones = gpd.GeoDataFrame({"zone": ["all"]}, geometry=[box(-180, -90, 180, 90)], crs="EPSG:4326")
    for call in (lambda: frame.dggs.cell_to_geometry(), lambda: frame.dggs.aggregate(2),
                 lambda: frame.dggs.sjoin_cells(zones, 2, cells="cell_3")):
        with pytest.raises(dggs.InvalidCellError) as info:
            call()
        message = str(info.value)
        assert "row 20" in message and "missing value" in message, message
        assert "e+18" not in message and str(good) not in message, message
    whole = pd.DataFrame({"cell_3": pd.array([good, good], dtype=dtype)}, index=[1, 2])
    assert whole.dggs.aggregate(2)["count"].tolist() == [2]
