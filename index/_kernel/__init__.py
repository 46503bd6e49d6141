"""The kernel floor: the compiled C core (libdggs/, bound as :mod:`dggs._core`), arrays in and out.

No containers and no exceptions here: inputs are checked by the verbs and
converted by :mod:`dggs.index._convert`; a kernel marks what it cannot take
(the null id 0, NaN, an index of the first bad item) and the caller raises.
Each module re-exports the core's functions for one part of the grid under
the names the verbs call; a batch function is called ``f(n, *args)``, ``n``
the amount of work, which picks one thread or ``DGGS_THREADS``
(:mod:`dggs.geometry._parallel`).

The modules: :mod:`.bits` (the id layout), :mod:`.codec` (strings <-> ids),
:mod:`.points` (points, centres, boundaries), :mod:`.hierarchy` (parents,
children), :mod:`.compact`, :mod:`.grid` and :mod:`.grid_tables` (neighbours,
disks, rings), :mod:`.distance`, :mod:`.strips` and :mod:`.paths`,
:mod:`.polygon` and :mod:`.fill` (polygon fill), :mod:`.line_trace`,
:mod:`.dissolve`, :mod:`.edges`, :mod:`.local`, :mod:`.clip` and :mod:`.pixels`;
the ``ivea_*`` modules are the same functions on the IVEA projection.
"""

# First: reads DGGS_THREADS and hands it to the core
from dggs.geometry import _parallel as _parallel
