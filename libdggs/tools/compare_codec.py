"""Compare libdggs's codec (dggs._core, this checkout's build) with the numba kernels bit for bit.

Runs index/_kernel/codec.py and scalar.py (the installed package: the numba reference) and this checkout's
dggs._core on string ids of every level 0..28 and junk (wrong letters and digits, too long, empty, NULs inside,
non-ASCII), as the callers pass them: numpy U and S arrays' character codes, pyarrow string and large_string
arrays (with nulls, sliced), NUL-joined uint8 and uint32 codes, uint64 id arrays for check_ints, valid_ints,
max_level and fill_codes, and Python str / int for the single-id entries. Exit code 0 only if all are equal.

    cd /tmp && nice python /work/wt/points/libdggs/tools/compare_codec.py [--scale 1.0]
"""

from __future__ import annotations

import argparse
import glob
import importlib.util
import math
import os
import sys
import time

import numpy as np
import pyarrow as pa

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))


def load_core():
    """Load dggs._core of this checkout's build, by path under its real name."""
    so = glob.glob(os.path.join(ROOT, "dggs", "_core.cpython-*.so"))[0]
    spec = importlib.util.spec_from_file_location("dggs._core", so)
    core = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(core)
    return core


core = load_core()
from dggs.index._convert import strings  # noqa: E402  (the installed package: the numba reference)
from dggs.index._kernel import codec as kc  # noqa: E402
from dggs.index._kernel import scalar as ks  # noqa: E402

FAILED: list[str] = []


def same(a, b) -> bool:
    """Whether two results are equal bit for bit (floats by their bits; tuples element-wise)."""
    if isinstance(a, tuple):
        return isinstance(b, tuple) and len(a) == len(b) and all(same(x, y) for x, y in zip(a, b, strict=True))
    a, b = np.asarray(a), np.asarray(b)
    if a.shape != b.shape or a.dtype != b.dtype:
        return False
    if a.dtype.kind == "f":
        return bool(np.array_equal(a.view(np.uint64), b.view(np.uint64)))
    return bool(np.array_equal(a, b))


def report(name: str, count: int, equal: bool) -> None:
    """Print one comparison's line and remember a failure."""
    print(f"{name:44s} {count:>10,d} items  {'equal' if equal else 'DIFFERENT'}", flush=True)
    if not equal:
        FAILED.append(name)


def random_ids(rng: np.random.Generator, n: int) -> np.ndarray:
    """Well-formed ids, levels 0..28 uniformly."""
    face = rng.integers(0, 20, n).astype(np.uint64)
    level = rng.integers(0, 29, n)
    cell = np.uint64(1 << 62) | (face << np.uint64(57))
    l1 = rng.integers(0, 6, n).astype(np.uint64) + np.uint64(1)
    cell |= np.where(level >= 1, l1 << np.uint64(54), np.uint64(0)).astype(np.uint64)
    for k in range(2, 29):
        code = rng.integers(1, 4, n).astype(np.uint64)
        cell |= np.where(level >= k, code << np.uint64(2 * (28 - k)), np.uint64(0)).astype(np.uint64)
    return cell


