"""Pure-Python paths for one cell id at a time (no floating point, so exact).

numpy costs about a microsecond per call whatever the array size, so a
single-id call through the array code pays for dozens of tiny passes.  The
operations that only rewrite digits (validity, level, parent, children,
neighbours, disks) have these string versions; they are tested to agree
with the array versions on every input.
"""

from __future__ import annotations

import re

from .cellid import FACE_LETTERS, MAX_LEVEL

_VALID = re.compile(r"[A-T](?:[0-5][0-2]{0,%d})?\Z" % (MAX_LEVEL - 1))


def is_valid(cell: str) -> bool:
    """Whether a str is a well-formed id."""
    return _VALID.match(cell) is not None


_tables = None


def _load_tables():
    """Plain-list copies of the neighbour tables in :mod:`index.grid`."""
    global _tables
    if _tables is None:
        from dggs.split26 import face_adjacency

        from . import _geo
        from .grid import _OUTER, _SIBLING, _level1_tables

        ccw, table = _level1_tables()
        adj = face_adjacency(_geo.ORIENTATION.geometry.face_vertices)
        _tables = (
            _SIBLING.tolist(),
            _OUTER.tolist(),
            [bool(v) for v in ccw],
            table.tolist(),
            [[FACE_LETTERS[adj[f][k]] for k in (1, 0, 2)] for f in range(20)],
        )
    return _tables


def neighbours(cell: str) -> list[str]:
    """The 3 edge neighbours of a valid id, in the array code's column order."""
    sibling, outer, l1_ccw, l1_table, base = _load_tables()
    if len(cell) == 1:
        return list(base[ord(cell) - 65])
    face = ord(cell[0]) - 65
    l1 = ord(cell[1]) - 48
    digits = [ord(ch) - 48 for ch in cell[2:]]
    flips = sum(1 for d in digits if d != 1)
    ccw = l1_ccw[l1] ^ (flips % 2 == 1)
    found = {}
    for label in (0, 1, 2):  # a, b, c
        new = digits[:]
        f, d1, edge = face, l1, label
        pos = len(new) - 1
        while pos >= 0:
            c = new[pos]
            sib = sibling[c][edge]
            if sib >= 0:
                new[pos] = sib
                break
            edge = outer[c][edge]
            pos -= 1
        else:  # reached the level-1 triangle's edge
            f, d1 = l1_table[f][d1][edge]
        found[label] = FACE_LETTERS[f] + chr(48 + d1) + "".join(chr(48 + d) for d in new)
    order = (2, 0, 1) if ccw else (1, 0, 2)  # corner-order columns: c, a, b or b, a, c
    return [found[i] for i in order]


def disk(cell: str, k: int) -> list[str]:
    """Sorted ids within k edge steps of a valid id (breadth-first on sets)."""
    seen = {cell}
    ring = [cell]
    for _ in range(k):
        nxt = []
        for c in ring:
            for n in neighbours(c):
                if n not in seen:
                    seen.add(n)
                    nxt.append(n)
        ring = nxt
    return sorted(seen)


def children(cell: str, level: int) -> list[str]:
    """Descendants of a valid id at ``level`` in id order."""
    out = [cell]
    for lv in range(len(cell), level + 1):
        digits = "012345" if lv == 1 else "012"
        out = [c + d for c in out for d in digits]
    return out
