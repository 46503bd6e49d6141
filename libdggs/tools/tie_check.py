"""The ids two builds of the core give the frozen points differ only at exact ties (issue 34).

Run ``save`` under each build (its venv's ``dggs``), ``diff`` the two folders, ``nudge`` the changed points under
each build, then ``verdict``. A changed point p (cell A in the old build, B in the new) is an exact tie when
moving it 1e-13 radians toward A's centre gives A and toward B's centre gives B in *both* builds: p lies within
1e-13 radians of both cells, on their shared edge or corner, where the last bit of a sine decides.

Centres and boundaries of the cells both builds agree on are compared too (the last bits may move: the new
sin/cos/atan2/asin/hypot round differently from glibc's, within an ulp), and reported as the largest difference
in degrees.

Examples
--------
cd /tmp && /work/main/.venv/bin/python libdggs/tools/tie_check.py save /tmp/ties/old
cd /tmp && .venv/bin/python libdggs/tools/tie_check.py save /tmp/ties/new
python libdggs/tools/tie_check.py diff /tmp/ties/old /tmp/ties/new /tmp/ties/changes.npz
cd /tmp && /work/main/.venv/bin/python libdggs/tools/tie_check.py nudge /tmp/ties/changes.npz /tmp/ties/old_nudge.npz
cd /tmp && .venv/bin/python libdggs/tools/tie_check.py nudge /tmp/ties/changes.npz /tmp/ties/new_nudge.npz
python libdggs/tools/tie_check.py verdict /tmp/ties/changes.npz /tmp/ties/old_nudge.npz /tmp/ties/new_nudge.npz
python libdggs/tools/tie_check.py digests /tmp/ties/old tests/reference/fixtures/kernel_digests.json  # all equal
python libdggs/tools/tie_check.py digests /tmp/ties/new tests/reference/fixtures/kernel_digests.json --write
"""

from __future__ import annotations

import argparse
import importlib.util
import os
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
PROJECTIONS = ("ISEA", "IVEA")
LEVELS = range(29)
NUDGE = 1e-13  # radians


