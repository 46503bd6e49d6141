/* The line tracer (line_trace.c, chord.c, line_layout.c) and the public dggs_line_to_cells: independent checks
 * (round trips, the line's invariants, errors and the grow protocol) and outputs of the numba kernel frozen by
 * tools/freeze_lines.py (frozen_lines.h), compared bit for bit. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bits.h"
#include "check.h"
#include "chord.h"
#include "dggs.h"
#include "frozen_lines.h"
#include "grid.h"
#include "line_layout.h"
#include "line_tables.h"
#include "line_trace.h"
#include "points.h"

#define COUNT(a) (sizeof(a) / sizeof((a)[0]))

static int same_double(double a, double b) { return memcmp(&a, &b, sizeof a) == 0; }

/* ---- a geodesic solver replaying pyproj's recorded answers (frozen_lines.h) ---- */

typedef struct {
    int misses;
} replay;

static void replay_inverse(const void *geod, double lat1, double lng1, double lat2, double lng2, double *s12,
                           double *azi1, double *azi2) {
    for (size_t i = 0; i < FROZEN_GEOD_INVERSE_N; i++) {
        const double *r = FROZEN_GEOD_INVERSE[i];
        if (same_double(r[0], lat1) && same_double(r[1], lng1) && same_double(r[2], lat2) && same_double(r[3], lng2)) {
            *s12 = r[4];
            *azi1 = r[5];
            *azi2 = r[6];
            return;
        }
    }
    ((replay *)(uintptr_t)geod)->misses++;
    *s12 = *azi1 = *azi2 = 0.0;
}

static void replay_direct(const void *geod, double lat1, double lng1, double azi1, double s12, double *lat2,
                          double *lng2, double *azi2) {
    for (size_t i = 0; i < FROZEN_GEOD_DIRECT_N; i++) {
        const double *r = FROZEN_GEOD_DIRECT[i];
        if (same_double(r[0], lat1) && same_double(r[1], lng1) && same_double(r[2], azi1) && same_double(r[3], s12)) {
            *lat2 = r[4];
            *lng2 = r[5];
            *azi2 = r[6];
            return;
        }
    }
    ((replay *)(uintptr_t)geod)->misses++;
    *lat2 = *lng2 = *azi2 = 0.0;
}

/* ---- a spherical geodesic solver (radius 6371 km) for the independent checks ---- */

#define SPH_R 6371008.8
#define SPH_D2R 0.017453292519943295

static void sph_inverse(const void *geod, double lat1, double lng1, double lat2, double lng2, double *s12, double *azi1,
                        double *azi2) {
    (void)geod;
    double p1 = lat1 * SPH_D2R, p2 = lat2 * SPH_D2R, dl = (lng2 - lng1) * SPH_D2R;
    double a = sin((p2 - p1) / 2) * sin((p2 - p1) / 2) + cos(p1) * cos(p2) * sin(dl / 2) * sin(dl / 2);
    *s12 = 2 * SPH_R * asin(sqrt(a < 1 ? a : 1));
    *azi1 = atan2(sin(dl) * cos(p2), cos(p1) * sin(p2) - sin(p1) * cos(p2) * cos(dl)) / SPH_D2R;
    *azi2 = atan2(sin(dl) * cos(p1), -cos(p2) * sin(p1) + sin(p2) * cos(p1) * cos(dl)) / SPH_D2R;
}

static void sph_direct(const void *geod, double lat1, double lng1, double azi1, double s12, double *lat2, double *lng2,
                       double *azi2) {
    double p1 = lat1 * SPH_D2R, th = azi1 * SPH_D2R, d = s12 / SPH_R;
    double sp2 = sin(p1) * cos(d) + cos(p1) * sin(d) * cos(th);
    double p2 = asin(sp2);
    double l2 = lng1 * SPH_D2R + atan2(sin(th) * sin(d) * cos(p1), cos(d) - sin(p1) * sp2);
    *lat2 = p2 / SPH_D2R;
    *lng2 = remainder(l2 / SPH_D2R, 360.0);
    double s, a1;
    sph_inverse(geod, lat1, lng1, *lat2, *lng2, &s, &a1, azi2);
}

