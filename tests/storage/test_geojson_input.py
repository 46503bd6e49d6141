"""GeoJSON input (issue 17, items 3, 14 and 18): malformed geometry is a bad row, nested properties are JSON text.

RFC 7946, section 3.1.1: a position is an array of two or more numbers; section 3.1.2 onwards: a Point's
coordinates are one position, a MultiPoint's an array of positions, a Polygon's an array of linear rings
(arrays of positions), a MultiPolygon's an array of those.  JSON strings, booleans and objects are none
of these, and must never be read as coordinates.
"""

from __future__ import annotations

import json
import warnings

import pytest
from click.testing import CliRunner

from dggs.cli import main
from dggs.storage import BadRowError, CellStore

GOOD = {"type": "Point", "coordinates": [2.35, 48.85]}
RING = [[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0], [0.0, 0.0]]  # holds cell centres at level 5

#: Geometries that are not GeoJSON, each of which must be one rejected row, never a stored point.
MALFORMED = {
    "point as a string": {"type": "Point", "coordinates": "45"},
    "point of strings": {"type": "Point", "coordinates": ["1", "2"]},
    "point of booleans": {"type": "Point", "coordinates": [True, False]},
    "point as an object": {"type": "Point", "coordinates": {"a": 1}},
    "point of one number": {"type": "Point", "coordinates": [1.0]},
    "empty point": {"type": "Point", "coordinates": []},
    "point nested once more": {"type": "Point", "coordinates": [[1.0, 2.0]]},
    "point with a string altitude": {"type": "Point", "coordinates": [1.0, 2.0, "x"]},
    "point without coordinates": {"type": "Point"},
    "multipoint of strings": {"type": "MultiPoint", "coordinates": ["12", "34"]},
    "empty multipoint": {"type": "MultiPoint", "coordinates": []},
    "multipoint with a boolean": {"type": "MultiPoint", "coordinates": [[1.0, 1.0], [1.0, True]]},
    "multipoint as an object": {"type": "MultiPoint", "coordinates": {"a": 1}},
    "multipoint as a string": {"type": "MultiPoint", "coordinates": "12"},
    "polygon as a string": {"type": "Polygon", "coordinates": "abc"},
    "polygon as an object": {"type": "Polygon", "coordinates": {"a": 1}},
    "polygon with a boolean": {"type": "Polygon", "coordinates": [[*RING[:2], [1.0, True], *RING[3:]]]},
    "polygon of strings": {"type": "Polygon", "coordinates": [[["0", "0"], ["1", "0"], ["1", "1"], ["0", "0"]]]},
    "polygon one level short": {"type": "Polygon", "coordinates": RING},
    "multipolygon of a string": {"type": "MultiPolygon", "coordinates": [[["x"]]]},
    "multipolygon as an object": {"type": "MultiPolygon", "coordinates": {"a": 1}},
    "geometry as a list": [1, 2],
}


def _write(path, geometries):
    features = [{"type": "Feature", "geometry": GOOD, "properties": {"n": 0}}]
    features += [{"type": "Feature", "geometry": g, "properties": {"n": i + 1}} for i, g in enumerate(geometries)]
    path.write_text(json.dumps({"type": "FeatureCollection", "features": features}))
    return path


@pytest.mark.parametrize("name", list(MALFORMED))
def test_each_malformed_geometry_is_one_bad_row(tmp_path, name):
    path = _write(tmp_path / "m.geojson", [MALFORMED[name]])
    with CellStore() as store:
        with pytest.raises(BadRowError, match="row 2"):
            store.ingest_geojson(path, level=5)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            result = store.ingest_geojson(path, level=5, on_error="skip")
        assert (result.rows_inserted, result.rows_rejected) == (1, 1), name
        assert [(r["lat"], r["lng"], r["n"]) for r in store.db.query("SELECT lat, lng, n FROM all_points")] == [
            (48.85, 2.35, 0)
        ]


def test_all_malformed_geometries_at_once_are_each_counted(tmp_path):
    path = _write(tmp_path / "m.geojson", list(MALFORMED.values()))
    with CellStore() as store, warnings.catch_warnings():
        warnings.simplefilter("ignore")
        result = store.ingest_geojson(path, level=5, on_error="skip", batch_size=4)
        assert (result.rows_inserted, result.rows_rejected) == (1, len(MALFORMED))
        assert store.count() == 1


def test_an_integer_too_large_for_a_float_is_a_bad_row(tmp_path):
    path = tmp_path / "big.geojson"
    path.write_text('{"type": "Feature", "properties": {}, "geometry": {"type": "Point", "coordinates": [1'
                    + "0" * 400 + ", 1]}}")
    with CellStore() as store:
        with pytest.raises(BadRowError, match="row 1"):
            store.ingest_geojson(path, level=5)


def test_valid_geometries_still_read(tmp_path):
    square = [[10.0, 10.0], [14.0, 10.0], [14.0, 14.0], [10.0, 14.0], [10.0, 10.0]]
    geometries = [
        {"type": "Point", "coordinates": [1, 2, 30.5]},  # integers and an altitude
        {"type": "MultiPoint", "coordinates": [[3.0, 4.0], [5, 6]]},
        {"type": "Polygon", "coordinates": [square]},
        {"type": "MultiPolygon", "coordinates": [[square]]},
    ]
    path = _write(tmp_path / "ok.geojson", geometries)
    with CellStore() as store:
        result = store.ingest_geojson(path, level=5)
        assert result.rows_rejected == 0
        points = sorted((r["n"], r["lat"], r["lng"]) for r in store.db.query("SELECT n, lat, lng FROM all_points"))
        assert points[:4] == [(0, 48.85, 2.35), (1, 2.0, 1.0), (2, 4.0, 3.0), (2, 6.0, 5.0)]
        assert {n for n, _, _ in points} == {0, 1, 2, 3, 4}


@pytest.mark.parametrize("skip", [False, True])
def test_cli_coordinates_as_an_object_is_one_line(tmp_path, skip):
    path = _write(tmp_path / "o.geojson", [{"type": "Point", "coordinates": {"a": 1}}])
    args = ["bin", str(path), "--db", str(tmp_path / "o.db"), "--level", "5"]
    result = CliRunner().invoke(main, args + (["--on-error", "skip"] if skip else []))
    assert result.exception is None or isinstance(result.exception, SystemExit), result.exception
    assert "Traceback" not in result.output
    if skip:
        assert result.exit_code == 0, result.output
        assert "skipped 1 bad row" in result.output
        with CellStore(tmp_path / "o.db", readonly=True) as store:
            assert store.count() == 1
    else:
        assert result.exit_code == 1 and result.output.count("\n") == 1, result.output
        assert "row 2" in result.output


def test_nested_properties_are_stored_as_json_text(tmp_path):
    nested = [{"a": [1, 2]}, [1, "x", None, True], {"é": {"deep": 1.5}}, "plain", None]
    path = tmp_path / "n.geojson"
    path.write_text(json.dumps({"type": "FeatureCollection", "features": [
        {"type": "Feature", "geometry": {"type": "Point", "coordinates": [i, i]}, "properties": {"n": i, "p": p}}
        for i, p in enumerate(nested)]}))
    with CellStore() as store:
        store.ingest_geojson(path, level=5)
        assert store.columns["p"] == "TEXT"
        stored = {r["n"]: r["p"] for r in store.db.query("SELECT n, p FROM all_points")}
    assert stored == {0: '{"a": [1, 2]}', 1: '[1, "x", null, true]', 2: '{"é": {"deep": 1.5}}', 3: "plain", 4: None}
    assert [json.loads(stored[i]) for i in range(3)] == nested[:3]
