/* Dissolve a set of cells into its outline: outline edges by id, rings, ring points. A port of
 * index/_kernel/dissolve.py (and of ivea_edges.ring_points, the ring points recompiled with IVEA's inverse:
 * here `proj` selects).
 *
 * Everything is integer work on ids but the last step (the ring's points):
 * - the set is sorted, without duplicates and without cells inside other cells of the set (dggs_drop_covered),
 *   so its cells' id ranges are disjoint and a cell is covered by the set exactly when the greatest set id at or
 *   below it is itself or an ancestor (dggs_covered, one binary search);
 * - a cell coarser than the finest level of the set stands for its boundary descendants at that level, the
 *   descendants with an edge on its outline (dggs_dissolve_descend): the edge neighbour of a descendant is
 *   outside the cell exactly when its id is outside the cell's range;
 * - an edge of a fine cell is on the outline when the cell across it (same level, grid.h) is not covered
 *   (dggs_outline_mask): edges shared by two cells of the set cancel by identity, never by coordinates;
 * - the outline edges are chained into rings (dggs_chain): an edge runs from corner i to corner i + 1 of its
 *   cell, counter-clockwise, so the set lies on its left; at its end corner the walk turns through the covered
 *   cells around the corner until the cell across is not covered: that edge is the next one.
 * dggs_ring_points then writes each ring's (lat, lng) points as points.c's special ring writes a cell's: each
 * edge's points straight on its face plane, a pole on the ring as two points at latitude +-90, the antimeridian
 * crossing between two points bisected to longitude +-180.
 *
 * Inputs are assumed checked, as the numba functions assume (valid ids; the set sorted and disjoint). */
#ifndef DGGS_DISSOLVE_H
#define DGGS_DISSOLVE_H

#include <stdbool.h>
#include <stdint.h>

#include "dggs.h"

/* drop_covered: keep[i] = whether sorted unique ids[i] is not inside an earlier id of the array. */
void dggs_drop_covered(const uint64_t *ids, int64_t n, uint8_t *keep);
/* _covered: whether y is in the range of a cell of `cells` (n, sorted, disjoint ranges). */
bool dggs_covered(const uint64_t *cells, int64_t n, uint64_t y);
/* The stack _descend needs: 6 (level - top + 1) ids, at most this many (levels 0..28). */
#define DGGS_DESCEND_STACK (6 * (DGGS_MAX_LEVEL + 1))
/* _descend: the boundary descendants of `cell` at `level` (> its level, <= 28), depth first (not sorted); the
 * first min(count, cap) written to out (out may be NULL with cap 0: count only, as numba's write=False);
 * returns their count, or -1 for a level not finer than the cell's or past 28. */
int64_t dggs_dissolve_descend(uint64_t cell, int level, uint64_t *out, int64_t cap);
/* _outline_mask, per item: mask[col] = whether edge col of the fine cell `cell` is on the outline of `cells`. */
void dggs_outline_mask(uint64_t cell, const uint64_t *cells, int64_t n, uint8_t mask[3]);
/* _find: the index of edge (cell, col) in the sorted edges (ecell, ecol)[0..m), or -1. */
int64_t dggs_dissolve_find(const uint64_t *ecell, const int64_t *ecol, int64_t m, uint64_t cell, int64_t col);
/* chain: chain the m outline edges (sorted by cell, then column) into rings. Writes order[0..m) (the edges'
 * indices ring after ring) and starts[0..*nstarts) (the start of each ring in order, then the end; at most
 * m + 1); `visited` is m bytes of scratch. Returns -1, or the index of an edge whose successor was not found
 * (a broken grid; starts' last entry is then the end so far). */
int64_t dggs_chain(const uint64_t *ecell, const int64_t *ecol, int64_t m, const uint64_t *cells, int64_t n,
                   uint8_t *visited, int64_t *order, int64_t *starts, int64_t *nstarts);
/* ring_point_bound: rows dggs_ring_points may write for m edges of steps[i] segments each. */
int64_t dggs_ring_point_bound(const int64_t *steps, int64_t m);
/* _grid_point: point j of `step` along the planar edge (x0, y0) -> (x1, y1) of `face` as (lat, lng), computed as
 * points.c's boundaries compute it. */
void dggs_grid_point(dggs_projection proj, int face, double x0, double y0, double x1, double y1, int64_t j,
                     int64_t step, double *lat, double *lng);
/* ring_points: write the rings' (lat, lng) points into out (rows of 2 doubles, `rows` of them, at least
 * dggs_ring_point_bound); ends[r] is one past ring r's last row. cell, col and steps (segments per edge:
 * densify + 1, >= 1) are the edges in ring order, ring r being starts[r]..starts[r + 1] (nstarts entries).
 * corner[row] is set where the row is a corner of the outline (not a pole, a crossing or a densified point).
 * `ts` is scratch of ts_len >= max(steps) + 2 doubles. DGGS_E_BUFFER if out or ts is too small (nothing is
 * written past them), else DGGS_OK. */
dggs_error dggs_ring_points(dggs_projection proj, const uint64_t *cell, const int64_t *col, const int64_t *steps,
                            const int64_t *starts, int64_t nstarts, double *out, int64_t rows, uint8_t *corner,
                            int64_t *ends, double *ts, int64_t ts_len);

#endif
