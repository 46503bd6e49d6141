"""snyder.forward / inverse on bad and extreme inputs (issue 10): typed errors naming the value, and the
right answer for tiny planar coordinates (the thesis's inverse methods: tests/experiments/test_inverse.py)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from dggs.errors import CoordinateError
from dggs.geometry import snyder
from dggs.geometry.icosahedron import ISEA


def face_centre(face: int) -> tuple[float, float]:
    """A face centre's spherical (lat, lng) from the icosahedron's vectors (not from the projection)."""
    x, y, z = ISEA.geometry.centres[face]
    return math.degrees(math.atan2(z, math.hypot(x, y))), math.degrees(math.atan2(y, x))


TINY = [5e-324, -5e-324, 1e-320, 2.2e-308, 1e-200, 1e-160, 1e-100]


@pytest.mark.parametrize("face", [0, 7, 15, 19])
def test_tiny_coordinates_give_the_face_centre(face):
    lat0, lng0 = face_centre(face)
    for x in TINY + [0.0]:
        for y in (0.0, x, -x, 1e-310):
            lat, lng = snyder.inverse(face, x, y)
            assert lat == pytest.approx(lat0, abs=1e-12), (x, y)
            assert lng == pytest.approx(lng0, abs=1e-12), (x, y)
    lat, lng = snyder.inverse(np.full(len(TINY), face), TINY, np.zeros(len(TINY)))
    assert np.isfinite(lat).all() and np.isfinite(lng).all()
    np.testing.assert_allclose(lat, lat0, atol=1e-12)
    np.testing.assert_allclose(lng, lng0, atol=1e-12)


@given(st.integers(0, 19), st.floats(-1e-150, 1e-150), st.floats(-1e-150, 1e-150))
def test_near_centre_is_finite_and_the_centre(face, x, y):
    lat0, lng0 = face_centre(face)
    lat, lng = snyder.inverse(face, x, y)
    assert lat == pytest.approx(lat0, abs=1e-12)
    assert lng == pytest.approx(lng0, abs=1e-12)


def test_small_but_normal_coordinates_still_move_away_from_the_centre():
    # the scaled path must not change the direction: compare just above and below the threshold
    a = np.array(snyder.inverse(3, 1e-140, 2e-140))
    b = np.array(snyder.inverse(3, 1e-160, 2e-160))
    np.testing.assert_allclose(a, b, atol=1e-12)


BAD_VALUES = ["10", b"10", True, False, np.True_, None, "nan", object(), 1j]


@pytest.mark.parametrize("bad", BAD_VALUES, ids=repr)
def test_forward_rejects_non_numbers_naming_them(bad):
    for lat, lng, name in ((bad, 5.0, "latitude"), (10.0, bad, "longitude")):
        with pytest.raises(CoordinateError, match=name) as info:
            snyder.forward(lat, lng)
        if isinstance(bad, (str, bool)):
            assert repr(bad) in str(info.value)
    with pytest.raises(CoordinateError, match="index 1"):
        snyder.forward([1.0, bad, 3.0], [1.0, 2.0, 3.0])
    with pytest.raises(CoordinateError, match="latitude"):
        snyder.Projection().forward(bad, 5.0)


@pytest.mark.parametrize("bad", BAD_VALUES, ids=repr)
def test_inverse_rejects_non_numbers_naming_them(bad):
    for args, name in (((bad, 0.1, 0.0), "face"), ((15, bad, 0.0), "x"), ((15, 0.1, bad), "y")):
        with pytest.raises(CoordinateError, match=f"^{name} ") as info:
            snyder.inverse(*args)
        if isinstance(bad, (str, bool)):
            assert repr(bad) in str(info.value)
    with pytest.raises(CoordinateError, match="x True at index 1"):
        snyder.inverse([15, 15], [0.0, True], [0.0, 0.0])


def test_numbers_still_pass():
    assert snyder.forward(10, 5)[0] == snyder.forward(10.0, 5.0)[0]
    assert snyder.forward(np.float32(10), np.int64(5))[0] == snyder.forward(10.0, 5.0)[0]
    assert snyder.inverse(15.0, 0, 0) == snyder.inverse(15, 0.0, 0.0)
    face, x, y = snyder.forward([10.0, 20.0], [5.0, 6.0])
    assert face.shape == (2,)
