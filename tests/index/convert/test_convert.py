"""String <-> 64-bit id codec and the container converters (dggs.index._kernel.codec, dggs.index._convert).

Reference values never come from the code under test: expected integers are
built here from the documented layout (index/_bits.py), bit by bit.
"""

from __future__ import annotations

import doctest
import sys

import numpy as np
import pytest
from hypothesis import example, given
from hypothesis import strategies as st

import dggs
from dggs.errors import InvalidCellError
from dggs.index import ids as _ids
from dggs.index._convert import Kind, cells_in, cells_out, cells_out_flat, is_valid_any
from dggs.index._convert import strings as _codec
from dggs.index._kernel import codec as _kcodec
from dggs.index.ids import int_to_str, str_to_int

pd = pytest.importorskip("pandas")
pa = pytest.importorskip("pyarrow")

MAX_LEVEL = 28
FACES = "ABCDEFGHIJKLMNOPQRST"


# --------------------------------------------------------------------------
# Independent reference: the layout of index/_bits.py, by hand
# --------------------------------------------------------------------------


def shift(level: int) -> int:
    """Lowest bit of a level's field: face at 57, level 1 at 54, level k >= 2 at 2 * (28 - k)."""
    return 57 if level == 0 else 54 if level == 1 else 2 * (MAX_LEVEL - level)


def ref_int(s: str) -> int:
    v = (1 << 62) | (FACES.index(s[0]) << 57)
    for k in range(1, len(s)):
        v |= (int(s[k]) + 1) << shift(k)
    return v


def ref_str(v: object) -> str | None:
    """The string id of an int, or None if it is not a well-formed id."""
    if type(v) is not int or not 0 <= v < 1 << 64 or v >> 62 != 1 or (v >> 57) & 31 >= 20:
        return None
    out = FACES[(v >> 57) & 31]
    codes = [(v >> 54) & 7] + [(v >> shift(k)) & 3 for k in range(2, MAX_LEVEL + 1)]
    if codes[0] == 7:
        return None
    ended = False
    for code in codes:
        if code == 0:
            ended = True
        elif ended:
            return None
        else:
            out += str(code - 1)
    return out


def ref_valid_str(s: object) -> bool:
    if type(s) is not str or not 1 <= len(s) <= MAX_LEVEL + 1 or s[0] not in FACES:
        return False
    return (len(s) < 2 or s[1] in "012345") and all(c in "012" for c in s[2:])


@st.composite
def cells(draw, min_level: int = 0, max_level: int = MAX_LEVEL) -> str:
    """Random valid string ids, digit by digit (levels 0..28)."""
    level = draw(st.integers(min_level, max_level))
    out = FACES[draw(st.integers(0, 19))]
    if level >= 1:
        out += str(draw(st.integers(0, 5)))
    return out + "".join(str(draw(st.integers(0, 2))) for _ in range(level - 1))


def test_reference_values_by_hand():
    assert ref_int("C401") == (1 << 62) | (2 << 57) | (5 << 54) | (1 << 52) | (2 << 50) == 0x4558000000000000
    assert ref_int("A") == 1 << 62
    assert ref_int("T5") == (1 << 62) | (19 << 57) | (6 << 54)
    assert ref_int("A0" + "0" * 27) == (1 << 62) | (1 << 54) | int("01" * 27, 2)


# --------------------------------------------------------------------------
# Scalars
# --------------------------------------------------------------------------


@given(cells())
@example("A")
@example("T5")
@example("A0" + "0" * 27)
@example("T5" + "2" * 27)
def test_scalar_round_trip(s):
    v = ref_int(s)
    assert str_to_int(s) == v and type(str_to_int(s)) is int
    assert int_to_str(v) == s and type(int_to_str(v)) is str
    assert _codec.parse_str(s) == v
    assert _codec.format_int(v) == s
    ids, kind = cells_in(s)
    assert ids.dtype == np.uint64 and ids.tolist() == [v] and kind.scalar and kind.form == "str"
    assert cells_out(ids, kind) == s
    ids, kind = cells_in(v)
    assert ids.tolist() == [v] and kind.form == "int"
    assert cells_out(ids, kind) == v
    assert cells_in(np.str_(s))[0].tolist() == [v]
    assert cells_in(np.uint64(v))[0].tolist() == [v]
    assert cells_in(np.int64(v))[0].tolist() == [v]


