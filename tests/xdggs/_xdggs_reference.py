"""Expected values for the xdggs referee tests, from sources independent of dggs's code.

- Ids: the string form and the integer bit layout written out in docs/grid.md ("Cell ids"), encoded here by
  hand: a face letter ``A``-``T``, a level-1 digit ``0``-``5``, then one digit ``0``-``2`` a level; bit 62 set,
  the face in bits 61-57, the level-1 code (digit + 1) in bits 56-54, the level-k code in bits
  2(28-k)+1 .. 2(28-k). Parents are prefixes, children are the next digits in order.
- Geometry: the icosahedron in PROJ's ``isea`` orientation as docs/grid.md states it (a vertex at
  atan(phi) N, 11.25 E; both poles on edge midpoints), built from the textbook coordinates (0, +-1, +-phi);
  Snyder's projection keeps the face centre, the vertices and the edge midpoints, and maps the sides of the
  six triangles (vertex, centre, edge midpoint) of a face to great-circle arcs, so the level-0 cells are the
  spherical faces and the level-1 cells these spherical triangles. Latitudes go between geodetic and
  authalic by the closed form q(phi) (Snyder 1987, eq. 3-12) and bisection, not the series dggs uses.
"""

from __future__ import annotations

import itertools
import math

import numpy as np

FACES = "ABCDEFGHIJKLMNOPQRST"

# WGS84
A = 6378137.0
F = 1 / 298.257223563
E2 = F * (2 - F)
E = math.sqrt(E2)


def doc_int(cell: str) -> int:
    """The integer id of a string id, by the bit layout of docs/grid.md."""
    value = (1 << 62) | (FACES.index(cell[0]) << 57)
    if len(cell) > 1:
        value |= (int(cell[1]) + 1) << 54
    for k, digit in enumerate(cell[2:], start=2):
        value |= (int(digit) + 1) << (2 * (28 - k))
    return value


def doc_ints(cells) -> np.ndarray:
    return np.array([doc_int(c) for c in cells], dtype=np.uint64)


def doc_children(cell: str, level: int) -> list[str]:
    """The descendants of a string id at a level, in id order (digits 0-5 at level 1, 0-2 below)."""
    out = [cell]
    for k in range(len(cell), level + 1):
        digits = "012345" if k == 1 else "012"
        out = [c + d for c in out for d in digits]
    return out


LEVEL0 = list(FACES)
LEVEL1 = [c for f in FACES for c in doc_children(f, 1)]


def num_cells(level: int) -> int:
    return 20 if level == 0 else 120 * 3 ** (level - 1)


def _q(sin_phi: np.ndarray) -> np.ndarray:
    es = E * sin_phi
    return (1 - E2) * (sin_phi / (1 - E2 * sin_phi**2) - np.log((1 - es) / (1 + es)) / (2 * E))


QP = float(_q(np.array(1.0)))
ELLIPSOID_AREA = 2 * math.pi * A * A * QP  # 4 pi R_q^2 with the authalic radius R_q = a sqrt(qp / 2)


def authalic(lat_deg) -> np.ndarray:
    """Authalic latitude (radians) of geodetic latitudes (degrees)."""
    lat = np.asarray(lat_deg, dtype=float)
    ratio = np.clip(_q(np.sin(np.radians(lat))) / QP, -1.0, 1.0)
    return np.where(np.abs(lat) == 90.0, np.radians(lat), np.arcsin(ratio))  # arcsin is blunt next to +-1


def geodetic(beta) -> np.ndarray:
    """Geodetic latitude (degrees) of authalic latitudes (radians), by bisection on the monotone q."""
    target = np.sin(np.asarray(beta, dtype=float)) * QP
    lo = np.full(target.shape, -math.pi / 2)
    hi = np.full(target.shape, math.pi / 2)
    for _ in range(64):
        mid = (lo + hi) / 2
        below = _q(np.sin(mid)) < target
        lo = np.where(below, mid, lo)
        hi = np.where(below, hi, mid)
    return np.degrees((lo + hi) / 2)


