"""Freeze outputs of the numba codec (index/_kernel/codec.py, scalar.py) into libdggs/tests/test_codec.c.

Rewrites the block between ``BEGIN FROZEN`` and ``END FROZEN`` of the test with C tables: string ids of every
level 0..28 (every face, first and last digits) and junk with their parsed ids (0: invalid), malformed and
well-formed integers with their validity and strings, and small arrays with max_level's answer. Run with the
numba package installed (the reference), from anywhere but this checkout's root::

    cd /tmp && python /path/to/libdggs/tools/freeze_codec.py
"""

from __future__ import annotations

import os
import re

import numpy as np

from dggs.index._kernel import codec as kc
from dggs.index._kernel import scalar as ks

HERE = os.path.dirname(os.path.abspath(__file__))
TEST = os.path.join(os.path.dirname(HERE), "tests", "test_codec.c")


def c_string(s: str) -> str:
    """A C string literal of an ASCII str (octal escapes for the rest, so no escape runs into a digit)."""
    out = []
    for ch in s:
        o = ord(ch)
        out.append(ch if 32 <= o < 127 and ch not in '"\\' else f"\\{o:03o}")
    return '"' + "".join(out) + '"'


def strings_table() -> list[str]:
    """String ids of every level, and junk."""
    rng = np.random.default_rng(3)
    faces = "ABCDEFGHIJKLMNOPQRST"
    items = []
    for level in range(29):
        face = faces[level % 20]
        items.append(face + ("5" + "2" * (level - 1) if level else ""))
        items.append(face + ("0" * level))
        digits = "".join(str(rng.integers(0, 3)) for _ in range(max(level - 1, 0)))
        items.append(faces[int(rng.integers(0, 20))] + (str(rng.integers(0, 6)) + digits if level else ""))
    items += ["", "Z", "U1", "A6", "A03", "A0 1", "a01", "A" + "0" * 29, "T5" + "2" * 28, "+A0", "A_0", "@", "[",
              "A/", "A:", "T52223", "Q5" + "2" * 27]
    rows = []
    for s in items:
        rows.append(f"    {{{c_string(s)}, 0x{int(ks.parse_one(s)):016x}ULL}},")
    return rows


def ints_table() -> list[str]:
    """Integers: validity (valid_ints) and string (format_one, "" when not an id)."""
    rng = np.random.default_rng(5)
    vals = [0, 1, 1 << 62, (1 << 62) | (19 << 57), (1 << 62) | (20 << 57), (1 << 62) | (7 << 54),
            (1 << 62) | (1 << 54) | 1, (1 << 62) | 1, 2**63 - 1, (1 << 62) | (6 << 54) | (3 << 52) | 1,
            (1 << 62) | (6 << 54) | (3 << 52) | (3 << 50)]
    for s in ("C401", "T5" + "2" * 27, "A0" + "1" * 27, "J3"):
        c = int(ks.parse_one(s))
        vals += [c, c ^ (1 << int(rng.integers(0, 63))), c | 1]
    rows = []
    for v in vals:
        ok = bool(kc.valid_ints(np.array([v], dtype=np.uint64))[0])
        rows.append(f"    {{0x{v:016x}ULL, {int(ok)}, {c_string(ks.format_one(v))}}},")
    return rows


def max_level_table() -> list[str]:
    """Arrays of up to 4 ids (0-padded) with max_level's (level, bad)."""
    p = ks.parse_one
    cases = [[0], [p("A")], [p("A"), p("B3")], [0, p("T5222"), 0, p("C1")], [p("A" + "0" * 28), p("B")],
             [0, 0, 0, 0], [p("C40"), 12345, p("D")], [p("C40"), 0, (1 << 62) | (7 << 54)], [p("E5")]]
    rows = []
    for case in cases:
        arr = np.array(case, dtype=np.uint64)
        level, bad = kc.max_level(arr)
        vals = ", ".join(f"0x{int(v):016x}ULL" for v in case)
        rows.append(f"    {{{len(case)}, {{{vals}}}, {int(level)}, {int(bad)}}},")
    return rows


def main() -> None:
    """Rewrite the frozen block of test_codec.c."""
    block = ["/* BEGIN FROZEN (tools/freeze_codec.py) */",
             "/* parse_one: string, id (0: not a string id) */",
             "static const struct { const char *s; uint64_t id; } FROZEN_STRINGS[] = {", *strings_table(), "};",
             "/* valid_ints and format_one: integer, valid, string (\"\" when not an id) */",
             "static const struct { uint64_t v; int valid; const char *s; } FROZEN_INTS[] = {", *ints_table(), "};",
             "/* max_level: count, ids, level, bad */",
             "static const struct { int n; uint64_t ids[4]; int level; int64_t bad; } FROZEN_MAX_LEVEL[] = {",
             *max_level_table(), "};", "/* END FROZEN */"]
    with open(TEST) as f:
        text = f.read()
    text = re.sub(r"/\* BEGIN FROZEN.*?/\* END FROZEN \*/", lambda m: "\n".join(block), text, flags=re.S)
    with open(TEST, "w") as f:
        f.write(text)
    print(f"wrote {TEST}")


if __name__ == "__main__":
    main()
