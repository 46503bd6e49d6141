"""The polyline tracer of :mod:`.line_trace` on the IVEA projection: compiled C, libdggs/src/line_trace.c.

One C tracer serves both projections (its first argument selects ISEA's or IVEA's face projection): the
tracer locates interpolated points without a trigonometric call, through the geometry kernel's nearest-face
search and the face projection (IVEA's here, :func:`dggs.geometry.ivea.face_forward`), and the polyline's
own points through IVEA's ``one_point``.  The faces and their frames are the same on both projections, so
the face search (the previous point's face first) holds as it is.  The Hermite spans, the return to the
surface, the edge neighbours and the planar test of a crossing between two samples (:func:`.chord.clear`,
its bend bound covering IVEA's smaller measured bend) do not project and are the same code.
"""

from __future__ import annotations

from dggs._core import ivea_cells_at as cells_at
from dggs._core import ivea_trace as trace

from .line_trace import clean, interpolate, layout, span_for

__all__ = ["cells_at", "clean", "interpolate", "layout", "span_for", "trace"]
