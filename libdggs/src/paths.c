/* Shortest paths (a port of index/_kernel/paths.py, operation for operation). See paths.h. */
#include "paths.h"

#include <stdlib.h>

#include "bits.h"
#include "dggs.h"
#include "distance.h"
#include "grid.h"

#define PATHS_FAR ((int64_t)1 << 62)

/* _steps: the exact distance, by the search where no strip serves. */
static int64_t paths_steps(uint64_t x, uint64_t target, uint64_t *work, int64_t work_len) {
    int64_t d = dggs_distance(x, target, PATHS_FAR);
    if (d == DGGS_NEEDS_SEARCH) d = dggs_search(x, target, DGGS_SEARCH_LIMIT, work, work_len);
    return d;
}

/* _walk: the cell stepped from is one step farther, so it is skipped; of the other two, if the first is not
 * nearer the second is: one distance evaluation a step, two at most on the first. Level 0 (whose graph has
 * 5-cycles, so neighbours can be equally far) checks every candidate. */
int dggs_paths_walk(uint64_t a, uint64_t b, uint64_t *out, int64_t start, int64_t stop, uint64_t *work,
                    int64_t work_len) {
    out[start] = a;
    uint64_t cur = a, prev = 0;
    int level = dggs_level_of(a);
    int64_t d = stop - start - 1;
    int64_t j = start;
    while (d > 0) {
        uint64_t nxt = 0;
        int left = prev == 0 ? 3 : 2; /* candidates not yet ruled out */
        for (int col = 0; col < 3; col++) {
            uint64_t nb = dggs_neighbour(cur, level, col);
            if (nb == prev) continue;
            if (d == 1) {
                if (nb == b) {
                    nxt = nb;
                    break;
                }
            } else if (left == 1 && level > 0) {
                nxt = nb;
                break;
            } else {
                int64_t s = paths_steps(nb, b, work, work_len);
                if (s == DGGS_SEARCH_NO_ROOM) return DGGS_WALK_NEEDS_WORK;
                if (s == d - 1) {
                    nxt = nb;
                    break;
                }
            }
            left -= 1;
        }
        if (nxt == 0) return -1;
        out[++j] = nxt;
        prev = cur;
        cur = nxt;
        d -= 1;
    }
    return cur == b ? 0 : -1;
}

/* Public API (dggs.h, "grid"). */
dggs_error dggs_grid_path_cells_size(dggs_cell a, dggs_cell b, int64_t *size) {
    int64_t d;
    dggs_error err = dggs_grid_distance(a, b, &d);
    if (err) return err;
    *size = d + 1;
    return DGGS_OK;
}

dggs_error dggs_grid_path_cells(dggs_cell a, dggs_cell b, dggs_cell *out, int64_t size) {
    int64_t n;
    dggs_error err = dggs_grid_path_cells_size(a, b, &n);
    if (err) return err;
    if (size < n) return DGGS_E_BUFFER;
    int st = dggs_paths_walk(a, b, out, 0, n, NULL, 0);
    if (st == DGGS_WALK_NEEDS_WORK) { /* a step needs the fallback search (never seen): its work space */
        int64_t len = dggs_search_work_size(DGGS_SEARCH_LIMIT);
        uint64_t *work = malloc((size_t)len * sizeof *work);
        if (!work) return DGGS_E_FAILED;
        st = dggs_paths_walk(a, b, out, 0, n, work, len);
        free(work);
    }
    return st == 0 ? DGGS_OK : DGGS_E_FAILED;
}
