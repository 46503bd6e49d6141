"""Exact weights of polygons in cells: each polygon cut along cell edges in Snyder's face planes.

Compiled C, libdggs/src/pixels.c and clip.c (through ``dggs._core``).

Snyder's projection is equal-area and maps every cell to a planar triangle
with straight edges (thesis §6.1.7): the area of a polygon's part inside a
cell is the planar area, in the cell's face plane, of the polygon clipped by
the cell's triangle, times one constant.  So :func:`grid_pieces` finds, for
each polygon (a raster pixel, its edges densified by the caller), every cell
of a level it meets and the planar area they share, by descending the
hierarchy:

* a polygon whose vertices all lie in one cell of the level lies wholly in it
  (cells are convex): one piece, its whole area;
* otherwise it is clipped (Sutherland-Hodgman against each child triangle, a
  convex window) from the smallest cell holding all its vertices down to the
  level; a triangle the polygon covers wholly gives all its descendants at the
  level, an equal share each (cells are congruent in the plane);
* a polygon across face edges is projected onto each face near it (Snyder's
  forward on that face: the sector formulas hold past the face's edges) and
  clipped by that face's triangle first, so each face keeps its own part.

Areas are planar, in the unit-sphere face frame; the caller scales them to
m² (:data:`FACE_AREA` is one face's planar area, 1/20 of the sphere).  The
polygons' edges are chords in the face plane: the caller densifies them.
"""

from __future__ import annotations

from dggs._core import PIXELS_FACE_AREA, PIXELS_MAX_RADIUS
from dggs._core import pixels_chord_errors as chord_errors
from dggs._core import pixels_grid_pieces as grid_pieces
from dggs._core import pixels_latlng_pieces as latlng_pieces
from dggs._core import pixels_plane_pieces as plane_pieces
from dggs._core import pixels_region as region

__all__ = ["FACE_AREA", "MAX_RADIUS", "chord_errors", "grid_pieces", "latlng_pieces", "plane_pieces", "region"]

#: Planar area of a face triangle in the unit-sphere face frame (a twentieth of the sphere's 4 pi).
FACE_AREA: float = PIXELS_FACE_AREA
#: Faces whose triangle may meet a polygon within this angle (radians) of one of its vertices: the largest
#: polygon :func:`grid_pieces` takes.
MAX_RADIUS: float = PIXELS_MAX_RADIUS
