/* The geometry floor: the authalic sphere, Snyder's equal-area projection (ISEA) per point and the Split (2:6)
 * steps on a face plane. A transliteration of dggs/geometry/kernel.py, operation for operation: Snyder 1992
 * eqs. 6-14 with the closed-form inverse azimuth of thesis chapter 4, the authalic series of authalic.py
 * (Karney 2023) and the Split (2:6) steps of split26.py (thesis §6.1.7). Every constant is tables.h's exact
 * double. numba's math.radians / math.degrees are x * (pi / 180) / x * (180 / pi); its min(a, b) is
 * (b < a ? b : a) and max(a, b) is (b > a ? b : a), as Python's. */
#include "geometry.h"

#include <math.h>

#include "dmath.h"
#include "dmath_inline.h"
#include "tables.h"

/* Python's min / max of two floats (numba's do_minmax): the second only if strictly smaller / larger. */
static inline double py_min(double a, double b) { return b < a ? b : a; }
static inline double py_max(double a, double b) { return b > a ? b : a; }

/* ------------------------------------------------------------------------------------------------------------
 * Latitudes and longitudes
 * ------------------------------------------------------------------------------------------------------------ */

/* kernel.wrap_degrees: a longitude reduced exactly to -180..180 (fmod is exact; no radians first). */
double dggs_wrap_degrees(double lng) {
    if (-180.0 <= lng && lng <= 180.0) return lng;
    lng = fmod(lng, 360.0);
    if (lng > 180.0)
        lng -= 360.0;
    else if (lng < -180.0)
        lng += 360.0;
    return lng;
}

/* kernel.unit_to_geodetic: vector on the authalic sphere (any norm) -> geodetic WGS84 (lat, lng) degrees.
 * sin 2 beta and cos 2 beta for the series (Clenshaw) come from the vector itself. */
void dggs_unit_to_geodetic(double px, double py, double pz, double *lat, double *lng) {
    double h2 = px * px + py * py;
    double h = sqrt(h2);
    double beta = dggs_atan2(pz, h);
    double r2 = h2 + pz * pz;
    double s2 = 2.0 * pz * h / r2;
    double two_c2 = 2.0 * (h2 - pz * pz) / r2;
    double b1 = 0.0, b2 = 0.0;
    for (int i = DGGS_GEODETIC_TERMS - 1; i >= 0; i--) {
        double t = two_c2 * b1 - b2 + dggs_to_geodetic[i];
        b2 = b1;
        b1 = t;
    }
    *lat = (beta + b1 * s2) * DGGS_DEG_PER_RAD;
    *lng = dggs_atan2(py, px) * DGGS_DEG_PER_RAD;
}

/* kernel.authalic_sincos: (sin beta, cos beta) of the authalic latitude from the geodetic sin phi, cos phi.
 * d = beta - phi from the series in sin 2 phi, cos 2 phi; sin d, cos d by Taylor series to the ninth order. */
void dggs_authalic_sincos(double sp, double cp, double *sb, double *cb) {
    double s2 = 2.0 * sp * cp;
    double two_c2 = 2.0 * ((cp - sp) * (cp + sp));
    double b1 = 0.0, b2 = 0.0;
    for (int i = DGGS_AUTHALIC_TERMS - 1; i >= 0; i--) {
        double t = two_c2 * b1 - b2 + dggs_to_authalic[i];
        b2 = b1;
        b1 = t;
    }
    double d = b1 * s2;
    double d2 = d * d;
    double sd = d * (1.0 - d2 / 6.0 * (1.0 - d2 / 20.0 * (1.0 - d2 / 42.0 * (1.0 - d2 / 72.0))));
    double cd = 1.0 - d2 / 2.0 * (1.0 - d2 / 12.0 * (1.0 - d2 / 30.0 * (1.0 - d2 / 56.0)));
    *sb = sp * cd + cp * sd;
    *cb = cp * cd - sp * sd;
}

/* kernel.geodetic_to_unit: geodetic WGS84 degrees -> unit vector on the authalic sphere. */
void dggs_geodetic_to_unit(double lat, double lng, double p[3]) {
    double phi = lat * DGGS_RAD_PER_DEG;
    double sb, cb;
    double sp, cp, sl, cl;
    dggs_sincos(phi, &sp, &cp);
    dggs_authalic_sincos(sp, cp, &sb, &cb);
    double lam = dggs_wrap_degrees(lng) * DGGS_RAD_PER_DEG;
    dggs_sincos(lam, &sl, &cl);
    p[0] = cb * cl;
    p[1] = cb * sl;
    p[2] = sb;
}

