"""The thesis's published values for chapters 5 and 6, transcribed by hand.

Source: "Equal Area Spherical Subdivision", Table 5.1 (§5.1.9) and
Tables 6.1-6.7 (§6.3).  Rows are keyed by our scheme names; each row lists
levels 1, 2, ... as printed (``None`` where a cell is empty).  Values are in
the units of the table (percent without the ``%`` sign, km, km^2).  Known
typos are kept as printed and flagged in :data:`NOTES`.

Examples
--------
>>> TABLE_6_6["1:4"][:4]
(13.42, 18.64, 20.14, 20.53)
>>> TABLE_6_2["1:5"][0]
32
"""

from __future__ import annotations

from collections.abc import Mapping

__all__ = [
    "TABLE_5_1",
    "TABLE_6_1",
    "TABLE_6_2",
    "TABLE_6_3",
    "TABLE_6_4",
    "TABLE_6_5",
    "TABLE_6_6",
    "TABLE_6_7",
    "TABLES_6",
    "DGGS_BEST_MAX_FACE_ERROR_PCT",
    "NOTES",
]

#: Table 5.1 "Length Analysis": (initial, 2 iterations, 3 iterations, error %).
TABLE_5_1: dict[str, tuple[float, float, float, float]] = {
    "triangle": (442.709, 442.709, 442.708, 2.26e-4),
    "circumscribed quadrilateral": (456.760, 442.797, 456.765, 3.05),
    "convex pentagon": (803.23, 803.359, 803.283, 6.60e-3),
}

#: Table 6.1 "Global Area Preservation Results - Percent Deviation (%)".
TABLE_6_1: dict[str, tuple[float, ...]] = {
    "1:4": (-2.49e-06, -2.33e-06, -9.00e-07, -8.26e-07, 6.68e-07, 1.90e-06),
    "1:9": (-3.89e-08, 9.05e-07, 6.44e-08),
    "1:3": (6.23e-07, -2.80e-06, 1.95e-07, 2.09e-06, -5.54e-07, 4.54e-07, -3.98e-06),
    "1:6": (2.49e-06, -2.14e-06, 1.06e-06, -2.08e-07),
    "2:6": (2.49e-06, 1.48e-06, 4.28e-07, 2.41e-06, -4.50e-07, 9.80e-07, -2.66e-06),
    "1:5": (12.47, 17.12, 18.70, 19.24, 19.42, 19.48, 19.50),
    "catmull-clark": (55.78, -11.16, 49.75, -12.05, 49.36, -12.11),
}

#: Table 6.2 "Face Count".
TABLE_6_2: dict[str, tuple[int, ...]] = {
    "1:4": (80, 320, 1280, 5120, 20480, 81920),
    "1:9": (180, 1620, 14580),
    "1:3": (60, 180, 540, 1620, 4860, 14580, 43740),
    "1:6": (120, 720, 4320, 25920),
    "2:6": (120, 360, 1080, 3240, 9720, 29160, 87480),
    "1:5": (32, 92, 272, 812, 2432, 7292, 21872),
    "catmull-clark": (60, 240, 960, 3840, 15360, 61440),
}

#: Table 6.3 "Average Spherical Displacement (%)".
TABLE_6_3: dict[str, tuple[float, ...]] = {
    "1:4": (5.84, 1.51, 0.38, 0.10, 0.02, 0.01),
    "1:9": (2.66, 0.30, 0.03),
    "1:3": (11.35, 6.33, 3.53, 1.97, 1.10, 0.61, 0.34),
    "1:6": (4.79, 1.07, 0.24, 0.05),
    "2:6": (4.79, 1.74, 0.60, 0.20, 0.07, 0.02, 0.01),
    "1:5": (7.64, 2.64, 0.89, 0.30, 0.10, 0.00, 0.01),
    "catmull-clark": (5.31, 1.32, 0.33, 0.08, 0.02, 0.01),
}

#: Table 6.4 "Maximumal [sic] Spherical Displacement (%)".
TABLE_6_4: dict[str, tuple[float, ...]] = {
    "1:4": (6.58, 1.78, 0.45, 0.11, 0.03, 0.01),
    "1:9": (2.86, 0.33, 0.04),
    "1:3": (11.35, 10.15, 9.98, 9.96, 9.96, 9.96, 9.96),
    "1:6": (4.79, 1.49, 0.53, 0.19),
    "2:6": (4.79, 1.86, 0.67, 0.23, 0.08, 0.03, 0.01),
    "1:5": (8.09, 2.77, 0.98, 0.33, 0.11, 0.04, 0.01),
    "catmull-clark": (5.31, 1.76, 0.55, 0.17, 0.05, 0.02),
}