def junk_ints(rng: np.random.Generator, ids: np.ndarray) -> np.ndarray:
    """Ids with one bit flipped, random uint64s, the null id and hand-made malformed ids."""
    flip = ids ^ (np.uint64(1) << rng.integers(0, 64, ids.size).astype(np.uint64))
    raw = rng.integers(0, 2**64 - 1, ids.size // 4, dtype=np.uint64, endpoint=True)
    hand = np.array(
        [
            0,
            1,
            1 << 62,
            (1 << 62) | (20 << 57),
            (1 << 62) | (31 << 57),
            (1 << 62) | (7 << 54),
            (1 << 62) | (1 << 54) | 1,
            (1 << 62) | 1,
            2**63 - 1,
            2**63,
            2**64 - 1,
            1 << 63 | 1 << 62,
        ],
        dtype=np.uint64,
    )
    return np.concatenate([flip, raw, hand])


def junk_strings(rng: np.random.Generator, good: list[str], n: int) -> list[str]:
    """Hand-made junk and mutations of good ids (a character replaced, inserted, deleted; too long)."""
    out = [
        "",
        "Z",
        "U1",
        "A6",
        "A03",
        "A0 1",
        "a01",
        "A01\x00",
        "A0\u0661",
        "A" + "0" * 29,
        "T5" + "2" * 28,
        "T5" + "2" * 27,
        "+A0",
        "A_0",
        "A\x000",
        "\x00",
        "A0\U0001f600",
        "\u00c1",
        "@",
        "[",
        "A/",
        "A:",
        "A03",
    ]
    alphabet = list("ABCSTU@[0123456789/:_ \x00\u00c9\u0661")
    for s in rng.choice(good, n):
        s = list(s)
        k = int(rng.integers(0, len(s) + 1))
        op = rng.integers(0, 4)
        if op == 0 and s:
            s[min(k, len(s) - 1)] = str(rng.choice(alphabet))
        elif op == 1:
            s.insert(k, str(rng.choice(alphabet)))
        elif op == 2 and s:
            del s[min(k, len(s) - 1)]
        else:
            s += ["0"] * int(rng.integers(1, 4))
        out.append("".join(s))
    return out


def compare_ints(rng, n: int) -> np.ndarray:
    """valid_ints, check_ints, max_level and fill_codes on uint64 arrays; returns good ids."""
    ids = random_ids(rng, n)
    bad = junk_ints(rng, ids)
    mixed = np.concatenate([ids, bad])
    rng.shuffle(mixed)
    report("valid_ints", mixed.size, same(kc.valid_ints(mixed), core.valid_ints(mixed)))
    ok, total = True, 0
    for arr in (ids, mixed, mixed[::3], np.zeros(5, np.uint64), np.zeros(0, np.uint64), ids[:1000]):
        ok &= int(kc.check_ints(arr)) == core.check_ints(arr)
        total += arr.size
    for _ in range(2000):  # one bad id at a random place
        a = ids[:50].copy()
        if rng.random() < 0.8:
            a[rng.integers(0, 50)] = bad[rng.integers(0, bad.size)]
        ok &= int(kc.check_ints(a)) == core.check_ints(a)
        total += a.size
    report("check_ints", total, ok)
    ok, total = True, 0
    with_nulls = ids.copy()
    with_nulls[rng.random(ids.size) < 0.1] = 0
    for arr in (ids, with_nulls, mixed, np.zeros(3, np.uint64), np.zeros(0, np.uint64)):
        ok &= tuple(int(v) for v in kc.max_level(arr)) == core.max_level(arr)
        total += arr.size
    for _ in range(5000):  # small arrays of few levels, some nulls, sometimes a bad one
        m = int(rng.integers(1, 8))
        a = ids[rng.integers(0, ids.size, m)].copy()
        a[rng.random(m) < 0.3] = 0
        if rng.random() < 0.2:
            a[rng.integers(0, m)] = bad[rng.integers(0, bad.size)]
        ok &= tuple(int(v) for v in kc.max_level(a)) == core.max_level(a)
        total += m
    report("max_level", total, ok)
    ok, total = True, 0
    for dtype in (np.uint8, np.uint32):
        for width in (1, 2, 5, 17, 29):
            a = np.full((with_nulls.size, width), 99, dtype=dtype)
            b = np.full((with_nulls.size, width), 99, dtype=dtype)
            kc.fill_codes(with_nulls, a)
            core.fill_codes(with_nulls, b)
            ok &= same(a, b)
            total += with_nulls.size
    report("fill_codes (uint8, uint32; widths 1..29)", total, ok)
    return ids


def compare_strings(rng, ids: np.ndarray, n_scalar: int) -> None:
    """The parsers on every container the callers pass, and the single-id entries."""
    good = [strings.format_int(int(c)) for c in ids]
    junk = junk_strings(rng, good, len(good) // 5)
    allstr = good + junk
    order = rng.permutation(len(allstr))
    allstr = [allstr[i] for i in order]
    # numpy U (uint32 codes) and S (uint8 codes; non-ASCII replaced), as strings.parse_chars views them
    u = np.array(allstr)
    codes_u = u.view(np.uint32).reshape(u.size, -1)
    a, b = kc.parse_codes(codes_u), core.parse_codes(codes_u)
    report("parse_codes uint32 (numpy U)", u.size, same(a[0], b[0]) and int(a[1]) == b[1])
    s = np.array([x.encode("latin-1", "replace") for x in allstr])
    codes_s = s.view(np.uint8).reshape(s.size, -1)
    a, b = kc.parse_codes(codes_s), core.parse_codes(codes_s)
    report("parse_codes uint8 (numpy S)", s.size, same(a[0], b[0]) and int(a[1]) == b[1])
    ok = True
    for dtype in (np.int64, np.uint16, np.int32):  # other integer codes, as numba takes any
        c = codes_u[:20000].astype(dtype)
        a, b = kc.parse_codes(c), core.parse_codes(c)
        ok &= same(a[0], b[0]) and int(a[1]) == b[1]
    good_u = np.array(good[:20000])
    c = good_u.view(np.uint32).reshape(good_u.size, -1)
    a, b = kc.parse_codes(c), core.parse_codes(c)
    ok &= same(a[0], b[0]) and int(a[1]) == b[1]
    report("parse_codes int64/uint16/int32 codes, all good", 80000, ok)
    # pyarrow string / large_string with nulls, sliced
    total, ok = 0, True
    for large in (False, True):
        items = [None if rng.random() < 0.05 else x for x in allstr]
        arr = pa.array(items, type=pa.large_string() if large else pa.string())
        for sl in (
            arr,
            arr.slice(3),
            arr.slice(1001, 50000),
            pa.array(good, type=pa.large_string() if large else pa.string()),
        ):
            validity, off_buf, data_buf = sl.buffers()[:3]
            offsets = np.frombuffer(off_buf, dtype=np.int64 if large else np.int32)
            data = np.frombuffer(data_buf, dtype=np.uint8) if data_buf is not None else np.zeros(0, dtype=np.uint8)
            bits = (
                np.frombuffer(validity, dtype=np.uint8)
                if validity is not None and sl.null_count
                else np.zeros(0, dtype=np.uint8)
            )
            a = kc.parse_arrow(data, offsets, bits, sl.offset, len(sl))
            b = core.parse_arrow(data, offsets, bits, sl.offset, len(sl))
            ok &= same(a[0], b[0]) and int(a[1]) == b[1]
            total += len(sl)
    report("parse_arrow (string, large_string, nulls)", total, ok)
    # NUL-joined, as strings.parse_pystrings builds it: ASCII as uint8, else uint32 codes
    total, ok = 0, True
    ascii_items = [x for x in allstr if x.isascii()]
    for items in (ascii_items, allstr, good, allstr[:1000] + ["A\x000"], [], [""], ["A"]):
        text = "\x00".join(items)
        wide = not text.isascii()
        data = np.frombuffer(
            text.encode("utf-32-le" if wide else "ascii", "surrogatepass"), dtype=np.uint32 if wide else np.uint8
        )
        for n in (len(items), len(items) + 2, max(len(items) - 1, 0)):
            a = kc.parse_joined(data, n)
            b = core.parse_joined(data, n)
            ok &= same(a[0], b[0]) and int(a[1]) == b[1] and int(a[2]) == b[2]
            total += n
    report("parse_joined (uint8, uint32)", total, ok)
    # the single-id entries
    sample = [allstr[i] for i in rng.integers(0, len(allstr), n_scalar)] + junk_strings(rng, good, 100)[:23]
    report("parse_one", len(sample), all(int(ks.parse_one(x)) == core.parse_one(x) for x in sample))
    ints = [int(v) for v in junk_ints(rng, ids[:n_scalar])] + [int(v) for v in ids[:n_scalar]]
    ints += [-1, -(2**63), 2**63 - 1]
    ints_ok = all(ks.format_one(v) == core.format_one(v) for v in ints if v < 2**63)
    big_ok = all(core.format_one(v) == "" for v in ints if v >= 2**63)  # numba takes them as uint64: never ids
    report("format_one", len(ints), ints_ok and big_ok)
    ok = True
    for x in sample:
        for level in (-1, 0, 1, 5, 17, 27, 28, 29, -2, 2**40):
            ok &= ks.parent_str(x, level) == core.parent_str(x, level)
    report("parent_str (levels -2..29, 2**40)", len(sample) * 10, ok)
    ok = True
    for x in sample:
        a, b = ks.centre_str(x), core.centre_str(x)
        ok &= same(np.array(a), np.array(b))
    report("centre_str", len(sample), ok)
    lat = np.degrees(np.arcsin(rng.uniform(-1, 1, n_scalar)))
    lng = rng.uniform(-180, 180, n_scalar)
    lat[:8] = [90.0, -90.0, 0.0, 0.0, math.nan, 91.0, 45.0, -90.0]
    lng[:8] = [0.0, 180.0, -180.0, 180.0, 0.0, 0.0, math.inf, -180.0]
    lv = rng.integers(0, 29, n_scalar)
    ok = all(
        ks.point_str(float(a), float(b), int(v)) == core.point_str(float(a), float(b), int(v))
        for a, b, v in zip(lat, lng, lv, strict=True)
    )
    report("point_str", n_scalar, ok)


def main() -> int:
    """Run every comparison; 0 only if all are equal."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scale", type=float, default=1.0, help="multiply every count by this")
    parser.add_argument("--seed", type=int, default=20261207)
    args = parser.parse_args()
    rng = np.random.default_rng(args.seed)
    t0 = time.time()
    ids = compare_ints(rng, int(1_000_000 * args.scale))
    compare_strings(rng, ids, int(100_000 * args.scale))
    print(f"{time.time() - t0:.0f} s; {'ALL EQUAL' if not FAILED else 'DIFFERENT: ' + ', '.join(FAILED)}")
    return 0 if not FAILED else 1


if __name__ == "__main__":
    sys.exit(main())
