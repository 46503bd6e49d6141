/* polygon.c, the edge bucket grid of polygon fill: frozen outputs of the numba kernel (frozen_polygon.h, from
 * tools/freeze_polygon.py) and independent checks: the rings split at the first point's repeat, every empty
 * bucket is its own stop, parity agrees with a brute-force crossing count wherever that one is far from
 * rounding, near agrees with a brute-force distance, and the inputs refused. */
#include <math.h>

#include "check.h"
#include "dggs.h"
#include "frozen_polygon.h"
#include "polygon.h"

#define MAX_SIDE 13

static int64_t start_buf[MAX_SIDE * MAX_SIDE + 1], empty_buf[MAX_SIDE * MAX_SIDE], items_buf[4096];
static double scratch_buf[4096], frame_buf[DGGS_FRAME_SIZE];

/* The grid of the frozen edges at `side`, in the static buffers. */
static dggs_edge_grid build(int64_t side) {
    dggs_edge_grid g = {frozen_x0, frozen_y0, frozen_x1, frozen_y1, frame_buf, start_buf, items_buf, empty_buf};
    CHECK(dggs_polygon_build_count(frozen_x0, frozen_y0, frozen_x1, frozen_y1, FROZEN_N_EDGES, side, frame_buf,
                                   start_buf) == DGGS_OK);
    CHECK(start_buf[side * side] <= 4096);
    dggs_polygon_build_fill(frozen_x0, frozen_y0, frozen_x1, frozen_y1, FROZEN_N_EDGES, frame_buf, start_buf,
                            items_buf, empty_buf, scratch_buf);
    return g;
}

static void check_frozen(int64_t side, const double *frame, const int64_t *start, const int64_t *items,
                         const int64_t *empty, const int8_t *parity, const uint8_t *near) {
    dggs_edge_grid g = build(side);
    for (int k = 0; k < DGGS_FRAME_SIZE; k++) CHECK_SAME_DOUBLE(frame_buf[k], frame[k]);
    for (int64_t b = 0; b <= side * side; b++) CHECK(start_buf[b] == start[b]);
    for (int64_t k = 0; k < start[side * side]; k++) CHECK(items_buf[k] == items[k]);
    for (int64_t b = 0; b < side * side; b++) CHECK(empty_buf[b] == empty[b]);
    int j = 0;
    for (int i = 0; i < FROZEN_N_QUERIES; i++) {
        CHECK(dggs_parity(frozen_qx[i], frozen_qy[i], &g) == parity[i]);
        for (int r = 0; r < 5; r++)
            for (int s = 0; s < 3; s++, j++)
                CHECK(dggs_near(frozen_qx[i], frozen_qy[i], frozen_radii[r], frozen_scales[s], &g) == (near[j] != 0));
    }
}

/* Brute force: the crossing number of the ray to +x (half-open rule) and the smallest orientation margin. */
static int brute_parity(double px, double py, double *margin) {
    int odd = 0;
    *margin = INFINITY;
    for (int i = 0; i < FROZEN_N_EDGES; i++) {
        double ax = frozen_x0[i], ay = frozen_y0[i], bx = frozen_x1[i], by = frozen_y1[i];
        if ((ay > py) != (by > py)) {
            double x = ax + (py - ay) * (bx - ax) / (by - ay);
            if (fabs(x - px) < *margin) *margin = fabs(x - px);
            if (x > px) odd ^= 1;
        }
        if (ay == py && by == py && fmin(ax, bx) <= px && px <= fmax(ax, bx)) *margin = 0.0;
    }
    return odd;
}

static double segment_distance(double px, double py, int i) {
    double ax = frozen_x0[i], ay = frozen_y0[i], bx = frozen_x1[i], by = frozen_y1[i];
    double ex = bx - ax, ey = by - ay, ee = ex * ex + ey * ey;
    double t = ee == 0.0 ? 0.0 : ((px - ax) * ex + (py - ay) * ey) / ee;
    t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
    return hypot(px - ax - t * ex, py - ay - t * ey);
}

