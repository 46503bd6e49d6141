/* Shortest paths (paths.c): each path is a chain of neighbours of distance + 1 cells from a to b; the public
 * API; whole paths of the numba kernel frozen by tools/freeze_distance.py. */
#include <stdlib.h>

#include "bits.h"
#include "check.h"
#include "distance.h"
#include "dggs.h"
#include "frozen_distance.h"
#include "grid.h"
#include "grid_testutil.h"
#include "paths.h"

#define NELEM(a) (sizeof(a) / sizeof((a)[0]))

static void test_frozen(void) {
    uint64_t out[NELEM(FROZEN_PATH_CELLS)];
    for (size_t i = 0; i < NELEM(FROZEN_PATH_ENDS); i++) {
        int st = dggs_paths_walk(FROZEN_PATH_ENDS[i][0], FROZEN_PATH_ENDS[i][1], out, FROZEN_PATH_OFFSETS[i],
                                 FROZEN_PATH_OFFSETS[i + 1], NULL, 0);
        CHECK(st == 0);
    }
    for (size_t j = 0; j < NELEM(FROZEN_PATH_CELLS); j++) CHECK_EQ_U64(out[j], FROZEN_PATH_CELLS[j]);
}

static void test_chains(void) {
    uint64_t state = 20;
    static uint64_t path[2000];
    for (int level = 0; level <= DGGS_MAX_LEVEL; level++) {
        for (int t = 0; t < 40; t++) {
            uint64_t a = gt_random_id(&state, level);
            uint64_t b = level <= 6 ? gt_random_id(&state, level) : gt_walk(&state, a, gt_below(&state, 200));
            int64_t d = dggs_distance(a, b, INT64_MAX);
            CHECK(d >= 0 && d < 2000);
            if (d < 0 || d >= 2000) continue;
            CHECK(dggs_paths_walk(a, b, path, 0, d + 1, NULL, 0) == 0);
            CHECK(path[0] == a && path[d] == b);
            for (int64_t j = 1; j <= d; j++) {
                CHECK(dggs_are_neighbours(path[j - 1], path[j]));
                CHECK(dggs_distance(path[j], b, INT64_MAX) == d - j);
            }
            /* a wrong length: no path */
            if (d >= 2) CHECK(dggs_paths_walk(a, b, path, 0, d, NULL, 0) == -1);
            if (level >= 1 && d + 2 < 2000) CHECK(dggs_paths_walk(a, b, path, 0, d + 2, NULL, 0) == -1);
        }
    }
}

static void test_public(void) {
    uint64_t state = 21;
    uint64_t a = gt_random_id(&state, 17), b = gt_walk(&state, a, 60);
    int64_t n = 0;
    CHECK(dggs_grid_path_cells_size(a, b, &n) == DGGS_OK && n == dggs_distance(a, b, INT64_MAX) + 1);
    uint64_t *out = malloc((size_t)n * sizeof *out);
    if (!out) return;
    CHECK(dggs_grid_path_cells(a, b, out, n - 1) == DGGS_E_BUFFER);
    CHECK(dggs_grid_path_cells(a, b, out, n) == DGGS_OK && out[0] == a && out[n - 1] == b);
    for (int64_t j = 1; j < n; j++) CHECK(dggs_are_neighbours(out[j - 1], out[j]));
    free(out);
    uint64_t one[1];
    CHECK(dggs_grid_path_cells_size(a, a, &n) == DGGS_OK && n == 1);
    CHECK(dggs_grid_path_cells(a, a, one, 1) == DGGS_OK && one[0] == a);
    CHECK(dggs_grid_path_cells_size(a, dggs_parent_at(a, 3), &n) == DGGS_E_LEVEL_MISMATCH);
    CHECK(dggs_grid_path_cells(0, a, one, 1) == DGGS_E_CELL);
}

int main(void) {
    test_frozen();
    test_chains();
    test_public();
    CHECK_DONE();
}
