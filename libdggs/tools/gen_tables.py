"""Write libdggs/src/tables.h and tables.c from the Python geometry floor, so that no constant is ever retyped.

Every float is written as a C99 hex-float literal (``float.hex()``), the exact double the Python kernel uses:
the WGS84 authalic series (dggs.geometry.authalic), PROJ's ISEA orientation (dggs.geometry.icosahedron),
Snyder's constants (dggs.geometry.constants), the Split (2:6) matrices and the jump table
(dggs.geometry.split26, dggs/geometry/jump_table.npz through dggs.geometry.kernel) and IVEA's module constants
(dggs.geometry.ivea).

Run from the repository root, after any change to those modules::

    .venv/bin/python libdggs/tools/gen_tables.py

The kernel modules are imported with a stand-in for ``dggs._core`` (their compiled entries are not needed to
read their constants, and the extension may not be built yet).
"""

from __future__ import annotations

import math
import os
import sys
import types

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SRC = os.path.join(ROOT, "libdggs", "src")


def _stub_core() -> None:
    """Let ``from dggs._core import ...`` succeed without the extension (only constants are read here)."""
    if "dggs._core" in sys.modules:
        return
    stub = types.ModuleType("dggs._core")

    def __getattr__(name: str):  # noqa: N807 - PEP 562 module attribute hook
        if name.startswith("__"):
            raise AttributeError(name)
        return None

    stub.__getattr__ = __getattr__  # type: ignore[method-assign]
    sys.modules["dggs._core"] = stub


def fhex(v: float) -> str:
    """A double as a C99 hex-float literal (parenthesised when negative)."""
    v = float(v)
    if not math.isfinite(v):
        raise ValueError(f"not finite: {v!r}")
    s = v.hex()
    return f"({s})" if s.startswith("-") else s


def flat_doubles(arr: np.ndarray, per_line: int = 3) -> str:
    """A 1-d array of doubles as initialiser lines of hex floats."""
    vals = [fhex(v).strip("()") for v in np.asarray(arr, dtype=np.float64).ravel()]
    lines = [", ".join(vals[i:i + per_line]) for i in range(0, len(vals), per_line)]
    return "    " + ",\n    ".join(lines)


def flat_ints(arr: np.ndarray, per_line: int = 32, fmt: str = "%d") -> str:
    """A 1-d array of integers as initialiser lines."""
    vals = [fmt % int(v) for v in np.asarray(arr).ravel()]
    lines = [",".join(vals[i:i + per_line]) for i in range(0, len(vals), per_line)]
    return "    " + ",\n    ".join(lines)


def nested(data: np.ndarray, ctype: str) -> str:
    """A row of a multi-dimensional array as a braced initialiser (every level braced)."""
    if data.ndim == 1:
        vals = [fhex(v).strip("()") if ctype == "double" else str(int(v)) for v in data]
        return "{" + ", ".join(vals) + "}"
    return "{" + ", ".join(nested(row, ctype) for row in data) + "}"


