"""The polygon-fill descent of :mod:`.fill` on the IVEA projection.

Compiled C, libdggs/src/fill.c (through ``dggs._core``): the same functions as :mod:`.fill`, called with
``DGGS_IVEA``, so that centres and footprints map planar points back by IVEA's inverse.  The footprint bound of
:mod:`.fill` holds unchanged: it needs the inverse to stretch no planar length by more than ``K_INV = 1.17``, and
IVEA's largest scale factor is 1.102 (``dggs experiments projections``; Snyder's is 1.163), so every IVEA cell
lies in the same footprint caps.
"""

from __future__ import annotations

from dggs._core import ivea_fill_centre as centre
from dggs._core import ivea_fill_descend as descend
from dggs._core import ivea_fill_footprint as footprint

from .fill import CENTRE, EDGE, SURE, TOO_MANY, first_over

__all__ = ["descend", "centre", "footprint", "first_over", "TOO_MANY", "SURE", "CENTRE", "EDGE"]
