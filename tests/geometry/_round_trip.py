"""Helpers shared by the projection tests (test_snyder.py, test_ivea.py): the angle between points, random points
uniform on the sphere, and the round trip ``inverse(forward(p)) == p`` with its pinned special points.

The reference is geometry, not the code under test: the angle between two unit vectors built by
:func:`dggs.geometry.icosahedron.latlng_to_xyz` from the input and from the round trip's output.
"""

from __future__ import annotations

from types import ModuleType

import numpy as np
from hypothesis import example

from dggs.geometry.icosahedron import latlng_to_xyz

#: Points every round-trip property test takes first: the poles, the antimeridian from both sides,
#: the ISEA orientation's vertex (58.28N 11.25E) and a vertex of the lower ring.
PINNED = ((90.0, 0.0), (-90.0, 123.0), (0.0, 180.0), (0.0, -180.0), (58.282525588539, 11.25),
          (26.565051177078, -168.75))


def pinned(test):
    """Add the :data:`PINNED` points as hypothesis examples of a test taking one (lat, lng) pair."""
    for p in reversed(PINNED):
        test = example(p)(test)
    return test


def random_points(n, seed):
    """``n`` points uniform on the sphere: (lat, lng) degrees."""
    rng = np.random.default_rng(seed)
    lat = np.degrees(np.arcsin(rng.uniform(-1, 1, n)))
    lng = rng.uniform(-180, 180, n)
    return lat, lng


def angle_between(lat1, lng1, lat2, lng2):
    """The angle (radians) between points given in degrees, from the chord (exact near 0)."""
    a = latlng_to_xyz(np.radians(lat1), np.radians(lng1))
    b = latlng_to_xyz(np.radians(lat2), np.radians(lng2))
    return 2 * np.arcsin(np.clip(np.linalg.norm(a - b, axis=-1) / 2, 0, 1))


def round_trip_error(module: ModuleType, lat, lng):
    """The largest angle between points and ``module.inverse(*module.forward(lat, lng))`` (radians)."""
    face, x, y = module.forward(lat, lng)
    lat2, lng2 = module.inverse(face, x, y)
    return float(np.max(angle_between(lat, lng, lat2, lng2)))
