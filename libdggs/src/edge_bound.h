/* Points per edge from a bound on each edge's bulge, with no geodesic call per edge (see edge_bound.c). */
#ifndef DGGS_EDGE_BOUND_H
#define DGGS_EDGE_BOUND_H

#include <stdbool.h>
#include <stdint.h>

#include "dggs.h"

/* The unchecked per-cell work of dggs_cell_edge_bounds / dggs_cell_edge_points (valid ids, valid proj). */
void dggs_edge_bounds_of(dggs_projection proj, uint64_t cell, double bulge_m[3], double length_m[3]);
int dggs_edge_points_of(dggs_projection proj, uint64_t cell, double tolerance_m, double area_tolerance);

/* Rows dggs_edge_ring_of may write: the closed ring of 3 points per edge. */
#define DGGS_EDGE_RING_REUSED 13

/* dggs_edge_points_of, and where its count is 0, 1 or 3 (every ring point one the count projected), the closed
 * (lng, lat) ring dggs_one_boundary(proj, cell, count, ring, 1) writes, bit for bit, into ring (room for
 * DGGS_EDGE_RING_REUSED rows); *drawn (unless NULL) tells whether it was written. Returns the count. */
int dggs_edge_ring_of(dggs_projection proj, uint64_t cell, double tolerance_m, double area_tolerance, double *ring,
                      bool *drawn);

#endif
