/* Points per edge (edge_bound.c): the public API's errors, and invariants of the counts. Their guarantee (the
 * distance and geodesic area the counts promise) is checked against pyproj.Geod in tests/index/test_edge_bound.py. */
#include <math.h>
#include <string.h>

#include "bits.h"
#include "check.h"
#include "dggs.h"

/* A cell at `level` below face `face`: digit 0 all the way (a corner of the face, by an icosahedron vertex),
 * or digit 1 (inside). */
static uint64_t cell_at(int face, int level, int digit) {
    uint64_t cell = dggs_base_cell(face);
    if (level >= 1) cell |= (uint64_t)(digit + 1) << DGGS_L1_SHIFT;
    for (int k = 2; k <= level; k++) cell |= (uint64_t)(digit + 1) << dggs_shift_of(k);
    return cell;
}

static void test_errors(void) {
    int points = -1;
    double b[3], l[3];
    uint64_t cell = cell_at(3, 5, 1);
    CHECK(dggs_cell_edge_points(0, DGGS_ISEA, 10.0, 0.0, &points) == DGGS_E_CELL);
    CHECK(dggs_cell_edge_points(cell, (dggs_projection)2, 10.0, 0.0, &points) == DGGS_E_PROJECTION);
    CHECK(dggs_cell_edge_points(cell, DGGS_ISEA, 0.0, 0.0, &points) == DGGS_E_DOMAIN);
    CHECK(dggs_cell_edge_points(cell, DGGS_ISEA, -1.0, 0.0, &points) == DGGS_E_DOMAIN);
    CHECK(dggs_cell_edge_points(cell, DGGS_ISEA, NAN, 0.0, &points) == DGGS_E_DOMAIN);
    CHECK(dggs_cell_edge_points(cell, DGGS_ISEA, INFINITY, 0.0, &points) == DGGS_E_DOMAIN);
    CHECK(points == -1); /* untouched on error */
    CHECK(dggs_cell_edge_bounds(0, DGGS_ISEA, b, l) == DGGS_E_CELL);
    CHECK(dggs_cell_edge_bounds(cell, (dggs_projection)7, b, l) == DGGS_E_PROJECTION);
}

static void test_counts(void) {
    for (int proj = 0; proj < 2; proj++) {
        for (int level = 0; level <= DGGS_MAX_LEVEL; level++) {
            for (int digit = 0; digit < 2; digit++) {
                uint64_t cell = cell_at(level % 20, level, digit);
                double b[3], l[3];
                CHECK(dggs_cell_edge_bounds(cell, (dggs_projection)proj, b, l) == DGGS_OK);
                for (int i = 0; i < 3; i++) CHECK(b[i] >= 0.0 && l[i] > 0.0 && b[i] < l[i]);
                int last = -1;
                for (double tol = 1e4; tol >= 1e-3; tol /= 10.0) { /* a finer tolerance never asks for fewer */
                    int points = -1;
                    CHECK(dggs_cell_edge_points(cell, (dggs_projection)proj, tol, 0.0, &points) == DGGS_OK);
                    CHECK(points >= last && points <= DGGS_EDGE_POINTS_MAX);
                    last = points;
                }
                int exact = -1, both = -1;
                CHECK(dggs_cell_edge_points(cell, (dggs_projection)proj, 0.0, 1e-6, &exact) == DGGS_OK);
                CHECK(dggs_cell_edge_points(cell, (dggs_projection)proj, 1e4, 1e-6, &both) == DGGS_OK);
                CHECK(exact >= 0 && both >= exact); /* both asked: at least each's count */
            }
        }
    }
    int coarse = -1, fine = -1; /* a level-0 face needs the cap for 1e-6 of its area; a level-14 cell a few */
    CHECK(dggs_cell_edge_points(cell_at(0, 0, 0), DGGS_ISEA, 0.0, 1e-6, &coarse) == DGGS_OK);
    CHECK(dggs_cell_edge_points(cell_at(0, 14, 1), DGGS_ISEA, 0.0, 1e-6, &fine) == DGGS_OK);
    CHECK(coarse == DGGS_EDGE_POINTS_MAX - 1 && fine < coarse && ((fine + 1) & fine) == 0); /* 2^k - 1 */
}