@given(st.lists(cells(), min_size=1, max_size=40))
def test_numeric_order_is_string_order(strs):
    ints = [ref_int(s) for s in strs]
    assert str_to_int(strs) == ints
    assert [int_to_str(i) for i in sorted(str_to_int(strs))] == sorted(strs)
    arr = str_to_int(np.array(strs))
    assert np.sort(arr).tolist() == [ref_int(s) for s in sorted(strs)]


@st.composite
def extensions(draw, c: str) -> str:
    """``c`` with 1..4 more digits (0-5 at level 1, 0-2 after): a true descendant."""
    out = c
    for _ in range(draw(st.integers(1, 4))):
        out += draw(st.sampled_from("012345" if len(out) == 1 else "012"))
    return out


@given(cells(max_level=6).flatmap(lambda c: st.tuples(st.just(c), st.lists(extensions(c), max_size=5))), st.lists(cells(max_level=10), max_size=30))
def test_descendants_are_one_integer_range(c_and_desc, others):
    c, descendants = c_and_desc
    lo = ref_int(c)
    hi = lo + (1 << shift(len(c) - 1))
    assert str_to_int(c) == lo
    for s in [c, *descendants, *others]:
        assert (lo <= str_to_int(s) < hi) == s.startswith(c), (c, s)
    ids = str_to_int(np.array([c, *descendants, *others], dtype="U29"))
    inside = (ids >= lo) & (ids < hi)
    assert inside.tolist() == [s.startswith(c) for s in [c, *descendants, *others]]


NEAR_VALID = cells().map(ref_int).flatmap(lambda v: st.sampled_from([v, v ^ (1 << 63), v ^ (3 << 54), v | 1, v - 1, v + 1, v ^ (1 << 61), v | (1 << 52)]))


@given(st.integers(min_value=-(1 << 64), max_value=1 << 65) | NEAR_VALID)
@example(0)
@example(1 << 62)
@example((1 << 62) | 1)  # a level-28 digit below empty levels
@example((1 << 62) | (7 << 54))  # level-1 code 7
@example((1 << 62) | (20 << 57))  # face 20
def test_int_validity_matches_reference(v):
    expected = ref_str(v)
    assert is_valid_any(v) is (expected is not None)
    assert _codec.valid_int(v) is (expected is not None)
    assert _codec.format_int(v) == expected
    if 0 <= v < 1 << 64:
        arr = np.array([v], dtype=np.uint64)
        assert bool(_kcodec.valid_ints(arr)[0]) is (expected is not None)
        assert (_kcodec.check_ints(arr) == -1) is (expected is not None)
    if expected is None:
        with pytest.raises(InvalidCellError, match=f"^{v} is not a valid cell id"):
            int_to_str(v)
    else:
        assert int_to_str(v) == expected
        assert int_to_str(np.array([v], dtype=np.uint64)).tolist() == [expected]


@given(st.text(alphabet="ABCTUa0123456\x00é_ -+", max_size=32))
@example("A" + "0" * 28)
@example("A" + "0" * 29)
@example("C4_0")
@example("C4 0")
@example("C4+0")
def test_str_validity_matches_reference(s):
    ok = ref_valid_str(s)
    assert is_valid_any(s) is ok
    assert (_codec.parse_str(s) == ref_int(s)) if ok else (_codec.parse_str(s) == 0)
    assert bool(is_valid_any(np.array([s]))[0]) is ref_valid_str(s.rstrip("\x00"))  # numpy drops trailing NULs
    assert bool(is_valid_any(pa.array([s]))[0]) is ok
    assert bool(is_valid_any([s])[0]) is ok
    assert bool(is_valid_any(np.array([s], dtype=object))[0]) is ok
    assert bool(is_valid_any(np.array([s], dtype=np.dtypes.StringDType()))[0]) is ok


