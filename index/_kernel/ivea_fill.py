"""The polygon-fill descent of :mod:`.fill` on the IVEA projection: the same code, compiled a second time.

As :mod:`.ivea_points` does for the point kernels: the functions of :mod:`.fill` that map planar points to
the globe (``_on_globe`` and its callers) are rebuilt with ``gk`` bound to the geometry kernel whose
``inverse_unit`` is IVEA's.  The footprint bound of :mod:`.fill` holds unchanged: it needs the inverse to
stretch no planar length by more than ``K_INV = 1.17``, and IVEA's largest scale factor is 1.102
(``dggs experiments projections``; Snyder's is 1.163), so every IVEA cell lies in the same footprint caps.
"""

from __future__ import annotations

from . import fill as _fill
from .ivea_points import rebuilder

_GLOBALS, _rebuilt, _compiled = rebuilder(_fill)

_on_globe = _compiled("_on_globe")
centre = _compiled("centre")
footprint = _compiled("footprint")
_walk = _compiled("_walk")
descend = _compiled("descend")
first_over = _fill.first_over
TOO_MANY, SURE, CENTRE, EDGE = _fill.TOO_MANY, _fill.SURE, _fill.CENTRE, _fill.EDGE

__all__ = ["descend", "centre", "footprint", "first_over", "TOO_MANY", "SURE", "CENTRE", "EDGE"]