def main() -> int:
    """Write tables.h and tables.c; the exit code."""
    sys.path.insert(0, ROOT)
    _stub_core()
    from dggs.geometry import constants as C
    from dggs.geometry import icosahedron, split26
    from dggs.geometry import ivea as V
    from dggs.geometry import kernel as K
    from dggs.geometry.authalic import WGS84

    geo = icosahedron.ISEA.geometry
    nf = icosahedron.NUM_FACES
    table, packed, maps = K.JUMP_TABLE, K.JUMP_PACKED, K.JUMP_MAPS
    assert table.dtype == np.uint8 and table.shape == ((split26.GRID_H + 2) * (split26.GRID_W + 2),)
    assert packed.dtype == np.uint64 and packed.shape == (81,) and maps.shape == (81, 6)
    ts = np.ascontiguousarray(WGS84.to_authalic_series)
    tg = np.ascontiguousarray(WGS84.to_geodetic_series)
    tie_bias = -icosahedron.TIE_STEP * np.arange(nf, dtype=np.float64)  # kernel.TIE_BIAS's expression
    assert np.array_equal(tie_bias, K.TIE_BIAS)

    # (name, value, comment); doubles are hex floats, ints decimal
    scalars: list[tuple[str, object, str]] = [
        ("DGGS_PI", math.pi, "math.pi"),
        ("DGGS_TWO_PI", 2.0 * math.pi, "kernel._TWO_PI"),
        ("DGGS_RAD_PER_DEG", math.pi / 180, "math.radians(x) = x * (pi / 180) in numba"),
        ("DGGS_DEG_PER_RAD", 180 / math.pi, "math.degrees(x) = x * (180 / pi) in numba"),
        ("DGGS_SQRT3", C.SQRT3, "constants.SQRT3"),
        ("DGGS_HALF_SQRT3", 0.5 * C.SQRT3, "kernel._HALF_SQRT3"),
        ("DGGS_TAN_G", C.TAN_G, "constants.TAN_G: tan g, g the arc from a face centre to a vertex"),
        ("DGGS_G_ARC", C.G_ARC, "constants.G_ARC: g"),
        ("DGGS_G", C.G, "constants.G: 36 degrees"),
        ("DGGS_COT_THETA", C.COT_THETA, "constants.COT_THETA"),
        ("DGGS_SIN_G", C.SIN_G, "constants.SIN_G: sin G"),
        ("DGGS_COS_G", C.COS_G, "constants.COS_G: cos G"),
        ("DGGS_COS_SMALL_G", C.COS_SMALL_G, "constants.COS_SMALL_G: cos g"),
        ("DGGS_RT2", C.RT2, "constants.RT2: R'^2 tan^2 g (Snyder eq. 8)"),
        ("DGGS_D_PRIME_NUM", C.D_PRIME_NUM, "constants.D_PRIME_NUM: R' tan g (Snyder eq. 10)"),
        ("DGGS_TAN_G2", C.TAN_G2, "constants.TAN_G2: tan^2 g"),
        ("DGGS_R_PRIME", C.R_PRIME, "constants.R_PRIME"),
        ("DGGS_FACE_CIRCUMRADIUS", C.FACE_CIRCUMRADIUS, "constants.FACE_CIRCUMRADIUS (unit sphere)"),
        ("DGGS_FACE_INRADIUS", C.FACE_INRADIUS, "constants.FACE_INRADIUS"),
        ("DGGS_FACE_EDGE", C.FACE_EDGE, "constants.FACE_EDGE"),
        ("DGGS_TINY", C.TINY, "constants.TINY: 2**-500"),
        ("DGGS_UNTINY", C.UNTINY, "constants.UNTINY: 2**600"),
        ("DGGS_TIE_STEP", icosahedron.TIE_STEP, "icosahedron.TIE_STEP"),
        ("DGGS_VERTEX_LATITUDE", icosahedron.VERTEX_LATITUDE, "icosahedron.VERTEX_LATITUDE, degrees"),
        ("DGGS_AUTHALIC_RADIUS", WGS84.authalic_radius, "WGS84.authalic_radius, metres"),
        ("DGGS_JUMP_SX", K._JUMP_SX, "kernel._JUMP_SX = GRID_W / SQRT3"),
        ("DGGS_IVEA_H", V._H, "ivea._H = 0.5 * SQRT3"),
        ("DGGS_IVEA_NATURAL_AREA", V.NATURAL_AREA, "ivea.NATURAL_AREA = pi / 30"),
        ("DGGS_IVEA_COS_VM", V.COS_VM, "ivea.COS_VM"),
        ("DGGS_IVEA_VM_ARC", V.VM_ARC, "ivea.VM_ARC"),
        ("DGGS_IVEA_TAN_VM2", V._TAN_VM2, "ivea._TAN_VM2 = tan(VM)**2"),
        ("DGGS_IVEA_VX", V._VX, "ivea._VX: the natural triangle's vertex V (c, n, e)"),
        ("DGGS_IVEA_VY", V._VY, "ivea._VY"),
        ("DGGS_IVEA_VZ", V._VZ, "ivea._VZ"),
        ("DGGS_IVEA_MX", V._MX, "ivea._MX: the edge midpoint M (c, n, e)"),
        ("DGGS_IVEA_MY", V._MY, "ivea._MY"),
        ("DGGS_IVEA_MZ", V._MZ, "ivea._MZ"),
        ("DGGS_IVEA_VM", V._VM, "ivea._VM = V . M"),
        ("DGGS_IVEA_SGN", V._SGN, "ivea._SGN"),
        ("DGGS_IVEA_RV", V._RV, "ivea._RV = FACE_CIRCUMRADIUS"),
        ("DGGS_IVEA_RM", V._RM, "ivea._RM = FACE_INRADIUS"),
    ] + [(f"DGGS_IVEA_T{i}", V._T[i], f"ivea._T[{i}]: tangents at V (towards M: 0-2, normal: 3-5)")
         for i in range(6)]
    ints = [
        ("DGGS_AUTHALIC_TERMS", ts.shape[0], "terms of the authalic series"),
        ("DGGS_GEODETIC_TERMS", tg.shape[0], "terms of the inverse (geodetic) series"),
        ("DGGS_GRID_W", split26.GRID_W, "split26.GRID_W: jump grid columns"),
        ("DGGS_GRID_H", split26.GRID_H, "split26.GRID_H: jump grid rows"),
        ("DGGS_JUMP_W2", K._JUMP_W2, "kernel._JUMP_W2 = GRID_W + 2: a jump table row, with its border"),
        ("DGGS_JUMP_SIZE", table.shape[0], "(GRID_H + 2) * (GRID_W + 2) jump table cells"),
        ("DGGS_JUMP_AMBIGUOUS", split26.AMBIGUOUS, "split26.AMBIGUOUS: a jump cell that takes 4 exact steps"),
        ("DGGS_JUMP_LEVELS", split26.JUMP_LEVELS, "split26.JUMP_LEVELS"),
        ("DGGS_JUMP_CODES", packed.shape[0], "3**JUMP_LEVELS jump codes"),
    ]
    # (C type, name, dims, data, comment)
    arrays: list[tuple[str, str, tuple[int, ...], np.ndarray, str]] = [
        ("double", "dggs_to_authalic", (ts.shape[0],), ts,
         "WGS84.to_authalic_series: Karney (2023) eq. A19, Clenshaw coefficients of sin(2 l phi) (kernel.TO_AUTHALIC)"),
        ("double", "dggs_to_geodetic", (tg.shape[0],), tg,
         "WGS84.to_geodetic_series: Karney (2023) eq. A20 (kernel.TO_GEODETIC)"),
        ("double", "dggs_isea_centres", (nf, 3), K.ISEA_CENTRES,
         "ISEA face centres, geographic unit vectors (kernel.ISEA_CENTRES; icosahedron.ISEA.geometry.centres)"),
        ("double", "dggs_isea_frames", (nf, 3, 3), K.ISEA_FRAMES,
         "ISEA face frames: rows centre, north (+y), east (+x) of each face (kernel.ISEA_FRAMES)"),
        ("double", "dggs_isea_vertices", (12, 3), geo.vertices,
         "ISEA icosahedron vertices, geographic unit vectors (ISEA.geometry.vertices)"),
        ("int", "dggs_isea_face_vertices", (nf, 3), geo.face_vertices,
         "vertex ids of each face, vertex k at azimuth 120 k clockwise (ISEA.geometry.face_vertices)"),
        ("double", "dggs_tie_bias", (nf,), tie_bias,
         "-TIE_STEP * face: the near-tie bias of nearest_face (kernel.TIE_BIAS)"),
        ("double", "dggs_rot_cos", (3,), C.ROT_COS, "constants.ROT_COS: cos(120 k degrees)"),
        ("double", "dggs_rot_sin", (3,), C.ROT_SIN, "constants.ROT_SIN: sin(120 k degrees)"),
        ("double", "dggs_face_vertices", (3, 2), split26.FACE_VERTICES,
         "planar face vertices (x, y), vertex k at azimuth 120 k clockwise from +y (split26.FACE_VERTICES)"),
        ("double", "dggs_face_corners_ccw", (3, 2), K.FACE_CORNERS_CCW,
         "a base cell's corners counter-clockwise: FACE_VERTICES reversed (kernel.FACE_CORNERS_CCW)"),
        ("double", "dggs_level1_corners", (6, 3, 2), K.LEVEL1_CORNERS,
         "the six level-1 triangles' corners (A, B, C) as (x, y) (kernel.LEVEL1_CORNERS; split26.LEVEL1)"),
        ("double", "dggs_edge_normals", (3, 2), split26.EDGE_NORMALS,
         "outward unit normals of face edge k, azimuth 60 + 120 k (split26.EDGE_NORMALS)"),
        ("double", "dggs_l1_c", (6, 2), K.L1_C, "level-1 triangle d's corner C (split26.L1_C)"),
        ("double", "dggs_l1_rows", (6, 2, 2), K.L1_ROWS,
         "face frame -> level-1 triangle d's canonical frame, divided by the inradius (split26.L1_ROWS)"),
        ("double", "dggs_child_m", (3, 2, 2), K.CHILD_M,
         "parent canonical -> child canonical: p' = CHILD_M[c] p + CHILD_T[c] (split26.CHILD_M)"),
        ("double", "dggs_child_t", (3, 2), K.CHILD_T, "(split26.CHILD_T)"),
        ("uint8_t", "dggs_jump_table", (table.shape[0],), table,
         "split26.jump_table(): per grid cell (row-major, bordered) the level-4 code or DGGS_JUMP_AMBIGUOUS "
         "(kernel.JUMP_TABLE, from dggs/geometry/jump_table.npz)"),
        ("uint64_t", "dggs_jump_packed", (81,), packed,
         "each code's 4 digit codes (digit + 1), 2 bits each, first level highest (kernel.JUMP_PACKED)"),
        ("double", "dggs_jump_maps", (81, 6), maps,
         "each code's map (a00, a01, a10, a11, b0, b1): p -> A p + b (kernel.JUMP_MAPS)"),
    ]

    head = "/* GENERATED by libdggs/tools/gen_tables.py from the Python geometry floor: do not edit. */\n"
    h = [head, "/* The geometry floor's constants and tables, the exact doubles of dggs.geometry (hex floats).\n",
         " * Arrays are row-major as the numpy arrays they come from; indices as named in each comment. */\n",
         "#ifndef DGGS_TABLES_H\n#define DGGS_TABLES_H\n\n#include <stdint.h>\n\n"]
    for name, value, comment in scalars:
        h.append(f"/* {comment} */\n#define {name} {fhex(value)}\n")
    h.append("\n")
    for name, value, comment in ints:
        h.append(f"/* {comment} */\n#define {name} {int(value)}\n")
    h.append("\n")
    c = [head, '#include "tables.h"\n\n']
    for ctype, name, dims, data, comment in arrays:
        data = np.asarray(data)
        assert data.shape == dims, (name, data.shape, dims)
        decl = f"const {ctype} {name}" + "".join(f"[{d}]" for d in dims)
        h.append(f"/* {comment} */\nextern {decl};\n")
        if data.ndim == 1:
            if ctype == "double":
                body = flat_doubles(data, per_line=3)
            elif ctype == "uint64_t":
                body = flat_ints(data.astype(np.uint64), per_line=4, fmt="UINT64_C(0x%x)")
            else:
                body = flat_ints(data, per_line=40 if ctype == "uint8_t" else 3)
        else:
            body = "    " + ",\n    ".join(nested(row, ctype) for row in data)
        c.append(f"{decl} = {{\n{body}\n}};\n\n")
    h.append("\n#endif /* DGGS_TABLES_H */\n")
    with open(os.path.join(SRC, "tables.h"), "w") as f:
        f.write("".join(h))
    with open(os.path.join(SRC, "tables.c"), "w") as f:
        f.write("".join(c))
    print(f"wrote {os.path.join(SRC, 'tables.h')} and tables.c")
    return 0


if __name__ == "__main__":
    sys.exit(main())
