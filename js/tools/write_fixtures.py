"""Write the JS package's test fixtures from the Python package: what js/test/dggs.test.mjs compares with.

    python js/tools/write_fixtures.py OUT_DIR

OUT_DIR/fixtures.json: points (random, the poles, the antimeridian, the icosahedron's vertices and points 1e-9
degrees from them, face centres and edge midpoints), and for each of ISEA and IVEA and every level 0..28 their
cells (string ids), which of them lie on an edge or corner of their cell and the cells that meet there
(`ties`), the cells' centres and corners, and densified boundaries of some; parents, children, disks
and rings, compaction, polygon fills in every mode, valid and invalid ids, areas. OUT_DIR/bulk.bin: 100,000
random points and their level-17 and level-28 cells on both projections, as little-endian arrays (float64 lat,
float64 lng, then uint64 ids: ISEA 17, ISEA 28, IVEA 17, IVEA 28), for the bulk comparison and the benchmark.
Everything is seeded: the same package writes the same files.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

import numpy as np
from shapely.geometry import Polygon

import dggs

LEVELS = range(29)
PROJECTIONS = ("ISEA", "IVEA")
BULK = 100_000


def random_points(rng: np.random.Generator, n: int) -> tuple[np.ndarray, np.ndarray]:
    """Uniform on the sphere."""
    lat = np.degrees(np.arcsin(rng.uniform(-1.0, 1.0, n)))
    lng = rng.uniform(-180.0, 180.0, n)
    return lat, lng


def edge_points() -> list[tuple[float, float, str]]:
    """Points named by kind.

    The poles, the antimeridian, the icosahedron's vertices (and points beside them), face centres and the
    midpoints of face edges.
    """
    pts: list[tuple[float, float, str]] = []
    for lng in (0.0, 180.0, -180.0, -73.5, 45.0):
        pts += [(90.0, lng, "north pole"), (-90.0, lng, "south pole")]
    pts += [(89.9999999, 10.0, "near north pole"), (-89.9999999, -170.0, "near south pole")]
    for lat in (0.0, 45.0, -45.0, 10.0, 80.0, -63.0):
        pts += [(lat, 180.0, "antimeridian"), (lat, -180.0, "antimeridian")]
        pts += [(lat, 179.9999999999, "antimeridian east"), (lat, -179.9999999999, "antimeridian west")]
    pts += [(30.0, 360.5, "wrapped longitude"), (-30.0, -540.25, "wrapped longitude")]
    faces = [dggs.str_to_int(chr(ord("A") + f)) for f in range(20)]
    corners = np.array(dggs.cell_to_boundary(np.array(faces, dtype=np.uint64), densify=1)).reshape(-1, 2)
    seen: set[tuple[float, float]] = set()
    for k, (lat, lng) in enumerate(corners):
        key = (round(float(lat), 6), round(float(lng), 6) % 360.0 if abs(lat) < 89.999 else 0.0)
        if k % 2 == 1:
            pts.append((float(lat), float(lng), "face edge midpoint"))
            continue
        if key in seen:
            continue
        seen.add(key)
        pts.append((float(lat), float(lng), "icosahedron vertex"))
        for dlat, dlng in ((1e-9, 0.0), (-1e-9, 0.0), (0.0, 1e-9), (0.0, -1e-9)):
            pts.append((float(lat) + dlat, float(lng) + dlng, "beside a vertex"))
    for face in faces:
        lat, lng = dggs.cell_to_latlng(face)
        pts.append((float(lat), float(lng), "face centre"))
    return [(max(-90.0, min(90.0, a)), b, c) for a, b, c in pts]


def ties(g: dggs.Grid, lat: np.ndarray, lng: np.ndarray, level: int) -> dict[str, list[str]]:
    """The points on an edge or corner of their cell at `level`.

    Index -> the cells that meet there (those of 72 points 1e-11 degrees, 1 µm, around it), where more than one.
    A point exactly on an edge is given to one of its cells by the tie rules, and which one depends on the last
    bit of sin, cos, atan2, hypot and asin: the WebAssembly build's libm (musl's, in wasi-libc) differs from
    glibc's by an ulp in 3-17 % of arguments.
    """
    theta = np.radians(np.arange(72) * 5.0)[None, :, None]
    delta = np.radians(1e-11)
    phi, lam = np.radians(lat)[:, None, None], np.radians(lng)[:, None, None]
    up = np.concatenate([np.cos(phi) * np.cos(lam), np.cos(phi) * np.sin(lam), np.sin(phi)], axis=-1)
    north = np.concatenate([-np.sin(phi) * np.cos(lam), -np.sin(phi) * np.sin(lam), np.cos(phi)], axis=-1)
    east = np.concatenate([-np.sin(lam), np.cos(lam), np.zeros_like(lam)], axis=-1)
    q = up * np.cos(delta) + (north * np.cos(theta) + east * np.sin(theta)) * np.sin(delta)
    nlat = np.degrees(np.arctan2(q[..., 2], np.hypot(q[..., 0], q[..., 1])))
    nlng = np.degrees(np.arctan2(q[..., 1], q[..., 0]))
    around = np.asarray(g.latlng_to_cell(nlat.ravel(), nlng.ravel(), level)).reshape(nlat.shape)
    out: dict[str, list[str]] = {}
    for i, row in enumerate(around):
        cells = sorted(set(row.tolist()))
        if len(cells) > 1:
            out[str(i)] = cells
    return out


def polygons() -> list[dict]:
    """(lng, lat) shells and holes, and the levels to fill them at."""
    return [
        {"name": "box in Europe", "rings": [[(0, 40), (10, 40), (10, 50), (0, 50)]], "levels": [3, 6]},
        {
            "name": "box with a hole",
            "rings": [[(-10, -10), (10, -10), (10, 10), (-10, 10)], [(-3, -3), (-3, 3), (3, 3), (3, -3)]],
            "levels": [5],
        },
        {"name": "against the antimeridian", "rings": [[(170, -20), (180, -20), (180, -5), (170, -5)]], "levels": [5]},
        {
            "name": "round the north pole",
            "rings": [[(-180, 80), (-60, 80), (60, 80), (180, 80), (180, 90), (-180, 90)]],
            "levels": [4],
        },
        {"name": "small triangle", "rings": [[(2.3, 48.8), (2.4, 48.8), (2.35, 48.9)]], "levels": [12]},
    ]


def main(out: Path) -> None:
    """Write fixtures.json and bulk.bin into `out`."""
    out.mkdir(parents=True, exist_ok=True)
    rng = np.random.default_rng(34)
    lat, lng = random_points(rng, 300)
    named = [(float(a), float(b), "random") for a, b in zip(lat, lng, strict=True)] + edge_points()
    plat = np.array([p[0] for p in named])
    plng = np.array([p[1] for p in named])
    fx: dict = {"points": [[a, b, c] for a, b, c in named], "projections": {}}

    for proj in PROJECTIONS:
        g = dggs.Grid(proj)
        per: dict = {"levels": {}, "dense": []}
        for level in LEVELS:
            cells = np.asarray(g.latlng_to_cell(plat, plng, level))
            ids = cells.tolist()
            uniq = sorted(set(ids))
            centres = np.stack(g.cell_to_latlng(np.array(uniq)), axis=-1)
            bounds = np.asarray(g.cell_to_boundary(np.array(uniq)))
            per["levels"][str(level)] = {
                "cells": ids,
                "ints": [str(v) for v in np.asarray(g.latlng_to_cell(plat, plng, level, as_int=True)).tolist()],
                "unique": uniq,
                "centres": centres.reshape(-1, 2).tolist(),
                "boundaries": bounds.reshape(len(uniq), -1).tolist(),
                "ties": ties(g, plat, plng, level),
            }
        for level in (0, 1, 5, 13, 20, 28):
            for cell in per["levels"][str(level)]["unique"][::7]:
                per["dense"].append(
                    {"cell": cell, "densify": 4, "boundary": np.asarray(g.cell_to_boundary(cell, densify=4)).tolist()}
                )
        per["polygons"] = []
        for poly in polygons():
            shape = Polygon(poly["rings"][0], poly["rings"][1:])
            for level in poly["levels"]:
                for mode in ("center", "contains", "overlaps", "overlapping_bbox"):
                    cells = g.polygon_to_cells(shape, level, mode=mode)
                    per["polygons"].append(
                        {
                            "name": poly["name"],
                            "rings": poly["rings"],
                            "level": level,
                            "mode": mode,
                            "cells": np.asarray(cells).tolist(),
                        }
                    )
        fx["projections"][proj] = per

    # the topology (the same on both projections): parents, children, disks, rings, compaction
    sample = sorted(
        {c for lv in (0, 1, 2, 7, 15, 27, 28) for c in fx["projections"]["ISEA"]["levels"][str(lv)]["unique"]}
    )
    edge_cells = [c for k, c in enumerate(sample) if k % 3 == 0]
    topo: dict = {"parents": [], "children": [], "disks": [], "rings": [], "compact": []}
    for cell in edge_cells:
        level = dggs.get_level(cell)
        if level > 0:
            topo["parents"].append({"cell": cell, "level": level - 1, "parent": dggs.cell_to_parent(cell)})
            topo["parents"].append({"cell": cell, "level": 0, "parent": dggs.cell_to_parent(cell, 0)})
        if level < 28:
            topo["children"].append({"cell": cell, "level": level + 1, "children": list(dggs.cell_to_children(cell))})
        if level <= 26 and level % 2 == 0:
            topo["children"].append(
                {"cell": cell, "level": level + 2, "children": list(dggs.cell_to_children(cell, level + 2))}
            )
        for k in (1, 2, 4):
            topo["disks"].append({"cell": cell, "k": k, "cells": list(dggs.grid_disk(cell, k))})
        topo["rings"].append({"cell": cell, "k": 2, "cells": list(dggs.grid_ring(cell, 2))})
    for cell in edge_cells[:40]:
        level = dggs.get_level(cell)
        if level > 25:
            continue
        group = list(dggs.cell_to_children(cell, level + 2)) + list(dggs.grid_disk(cell, 1))
        group += list(dggs.cell_to_children(dggs.grid_disk(cell, 1)[0], level + 1))[:2]
        compact = list(dggs.compact_cells(group))
        finest = max(dggs.get_level(c) for c in group)
        topo["compact"].append(
            {
                "cells": group,
                "compact": compact,
                "level": finest,
                "uncompact": list(dggs.uncompact_cells(compact, finest)),
            }
        )
    fx["topology"] = topo

    valid = ["A", "T0", "C401", "B" + "5" + "2" * 27, "S1021"]
    invalid = ["", "U", "a", "C6", "C403", "C4019", "C40 1", "B" + "5" + "2" * 28, "c401", "C4-1", "é"]
    ints = [str(dggs.str_to_int(c)) for c in valid] + ["0", "1", str(2**64 - 1), str(2**63), "12345"]
    fx["valid"] = {
        "strings": [[c, bool(dggs.is_valid_cell(c))] for c in valid + invalid],
        "ints": [[c, bool(dggs.is_valid_cell(int(c)))] for c in ints],
    }
    fx["areas"] = {unit: [float(dggs.cell_area(lv, unit)) for lv in LEVELS] for unit in ("m^2", "km^2", "rads^2")}
    (out / "fixtures.json").write_text(json.dumps(fx))

    blat, blng = random_points(np.random.default_rng(3434), BULK)
    cols = [blat, blng]
    for proj in PROJECTIONS:
        for level in (17, 28):
            ids = np.asarray(dggs.Grid(proj).latlng_to_cell(blat, blng, level, as_int=True), dtype=np.uint64)
            cols.append(ids.view(np.float64))
    np.stack(cols).astype("<f8").tofile(out / "bulk.bin")
    print(f"wrote {out / 'fixtures.json'} ({len(named)} points) and {out / 'bulk.bin'} ({BULK} points)")


if __name__ == "__main__":
    main(Path(sys.argv[1] if len(sys.argv) > 1 else "build/js-fixtures"))
