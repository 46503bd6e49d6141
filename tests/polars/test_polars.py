"""Issue 36: polars. ``dggs.polars``'s expression and Series namespaces against the module-level functions.

The referee for each verb is the module-level function on the same rows as numpy; the polars columns must
hold the same values, in lazy queries too, with the output types the expressions declare.
"""

from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest
import shapely

import dggs

pl = pytest.importorskip("polars")
import dggs.polars  # noqa: E402  (registers the namespaces)

# the poles' cells, cells split at the antimeridian, level 0 and the deepest level
CELLS = ["C401", "B100", "A0", "T5", "O311", "A" + "0" * 10, "T5" + "2" * 27]
INTS = [int(i) for i in dggs.str_to_int(CELLS)]

# verb -> (arguments, the module-level call on a numpy array giving the reference)
CASES = {
    "str_to_int": ((), lambda c: dggs.str_to_int(dggs.int_to_str(c))),
    "int_to_str": ((), lambda c: dggs.int_to_str(dggs.str_to_int(c))),
    "is_valid_cell": ((), dggs.is_valid_cell),
    "get_level": ((), dggs.get_level),
    "get_face": ((), dggs.get_face),
    "cell_area": (("km^2",), lambda c: dggs.cell_area(c, "km^2")),
    "cell_to_parent": ((0,), lambda c: dggs.cell_to_parent(c, 0)),
    "cell_to_center_child": ((None,), lambda c: [dggs.cell_to_center_child(x) for x in c.tolist()]),  # one down each
    "cell_to_latlng": ((), dggs.cell_to_latlng),
    "cell_to_polygon": ((2,), lambda c: dggs.cell_to_polygon(c, 2)),
    "grid_disk": ((1,), lambda c: dggs.grid_disk(c, 1)),
    "grid_ring": ((1,), lambda c: dggs.grid_ring(c, 1)),
}


def _deep_ok(verb):  # the deepest cell has no centre child
    return [c for c in CELLS if verb != "cell_to_center_child" or dggs.get_level(c) < 28]  # the deepest has none


def _expected(verb, cells):
    args, ref = CASES[verb]
    want = ref(np.asarray(cells))
    if verb == "cell_to_latlng":
        return [{"lat": float(a), "lng": float(b)} for a, b in zip(*want, strict=True)]
    if verb == "cell_to_polygon":
        return list(want)
    if verb == "cell_to_center_child":
        return list(want)
    if verb in ("grid_disk", "grid_ring"):
        return [[x for x in row.tolist() if x not in ("", 0)] for row in want]
    return np.asarray(want).tolist()


def _compare(verb, got, want):
    if verb == "cell_to_polygon":
        assert shapely.equals_exact(shapely.from_wkb(got), np.asarray(want, dtype=object), 0).all()
    else:
        assert got == want


@pytest.mark.parametrize("form", ["str", "int"])
@pytest.mark.parametrize("lazy", [False, True], ids=["eager", "lazy"])
@pytest.mark.parametrize("verb", sorted(CASES))
def test_each_expression_verb_matches_the_module_function(verb, lazy, form):
    cells = _deep_ok(verb)
    col = pl.Series("cell", cells) if form == "str" else pl.Series("cell", dggs.str_to_int(cells), dtype=pl.UInt64)
    frame = pl.DataFrame({"cell": col, "n": range(len(cells))})
    query = (frame.lazy() if lazy else frame).with_columns(getattr(pl.col("cell").dggs, verb)(*CASES[verb][0]).alias("out"))
    schema = query.collect_schema() if lazy else None
    out = query.collect() if lazy else query
    if schema is not None:
        assert schema["out"] == out.schema["out"], verb  # the declared type is the one computed
    given = cells if form == "str" else [int(i) for i in dggs.str_to_int(cells)]
    _compare(verb, out["out"].to_list(), _expected(verb, given))
    assert out["cell"].to_list() == col.to_list() and out["n"].to_list() == list(range(len(cells)))


@pytest.mark.parametrize("verb", sorted(CASES))
def test_the_series_namespace_is_the_same(verb):
    cells = _deep_ok(verb)
    got = getattr(pl.Series("cell", cells).dggs, verb)(*CASES[verb][0])
    assert isinstance(got, pl.Series)
    _compare(verb, got.to_list(), _expected(verb, cells))


def test_id_outputs_keep_the_input_type_and_name():
    for col in (pl.Series("c", CELLS), pl.Series("c", INTS, dtype=pl.UInt64), pl.Series("c", INTS, dtype=pl.Int64),
                pl.Series("c", CELLS, dtype=pl.Categorical)):
        out = pl.DataFrame({"c": col}).select(pl.col("c").dggs.cell_to_parent(0))["c"]
        assert out.dtype == col.dtype and out.to_list() == pl.Series(dggs.cell_to_parent(col.to_numpy(), 0)).cast(col.dtype).to_list()
        plain = dggs.cell_to_parent(col, 0)  # polars in, polars out, without the namespace
        assert isinstance(plain, pl.Series) and plain.name == "c" and plain.to_list() == out.to_list()


def test_latlng_to_cell_of_two_columns():
    rng = np.random.default_rng(36)
    lat = np.concatenate([np.degrees(np.arcsin(rng.uniform(-1, 1, 200))), [90.0, -90.0, 0.0, 10.0]])
    lng = np.concatenate([rng.uniform(-180, 180, 200), [0.0, 45.0, 180.0, -180.0]])
    frame = pl.DataFrame({"y": lat, "x": lng})
    for as_int in (False, True):
        out = frame.lazy().select(dggs.polars.latlng_to_cell("y", pl.col("x"), 7, as_int)).collect()["cell"]
        want = np.asarray(dggs.latlng_to_cell(lat, lng, 7, as_int)).tolist()
        assert out.to_list() == want and out.dtype == (pl.UInt64 if as_int else pl.String)
        direct = dggs.latlng_to_cell(frame["y"], frame["x"], 7, as_int)  # polars coordinates in: a polars Series out
        assert isinstance(direct, pl.Series) and direct.name == "y" and direct.to_list() == want


def test_group_by_aggregates_to_parents():
    cells = dggs.uncompact_cells(["C4"], 4)
    frame = pl.DataFrame({"cell": cells, "v": np.arange(len(cells), dtype=float)})
    got = frame.group_by(pl.col("cell").dggs.cell_to_parent(2).alias("p")).agg(pl.col("v").sum()).sort("p")
    parents = np.asarray(dggs.cell_to_parent(np.asarray(cells), 2))
    want = {p: float(np.arange(len(cells))[parents == p].sum()) for p in np.unique(parents)}
    assert dict(zip(got["p"].to_list(), got["v"].to_list(), strict=True)) == want


def test_a_bad_id_names_itself():
    with pytest.raises(Exception, match="C9"):  # polars may wrap the DggsError raised in its batch
        pl.DataFrame({"c": ["C401", "C9"]}).select(pl.col("c").dggs.get_level())
    with pytest.raises(dggs.InvalidCellError, match="C9"):
        dggs.get_level(pl.Series("c", ["C401", "C9"]))


def test_importing_dggs_does_not_import_polars():
    code = "import sys, dggs; dggs.cell_to_parent(['C401']); dggs.latlng_to_cell([1.0], [2.0], 3); print('polars' in sys.modules)"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout.strip()
    assert out == "False"
