/* Grid distances between ids of one level: exact, by mirror lines, in O(level) time at any range (a port of
 * index/_kernel/distance.py).
 *
 * Within one face pair and away from the icosahedron vertices the distance is the count of separating mirror
 * lines in a planar chart, which proves it (dggs_chart_distance); elsewhere the fewest mirror lines over the
 * straight face strips (dggs_strip_distance). Level 0 reads the faces' distances. Any pair no strip serves
 * (none in the checks) is marked DGGS_NEEDS_SEARCH, for a bidirectional breadth-first search within
 * DGGS_SEARCH_LIMIT steps (dggs_search), which works in a caller buffer of dggs_search_work_size ids. */
#ifndef DGGS_DISTANCE_H
#define DGGS_DISTANCE_H

#include <stdint.h>

/* NEEDS_SEARCH: what dggs_distance returns for a pair only a search can settle. */
#define DGGS_NEEDS_SEARCH (-3)
/* SEARCH_LIMIT: most steps the fallback search takes (O(d^2) cells: 4096 steps is about 20 M cells). */
#define DGGS_SEARCH_LIMIT 4096
/* What the search returns when a ring outgrows its work buffer (the numba code grows its arrays instead; with
 * dggs_search_work_size ids this means a ring broke ring_size_bound, never seen). */
#define DGGS_SEARCH_NO_ROOM (-2)

/* distance: edge steps on a shortest path between two valid cells of one level (the caller checks the levels);
 * -1 if it exceeds max_steps; DGGS_NEEDS_SEARCH if no straight strip serves the pair (then dggs_search). */
int64_t dggs_distance(uint64_t a, uint64_t b, int64_t max_steps);

/* Ids of work dggs_search (and dggs_bfs_distance) need for max_steps: rings of up to
 * C = max(6, ring_size_bound(min(max_steps, DGGS_SEARCH_LIMIT))) cells, six of them (prev, cur, next per side)
 * and 3 C candidates: 9 C (88,479 ids, 708 KB, at the limit). */
int64_t dggs_search_work_size(int64_t max_steps);
/* _bfs_distance: bidirectional breadth-first search, rings from both ends, the smaller grows. The distance, -1
 * beyond max_steps (or if a side's rings run out), DGGS_SEARCH_NO_ROOM if a ring does not fit in `work`
 * (work_len ids, split as dggs_search_work_size says: C = work_len / 9). */
int64_t dggs_bfs_distance(uint64_t a, uint64_t b, int64_t max_steps, uint64_t *work, int64_t work_len);
/* search: the distance by breadth-first search, or -1 beyond min(max_steps, DGGS_SEARCH_LIMIT) steps;
 * DGGS_SEARCH_NO_ROOM as dggs_bfs_distance. */
int64_t dggs_search(uint64_t a, uint64_t b, int64_t max_steps, uint64_t *work, int64_t work_len);

#endif
