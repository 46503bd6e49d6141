/* Grid distances (a port of index/_kernel/distance.py, operation for operation). See distance.h. */
#include "distance.h"

#include <stdbool.h>
#include <stdlib.h>

#include "bits.h"
#include "dggs.h"
#include "grid.h"
#include "grid_tables.h"
#include "strips.h"

/* _intersects: whether two sorted runs share an id. */
static bool distance_intersects(const uint64_t *x, int64_t nx, const uint64_t *y, int64_t ny) {
    int64_t i = 0, j = 0;
    while (i < nx && j < ny) {
        if (x[i] == y[j]) return true;
        if (x[i] < y[j])
            i++;
        else
            j++;
    }
    return false;
}

int64_t dggs_search_work_size(int64_t max_steps) {
    int64_t lim = max_steps < DGGS_SEARCH_LIMIT ? max_steps : DGGS_SEARCH_LIMIT;
    if (lim < 0) lim = 0;
    int64_t c = dggs_ring_size_bound(lim);
    if (c < 6) c = 6; /* ring_size_bound is 6 at k = 2 and non-decreasing from k = 3: the largest ring <= lim */
    return 9 * c;
}

/* _bfs_distance. Invariant: the distance exceeds ra + rb. Growing ring ra to ra + 1, a path of length
 * ra + 1 + rb exists iff the new ring meets ring rb. The numba code's six growing arrays are six fixed slots of
 * C ids here; a ring larger than C stops the search with DGGS_SEARCH_NO_ROOM. */
int64_t dggs_bfs_distance(uint64_t a, uint64_t b, int64_t max_steps, uint64_t *work, int64_t work_len) {
    if (a == b) return 0;
    int64_t c = work_len / 9;
    uint64_t *bufs[6]; /* (prev, cur, next) per side */
    for (int i = 0; i < 6; i++) bufs[i] = work + i * c;
    uint64_t *cand = work + 6 * c;
    int64_t ns[6] = {0, 0, 0, 0, 0, 0};
    int64_t radius[2] = {0, 0};
    if (max_steps <= 0) return -1; /* the loop below would not run */
    if (c < 1) return DGGS_SEARCH_NO_ROOM;
    bufs[1][0] = a;
    bufs[4][0] = b;
    ns[1] = ns[4] = 1;
    while (radius[0] + radius[1] < max_steps) {
        int side = ns[1] <= ns[4] ? 0 : 1;
        int o = 3 * side;
        if (ns[o + 1] > c) return DGGS_SEARCH_NO_ROOM; /* candidates need 3 * ns ids */
        int64_t n = dggs_next_ring(bufs[o + 1], ns[o + 1], bufs[o], ns[o], bufs[o + 2], c, cand);
        if (n < 0) return DGGS_SEARCH_NO_ROOM;
        if (n == 0) return -1;
        uint64_t *t = bufs[o];
        bufs[o] = bufs[o + 1];
        bufs[o + 1] = bufs[o + 2];
        bufs[o + 2] = t;
        ns[o] = ns[o + 1];
        ns[o + 1] = n;
        radius[side] += 1;
        int other = 3 - o;
        if (distance_intersects(bufs[o + 1], n, bufs[other + 1], ns[other + 1])) return radius[0] + radius[1];
    }
    return -1;
}

int64_t dggs_distance(uint64_t a, uint64_t b, int64_t max_steps) {
    if (a == b) return 0;
    int level = dggs_level_of(a);
    int64_t d;
    if (level == 0) {
        d = DGGS_GRID_FACE_DISTANCE[(a >> 57) & 31u][(b >> 57) & 31u];
    } else {
        d = dggs_chart_distance(a, b, level);
        if (d < 0) d = dggs_chart_distance(b, a, level);
        if (d < 0) d = dggs_strip_distance(a, b, level);
        if (d < 0) return DGGS_NEEDS_SEARCH;
    }
    return d <= max_steps ? d : -1;
}

int64_t dggs_search(uint64_t a, uint64_t b, int64_t max_steps, uint64_t *work, int64_t work_len) {
    return dggs_bfs_distance(a, b, max_steps < DGGS_SEARCH_LIMIT ? max_steps : DGGS_SEARCH_LIMIT, work, work_len);
}

/* Public API (dggs.h, "grid"). The checks of index/grid.py's _distances: valid ids of one level. */
dggs_error dggs_grid_distance(dggs_cell a, dggs_cell b, int64_t *out) {
    if (!dggs_is_valid(a) || !dggs_is_valid(b)) return DGGS_E_CELL;
    if (dggs_level_of(a) != dggs_level_of(b)) return DGGS_E_LEVEL_MISMATCH;
    int64_t d = dggs_distance(a, b, INT64_MAX);
    if (d == DGGS_NEEDS_SEARCH) { /* no straight face strip serves the pair (none known) */
        int64_t len = dggs_search_work_size(DGGS_SEARCH_LIMIT);
        uint64_t *work = malloc((size_t)len * sizeof *work);
        if (!work) return DGGS_E_FAILED;
        d = dggs_search(a, b, DGGS_SEARCH_LIMIT, work, len);
        free(work);
    }
    if (d < 0) return DGGS_E_FAILED;
    *out = d;
    return DGGS_OK;
}