/* The public verb with the grow protocol: starts from `cap` cells, grows as asked; out is malloc'd. */
static dggs_error line_cells(const double *xy, size_t n, int level, dggs_projection proj, const dggs_geodesic *g,
                             size_t cap, dggs_cell **out, size_t *count, int *grown) {
    size_t est, ws;
    *out = NULL;
    *count = 0;
    *grown = 0;
    dggs_error err = dggs_line_to_cells_size(xy, n, level, g, &est, &ws);
    if (err != DGGS_OK) return err;
    void *work = malloc(ws ? ws : 1);
    if (cap == 0) cap = est;
    for (;;) {
        *out = malloc((cap ? cap : 1) * sizeof(dggs_cell));
        err = dggs_line_to_cells(xy, n, level, proj, g, work, ws, *out, cap, count);
        if (err != DGGS_E_BUFFER) break;
        CHECK(*count > cap);
        cap = *count;
        free(*out);
        (*grown)++;
    }
    free(work);
    return err;
}

/* The line's invariants: distinct consecutive cells sharing an edge, the ends' cells first and last. */
static void check_line(const dggs_cell *c, size_t n, int level, double lat0, double lng0, double lat1, double lng1,
                       dggs_projection proj) {
    CHECK(n >= 1);
    CHECK_EQ_U64(c[0], dggs_one_point(proj, lat0, lng0, level));
    CHECK_EQ_U64(c[n - 1], dggs_one_point(proj, lat1, lng1, level));
    for (size_t i = 0; i < n; i++) {
        CHECK(dggs_is_valid(c[i]) && dggs_level_of(c[i]) == level);
        if (i > 0) CHECK(dggs_are_neighbours(c[i - 1], c[i]));
    }
}