# --------------------------------------------------------------------------
# Containers: every kind round-trips and keeps its kind
# --------------------------------------------------------------------------

STRS = ["C401", "A", "T5", "B0222", "A0" + "0" * 27, "S12"]
INTS = [ref_int(s) for s in STRS]


def _containers():
    idx = pd.Index([10, 20, 30, 40, 50, 60], name="k")
    return {
        "U": np.array(STRS),
        "S": np.array(STRS, dtype="S"),
        "object": np.array(STRS, dtype=object),
        "StringDType": np.array(STRS, dtype=np.dtypes.StringDType()),
        "int64": np.array(INTS, dtype=np.int64),
        "uint64": np.array(INTS, dtype=np.uint64),
        "U 2-D": np.array(STRS).reshape(2, 3),
        "uint64 2-D": np.array(INTS, dtype=np.uint64).reshape(3, 2),
        "U big-endian": np.array(STRS).astype(">U29"),
        "U strided": np.array(STRS * 2)[::2],
        "list": list(STRS),
        "tuple": tuple(STRS),
        "nested list": [STRS[:3], STRS[3:]],
        "int list": list(INTS),
        "pandas object": pd.Series(STRS, index=idx, name="cell", dtype=object),
        "pandas str": pd.Series(STRS, index=idx, name="cell", dtype=pd.StringDtype("pyarrow")),
        "pandas python str": pd.Series(STRS, index=idx, dtype=pd.StringDtype("python")),
        "pandas default": pd.Series(STRS, index=idx),
        "pandas int64": pd.Series(INTS, index=idx, name="cell", dtype=np.int64),
        "pandas uint64": pd.Series(INTS, index=idx, dtype=np.uint64),
        "pandas Int64": pd.Series(INTS, index=idx, dtype="Int64"),
        "pandas arrow string": pd.Series(STRS, index=idx, dtype=pd.ArrowDtype(pa.string())),
        "pandas arrow int64": pd.Series(INTS, index=idx, dtype=pd.ArrowDtype(pa.int64())),
        "pandas category": pd.Series(STRS, index=idx, dtype="category"),
        "arrow string": pa.array(STRS),
        "arrow large_string": pa.array(STRS, pa.large_string()),
        "arrow sliced": pa.array(["x", *STRS, "y"]).slice(1, len(STRS)),
        "arrow int64": pa.array(INTS, pa.int64()),
        "arrow uint64": pa.array(INTS, pa.uint64()),
        "arrow chunked": pa.chunked_array([STRS[:2], [], STRS[2:]]),
        "arrow chunked int": pa.chunked_array([INTS[:4], INTS[4:]], pa.uint64()),
    }


def _values(obj):
    """Flat Python values of any container (for comparisons)."""
    if isinstance(obj, (pa.Array, pa.ChunkedArray)):
        return obj.to_pylist()
    if isinstance(obj, pd.Series):
        return obj.tolist()
    vals = np.asarray(obj, dtype=object).reshape(-1).tolist()
    return [v.decode() if isinstance(v, bytes) else int(v) if isinstance(v, np.integer) else v for v in vals]


@pytest.mark.parametrize("name", list(_containers()))
def test_container_round_trip(name):
    obj = _containers()[name]
    ids, kind = cells_in(obj)
    assert ids.dtype == np.uint64 and ids.ndim == 1 and ids.flags.c_contiguous
    assert ids.tolist() == [ref_int(s) if isinstance(s, str) else s for s in _values(obj)]
    out = cells_out(ids, kind)
    vals = _values(obj)
    assert _values(out) == vals
    if isinstance(obj, np.ndarray):
        assert type(out) is np.ndarray and out.shape == obj.shape
        assert out.dtype.kind == obj.dtype.kind and (out.dtype.kind != "i" or out.dtype == obj.dtype)
        if obj.dtype.kind == "T":
            assert out.dtype == obj.dtype
    elif isinstance(obj, (list, tuple)):
        assert type(out) is list and np.shape(out) == np.shape(obj)
    elif isinstance(obj, pd.Series):
        assert type(out) is pd.Series and out.index.equals(obj.index) and out.name == obj.name
        assert out.dtype == (object if obj.dtype == "category" else obj.dtype)
    else:
        assert type(out) is type(obj) and out.type == obj.type


