/* Grid distances (distance.c, strips.c, grid_tables.c): against the breadth-first search, the graph's
 * invariants, the public API, and outputs of the numba kernel frozen by tools/freeze_distance.py. */
#include <stdlib.h>

#include "bits.h"
#include "check.h"
#include "distance.h"
#include "dggs.h"
#include "frozen_distance.h"
#include "grid.h"
#include "grid_tables.h"
#include "grid_testutil.h"
#include "strips.h"

#define NELEM(a) (sizeof(a) / sizeof((a)[0]))

static uint64_t *work;
static int64_t work_len;

static void test_frozen(void) {
    for (size_t i = 0; i < NELEM(FROZEN_DISTANCE); i++) {
        CHECK(dggs_distance(FROZEN_DISTANCE[i].a, FROZEN_DISTANCE[i].b, (int64_t)1 << 40) == FROZEN_DISTANCE[i].d);
        if (FROZEN_DISTANCE[i].level >= 1)
            CHECK(dggs_strip_distance(FROZEN_DISTANCE[i].a, FROZEN_DISTANCE[i].b, FROZEN_DISTANCE[i].level) ==
                  FROZEN_DISTANCE[i].strip);
    }
    for (size_t i = 0; i < NELEM(FROZEN_SEARCH); i++)
        CHECK(dggs_search(FROZEN_SEARCH[i].a, FROZEN_SEARCH[i].b, FROZEN_SEARCH[i].max_steps, work, work_len) ==
              FROZEN_SEARCH[i].d);
}

/* The exact distance equals the search's on walks; it is symmetric; a step changes it by exactly one (from
 * level 1 the graph is bipartite); max_steps cuts it off. */
static void test_against_search(void) {
    uint64_t state = 10;
    for (int level = 0; level <= DGGS_MAX_LEVEL; level++) {
        for (int t = 0; t < 40; t++) {
            uint64_t a = gt_random_id(&state, level);
            uint64_t b = gt_walk(&state, a, gt_below(&state, 30));
            int64_t d = dggs_distance(a, b, (int64_t)1 << 40);
            CHECK(d >= 0);
            CHECK(d == dggs_search(a, b, (int64_t)1 << 40, work, work_len));
            CHECK(d == dggs_distance(b, a, (int64_t)1 << 40));
            if (d > 0) CHECK(dggs_distance(a, b, d - 1) == -1 && dggs_distance(a, b, d) == d);
            if (d > 0) CHECK(dggs_search(a, b, d - 1, work, work_len) == -1);
            if (level >= 1) {
                for (int j = 0; j < 3; j++) {
                    int64_t e = dggs_distance(dggs_neighbour(a, level, j), b, (int64_t)1 << 40);
                    CHECK(e == d + 1 || e == d - 1);
                }
                int64_t s = dggs_strip_distance(a, b, level);
                CHECK(s < 0 || s >= d);
                int64_t c = dggs_chart_distance(a, b, level);
                CHECK(c < 0 || c == d);
            }
        }
    }
    /* far pairs: symmetric, and never NEEDS_SEARCH in practice */
    for (int level = 1; level <= DGGS_MAX_LEVEL; level++) {
        for (int t = 0; t < 200; t++) {
            uint64_t a = gt_random_id(&state, level), b = gt_random_id(&state, level);
            int64_t d = dggs_distance(a, b, INT64_MAX);
            CHECK(d >= 0 && d == dggs_distance(b, a, INT64_MAX));
        }
    }
    /* level 0: the dodecahedron graph's distances, diameter 5 */
    int64_t most = 0;
    for (int f = 0; f < 20; f++)
        for (int g = 0; g < 20; g++) {
            int64_t d = dggs_distance(dggs_base_cell(f), dggs_base_cell(g), 99);
            CHECK(d == dggs_search(dggs_base_cell(f), dggs_base_cell(g), 99, work, work_len));
            most = d > most ? d : most;
        }
    CHECK(most == 5);
}

static void test_search_limits(void) {
    uint64_t state = 11;
    uint64_t a = gt_random_id(&state, 20), b = gt_walk(&state, a, 40);
    int64_t d = dggs_distance(a, b, INT64_MAX);
    CHECK(dggs_search(a, b, INT64_MAX, work, 9 * 4) == DGGS_SEARCH_NO_ROOM); /* rings of 4 ids: no room */
    CHECK(dggs_search(a, b, INT64_MAX, NULL, 0) == DGGS_SEARCH_NO_ROOM);
    CHECK(dggs_search(a, a, INT64_MAX, NULL, 0) == 0);
    CHECK(dggs_search(a, b, 0, NULL, 0) == -1);
    CHECK(dggs_bfs_distance(a, b, INT64_MAX, work, work_len) == d);
    CHECK(dggs_search_work_size(DGGS_SEARCH_LIMIT) == 9 * 9831);
    CHECK(dggs_search_work_size(1) == 9 * 6 && dggs_search_work_size(-5) == 9 * 6);
    CHECK(dggs_search_work_size(INT64_MAX) == dggs_search_work_size(DGGS_SEARCH_LIMIT));
}

static void test_public(void) {
    uint64_t state = 12;
    uint64_t a = gt_random_id(&state, 14), b = gt_walk(&state, a, 25);
    int64_t d = -1;
    CHECK(dggs_grid_distance(a, b, &d) == DGGS_OK && d == dggs_distance(a, b, INT64_MAX));
    CHECK(dggs_grid_distance(a, a, &d) == DGGS_OK && d == 0);
    CHECK(dggs_grid_distance(a, dggs_parent_at(a, 13), &d) == DGGS_E_LEVEL_MISMATCH);
    CHECK(dggs_grid_distance(a, 0, &d) == DGGS_E_CELL);
    CHECK(dggs_grid_distance((uint64_t)1 << 63, a, &d) == DGGS_E_CELL);
}

int main(void) {
    work_len = dggs_search_work_size(DGGS_SEARCH_LIMIT);
    work = malloc((size_t)work_len * sizeof *work);
    if (!work) return EXIT_FAILURE;
    test_frozen();
    test_against_search();
    test_search_limits();
    test_public();
    free(work);
    CHECK_DONE();
}