def to_xyz(lon_deg, lat_deg) -> np.ndarray:
    """Unit vectors (N, 3) on the authalic sphere of geodetic (lon, lat) in degrees."""
    beta = authalic(lat_deg)
    lam = np.radians(np.asarray(lon_deg, dtype=float))
    return np.stack([np.cos(beta) * np.cos(lam), np.cos(beta) * np.sin(lam), np.sin(beta)], axis=-1)


def to_lonlat(xyz: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Geodetic (lon, lat) in degrees of unit vectors on the authalic sphere."""
    xyz = np.asarray(xyz, dtype=float)
    lon = np.degrees(np.arctan2(xyz[..., 1], xyz[..., 0]))
    return lon, geodetic(np.arctan2(xyz[..., 2], np.hypot(xyz[..., 0], xyz[..., 1])))


def _unit(v: np.ndarray) -> np.ndarray:
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def _icosahedron() -> tuple[np.ndarray, list[tuple[int, int, int]]]:
    phi = (1 + math.sqrt(5)) / 2
    raw = []
    for s1, s2 in itertools.product((1, -1), repeat=2):
        raw += [(0, s1, s2 * phi), (s1, s2 * phi, 0), (s2 * phi, 0, s1)]
    verts = np.array(raw, dtype=float)  # edges have length 2; (0, 1, phi) and (0, -1, phi) straddle the pole
    turn = math.radians(11.25 - 90.0)  # (0, 1, phi) is at longitude 90: turn it to 11.25 E
    rot = np.array([[math.cos(turn), -math.sin(turn), 0], [math.sin(turn), math.cos(turn), 0], [0, 0, 1]])
    verts = verts @ rot.T
    faces = [
        t
        for t in itertools.combinations(range(12), 3)
        if all(abs(np.linalg.norm(verts[i] - verts[j]) - 2) < 1e-9 for i, j in itertools.combinations(t, 2))
    ]
    return _unit(verts), faces


VERTICES, _FACE_INDEX = _icosahedron()
FACE_TRIANGLES = np.array([VERTICES[list(t)] for t in _FACE_INDEX])  # (20, 3, 3)
FACE_CENTRES = _unit(FACE_TRIANGLES.sum(axis=1))  # (20, 3)


def _level1_triangles() -> tuple[np.ndarray, np.ndarray]:
    tris, owner = [], []
    for f, (tri, centre) in enumerate(zip(FACE_TRIANGLES, FACE_CENTRES, strict=True)):
        for i, j in itertools.permutations(range(3), 2):
            tris.append([tri[i], centre, _unit(tri[i] + tri[j])])
            owner.append(f)
    return np.array(tris), np.array(owner)


LEVEL1_TRIANGLES, LEVEL1_FACE = _level1_triangles()  # (120, 3, 3): vertex, face centre, edge midpoint


def containing(triangles: np.ndarray, points: np.ndarray, margin: float = 0.0) -> np.ndarray:
    """(N, T) bool: which spherical triangles (great-circle sides) hold each unit vector (inside by margin)."""
    a, b, c = triangles[:, 0], triangles[:, 1], triangles[:, 2]
    sign = np.sign(np.einsum("ti,ti->t", np.cross(a, b), c))
    sides = [np.cross(a, b), np.cross(b, c), np.cross(c, a)]
    dets = np.stack([points @ s.T for s in sides]) * sign  # (3, N, T)
    return np.all(dets > margin, axis=0)


def nearest(targets: np.ndarray, points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Index of the nearest target (by angle) of each point, and that angle in radians."""
    idx = (points @ targets.T).argmax(axis=1)
    chosen = targets[idx]
    angle = np.arctan2(np.linalg.norm(np.cross(points, chosen), axis=-1), np.einsum("ni,ni->n", points, chosen))
    return idx, angle