@pytest.mark.parametrize("name", list(_containers()))
def test_container_conversions(name):
    obj = _containers()[name]
    ints, strs = str_to_int(obj), int_to_str(obj)
    expected = [ref_int(s) if isinstance(s, str) else s for s in _values(obj)]
    assert _values(ints) == expected
    assert _values(strs) == [ref_str(v) for v in expected]
    assert _values(str_to_int(strs)) == _values(ints)
    assert _values(int_to_str(ints)) == _values(strs)
    for out in (ints, strs):
        if isinstance(obj, np.ndarray):
            assert type(out) is np.ndarray and out.shape == obj.shape
        elif isinstance(obj, pd.Series):
            assert type(out) is pd.Series and out.index.equals(obj.index)
        elif isinstance(obj, (list, tuple)):
            assert type(out) is list
        else:
            assert isinstance(out, pa.ChunkedArray) == isinstance(obj, pa.ChunkedArray)
    if isinstance(obj, np.ndarray):
        assert ints.dtype in (np.uint64, np.int64) and strs.dtype.kind in "USOT"


@given(st.lists(cells(), max_size=20))
def test_random_lists_round_trip(strs):
    for obj in (strs, np.array(strs, dtype="U29"), np.array(strs, dtype=object), pa.array(strs, pa.string())):
        ids, kind = cells_in(obj)
        assert ids.tolist() == [ref_int(s) for s in strs]
        assert _values(cells_out(ids, kind)) == strs


def test_empty_inputs():
    for obj in ([], (), np.array([], dtype="U1"), np.array([], dtype=np.uint64), pa.array([], pa.string()), pd.Series([], dtype=object), [[]]):
        ids, kind = cells_in(obj)
        assert ids.shape == (0,) and ids.dtype == np.uint64
        out = cells_out(ids, kind)
        assert len(out) == len(obj)
    assert str_to_int([]) == [] and int_to_str(np.array([], dtype=np.uint64)).shape == (0,)


def test_zero_d_array():
    out = int_to_str(np.array(ref_int("C401"), dtype=np.uint64))
    assert isinstance(out, np.ndarray) and out.shape == () and out[()] == "C401"


# --------------------------------------------------------------------------
# Trailing dims, nulls and flat outputs
# --------------------------------------------------------------------------

DISK = np.array([[ref_int("C401"), ref_int("C402"), 0], [ref_int("A"), 0, 0]], dtype=np.uint64)


def test_trailing_dims_numpy():
    _, kind = cells_in(np.array(["C4", "A0"]))
    out = cells_out(DISK, kind, (3,))
    assert out.shape == (2, 3) and out.dtype.kind == "U"
    assert out.tolist() == [["C401", "C402", ""], ["A", "", ""]]
    _, kind = cells_in(np.array([ref_int("A")], dtype=np.int64).repeat(2))
    out = cells_out(DISK, kind, (3,))
    assert out.dtype == np.int64 and out[1].tolist() == [ref_int("A"), 0, 0]
    _, kind = cells_in(np.array(["C4", "A0"], dtype="S"))
    assert cells_out(DISK, kind, (3,)).tolist() == [[b"C401", b"C402", b""], [b"A", b"", b""]]


