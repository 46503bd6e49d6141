/* fill.c, polygon fill's descent: frozen outputs of the numba kernels (frozen_fill.h, from tools/freeze_fill.py)
 * and independent checks: corners carried down from the id are points.triangle's, the footprint bound holds at
 * sampled points of cells at every level, the output is sorted and disjoint whatever the room given, a polygon
 * holding the whole globe gives the 20 base cells, and first_over's sums. */
#include <math.h>

#include "bits.h"
#include "check.h"
#include "dggs.h"
#include "fill.h"
#include "frozen_fill.h"
#include "geometry.h"
#include "hierarchy.h"
#include "polygon.h"
#include "tables.h"

/* The corners (A, B, C) of a cell as the fill carries them down: the face's, the level-1 triangle's, then one
 * dggs_child_corners a level. */
static void carried(uint64_t cell, double t[6]) {
    int level = dggs_level_of(cell);
    if (level == 0) {
        for (int k = 0; k < 6; k++) t[k] = dggs_face_corners_ccw[k / 2][k % 2];
        return;
    }
    int d = dggs_digit_of(cell, 1);
    for (int k = 0; k < 6; k++) t[k] = dggs_level1_corners[d][k / 2][k % 2];
    for (int lv = 2; lv <= level; lv++) dggs_child_corners(t, dggs_digit_of(cell, lv));
}

/* The edge grid of rings laid end to end, as polyfill._edge_index builds it (buffers malloc'ed, kept in g). */
typedef struct {
    dggs_edge_grid g;
    double *x0, *y0, *x1, *y1, *frame, *scratch;
    int64_t *start, *items, *empty;
} grid_buffers;

static void grid_of(const double *xy, int64_t n, int64_t side, grid_buffers *b) {
    int64_t m;
    bool closed;
    b->x0 = malloc((size_t)n * sizeof(double));
    b->y0 = malloc((size_t)n * sizeof(double));
    b->x1 = malloc((size_t)n * sizeof(double));
    b->y1 = malloc((size_t)n * sizeof(double));
    b->frame = malloc(DGGS_FRAME_SIZE * sizeof(double));
    b->start = malloc((size_t)(side * side + 1) * sizeof(int64_t));
    b->empty = malloc((size_t)(side * side) * sizeof(int64_t));
    dggs_ring_edges(xy, n, b->x0, b->y0, b->x1, b->y1, &m, &closed);
    CHECK(closed);
    CHECK(dggs_polygon_build_count(b->x0, b->y0, b->x1, b->y1, m, side, b->frame, b->start) == DGGS_OK);
    int64_t k = b->start[side * side];
    b->items = malloc((size_t)(k + 1) * sizeof(int64_t));
    b->scratch = malloc((size_t)(k + 1) * sizeof(double));
    dggs_polygon_build_fill(b->x0, b->y0, b->x1, b->y1, m, b->frame, b->start, b->items, b->empty, b->scratch);
    dggs_edge_grid g = {b->x0, b->y0, b->x1, b->y1, b->frame, b->start, b->items, b->empty};
    b->g = g;
}

static void grid_free(grid_buffers *b) {
    free(b->x0), free(b->y0), free(b->x1), free(b->y1), free(b->frame), free(b->scratch);
    free(b->start), free(b->items), free(b->empty);
}

static uint64_t fnv1a(const uint64_t *ids, const uint8_t *flags, int64_t n) {
    uint64_t h = 0xCBF29CE484222325u;
    for (int64_t i = 0; i < n; i++) {
        for (int k = 0; k < 8; k++) h = (h ^ ((ids[i] >> (8 * k)) & 0xFF)) * 0x100000001B3u;
        h = (h ^ flags[i]) * 0x100000001B3u;
    }
    return h;
}

