"""The point kernels of :mod:`.points` on the IVEA projection: compiled C, libdggs/src/points.c.

The same C functions as :mod:`.points`, given IVEA's forward and inverse
(:func:`dggs.geometry.ivea.forward_unit`, :func:`dggs.geometry.ivea.face_inverse`)
instead of Snyder's.  What does not project (``encode_point``, ``corners``,
``triangle``, the pole table: the poles sit on the same planar edge midpoints in
both projections) is :mod:`.points`' own.
"""

from __future__ import annotations

from dggs import _core
from dggs._core import ivea_boundaries as boundaries
from dggs._core import ivea_centre_of as centre_of
from dggs._core import ivea_centres as centres
from dggs._core import ivea_locate as locate
from dggs._core import ivea_one_point as one_point
from dggs._core import ivea_special_ring as special_ring

from .points import SPECIAL_EXTRA

# special_ring's helpers that project, which the dissolved outlines and edges share
_lat_lng_at = _core.ivea_lat_lng_at
_crossing = _core.ivea_crossing

__all__ = ["one_point", "centre_of", "special_ring", "locate", "centres", "boundaries", "SPECIAL_EXTRA"]
