"""Whether a line between samples in two edge neighbours crosses only their shared edge (compiled C, chord.c).

:func:`dggs.index._kernel.line_trace.trace` samples each geodesic every half
short edge.  Two consecutive samples in cells that share an edge do not prove
that the line went straight across it: passing near an end of that edge it
can clip the cells on the other side of the corner (at a corner of 4 cells,
A -> C -> D -> B).  :func:`clear` decides, in the face plane where the
samples were located, whether the line cannot have done so; where it is
not sure the tracer bisects the span, which costs one located point.

The bound on the line's bend: in the face plane the image of a geodesic is
not straight.  Within one of Snyder's six sectors of a face it curves
gently (its curvature scaled by the step length, vanishing for short steps),
but where it crosses a sector boundary the projection's derivative jumps and
the image has a kink, whose offset from the chord scales with the chord's
length L.  Measured over 1.2 million great-circle arcs of 1e-4 to 0.3 rad
(16 interior points each, random places and directions, on one face), the
largest distance from the chord was 0.137 L on ISEA and 0.068 L on IVEA,
the same from 1e-4 to 0.01 rad (the kink), less at 0.3 rad.  :data:`BEND` is
0.25: a false alarm only costs a bisection.  The floor covers the
interpolation's 0.1 mm and rounding.

The functions are the C core's (``dggs._core``, libdggs/src/chord.c), bit for bit the numba kernel's they replace.
"""

from __future__ import annotations

from dggs._core import clear, corner_clear, corners6, crosses, dist_to_segment

__all__ = ["BEND", "clear", "corner_clear", "corners6", "crosses", "dist_to_segment"]

#: Bound on how far the face-plane image of a geodesic strays from its chord, as a fraction of the
#: chord's length (the module's measurement: at most 0.137 on ISEA, 0.068 on IVEA).  DGGS_BEND in chord.h.
BEND = 0.25
#: Absolute floor of the bend bound (plane units of the unit sphere: 0.6 mm, over the interpolation's 0.1 mm).
_BEND_FLOOR = 1e-10
