"""Orientation and face geometry."""

from __future__ import annotations

import math

import numpy as np
import pytest

from dggs.geometry.icosahedron import ISEA, POLE, Orientation, face_of, latlng_to_xyz, xyz_to_latlng

PHI = (1 + math.sqrt(5)) / 2


def test_isea_vertex_zero_and_one():
    # Snyder (1992) / PROJ: vertex 0 at atan(phi) N, 11.25 E; vertex 1 at azimuth 0 from it
    lat, lng = (np.degrees(v) for v in xyz_to_latlng(ISEA.geometry.vertices))
    assert lat[0] == pytest.approx(math.degrees(math.atan(PHI)), abs=1e-12)
    assert lng[0] == pytest.approx(11.25, abs=1e-12)
    assert lat[1] == pytest.approx(58.282525588539, abs=1e-9)
    assert lng[1] == pytest.approx(-168.75, abs=1e-12)


def test_poles_are_edge_midpoints_in_isea():
    geo = ISEA.geometry
    mids = []
    for f in range(20):
        for k in range(3):
            a, b = geo.vertices[geo.face_vertices[f, k]], geo.vertices[geo.face_vertices[f, (k + 1) % 3]]
            m = a + b
            mids.append(m / np.linalg.norm(m))
    mids = np.array(mids)
    for pole in ([0, 0, 1], [0, 0, -1]):
        assert np.min(np.linalg.norm(mids - pole, axis=1)) < 1e-15


def test_pole_orientation_puts_a_vertex_at_the_pole():
    assert POLE.geometry.vertices[0] == pytest.approx([0, 0, 1], abs=1e-15)


def test_icosahedron_is_regular():
    v = ISEA.geometry.vertices
    d = np.linalg.norm(v[:, None] - v[None], axis=-1)
    edge = np.sort(d, axis=1)[:, 1:6]  # five nearest neighbours of every vertex
    assert np.allclose(edge, 1 / math.sin(2 * math.pi / 5), rtol=1e-12)


def test_face_vertices_are_clockwise_and_centred():
    geo = ISEA.geometry
    for f in range(20):
        tri = geo.vertices[geo.face_vertices[f]]
        c = tri.sum(axis=0)
        assert c / np.linalg.norm(c) == pytest.approx(geo.centres[f], abs=1e-14)
        # vertex 0 due "north" in the face frame, the others at azimuth 120 and 240, clockwise
        az = np.degrees(np.arctan2(tri @ geo.easts[f], tri @ geo.norths[f])) % 360
        assert az == pytest.approx([0, 120, 240], abs=1e-9) or az == pytest.approx([360, 120, 240], abs=1e-9)


def test_face_lookup_is_nearest_centre_and_ties_go_low():
    geo = ISEA.geometry
    rng = np.random.default_rng(0)
    p = rng.normal(size=(10000, 3))
    p /= np.linalg.norm(p, axis=1)[:, None]
    f = face_of(ISEA, p)
    dots = p @ geo.centres.T
    assert np.all(dots[np.arange(len(p)), f] >= dots.max(axis=1) - 20 * 4e-16)
    # a vertex touches five faces; it goes to the lowest-numbered one
    for vid in range(12):
        faces = np.flatnonzero((geo.face_vertices == vid).any(axis=1))
        assert face_of(ISEA, geo.vertices[vid : vid + 1])[0] == faces.min()


def test_custom_orientation_and_bad_values():
    o = Orientation(10.0, 20.0, 30.0)
    v0 = o.geometry.vertices[0]
    assert v0 == pytest.approx(latlng_to_xyz(math.radians(10), math.radians(20)), abs=1e-15)
    with pytest.raises(ValueError, match="lat 91"):
        Orientation(91.0, 0.0)
    with pytest.raises(ValueError, match="lng nan"):
        Orientation(0.0, float("nan"))
