"""The kernel floor: compiled code (numba) over 64-bit ids, arrays in and out.

No containers and no exceptions here: inputs are checked by the verbs and
converted by :mod:`dggs.index._convert`; a kernel marks what it cannot take
(the null id 0, NaN, an index of the first bad item) and the caller raises.
Every batch loop is one ``prange`` body compiled serial and parallel by
:func:`dggs.geometry._parallel.loops`.

The modules: :mod:`.bits` (the id layout), :mod:`.codec` (strings <-> ids),
:mod:`.points` (points, centres, boundaries), :mod:`.hierarchy` (parents,
children, compaction), :mod:`.grid` and :mod:`.grid_tables` (neighbours,
disks, rings, distances).
"""

# First, before any kernel module imports numba: checks NUMBA_NUM_THREADS and installs the package's compiled cache
from dggs.geometry import _parallel as _parallel
