"""Constants of Snyder's icosahedral projection, defined once for the whole geometry package.

The ground floor of :mod:`dggs.geometry`: plain floats and small numpy arrays,
no imports from the package.  :mod:`.snyder`, :mod:`.split26` and the compiled
:mod:`.kernel` all read them from here.

Snyder, J. P. (1992), "An equal-area map projection for polyhedral globes",
Cartographica 29(1): 10-21, Table 1 (icosahedron); the same values as PROJ's
``+proj=isea`` (``isea.cpp``) and thesis §3.1.3.

Examples
--------
>>> round(math.degrees(G_ARC), 10), round(R_PRIME, 10)
(37.3773681406, 0.9103832815)
"""

from __future__ import annotations

import math

import numpy as np

__all__ = [
    "TAN_G",
    "G_ARC",
    "G",
    "THETA",
    "COT_THETA",
    "FACE_CIRCUMRADIUS",
    "R_PRIME",
    "FACE_INRADIUS",
    "FACE_EDGE",
    "SQRT3",
]

# Snyder 1992, Table 1 (icosahedron).
TAN_G = 3.0 - math.sqrt(5.0)  # g: arc from face centre to vertex, tan g = 3 - sqrt 5
G_ARC = math.atan(TAN_G)  # g = 37.3773681406 degrees
G = math.pi / 5  # G = 36 degrees (the thesis's "46" is a typo)
THETA = math.pi / 6  # theta = 30 degrees
COT_THETA = math.sqrt(3.0)
#: Planar circumradius of a face: sqrt(4 pi / (15 sqrt 3)) so the face has area pi / 5.
FACE_CIRCUMRADIUS = math.sqrt(4 * math.pi / (15 * math.sqrt(3.0)))
#: R' / R = 0.9103832815 (Snyder 1992, eq. 3.1 = 3.2 solved for R').
R_PRIME = FACE_CIRCUMRADIUS / TAN_G
#: Planar inradius of a face (centre to edge midpoint).
FACE_INRADIUS = FACE_CIRCUMRADIUS / 2
#: Planar edge length of a face.
FACE_EDGE = FACE_CIRCUMRADIUS * math.sqrt(3.0)
SQRT3 = math.sqrt(3.0)

# Derived terms of Snyder's eqs. 6-12.
SIN_G, COS_G = math.sin(G), math.cos(G)
COS_SMALL_G = math.cos(G_ARC)
RT2 = (R_PRIME * TAN_G) ** 2  # R'^2 tan^2 g (eq. 8)
D_PRIME_NUM = R_PRIME * TAN_G  # numerator of d' (eq. 10)
TAN_G2 = TAN_G * TAN_G

#: Az runs over 120-degree sectors, vertex to vertex (Snyder 1992, §"Forward").
SECTOR = 2 * math.pi / 3
#: cos and sin of 120 k degrees, k = 0, 1, 2: turn a point into sector 0 and back.
ROT_COS = np.cos(SECTOR * np.arange(3))
ROT_SIN = np.sin(SECTOR * np.arange(3))
#: Planar distances below TINY are scaled by UNTINY before 1 / rho (1 / rho would overflow).
TINY = 2.0**-500
UNTINY = 2.0**600
