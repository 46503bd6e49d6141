/* The geometry floor (geometry.c, ivea.c): invariants and round trips, and outputs frozen from the numba kernel
 * (dggs/geometry/kernel.py, ivea.py) by tools/freeze_geometry.py, compared bit for bit. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "dggs.h"
#include "frozen_geometry.h"
#include "geometry.h"
#include "tables.h"
#include "testutil.h"

static double angle(const double a[3], const double b[3]) {
    double cx = a[1] * b[2] - a[2] * b[1], cy = a[2] * b[0] - a[0] * b[2], cz = a[0] * b[1] - a[1] * b[0];
    return atan2(sqrt(cx * cx + cy * cy + cz * cz), a[0] * b[0] + a[1] * b[1] + a[2] * b[2]);
}

static void invariants(void) {
    /* every face centre maps to its own face's origin, on both projections */
    for (int f = 0; f < DGGS_NUM_FACES; f++) {
        for (int proj = 0; proj < 2; proj++) {
            double x, y;
            const double *c = dggs_isea_centres[f];
            int face = dggs_proj_forward((dggs_projection)proj, c[0], c[1], c[2], &x, &y);
            CHECK(face == f);
            CHECK(hypot(x, y) < 1e-14);
        }
    }
    /* round trips on a lattice of the sphere, both projections: forward then inverse within 1e-13 rad */
    for (int i = 0; i <= 180; i += 3) {
        for (int j = -180; j < 180; j += 7) {
            double p[3], q[3];
            dggs_geodetic_to_unit(i - 90.0, j + 0.25, p);
            CHECK(fabs(p[0] * p[0] + p[1] * p[1] + p[2] * p[2] - 1.0) < 1e-15);
            for (int proj = 0; proj < 2; proj++) {
                double x, y;
                int face = dggs_proj_forward((dggs_projection)proj, p[0], p[1], p[2], &x, &y);
                dggs_proj_inverse((dggs_projection)proj, face, x, y, q);
                CHECK(angle(p, q) < 1e-13);
                double lat, lng;
                dggs_unit_to_geodetic(q[0], q[1], q[2], &lat, &lng);
                CHECK(fabs(lat - (i - 90.0)) < 1e-9);
                if (fabs(lat) < 89.9) CHECK(fabs(dggs_wrap_degrees(lng - (j + 0.25))) < 1e-9);
            }
        }
    }
    /* the level-1 digit of a point at planar azimuth 60 d + 30 is d; a point descends into a child that holds it */
    for (int d = 0; d < 6; d++) {
        double az = (60.0 * d + 30.0) * DGGS_RAD_PER_DEG, px, py;
        CHECK(dggs_level1_digit(0.3 * sin(az), 0.3 * cos(az)) == d);
        CHECK(dggs_level1_start(0.3 * sin(az), 0.3 * cos(az), &px, &py) == d);
        CHECK(px >= 0.0 && py >= 0.0 && px <= DGGS_SQRT3 && py <= 1.0);
    }
    CHECK(dggs_sector_of(0.0, 0.0) == 0 && dggs_sector_of(0.0, -1.0) == 1 && dggs_sector_of(-1.0, 0.0) == 2);
    CHECK(dggs_wrap_degrees(540.0) == 180.0 && dggs_wrap_degrees(-190.0) == 170.0 && dggs_wrap_degrees(-180.0) == -180.0);
    /* descend4 equals four descend steps on a grid of the canonical triangle (the jump table's promise) */
    int mismatches = 0;
    for (int i = 0; i < 400; i++) {
        for (int j = 0; j < 230; j++) {
            double x = DGGS_SQRT3 * (i + 0.37) / 400.0, y = (j + 0.61) / 230.0;
            if (y > 1.0 - x / DGGS_SQRT3) continue;
            double x4 = x, y4 = y, x1 = x, y1 = y;
            uint64_t packed = dggs_descend4(&x4, &y4), steps = 0;
            for (int k = 0; k < 4; k++) steps = (steps << 2) | (uint64_t)(dggs_descend(&x1, &y1) + 1);
            if (packed != steps || fabs(x4 - x1) > 1e-9 || fabs(y4 - y1) > 1e-9) mismatches++;
        }
    }
    CHECK(mismatches == 0);
    /* child_corners: child 0 of the canonical triangle (A, B, C) = ((sqrt3, 0), (0, 1), (0, 0)) is (B, D, C) */
    double t[6] = {DGGS_SQRT3, 0.0, 0.0, 1.0, 0.0, 0.0};
    dggs_child_corners(t, 0);
    CHECK(t[0] == 0.0 && t[1] == 1.0 && fabs(t[2] - 1.0 / DGGS_SQRT3) < 1e-15 && t[3] == 0.0 && t[4] == 0.0);
}

