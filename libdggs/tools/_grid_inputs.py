"""Inputs shared by the grid part's freeze_ and compare_ tools: random valid ids, edge ids, and the binding.

Edge ids: the cells at the poles, on the antimeridian and at the 12 icosahedron vertices (through
``dggs.latlng_to_cell`` on both projections), the corner cells of every face (all digits 0 or 2, which keep a
corner), the 20 faces, and cells along face edges, at every level 0..28.
"""

from __future__ import annotations

import glob
import importlib.util
import os

import numpy as np

MARKER = 1 << 62
HERE = os.path.dirname(os.path.abspath(__file__))
WORKTREE = os.path.normpath(os.path.join(HERE, "..", ".."))


def load_core(path: str | None = None):
    """The binding this worktree built (``setup.py build_ext --inplace``), loaded by path as ``dggs._core``."""
    so = path or glob.glob(os.path.join(WORKTREE, "dggs", "_core.cpython-*.so"))[0]
    spec = importlib.util.spec_from_file_location("dggs._core", so)
    core = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(core)
    return core


def build_ids(face: np.ndarray, level: np.ndarray, digits: np.ndarray) -> np.ndarray:
    """Ids from faces (N,), levels (N,) and digits (N, 29): column 1 the level-1 digit 0..5, then 0..2."""
    ids = np.full(face.shape[0], MARKER, dtype=np.uint64) | (face.astype(np.uint64) << np.uint64(57))
    has1 = level >= 1
    ids[has1] |= (digits[has1, 1].astype(np.uint64) + np.uint64(1)) << np.uint64(54)
    for lv in range(2, 29):
        on = level >= lv
        ids[on] |= (digits[on, lv].astype(np.uint64) + np.uint64(1)) << np.uint64(2 * (28 - lv))
    return ids


def random_ids(rng: np.random.Generator, n: int, levels=None) -> np.ndarray:
    """``n`` uniformly random valid ids; levels uniform over ``levels`` (default 0..28)."""
    lv = rng.choice(np.arange(29) if levels is None else np.asarray(levels), n)
    digits = rng.integers(0, 3, (n, 29))
    digits[:, 1] = rng.integers(0, 6, n)
    return build_ids(rng.integers(0, 20, n), lv, digits)


def corner_ids() -> np.ndarray:
    """Every face's cells that keep a corner or run along an edge: constant digit tails 0 or 2, each level."""
    out = []
    for f in range(20):
        for d1 in range(6):
            for tail in ((0,), (2,), (1,), (0, 2), (2, 0), (1, 2), (2, 1), (0, 1)):
                for level in range(0, 29):
                    digits = np.zeros((1, 29), dtype=np.int64)
                    digits[0, 1] = d1
                    for lv in range(2, 29):
                        digits[0, lv] = tail[(lv - 2) % len(tail)]
                    out.append(build_ids(np.array([f]), np.array([level]), digits)[0])
    return np.unique(np.array(out, dtype=np.uint64))


def point_ids() -> np.ndarray:
    """Cells at the poles, the antimeridian and the 12 vertices (and just off them), both projections."""
    import dggs
    from dggs.geometry.icosahedron import _VERTEX_LATLNG

    lat = [90.0, -90.0, 0.0, 0.0, 45.0, -45.0, 89.999999, -89.999999]
    lng = [0.0, 0.0, 180.0, -180.0, 179.9999999, -179.9999999, 180.0, 180.0]
    for la, lo in _VERTEX_LATLNG:
        for dla, dlo in ((0.0, 0.0), (1e-7, 0.0), (-1e-7, 0.0), (0.0, 1e-7), (0.0, -1e-7), (1e-3, 1e-3)):
            lat.append(max(-90.0, min(90.0, la + dla)))
            lng.append(lo + dlo)
    la, lo = np.array(lat), np.array(lng)
    out = []
    for grid in (dggs.Grid("ISEA"), dggs.Grid("IVEA")):
        for level in range(29):
            out.append(np.asarray(dggs.str_to_int(grid.latlng_to_cell(la, lo, level)), dtype=np.uint64))
    return np.unique(np.concatenate(out))


def edge_ids() -> np.ndarray:
    return np.unique(np.concatenate([corner_ids(), point_ids()]))


def level_of(ids: np.ndarray) -> np.ndarray:
    """Levels of valid ids (vectorised bits.level_of)."""
    low = ids & np.uint64((1 << 54) - 1)
    lv = np.where((ids >> np.uint64(54)) & np.uint64(7) != 0, 1, 0)
    for k in range(2, 29):
        lv = np.where((low >> np.uint64(2 * (28 - k))) & np.uint64(3) != 0, k, lv)
    return lv


def walk_pairs(rng: np.random.Generator, start: np.ndarray, steps: np.ndarray) -> np.ndarray:
    """Random walks from ``start`` over edge neighbours (numba's kernel), ``steps[i]`` steps each: the ends."""
    from dggs.index._kernel import grid as K

    cur = start.copy()
    nb = np.empty((cur.shape[0], 3), dtype=np.uint64)
    for s in range(int(steps.max()) if steps.size else 0):
        K.neighbours(cur, nb)
        pick = nb[np.arange(cur.shape[0]), rng.integers(0, 3, cur.shape[0])]
        cur = np.where(steps > s, pick, cur)
    return cur
