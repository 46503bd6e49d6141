"""The polyline tracer of :mod:`.line_trace` on the IVEA projection: the same code, compiled a second time.

As :mod:`.ivea_points` does for the point kernels: the functions of :mod:`.line_trace` that locate a point
(``_sample``, and its callers ``_cell_at``, ``_anchor``, ``cells_at`` and ``trace``) are rebuilt from their own
code objects.  The tracer
locates interpolated points without a trigonometric call, through the geometry kernel's ``nearest_face`` and
``face_forward`` rather than ``forward_unit``, so ``gk`` is bound here to :data:`.ivea_points.IVEA_KERNEL`
with ``face_forward`` IVEA's as well (:func:`dggs.geometry.ivea.face_forward`, the same signature); the
polyline's own points go through IVEA's ``one_point``.  The faces and their frames are the same on both
projections, so the face search (the previous point's face first) holds as it is.  The Hermite spans, the
return to the surface, the edge neighbours and the planar test of a crossing between two samples
(:func:`.chord.clear`, on the face-plane points the rebuilt ``_sample`` gives, its bend bound covering IVEA's
smaller measured bend) do not project and are shared as compiled.
"""

from __future__ import annotations

import types

from dggs.geometry import ivea as _ivea

from . import ivea_points as _ki
from . import line_trace as _line_trace
from .ivea_points import IVEA_KERNEL, rebuilder


def _line_kernel() -> types.ModuleType:
    """:data:`IVEA_KERNEL` with ``face_forward`` IVEA's too (the tracer's trigonometry-free locator calls it)."""
    mod = types.ModuleType("dggs.geometry.kernel_ivea_lines")
    mod.__dict__.update({k: v for k, v in vars(IVEA_KERNEL).items() if not k.startswith("__")})
    mod.face_forward = _ivea.face_forward  # type: ignore[attr-defined]
    return mod


_GLOBALS, _rebuilt, _compiled = rebuilder(_line_trace)
_GLOBALS["gk"] = _line_kernel()
_GLOBALS["one_point"] = _ki.one_point

_sample = _compiled("_sample")
_cell_at = _compiled("_cell_at")
_anchor = _compiled("_anchor")
cells_at = _compiled("cells_at")
trace = _compiled("trace")
# what does not project: the same compiled functions
clean, layout, span_for, interpolate = _line_trace.clean, _line_trace.layout, _line_trace.span_for, _line_trace.interpolate

__all__ = ["cells_at", "clean", "interpolate", "layout", "span_for", "trace"]
