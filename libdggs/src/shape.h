/* Cells as dggs.cell_to_polygon draws them (index/_shapes.py geometries and ring_to_geometry): a cell's lng/lat
 * ring, unwrapped at the antimeridian and closed over a pole where it goes round one (the polygon fill's boundary
 * test, fill.c), and the same ring split at +-180 into the parts of a (Multi)Polygon (dggs_cell_to_polygon). */
#ifndef DGGS_SHAPE_H
#define DGGS_SHAPE_H

#include <math.h>
#include <stdbool.h>
#include <stdint.h>

#include "dggs.h"

/* _shapes._POLE_TOL: a ring point this close (degrees) to a pole is at it. */
#define DGGS_POLE_TOL 1e-9

/* Python's float a % b for b > 0 (the result in [0, b)). */
static inline double dggs_pymod(double a, double b) {
    double r = fmod(a, b);
    if (r < 0.0) r += b;
    return r;
}

/* Whether a closed (lng, lat) ring of `rows` points (its first repeated last) crosses the antimeridian or comes
 * within a degree of a pole (_shapes.special_rings): a step of over 90 degrees of longitude between consecutive
 * points, or a latitude over 89 degrees. Such cells take the exact ring (dggs_cell_ring, ring_to_geometry). */
bool dggs_ring_is_special(const double *lng_lat, int64_t rows);

/* The room (in points) of dggs_cell_ring's output: `ring` and `tmp` each need 4 dggs_cell_ring_room(densify)
 * doubles. */
int64_t dggs_cell_ring_room(int densify);

/* The lng/lat ring of a valid cell with `densify` points per edge, as index/_shapes.py draws it: the plain
 * boundary, or, for a cell that crosses the antimeridian or comes within a degree of a pole
 * (_shapes.special_rings), the exact ring (points.c dggs_special_ring) unwrapped as ring_to_geometry does it:
 * pole points in pairs, longitudes stepping under 180 degrees (along a pole westward at the North Pole, eastward
 * at the South), and closed over the pole where it goes round one. Not split at +-180. Writes (lng, lat) points
 * into `ring`; `tmp` is scratch. Returns the count of points (the ring is closed implicitly); *special (if not
 * NULL) tells whether the exact path was taken. */
int64_t dggs_cell_ring(dggs_projection proj, uint64_t cell, int densify, double *ring, double *tmp, bool *special);

#endif
