"""Geodetic <-> authalic latitude and the authalic radius, against independent references."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import example, given
from hypothesis import strategies as st
from pyproj import Geod

from dggs.geometry.authalic import WGS84, Ellipsoid, sphere


def exact_authalic(phi: np.ndarray) -> np.ndarray:
    """Snyder (1987) eqs. 3-11/3-12 in closed form: beta = asin(q / q_p).

    Accurate away from the poles (asin loses digits near +-1), which is
    where it is used here.
    """
    e2 = WGS84.f * (2 - WGS84.f)
    e = math.sqrt(e2)
    s = np.sin(phi)
    q = (1 - e2) * (s / (1 - e2 * s * s) + np.arctanh(e * s) / e)
    qp = (1 - e2) * (1 / (1 - e2) + math.atanh(e) / e)
    return np.arcsin(q / qp)


def test_authalic_radius_matches_published_value():
    # WGS84 authalic radius R_q = 6371007.1809 m (Moritz 1980, Geodetic Reference System)
    assert WGS84.authalic_radius == pytest.approx(6371007.1809, abs=1e-4)


def test_area_matches_geod():
    # the ellipsoid's area from pyproj.Geod: a polygon over the whole northern hemisphere, twice
    g = Geod(ellps="WGS84")
    lons = np.linspace(-180, 180, 721)[:-1]
    north, _ = g.polygon_area_perimeter(lons, np.zeros_like(lons))
    assert 2 * abs(north) == pytest.approx(WGS84.area, rel=1e-12)


def test_series_matches_closed_form_away_from_poles():
    phi = np.radians(np.linspace(-80, 80, 10001))
    assert np.abs(WGS84.geodetic_to_authalic(phi) - exact_authalic(phi)).max() < 1e-14


@given(st.floats(-90, 90))
@example(90.0)
@example(-90.0)
@example(0.0)
def test_round_trip(lat):
    phi = math.radians(lat)
    back = float(WGS84.authalic_to_geodetic(WGS84.geodetic_to_authalic(phi)))
    assert abs(back - phi) <= 1e-12


def test_poles_and_equator_are_fixed():
    for lat in (-90.0, 0.0, 90.0):
        assert float(WGS84.geodetic_to_authalic_deg(lat)) == pytest.approx(lat, abs=1e-12)


@pytest.mark.parametrize("band", [(0.0, 10.0), (30.0, 45.0), (60.0, 89.0), (-75.0, -20.0)])
def test_latitude_band_areas_match_geod(band):
    """Area of a band on the ellipsoid (pyproj.Geod) = area of its authalic band on the sphere."""
    lo, hi = band
    g = Geod(ellps="WGS84")
    # a 10-degree-wide lune of the band, densified along its parallels
    lons = np.linspace(0.0, 10.0, 2001)
    ring_lng = np.concatenate([lons, lons[::-1]])
    ring_lat = np.concatenate([np.full_like(lons, lo), np.full_like(lons, hi)])
    geod_area = abs(g.polygon_area_perimeter(ring_lng, ring_lat)[0])
    b_lo, b_hi = (float(WGS84.geodetic_to_authalic(math.radians(v))) for v in (lo, hi))
    sphere_area = WGS84.authalic_radius**2 * math.radians(10.0) * (math.sin(b_hi) - math.sin(b_lo))
    # Geod joins the ring's points by geodesics, not parallels: the 2001-point densification
    # keeps that chord error under 1e-6 of the band's area.
    assert geod_area == pytest.approx(sphere_area, rel=1e-6)


def test_sphere_mode_is_identity():
    s = sphere(1000.0)
    phi = np.radians(np.linspace(-90, 90, 7))
    assert np.array_equal(s.geodetic_to_authalic(phi), phi)
    assert s.authalic_radius == 1000.0


def test_bad_ellipsoids():
    with pytest.raises(ValueError, match="semi-major axis -1"):
        Ellipsoid(-1.0, 0.0)
    with pytest.raises(ValueError, match="flattening 1.5"):
        Ellipsoid(1.0, 1.5)