static void public_api(void) {
    int face;
    double x, y, lat, lng;
    CHECK(dggs_geo_to_face(91.0, 0.0, DGGS_ISEA, &face, &x, &y) == DGGS_E_LATLNG);
    CHECK(dggs_geo_to_face(NAN, 0.0, DGGS_ISEA, &face, &x, &y) == DGGS_E_LATLNG);
    CHECK(dggs_geo_to_face(0.0, INFINITY, DGGS_ISEA, &face, &x, &y) == DGGS_E_LATLNG);
    CHECK(dggs_geo_to_face(0.0, 0.0, (dggs_projection)2, &face, &x, &y) == DGGS_E_PROJECTION);
    CHECK(dggs_face_to_geo(20, 0.0, 0.0, DGGS_ISEA, &lat, &lng) == DGGS_E_DOMAIN);
    CHECK(dggs_face_to_geo(-1, 0.0, 0.0, DGGS_IVEA, &lat, &lng) == DGGS_E_DOMAIN);
    CHECK(dggs_face_to_geo(0, 0.0, 1.0, DGGS_ISEA, &lat, &lng) == DGGS_E_DOMAIN);
    CHECK(dggs_face_to_geo(0, NAN, 0.0, DGGS_ISEA, &lat, &lng) == DGGS_E_LATLNG);
    for (int proj = 0; proj < 2; proj++) {
        CHECK(dggs_geo_to_face(12.5, 540.0 - 33.25, (dggs_projection)proj, &face, &x, &y) == DGGS_OK);
        CHECK(dggs_face_to_geo(face, x, y, (dggs_projection)proj, &lat, &lng) == DGGS_OK);
        CHECK(fabs(lat - 12.5) < 1e-12 && fabs(lng - (180.0 - 33.25)) < 1e-12);
        /* the north pole goes to face 0 (the lowest of the five faces round it), the south pole to 16 */
        CHECK(dggs_geo_to_face(90.0, 0.0, (dggs_projection)proj, &face, &x, &y) == DGGS_OK && face == 0);
        CHECK(dggs_geo_to_face(-90.0, 0.0, (dggs_projection)proj, &face, &x, &y) == DGGS_OK && face == 16);
    }
}