/* A whole descent with output room growing from `room` (doubling, as the binding does). */
static int descend(dggs_projection proj, const dggs_edge_grid *g, int level, bool center, int direct, double miny,
                   double maxy, int64_t limit, int64_t room, dggs_fill_state *s, uint64_t **ids, uint8_t **flags) {
    *ids = malloc((size_t)room * sizeof(uint64_t));
    *flags = malloc((size_t)room);
    dggs_fill_start(s, level, center, direct, miny, maxy, limit);
    for (;;) {
        int status = dggs_fill_walk(proj, s, g, *ids, *flags, room);
        if (status != DGGS_FILL_FULL) return status;
        room *= 2;
        *ids = realloc(*ids, (size_t)room * sizeof(uint64_t));
        *flags = realloc(*flags, (size_t)room);
    }
}

static void check_frozen_cells(void) {
    for (int i = 0; i < FROZEN_N_CELLS; i++) {
        const frozen_cell *c = &frozen_cells[i];
        double t[6];
        carried(c->id, t);
        CHECK(dggs_face_of(c->id) == c->face && dggs_level_of(c->id) == c->level);
        for (int k = 0; k < 6; k++) CHECK_NEAR_DOUBLE(t[k], c->corners[k]);
        for (int p = 0; p < 2; p++) {
            const double *o = c->out[p];
            double lat, lng, u[3], a, lam;
            dggs_fill_centre((dggs_projection)p, c->face, c->level, t[0], t[1], t[2], t[3], t[4], t[5], &lat, &lng, u);
            CHECK_NEAR_DOUBLE(lat, o[0]);
            CHECK_NEAR_DOUBLE(lng, o[1]);
            for (int k = 0; k < 3; k++) CHECK_NEAR_DOUBLE(u[k], o[2 + k]);
            dggs_footprint((dggs_projection)p, c->face, c->level, t[0], t[1], t[2], t[3], t[4], t[5], &lat, &lng, u);
            CHECK_NEAR_DOUBLE(lat, o[5]);
            CHECK_NEAR_DOUBLE(lng, o[6]);
            for (int k = 0; k < 3; k++) CHECK_NEAR_DOUBLE(u[k], o[7 + k]);
            dggs_ellipse(c->level, u[0], u[1], u[2], &a, &lam);
            CHECK_NEAR_DOUBLE(a, o[10]);
            CHECK_NEAR_DOUBLE(lam, o[11]);
        }
    }
}

static void check_frozen_descents(void) {
    for (int i = 0; i < FROZEN_N_DESCENTS; i++) {
        const frozen_descent *f = &frozen_descents[i];
        grid_buffers b;
        grid_of(frozen_xy + 2 * f->xy_start, f->xy_end - f->xy_start, f->side, &b);
        for (int64_t room = 1; room <= 4096; room *= 64) { /* the output is the same whatever room it starts with */
            dggs_fill_state s;
            uint64_t *ids;
            uint8_t *flags;
            int status = descend((dggs_projection)f->proj, &b.g, f->level, f->center != 0, f->direct, f->miny,
                                 f->maxy, f->limit, room, &s, &ids, &flags);
            CHECK(status == f->status);
            CHECK(s.n == f->n && s.tested == f->tested && s.classified == f->classified);
            CHECK_EQ_U64(fnv1a(ids, flags, s.n), f->hash);
            if (s.n) {
                CHECK_EQ_U64(ids[0], f->first);
                CHECK_EQ_U64(ids[s.n - 1], f->last);
            }
            for (int lv = 0; lv < DGGS_FILL_LEVELS; lv++) CHECK(s.cand[lv] == f->cand[lv] && s.insides[lv] == f->insides[lv]);
            /* sorted, disjoint, no finer than the level, flags as the mode allows */
            for (int64_t k = 0; k < s.n; k++) {
                CHECK(dggs_is_valid(ids[k]) && dggs_level_of(ids[k]) <= f->level);
                if (k) CHECK(ids[k] >= dggs_range_end(ids[k - 1], dggs_level_of(ids[k - 1])));
                CHECK(flags[k] == DGGS_FILL_SURE || flags[k] == (f->center ? DGGS_FILL_CENTRE : DGGS_FILL_EDGE));
                if (flags[k] != DGGS_FILL_SURE) CHECK(dggs_level_of(ids[k]) == f->level);
            }
            free(ids);
            free(flags);
        }
        grid_free(&b);
    }
}