def test_trailing_dims_lists_drop_nulls():
    _, kind = cells_in(["C4", "A0"])
    assert cells_out(DISK, kind, (3,)) == [["C401", "C402"], ["A"]]
    _, kind = cells_in("C4")
    assert cells_out(DISK[:1], kind, (3,)) == ["C401", "C402"]
    assert cells_out(DISK[:1].reshape(1, 1, 3), kind, (1, 3)) == [["C401", "C402"]]
    _, kind = cells_in(ref_int("C4"))
    assert cells_out(DISK[1:], kind, (3,)) == [ref_int("A")]


def test_trailing_dims_pandas_and_arrow():
    s = pd.Series(["C4", "A0"], index=["x", "y"], name="n")
    out = cells_out(DISK, cells_in(s)[1], (3,))
    assert out.index.tolist() == ["x", "y"] and out.name == "n" and out.tolist() == [["C401", "C402"], ["A"]]
    for arr in (pa.array(["C4", "A0"]), pa.chunked_array([["C4"], ["A0"]])):
        out = cells_out(DISK, cells_in(arr)[1], (3,))
        assert isinstance(out, pa.ChunkedArray) == isinstance(arr, pa.ChunkedArray)
        assert out.type == pa.list_(pa.string()) and out.to_pylist() == [["C401", "C402"], ["A"]]
    out = cells_out(DISK, cells_in(pa.array([1 << 62, 1 << 62], pa.int64()))[1], (3,))
    assert out.type == pa.list_(pa.int64()) and out.to_pylist() == [[ref_int("C401"), ref_int("C402")], [ref_int("A")]]


def test_null_id_in_aligned_outputs():
    ids = np.array([ref_int("C4"), 0], dtype=np.uint64)
    assert cells_out(ids, cells_in(np.array(["A", "B"]))[1]).tolist() == ["C4", ""]
    assert cells_out(ids, cells_in(pa.array(["A", "B"]))[1]).to_pylist() == ["C4", None]
    assert cells_out(ids, cells_in(pa.array([1 << 62] * 2, pa.uint64()))[1]).to_pylist() == [ref_int("C4"), None]


def test_arrow_string_output_uniform_and_mixed_lengths():
    for strs in (["C4", "A0", "T5"], ["C401", "A", "T50", "B0222"], ["A0" + "0" * 27] * 2):
        for typ in (pa.uint64(), pa.int64()):
            out = int_to_str(pa.array([ref_int(s) for s in strs], typ))
            assert out.type == pa.string() and out.to_pylist() == strs
        out = cells_out(str_to_int(np.array(strs)), cells_in(pa.array(strs, pa.large_string()))[1])
        assert out.type == pa.large_string() and out.to_pylist() == strs


def test_cells_out_flat():
    ids = np.array([ref_int("C4"), 0, ref_int("A")], dtype=np.uint64)
    assert cells_out_flat(ids, cells_in("B")[1]) == ["C4", "A"]
    assert cells_out_flat(ids, cells_in(1 << 62)[1]) == [ref_int("C4"), ref_int("A")]
    out = cells_out_flat(ids, cells_in(np.array([["A"]], dtype="S"))[1])
    assert out.dtype.kind == "S" and out.tolist() == [b"C4", b"A"]
    out = cells_out_flat(ids, cells_in(pd.Series(["A"], index=[7], name="n"))[1])
    assert out.index.tolist() == [0, 1] and out.name == "n" and out.tolist() == ["C4", "A"]
    out = cells_out_flat(ids, cells_in(pa.chunked_array([["A"]], pa.large_string()))[1])
    assert isinstance(out, pa.ChunkedArray) and out.type == pa.large_string() and out.to_pylist() == ["C4", "A"]


def test_kind_is_frozen_and_shape_checked():
    ids, kind = cells_in(["A", "B"])
    assert isinstance(kind, Kind) and kind.shape == (2,) and kind.container == "list"
    with pytest.raises(AttributeError):
        kind.shape = (3,)  # type: ignore[misc]
    with pytest.raises(ValueError, match="shape"):
        cells_out(ids[:1], kind)


# --------------------------------------------------------------------------
# Invalid inputs
# --------------------------------------------------------------------------

