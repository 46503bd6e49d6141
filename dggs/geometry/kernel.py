"""The geometry kernel, one point or one planar triangle at a time: compiled C, libdggs/src/geometry.c.

The per-point functions of the standard grid and of any orientation (Snyder 1992, eqs. 6-14, with the
closed-form inverse azimuth derived in thesis chapter 4; the authalic series of :mod:`.authalic`, Karney 2023;
the Split (2:6) steps of :mod:`.split26`, thesis §6.1.7) live in the C core (``libdggs/src/geometry.c``) and are
re-exported here from :mod:`dggs._core` under their old names, as plain Python functions over Python floats and
ints.  The C core reads the tables below from ``libdggs/src/tables.c``, which ``libdggs/tools/gen_tables.py``
writes from this module and the modules it imports (run it after changing any of them).

This module sits below :mod:`.snyder`: it reads its constants from :mod:`.constants` and its tables from
:mod:`.authalic`, :mod:`.icosahedron` and :mod:`.split26`, and imports nothing above them.  Functions that take
an orientation's tables take them as C-contiguous float64 arrays: ``centres`` (20, 3), ``frames`` (20, 3, 3).

Examples
--------
>>> face, x, y = forward_unit(ISEA_CENTRES, ISEA_FRAMES, 0.0, 0.0, 1.0)
>>> face
0
>>> p = inverse_unit(ISEA_FRAMES, face, x, y)
>>> [abs(round(v, 12)) for v in p]
[0.0, 0.0, 1.0]
"""

from __future__ import annotations

import os

import numpy as np

from dggs._core import (
    authalic_sincos,
    child_corners,
    descend,
    descend4,
    geodetic_to_unit,
    level1_digit,
    level1_start,
    nearest_face,
    sector_forward,
    sector_of,
    snyder_forward_rad,
    snyder_inverse_deg,
    unit_to_geodetic,
    wrap_degrees,
)
from dggs._core import snyder_face_forward as face_forward
from dggs._core import snyder_forward_unit as forward_unit
from dggs._core import snyder_inverse_unit as inverse_unit

from .authalic import WGS84
from .constants import SQRT3
from .icosahedron import ISEA, NUM_FACES, TIE_STEP
from .split26 import CHILD_M as _CHILD_M
from .split26 import CHILD_T as _CHILD_T
from .split26 import FACE_VERTICES, GRID_W, LEVEL1, jump_table
from .split26 import L1_C as _L1_C
from .split26 import L1_ROWS as _L1_ROWS

__all__ = [
    "wrap_degrees",
    "unit_to_geodetic",
    "authalic_sincos",
    "geodetic_to_unit",
    "nearest_face",
    "sector_forward",
    "forward_unit",
    "face_forward",
    "sector_of",
    "inverse_unit",
    "level1_digit",
    "level1_start",
    "descend",
    "descend4",
    "child_corners",
    "forward_rad",
    "inverse_deg",
    "jump_constants",
    "write_jump_file",
    "ISEA_CENTRES",
    "ISEA_FRAMES",
    "TIE_BIAS",
    "TO_AUTHALIC",
    "TO_GEODETIC",
    "L1_C",
    "L1_ROWS",
    "CHILD_M",
    "CHILD_T",
    "LEVEL1_CORNERS",
    "JUMP_FILE",
    "JUMP_TABLE",
    "JUMP_PACKED",
    "JUMP_MAPS",
    "FACE_CORNERS_CCW",
]

#: The batch loops of the checked API (:mod:`._checked`): ``forward_rad(n, lat, lng, centres, frames, face, x, y)``
#: (radians on the sphere in; face, face-frame x, y out) and ``inverse_deg(n, face, x, y, frames, lat, lng)``.
#: ``n`` is the amount of work (threads from ``dggs._core.PARALLEL_MIN`` on).  Static methods (callable since
#: Python 3.10), so that a class attribute holding one (``snyder.Projection.forward_rad``) is not bound as a method.
forward_rad = staticmethod(snyder_forward_rad)
inverse_deg = staticmethod(snyder_inverse_deg)

# The standard grid's tables (the C core's copies are tables.c, generated from these).
ISEA_CENTRES = np.ascontiguousarray(ISEA.geometry.centres)
ISEA_FRAMES = np.ascontiguousarray(ISEA.geometry.frames)
TIE_BIAS = -TIE_STEP * np.arange(NUM_FACES, dtype=np.float64)
TO_AUTHALIC = np.ascontiguousarray(WGS84.to_authalic_series)
TO_GEODETIC = np.ascontiguousarray(WGS84.to_geodetic_series)
L1_C = np.ascontiguousarray(_L1_C)
L1_ROWS = np.ascontiguousarray(_L1_ROWS)
CHILD_M = np.ascontiguousarray(_CHILD_M)
CHILD_T = np.ascontiguousarray(_CHILD_T)
LEVEL1_CORNERS = np.ascontiguousarray(LEVEL1)


def jump_constants() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """split26's 4-level jump table as flat arrays: cell codes, packed digit codes, maps (computed, ~0.5 s).

    Returns
    -------
    table : ndarray of uint8
        Per grid cell, the level-4 code or ``split26.AMBIGUOUS``.
    packed : ndarray of uint64, (81,)
        Each code's 4 digit codes (digit + 1), 2 bits each, first level highest.
    maps : ndarray, (81, 6)
        Each code's map ``(a00, a01, a10, a11, b0, b1)``.
    """
    table, digit_rows, coef = jump_table()
    # the 4 digit codes (digit + 1) of each path, packed 2 bits each, first level highest
    packed = np.zeros(81, dtype=np.uint64)
    for j in range(4):
        packed = (packed << np.uint64(2)) | (digit_rows[j].astype(np.uint64) + np.uint64(1))
    return np.ascontiguousarray(table), packed, np.ascontiguousarray(np.stack(coef, axis=1))


#: The jump table shipped with the package, so that import does not recompute it
#: (tests/test_hierarchy.py checks it equals :func:`jump_constants`;
#: :func:`write_jump_file` rewrites it; libdggs/tools/gen_tables.py copies it into the C core).
JUMP_FILE = os.path.join(os.path.dirname(__file__), "jump_table.npz")


def _load_jump_constants() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    try:
        with np.load(JUMP_FILE) as data:
            return data["table"], data["packed"], data["maps"]
    except (OSError, KeyError, ValueError):  # missing or unreadable: compute it
        return jump_constants()


JUMP_TABLE, JUMP_PACKED, JUMP_MAPS = _load_jump_constants()
_JUMP_SX = GRID_W / SQRT3
_JUMP_W2 = GRID_W + 2
#: A base cell's corners counter-clockwise: the face vertices in reverse (azimuth) order.
FACE_CORNERS_CCW = np.ascontiguousarray(FACE_VERTICES[::-1])


def write_jump_file() -> None:
    """Rewrite the shipped jump table from :func:`jump_constants` (after a change to split26).

    Then run ``libdggs/tools/gen_tables.py`` and rebuild, so that the C core's copy follows.
    """
    table, packed, maps = jump_constants()
    np.savez_compressed(JUMP_FILE, table=table, packed=packed, maps=maps)