/* ------------------------------------------------------------------------------------------------------------
 * Snyder forward and inverse (Snyder 1992, eqs. 6-14)
 * ------------------------------------------------------------------------------------------------------------ */

void dggs_sector_forward(double sin_az, double cos_az, double sin_half_z, double *x, double *y) {
    double u = cos_az + sin_az * DGGS_COT_THETA; /* eq. 9 */
    double sin_half_q = sqrt(0.5 * (1.0 - u / sqrt(DGGS_TAN_G2 + u * u)));
    double cos_h = sin_az * (DGGS_SIN_G * DGGS_COS_SMALL_G) - cos_az * DGGS_COS_G; /* eq. 6 */
    double sin_h = sqrt(1.0 - cos_h * cos_h);                                       /* H in (36, 144) degrees */
    double az_plus_h = dggs_atan2(sin_az * cos_h + cos_az * sin_h, cos_az * cos_h - sin_az * sin_h);
    if (az_plus_h < 0.0) az_plus_h += DGGS_TWO_PI;
    double area = az_plus_h + (DGGS_G - DGGS_PI);      /* eq. 7 */
    double big_x = DGGS_RT2 - 2.0 * area * DGGS_COT_THETA; /* eq. 8 as (X, Y) */
    double big_y = 2.0 * area;
    double rho = DGGS_D_PRIME_NUM / (big_x + big_y * DGGS_COT_THETA) * sin_half_z / sin_half_q; /* eqs. 10-12 */
    *x = rho * big_y;
    *y = rho * big_x;
}

/* kernel.face_forward: unit vector -> (x, y) in the frame of `face`, nearest or not. The reduced azimuth's sine
 * and cosine come from rotating (east, north) by -120 k degrees, so only the arctangent of Az + H remains. */
void dggs_snyder_face_forward(const double *frames, int face, double px, double py, double pz, double *x, double *y) {
    const double *f = frames + 9 * face;
    double c = f[0] * px + f[1] * py + f[2] * pz;
    double n = f[3] * px + f[4] * py + f[5] * pz;
    double e = f[6] * px + f[7] * py + f[8] * pz;
    double h2 = n * n + e * e;
    if (h2 == 0.0) {
        *x = 0.0;
        *y = 0.0;
        return;
    }
    /* sector k = azimuth // 120 degrees: sin(Az - 120) < 0 on [0, 120), sin(Az - 240) >= 0 on [240, 360) */
    int k;
    if (e >= 0.0 && -0.5 * e - DGGS_HALF_SQRT3 * n < 0.0 && !(e == 0.0 && n < 0.0))
        k = 0;
    else if (e < 0.0 && -0.5 * e + DGGS_HALF_SQRT3 * n >= 0.0)
        k = 2;
    else
        k = 1;
    double rc = dggs_rot_cos[k], rs = dggs_rot_sin[k];
    double inv_h = 1.0 / sqrt(h2);
    double sin_az = (e * rc - n * rs) * inv_h;
    double cos_az = (n * rc + e * rs) * inv_h;
    double sin_half_z = sqrt(0.5 * h2 / (1.0 + c));
    double sp, cp;
    dggs_sector_forward(sin_az, cos_az, sin_half_z, &sp, &cp);
    *x = sp * rc + cp * rs;
    *y = cp * rc - sp * rs;
}

/* kernel.forward_unit: unit vector -> (face, x, y) in the face frame (unit sphere). */
int dggs_snyder_forward_unit(const double *centres, const double *frames, double px, double py, double pz, double *x,
                             double *y) {
    int face = dggs_nearest_face(centres, px, py, pz);
    dggs_snyder_face_forward(frames, face, px, py, pz, x, y);
    return face;
}

/* kernel.inverse_unit of n <= DGGS_INVERSE_LANES points of one face: face-frame (x, y) -> unit vector, by the
 * exact closed form (Snyder 1992 eqs. 6-8 solved for Az; thesis ch. 4); sin(G - A/2), sin(G - A) from sin(A/2),
 * cos(A/2) by the angle-sum rules. Stage by stage: each stage runs over all points before the next, with dmath's
 * hypot and small-angle sin and cos inlined, so that the points' chains of divisions and square roots
 * (latency-bound, about 100 ns a point one by one) overlap in the CPU; each point's operations are the same
 * whatever n, so its bits do not depend on its neighbours. */