int main(void) {
    /* ring_edges: the frozen edges, all rings closed; without the last point the last ring never closes */
    static double x0[FROZEN_N_POINTS], y0[FROZEN_N_POINTS], x1[FROZEN_N_POINTS], y1[FROZEN_N_POINTS];
    int64_t m = -1;
    bool closed = false;
    dggs_ring_edges(frozen_xy, FROZEN_N_POINTS, x0, y0, x1, y1, &m, &closed);
    CHECK(closed && m == FROZEN_N_EDGES);
    for (int i = 0; i < FROZEN_N_EDGES; i++) {
        CHECK_SAME_DOUBLE(x0[i], frozen_x0[i]);
        CHECK_SAME_DOUBLE(y0[i], frozen_y0[i]);
        CHECK_SAME_DOUBLE(x1[i], frozen_x1[i]);
        CHECK_SAME_DOUBLE(y1[i], frozen_y1[i]);
    }
    dggs_ring_edges(frozen_xy, FROZEN_N_POINTS - 1, x0, y0, x1, y1, &m, &closed);
    CHECK(!closed && m == FROZEN_N_EDGES - 4); /* the last ring (the polar box, 4 edges) is left open */
    dggs_ring_edges(frozen_xy, 0, x0, y0, x1, y1, &m, &closed);
    CHECK(closed && m == 0);

    check_frozen(5, frozen_frame_5, frozen_start_5, frozen_items_5, frozen_empty_5, frozen_parity_5, frozen_near_5);
    check_frozen(13, frozen_frame_13, frozen_start_13, frozen_items_13, frozen_empty_13, frozen_parity_13,
                 frozen_near_13);

    for (int64_t side = 1; side <= MAX_SIDE; side++) {
        dggs_edge_grid g = build(side);
        /* the frame is the edges' bounding box */
        CHECK(frame_buf[0] == -180.0 && frame_buf[5] == 180.0 && frame_buf[1] == -20.0 && frame_buf[6] == 90.0);
        /* every empty bucket is its own stop, and a bucket's stop is never left of it */
        for (int64_t b = 0; b < side * side; b++) {
            int64_t stop = empty_buf[b] % (side + 1), col = b % side;
            if (start_buf[b] == start_buf[b + 1]) CHECK(stop == col);
            CHECK(stop >= col);
        }
        /* parity against brute force, off the edges; near against brute-force distances */
        uint64_t state = 0x9E3779B97F4A7C15u;
        for (int i = 0; i < 4000; i++) {
            state = state * 6364136223846793005u + 1442695040888963407u;
            double px = -185.0 + 370.0 * (double)(state >> 11) * 0x1p-53;
            state = state * 6364136223846793005u + 1442695040888963407u;
            double py = -25.0 + 120.0 * (double)(state >> 11) * 0x1p-53;
            if (i % 3 == 0) px = 25.0 * (px + 185.0) / 370.0 - 3.0; /* crowd the lattice polygon */
            if (i % 3 == 1) py = 15.0 * (py + 25.0) / 120.0 - 2.0;
            double margin;
            int want = brute_parity(px, py, &margin);
            int got = dggs_parity(px, py, &g);
            if (margin > 1e-9) CHECK(got == want);
            CHECK(got != -1 || margin < 1e-9);
            double r = (double)(i % 7) * 0.3, best = INFINITY;
            for (int e = 0; e < FROZEN_N_EDGES; e++) best = fmin(best, segment_distance(px, py, e));
            if (fabs(best - r) > 1e-9) CHECK(dggs_near(px, py, r, 1.0, &g) == (best <= r));
            bool hit, inside;
            dggs_polygon_classify(px, py, r, &g, &hit, &inside);
            if (fabs(best - r) > 1e-9 && margin > 1e-9) {
                CHECK(hit == (best <= r || want == 1));
                CHECK(inside == (best > r && want == 1));
            }
        }
    }
    /* refused: no edges, a side of 0 */
    CHECK(dggs_polygon_build_count(frozen_x0, frozen_y0, frozen_x1, frozen_y1, 0, 4, frame_buf, start_buf) ==
          DGGS_E_DOMAIN);
    CHECK(dggs_polygon_build_count(frozen_x0, frozen_y0, frozen_x1, frozen_y1, FROZEN_N_EDGES, 0, frame_buf,
                                   start_buf) == DGGS_E_DOMAIN);
    CHECK_DONE();
}
