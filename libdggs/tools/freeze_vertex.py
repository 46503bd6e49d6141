"""Freeze the vertex verbs' answers (issue 32 item 6: their work moved from numpy into the C core).

``--write PATH`` records, with the current build, ``grid_disk_vertex``, ``vertex_neighbors`` and
``cell_to_vertexes`` round the special points (poles, antimeridian, the 12 icosahedron vertices, face-edge
midpoints) at levels 0-28, over whole levels 0-3 and at random cells, as SHA-256 digests of the answers
(string ids joined by newlines) and their sizes; ``--check PATH`` recomputes them and prints the differences.
The file was written at the last commit where the verbs walked corners in numpy.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]
LEVELS = (0, 1, 2, 3, 5, 9, 13, 20, 27, 28)


def _special_points() -> list[tuple[float, float]]:
    sys.path.insert(0, str(ROOT))
    from tests.strategies import special_points

    return special_points()


def _digest(rows: list[list[str]]) -> dict:
    text = "\n".join(" ".join(r) for r in rows)
    return {"n": sum(len(r) for r in rows), "sha256": hashlib.sha256(text.encode()).hexdigest()}


def cases() -> dict[str, dict]:
    import dggs

    out: dict[str, dict] = {}
    pts = _special_points()
    lat = np.array([p[0] for p in pts])
    lng = np.array([p[1] for p in pts])
    for level in LEVELS:
        cells = [str(c) for c in dggs.latlng_to_cell(lat, lng, level).tolist()]
        for k in (0, 1, 2, 4):
            out[f"disk special level={level} k={k}"] = _digest([dggs.grid_disk_vertex(c, k) for c in cells])
        ints = [dggs.str_to_int(c) for c in cells]
        out[f"disk special int level={level} k=3"] = _digest(
            [[str(x) for x in dggs.grid_disk_vertex(c, 3)] for c in ints]
        )
        out[f"neighbors special level={level}"] = _digest([dggs.vertex_neighbors(c) for c in cells])
        out[f"vertexes special level={level}"] = _digest([dggs.cell_to_vertexes(c) for c in cells])
    for level in (0, 1, 2, 3):
        cells = dggs.cell_to_children(dggs.get_base_cells(), level).tolist()
        out[f"neighbors whole level={level}"] = _digest([dggs.vertex_neighbors(c) for c in cells])
        out[f"vertexes whole level={level}"] = _digest([dggs.cell_to_vertexes(c) for c in cells])
        out[f"disk whole level={level} k=2"] = _digest([dggs.grid_disk_vertex(c, 2) for c in cells])
    rng = np.random.default_rng(32)
    for level in (4, 8, 16, 24, 28):
        n = 300
        la = np.degrees(np.arcsin(rng.uniform(-1, 1, n)))
        lo = rng.uniform(-180, 180, n)
        cells = [str(c) for c in dggs.latlng_to_cell(la, lo, level).tolist()]
        out[f"neighbors random level={level}"] = _digest([dggs.vertex_neighbors(c) for c in cells])
        out[f"vertexes random level={level}"] = _digest([dggs.cell_to_vertexes(c) for c in cells])
        out[f"disk random level={level} k=3"] = _digest([dggs.grid_disk_vertex(c, 3) for c in cells[:40]])
    big = [str(c) for c in dggs.latlng_to_cell(np.array([58.2825255885, 10.0, 90.0]), np.array([11.25, 180.0, 0.0]), 28).tolist()]
    for c, k in zip(big, (40, 60, 300), strict=True):
        out[f"disk {c} k={k}"] = _digest([dggs.grid_disk_vertex(c, k, max_cells=10**7)])
    return out


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__)
    g = ap.add_mutually_exclusive_group(required=True)
    g.add_argument("--write", type=Path)
    g.add_argument("--check", type=Path)
    a = ap.parse_args(argv)
    got = cases()
    if a.write:
        a.write.write_text(json.dumps(got, indent=1, sort_keys=True) + "\n")
        print(f"wrote {len(got)} digests")
        return 0
    want = json.loads(a.check.read_text())
    bad = [k for k in want if got.get(k) != want[k]]
    for k in bad:
        print(f"differs: {k}: {got.get(k)} != {want[k]}")
    print(f"{len(want) - len(bad)} of {len(want)} digests equal")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