static void test_frozen_kernels(void) {
    for (size_t i = 0; i < COUNT(FROZEN_LOCATE); i++) {
        const frozen_locate *r = &FROZEN_LOCATE[i];
        double x, y, z, fx, fy;
        int face;
        dggs_ecef(r->lat, r->lng, &x, &y, &z);
        CHECK_EQ_U64(dggs_cell_at(DGGS_ISEA, x, y, z, r->level, -1, &face), r->isea);
        CHECK_EQ_U64(dggs_cell_at(DGGS_IVEA, x, y, z, r->level, -1, &face), r->ivea);
        CHECK_EQ_U64(dggs_sample(DGGS_ISEA, x, y, z, r->level, -1, &face, &fx, &fy), r->isea);
        CHECK(face == r->face);
        CHECK_NEAR_DOUBLE(fx, r->fx);
        CHECK_NEAR_DOUBLE(fy, r->fy);
        dggs_cell got;
        dggs_cells_at(DGGS_ISEA, &r->lat, &r->lng, 1, r->level, &got, false);
        CHECK_EQ_U64(got, r->isea);
    }
    uint64_t chain[COUNT(FROZEN_CHAIN_LAT)];
    dggs_cells_at(DGGS_ISEA, FROZEN_CHAIN_LAT, FROZEN_CHAIN_LNG, COUNT(chain), FROZEN_CHAIN_LEVEL, chain, true);
    for (size_t i = 0; i < COUNT(chain); i++) CHECK_EQ_U64(chain[i], FROZEN_CHAIN_ISEA[i]);
    dggs_cells_at(DGGS_IVEA, FROZEN_CHAIN_LAT, FROZEN_CHAIN_LNG, COUNT(chain), FROZEN_CHAIN_LEVEL, chain, true);
    for (size_t i = 0; i < COUNT(chain); i++) CHECK_EQ_U64(chain[i], FROZEN_CHAIN_IVEA[i]);

    for (size_t i = 0; i < COUNT(FROZEN_SCALARS); i++) {
        const frozen_scalar *r = &FROZEN_SCALARS[i];
        double e[3], t[3], g[2];
        dggs_ecef(r->lat, r->lng, &e[0], &e[1], &e[2]);
        dggs_tangent(r->lat, r->lng, r->az, &t[0], &t[1], &t[2]);
        dggs_geodetic(e[0] * 1.001, e[1] * 1.001, e[2] * 1.001, &g[0], &g[1]);
        for (int k = 0; k < 3; k++) {
            CHECK_NEAR_DOUBLE(e[k], r->e[k]);
            CHECK_NEAR_DOUBLE(t[k], r->t[k]);
        }
        CHECK_NEAR_DOUBLE(g[0], r->g[0]);
        CHECK_NEAR_DOUBLE(g[1], r->g[1]);
    }

    for (size_t i = 0; i < COUNT(FROZEN_CHORD); i++) {
        const frozen_chord *r = &FROZEN_CHORD[i];
        double ta[6];
        dggs_corners6(r->a, ta);
        CHECK(dggs_clear(r->a, r->b, r->fa, r->xa, r->ya, r->fb, r->xb, r->yb) == (r->clear != 0));
        CHECK(dggs_corner_clear(r->a, r->b, r->fa, r->xa, r->ya, r->fb, r->xb, r->yb) == (r->corner != 0));
        CHECK_NEAR_DOUBLE(dggs_dist_to_segment(ta[0], ta[1], r->xa, r->ya, r->xb, r->yb), r->dist);
        /* the planar tests trust no sample off the cells' face */
        CHECK(!dggs_clear(r->a, r->b, -1, r->xa, r->ya, -1, r->xb, r->yb));
        CHECK(!dggs_corner_clear(r->a, r->b, r->fa, r->xa, r->ya, (r->fa + 1) % 20, r->xb, r->yb));
    }

    double pts[2 * FROZEN_CLEAN_N];
    size_t kept;
    CHECK(dggs_clean(FROZEN_CLEAN_IN, FROZEN_CLEAN_N, pts, &kept) == -1);
    CHECK(kept == FROZEN_CLEAN_KEPT);
    for (size_t i = 0; i < 2 * kept && i < COUNT(FROZEN_CLEAN_OUT); i++) CHECK_NEAR_DOUBLE(pts[i], FROZEN_CLEAN_OUT[i]);
    size_t size, inner, nseg = FROZEN_CLEAN_KEPT - 1;
    dggs_layout_size(FROZEN_LAYOUT_DIST, nseg, FROZEN_LAYOUT_MAX_SPAN, &size, &inner);
    CHECK(size == FROZEN_LAYOUT_SIZE && inner == FROZEN_LAYOUT_INNER);
    if (size == FROZEN_LAYOUT_SIZE && inner == FROZEN_LAYOUT_INNER) {
        double lat[FROZEN_LAYOUT_SIZE], lng[FROZEN_LAYOUT_SIZE], ao[FROZEN_LAYOUT_SIZE], ai[FROZEN_LAYOUT_SIZE];
        double span[FROZEN_LAYOUT_SIZE], s[FROZEN_LAYOUT_INNER + 1];
        int64_t at[FROZEN_LAYOUT_INNER + 1], seg[FROZEN_LAYOUT_INNER + 1];
        dggs_layout(pts, FROZEN_LAYOUT_AZ12, FROZEN_LAYOUT_AZ21, FROZEN_LAYOUT_DIST, nseg, FROZEN_LAYOUT_MAX_SPAN, lat,
                    lng, ao, ai, span, at, seg, s);
        for (size_t i = 0; i < inner; i++) lat[at[i]] = lng[at[i]] = 0.0; /* the caller fills these */
        for (size_t i = 0; i < size; i++) {
            CHECK_NEAR_DOUBLE(lat[i], FROZEN_LAYOUT_LAT[i]);
            CHECK_NEAR_DOUBLE(lng[i], FROZEN_LAYOUT_LNG[i]);
            CHECK_NEAR_DOUBLE(ao[i], FROZEN_LAYOUT_AZ_OUT[i]);
            CHECK_NEAR_DOUBLE(ai[i], FROZEN_LAYOUT_AZ_IN[i]);
            if (i + 1 < size) CHECK_NEAR_DOUBLE(span[i], FROZEN_LAYOUT_SPAN[i]);
        }
        for (size_t i = 0; i < inner; i++) {
            CHECK(at[i] == FROZEN_LAYOUT_AT[i] && seg[i] == FROZEN_LAYOUT_SEG[i]);
            CHECK_NEAR_DOUBLE(s[i], FROZEN_LAYOUT_S[i]);
        }
    }
    /* a bad point: its index, nothing kept */
    double bad[6] = {1.0, 2.0, 90.5, 0.0, NAN, 1.0};
    CHECK(dggs_clean(bad, 3, pts, &kept) == 1 && kept == 0);
    bad[2] = 90.0;
    CHECK(dggs_clean(bad, 3, pts, &kept) == 2);
    bad[4] = -90.0;
    bad[5] = INFINITY;
    CHECK(dggs_clean(bad, 3, pts, &kept) == 2);
    /* numba's max(1, int(ceil(q))) */
    CHECK(dggs_span_count(NAN) == 1 && dggs_span_count(0.0) == 1 && dggs_span_count(-5.0) == 1);
    CHECK(dggs_span_count(2.5) == 3 && dggs_span_count(7.0) == 7 && dggs_span_count(1e300) == 1);
}