void dggs_snyder_inverse_units(const double *frames, int face, int n, const double *x, const double *y,
                               double (*p)[3]) {
    double rho[DGGS_INVERSE_LANES], rc[DGGS_INVERSE_LANES], rs[DGGS_INVERSE_LANES];
    double sin_a[DGGS_INVERSE_LANES], cos_a[DGGS_INVERSE_LANES], sh[DGGS_INVERSE_LANES], ch[DGGS_INVERSE_LANES];
    double sin_az[DGGS_INVERSE_LANES], cos_az[DGGS_INVERSE_LANES], sin_half_q[DGGS_INVERSE_LANES];
    double s[DGGS_INVERSE_LANES];
    for (int j = 0; j < n; j++) {
        rho[j] = dmath_hypot(x[j], y[j]);
        int k = dggs_sector_of(x[j], y[j]);
        rc[j] = dggs_rot_cos[k];
        rs[j] = dggs_rot_sin[k];
    }
    for (int j = 0; j < n; j++) {
        if (rho[j] > DGGS_TINY) {
            double inv_rho = 1.0 / rho[j];
            sin_a[j] = (x[j] * rc[j] - y[j] * rs[j]) * inv_rho;
            cos_a[j] = (y[j] * rc[j] + x[j] * rs[j]) * inv_rho;
        } else if (rho[j] > 0.0) { /* subnormal or tiny: 1 / rho would overflow; the direction from scaled copies */
            double sx = x[j] * DGGS_UNTINY, sy = y[j] * DGGS_UNTINY;
            double inv_rho = 1.0 / dggs_hypot(sx, sy);
            sin_a[j] = (sx * rc[j] - sy * rs[j]) * inv_rho;
            cos_a[j] = (sy * rc[j] + sx * rs[j]) * inv_rho;
        } else {
            sin_a[j] = 0.0;
            cos_a[j] = 1.0;
        }
    }
    for (int j = 0; j < n; j++) {
        double area = DGGS_RT2 * sin_a[j] / (2.0 * (cos_a[j] + DGGS_COT_THETA * sin_a[j])); /* eq. 8 inverted */
        /* |0.5 area| <= 0.16 in a sector (|Az| <= 60 degrees); the called sin and cos stay for safety */
        if (!dmath_sincos_pio4(0.5 * area, &sh[j], &ch[j])) dggs_sincos(0.5 * area, &sh[j], &ch[j]);
    }
    for (int j = 0; j < n; j++) {
        double sin_g_half = DGGS_SIN_G * ch[j] - DGGS_COS_G * sh[j]; /* sin(G - A/2) */
        /* sin(G - A) */
        double sin_g_full = DGGS_SIN_G * (ch[j] * ch[j] - sh[j] * sh[j]) - DGGS_COS_G * (2.0 * sh[j] * ch[j]);
        double num = 2.0 * sin_g_half * sh[j];
        double den = sin_g_full - DGGS_SIN_G * DGGS_COS_SMALL_G;
        double r = sqrt(num * num + den * den);
        sin_az[j] = num / r;
        cos_az[j] = den / r;
    }
    for (int j = 0; j < n; j++) {
        double u = cos_az[j] + sin_az[j] * DGGS_COT_THETA; /* eq. 9 */
        sin_half_q[j] = sqrt(0.5 * (1.0 - u / sqrt(DGGS_TAN_G2 + u * u)));
    }
    for (int j = 0; j < n; j++) {
        double d_prime = DGGS_D_PRIME_NUM / (cos_a[j] + sin_a[j] * DGGS_COT_THETA); /* eq. 10 */
        s[j] = py_min(rho[j] / d_prime * sin_half_q[j], 1.0); /* sin(z/2), eqs. 11-12 inverted */
    }
    const double *f = frames + 9 * face;
    for (int j = 0; j < n; j++) {
        double cos_z = 1.0 - 2.0 * s[j] * s[j];
        double sin_z = 2.0 * s[j] * sqrt(1.0 - s[j] * s[j]);
        double ct = (cos_az[j] * rc[j] - sin_az[j] * rs[j]) * sin_z; /* Az + 120 k */
        double st = (sin_az[j] * rc[j] + cos_az[j] * rs[j]) * sin_z;
        p[j][0] = cos_z * f[0] + ct * f[3] + st * f[6];
        p[j][1] = cos_z * f[1] + ct * f[4] + st * f[7];
        p[j][2] = cos_z * f[2] + ct * f[5] + st * f[8];
    }
}

