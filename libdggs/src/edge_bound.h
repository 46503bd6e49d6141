/* Points per edge from a bound on each edge's bulge, with no geodesic call per edge (see edge_bound.c). */
#ifndef DGGS_EDGE_BOUND_H
#define DGGS_EDGE_BOUND_H

#include <stdint.h>

#include "dggs.h"

/* The unchecked per-cell work of dggs_cell_edge_bounds / dggs_cell_edge_points (valid ids, valid proj). */
void dggs_edge_bounds_of(dggs_projection proj, uint64_t cell, double bulge_m[3], double length_m[3]);
int dggs_edge_points_of(dggs_projection proj, uint64_t cell, double tolerance_m, double area_tolerance);

#endif
