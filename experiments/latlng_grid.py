"""Chapter 7's proposal: an equal-area latitude-longitude grid.

"For a given number of lines of latitude, and a given number of lines of
longitude, a polyhedral approximation could be constructed.  The placement of
the lines of latitude could be adjusted so that the resulting quadrilaterals
would have equi-areal properties" (thesis ch. 7).  On the sphere this has a
closed form for any numbers: with ``n`` bands and ``m`` meridians, the
parallels ``sin(lat_k) = -1 + 2 k / n`` (``k = 0..n``; on the authalic sphere
for the Earth) cut zones of equal area ``4 pi R^2 / n`` (Archimedes: a zone's
area is ``2 pi R^2 (sin b - sin a)``), and equally spaced meridians cut each
zone into ``m`` cells of area ``4 pi R^2 / (n m)`` exactly.  Doubling ``n``
keeps every parallel (``k -> 2 k``), so the grid is hierarchical.

The *polyhedral approximation* (the thesis's words; what chapter 6 measures) is
the mesh on the grid's vertices: flat quadrilaterals between two parallels and
flat triangles at the poles.  Its faces are not equal: near the poles the
cells become slivers (tall bands of one tenth of a degree of longitude), so the
flat faces' areas drift from the spherical cells'.  :func:`latlng_grid_scheme`
runs it beside the thesis's schemes with the chapter-6 metrics: level ``L``
has ``n = 2^(L+1)`` bands and ``m = 2^(L+2)`` meridians (``8 * 4^L`` faces;
level 0 is the octahedron).

Examples
--------
>>> import math
>>> lat = equal_area_parallels(4)
>>> [round(math.degrees(x), 4) for x in lat]
[-90.0, -30.0, 0.0, 30.0, 90.0]
>>> cell_areas(4, 6).round(6).tolist() == [round(4 * math.pi / 24, 6)] * 24
True
>>> m = latlng_mesh(2, 4)
>>> m.num_vertices, [b.shape for b in m.faces]
(6, [(8, 3)])
"""

from __future__ import annotations

import math

import numpy as np

from dggs.experiments.errors import ExperimentLevelError
from dggs.experiments.mesh import Mesh

__all__ = [
    "equal_area_parallels",
    "cell_areas",
    "latlng_mesh",
    "latlng_level",
    "octahedron",
    "spherical_cell_errors",
]


def _check(n: int, m: int) -> None:
    for name, value, low in (("bands", n, 2), ("meridians", m, 3)):
        if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < low:
            raise ExperimentLevelError(f"{name} {value!r} must be an integer >= {low}")


def equal_area_parallels(n: int) -> np.ndarray:
    """Latitudes (radians) of the ``n + 1`` parallels that cut the sphere into ``n`` equal-area zones.

    ``sin(lat_k) = -1 + 2 k / n``, poles included.

    Examples
    --------
    >>> [round(math.degrees(x), 3) for x in equal_area_parallels(3)]
    [-90.0, -19.471, 19.471, 90.0]
    """
    _check(n, 3)
    lat = np.arcsin(np.clip(-1.0 + 2.0 * np.arange(n + 1) / n, -1.0, 1.0))
    lat[0], lat[-1] = -math.pi / 2, math.pi / 2
    return lat


def cell_areas(n: int, m: int, radius: float = 1.0) -> np.ndarray:
    """Spherical areas of the ``n m`` cells by Archimedes' zone formula, band by band from the south.

    A cell between latitudes ``a < b`` and longitudes ``l, l + 2 pi / m`` has
    area ``R^2 (sin b - sin a) 2 pi / m``.

    Examples
    --------
    >>> round(float(cell_areas(5, 7).sum()), 12) == round(4 * math.pi, 12)
    True
    """
    _check(n, m)
    lat = equal_area_parallels(n)
    zone = np.diff(np.sin(lat))
    return np.repeat(radius * radius * zone * (2 * math.pi / m), m)


def latlng_mesh(n: int, m: int, radius: float = 1.0) -> Mesh:
    """The polyhedral approximation: vertices at the grid's corners, flat quads and polar triangles.

    Two blocks: the ``2 m`` polar triangles (south cap, then north), and the
    quads band by band from the south, meridian by meridian from longitude 0;
    every face counter-clockwise seen from outside.

    Parameters
    ----------
    n, m : int
        Number of bands (zones between parallels, ``n >= 2``) and of
        meridians (``m >= 3``).
    radius : float
        Sphere radius.

    Examples
    --------
    >>> m = latlng_mesh(4, 8)
    >>> [b.shape for b in m.faces]
    [(16, 3), (16, 4)]
    """
    _check(n, m)
    lat = equal_area_parallels(n)[1:-1]  # interior parallels, south to north
    lng = 2 * math.pi * np.arange(m) / m
    la, lo = np.meshgrid(lat, lng, indexing="ij")
    ring = np.stack([np.cos(la) * np.cos(lo), np.cos(la) * np.sin(lo), np.sin(la)], axis=-1).reshape(-1, 3)
    south, north = 0, 1
    verts = np.concatenate([[[0.0, 0.0, -1.0], [0.0, 0.0, 1.0]], ring]) * radius
    ids = 2 + np.arange((n - 1) * m).reshape(n - 1, m)  # ids[k, j]: parallel k (interior), meridian j
    nxt = np.roll(ids, -1, axis=1)
    tri = np.concatenate([
        np.stack([np.full(m, south), nxt[0], ids[0]], axis=1),  # south cap, CCW from outside (below)
        np.stack([np.full(m, north), ids[-1], nxt[-1]], axis=1),  # north cap
    ])
    quads = np.stack([ids[:-1], nxt[:-1], nxt[1:], ids[1:]], axis=-1).reshape(-1, 4)
    faces = (tri.astype(np.int64),) if n == 2 else (tri.astype(np.int64), quads.astype(np.int64))
    return Mesh(verts, faces)


def latlng_level(level: int, radius: float = 1.0) -> Mesh:
    """Level ``L`` of the hierarchy: ``2^(L+1)`` bands, ``2^(L+2)`` meridians, ``8 * 4^L`` faces.

    Examples
    --------
    >>> latlng_level(2).num_faces
    128
    """
    if isinstance(level, bool) or not isinstance(level, (int, np.integer)) or level < 0:
        raise ExperimentLevelError(f"level {level!r} must be an integer >= 0")
    return latlng_mesh(2 ** (level + 1), 2 ** (level + 2), radius)


def octahedron(radius: float = 1.0) -> Mesh:
    """The regular octahedron: level 0 of the equal-area lat-lng grid (2 bands, 4 meridians).

    Examples
    --------
    >>> octahedron().num_faces
    8
    """
    return latlng_mesh(2, 4, radius)


def spherical_cell_errors(n: int, m: int) -> np.ndarray:
    """Relative errors (%) of the *spherical* cells' areas against ``4 pi / (n m)``: zero to rounding.

    Examples
    --------
    >>> float(np.abs(spherical_cell_errors(64, 128)).max()) < 1e-9
    True
    """
    return (cell_areas(n, m) / (4 * math.pi / (n * m)) - 1.0) * 100.0