#: Table 6.5 "Absolute Spherical Displacement (km)" (average, 6,371 km Earth).
TABLE_6_5: dict[str, tuple[float, ...]] = {
    "1:4": (372.31, 96.27, 24.27, 6.08, 1.52, 0.38),
    "1:9": (169.68, 19.19, 2.14),
    "1:3": (723.06, 403.10, 224.89, 125.37, 69.83, 38.87, 21.63),
    "1:6": (304.98, 68.44, 15.24, 3.39),
    "2:6": (304.98, 110.65, 37.96, 12.78, 4.28, 1.43, 0.48),
    "1:5": (486.97, 168.23, 56.85, 19.06, 6.37, 2.13, 0.71),
    "catmull-clark": (338.15, 84.25, 20.98, 5.24, 1.31, 0.33),
}

#: Table 6.6 "Maximum Face Areal Error (%)".
TABLE_6_6: dict[str, tuple[float, ...]] = {
    "1:4": (13.42, 18.64, 20.14, 20.53, 20.62, 20.65),
    "1:9": (8.12, 9.51, 9.67),
    "1:3": (0.00, 33.73, 172.39, 552.13, 1469.73, 3619.13, 8525.78),
    "1:6": (0.00, 2.81, 5.39, 8.84),
    "2:6": (0.00, 0.21, 2.28, 5.37, 8.92, 12.96, 16.63),
    "1:5": (22.17, 23.77, 35.34, 48.83, 59.60, 68.12, 74.84),
    "catmull-clark": (55.78, 40.04, 145.48, 75.65, 261.67, 157.67),
}

#: Table 6.7 "Maximum Face Areal Error - Absolute (km^2)" (510,072,000 km^2 Earth).
TABLE_6_7: dict[str, tuple[float, ...]] = {
    "1:4": (8.56e05, 2.97e05, 8.02e04, 2.04e04, 5.14e03, 1.29e03),
    "1:9": (2.30e05, 2.99e04, 3.38e03),
    "1:3": (85.0, 9.56e05, 1.63e06, 1.74e06, 1.54e06, 1.27e06, 9.94e05),
    "1:6": (42.5, 1.99e04, 6.36e03, 1.74e03),
    "2:6": (42.5, 3.02e03, 1.08e04, 8.45e03, 4.68e03, 2.27e04, 970.0),
    "1:5": (3.97e06, 1.54e06, 7.87e05, 3.66e05, 1.49e05, 5.69e05, 2.09e04),
    "catmull-clark": (7.38e06, 7.56e05, 1.16e06, 8.84e04, 1.30e05, 1.15e04),
}

#: All chapter-6 tables by number, with their captions.
TABLES_6: dict[str, tuple[str, Mapping[str, tuple[float, ...]]]] = {
    "6.1": ("Global area deviation (%)", TABLE_6_1),
    "6.2": ("Face count", TABLE_6_2),
    "6.3": ("Average spherical displacement (%)", TABLE_6_3),
    "6.4": ("Maximum spherical displacement (%)", TABLE_6_4),
    "6.5": ("Average spherical displacement (km)", TABLE_6_5),
    "6.6": ("Maximum face area error (%)", TABLE_6_6),
    "6.7": ("Maximum face area error (km^2)", TABLE_6_7),
}

#: The thesis's best maximum face error (Split 2:6, level 7; Table 6.6 and §8).
DGGS_BEST_MAX_FACE_ERROR_PCT = 16.63

#: Inconsistencies in the printed tables, as found while transcribing.
NOTES: tuple[str, ...] = (
    "Table 6.7, 2:6 level 6 prints 2.27e04 km^2; Table 6.6's 12.96 % of "
    "510,072,000/29,160 km^2 is 2.27e03 (a factor-10 slip).",
    "Table 6.6, 2:6 level 6 prints 12.96 %; the thesis's own rule gives 12.69 %: likely transposed "
    "digits (every other cell of the row reproduces and 12.69 continues its steps), not proven: "
    "Table 6.7's 2.27e04 carries 12.96's digits (12.96 % of a face is 2,267 km^2, 12.69 % 2,220).",
    "Table 6.7, 1:5 level 6 prints 5.69e05 km^2, a typo for 5.69e04.",
    "Table 6.7, 1:3 and 1:6 level 1 print 85.0 and 42.5 km^2 where Table 6.6 "
    "prints 0.00 %: about 1e-5 relative, the thesis's floating-point noise.",
    "Table 6.7 is Table 6.6 times the mesh's total area, Earth (1 + Table 6.1) / F: "
    "so Catmull-Clark level 1 (55.78 % of 1.5578 Earth / 60 = 7.39e06, printed 7.38e06) "
    "and 1:5 level 1 (3.97e06) follow from Tables 6.1 and 6.6.",
    "Table 6.3, 1:5 level 6 prints 0.00 % between 0.10 % and 0.01 %; Table 6.5 "
    "(2.13 km = 0.03 %) suggests 0.03.",
    "§6.4.2 says Table 6.1 shows Split (1:3)'s 8,525 % error; it is Table 6.6.",
    "Table 5.1's error column is the level-3 error for the triangle and pentagon "
    "but the level-2 error (3.05 %) for the quadrilateral.",
)