/* One point: the batch of one (the same operations, the same bits). */
void dggs_snyder_inverse_unit(const double *frames, int face, double x, double y, double p[3]) {
    dggs_snyder_inverse_units(frames, face, 1, &x, &y, (double (*)[3])p);
}

/* ------------------------------------------------------------------------------------------------------------
 * The standard grid's tables on either projection
 * ------------------------------------------------------------------------------------------------------------ */

int dggs_proj_forward(dggs_projection proj, double px, double py, double pz, double *x, double *y) {
    const double *centres = &dggs_isea_centres[0][0], *frames = &dggs_isea_frames[0][0][0];
    if (proj == DGGS_IVEA) return dggs_ivea_forward_unit(centres, frames, px, py, pz, x, y);
    return dggs_snyder_forward_unit(centres, frames, px, py, pz, x, y);
}

void dggs_proj_face_forward(dggs_projection proj, int face, double px, double py, double pz, double *x, double *y) {
    const double *frames = &dggs_isea_frames[0][0][0];
    if (proj == DGGS_IVEA)
        dggs_ivea_face_forward(frames, face, px, py, pz, x, y);
    else
        dggs_snyder_face_forward(frames, face, px, py, pz, x, y);
}

void dggs_proj_inverse_many(dggs_projection proj, int face, int n, const double *x, const double *y, double (*p)[3]) {
    if (proj == DGGS_IVEA) {
        for (int j = 0; j < n; j++) dggs_ivea_inverse_unit(&dggs_isea_frames[0][0][0], face, x[j], y[j], p[j]);
        return;
    }
    for (int j = 0; j < n; j += DGGS_INVERSE_LANES) {
        int lanes = n - j < DGGS_INVERSE_LANES ? n - j : DGGS_INVERSE_LANES;
        dggs_snyder_inverse_units(&dggs_isea_frames[0][0][0], face, lanes, x + j, y + j, p + j);
    }
}

void dggs_proj_inverse(dggs_projection proj, int face, double x, double y, double p[3]) {
    const double *frames = &dggs_isea_frames[0][0][0];
    if (proj == DGGS_IVEA)
        dggs_ivea_inverse_unit(frames, face, x, y, p);
    else
        dggs_snyder_inverse_unit(frames, face, x, y, p);
}

/* ------------------------------------------------------------------------------------------------------------
 * Split (2:6) on a face plane (thesis §6.1.7; split26.py)
 * ------------------------------------------------------------------------------------------------------------ */

/* kernel.level1_digit: planar azimuth // 60 degrees (clockwise from +y) by half-planes; the centre gives 0.
 * A point on a dividing ray goes to the triangle clockwise of it, as int(Az / 60) would. */
int dggs_level1_digit(double x, double y) {
    if (x > 0.0 || (x == 0.0 && y >= 0.0)) {
        if (x == 0.0 && y == 0.0) return 0;
        if (-0.5 * x - DGGS_HALF_SQRT3 * y >= 0.0) return 2; /* Az >= 120 */
        if (0.5 * x - DGGS_HALF_SQRT3 * y >= 0.0) return 1;  /* Az >= 60 */
        return 0;
    }
    if (0.5 * x + DGGS_HALF_SQRT3 * y >= 0.0) return 5;  /* Az >= 300 */
    if (-0.5 * x + DGGS_HALF_SQRT3 * y >= 0.0) return 4; /* Az >= 240 */
    return 3;
}

/* kernel.level1_start: level-1 digit and the point in that triangle's canonical frame. */
int dggs_level1_start(double x, double y, double *px, double *py) {
    int d = dggs_level1_digit(x, y);
    double dx = x - dggs_l1_c[d][0], dy = y - dggs_l1_c[d][1];
    const double(*m)[2] = dggs_l1_rows[d];
    *px = m[0][0] * dx + m[0][1] * dy;
    *py = m[1][0] * dx + m[1][1] * dy;
    return d;
}

/* kernel.descend: one level down in the canonical frame. Child 0 (BCD) lies on C's side of BD
 * (sqrt3 x + y < 1), child 2 (ADE) on A's side of DE (sqrt3 x - y > 1), child 1 between them; 0 wins over 2. */
int dggs_descend(double *px, double *py) {
    double x = *px, y = *py;
    double sx = DGGS_SQRT3 * x;
    int c = (1 - (sx + y < 1.0)) * (1 + (sx - y > 1.0));
    *px = dggs_child_m[c][0][0] * x + dggs_child_m[c][0][1] * y + dggs_child_t[c][0];
    *py = dggs_child_m[c][1][0] * x + dggs_child_m[c][1][1] * y + dggs_child_t[c][1];
    return c;
}

