"""Loops between points and 64-bit cell ids: location, centres, corners, boundaries: compiled C, libdggs/src/points.c.

Each operation is a per-item C function and one OpenMP loop over it (called
as ``loop(n, *args)``, where ``n``, the amount of work, picks the threads).
The per-item functions that validate their input (:func:`one_point`,
:func:`centre_of`) are the single-id entries.  Inputs are assumed checked,
except coordinates: a point that is not a finite latitude in
-90..90 and a finite longitude gets the null id 0, which the caller turns
into a :class:`~dggs.errors.CoordinateError` naming it.
"""

from __future__ import annotations

from dggs import _core
from dggs._core import (
    boundaries,
    center_children,
    centre_of,
    centres,
    corners,
    encode_point,
    locate,
    one_point,
    pole_table,
    special_ring,
    triangle,
)
from dggs.geometry import kernel as gk

__all__ = [
    "POLES", "SPECIAL_EXTRA", "boundaries", "center_children", "centre_of", "centres", "corners", "encode_point",
    "locate", "one_point", "special_ring", "triangle",
]  # fmt: skip

# the pole and antimeridian helpers of special_ring, which the dissolved outlines share
_pole_on = _core.pole_on
_edge_params = _core.edge_params
_lat_lng_at = _core.lat_lng_at
_crossing = _core.crossing

_ISEA_CENTRES = gk.ISEA_CENTRES
_ISEA_FRAMES = gk.ISEA_FRAMES

#: (20, 3): per face the face-frame (x, y) of a pole on its boundary and the pole's sign (0: none).
#: Both poles sit on the midpoints of face edges (PROJ's ISEA orientation): each lies on two faces' boundaries.
POLES = pole_table()
POLES.setflags(write=False)
#: A pole this close (relative to the edge, planar) to a cell's edge lies on it.
_ON_EDGE = 1e-9
#: The direction in which an edge leaves a pole: the point this fraction of a densify step away.
_POLE_LEAD = 1e-4
#: Extra rows of a special ring: two per pole corner, one per antimeridian crossing.
SPECIAL_EXTRA = 16
