"""Freeze outputs of the numba pixel kernels (index/_kernel/pixels.py, clip.py) into libdggs/tests/test_pixels.c.

Rewrites the block between ``BEGIN FROZEN`` and ``END FROZEN`` of the test with C tables (floats as C99 hex-float
literals): small rasters of lng/lat pixels at the poles, on the antimeridian, at icosahedron vertices, on face edges
and anywhere, one at every level 0..28 with pixels about that level's cell size, and a few with cells much finer
than the pixels (equal shares of covered cells), k = 1, 2, 4 points an edge: each raster's grid_pieces (the first
pieces: pixel, cell, area; their count; coarse); chord_errors of pixels of every size at those places; and numba's
np.argsort (its quicksort: the order of ties) of arrays with ties and NaNs. ISEA only, as the kernel. The rasters'
points are rebuilt in the test by the same arithmetic (lat0 - d r, lng0 + d c). Run with the numba package
installed (the reference), from anywhere but this checkout's root::

    cd /tmp && python /path/to/libdggs/tools/freeze_pixels.py
"""

from __future__ import annotations

import math
import os
import re

import numpy as np
from numba import njit

from dggs.index._kernel import pixels as kpx

HERE = os.path.dirname(os.path.abspath(__file__))
TEST = os.path.join(os.path.dirname(HERE), "tests", "test_pixels.c")
PLACES = [(90.0, -1.0, "at the north pole"), (-89.0, 179.5, "near the south pole, across +-180"),
          (30.5, 179.7, "across the antimeridian"), (52.62263186, -144.01, "on a vertex"),
          (-10.8, 35.99, "on a vertex"), (31.7174744, 179.999, "on a face edge"), (26.57, -0.01, "on a vertex"),
          (12.3, 45.6, "anywhere"), (-67.8, -123.4, "anywhere")]
#: Pieces frozen per raster.
PIECES = 24


def h(x: float) -> str:
    """A double as a C99 hex-float literal (NAN spelled out)."""
    x = float(x)
    return "NAN" if math.isnan(x) else x.hex()


def u(c) -> str:
    """A uint64 as a C literal."""
    return f"0x{int(c):016x}ULL"


def grid(lat0: float, lng0: float, d: float, rows: int, cols: int, k: int):
    """hlat, hlng, vlat, vlng of rows x cols lng/lat pixels of side d from (lat0, lng0) (test_pixels.c's arithmetic)."""
    hr = np.arange(rows + 1, dtype=np.float64)[:, None] + np.zeros((1, cols * k + 1))
    hc = (np.arange(cols * k + 1) / k)[None, :] + np.zeros((rows + 1, 1))
    vr = (np.arange(rows * k + 1) / k)[:, None] + np.zeros((1, cols + 1))
    vc = np.arange(cols + 1, dtype=np.float64)[None, :] + np.zeros((rows * k + 1, 1))
    return lat0 - d * hr, lng0 + d * hc, lat0 - d * vr, lng0 + d * vc


def rasters() -> list[tuple]:
    """(lat0, lng0, d, rows, cols, k, level, valid bits, what) of the frozen rasters."""
    out = []
    for level in range(29):
        lat0, lng0, what = PLACES[level % len(PLACES)]
        side = 63.0 / math.sqrt(3.0) ** level  # about a level's cell side, degrees
        d = side * (0.6 + 0.3 * (level % 4))
        rows, cols, k = 2, 2, (1, 2, 4)[level % 3]
        if lat0 - rows * d < -90.0:
            lat0 = -90.0 + 2.5 * rows * d
        valid = 0b1111 if level % 5 else 0b1011
        out.append((lat0, lng0, d, rows, cols, k, level, valid, f"level {level}, {what}"))
    for level, place, factor in ((6, 0, 12.0), (9, 2, 20.0), (20, 3, 15.0), (28, 7, 9.0)):
        lat0, lng0, what = PLACES[place]
        d = 63.0 / math.sqrt(3.0) ** level * factor
        out.append((lat0, lng0, d, 1, 2, 2, level, 0b11, f"level {level}, {what}, pixels {factor} cells wide"))
    return out


@njit(cache=False)
def numba_argsort(a):
    """numba's np.argsort (quicksort)."""
    return np.argsort(a)