static void test_frozen_traces(void) {
    for (size_t i = 0; i < COUNT(FROZEN_TRACE); i++) {
        const frozen_trace *r = &FROZEN_TRACE[i];
        /* the step and corner dggs.index.paths uses: half the level's short edge, 0.1 mm */
        double edge_step = DGGS_LT_STEP_EDGES * DGGS_LT_SHORT_EDGE[r->level];
        for (int p = 0; p < 2; p++) {
            dggs_projection proj = p ? DGGS_IVEA : DGGS_ISEA;
            for (int s = 0; s < 2; s++) {
                uint64_t out[4096];
                int64_t fix[256], nfix = -7;
                int64_t n = dggs_trace(proj, r->lat, r->lng, r->az_out, r->az_in, r->span, (size_t)r->n, r->level,
                                       edge_step, 1e-4, out, COUNT(out), fix, COUNT(fix), s == 0, &nfix);
                CHECK(n == r->ncells[p][s] && nfix == r->nfix[p][s]);
                for (int64_t k = 0; k < n && k < r->ncells[p][s]; k++) CHECK_EQ_U64(out[k], r->cells[p][s][k]);
                for (int64_t k = 0; k < nfix && k < r->nfix[p][s]; k++) CHECK(fix[k] == r->fix[p][s][k]);
                /* invariants: the anchors' cells at the ends, distinct neighbours but at the corner gaps */
                CHECK_EQ_U64(out[0], dggs_one_point(proj, r->lat[0], r->lng[0], r->level));
                CHECK_EQ_U64(out[n - 1], dggs_one_point(proj, r->lat[r->n - 1], r->lng[r->n - 1], r->level));
                int64_t gaps = 0;
                for (int64_t k = 1; k < n; k++) {
                    CHECK(out[k] != out[k - 1]);
                    if (!dggs_adjacent(out[k - 1], out[k], r->level)) {
                        CHECK(gaps < nfix && fix[gaps] == k);
                        gaps++;
                    }
                }
                CHECK(gaps == nfix);
                /* without a fix buffer: the same cells, the gaps counted */
                uint64_t again[4096];
                int64_t nfix2 = -1;
                CHECK(dggs_trace(proj, r->lat, r->lng, r->az_out, r->az_in, r->span, (size_t)r->n, r->level, edge_step,
                                 1e-4, again, COUNT(again), NULL, 0, s == 0, &nfix2) == n);
                CHECK(nfix2 == nfix && memcmp(again, out, (size_t)n * sizeof *out) == 0);
                /* a full buffer (or a full fix list): -1, no gaps reported */
                if (n > 1) {
                    CHECK(dggs_trace(proj, r->lat, r->lng, r->az_out, r->az_in, r->span, (size_t)r->n, r->level,
                                     edge_step, 1e-4, again, (size_t)n - 1, fix, COUNT(fix), s == 0, &nfix2) == -1);
                    CHECK(nfix2 == 0);
                }
                if (nfix > 0) {
                    size_t fixcap = (size_t)nfix - 1;
                    CHECK(dggs_trace(proj, r->lat, r->lng, r->az_out, r->az_in, r->span, (size_t)r->n, r->level,
                                     edge_step, 1e-4, again, COUNT(again), fix, fixcap, s == 0, &nfix2) == -1);
                }
            }
        }
    }
    double lat[FROZEN_INTERP_N], lng[FROZEN_INTERP_N];
    const frozen_trace *r = &FROZEN_TRACE[1];
    dggs_interpolate(r->lat, r->lng, r->az_out, r->az_in, r->span, FROZEN_INTERP_K, FROZEN_INTERP_T, FROZEN_INTERP_N,
                     lat, lng);
    for (size_t i = 0; i < FROZEN_INTERP_N; i++) {
        CHECK_NEAR_DOUBLE(lat[i], FROZEN_INTERP_LAT[i]);
        CHECK_NEAR_DOUBLE(lng[i], FROZEN_INTERP_LNG[i]);
    }
    /* t = 0 and 1 are the anchors themselves, to rounding */
    double la, lo, c[12];
    dggs_line_trace_span(r->lat, r->lng, r->az_out, r->az_in, r->span, 1, c);
    dggs_at(c, 0.0, &la, &lo);
    CHECK(fabs(la - r->lat[1]) < 1e-12 && fabs(lo - r->lng[1]) < 1e-12);
    dggs_at(c, 1.0, &la, &lo);
    CHECK(fabs(la - r->lat[2]) < 1e-12 && fabs(lo - r->lng[2]) < 1e-12);

    for (size_t i = 0; i < FROZEN_AROUND_N; i++) {
        const frozen_around *a = &FROZEN_AROUND[i];
        uint64_t way[5];
        int n = dggs_line_around(a->a, a->b, way);
        CHECK(n == a->n);
        for (int k = 0; k < n && k < a->n; k++) CHECK_EQ_U64(way[k], a->way[k]);
        /* a walk from a through the way to b, edge neighbours all along */
        uint64_t prev = a->a;
        for (int k = 0; k < n; k++) {
            CHECK(dggs_are_neighbours(prev, way[k]));
            prev = way[k];
        }
        CHECK(dggs_are_neighbours(prev, a->b));
    }
}

