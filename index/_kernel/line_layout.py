"""A polyline's points checked, and its anchors laid out: compiled C, libdggs/src/line_layout.c.

The plain loops before :mod:`.line_trace` traces a polyline.  Neither locates a point, so the IVEA tracer
(:mod:`.ivea_lines`) shares them.  Re-exported from ``dggs._core``, bit for bit the numba kernel's they replace.
"""

from __future__ import annotations

from dggs._core import clean, layout

__all__ = ["clean", "layout"]