/* The footprint bound: sampled points of cells at every level lie within RHO of the footprint centre (the arc on
 * the authalic sphere) and inside the footprint ellipse. */
static void check_footprint_bound(void) {
    uint64_t state = 12345;
    double worst = 0.0;
    for (int i = 0; i < FROZEN_N_CELLS; i++) {
        const frozen_cell *c = &frozen_cells[i];
        const double *t = c->corners;
        for (int p = 0; p < 2; p++) {
            double lat0, lng0, u[3], a, lam;
            dggs_footprint((dggs_projection)p, c->face, c->level, t[0], t[1], t[2], t[3], t[4], t[5], &lat0, &lng0, u);
            double nu = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
            dggs_ellipse(c->level, u[0], u[1], u[2], &a, &lam);
            for (int k = 0; k < 60; k++) {
                double w[3];
                for (int j = 0; j < 3; j++) {
                    state = state * 6364136223846793005u + 1442695040888963407u;
                    w[j] = (double)(state >> 11) * 0x1p-53;
                }
                if (k < 3) w[0] = w[1] = w[2] = 0.0, w[k] = 1.0; /* the corners themselves */
                double sum = w[0] + w[1] + w[2];
                double x = (w[0] * t[0] + w[1] * t[2] + w[2] * t[4]) / sum, y = (w[0] * t[1] + w[1] * t[3] + w[2] * t[5]) / sum;
                double q[3], lat, lng;
                dggs_proj_inverse((dggs_projection)p, c->face, x, y, q);
                dggs_unit_to_geodetic(q[0], q[1], q[2], &lat, &lng);
                double nq = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
                double cosang = (q[0] * u[0] + q[1] * u[1] + q[2] * u[2]) / (nq * nu);
                double arc = acos(cosang > 1.0 ? 1.0 : cosang);
                if (arc / dggs_fill_rho[c->level] > worst) worst = arc / dggs_fill_rho[c->level];
                if (c->level < 20) CHECK(arc <= dggs_fill_rho[c->level]); /* finer: acos's rounding rules */
                if (lam > 0.0) {
                    double dlng = fmod(lng - lng0 + 540.0, 360.0) - 180.0;
                    CHECK((lat - lat0) * (lat - lat0) / (a * a) + dlng * dlng / (lam * lam) <= 1.0 + 1e-9);
                } else {
                    CHECK(fabs(lat - lat0) <= a);
                }
            }
        }
    }
    CHECK(worst > 0.5 && worst <= 1.0);
}

/* The public verb: polygon_to_cells' docstring example (box(-10, -10, 10, 10) at level 6: 276 cells by centre,
 * 232 contained, 338 overlapping), sorted output within the size bound, nesting of the modes, the errors. */
