/* Corners (vertex.c): fans against the geometry (every cell of a fan has that corner, at the same point), their
 * sizes round the special corners, the corner-sharing disk against a plain breadth-first search over fans (a set of
 * every cell seen, no marks), and the public API's errors. */
#include "vertex.h"

#include <math.h>

#include "bits.h"
#include "check.h"
#include "dggs.h"
#include "grid.h"
#include "hierarchy.h"
#include "testutil.h"

static uint64_t rnd_state = 32;
static uint64_t rnd(void) { return splitmix64(&rnd_state); }
static uint64_t rnd_cell(int level) {
    uint64_t c = dggs_base_cell((int)(rnd() % 20));
    if (level >= 1) c |= (rnd() % 6 + 1) << DGGS_L1_SHIFT;
    for (int k = 2; k <= level; k++) c |= (rnd() % 3 + 1) << (2 * (DGGS_MAX_LEVEL - k));
    return c;
}

/* Unit vector of corner `corner` of `cell` (its geodetic boundary). */
static const double DEG = 3.14159265358979323846 / 180.0;

static void corner_xyz(uint64_t cell, int corner, double v[3]) {
    double b[6];
    size_t count = 0;
    CHECK(dggs_cell_to_boundary(cell, 0, DGGS_ISEA, b, 3, &count) == DGGS_OK && count == 3);
    double lat = b[2 * corner] * DEG, lng = b[2 * corner + 1] * DEG;
    v[0] = cos(lat) * cos(lng);
    v[1] = cos(lat) * sin(lng);
    v[2] = sin(lat);
}

/* Every cell of the fan has the fan's corner (as its corners[i]) at one point, within 1e-9 of the unit sphere
 * (corners of a level-28 cell are 0.8 m = 1.2e-7 apart), and no other corner of its there; the cells are distinct
 * edge neighbours in turn, closing the ring. */
static void check_fan(uint64_t cell, int corner) {
    uint64_t fan[DGGS_MAX_FAN];
    int corners[DGGS_MAX_FAN], n = 0;
    CHECK(dggs_cell_to_vertex_fan(cell, corner, fan, corners, &n) == DGGS_OK);
    CHECK(n == 4 || n == 5 || n == 6 || n == 10 || n == 12);
    double p[3];
    corner_xyz(cell, corner, p);
    for (int i = 0; i < n; i++) {
        for (int c = 0; c < 3; c++) {
            double q[3];
            corner_xyz(fan[i], c, q);
            double d = sqrt((q[0] - p[0]) * (q[0] - p[0]) + (q[1] - p[1]) * (q[1] - p[1]) + (q[2] - p[2]) * (q[2] - p[2]));
            if (c == corners[i]) CHECK(d < 1e-9);
            else CHECK(d > 1e-8);
        }
        CHECK(dggs_are_neighbours(fan[i], fan[(i + 1) % n]));
        for (int j = 0; j < i; j++) CHECK(fan[i] != fan[j]);
    }
}

static void test_fans_are_shared_corners(void) {
    for (int level = 0; level <= 2; level++) { /* whole levels */
        uint64_t cells[720];
        int64_t n = 0;
        for (int f = 0; f < 20; f++) {
            int64_t size = 0;
            CHECK(dggs_cell_to_children_size(dggs_base_cell(f), level, &size) == DGGS_OK);
            CHECK(dggs_cell_to_children(dggs_base_cell(f), level, cells + n, size) == DGGS_OK);
            n += size;
        }
        for (int64_t i = 0; i < n; i++)
            for (int c = 0; c < 3; c++) check_fan(cells[i], c);
    }
    for (int t = 0; t < 300; t++) check_fan(rnd_cell(3 + (int)(rnd() % 26)), (int)(rnd() % 3));
}

static int fan_size(double lat, double lng, int level, int corner) {
    uint64_t cell = 0, fan[DGGS_MAX_FAN];
    int corners[DGGS_MAX_FAN], n = 0;
    CHECK(dggs_latlng_to_cell(lat, lng, level, DGGS_ISEA, &cell) == DGGS_OK);
    CHECK(dggs_cell_to_vertex_fan(cell, corner, fan, corners, &n) == DGGS_OK);
    return n;
}

static void test_special_corners(void) {
    /* the icosahedron vertex at 58.397N 11.25E (authalic 58.2825): 5 faces at level 0, 10 cells from level 1; a cell there has one
     * corner on it, and its others at a right angle (4) and 60 degrees (6): vertex.test_fan_sizes_around_special_points */
    for (int level = 0; level <= 28; level += 1) {
        int sizes[3];
        for (int c = 0; c < 3; c++) sizes[c] = fan_size(58.39714590743121, 11.25, level, c);
        int tens = 0;
        for (int c = 0; c < 3; c++) tens += sizes[c] == (level == 0 ? 5 : 10);
        CHECK(tens >= 1);
    }
    /* docs: vertex_to_cells("C401:1") == ['C401', 'C402', 'C411', 'C412'] */
    uint64_t fan[DGGS_MAX_FAN];
    int corners[DGGS_MAX_FAN], n = 0;
    CHECK(dggs_cell_to_vertex_fan(sid("C401"), 1, fan, corners, &n) == DGGS_OK && n == 4);
    dggs_sort_small(fan, n);
    CHECK_EQ_U64(fan[0], sid("C401"));
    CHECK_EQ_U64(fan[1], sid("C402"));
    CHECK_EQ_U64(fan[2], sid("C411"));
    CHECK_EQ_U64(fan[3], sid("C412"));
}

