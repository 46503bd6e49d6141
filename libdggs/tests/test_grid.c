/* The grid graph (grid.c, grid_tables.c): invariants, values from docs/grid.md, the public API, and outputs of
 * the numba kernel frozen by tools/freeze_grid.py (frozen_grid.h). */
#include <stdlib.h>
#include <string.h>

#include "bits.h"
#include "check.h"
#include "dggs.h"
#include "frozen_grid.h"
#include "grid.h"
#include "grid_tables.h"
#include "grid_testutil.h"

#define NELEM(a) (sizeof(a) / sizeof((a)[0]))

static int sorted_unique(const uint64_t *a, int64_t n) {
    for (int64_t i = 1; i < n; i++)
        if (!(a[i - 1] < a[i])) return 0;
    return 1;
}

static int contains(const uint64_t *a, int64_t n, uint64_t x) {
    for (int64_t i = 0; i < n; i++)
        if (a[i] == x) return 1;
    return 0;
}

static void test_frozen(void) {
    for (size_t i = 0; i < NELEM(FROZEN_NEIGHBOURS); i++) {
        uint64_t out[3];
        dggs_neighbours(FROZEN_NEIGHBOURS[i][0], out);
        for (int j = 0; j < 3; j++) {
            CHECK_EQ_U64(out[j], FROZEN_NEIGHBOURS[i][j + 1]);
            CHECK_EQ_U64(dggs_neighbour(FROZEN_NEIGHBOURS[i][0], dggs_level_of(FROZEN_NEIGHBOURS[i][0]), j),
                         FROZEN_NEIGHBOURS[i][j + 1]);
        }
    }
    uint64_t row[160], table[512], work[6 * 160];
    for (size_t i = 0; i < NELEM(FROZEN_DISK); i++) {
        int level = dggs_level_of(FROZEN_DISK[i].cell);
        int64_t w = dggs_disk_width(FROZEN_DISK[i].k, level);
        CHECK(w <= 160 && dggs_disk_table_size(w) <= 512);
        memset(table, 0, sizeof table);
        int64_t m = dggs_disk_row(FROZEN_DISK[i].cell, FROZEN_DISK[i].k, row, w, table, dggs_disk_table_size(w));
        CHECK(m == FROZEN_DISK[i].count);
        for (int64_t j = 0; j < m && j < 128; j++) CHECK_EQ_U64(row[j], FROZEN_DISK[i].ids[j]);
        for (int j = 0; j < 512; j++) CHECK(table[j] == 0); /* the set is emptied again */
    }
    for (size_t i = 0; i < NELEM(FROZEN_RING); i++) {
        int level = dggs_level_of(FROZEN_RING[i].cell);
        int64_t w = dggs_ring_width(FROZEN_RING[i].k, level);
        CHECK(w <= 160 && dggs_ring_work_size(w) <= 6 * 160);
        int64_t m = dggs_ring_row(FROZEN_RING[i].cell, FROZEN_RING[i].k, row, w, work);
        CHECK(m == FROZEN_RING[i].count);
        for (int64_t j = 0; j < m && j < 128; j++) CHECK_EQ_U64(row[j], FROZEN_RING[i].ids[j]);
    }
    for (size_t i = 0; i < NELEM(FROZEN_BOUNDS); i++) {
        CHECK(dggs_disk_size_bound(FROZEN_BOUNDS[i][0]) == FROZEN_BOUNDS[i][1]);
        CHECK(dggs_ring_size_bound(FROZEN_BOUNDS[i][0]) == FROZEN_BOUNDS[i][2]);
    }
    for (size_t i = 0; i < NELEM(FROZEN_CHART); i++) {
        CHECK(dggs_chart_distance(FROZEN_CHART[i].a, FROZEN_CHART[i].b, FROZEN_CHART[i].level) == FROZEN_CHART[i].ab);
        CHECK(dggs_chart_distance(FROZEN_CHART[i].b, FROZEN_CHART[i].a, FROZEN_CHART[i].level) == FROZEN_CHART[i].ba);
    }
}

/* Neighbours are symmetric, of the same level, valid and distinct, and are_neighbours agrees. */
static void test_neighbour_invariants(void) {
    uint64_t state = 1;
    for (int level = 0; level <= DGGS_MAX_LEVEL; level++) {
        for (int t = 0; t < 300; t++) {
            uint64_t c = gt_random_id(&state, level), nb[3];
            dggs_neighbours(c, nb);
            CHECK(nb[0] != nb[1] && nb[1] != nb[2] && nb[0] != nb[2]);
            for (int j = 0; j < 3; j++) {
                CHECK(dggs_is_valid(nb[j]) && dggs_level_of(nb[j]) == level && nb[j] != c);
                uint64_t back[3];
                dggs_neighbours(nb[j], back);
                CHECK(back[0] == c || back[1] == c || back[2] == c);
                CHECK(dggs_are_neighbours(c, nb[j]) && dggs_are_neighbours(nb[j], c));
            }
            CHECK(!dggs_are_neighbours(c, c));
            if (level > 0) CHECK(!dggs_are_neighbours(c, dggs_parent_at(c, level - 1)));
            /* from level 1 the graph is bipartite: a step flips the orientation */
            if (level > 0)
                for (int j = 0; j < 3; j++) CHECK(dggs_is_ccw(nb[j]) != dggs_is_ccw(c));
        }
    }
}

