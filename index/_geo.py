"""Internal glue between cell ids and the geometry: planar corners and projection."""

from __future__ import annotations

import numpy as np

from dggs.geometry import snyder
from dggs.geometry._parallel import run_chunks
from dggs.geometry.authalic import WGS84
from dggs.geometry.icosahedron import ISEA, latlng_to_xyz, xyz_to_latlng
from dggs.geometry.split26 import FACE_VERTICES, cell_vertices

from .cellid import Decoded

#: The default grid: PROJ's ISEA orientation on the WGS84 authalic sphere.
ORIENTATION = ISEA
ELLIPSOID = WGS84


def geodetic_to_xyz(lat_deg: np.ndarray, lng_deg: np.ndarray) -> np.ndarray:
    """Geodetic WGS84 degrees -> unit vectors on the authalic sphere."""
    beta = ELLIPSOID.geodetic_to_authalic(np.radians(lat_deg))
    return latlng_to_xyz(beta, np.radians(lng_deg))


def xyz_to_geodetic(xyz: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Unit vectors on the authalic sphere -> geodetic WGS84 (lat, lng) degrees."""
    beta, lng = xyz_to_latlng(xyz)
    return np.degrees(ELLIPSOID.authalic_to_geodetic(beta)), np.degrees(lng)


def planar_to_geodetic(face: np.ndarray, x: np.ndarray, y: np.ndarray):
    """Face-frame points -> geodetic (lat, lng) degrees (exact closed-form inverse), chunked."""
    n = x.shape[0]
    lat, lng = np.empty(n), np.empty(n)

    def kernel(sl: slice) -> None:
        xyz, _ = snyder.inverse_xyz(face[sl], x[sl], y[sl], ORIENTATION)
        lat[sl], lng[sl] = xyz_to_geodetic(xyz)

    run_chunks(kernel, n)
    return lat, lng


def corners(dec: Decoded) -> np.ndarray:
    """Planar corners (N, 3, 2) of decoded cells, counter-clockwise seen from outside.

    Level-0 cells are their face triangles; finer cells are their Split (2:6)
    triangles (A, B, C reordered where needed to run counter-clockwise).
    """
    n = dec.face.shape[0]
    out = np.empty((n, 3, 2))
    coarse = dec.level == 0
    if coarse.any():
        # Face vertices run clockwise (azimuth order); reverse them.
        out[coarse] = FACE_VERTICES[::-1]
    fine = ~coarse
    if fine.any():
        a, b, c = cell_vertices(dec.l1[fine], dec.digits[fine], dec.level[fine])
        cross = (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0])
        ccw = (cross > 0)[:, None]
        out[fine, 0] = a
        out[fine, 1] = np.where(ccw, b, c)
        out[fine, 2] = np.where(ccw, c, b)
    return out
