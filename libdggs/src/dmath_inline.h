/* The parts of dmath.c's functions that callers inline (dmath.h's functions are these, called): the error-free
 * transformations, the sin and cos kernels on [-pi/4, pi/4], hypot whole, and sin and cos of an argument in
 * [-pi/4, pi/4]. Inlined where several independent points are computed at once (geometry.c's
 * dggs_snyder_inverse_units), so that the compiler can interleave their chains; the same operations, the same
 * bits as the calls. */
#ifndef DGGS_DMATH_INLINE_H
#define DGGS_DMATH_INLINE_H

#include <math.h>
#include <stdbool.h>

/* ------------------------------------------------------------------------------------------------------------
 * Error-free transformations (Knuth's TwoSum, Dekker's FastTwoSum, Veltkamp's split and Dekker's product)
 * ------------------------------------------------------------------------------------------------------------ */

static inline void dmath_two_sum(double a, double b, double *s, double *e) {
    double t = a + b;
    double bb = t - a;
    *e = (a - (t - bb)) + (b - bb);
    *s = t;
}

/* |a| >= |b| (or a == 0). */
static inline void dmath_fast_two_sum(double a, double b, double *s, double *e) {
    double t = a + b;
    *e = b - (t - a);
    *s = t;
}

/* a * b = p + e exactly, for |a|, |b| < 2^995 and products well above the subnormals. */
static inline void dmath_two_prod(double a, double b, double *p, double *e) {
    double ca = 134217729.0 * a, cb = 134217729.0 * b; /* 2^27 + 1 */
    double ah = ca - (ca - a), al = a - ah;
    double bh = cb - (cb - b), bl = b - bh;
    double q = a * b;
    *e = ((ah * bh - q) + ah * bl + al * bh) + al * bl;
    *p = q;
}

/* sin(x + y) for |x| <= pi/4, |y| <= ulp(x) / 2: x + x^3 (S1 + x^2 P(x^2)), y entering as y (1 - x^2 / 2). */
static inline double dmath_kernel_sin(double x, double y) {
    static const double S1 = -1.66666666666666324348e-01, S2 = 8.33333333332248946124e-03,
                        S3 = -1.98412698298579493134e-04, S4 = 2.75573137070700676789e-06,
                        S5 = -2.50507602534068634195e-08, S6 = 1.58969099521155010221e-10;
    double z = x * x;
    double v = z * x;
    double r = S2 + z * (S3 + z * (S4 + z * (S5 + z * S6)));
    return x - ((z * (0.5 * y - v * r) - y) - v * S1);
}

/* cos(x + y) for |x| <= pi/4: 1 - x^2/2 + x^4 Q(x^2) - x y, the rounding of 1 - x^2/2 carried along. */
static inline double dmath_kernel_cos(double x, double y) {
    static const double C1 = 4.16666666666666019037e-02, C2 = -1.38888888888741095749e-03,
                        C3 = 2.48015872894767294178e-05, C4 = -2.75573143513906633035e-07,
                        C5 = 2.08757232129817482790e-09, C6 = -1.13596475577881948265e-11;
    double z = x * x;
    double w = z * z;
    double r = z * (C1 + z * (C2 + z * C3)) + w * w * (C4 + z * (C5 + z * C6));
    double hz = 0.5 * z;
    double one_minus_hz = 1.0 - hz;
    return one_minus_hz + (((1.0 - one_minus_hz) - hz) + (z * r - x * y));
}

/* dmath.c's PIO4, pi/4 rounded (tests/index/test_dmath.py checks that the two are one number). */
#define DMATH_PIO4 0x1.921fb54442d18p-1

/* dggs_sincos(x) where |x| <= pi/4 (true), else false and nothing written. */
static inline bool dmath_sincos_pio4(double x, double *s, double *c) {
    double ax = fabs(x);
    if (!(ax <= DMATH_PIO4)) return false;
    *s = ax < 0x1p-26 ? x : dmath_kernel_sin(x, 0.0);
    *c = ax < 0x1p-27 ? 1.0 : dmath_kernel_cos(x, 0.0);
    return true;
}

static inline double dmath_hypot(double x, double y) {
    double ax = fabs(x), ay = fabs(y);
    if (isinf(ax) || isinf(ay)) return INFINITY;
    if (isnan(ax) || isnan(ay)) return ax + ay;
    if (ay > ax) {
        double t = ax;
        ax = ay;
        ay = t;
    }
    if (ay == 0.0 || ay * 0x1p54 < ax) return ax; /* sqrt(ax^2 + ay^2) < ax (1 + 2^-109) */
    double scale = 1.0;                           /* a power of two: squares neither overflow nor go subnormal */
    if (ax > 0x1p500) {
        scale = 0x1p600;
        ax *= 0x1p-600;
        ay *= 0x1p-600;
    } else if (ay < 0x1p-450) {
        scale = 0x1p-600;
        ax *= 0x1p600;
        ay *= 0x1p600;
    }
    double xx, xe, yy, ye, s, se;
    dmath_two_prod(ax, ax, &xx, &xe);
    dmath_two_prod(ay, ay, &yy, &ye);
    dmath_two_sum(xx, yy, &s, &se);
    double sl = se + (xe + ye);
    double h = sqrt(s), hh, he;
    dmath_two_prod(h, h, &hh, &he);
    h += (((s - hh) - he) + sl) / (2.0 * h); /* Newton on h^2 = s + sl; s - hh is exact */
    return h * scale;
}

#endif
