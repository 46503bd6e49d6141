"""feature_collection (orjson, geometry text as fragments) against the same document built with the json module."""

from __future__ import annotations

import json
import math

import numpy as np
import shapely
from hypothesis import example, given, settings
from hypothesis import strategies as st

import dggs
from dggs.server.geojson import clean, feature_collection

from ..strategies import examples, special_points

_SCALARS = (
    st.none()
    | st.booleans()
    | st.integers(min_value=-(2**63), max_value=2**64 - 1)
    | st.floats(allow_nan=True, allow_infinity=True)
    | st.text(max_size=12)
)
_VALUES = st.recursive(_SCALARS, lambda inner: st.lists(inner, max_size=3) | st.dictionaries(st.text(max_size=5), inner, max_size=3),
                       max_leaves=6)
_PROPS = st.dictionaries(st.text(max_size=8), _VALUES, max_size=4)
_IDS = st.one_of(st.text(min_size=1, max_size=10), st.integers(min_value=0, max_value=2**64 - 1))


def _cleaned(value):
    """NaN and infinities as null, at any depth (what JSON can hold)."""
    if isinstance(value, float) and not math.isfinite(value):
        return None
    if isinstance(value, dict):
        return {k: _cleaned(v) for k, v in value.items()}
    if isinstance(value, list):
        return [_cleaned(v) for v in value]
    return value


def _reference(ids, texts, props, extra):
    """The document the json module gives, the geometry text parsed."""
    features = [{"type": "Feature", "id": i, "geometry": json.loads(g), "properties": _cleaned(p)}
                for i, g, p in zip(ids, texts, props, strict=True)]
    return {"type": "FeatureCollection", "features": features, **_cleaned(extra)}


_CELLS = sorted({str(dggs.latlng_to_cell(lat, lng, 4)) for lat, lng in special_points()})
_TEXTS = [str(t) for t in shapely.to_geojson(np.asarray(dggs.cell_to_polygon(np.array(_CELLS), 2), dtype=object))]


@settings(max_examples=examples(100), deadline=None)
@given(st.lists(st.tuples(_IDS, st.sampled_from(range(len(_TEXTS))), _PROPS), max_size=6),
       st.dictionaries(st.text(max_size=8).filter(lambda k: k not in ("type", "features")), _VALUES, max_size=3))
@example([("A", 0, {"n": 1, "name": "Zürich ☃", "nan": float("nan")})], {"numberReturned": 1})
@example([(2**64 - 1, 1, {})], {"links": [{"rel": "next", "href": "/zones?offset=1"}]})
@example([], {"numberReturned": 0})
def test_the_document_is_the_json_modules(rows, extra):
    ids = [r[0] for r in rows]
    texts = [_TEXTS[r[1]] for r in rows]
    props = [r[2] for r in rows]
    text = feature_collection(ids, texts, props, extra)
    assert isinstance(text, str)
    assert json.loads(text) == _reference(ids, texts, props, extra)


def test_geometry_text_goes_in_as_it_is():
    # the pole and antimeridian cells' text, every digit of every coordinate, appears unchanged
    text = feature_collection(_CELLS, _TEXTS, [{} for _ in _CELLS], {})
    for geometry in _TEXTS:
        assert f'"geometry":{geometry},' in text


def test_numpy_scalars_are_numbers_and_cleaned_nan_is_null():
    props = [{"count": np.int64(3), "value": np.float64(2.5), "mean": clean(np.float64("nan"))}]
    doc = json.loads(feature_collection(["A"], [_TEXTS[0]], props, {"numberReturned": np.int64(1)}))
    assert doc["features"][0]["properties"] == {"count": 3, "value": 2.5, "mean": None}
    assert doc["numberReturned"] == 1


def test_keys_that_are_not_strings_are_written_as_the_json_module_writes_them():
    props = [{1: "a", 2.5: "b", None: "c", False: "d"}]
    doc = json.loads(feature_collection(["A"], [_TEXTS[0]], props, {}))
    assert doc["features"][0]["properties"] == json.loads(json.dumps(props[0]))