static void check_public(void) {
    static const double box[] = {-10, -10, -10, 10, 10, 10, 10, -10, -10, -10}; /* (lat, lng), closed */
    static const int64_t sizes[] = {5};
    static dggs_cell out[4][512];
    static const int64_t want[4] = {276, 232, 338, 338};
    int64_t count[4];
    for (int mode = 0; mode < 4; mode++) {
        int64_t size = -1;
        CHECK(dggs_polygon_to_cells_size(box, sizes, 1, 6, (dggs_fill_mode)mode, DGGS_ISEA, &size) == DGGS_OK);
        CHECK(size >= want[mode] && size <= 512);
        CHECK(dggs_polygon_to_cells(box, sizes, 1, 6, (dggs_fill_mode)mode, DGGS_ISEA, out[mode], size,
                                    &count[mode]) == DGGS_OK);
        CHECK(count[mode] == want[mode]);
        for (int64_t i = 0; i < count[mode]; i++) {
            CHECK(dggs_level_of(out[mode][i]) == 6);
            if (i) CHECK(out[mode][i] > out[mode][i - 1]);
        }
        int64_t need = 0;
        CHECK(dggs_polygon_to_cells(box, sizes, 1, 6, (dggs_fill_mode)mode, DGGS_ISEA, out[mode], 10, &need) ==
              DGGS_E_BUFFER);
        CHECK(need == want[mode]);
    }
    /* contains within center within overlaps (sorted sets) */
    for (int64_t i = 0, j = 0; i < count[1]; i++) {
        while (j < count[0] && out[0][j] < out[1][i]) j++;
        CHECK(j < count[0] && out[0][j] == out[1][i]);
    }
    for (int64_t i = 0, j = 0; i < count[0]; i++) {
        while (j < count[2] && out[2][j] < out[0][i]) j++;
        CHECK(j < count[2] && out[2][j] == out[0][i]);
    }
    /* the same ring unclosed, and with its orientation reversed: the same cells */
    static const double open_box[] = {-10, 10, 10, 10, 10, -10, -10, -10};
    static const int64_t open_sizes[] = {4};
    int64_t n = 0;
    static dggs_cell again[400];
    CHECK(dggs_polygon_to_cells(open_box, open_sizes, 1, 6, DGGS_FILL_MODE_CENTER, DGGS_ISEA, again, 400, &n) ==
          DGGS_OK);
    CHECK(n == count[0] && memcmp(again, out[0], (size_t)n * sizeof(dggs_cell)) == 0);
    /* no rings: no cells */
    CHECK(dggs_polygon_to_cells(box, sizes, 0, 6, DGGS_FILL_MODE_CENTER, DGGS_IVEA, again, 0, &n) == DGGS_OK && n == 0);
    /* errors */
    static const double far[] = {0, 0, 0, 190, 10, 190};
    static const double nan_ring[] = {0, 0, NAN, 1, 1, 1};
    static const int64_t three[] = {3}, two[] = {2};
    int64_t size;
    CHECK(dggs_polygon_to_cells_size(box, sizes, 1, 29, DGGS_FILL_MODE_CENTER, DGGS_ISEA, &size) == DGGS_E_LEVEL);
    CHECK(dggs_polygon_to_cells_size(box, sizes, 1, -1, DGGS_FILL_MODE_CENTER, DGGS_ISEA, &size) == DGGS_E_LEVEL);
    CHECK(dggs_polygon_to_cells_size(box, sizes, 1, 6, (dggs_fill_mode)4, DGGS_ISEA, &size) == DGGS_E_DOMAIN);
    CHECK(dggs_polygon_to_cells_size(box, sizes, 1, 6, DGGS_FILL_MODE_CENTER, (dggs_projection)2, &size) ==
          DGGS_E_PROJECTION);
    CHECK(dggs_polygon_to_cells_size(box, sizes, -1, 6, DGGS_FILL_MODE_CENTER, DGGS_ISEA, &size) == DGGS_E_DOMAIN);
    CHECK(dggs_polygon_to_cells_size(box, two, 1, 6, DGGS_FILL_MODE_CENTER, DGGS_ISEA, &size) == DGGS_E_DOMAIN);
    CHECK(dggs_polygon_to_cells_size(far, three, 1, 6, DGGS_FILL_MODE_CENTER, DGGS_ISEA, &size) == DGGS_E_LATLNG);
    CHECK(dggs_polygon_to_cells_size(nan_ring, three, 1, 6, DGGS_FILL_MODE_CENTER, DGGS_ISEA, &size) ==
          DGGS_E_LATLNG);
}