/* docs/grid.md: "C401" and "C402" share an edge; the level sizes; the disk and ring bounds. */
static void test_docs(void) {
    uint64_t c401 = DGGS_MARKER | ((uint64_t)2 << 57) | ((uint64_t)5 << 54) | ((uint64_t)1 << 52) | ((uint64_t)2 << 50);
    uint64_t c402 = (c401 & ~((uint64_t)3 << 50)) | ((uint64_t)3 << 50);
    CHECK(dggs_are_neighbours(c401, c402));
    CHECK(dggs_level_cells(0) == 20 && dggs_level_cells(1) == 120 && dggs_level_cells(2) == 360);
    CHECK(dggs_level_cells(28) == 120 * 7625597484987LL);
    static const int64_t disk[] = {1, 4, 10, 16, 25, 37, 52};
    for (int k = 0; k < 7; k++) CHECK(dggs_disk_size_bound(k) == disk[k]);
    static const int64_t ring[] = {1, 3, 6, 7, 9, 12, 15, 17};
    for (int k = 0; k < 8; k++) CHECK(dggs_ring_size_bound(k) == ring[k]);
    CHECK(dggs_disk_width(100, 0) == 20 && dggs_ring_width(100, 1) == 120 && dggs_disk_width(3, 5) == 16);
    /* level 0 is the dodecahedron graph: rings of 1, 3, 6, 6, 3, 1 faces */
    static const int64_t dodeca[] = {1, 3, 6, 6, 3, 1, 0};
    uint64_t out[20], work[6 * 20];
    for (int f = 0; f < 20; f++) {
        for (int k = 0; k < 7; k++) {
            int64_t m = dggs_ring_row(dggs_base_cell(f), k, out, 20, work);
            CHECK(m == dodeca[k]);
        }
    }
    /* numba's float ** int: exponentiation by squaring */
    CHECK_SAME_DOUBLE(dggs_grid_powi(3.0, 4), 81.0);
    CHECK_SAME_DOUBLE(dggs_grid_powi(2.0, -2), 0.25);
    CHECK_SAME_DOUBLE(dggs_grid_powi(1.5, 0), 1.0);
}

/* Disks are the union of rings 0..k, sorted; disk_size_count counts them; rings never exceed their bound. */
static void test_disks_rings(void) {
    uint64_t state = 2;
    enum { K = 9 };
    uint64_t drow[400], table[1024], rrow[64], work[6 * 64], sw[8 * 200];
    for (int level = 0; level <= DGGS_MAX_LEVEL; level++) {
        for (int t = 0; t < 40; t++) {
            uint64_t c = gt_random_id(&state, level);
            int64_t w = dggs_disk_width(K, level), ts = dggs_disk_table_size(w);
            memset(table, 0, sizeof table);
            int64_t n = dggs_disk_row(c, K, drow, w, table, ts);
            CHECK(n > 0 && n <= w && sorted_unique(drow, n) && contains(drow, n, c));
            int64_t total = 0;
            for (int k = 0; k <= K; k++) {
                int64_t rw = dggs_ring_width(k, level);
                int64_t m = dggs_ring_row(c, k, rrow, rw, work);
                CHECK(m >= 0 && m <= rw && m <= dggs_ring_size_bound(k) + (level == 0 ? 1 : 0));
                CHECK(sorted_unique(rrow, m));
                for (int64_t j = 0; j < m; j++) CHECK(contains(drow, n, rrow[j]));
                total += m;
            }
            CHECK(total == n);
            CHECK(dggs_disk_size_count(c, K, 1 << 20, sw, (int64_t)NELEM(sw)) == n);
            int64_t early = dggs_disk_size_count(c, K, 5, sw, (int64_t)NELEM(sw));
            CHECK(early > 5 || early == n);
        }
    }
    /* too narrow a row: -1, and the table is left empty */
    uint64_t c = gt_random_id(&state, 12);
    memset(table, 0, sizeof table);
    CHECK(dggs_disk_row(c, 3, drow, 5, table, 64) == -1);
    for (int j = 0; j < 64; j++) CHECK(table[j] == 0);
    CHECK(dggs_ring_row(c, 3, rrow, 2, work) == -1);
    CHECK(dggs_ring_row(c, 0, rrow, 0, work) == -1);
    /* disk_size_count: too small a work buffer says so (-2) */
    CHECK(dggs_disk_size_count(c, 30, 1 << 20, sw, 16) == -2);
    CHECK(dggs_disk_size_count(c, 30, 1 << 20, sw, 0) == -2);
    /* disk_of's checks */
    CHECK(dggs_disk_of_width(c, 65, 1 << 20) == -1 && dggs_disk_of_width(0, 1, 1 << 20) == -1);
    CHECK(dggs_disk_of_width(c, 3, 15) == -1 && dggs_disk_of_width(c, 3, 16) == 16);
}