/* The oracle: breadth-first over whole fans, a linear scan of every cell seen. */
static int64_t naive_disk(uint64_t cell, int64_t k, uint64_t *seen, int64_t cap) {
    seen[0] = cell;
    int64_t head = 0, n = 1;
    for (int64_t step = 0; step < k; step++) {
        int64_t end = n;
        for (; head < end; head++) {
            for (int c = 0; c < 3; c++) {
                uint64_t fan[DGGS_MAX_FAN];
                int corners[DGGS_MAX_FAN];
                int m = dggs_fan(seen[head], c, fan, corners);
                CHECK(m > 0);
                for (int i = 0; i < m; i++) {
                    int found = 0;
                    for (int64_t j = 0; j < n && !found; j++) found = seen[j] == fan[i];
                    if (!found && n < cap) seen[n++] = fan[i];
                }
            }
        }
    }
    dggs_sort_small(seen, n);
    return n;
}

static void check_disk(uint64_t cell, int64_t k) {
    static uint64_t want[8192];
    int64_t size = 0, count = -1;
    CHECK(dggs_grid_disk_vertex_size(cell, k, &size) == DGGS_OK);
    uint64_t *out = calloc((size_t)size, sizeof *out);
    CHECK(dggs_grid_disk_vertex(cell, k, out, size, &count) == DGGS_OK);
    int64_t n = naive_disk(cell, k, want, 8192);
    CHECK(count == n && n < 8192);
    for (int64_t i = 0; i < n && i < count; i++) CHECK_EQ_U64(out[i], want[i]);
    for (int64_t i = count; i < size; i++) CHECK(out[i] == 0);
    free(out);
}

static void test_disks_equal_breadth_first_over_fans(void) {
    check_disk(sid("C40120"), 0);
    check_disk(sid("C40120"), 1);
    check_disk(sid("C40120"), 2);
    check_disk(sid("C"), 3); /* the whole level 0 */
    check_disk(sid("C4"), 6); /* the whole level 1 */
    uint64_t vertex_cell = 0, pole = 0;
    for (int level = 3; level <= 28; level += 5) {
        CHECK(dggs_latlng_to_cell(58.39714590743121, 11.25, level, DGGS_ISEA, &vertex_cell) == DGGS_OK);
        CHECK(dggs_latlng_to_cell(90.0, 0.0, level, DGGS_ISEA, &pole) == DGGS_OK);
        check_disk(vertex_cell, 5);
        check_disk(pole, 4);
    }
    for (int t = 0; t < 40; t++) check_disk(rnd_cell((int)(rnd() % 29)), (int64_t)(rnd() % 6));
    /* sizes: 17 cells in a radius-1 disk away from icosahedron vertices, 52 at radius 2 (vertex.py's docstring) */
    int64_t size = 0, count = 0;
    CHECK(dggs_grid_disk_vertex_size(sid("C40120"), 2, &size) == DGGS_OK);
    uint64_t *out = calloc((size_t)size, sizeof *out);
    CHECK(dggs_grid_disk_vertex(sid("C40120"), 2, out, size, &count) == DGGS_OK && count == 52);
    CHECK(dggs_grid_disk_vertex(sid("C40120"), 1, out, size, &count) == DGGS_OK && count == 17);
    free(out);
}

static void test_errors(void) {
    uint64_t fan[DGGS_MAX_FAN], out[256];
    int corners[DGGS_MAX_FAN], n = -7;
    int64_t size = -7, count = -7;
    CHECK(dggs_cell_to_vertex_fan(0, 0, fan, corners, &n) == DGGS_E_CELL && n == -7);
    CHECK(dggs_cell_to_vertex_fan(sid("C401"), 3, fan, corners, &n) == DGGS_E_DOMAIN);
    CHECK(dggs_cell_to_vertex_fan(sid("C401"), -1, fan, corners, &n) == DGGS_E_DOMAIN);
    CHECK(dggs_grid_disk_vertex_size(12345, 1, &size) == DGGS_E_CELL);
    CHECK(dggs_grid_disk_vertex_size(sid("C401"), -1, &size) == DGGS_E_DOMAIN);
    CHECK(dggs_grid_disk_vertex_size(sid("C401"), ((int64_t)1 << 31) + 1, &size) == DGGS_E_DOMAIN);
    CHECK(dggs_grid_disk_vertex_size(sid("C401"), (int64_t)1 << 31, &size) == DGGS_OK && size > 0);
    CHECK(dggs_grid_disk_vertex_size(sid("C401"), 1, &size) == DGGS_OK);
    CHECK(dggs_grid_disk_vertex(sid("C401"), 1, out, size - 1, &count) == DGGS_E_BUFFER && count == -7);
    /* the bound never under the level: a radius past the far side gives the whole level */
    CHECK(dggs_grid_disk_vertex_size(sid("C"), 1000, &size) == DGGS_OK && size <= 256);
    CHECK(dggs_grid_disk_vertex(sid("C"), 1000, out, size, &count) == DGGS_OK && count == 20);
    CHECK(dggs_disk_vertex_width(((int64_t)1 << 31), 28) == dggs_level_cells(28));
}

int main(void) {
    test_fans_are_shared_corners();
    test_special_corners();
    test_disks_equal_breadth_first_over_fans();
    test_errors();
    return check_failures ? 1 : 0;
}