static void test_public(void) {
    replay rp = {0};
    dggs_geodesic g = {replay_inverse, replay_direct, &rp};
    for (size_t i = 0; i < COUNT(FROZEN_PUBLIC); i++) {
        const frozen_public *r = &FROZEN_PUBLIC[i];
        for (int p = 0; p < 2; p++) {
            for (int small = 0; small < 2; small++) {
                dggs_cell *out;
                size_t n;
                int grown;
                dggs_error err = line_cells(r->xy, (size_t)r->n, r->level, p ? DGGS_IVEA : DGGS_ISEA, &g,
                                            small ? 1 : 0, &out, &n, &grown);
                CHECK(err == DGGS_OK);
                int want_n = p ? r->nivea : r->nisea;
                const uint64_t *want = p ? r->ivea : r->isea;
                CHECK(n == (size_t)want_n);
                for (size_t k = 0; k < n && k < (size_t)want_n; k++) CHECK_EQ_U64(out[k], want[k]);
                if (small && want_n > 1) CHECK(grown > 0);
                free(out);
            }
        }
    }
    CHECK(rp.misses == 0);

    /* independent: on a spherical solver, lines at every level keep the invariants */
    dggs_geodesic sph = {sph_inverse, sph_direct, NULL};
    static const double lines[][6] = {
        /* three points each: over the north pole, across the antimeridian, through the south pole region */
        {80.0, 10.0, 85.0, -170.0, 70.0, -100.0},
        {0.5, 179.9, -0.5, -179.9, 10.0, 175.0},
        {-89.0, 0.0, -88.0, 120.0, -89.5, -60.0},
        {58.2825, 11.25, 58.3, 11.3, 58.25, 11.2},
    };
    for (int level = 0; level <= DGGS_MAX_LEVEL; level++) {
        for (size_t i = 0; i < COUNT(lines); i++) {
            double xy[6];
            memcpy(xy, lines[i], sizeof xy);
            if (level > 12) { /* shorter lines deeper: about a thousand cells */
                double f = ldexp(1.0, -(level - 12));
                for (int k = 2; k < 6; k += 2) {
                    xy[k] = xy[0] + (xy[k] - xy[0]) * f;
                    xy[k + 1] = xy[1] + remainder(xy[k + 1] - xy[1], 360.0) * f;
                }
            }
            for (int p = 0; p < 2; p++) {
                dggs_cell *out;
                size_t n;
                int grown;
                dggs_projection proj = p ? DGGS_IVEA : DGGS_ISEA;
                CHECK(line_cells(xy, 3, level, proj, &sph, 0, &out, &n, &grown) == DGGS_OK);
                check_line(out, n, level, xy[0], xy[1], xy[4], xy[5], proj);
                free(out);
            }
        }
    }

    /* one point, repeated points, no points */
    double one[4] = {10.0, 20.0, 10.0, 20.0};
    dggs_cell cell;
    size_t n, est, ws;
    char work[64];
    CHECK(dggs_line_to_cells_size(one, 2, 7, &sph, &est, &ws) == DGGS_OK && est >= 1);
    CHECK(dggs_line_to_cells(one, 2, 7, DGGS_ISEA, &sph, work, sizeof work, &cell, 1, &n) == DGGS_OK && n == 1);
    CHECK_EQ_U64(cell, dggs_one_point(DGGS_ISEA, 10.0, 20.0, 7));
    CHECK(dggs_line_to_cells(one, 1, 7, DGGS_IVEA, &sph, work, sizeof work, &cell, 1, &n) == DGGS_OK && n == 1);
    CHECK_EQ_U64(cell, dggs_one_point(DGGS_IVEA, 10.0, 20.0, 7));
    CHECK(dggs_line_to_cells(one, 1, 7, DGGS_IVEA, &sph, work, sizeof work, &cell, 0, &n) == DGGS_E_BUFFER && n == 1);
    CHECK(dggs_line_to_cells(one, 0, 7, DGGS_ISEA, &sph, NULL, 0, NULL, 0, &n) == DGGS_OK && n == 0);

    /* errors */
    double bad[4] = {10.0, 20.0, 91.0, 20.0};
    CHECK(dggs_line_to_cells_size(bad, 2, 7, &sph, &est, &ws) == DGGS_E_LATLNG);
    CHECK(dggs_line_to_cells(bad, 2, 7, DGGS_ISEA, &sph, work, sizeof work, &cell, 1, &n) == DGGS_E_LATLNG);
    bad[2] = 10.0;
    bad[3] = NAN;
    CHECK(dggs_line_to_cells_size(bad, 2, 7, &sph, &est, &ws) == DGGS_E_LATLNG);
    CHECK(dggs_line_to_cells_size(one, 2, 29, &sph, &est, &ws) == DGGS_E_LEVEL);
    CHECK(dggs_line_to_cells_size(one, 2, -1, &sph, &est, &ws) == DGGS_E_LEVEL);
    CHECK(dggs_line_to_cells(one, 2, 29, DGGS_ISEA, &sph, work, sizeof work, &cell, 1, &n) == DGGS_E_LEVEL);
    CHECK(dggs_line_to_cells(one, 2, 7, (dggs_projection)2, &sph, work, sizeof work, &cell, 1, &n) ==
          DGGS_E_PROJECTION);
    CHECK(dggs_line_to_cells_size(one, 2, 7, NULL, &est, &ws) == DGGS_E_DOMAIN);
    dggs_geodesic half = {sph_inverse, NULL, NULL};
    CHECK(dggs_line_to_cells(one, 2, 7, DGGS_ISEA, &half, work, sizeof work, &cell, 1, &n) == DGGS_E_DOMAIN);
    double two[4] = {10.0, 20.0, 10.5, 21.0};
    CHECK(dggs_line_to_cells_size(two, 2, 7, &sph, &est, &ws) == DGGS_OK && ws > sizeof work);
    CHECK(dggs_line_to_cells(two, 2, 7, DGGS_ISEA, &sph, work, sizeof work, &cell, 1, &n) == DGGS_E_DOMAIN);
}

