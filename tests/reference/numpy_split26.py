"""Numpy twins of the compiled Split (2:6) point location, kept as independent oracles for the tests.

They were :func:`dggs.geometry.split26.locate` and its helpers until issue 16
moved them out of the package (only tests used them): the package locates
points with the compiled kernel (:func:`dggs.geometry.kernel.level1_start`,
``descend``, ``descend4``).  The steps are the thesis's (§6.1.7), over arrays;
the tables come from :mod:`dggs.geometry.split26`.
"""

from __future__ import annotations

import numpy as np

from dggs.geometry.constants import SQRT3
from dggs.geometry.split26 import (
    AMBIGUOUS,
    GRID_H,
    GRID_W,
    JUMP_LEVELS,
    L1_C,
    L1_ROWS,
    LEVEL1,
    descend_rows,
    jump_table,
    level1_digit,
)

K = JUMP_LEVELS


def _jump(px: np.ndarray, py: np.ndarray, rows: np.ndarray, row: int):
    """K levels at once through the jump table; exact descent where it is ambiguous."""
    table, digit_rows, (a00, a01, a10, a11, b0, b1) = jump_table()
    # grid cell + 1 (the border), clipped: off-grid points land on the ambiguous border
    ix = np.clip(px * (GRID_W / SQRT3) + 1.0, 0.0, GRID_W + 1.0).astype(np.intp)
    iy = np.clip(py * GRID_H + 1.0, 0.0, GRID_H + 1.0).astype(np.intp)
    iy *= GRID_W + 2
    iy += ix
    code = table[iy]
    amb = np.flatnonzero(code == AMBIGUOUS)
    if amb.size:
        sub = np.empty((K, amb.size), dtype=np.uint8)
        descend_rows(px[amb], py[amb], K, sub, 0)
        code[amb] = 3 ** np.arange(K - 1, -1, -1) @ sub.astype(np.intp)
    for j in range(K):
        rows[row + j] = digit_rows[j][code]
    return a00[code] * px + a01[code] * py + b0[code], a10[code] * px + a11[code] * py + b1[code]


def _start(x: np.ndarray, y: np.ndarray, level: int):
    """Digit rows (level, N) with the level-1 digits filled, and the points in their level-1 canonical frame."""
    rows = np.empty((max(level, 0), x.shape[0]), dtype=np.uint8)
    if level <= 0:
        return rows, None, None
    d = level1_digit(x, y)
    rows[0] = d
    dx, dy = x - L1_C[d, 0], y - L1_C[d, 1]
    m = L1_ROWS[d]
    return rows, m[:, 0, 0] * dx + m[:, 0, 1] * dy, m[:, 1, 0] * dx + m[:, 1, 1] * dy


def locate(x: np.ndarray, y: np.ndarray, level: int) -> np.ndarray:
    """Digits (N, level) uint8 of the level-``level`` cells holding face-frame points.

    Column 0 holds the level-1 digit (0..5), later columns 0..2.  Points on a
    shared edge go to one side by fixed comparisons (child 1 wins its two
    internal edges), so the same point always gets the same cell.  Four
    levels at a time go through the jump table, which reproduces the
    per-level comparisons exactly (points near a cell edge take the
    per-level path).

    Examples
    --------
    >>> locate(np.array([0.01]), np.array([0.2]), 3).tolist()
    [[0, 1, 2]]
    """
    rows, px, py = _start(x, y, level)
    if level <= 0:
        return rows.T
    row = 1
    while level - row >= K:
        px, py = _jump(px, py, rows, row)
        row += K
    descend_rows(px, py, level - row, rows, row)
    return rows.T


def locate_per_level(x: np.ndarray, y: np.ndarray, level: int) -> np.ndarray:
    """:func:`locate` without the jump table: one exact step per level."""
    rows, px, py = _start(x, y, level)
    if level <= 0:
        return rows.T
    descend_rows(px, py, level - 1, rows, 1)
    return rows.T


def cell_vertices_per_level(l1: np.ndarray, digits: np.ndarray, levels: np.ndarray | None = None):
    """Reference for :func:`dggs.geometry.split26.cell_vertices`: D and E level by level (thesis §6.1.7)."""
    tri = LEVEL1[l1]
    a, b, c = tri[:, 0].copy(), tri[:, 1].copy(), tri[:, 2].copy()
    for col in range(digits.shape[1]):
        dig = digits[:, col]
        dpt = c + (a - c) / 3.0  # D: a third of the way from C to A
        ept = 0.5 * (a + b)  # E: the midpoint of AB
        active = None if levels is None else (levels > col + 1)
        na = np.where((dig == 2)[:, None], a, b)
        nb = dpt
        nc = np.where((dig == 0)[:, None], c, ept)
        if active is None:
            a, b, c = na, nb, nc
        else:
            m = active[:, None]
            a, b, c = np.where(m, na, a), np.where(m, nb, b), np.where(m, nc, c)
    return a, b, c
