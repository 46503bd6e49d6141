"""Chapter 4 of the thesis: its published values (Tables 4.1-4.3) and the constants of our reproduction.

Shared by the chapter-4 modules (:mod:`dggs.experiments.chapter4` and its
``chapter4_*`` parts).
"""

from __future__ import annotations

import math

__all__ = [
    "THESIS_TABLE_4_1",
    "THESIS_TABLE_4_2",
    "THESIS_TABLE_4_3",
    "EARTH_RADIUS_M",
    "THESIS_EARTH_RADIUS_M",
    "QUALITIES",
    "TOL",
    "TOLERANCES",
]

# ----------------------------------------------------------------------------
# The thesis's published values (transcribed from the thesis text)
# ----------------------------------------------------------------------------
#: thesis Table 4.1 "Polynomial Approximating Azimuthal Shift": degree -> (SS, variance).
THESIS_TABLE_4_1: dict[int, tuple[float, float]] = {
    1: (1.19e00, 2.02e-04),
    2: (9.27e-01, 1.66e-04),
    3: (2.30e-04, 3.92e-08),
    4: (2.06e-04, 3.51e-08),
    5: (2.51e-05, 4.28e-09),
    6: (2.20e-05, 3.75e-09),
    7: (9.06e-07, 1.55e-10),
}

#: thesis Table 4.2 "Profiling Results": quality -> method -> (avg iterations, avg time s,
#: std dev s, time improvement %, iteration improvement %); ``None`` where empty.
THESIS_TABLE_4_2: dict[int, dict[str, tuple[float, float, float, float | None, float | None]]] = {
    25: {"O": (3.61, 0.0082, 0.0083, None, None), "I": (2.76, 0.0059, 0.0081, 28.05, 23.66),
         "E": (0.0, 0.0035, 0.0058, 57.32, None)},
    50: {"O": (3.70, 0.0229, 0.0149, None, None), "I": (2.82, 0.0205, 0.0131, 10.48, 23.83),
         "E": (0.0, 0.0138, 0.0113, 39.74, None)},
    75: {"O": (3.74, 0.0546, 0.0222, None, None), "I": (2.81, 0.0509, 0.0217, 6.78, 24.72),
         "E": (0.0, 0.0310, 0.0167, 43.22, None)},
    100: {"O": (3.75, 0.0996, 0.0329, None, None), "I": (2.83, 0.0832, 0.0292, 16.47, 24.50),
          "E": (0.0, 0.0524, 0.0209, 47.39, None)},
}

#: thesis Table 4.3 "Error Analysis of Elimination Approach" (cubic), as printed:
#: quality -> (avg dist. error, max dist. error, avg area error %, max area error %).
#: The distance columns carry no unit in the table; the text calls 9.379e-05 a percentage.
THESIS_TABLE_4_3: dict[int, tuple[float, float, float, float]] = {
    25: (9.379e-05, 6.193e-04, 1.982e-05, 1.596e-02),
    50: (9.439e-05, 6.193e-04, 9.223e-06, 2.195e-02),
    75: (9.459e-05, 6.193e-04, 3.330e-06, 3.504e-02),
    100: (9.490e-05, 6.193e-04, 1.758e-06, 5.073e-02),
}

#: Earth radius we use for metres (IUGG mean radius).  The thesis used 6,369 km (§4.2).
EARTH_RADIUS_M = 6_371_000.0
THESIS_EARTH_RADIUS_M = 6_369_000.0
#: thesis §4.2: "Resolution levels 25, 50, 75 and 100 were profiled".
QUALITIES = (25, 50, 75, 100)
#: Newton tolerance on the step (radians): the library default.  PROJ stops at 1e-11
#: degrees (1.745e-13 rad); DGGRID at 5e-13 rad.  The thesis's is unknown.
TOL = 1e-13
#: Tolerances of the iteration-versus-tolerance check (radians).
TOLERANCES = (1e-13, math.radians(1e-11), 1e-10, 1e-8)

_SECTOR = 2.0 * math.pi / 3.0  # Az runs over 120-degree sectors, vertex to vertex
_HALF = math.pi / 3.0
_SECTOR_AREA = math.pi / 15.0  # a third of the face area pi / 5 (unit sphere)