static void test_round_trips(void) {
    /* ecef -> geodetic gives the point back (Bowring's one round: to rounding near the surface) */
    for (int i = 0; i <= 180; i++) {
        double lat = -90.0 + i, lng = -180.0 + 2.0 * i, x, y, z, la, lo;
        dggs_ecef(lat, lng, &x, &y, &z);
        dggs_geodetic(x, y, z, &la, &lo);
        CHECK(fabs(la - lat) < 1e-12);
        if (fabs(lat) < 90.0) CHECK(fabs(remainder(lo - lng, 360.0)) < 1e-9);
        double tx, ty, tz;
        dggs_tangent(lat, lng, 37.0 * i, &tx, &ty, &tz);
        CHECK(fabs(tx * tx + ty * ty + tz * tz - 1.0) < 1e-14);
    }
    /* a chord between the planar centroids of a cell and its neighbour across the hypotenuse (length 2 short
     * edges) is clear: it crosses 0.83 and 1.17 short edges from the ends, beyond twice its bend 0.25 L (L = 0.58);
     * across the long leg too (0.58 and 1.15 from the ends, L = 0.67); across the short leg it crosses 1/3 from
     * the right angle, within 2 x 0.25 x 1.15, in doubt. A zero-length chord crosses nothing. */
    uint64_t a = dggs_one_point(DGGS_ISEA, 30.0, 40.0, 9);
    double ta[6], tb[6];
    int face = dggs_triangle(a, ta), clear = 0;
    for (int col = 0; col < 3; col++) {
        uint64_t b = dggs_neighbour(a, 9, col);
        if (dggs_face_of(b) != face) continue;
        dggs_corners6(b, tb);
        double xa = (ta[0] + ta[2] + ta[4]) / 3, ya = (ta[1] + ta[3] + ta[5]) / 3;
        double xb = (tb[0] + tb[2] + tb[4]) / 3, yb = (tb[1] + tb[3] + tb[5]) / 3;
        clear += dggs_clear(a, b, face, xa, ya, face, xb, yb);
        CHECK(!dggs_crosses(ta, tb, xa, ya, xa, ya));
        CHECK(dggs_dist_to_segment(xa, ya, xa, ya, xb, yb) == 0.0);
        CHECK(dggs_between(a, b, 9) == 0); /* edge neighbours share no edge neighbour */
        CHECK(dggs_adjacent(a, b, 9) && dggs_adjacent(b, a, 9));
    }
    CHECK(clear == 2);
}

int main(void) {
    test_frozen_kernels();
    test_frozen_traces();
    test_public();
    test_round_trips();
    CHECK_DONE();
}