/* kernel.descend4: four levels down at once by one look-up in split26's jump table; points in ambiguous grid
 * cells (near an edge) take four exact steps of descend.
 *
 * Not numba's for a NaN point: numba indexes the table with int(NaN) (out of bounds); here the index is
 * checked and such a point takes the exact steps (digit codes 2, 2, 2, 2 and a NaN point). */
uint64_t dggs_descend4(double *px, double *py) {
    double x = *px, y = *py;
    double fx = py_min(py_max(x * DGGS_JUMP_SX + 1.0, 0.0), (double)DGGS_JUMP_GRID_W + 1.0);
    double fy = py_min(py_max(y * (double)DGGS_JUMP_GRID_H + 1.0, 0.0), (double)DGGS_JUMP_GRID_H + 1.0);
    unsigned code = DGGS_JUMP_AMBIGUOUS;
    if (fx >= 0.0 && fy >= 0.0) /* false for NaN only */
        code = dggs_jump_table[(long)fy * DGGS_JUMP_W2 + (long)fx];
    if (code == DGGS_JUMP_AMBIGUOUS) {
        uint64_t packed = 0;
        for (int i = 0; i < 4; i++) {
            int c = dggs_descend(px, py);
            packed = (packed << 2) | (uint64_t)(c + 1);
        }
        return packed;
    }
    const double *m = dggs_jump_maps[code];
    *px = m[0] * x + m[1] * y + m[4];
    *py = m[2] * x + m[3] * y + m[5];
    return dggs_jump_packed[code];
}

/* kernel.child_corners: corners (A, B, C) of child `digit` of the 30-60-90 triangle (A, B, C), in place.
 * D is a third of the way from C to A, E the midpoint of AB; children 0 = (B, D, C), 1 = (B, D, E),
 * 2 = (A, D, E). */
void dggs_child_corners(double t[6], int digit) {
    double ax = t[0], ay = t[1], bx = t[2], by = t[3], cx = t[4], cy = t[5];
    double dx = cx + (ax - cx) / 3.0, dy = cy + (ay - cy) / 3.0;
    if (digit == 0) {
        t[0] = bx, t[1] = by, t[2] = dx, t[3] = dy, t[4] = cx, t[5] = cy;
        return;
    }
    double ex = 0.5 * (ax + bx), ey = 0.5 * (ay + by);
    if (digit == 1) {
        t[0] = bx, t[1] = by;
    } else {
        t[0] = ax, t[1] = ay;
    }
    t[2] = dx, t[3] = dy, t[4] = ex, t[5] = ey;
}

/* ------------------------------------------------------------------------------------------------------------
 * Public API (dggs.h, "projection")
 * ------------------------------------------------------------------------------------------------------------ */

dggs_error dggs_geo_to_face(double lat, double lng, dggs_projection proj, int *face, double *x, double *y) {
    if (!isfinite(lat) || !isfinite(lng) || lat < -90.0 || lat > 90.0) return DGGS_E_LATLNG;
    if (proj != DGGS_ISEA && proj != DGGS_IVEA) return DGGS_E_PROJECTION;
    double p[3];
    dggs_geodetic_to_unit(lat, lng, p);
    *face = dggs_proj_forward(proj, p[0], p[1], p[2], x, y);
    return DGGS_OK;
}

dggs_error dggs_face_to_geo(int face, double x, double y, dggs_projection proj, double *lat, double *lng) {
    if (proj != DGGS_ISEA && proj != DGGS_IVEA) return DGGS_E_PROJECTION;
    if (face < 0 || face >= DGGS_NUM_FACES) return DGGS_E_DOMAIN;
    if (!isfinite(x) || !isfinite(y)) return DGGS_E_LATLNG;
    /* _checked._outside_face with slack 1e-9: edge normals at azimuths 60, 180, 300 degrees */
    double limit = DGGS_FACE_INRADIUS * (1.0 + 1e-9);
    if (DGGS_HALF_SQRT3 * x + 0.5 * y > limit || -y > limit || -DGGS_HALF_SQRT3 * x + 0.5 * y > limit)
        return DGGS_E_DOMAIN;
    double p[3];
    dggs_proj_inverse(proj, face, x, y, p);
    dggs_unit_to_geodetic(p[0], p[1], p[2], lat, lng);
    return DGGS_OK;
}