/* dggs_cell_edge_ring: the count of dggs_cell_edge_points and the ring of dggs_cell_to_boundary at that count, bit
 * for bit (the two calls are the oracle), whichever path drew it (the count's points, or a boundary drawn anew). */
static void test_ring(void) {
    static double ring[2 * (3 * (DGGS_EDGE_POINTS_MAX + 1) + 1)], boundary[2 * 3 * (DGGS_EDGE_POINTS_MAX + 1)];
    const double tolerances[][2] = {{1e4, 0.0}, {100.0, 0.0}, {10.0, 0.0}, {1.0, 0.0}, {0.0, 1e-6}, {10.0, 1e-6}};
    int seen[DGGS_EDGE_POINTS_MAX + 1] = {0};
    for (int proj = 0; proj < 2; proj++) {
        for (int level = 0; level <= DGGS_MAX_LEVEL; level++) {
            for (int face = 0; face < 20; face += 3) {
                for (int digit = 0; digit < 3; digit++) {
                    uint64_t cell = cell_at(face, level, digit);
                    for (size_t t = 0; t < sizeof tolerances / sizeof tolerances[0]; t++) {
                        int points = -1, want = -2;
                        CHECK(dggs_cell_edge_points(cell, (dggs_projection)proj, tolerances[t][0], tolerances[t][1],
                                                    &want) == DGGS_OK);
                        CHECK(dggs_cell_edge_ring(cell, (dggs_projection)proj, tolerances[t][0], tolerances[t][1], ring,
                                                  sizeof ring / sizeof ring[0] / 2, &points) == DGGS_OK);
                        CHECK(points == want);
                        size_t count = 0;
                        CHECK(dggs_cell_to_boundary(cell, points, (dggs_projection)proj, boundary,
                                                    sizeof boundary / sizeof boundary[0] / 2, &count) == DGGS_OK);
                        CHECK(count == (size_t)(3 * (points + 1)));
                        int same = 1;
                        for (size_t k = 0; k <= count; k++) { /* (lng, lat) against (lat, lng); the last closes it */
                            size_t j = k % count;
                            same &= memcmp(&ring[2 * k], &boundary[2 * j + 1], sizeof(double)) == 0;
                            same &= memcmp(&ring[2 * k + 1], &boundary[2 * j], sizeof(double)) == 0;
                        }
                        CHECK(same);
                        seen[points] = 1;
                    }
                }
            }
        }
    }
    CHECK(seen[0] && seen[1] && seen[3] && seen[2]); /* both paths taken: from the count's points, and drawn anew */
    /* too small a buffer: the count, and nothing written */
    uint64_t cell = cell_at(4, 10, 1);
    int points = -1;
    ring[0] = 123.0;
    CHECK(dggs_cell_edge_ring(cell, DGGS_ISEA, 10.0, 0.0, ring, 3, &points) == DGGS_E_BUFFER);
    CHECK(points >= 0 && ring[0] == 123.0);
    CHECK(dggs_cell_edge_ring(cell, DGGS_ISEA, 10.0, 0.0, ring, (size_t)(3 * (points + 1) + 1), &points) == DGGS_OK);
    points = -1;
    CHECK(dggs_cell_edge_ring(0, DGGS_ISEA, 10.0, 0.0, ring, 13, &points) == DGGS_E_CELL);
    CHECK(dggs_cell_edge_ring(cell, (dggs_projection)2, 10.0, 0.0, ring, 13, &points) == DGGS_E_PROJECTION);
    CHECK(dggs_cell_edge_ring(cell, DGGS_ISEA, 0.0, 0.0, ring, 13, &points) == DGGS_E_DOMAIN);
    CHECK(points == -1);
}

int main(void) {
    test_errors();
    test_counts();
    test_ring();
    return check_failures ? 1 : 0;
}
