"""Freeze outputs of the numba edge kernels (index/_kernel/edges.py, ivea_edges.py) into libdggs/tests/test_edges.c.

Rewrites the block between ``BEGIN FROZEN`` and ``END FROZEN`` of the test with a C table (floats as C99 hex-float
literals): for cells at the poles, on the antimeridian, at icosahedron vertices, on face edges and at random points,
at every level 0..27, one directed edge each: its origin, destination, reverse, length (metres and radians) and
boundary with one point between its corners, on both projections. Run with the numba package installed (the
reference), from anywhere but this checkout's root::

    cd /tmp && python /path/to/libdggs/tools/freeze_edges.py
"""

from __future__ import annotations

import math
import os
import re

import numpy as np

import dggs
from dggs.index._kernel import edges as ke
from dggs.index._kernel import ivea_edges as kie

HERE = os.path.dirname(os.path.abspath(__file__))
TEST = os.path.join(os.path.dirname(HERE), "tests", "test_edges.c")
PLACES = [(90.0, 0.0, "north pole"), (-90.0, 0.0, "south pole"), (0.0, 180.0, "antimeridian"),
          (-45.0, -180.0, "antimeridian 45S"), (52.62263186, -180.0, "vertex"), (-10.81231696, 36.0, "vertex"),
          (31.7174744, 180.0, "face edge"), (26.56505118, 0.0, "vertex"), (12.3, 45.6, "anywhere"),
          (-67.8, -123.4, "anywhere")]


def h(x: float) -> str:
    """A double as a C99 hex-float literal (NAN spelled out)."""
    x = float(x)
    return "NAN" if math.isnan(x) else x.hex()


def u(c) -> str:
    """A uint64 as a C literal."""
    return f"0x{int(c):016x}ULL"


def rows() -> list[str]:
    """One C initialiser per frozen edge."""
    out = []
    for level in range(28):
        for j in range(2):
            lat, lng, what = PLACES[(2 * level + j) % len(PLACES)]
            cell = np.uint64(dggs.latlng_to_cell(lat, lng, level, as_int=True))
            d = (level + j) % 3
            edge = int(ke.edge_of(cell, d))
            o, dest = ke.one_ends(edge)
            rev = ke.one_reverse(edge)
            mi, ri = ke.one_length(edge, 16)
            mv, rv = kie.one_length(np.uint64(edge), 16)
            e = np.array([edge], dtype=np.uint64)
            bi, bv = np.empty((1, 3, 2)), np.empty((1, 3, 2))
            ke.boundaries(2, e, 1, bi)
            kie.boundaries(2, e, 1, bv)
            pts = ", ".join(h(x) for x in list(bi.ravel()) + list(bv.ravel()))
            out.append(f"    {{{u(edge)}, {u(o)}, {u(dest)}, {u(rev)}, {h(mi)}, {h(ri)}, {h(mv)}, {h(rv)},\n"
                       f"     {{{pts}}}}}, /* level {level}, {what}, direction {d} */")
    return out


def main() -> None:
    """Rewrite the frozen block of test_edges.c."""
    block = (
        "/* BEGIN FROZEN (tools/freeze_edges.py) */\n"
        "/* edge, origin, destination, reverse; length (m, rad) ISEA, IVEA; boundary (densify 1: 3 (lat, lng)) ISEA then\n"
        " * IVEA */\n"
        "static const struct {\n    uint64_t edge, origin, destination, reverse;\n"
        "    double m_isea, rad_isea, m_ivea, rad_ivea;\n    double boundary[12];\n} FROZEN_EDGES[] = {\n"
        + "\n".join(rows()) + "\n};\n/* END FROZEN */"
    )
    with open(TEST) as f:
        text = f.read()
    text = re.sub(r"/\* BEGIN FROZEN.*?/\* END FROZEN \*/", lambda _: block, text, flags=re.S)
    with open(TEST, "w") as f:
        f.write(text)


if __name__ == "__main__":
    main()
