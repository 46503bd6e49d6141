/* Shortest paths in the edge graph: one greedy walk per pair, a step per output cell (a port of
 * index/_kernel/paths.py).
 *
 * Every step of a shortest path lowers the exact grid distance to the target by one, and from level 1 the cells
 * form a bipartite graph, so each neighbour is one step nearer or one step farther. The walk takes, at each
 * cell, the first neighbour (in column order of dggs_neighbour) that is one step nearer. */
#ifndef DGGS_PATHS_H
#define DGGS_PATHS_H

#include <stdint.h>

/* What dggs_paths_walk returns when a step needs the fallback search and `work` cannot hold it (NULL, or fewer
 * than dggs_search_work_size(DGGS_SEARCH_LIMIT) ids, or a ring broke that bound): call again with that buffer. */
#define DGGS_WALK_NEEDS_WORK (-2)

/* _walk: fill out[start..stop) with a shortest path from a to b (stop - start - 1 = their distance); 0, or -1 if
 * a step found no nearer neighbour (a wrong distance: never seen), or DGGS_WALK_NEEDS_WORK. `work` (work_len
 * ids, may be NULL) is the search's scratch for pairs no straight strip serves (never seen in the checks). */
int dggs_paths_walk(uint64_t a, uint64_t b, uint64_t *out, int64_t start, int64_t stop, uint64_t *work,
                    int64_t work_len);

#endif
