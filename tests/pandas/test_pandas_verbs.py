"""Issue 36: the ``df.dggs`` accessor as broad as h3pandas. Each verb against the module-level function on the
same rows (the referee), for string and integer ids, cells at the poles and across the antimeridian included."""

from __future__ import annotations

import numpy as np
import pytest
import shapely

import dggs

pd = pytest.importorskip("pandas")
gpd = pytest.importorskip("geopandas")
import dggs.pandas  # noqa: E402,F401  (registers df.dggs)

CELLS = ["C401", "B100", "A0", "T5", "O311", "A" + "0" * 10, "F2000211"]  # A0/T5: the poles; O311: +-180
INDEX = ["a", "b", "c", "d", "e", "f", "g"]


@pytest.fixture(params=["str", "int"])
def frame(request):
    ids = CELLS if request.param == "str" else [int(i) for i in dggs.str_to_int(CELLS)]
    return pd.DataFrame({"cell_x": ids, "v": np.arange(len(ids), dtype=float)}, index=INDEX)


def _ids(frame):
    return np.asarray(frame["cell_x"].tolist(), dtype=object if isinstance(frame["cell_x"].iloc[0], str) else np.uint64)


def _same(got, want):
    assert [x.item() if isinstance(x, np.generic) else x for x in got] == [x.item() if isinstance(x, np.generic) else x for x in want]


def test_level_face_validity_area_and_centres(frame):
    ids = _ids(frame)
    acc = frame.dggs
    out = acc.get_level(column="cell_x")
    assert out.index.tolist() == INDEX and out["v"].tolist() == frame["v"].tolist()
    _same(out["level"], dggs.get_level(ids))
    _same(acc.get_face(column="cell_x")["face"], dggs.get_face(ids))
    _same(acc.is_valid_cell(column="cell_x")["is_valid"], dggs.is_valid_cell(ids))
    np.testing.assert_array_equal(acc.cell_area(column="cell_x")["cell_area"], dggs.cell_area(ids, "km^2"))
    np.testing.assert_array_equal(acc.cell_area("m^2", column="cell_x")["cell_area"], dggs.cell_area(ids))
    lat, lng = dggs.cell_to_latlng(ids)
    got = acc.cell_to_latlng(column="cell_x")
    np.testing.assert_array_equal(got["lat"], lat)
    np.testing.assert_array_equal(got["lng"], lng)
    points = acc.cell_to_point(column="cell_x")
    assert points.crs.to_epsg() == 4326 and points.index.tolist() == INDEX
    assert shapely.equals_exact(points.geometry.values, shapely.points(np.asarray(lng), np.asarray(lat)), 0).all()


def test_bad_ids_name_the_row():
    df = pd.DataFrame({"cell_x": ["C401", "Z9"]}, index=["ok", "bad"])
    with pytest.raises(dggs.InvalidCellError, match="'bad'"):
        df.dggs.get_level(column="cell_x")
    assert df.dggs.is_valid_cell(column="cell_x")["is_valid"].tolist() == [True, False]  # never raises


def test_parent_and_centre_child(frame):
    ids = _ids(frame)
    acc = frame.dggs
    _same(acc.cell_to_parent(0, column="cell_x")["cell_0"], dggs.cell_to_parent(ids, 0))
    _same(acc.cell_to_parent(column="cell_x")["parent"], [dggs.cell_to_parent(c) for c in ids.tolist()])
    _same(acc.cell_to_center_child(12, column="cell_x")["cell_12"], dggs.cell_to_center_child(ids, 12))
    _same(acc.cell_to_center_child(column="cell_x")["center_child"], [dggs.cell_to_center_child(c) for c in ids.tolist()])
    with pytest.raises(dggs.LevelMismatchError):
        acc.cell_to_parent(9, column="cell_x")