/* The exact predicates: collinear points off the double grid's exact lines, a point 1 ulp off a line. */
static void check_exact(void) {
    CHECK(dggs_orient_exact(0.0, 0.0, 3.0, 1.0, 6.0, 2.0) == 0);
    CHECK(dggs_orient_exact(0.0, 0.0, 1.0, 1.0, 0.5, 0.5) == 0);
    CHECK(dggs_orient_exact(0.0, 0.0, 1.0, 1.0, 0.5, nextafter(0.5, 1.0)) == 1);
    CHECK(dggs_orient_exact(0.0, 0.0, 1.0, 1.0, nextafter(0.5, 1.0), 0.5) == -1);
    /* 0.1 + k 0.2 on y = x: rounding makes them miss the line; exactly so, against the sign of y - x */
    for (int k = 0; k < 50; k++) {
        double x = 0.1 + 0.2 * k, y = 0.3 * (k + 1) - 0.2 * (k + 1) + 0.1 * k;
        int want = (y > x) - (y < x);
        CHECK(dggs_orient_exact(-1.0, -1.0, 7.0, 7.0, x, y) == want);
    }
    /* Shewchuk's near-degenerate case: points near (0.5, 0.5) on the line through (12, 12) and (24, 24) */
    for (int i = 0; i < 64; i++) {
        double px = 0.5 + i * 0x1p-53, py = 0.5;
        int want = px > py ? -1 : (px < py ? 1 : 0);
        CHECK(dggs_orient_exact(12.0, 12.0, 24.0, 24.0, px, py) == want);
    }
    CHECK(dggs_segments_meet(0, 0, 2, 2, 0, 2, 2, 0) == 2);
    CHECK(dggs_segments_meet(0, 0, 2, 2, 1, 1, 3, 0) == 1);
    CHECK(dggs_segments_meet(0, 0, 2, 2, 2, 2, 3, 3) == 1);
    CHECK(dggs_segments_meet(0, 0, 2, 2, 3, 3, 4, 4) == 0);
    CHECK(dggs_segments_meet(0, 0, 2, 0, 0, 1, 2, 1) == 0);
    static const double sq[] = {0, 0, 4, 0, 4, 4, 0, 4};
    CHECK(dggs_locate_ring(2, 2, sq, 4) == 1 && dggs_locate_ring(5, 2, sq, 4) == 0);
    CHECK(dggs_locate_ring(4, 2, sq, 4) == -1 && dggs_locate_ring(0, 0, sq, 4) == -1 && dggs_locate_ring(2, 4, sq, 4) == -1);
}

int main(void) {
    check_exact();
    check_public();
    check_frozen_cells();
    check_frozen_descents();
    check_footprint_bound();
    /* RHO: each level's about 1/sqrt(3) of the last (the children's hypotenuse) */
    for (int lv = 1; lv < DGGS_MAX_LEVEL; lv++)
        CHECK(fabs(dggs_fill_rho[lv] / dggs_fill_rho[lv + 1] - DGGS_SQRT3) < 1e-12);
    CHECK(dggs_fill_rho[0] > dggs_fill_rho[1]);
    /* a polygon over the whole lng/lat plane: the 20 base cells, whole */
    static const double globe[] = {-180, -90, 180, -90, 180, 90, -180, 90, -180, -90};
    grid_buffers b;
    grid_of(globe, 5, 4, &b);
    for (int level = 0; level <= 3; level++) {
        dggs_fill_state s;
        uint64_t *ids;
        uint8_t *flags;
        CHECK(descend(DGGS_ISEA, &b.g, level, false, 1, -90.0, 90.0, INT64_MAX, 8, &s, &ids, &flags) == DGGS_FILL_OK);
        int64_t total = 0;
        for (int64_t k = 0; k < s.n; k++) total += dggs_n_desc(dggs_level_of(ids[k]), level);
        CHECK(total == (level == 0 ? 20 : 120 * dggs_pow3(level - 1))); /* every cell: whole, or at the level */
        if (level == 0) CHECK(s.n == 20 && ids[0] == dggs_base_cell(0) && ids[19] == dggs_base_cell(19));
        free(ids);
        free(flags);
    }
    grid_free(&b);
    /* first_over: the first level-by-level count over the limit */
    int64_t cand[DGGS_FILL_LEVELS] = {20, 30, 30, 0}, insides[DGGS_FILL_LEVELS] = {0, 10, 40, 0};
    CHECK(dggs_first_over(cand, insides, 5, 3, true, 1000) == -1);
    CHECK(dggs_first_over(cand, insides, 5, 3, true, 39) == 40); /* 10 whole + 30 candidates of level 2 */
    CHECK(dggs_first_over(cand, insides, 5, 3, true, 40) == 50); /* 50 whole after level 2 */
    CHECK(dggs_first_over(cand, insides, 5, 3, true, 52) == 55); /* 50 whole + 5 tested */
    CHECK(dggs_first_over(cand, insides, 5, 3, false, 52) == -1);
    CHECK(dggs_first_over(cand, insides, 5, 0, true, 4) == 5);
    CHECK_DONE();
}
