"""Directed edges between edge neighbours, as 64-bit ids.

Compiled C, libdggs/src/edges.c (through ``dggs._core``).

Layout (docs/grid.md, "Directed edges"): the edge from a cell at level
``l < 28`` across its side ``d`` (0-2: corner ``d`` to corner ``d + 1``, the
column of :func:`dggs.edge_neighbors`) is ::

    (1 << 63) | cell | (d + 1) << shift(l + 1)

the sign bit marks an edge and the direction fills the cell's first empty
field.  With the sign bit cleared an edge is a valid cell id one level finer
(its "shadow"), so edges sort by origin then direction, and the origin is the
shadow's parent.  Level-28 cells have no empty field: their edges have no id
(the kernels answer the null id 0 and the caller refuses them).

The batch loops are called ``loop(n, *args)`` (``n`` the amount of work, which
picks the threads); the ``one_*`` functions take one valid edge as an int.
"""

from __future__ import annotations

import numpy as np

from dggs._core import edges_boundaries as boundaries
from dggs._core import edges_edge_of as edge_of
from dggs._core import edges_ends as ends
from dggs._core import edges_lengths as lengths
from dggs._core import edges_one_destination as one_destination
from dggs._core import edges_one_ends as one_ends
from dggs._core import edges_one_length as one_length
from dggs._core import edges_one_origin as one_origin
from dggs._core import edges_one_reverse as one_reverse
from dggs._core import edges_origin_edges as origin_edges
from dggs._core import edges_pair_edges as pair_edges
from dggs._core import edges_reverse as reverse
from dggs._core import edges_split as split

__all__ = ["EDGE_BIT", "edge_of", "split", "origin_edges", "pair_edges", "ends", "reverse", "lengths", "boundaries",
           "one_origin", "one_destination", "one_ends", "one_reverse", "one_length"]

#: The sign bit: set in every directed edge id.
EDGE_BIT = np.uint64(1 << 63)
