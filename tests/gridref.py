"""Reference geometry for the tests, independent of the compiled kernel.

String ids are decoded here by hand and their planar corners come from
:func:`dggs.geometry.split26.cell_vertices` (numpy, contractions composed
four digits at a time), not from the kernel's per-level construction.
"""

from __future__ import annotations

import numpy as np

from dggs.geometry.split26 import FACE_VERTICES, cell_vertices

FACES = "ABCDEFGHIJKLMNOPQRST"


def decode(cells) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """face, level, level-1 digit and later digits (N, L) of string ids."""
    cells = [str(c) for c in np.asarray(cells).ravel()]
    n = len(cells)
    depth = max((len(c) - 2 for c in cells), default=0)
    face = np.array([FACES.index(c[0]) for c in cells], dtype=np.intp)
    level = np.array([len(c) - 1 for c in cells], dtype=np.intp)
    l1 = np.array([int(c[1]) if len(c) > 1 else 0 for c in cells], dtype=np.intp)
    digits = np.zeros((n, max(depth, 0)), dtype=np.uint8)
    for i, c in enumerate(cells):
        for j, ch in enumerate(c[2:]):
            digits[i, j] = int(ch)
    return face, level, l1, digits


def planar_corners(cells) -> np.ndarray:
    """Face-frame corners (N, 3, 2), counter-clockwise, of string ids."""
    face, level, l1, digits = decode(cells)
    out = np.empty((len(face), 3, 2))
    coarse = level == 0
    out[coarse] = FACE_VERTICES[::-1]
    fine = ~coarse
    if fine.any():
        a, b, c = cell_vertices(l1[fine], digits[fine], level[fine])
        cross = (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0])
        ccw = (cross > 0)[:, None]
        out[fine, 0] = a
        out[fine, 1] = np.where(ccw, b, c)
        out[fine, 2] = np.where(ccw, c, b)
    return out


def encode(face: np.ndarray, digits: np.ndarray) -> np.ndarray:
    """String ids of faces (N,) and digit rows (N, level)."""
    return np.array([FACES[f] + "".join(str(int(d)) for d in row) for f, row in zip(face, digits, strict=True)])


def mirror_neighbours(cells) -> np.ndarray:
    """(N, 3) edge neighbours of string ids of one level >= 1 by geometry alone.

    Mirror the planar centroid in the edge from corner i to corner i + 1,
    carry it onto the adjacent face when it falls off this one, and locate it
    at the cell's level (docs/grid.md, "Neighbours").
    """
    from dggs.geometry.icosahedron import ISEA
    from dggs.geometry.split26 import neighbour_points

    from .reference.numpy_split26 import locate

    face, level, _, _ = decode(cells)
    assert (level == level[0]).all() and level[0] >= 1
    pts = planar_corners(cells)
    centre = pts.mean(axis=1)
    out = np.empty((len(face), 3), dtype=object)
    for i in range(3):
        p, q = pts[:, i], pts[:, (i + 1) % 3]
        d = q - p
        t = np.einsum("ij,ij->i", centre - p, d) / np.einsum("ij,ij->i", d, d)
        mirror = 2.0 * (p + t[:, None] * d) - centre
        nface, moved = neighbour_points(face, mirror, ISEA.geometry.face_vertices)
        out[:, i] = encode(nface, locate(moved[:, 0], moved[:, 1], int(level[0])))
    return out.astype(str)