def _points() -> tuple[np.ndarray, np.ndarray]:
    spec = importlib.util.spec_from_file_location("freeze_kernel", HERE / "freeze_kernel.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module.points()


def _grid(name: str):
    import dggs

    return dggs.Grid(name)


def save(folder: str, shape_points: int = 400_000) -> None:
    """Ids of every frozen point at every level, centres and boundaries of the first ``shape_points``' cells."""
    import dggs

    os.makedirs(folder, exist_ok=True)
    lat, lng = _points()
    print(f"dggs from {dggs.__file__}", file=sys.stderr)
    for name in PROJECTIONS:
        grid = _grid(name)
        for level in LEVELS:
            ids = grid.latlng_to_cell(lat, lng, level, as_int=True)
            cells = ids[:shape_points]
            np.save(os.path.join(folder, f"{name}_ids_{level}.npy"), ids)
            np.save(os.path.join(folder, f"{name}_centres_{level}.npy"), np.stack(grid.cell_to_latlng(cells)))
            b0 = grid.cell_to_boundary(cells[: shape_points // 4])
            b3 = grid.cell_to_boundary(cells[: shape_points // 4], densify=3)
            np.save(os.path.join(folder, f"{name}_b0_{level}.npy"), b0)
            np.save(os.path.join(folder, f"{name}_b3_{level}.npy"), b3)
        print(f"{name} saved", file=sys.stderr)


def diff(old: str, new: str, out: str) -> None:
    """Every point whose id differs, and how far centres and boundaries moved where the cells agree."""
    rows = []
    worst = {"centres": 0.0, "b0": 0.0, "b3": 0.0}
    moved = {"centres": 0, "b0": 0, "b3": 0}
    for p, name in enumerate(PROJECTIONS):
        for level in LEVELS:
            a = np.load(os.path.join(old, f"{name}_ids_{level}.npy"))
            b = np.load(os.path.join(new, f"{name}_ids_{level}.npy"))
            idx = np.nonzero(a != b)[0]
            rows += [(p, level, int(i), int(a[i]), int(b[i])) for i in idx]
            for kind in worst:
                x = np.load(os.path.join(old, f"{name}_{kind}_{level}.npy"))
                y = np.load(os.path.join(new, f"{name}_{kind}_{level}.npy"))
                if kind == "centres":  # (2, n): one column a cell
                    x, y = x.T, y.T
                same = a[: len(x)] == b[: len(x)]
                xs, ys = x[same].reshape(int(same.sum()), -1), y[same].reshape(int(same.sum()), -1)
                both = np.isfinite(xs) & np.isfinite(ys)
                assert (np.isnan(xs) == np.isnan(ys)).all(), (name, kind, level)
                d = np.where(both, np.abs(xs - ys), 0.0)
                worst[kind] = max(worst[kind], float(d.max(initial=0.0)))
                moved[kind] += int(np.count_nonzero((d > 0).any(axis=1)))
            print(f"{name} level {level:2d}: {idx.size:6d} ids differ", file=sys.stderr)
    arr = np.array(rows, dtype=np.uint64).reshape(-1, 5)
    np.savez(out, changes=arr)
    print(f"{len(rows):,} point-levels with another id; written to {out}")
    for kind in worst:
        print(f"{kind}: {moved[kind]:,} cells (of those with equal ids) with a coordinate moved, "
              f"the largest move {worst[kind]:.3g} degrees")


def _vectors(lat: np.ndarray, lng: np.ndarray) -> np.ndarray:
    la, lo = np.radians(lat), np.radians(lng)
    return np.stack([np.cos(la) * np.cos(lo), np.cos(la) * np.sin(lo), np.sin(la)], axis=-1)


def _latlng(v: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    return np.degrees(np.arctan2(v[:, 2], np.hypot(v[:, 0], v[:, 1]))), np.degrees(np.arctan2(v[:, 1], v[:, 0]))


def nudge(changes: str, out: str) -> None:
    """Under the current build: the id of each changed point moved NUDGE radians toward the old and new cells."""
    ch = np.load(changes)["changes"]
    lat, lng = _points()
    toward_old = np.zeros(len(ch), dtype=np.uint64)
    toward_new = np.zeros(len(ch), dtype=np.uint64)
    for p, name in enumerate(PROJECTIONS):
        grid = _grid(name)
        for level in LEVELS:
            sel = np.nonzero((ch[:, 0] == p) & (ch[:, 1] == level))[0]
            if not sel.size:
                continue
            i = ch[sel, 2].astype(np.int64)
            v = _vectors(lat[i], lng[i])
            for col, dest in ((3, toward_old), (4, toward_new)):
                c = _vectors(*grid.cell_to_latlng(ch[sel, col].astype(np.uint64)))
                t = c - np.sum(c * v, axis=1)[:, None] * v  # tangent at v toward the centre
                t /= np.linalg.norm(t, axis=1)[:, None]
                w = v + NUDGE * t
                w /= np.linalg.norm(w, axis=1)[:, None]
                dest[sel] = grid.latlng_to_cell(*_latlng(w), level, as_int=True)
    np.savez(out, toward_old=toward_old, toward_new=toward_new)
    print(f"{len(ch):,} changed point-levels nudged; written to {out}")


def verdict(changes: str, *nudged: str) -> int:
    ch = np.load(changes)["changes"]
    ok = np.ones(len(ch), dtype=bool)
    for path in nudged:
        n = np.load(path)
        ok &= (n["toward_old"] == ch[:, 3]) & (n["toward_new"] == ch[:, 4])
    for p, name in enumerate(PROJECTIONS):
        mine = ch[:, 0] == p
        print(f"{name}: {int(mine.sum()):,} point-levels with another id, {int((ok & mine).sum()):,} of them ties")
    bad = np.nonzero(~ok)[0]
    for row in ch[bad[:20]]:
        print(f"not a tie: {PROJECTIONS[int(row[0])]} level {int(row[1])} point {int(row[2])}: {int(row[3]):#x} -> {int(row[4]):#x}")
    print(f"{len(ch) - bad.size:,} of {len(ch):,} changed point-levels are exact ties (both cells within {NUDGE:g} rad, "
          f"on {len(nudged)} builds)")
    return 1 if bad.size else 0


def digests(folder: str, frozen: str, write: bool) -> int:
    """The digests of freeze_kernel.py from a ``save`` folder: compared with FILE, or written into it (``--write``).

    The same SHA-256 of the same arrays (ids; centres stacked (lat, lng); boundaries with densify 0 and 3 of the
    first quarter): run on the old build's folder it must give the frozen file's digests, every one.
    """
    import hashlib
    import json

    def digest(a: np.ndarray) -> str:
        return hashlib.sha256(np.ascontiguousarray(a).tobytes()).hexdigest()

    want = json.loads(Path(frozen).read_text())
    lat, lng = _points()
    found = {"points": digest(np.stack([lat, lng]))}
    for name in PROJECTIONS:
        for level in LEVELS:
            found[f"{name}/ids/{level}"] = digest(np.load(os.path.join(folder, f"{name}_ids_{level}.npy")))
            found[f"{name}/centres/{level}"] = digest(np.load(os.path.join(folder, f"{name}_centres_{level}.npy")))
            found[f"{name}/boundaries0/{level}"] = digest(np.load(os.path.join(folder, f"{name}_b0_{level}.npy")))
            found[f"{name}/boundaries3/{level}"] = digest(np.load(os.path.join(folder, f"{name}_b3_{level}.npy")))
    if write:
        want["digests"] = found
        Path(frozen).write_text(json.dumps(want, indent=1, sort_keys=True))
        print(f"wrote {len(found)} digests to {frozen}")
        return 0
    bad = sorted(k for k, v in want["digests"].items() if found.get(k) != v)
    print(f"{len(want['digests']) - len(bad)} of {len(want['digests'])} digests equal; differ: {', '.join(bad) or 'none'}")
    return 1 if bad else 0


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    sub = ap.add_subparsers(dest="cmd", required=True)
    sub.add_parser("save").add_argument("folder")
    d = sub.add_parser("diff")
    d.add_argument("old")
    d.add_argument("new")
    d.add_argument("out")
    n = sub.add_parser("nudge")
    n.add_argument("changes")
    n.add_argument("out")
    v = sub.add_parser("verdict")
    v.add_argument("changes")
    v.add_argument("nudged", nargs="+")
    g = sub.add_parser("digests")
    g.add_argument("folder")
    g.add_argument("frozen")
    g.add_argument("--write", action="store_true")
    args = ap.parse_args(argv)
    if args.cmd == "digests":
        return digests(args.folder, args.frozen, args.write)
    if args.cmd == "save":
        save(args.folder)
    elif args.cmd == "diff":
        diff(args.old, args.new, args.out)
    elif args.cmd == "nudge":
        nudge(args.changes, args.out)
    else:
        return verdict(args.changes, *args.nudged)
    return 0


if __name__ == "__main__":
    sys.exit(main())