/* Outputs of the numba kernel (tools/freeze_geometry.py), bit for bit. */
static void frozen(void) {
    size_t n = sizeof frozen_points / sizeof frozen_points[0];
    CHECK(n >= 30);
    for (size_t i = 0; i < n; i++) {
        const struct frozen_point *r = &frozen_points[i];
        const double *v = r->v;
        dggs_projection proj = (dggs_projection)r->proj;
        double p[3], q[3], x, y, lat, lng, px, py;
        dggs_geodetic_to_unit(v[0], v[1], p);
        for (int k = 0; k < 3; k++) CHECK_NEAR_DOUBLE(p[k], v[2 + k]);
        int face = dggs_proj_forward(proj, p[0], p[1], p[2], &x, &y);
        CHECK(face == r->face);
        CHECK_NEAR_DOUBLE(x, v[5]);
        CHECK_NEAR_DOUBLE(y, v[6]);
        /* the same through the any-orientation entries */
        double x2, y2;
        const double *centres = &dggs_isea_centres[0][0], *frames = &dggs_isea_frames[0][0][0];
        int face2 = proj == DGGS_IVEA ? dggs_ivea_forward_unit(centres, frames, p[0], p[1], p[2], &x2, &y2)
                                      : dggs_snyder_forward_unit(centres, frames, p[0], p[1], p[2], &x2, &y2);
        CHECK(face2 == face);
        CHECK_SAME_DOUBLE(x2, x);
        CHECK_SAME_DOUBLE(y2, y);
        dggs_proj_inverse(proj, face, x, y, q);
        for (int k = 0; k < 3; k++) CHECK_NEAR_DOUBLE(q[k], v[7 + k]);
        dggs_unit_to_geodetic(q[0], q[1], q[2], &lat, &lng);
        CHECK_NEAR_DOUBLE(lat, v[10]);
        CHECK_NEAR_DOUBLE(lng, v[11]);
        /* levels 1..28: level1_start, descend4 six times, descend three times */
        CHECK(dggs_level1_start(x, y, &px, &py) == r->digit1);
        uint64_t packed = 0;
        for (int k = 0; k < 6; k++) packed = (packed << 8) | dggs_descend4(&px, &py);
        for (int k = 0; k < 3; k++) packed = (packed << 2) | (uint64_t)(dggs_descend(&px, &py) + 1);
        CHECK_EQ_U64(packed, r->digits);
        CHECK_WITHIN(px, v[12], 1e-6); /* magnified 2^6 3^9 ... times */
        CHECK_WITHIN(py, v[13], 1e-6);
    }
    double t[6];
    for (int k = 0; k < 6; k++) t[k] = (&dggs_level1_corners[4][0][0])[k];
    for (size_t i = 0; i < sizeof frozen_corners / sizeof frozen_corners[0]; i++) {
        dggs_child_corners(t, frozen_corners[i].digit);
        for (int k = 0; k < 6; k++) CHECK_NEAR_DOUBLE(t[k], frozen_corners[i].t[k]);
    }
}

/* dggs_snyder_inverse_units (several points at once) gives each point the bits it gets alone
 * (dggs_snyder_inverse_unit, the batch of one; its bits against the numba kernel's are the kernel digests'): random
 * points of the face and far beyond it, the centre, tiny and subnormal radii, and batches of every size 1..12. */
static void inverse_units(void) {
    const double *frames = &dggs_isea_frames[0][0][0];
    uint64_t state = 35;
    double x[DGGS_INVERSE_LANES], y[DGGS_INVERSE_LANES], p[DGGS_INVERSE_LANES][3], q[3];
    const double fixed[][2] = {{0.0, 0.0}, {1e-300, 0.0}, {0.0, -4e-320}, {3e-310, 2e-310}, {-1e-200, 1e-200},
                               {0.5, 0.3}, {-0.7, -0.9}, {2.0, -1.5}, {0.0, 0.9}, {-0.0, -0.9}, {1e-17, 1.0}};
    int bad = 0;
    for (int round = 0; round < 20000; round++) {
        int n = 1 + round % DGGS_INVERSE_LANES, face = round % 20;
        for (int j = 0; j < n; j++) {
            uint64_t r = splitmix64(&state);
            if (r % 7 == 0) {
                size_t k = (size_t)(r >> 8) % (sizeof fixed / sizeof fixed[0]);
                x[j] = fixed[k][0], y[j] = fixed[k][1];
            } else {
                double scale = r % 5 == 0 ? 3.0 : 0.8; /* beyond the face now and then */
                x[j] = scale * ((double)(splitmix64(&state) >> 11) * 0x1p-53 * 2.0 - 1.0);
                y[j] = scale * ((double)(splitmix64(&state) >> 11) * 0x1p-53 * 2.0 - 1.0);
            }
        }
        dggs_snyder_inverse_units(frames, face, n, x, y, p);
        for (int j = 0; j < n; j++) {
            dggs_snyder_inverse_unit(frames, face, x[j], y[j], q);
            bad += memcmp(p[j], q, sizeof q) != 0;
        }
    }
    CHECK(bad == 0);
}

int main(void) {
    frozen();
    invariants();
    public_api();
    inverse_units();
    CHECK_DONE();
}