/* The heap sort past 48 ids gives the ascending order. */
static void test_sort(void) {
    uint64_t state = 3, a[300], b[300];
    for (int n = 0; n < 300; n += 7) {
        for (int i = 0; i < n; i++) a[i] = b[i] = gt_next(&state) % 50; /* repeats too */
        dggs_sort_small(a, n);
        for (int i = 1; i < n; i++) CHECK(a[i - 1] <= a[i]);
        for (int i = 0; i < n; i++) CHECK(contains(a, n, b[i]));
    }
}

static void test_public(void) {
    uint64_t state = 4;
    uint64_t c = gt_random_id(&state, 9), out[3];
    CHECK(dggs_edge_neighbors(c, out) == DGGS_OK);
    uint64_t nb[3];
    dggs_neighbours(c, nb);
    CHECK(memcmp(out, nb, sizeof nb) == 0);
    CHECK(dggs_edge_neighbors(0, out) == DGGS_E_CELL);
    int yes = -1;
    CHECK(dggs_are_neighbor_cells(c, nb[1], &yes) == DGGS_OK && yes == 1);
    CHECK(dggs_are_neighbor_cells(c, c, &yes) == DGGS_OK && yes == 0);
    CHECK(dggs_are_neighbor_cells(c, 12345, &yes) == DGGS_E_CELL);

    int64_t size = 0, count = -1;
    CHECK(dggs_grid_disk_size(c, 4, &size) == DGGS_OK && size == 25 + 64);
    CHECK(dggs_grid_disk_size(c, -1, &size) == DGGS_E_DOMAIN);
    CHECK(dggs_grid_disk_size(c, ((int64_t)1 << 31) + 1, &size) == DGGS_E_DOMAIN);
    CHECK(dggs_grid_disk_size(1, 1, &size) == DGGS_E_CELL);
    CHECK(dggs_grid_disk_size(c, 4, &size) == DGGS_OK);
    uint64_t *buf = malloc((size_t)size * sizeof *buf);
    CHECK(buf != NULL);
    if (!buf) return;
    for (int64_t i = 0; i < size; i++) buf[i] = 99;
    CHECK(dggs_grid_disk(c, 4, buf, size - 1, &count) == DGGS_E_BUFFER);
    CHECK(dggs_grid_disk(c, 4, buf, size, &count) == DGGS_OK && count > 0 && count <= 25);
    CHECK(sorted_unique(buf, count) && contains(buf, count, c));
    for (int64_t i = count; i < size; i++) CHECK(buf[i] == 0);
    free(buf);

    CHECK(dggs_grid_ring_size(c, 4, &size) == DGGS_OK && size == 9 + 6 * 9);
    buf = malloc((size_t)size * sizeof *buf);
    CHECK(buf != NULL);
    if (!buf) return;
    CHECK(dggs_grid_ring(c, 4, buf, size - 1, &count) == DGGS_E_BUFFER);
    CHECK(dggs_grid_ring(c, 4, buf, size, &count) == DGGS_OK && count > 0 && count <= 9);
    CHECK(sorted_unique(buf, count) && !contains(buf, count, c));
    for (int64_t i = count; i < size; i++) CHECK(buf[i] == 0);
    CHECK(dggs_grid_ring(c, -2, buf, size, &count) == DGGS_E_DOMAIN);
    free(buf);
    /* the whole of level 0 within 5 steps, nothing at 6 */
    uint64_t big[20 + 64 + 6 * 20];
    CHECK(dggs_grid_disk(dggs_base_cell(7), 5, big, (int64_t)NELEM(big), &count) == DGGS_OK && count == 20);
    CHECK(dggs_grid_ring(dggs_base_cell(7), 6, big, (int64_t)NELEM(big), &count) == DGGS_OK && count == 0);
}

int main(void) {
    test_frozen();
    test_neighbour_invariants();
    test_docs();
    test_disks_rings();
    test_sort();
    test_public();
    CHECK_DONE();
}