BAD = ["C6", "C0003", "", "c4", "A" * 30, "A0" + "0" * 28, "A0\x00", "A0\x000", "Cé", "C4 ", None, 3.5, True, -1, 1 << 64, 0, (1 << 62) | 1]


@pytest.mark.parametrize("bad", BAD, ids=repr)
def test_invalid_scalar(bad):
    with pytest.raises(InvalidCellError) as err:
        cells_in(bad)
    assert str(err.value).startswith(f"{bad!r} is not a valid cell id: ")
    assert is_valid_any(bad) is False
    with pytest.raises(InvalidCellError):
        str_to_int(bad)
    with pytest.raises(InvalidCellError):
        int_to_str(bad)


@pytest.mark.parametrize("bad", [*BAD, [1, 2], ["A"]], ids=repr)
def test_invalid_in_list_names_value_and_index(bad):
    good = [1 << 62] * 3 if type(bad) is int else ["A", "B", "C"]
    with pytest.raises(InvalidCellError, match="at index 3 is not a valid cell id") as err:
        cells_in([*good, bad])
    assert str(err.value).startswith(repr(bad))
    mask = is_valid_any([*good, bad])
    assert mask == [True, True, True, False]  # a list in, a list out


@pytest.mark.parametrize("bad", [b for b in BAD if isinstance(b, str)], ids=repr)
def test_invalid_strings_in_arrays(bad):
    objs = [np.array(["A", "B", "C", bad], dtype=object), pa.array(["A", "B", "C", bad]), pd.Series(["A", "B", "C", bad], index=list("wxyz"))]
    objs.append(np.array(["A", "B", "C", bad], dtype=np.dtypes.StringDType()))
    if "\x00" not in bad[-1:]:  # numpy U/S arrays cannot hold trailing NULs
        objs.append(np.array(["A", "B", "C", bad]))
        if bad.isascii():
            objs.append(np.array([b"A", b"B", b"C", bad.encode()]))
    for obj in objs:
        with pytest.raises(InvalidCellError, match="at index 3 is not a valid cell id") as err:
            cells_in(obj)
        assert repr(bad)[1:-1] in str(err.value)
        assert _values(is_valid_any(obj)) == [True, True, True, False]


def test_invalid_ints_in_arrays():
    for obj in (np.array([1 << 62, -1], dtype=np.int64), np.array([1 << 62, 1], dtype=np.uint64), pa.array([1 << 62, None], pa.uint64()), pd.Series([1 << 62, 5])):
        with pytest.raises(InvalidCellError, match="at index 1 is not a valid cell id"):
            cells_in(obj)
        assert _values(is_valid_any(obj)) == [True, False]


@pytest.mark.parametrize("dtype", ["Int64", "UInt64", "int64[pyarrow]"])
@pytest.mark.parametrize("at", [0, 1])
def test_pandas_na_in_a_bare_pandas_array_of_int_ids_is_named_at_its_index(dtype, at):
    """pd.array's <NA> is named (as in a Series), not its valid neighbour as a float (numpy's reading of it)."""
    good = ref_int("C401")
    obj = pd.array([good, pd.NA] if at == 1 else [pd.NA, good], dtype=dtype)
    with pytest.raises(InvalidCellError) as err:
        dggs.get_level(obj)
    assert str(err.value) == f"<NA> at index {at} is not a valid cell id: a missing value is not a cell id"
    assert _values(is_valid_any(obj)) == [i != at for i in range(2)]