def test_children_explode_each_row(frame):
    ids = _ids(frame)
    out = frame.dggs.cell_to_children(11, column="cell_x")
    want = [dggs.cell_to_children(c, 11) for c in ids.tolist()]
    assert out.index.tolist() == [label for label, w in zip(INDEX, want, strict=True) for _ in w]
    _same(out["cell_11"], [c for w in want for c in w])
    assert out["v"].tolist() == [v for v, w in zip(frame["v"], want, strict=True) for _ in w]


@pytest.mark.parametrize("verb", ["grid_disk", "grid_ring"])
def test_disk_and_ring(frame, verb):
    ids = _ids(frame)
    want = [list(getattr(dggs, verb)(c, 2)) for c in ids.tolist()]
    out = getattr(frame.dggs, verb)(2, column="cell_x")
    assert out.index.tolist() == INDEX
    assert [list(x) for x in out[verb]] == want
    flat = getattr(frame.dggs, verb)(2, column="cell_x", explode=True)
    _same(flat[verb], [c for w in want for c in w])
    assert flat.index.tolist() == [label for label, w in zip(INDEX, want, strict=True) for _ in w]


def test_linetrace_of_lines():
    lines = [shapely.LineString([(170, 10), (-170, 12)]), shapely.LineString([(0, 85), (90, 89.5), (180, 85)]), None]
    g = gpd.GeoDataFrame({"n": [1, 2, 3]}, geometry=lines, crs="EPSG:4326", index=["am", "pole", "none"])
    out = g.dggs.linetrace(6)
    assert out.index.tolist() == ["am", "pole", "none"]
    assert out["cell_6"].tolist() == [list(dggs.line_to_cells(lines[0], 6)), list(dggs.line_to_cells(lines[1], 6)), []]
    flat = g.dggs.linetrace(6, explode=True)
    assert flat["cell_6"].tolist() == out["cell_6"].iloc[0] + out["cell_6"].iloc[1]
    web = g.iloc[:1].to_crs("EPSG:3857")  # reprojected to WGS84 first
    assert web.dggs.linetrace(6)["cell_6"].iloc[0] == out["cell_6"].iloc[0]
    with pytest.raises(dggs.DggsValueError, match="'p'"):
        gpd.GeoDataFrame(geometry=[shapely.Point(0, 0)], index=["p"]).dggs.linetrace(6)


def test_disk_smoothing_spreads_evenly_and_keeps_totals(frame):
    ids = _ids(frame)
    out = frame.dggs.disk_smoothing(1, column="cell_x")
    want: dict = {}
    for c, v in zip(ids.tolist(), frame["v"], strict=True):  # brute force: v / |disk| to each disk cell
        disk = list(dggs.grid_disk(c, 1))
        for d in disk:
            want[d] = want.get(d, 0.0) + v / len(disk)
    assert sorted(out.index.tolist()) == sorted(want)
    np.testing.assert_allclose([out.loc[c, "v"] for c in want], list(want.values()))
    assert out["v"].sum() == pytest.approx(frame["v"].sum())


def test_resample_down_splits_and_up_aggregates():
    df = pd.DataFrame({"cell_3": ["C401", "O311"], "pop": [9.0, 6.0], "density": [2.0, 5.0]})
    down = df.dggs.resample(5, divide=["pop"])
    kids = [dggs.cell_to_children(c, 5) for c in df["cell_3"]]
    assert down.index.name == "cell_5" and down.index.tolist() == [c for k in kids for c in k]
    np.testing.assert_allclose(down["pop"], [p / len(k) for p, k in zip(df["pop"], kids, strict=True) for _ in k])
    assert down["density"].tolist() == [d for d, k in zip(df["density"], kids, strict=True) for _ in k]
    assert down["pop"].sum() == pytest.approx(15.0)
    up = df.dggs.resample(1, {"pop": "sum"})
    parents = dggs.cell_to_parent(np.asarray(df["cell_3"]), 1)
    assert up.index.tolist() == sorted(set(parents.tolist())) and up["pop"].sum() == 15.0
    mixed = pd.DataFrame({"cell": ["C4", "C4012"]})
    with pytest.raises(dggs.LevelError):
        mixed.dggs.resample(3, column="cell")
