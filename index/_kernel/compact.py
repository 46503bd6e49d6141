"""Compaction over ``uint64`` id arrays: compact and uncompact cell sets: compiled C, libdggs/src/compact.c.

Same conventions as :mod:`.hierarchy` (valid ids in, ``bad`` as the last
return value for a violated level relation).  Compaction is one stack pass
after a radix sort; uncompaction writes id ranges in order, with no re-sort.

Kernels: :func:`compact`, :func:`uncompact_prepare` (then
:func:`~dggs.index._kernel.hierarchy.children` into a buffer of the size it
gives) and :func:`uncompact`.
"""

from __future__ import annotations

from dggs._core import _compact_radix_sort as _radix_sort  # noqa: F401 - the sort helpers, which tests call
from dggs._core import _compact_sorted as _sorted  # noqa: F401
from dggs._core import compact, uncompact, uncompact_prepare

__all__ = ["compact", "uncompact", "uncompact_prepare"]

#: Radix sort: bits per pass, and the smallest input it is used for (a heap sort below).
_RADIX_BITS = 12
_RADIX_MIN = 4096
