"""Hierarchy kernels over ``uint64`` id arrays (levels, parents, children): compiled C, libdggs/src/hierarchy.c.

Every kernel takes a 1-d ``uint64`` array of VALID ids (the caller validates,
e.g. with :func:`valid_mask`) and plain int levels already range-checked to
``0 .. MAX_LEVEL``.  The layout is in :mod:`dggs.index._kernel.bits` (docs/grid.md,
"Integer ids"): marker bit 62, face in bits 61..57, the level-1 code in bits
56..54, the level-k code (k >= 2) in bits ``2(28-k)+1 .. 2(28-k)``; a code of
0 means "no digit", so the descendants of ``c`` at level ``l`` are the ints
``[c, c + 2**shift_of(l))`` and int order is the depth-first string order.

Error convention
----------------
A kernel that can meet a violated level relation returns an ``int`` named
``bad`` as its LAST return value (or as its only one): ``-1`` when every cell
is fine, else the position in the INPUT array (input order, before any
sorting) of the first offending cell.  Outputs returned next to ``bad >= 0``
are meaningless.  The Python caller raises the typed error naming
``ids[bad]``.  Violations: a cell finer than the requested level
(:func:`parents` below it, :func:`count_children`, :func:`children`,
:func:`~dggs.index._kernel.compact.uncompact_prepare`,
:func:`~dggs.index._kernel.compact.uncompact`) and a base cell passed to
:func:`parents_up`.  A too-small ``out`` buffer is a programming error and
raises ``ValueError`` instead.

Counts are exact ``int64`` and saturate at ``2**63 - 1`` (the caller compares
them with its ``max_cells`` limit before allocating).

Kernels: :func:`levels`, :func:`valid_mask`, :func:`level_bounds`,
:func:`parents`, :func:`parents_up`, :func:`count_children`, :func:`children`,
:func:`parent_of`; compaction is in :mod:`.compact`.
The kernels are serial (children run at memory speed, a few ns per output
cell) and release the GIL, so callers may run chunks on threads.
"""

from __future__ import annotations

from dggs._core import (
    children,
    count_children,
    finer_than,
    level_bounds,
    levels,
    n_desc,
    parent_of,
    parents,
    parents_up,
    valid_mask,
)

__all__ = [
    "children", "count_children", "finer_than", "level_bounds", "levels", "n_desc", "parent_of", "parents",
    "parents_up", "valid_mask",
]  # fmt: skip
