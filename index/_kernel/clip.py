"""Clipping of polygons by the cells of the hierarchy, in one face plane (for :mod:`.pixels`).

Compiled C, libdggs/src/clip.c (through ``dggs._core``).

A polygon inside a cell is cut into its parts in the cell's children, depth
first, down to a target level: a face's six children by Sutherland-Hodgman
clips against each triangle, a finer cell's three by two cuts along the lines
that part them (:func:`dggs.geometry.kernel.child_corners`).  Each part's
planar area is a piece; a child the polygon covers wholly gives all its
descendants at the target level an equal share (cells are congruent in the
plane).  Areas are shoelace sums about a vertex of the polygon, for precision
at fine levels.

The descent itself runs inside :func:`dggs.index._kernel.pixels.grid_pieces`
(C calls C); :func:`area` and :func:`clip` are the two steps callable from
Python.
"""

from __future__ import annotations

from dggs._core import clip_area as area
from dggs._core import clip_clip as clip

__all__ = ["area", "clip"]
