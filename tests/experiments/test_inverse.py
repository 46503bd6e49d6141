"""The thesis's inverse methods (Newton, Newton from a polynomial start, the polynomial alone), moved out of
dggs.geometry.snyder into dggs.experiments.inverse: round trips, iteration counts, tiny inputs, option checks."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from dggs.errors import CoordinateError, DggsValueError
from dggs.experiments import inverse as thesis_inverse
from dggs.experiments import numpy_snyder
from dggs.geometry import snyder
from dggs.geometry.icosahedron import ISEA

from ..geometry.test_snyder import angle_between, random_points


def face_centre(face: int) -> tuple[float, float]:
    """A face centre's spherical (lat, lng) from the icosahedron's vectors (not from the projection)."""
    x, y, z = ISEA.geometry.centres[face]
    return math.degrees(math.atan2(z, math.hypot(x, y))), math.degrees(math.atan2(y, x))


TINY = [5e-324, -5e-324, 1e-320, 2.2e-308, 1e-200, 1e-160, 1e-100]


def test_the_core_has_the_closed_form_only():
    assert not hasattr(snyder, "METHODS") and not hasattr(snyder, "polynomial") and not hasattr(snyder, "_newton")


def test_closed_agrees_with_the_library():
    lat, lng = random_points(20_000, seed=12)
    face, x, y = snyder.forward(lat, lng)
    a = np.array(thesis_inverse.inverse(face, x, y, method="closed"))
    b = np.array(snyder.inverse(face, x, y))
    assert np.abs(a - b).max() < 1e-9
    xyz, it = thesis_inverse.inverse_xyz(face, x, y)
    assert np.abs(xyz - numpy_snyder.inverse_xyz(face, x, y)).max() < 1e-15 and not it.any()


def test_unknown_method_and_bad_coordinates():
    with pytest.raises(DggsValueError, match="method 'fast'"):
        thesis_inverse.inverse(3, 0.0, 0.0, method="fast")
    with pytest.raises(CoordinateError, match="off face 3"):
        thesis_inverse.inverse(3, 0.0, 0.9, method="newton")


def test_round_trip_on_a_million_points_every_method():
    lat, lng = random_points(200_000, seed=13)
    face, x, y = snyder.forward(lat, lng)
    # the polynomial alone is approximate: cubic about 1.7 km at worst, degree 7 about 20 m
    cases = (("closed", 3, 1e-12), ("newton", 3, 1e-12), ("newton-poly", 3, 1e-12), ("poly", 3, 5e-4), ("poly", 7, 5e-6))
    for method, degree, tol in cases:
        lat2, lng2 = thesis_inverse.inverse(face, x, y, method=method, degree=degree)
        assert angle_between(lat, lng, lat2, lng2).max() <= tol, method


def test_newton_iterations_reported_and_fewer_from_polynomial():
    lat, lng = random_points(50_000, seed=14)
    face, x, y = snyder.forward(lat, lng)
    *_, it_plain = thesis_inverse.inverse(face, x, y, method="newton", return_iterations=True)
    *_, it_poly = thesis_inverse.inverse(face, x, y, method="newton-poly", degree=3, return_iterations=True)
    *_, it_poly7 = thesis_inverse.inverse(face, x, y, method="newton-poly", degree=7, return_iterations=True)
    assert 2 <= it_plain.mean() <= 5
    assert it_poly.mean() < it_plain.mean()
    assert it_poly7.mean() <= it_poly.mean()
    assert it_plain.max() <= 10



@pytest.mark.parametrize("method", thesis_inverse.METHODS)
@pytest.mark.parametrize("face", [0, 7, 15, 19])
def test_tiny_coordinates_give_the_face_centre(method, face):
    lat0, lng0 = face_centre(face)
    for x in TINY + [0.0]:
        for y in (0.0, x, -x, 1e-310):
            lat, lng = thesis_inverse.inverse(face, x, y, method=method)
            assert lat == pytest.approx(lat0, abs=1e-12), (x, y)
            assert lng == pytest.approx(lng0, abs=1e-12), (x, y)
    lat, lng = thesis_inverse.inverse(np.full(len(TINY), face), TINY, np.zeros(len(TINY)), method=method)
    assert np.isfinite(lat).all() and np.isfinite(lng).all()
    np.testing.assert_allclose(lat, lat0, atol=1e-12)
    np.testing.assert_allclose(lng, lng0, atol=1e-12)


@given(st.integers(0, 19), st.floats(-1e-150, 1e-150), st.floats(-1e-150, 1e-150), st.sampled_from(thesis_inverse.METHODS))
def test_near_centre_is_finite_and_the_centre(face, x, y, method):
    lat0, lng0 = face_centre(face)
    lat, lng = thesis_inverse.inverse(face, x, y, method=method)
    assert lat == pytest.approx(lat0, abs=1e-12)
    assert lng == pytest.approx(lng0, abs=1e-12)


def test_small_but_normal_coordinates_still_move_away_from_the_centre():
    # the scaled path must not change the direction: compare just above and below the threshold
    for method in thesis_inverse.METHODS:
        a = np.array(thesis_inverse.inverse(3, 1e-140, 2e-140, method=method))
        b = np.array(thesis_inverse.inverse(3, 1e-160, 2e-160, method=method))
        np.testing.assert_allclose(a, b, atol=1e-12)


@pytest.mark.parametrize(
    ("kwargs", "name"),
    [
        ({"tol": 0.0}, "tol"),
        ({"tol": -1e-13}, "tol"),
        ({"tol": float("nan")}, "tol"),
        ({"tol": float("inf")}, "tol"),
        ({"tol": "1e-13"}, "tol"),
        ({"max_iter": 0}, "max_iter"),
        ({"max_iter": -1}, "max_iter"),
        ({"max_iter": 2.5}, "max_iter"),
        ({"max_iter": True}, "max_iter"),
        ({"degree": 0}, "degree"),
        ({"degree": 10}, "degree"),
        ({"degree": 3.0}, "degree"),
        ({"degree": True}, "degree"),
    ],
)
@pytest.mark.parametrize("method", thesis_inverse.METHODS)
def test_bad_options_are_rejected_by_name(kwargs, name, method):
    with pytest.raises(DggsValueError, match=name):
        thesis_inverse.inverse(15, 0.1, 0.0, method=method, **kwargs)


def test_newton_with_one_iteration_is_allowed():
    lat, lng, it = thesis_inverse.inverse(15, 0.1, 0.0, method="newton", max_iter=1, return_iterations=True)
    assert it == 1 and math.isfinite(lat) and math.isfinite(lng)
