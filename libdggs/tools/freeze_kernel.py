"""Ids, centres and boundaries of >= 10M points at every level, as SHA-256 digests: the port to C changes nothing.

``--write FILE`` records the digests of the current build (run once at the last numba commit, 16e1ddf; the file
was refrozen for issue 34 by tie_check.py's ``digests``, after checking every changed id is an exact tie);
``--check FILE`` recomputes them and exits 1 naming every (projection, quantity, level) that differs.
``--save DIR`` also keeps the raw arrays (``.npy``), to find the points that differ between two builds.

The points (seeded, so every run draws the same): uniform on the sphere, plus the poles at many longitudes,
longitudes +-180 and 0, the latitudes of the icosahedron's vertices (PROJ's ISEA orientation) at every
longitude step, points along the 30 face edges (great circles between adjacent vertices), and each of these
moved by +-1e-12 and +-1e-9 degrees in latitude and longitude.  Ids go through the public verbs
(``dggs.latlng_to_cell``, ``dggs.Grid("IVEA")``), centres and boundaries (densify 0 and 3) of the first
``--shape-points`` points' cells likewise.

Examples
--------
python libdggs/tools/freeze_kernel.py --check tests/reference/fixtures/kernel_digests.json
"""

from __future__ import annotations

import argparse
import hashlib
import json
import os
import sys
import time

import numpy as np

UNIFORM = 9_400_000


def _special(rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray]:
    from dggs.geometry.icosahedron import ISEA

    v = np.asarray(ISEA.geometry.vertices, dtype=np.float64)  # (12, 3) unit vectors
    v_lat = np.degrees(np.arctan2(v[:, 2], np.hypot(v[:, 0], v[:, 1])))
    v_lng = np.degrees(np.arctan2(v[:, 1], v[:, 0]))
    lngs = np.linspace(-180.0, 180.0, 721)
    lat = [np.full(lngs.size, 90.0), np.full(lngs.size, -90.0)]
    lng = [lngs, lngs]
    for la in np.unique(np.round(v_lat, 12)):
        lat.append(np.full(lngs.size, la))
        lng.append(lngs)
    lat_axis = np.linspace(-90.0, 90.0, 1441)
    for lo in (-180.0, 180.0, 0.0):
        lat.append(lat_axis)
        lng.append(np.full(lat_axis.size, lo))
    lat.append(v_lat)
    lng.append(v_lng)
    # face edges: adjacent vertices are those at the smallest angle
    dots = v @ v.T
    near = np.isclose(dots, dots[0][dots[0] < 0.999].max())
    t = np.linspace(0.0, 1.0, 2001)[:, None]
    for i, j in zip(*np.nonzero(np.triu(near, 1)), strict=True):
        p = np.sin((1 - t) * np.arccos(dots[i, j])) * v[i] + np.sin(t * np.arccos(dots[i, j])) * v[j]
        p /= np.linalg.norm(p, axis=1)[:, None]
        lat.append(np.degrees(np.arctan2(p[:, 2], np.hypot(p[:, 0], p[:, 1]))))
        lng.append(np.degrees(np.arctan2(p[:, 1], p[:, 0])))
    base_lat, base_lng = np.concatenate(lat), np.concatenate(lng)
    out_lat, out_lng = [base_lat], [base_lng]
    for d in (1e-12, -1e-12, 1e-9, -1e-9):
        out_lat += [np.clip(base_lat + d, -90.0, 90.0), base_lat]
        out_lng += [base_lng, base_lng + d]
    return np.concatenate(out_lat), np.concatenate(out_lng)


def points(seed: int = 20261207) -> tuple[np.ndarray, np.ndarray]:
    """The points, special ones first (624,708), then UNIFORM uniform ones."""
    rng = np.random.default_rng(seed)
    s_lat, s_lng = _special(rng)
    u = rng.uniform(-1.0, 1.0, UNIFORM)
    lat = np.degrees(np.arcsin(u))
    lng = rng.uniform(-180.0, 180.0, UNIFORM)
    return np.concatenate([s_lat, lat]), np.concatenate([s_lng, lng])


def _digest(a: np.ndarray) -> str:
    return hashlib.sha256(np.ascontiguousarray(a).tobytes()).hexdigest()


def digests(shape_points: int, save: str | None) -> dict[str, str]:
    """Every digest, keyed ``projection/quantity/level``."""
    import dggs

    lat, lng = points()
    found: dict[str, str] = {"points": _digest(np.stack([lat, lng]))}
    grids = {"ISEA": None, "IVEA": dggs.Grid("IVEA")}
    for name, grid in grids.items():
        t0 = time.perf_counter()
        for level in range(29):
            if grid is None:
                ids = dggs.latlng_to_cell(lat, lng, level, as_int=True)
            else:
                ids = grid.latlng_to_cell(lat, lng, level, as_int=True)
            found[f"{name}/ids/{level}"] = _digest(ids)
            cells = ids[:shape_points]
            verbs = dggs if grid is None else grid
            c_lat, c_lng = verbs.cell_to_latlng(cells)
            found[f"{name}/centres/{level}"] = _digest(np.stack([c_lat, c_lng]))
            b0 = verbs.cell_to_boundary(cells[: shape_points // 4])
            b3 = verbs.cell_to_boundary(cells[: shape_points // 4], densify=3)
            found[f"{name}/boundaries0/{level}"] = _digest(b0)
            found[f"{name}/boundaries3/{level}"] = _digest(b3)
            if save:
                os.makedirs(save, exist_ok=True)
                np.save(os.path.join(save, f"{name}_ids_{level}.npy"), ids)
        print(f"{name}: {lat.size:,} points x 29 levels in {time.perf_counter() - t0:.1f} s", file=sys.stderr)
    return found


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--write", metavar="FILE")
    ap.add_argument("--check", metavar="FILE")
    ap.add_argument("--save", metavar="DIR")
    ap.add_argument("--shape-points", type=int, default=400_000)
    args = ap.parse_args(argv)
    if not (args.write or args.check):
        ap.error("give --write FILE or --check FILE")
    found = digests(args.shape_points, args.save)
    n = int(points()[0].size)
    if args.write:
        with open(args.write, "w") as f:
            json.dump({"points": n, "shape_points": args.shape_points, "digests": found}, f, indent=1, sort_keys=True)
        print(f"wrote {len(found)} digests of {n:,} points to {args.write}")
        return 0
    with open(args.check) as f:
        want = json.load(f)
    if want["shape_points"] != args.shape_points:
        print(f"the file was written with --shape-points {want['shape_points']}", file=sys.stderr)
        return 2
    bad = sorted(k for k, v in want["digests"].items() if found.get(k) != v)
    for k in bad:
        print(f"differs: {k}")
    print(f"{len(want['digests']) - len(bad)} of {len(want['digests'])} digests equal over {n:,} points")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
