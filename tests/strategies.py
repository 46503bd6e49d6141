"""Hypothesis strategies shared by the property tests."""

from __future__ import annotations

import math

import numpy as np
from hypothesis import settings
from hypothesis import strategies as st

import dggs
from dggs.geometry.icosahedron import ISEA, xyz_to_latlng

MAX_LEVEL = dggs.MAX_LEVEL


def examples(n: int) -> int:
    """A test's own hypothesis example count: ``n`` under the ci profile (max_examples 100), scaled with the
    loaded profile, so ``make test`` (default, 20) runs a fifth of them and thorough (2000) twenty times as many."""
    return max(5, n * settings.default.max_examples // 100)


def latitudes():
    return st.floats(min_value=-90.0, max_value=90.0, allow_nan=False, allow_infinity=False)


def longitudes():
    return st.floats(min_value=-180.0, max_value=180.0, allow_nan=False, allow_infinity=False)


def latlngs():
    """(lat, lng) pairs in degrees, uniform-ish plus the edge cases hypothesis likes."""
    return st.tuples(latitudes(), longitudes())


def levels(min_level: int = 0, max_level: int = MAX_LEVEL):
    return st.integers(min_value=min_level, max_value=max_level)


@st.composite
def cells(draw, level=None, min_level: int = 0, max_level: int = MAX_LEVEL):
    """Random valid cell ids, built digit by digit (not via the code under test)."""
    lv = draw(levels(min_level, max_level)) if level is None else level
    face = draw(st.integers(0, 19))
    out = "ABCDEFGHIJKLMNOPQRST"[face]
    if lv >= 1:
        out += str(draw(st.integers(0, 5)))
    for _ in range(max(lv - 1, 0)):
        out += str(draw(st.integers(0, 2)))
    return out


def special_points() -> list[tuple[float, float]]:
    """Poles, antimeridian, the 12 icosahedron vertices and face-edge midpoints (geodetic)."""
    from dggs.geometry.authalic import WGS84

    geo = ISEA.geometry
    pts = [(90.0, 0.0), (-90.0, 0.0), (0.0, 180.0), (0.0, -180.0), (45.0, 180.0), (-45.0, -180.0)]
    verts = geo.vertices
    mids = []
    for f in range(20):
        for k in range(3):
            a, b = verts[geo.face_vertices[f, k]], verts[geo.face_vertices[f, (k + 1) % 3]]
            m = a + b
            mids.append(m / np.linalg.norm(m))
    for v in list(verts) + mids:
        beta, lng = xyz_to_latlng(np.asarray(v))
        lat = float(WGS84.authalic_to_geodetic_deg(math.degrees(float(beta))))
        pts.append((max(-90.0, min(90.0, lat)), math.degrees(float(lng))))
    return pts
