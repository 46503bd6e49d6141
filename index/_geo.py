"""The standard grid's orientation and ellipsoid: PROJ's ISEA orientation on the WGS84 authalic sphere."""

from __future__ import annotations

from dggs.geometry.authalic import WGS84
from dggs.geometry.icosahedron import ISEA

#: The default grid: PROJ's ISEA orientation on the WGS84 authalic sphere.
ORIENTATION = ISEA
ELLIPSOID = WGS84