def main() -> None:
    """Rewrite the frozen block of test_pixels.c."""
    rs, pieces = [], []
    for lat0, lng0, d, rows, cols, k, level, bits, what in rasters():
        valid = np.array([[(bits >> (r * cols + c)) & 1 for c in range(cols)] for r in range(rows)], dtype=np.bool_)
        p, c, a, coarse = kpx.grid_pieces(*grid(lat0, lng0, d, rows, cols, k), k, valid, level)
        co = ", ".join(h(x) for x in coarse)
        rs.append(f"    {{{h(lat0)}, {h(lng0)}, {h(d)}, {rows}, {cols}, {k}, {level}, {bits}, {p.shape[0]}, "
                  f"{len(pieces)}, {{{co}}}}}, /* {what} */")
        for i in range(min(PIECES, p.shape[0])):
            pieces.append(f"    {{{int(p[i])}, {u(c[i])}, {h(a[i])}}},")
    # chord errors: pixels of 1e-4 .. 5 degrees at the places
    t = np.array([0.0, 0.25, 0.5, 0.75])
    dr = np.concatenate([0 * t, t, 1 + 0 * t, 1 - t])
    dc = np.concatenate([t, 1 + 0 * t, 1 - t, 0 * t])
    chords = []
    for i in range(36):
        lat0, lng0, _ = PLACES[i % len(PLACES)]
        d = 10.0 ** (-4 + (i % 6) * 0.74)
        if lat0 - d < -90.0:
            lat0 = -90.0 + 1.5 * d
        lat, lng = lat0 - d * dr, lng0 + d * dc
        e = kpx.chord_errors(lat[None, :], lng[None, :])[0]
        chords.append(f"    {{{h(lat0)}, {h(lng0)}, {h(d)}, {h(e)}}},")
    # argsort: ties and NaNs, below and above numba's insertion-sort size (15)
    rng = np.random.default_rng(7)
    sorts, values = [], []
    for n in (0, 1, 2, 5, 14, 15, 16, 17, 30, 31, 64, 100):
        a = rng.choice(np.array([0.25, 0.5, 0.75, 1.0, np.nan, -0.0, 0.0]), n)
        r = numba_argsort(a)
        sorts.append(f"    {{{n}, {len(values)}}},")
        values += [(h(a[i]), int(r[i])) for i in range(n)]
    block = (
        "/* BEGIN FROZEN (tools/freeze_pixels.py) */\n"
        f"#define FROZEN_PIECE_ROWS {PIECES}\n"
        "/* rasters: lat0, lng0, d (pixel side, degrees), rows, cols, k, level, valid (bit r cols + c), pieces,\n"
        " * first frozen piece, coarse (rows cols <= 4) */\n"
        "static const struct {\n    double lat0, lng0, d;\n    int rows, cols, k, level, valid, pieces, first;\n"
        "    double coarse[4];\n} FROZEN_RASTERS[] = {\n" + "\n".join(rs) + "\n};\n"
        "/* the first min(pieces, FROZEN_PIECE_ROWS) pieces of each raster: pixel, cell, planar area */\n"
        "static const struct {\n    int64_t pixel;\n    uint64_t cell;\n    double area;\n} FROZEN_PIECES[] = {\n"
        + "\n".join(pieces) + "\n};\n"
        "/* chord_errors of one pixel: lat0, lng0, d, error (points lat0 - d dr, lng0 + d dc round it) */\n"
        "static const struct {\n    double lat0, lng0, d, error;\n} FROZEN_CHORDS[] = {\n" + "\n".join(chords) + "\n};\n"
        "/* numba's np.argsort: arrays (count, first value) and their values with numba's order */\n"
        "static const struct {\n    int n, first;\n} FROZEN_SORTS[] = {\n" + "\n".join(sorts) + "\n};\n"
        "static const struct {\n    double value;\n    int64_t order;\n} FROZEN_SORT_VALUES[] = {\n"
        + "\n".join(f"    {{{v}, {r}}}," for v, r in values) + "\n};\n/* END FROZEN */"
    )
    with open(TEST) as f:
        text = f.read()
    text = re.sub(r"/\* BEGIN FROZEN.*?/\* END FROZEN \*/", lambda _: block, text, flags=re.S)
    with open(TEST, "w") as f:
        f.write(text)


if __name__ == "__main__":
    main()