def test_invalid_multi_dim_index_and_types():
    with pytest.raises(InvalidCellError, match=r"'x' at index \(1, 0\)"):
        cells_in(np.array([["A", "B"], ["x", "C"]]))
    with pytest.raises(InvalidCellError, match="1.5 at index 0"):
        cells_in(np.array([1.5, 2.0]))
    with pytest.raises(InvalidCellError, match="True at index 0"):
        cells_in(np.array([True]))
    with pytest.raises(InvalidCellError, match=r"\['A'\] at index 0 .*same length"):
        cells_in([["A"], ["B", "C"]])
    assert is_valid_any([["A"], "B", ["C", "D"]]) == [False, True, False]
    with pytest.raises(InvalidCellError, match=f"{1 << 62} at index 1 .*only string ids or only integer ids"):
        cells_in(["A", 1 << 62])
    with pytest.raises(InvalidCellError, match=r"b'\\xc3\\xa9' at index 1"):
        cells_in(np.array(["A", "é".encode()], dtype=object))
    with pytest.raises(InvalidCellError, match="None at index 2 .*missing"):
        cells_in(pa.chunked_array([["A"], ["B", None]]))
    with pytest.raises(InvalidCellError, match="at index 0"):
        cells_in(pa.array([1.5]))


def test_arrow_nulls_are_read_from_the_validity_bitmap():
    # element 1 is null but its slot holds "B"; element 3 (after slicing, 2) likewise holds "D"
    data = pa.py_buffer(b"ABCD")
    offsets = pa.py_buffer(np.array([0, 1, 2, 3, 4], dtype=np.int32))
    validity = pa.py_buffer(np.packbits([1, 0, 1, 0], bitorder="little"))
    arr = pa.Array.from_buffers(pa.string(), 4, [validity, offsets, data], null_count=2)
    assert arr.to_pylist() == ["A", None, "C", None]
    with pytest.raises(InvalidCellError, match="None at index 1 .*missing"):
        cells_in(arr)
    assert is_valid_any(arr).tolist() == [True, False, True, False]
    assert is_valid_any(arr.slice(1)).tolist() == [False, True, False]
    assert cells_in(arr.slice(2, 1))[0].tolist() == [ref_int("C")]


def test_bytes_in_object_arrays_decode_as_ascii():
    assert cells_in(np.array(["A", b"C401"], dtype=object))[0].tolist() == [ref_int("A"), ref_int("C401")]
    assert cells_in(b"C401")[0].tolist() == [ref_int("C401")]


@given(st.one_of(st.none(), st.booleans(), st.floats(), st.integers(), st.text(), st.binary(), st.lists(st.one_of(st.text(max_size=4), st.integers(), st.none()), max_size=4), st.lists(st.lists(st.text(max_size=3), max_size=3), max_size=3)))
def test_is_valid_any_never_raises(obj):
    out = is_valid_any(obj)
    if isinstance(obj, list):
        flat = np.asarray(out, dtype=object).reshape(-1)  # a list in, a list out (nested for nested lists)
        assert isinstance(out, list) and all(type(v) is bool for v in flat)
    elif isinstance(obj, bytes):
        assert out is (obj.isascii() and ref_valid_str(obj.decode()))
    elif type(obj) is int:
        assert out is (ref_str(obj) is not None)
    else:
        assert out is ref_valid_str(obj)


# --------------------------------------------------------------------------
# Kernels and docs
# --------------------------------------------------------------------------


def test_kernels_directly():
    codes = np.array(["C401", "A", "", "C6"]).view(np.uint32).reshape(4, 4)
    ids, bad = _kcodec.parse_codes(codes)
    assert ids.tolist() == [ref_int("C401"), ref_int("A"), 0, 0] and bad == 2
    codes, bad = _codec.format_u32(np.array([ref_int("C401"), 0, ref_int("B2")], dtype=np.uint64))
    assert bad == -1 and codes.view("U4").ravel().tolist() == ["C401", "", "B2"]
    _, bad = _codec.format_u8(np.array([ref_int("C401"), 5], dtype=np.uint64))
    assert bad == 1
    assert _kcodec.check_ints(np.array([ref_int("A"), ref_int("A") | 1 << 53 | 1], dtype=np.uint64)) == 1


def test_doctests():
    assert doctest.testmod(_ids, optionflags=doctest.NORMALIZE_WHITESPACE).failed == 0
    assert "pyarrow" in sys.modules
