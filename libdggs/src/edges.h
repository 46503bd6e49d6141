/* Directed edges between edge neighbours, as 64-bit ids: a port of index/_kernel/edges.py (and of
 * ivea_edges.py, which is edges.py's curves recompiled with IVEA's inverse: here `proj` selects).
 *
 * Layout (docs/grid.md, "Directed edges"): the edge from a cell at level l < 28 across its side d (0-2: corner
 * d to corner d + 1, the column of dggs.edge_neighbors) is
 *     (1 << 63) | cell | (d + 1) << shift(l + 1)
 * the sign bit marks an edge and the direction fills the cell's first empty field. With the sign bit cleared
 * an edge is a valid cell id one level finer (its "shadow"), so edges sort by origin then direction, and the
 * origin is the shadow's parent. Level-28 cells have no empty field: their edges have no id (the functions
 * answer the null id 0 and the caller refuses them).
 *
 * Inputs are assumed checked (valid ids, valid edges: the shadow a valid cell of level >= 1), as the numba
 * functions assume; the public verbs of dggs.h check them. One exception is kept safe: an "edge" whose shadow
 * is a base cell (Python's edge converter lets it through, and numba reads out of its tables for it) has no
 * destination, reverse, length or boundary here (0, NaN); its origin is numba's (the shadow's bits above 58). */
#ifndef DGGS_EDGES_H
#define DGGS_EDGES_H

#include <stdint.h>

#include "dggs.h"

/* EDGE_BIT: set in every directed edge id. */
#define DGGS_EDGE_BIT ((uint64_t)1 << 63)

/* edge_of: the edge id from `cell` across side `direction`; 0 at level 28. */
uint64_t dggs_edge_of(uint64_t cell, int direction);
/* split: (origin, level of the origin, direction) of a valid edge id. */
void dggs_edges_split(uint64_t edge, uint64_t *origin, int *level, int *direction);

/* _origin_edges, per item: out[d] = the edge from `cell` across side d (0 at level 28). */
void dggs_origin_edges(uint64_t cell, uint64_t out[3]);
/* _pair_edges, per item: the edge from a to its neighbour b; 0 if they are no neighbours or at level 28. */
uint64_t dggs_pair_edges(uint64_t a, uint64_t b);
/* _ends, per item (and one_ends): the origin and destination of a valid edge. */
void dggs_edges_ends(uint64_t edge, uint64_t *origin, uint64_t *destination);
/* _reverse, per item (and one_reverse): the edge back from the destination of `edge` to its origin (0 if none). */
uint64_t dggs_edges_reverse(uint64_t edge);
/* one_origin: the origin of one valid edge. */
uint64_t dggs_one_origin(uint64_t edge);
/* one_destination: the destination of one valid edge. */
uint64_t dggs_one_destination(uint64_t edge);

/* _one_length (and _lengths, per item): length of a valid edge's curve on WGS84 (metres) and on the unit
 * authalic sphere (radians). One walk of 2 pieces + 1 points along the straight edge on its face, each through
 * the projection's inverse: the chords between consecutive points and between every other point, extrapolated
 * (Richardson: chord sums err by ~1/n^2). pieces >= 1. */
void dggs_one_length(dggs_projection proj, uint64_t edge, int64_t pieces, double *metres, double *rads);

/* _one_boundary (and _boundaries, per item): the (lat, lng) points of a valid edge from its first corner to its
 * second, `densify` between, into out[0 .. 2 (densify + 2)) (rows of (lat, lng)). */
void dggs_edges_one_boundary(dggs_projection proj, uint64_t edge, int64_t densify, double *out);

#endif
