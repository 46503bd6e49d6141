/* The core's own sin, cos, atan2, hypot and asin: one implementation for every build, within 1 ulp (dmath.h).
 *
 * The algorithms are the published ones, written anew for this core:
 * - sin, cos: Cody & Waite's additive argument reduction by pi/2 in three 33-bit pieces for |x| < 2^20 (W. J.
 *   Cody, W. Waite, "Software Manual for the Elementary Functions", 1980, ch. 8), Payne & Hanek's reduction with
 *   the bits of 2/pi beyond (M. Payne, R. Hanek, "Radian reduction for trigonometric functions", SIGNUM
 *   Newsletter 18, 1983), then minimax polynomials on [-pi/4, pi/4] with the reduced argument's tail carried
 *   into the first-order term. The polynomial coefficients are fdlibm's (k_sin.c, k_cos.c; Sun Microsystems
 *   1993, K. C. Ng), numbers only.
 * - atan2: atan of q = |y / x| by reduction to |t| < 7/16 around atan(1/2), atan(1), atan(3/2) and infinity, t
 *   formed from x and y in one division, and an odd minimax polynomial of degree 23 (fdlibm s_atan.c's
 *   coefficients); below 7/16 the quotient's rounding error (Dekker's exact product, T. J. Dekker, "A
 *   floating-point technique for extending the available precision", Numer. Math. 18, 1971) is added as
 *   ql / (1 + q^2); the quadrant by a double-double pi.
 * - hypot: x^2 + y^2 as a double-double, its square root corrected by one Newton step (the residual by Dekker's
 *   product), scaled by powers of two only where a square would overflow or lose bits.
 * - asin: x + x R(x^2) for |x| < 1/2, and pi/2 - 2 asin(sqrt((1 - |x|) / 2)) above, with the square root split in
 *   a head and a tail; R is fdlibm e_asin.c's rational minimax approximation (coefficients only).
 * pi/2's pieces, pi, atan(1/2), atan(3/2) and the words of 2/pi are computed with mpmath at 2000 bits
 * (libdggs/tools/dmath_constants.py prints them). sqrt, fabs, ldexp, frexp and copysign are exact by IEEE 754. */
#include "dmath.h"
#include "dmath_inline.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

static inline uint64_t bits_of(double x) {
    uint64_t u;
    memcpy(&u, &x, sizeof u);
    return u;
}

static inline double with_bits(uint64_t u) {
    double x;
    memcpy(&x, &u, sizeof x);
    return x;
}

/* ------------------------------------------------------------------------------------------------------------
 * Constants (mpmath, 2000 bits: libdggs/tools/dmath_constants.py)
 * ------------------------------------------------------------------------------------------------------------ */

#define PIO4 0x1.921fb54442d18p-1
#define PIO2_HI 0x1.921fb54442d18p+0
#define PIO2_LO 0x1.1a62633145c07p-54
#define PI_HI 0x1.921fb54442d18p+1
#define PI_LO 0x1.1a62633145c07p-53
#define INV_PIO2 0x1.45f306dc9c883p-1
/* pi/2 = P1 + P2 + P3 + P3T, P1..P3 of 33 bits (n * Pk exact for |n| < 2^20); P1T = pi/2 - P1 rounded. */
#define P1 0x1.921fb54400000p+0
#define P1T 0x1.0b4611a626331p-34
#define P2 0x1.0b4611a600000p-34
#define P3 0x1.3198a2e000000p-69
#define P3T 0x1.b839a252049c1p-104

/* 2/pi in 32-bit words, most significant first: 2/pi = sum TWO_OVER_PI[k] 2^(-32 (k + 1)). 38 words cover the
 * window Payne-Hanek needs for the largest double (bits up to 2^-1161). */
static const uint32_t TWO_OVER_PI[40] = {
    0xa2f9836eu, 0x4e441529u, 0xfc2757d1u, 0xf534ddc0u, 0xdb629599u, 0x3c439041u, 0xfe5163abu, 0xdebbc561u,
    0xb7246e3au, 0x424dd2e0u, 0x06492eeau, 0x09d1921cu, 0xfe1deb1cu, 0xb129a73eu, 0xe88235f5u, 0x2ebb4484u,
    0xe99c7026u, 0xb45f7e41u, 0x3991d639u, 0x835339f4u, 0x9c845f8bu, 0xbdf9283bu, 0x1ff897ffu, 0xde05980fu,
    0xef2f118bu, 0x5a0a6d1fu, 0x6d367ecfu, 0x27cb09b7u, 0x4f463f66u, 0x9e5fea2du, 0x7527bac7u, 0xebe5f17bu,
    0x3d0739f7u, 0x8a5292eau, 0x6bfb5fb1u, 0x1f8d5d08u, 0x56033046u, 0xfc7b6babu, 0xf0cfbc20u, 0x9af4361du,
};

/* ------------------------------------------------------------------------------------------------------------
 * sin and cos
 * ------------------------------------------------------------------------------------------------------------ */

/* 32 bits of 2/pi from bit position p (position j weighs 2^-j; positions < 1 are zero). */
static uint32_t two_over_pi_bits(int p) {
    if (p <= -31) return 0;
    if (p <= 0) return TWO_OVER_PI[0] >> (1 - p);
    unsigned k = (unsigned)(p - 1) / 32u, o = (unsigned)(p - 1) % 32u;
    return o == 0 ? TWO_OVER_PI[k] : (TWO_OVER_PI[k] << o) | (TWO_OVER_PI[k + 1] >> (32u - o));
}

/* Payne-Hanek: |x| >= 2^20 finite -> x = n pi/2 + (y0 + y1), |y0 + y1| <= pi/4; returns n mod 4. x = m 2^(e-52)
 * with m < 2^53; the bits of 2/pi above position e - 53 only add multiples of 4 to x 2/pi, so m times the 192
 * bits from there is x 2/pi mod 4 with 190 fraction bits (the rest of 2/pi adds < 2^-137). */
static unsigned reduce_large(double x, double *y0, double *y1) {
    uint64_t u = bits_of(x);
    int e = (int)((u >> 52) & 0x7ffu) - 1023;
    uint64_t m = (u & 0xfffffffffffffull) | 0x10000000000000ull;
    uint32_t g[6], r[6] = {0, 0, 0, 0, 0, 0}, mw[2] = {(uint32_t)m, (uint32_t)(m >> 32)};
    for (int t = 0; t < 6; t++) g[5 - t] = two_over_pi_bits(e - 53 + 32 * t);
    for (int i = 0; i < 2; i++) {
        uint64_t carry = 0;
        for (int j = 0; j + i < 6; j++) {
            uint64_t t = (uint64_t)mw[i] * g[j] + r[i + j] + carry;
            r[i + j] = (uint32_t)t;
            carry = t >> 32;
        }
    }
    unsigned n = r[5] >> 30;
    uint64_t w2 = ((uint64_t)(r[5] & 0x3fffffffu) << 32) | r[4];
    uint64_t w1 = ((uint64_t)r[3] << 32) | r[2];
    uint64_t w0 = ((uint64_t)r[1] << 32) | r[0];
    int negative = (int)((w2 >> 61) & 1u); /* fraction >= 1/2: the next multiple, and 1 - fraction below it */
    if (negative) {
        n += 1u;
        w0 = ~w0;
        w1 = ~w1;
        w2 = ~w2 & 0x3fffffffffffffffull;
        if (++w0 == 0 && ++w1 == 0) ++w2;
    }
    int shift = 0;
    while (w2 == 0 && shift < 192) {
        w2 = w1;
        w1 = w0;
        w0 = 0;
        shift += 64;
    }
    if (w2 == 0) {
        *y0 = *y1 = 0.0;
        return n & 3u;
    }
    while (!(w2 & 0x8000000000000000ull)) { /* at most 63 steps, on arguments >= 2^20 only */
        w2 = (w2 << 1) | (w1 >> 63);
        w1 = (w1 << 1) | (w0 >> 63);
        w0 <<= 1;
        shift++;
    }
    /* fraction = w2:w1:w0 2^(-190 - shift), in quarter turns */
    double f_hi = ldexp((double)(w2 >> 11), -51 - shift);
    double f_lo = ldexp((double)(((w2 & 0x7ffu) << 53) | (w1 >> 11)), -115 - shift);
    double p, pe;
    dmath_two_prod(f_hi, PIO2_HI, &p, &pe);
    pe += f_hi * PIO2_LO + f_lo * PIO2_HI;
    dmath_fast_two_sum(p, pe, y0, y1);
    if (negative) {
        *y0 = -*y0;
        *y1 = -*y1;
    }
    if (x < 0) {
        *y0 = -*y0;
        *y1 = -*y1;
        n = 0u - n;
    }
    return n & 3u;
}

/* |x| > pi/4 finite -> x = n pi/2 + (y0 + y1) with |y0 + y1| <= pi/4 (a hair more), y1 the tail; n mod 4. */
static unsigned reduce(double x, double *y0, double *y1) {
    if (!(fabs(x) < 0x1p20)) return reduce_large(x, y0, y1);
    double fn = (x * INV_PIO2 + 0x1.8p52) - 0x1.8p52; /* round to nearest integer, |fn| < 2^20 */
    double a = x - fn * P1;                          /* exact: fn P1 has <= 53 bits, and Sterbenz */
    double w = fn * P1T;
    double hi = a - w;
    if (fabs(hi) >= fabs(fn) * 0x1p-26) { /* the error of fn P1T (< |fn| 2^-86) is < 2^-60 |hi| */
        *y0 = hi;
        *y1 = (a - hi) - w;
    } else { /* near a multiple of pi/2: two more 33-bit pieces, exact products, double-double sums */
        double s, e, s2, e2;
        dmath_two_sum(a, -(fn * P2), &s, &e);
        dmath_two_sum(s, -(fn * P3), &s2, &e2);
        dmath_fast_two_sum(s2, (e + e2) - fn * P3T, y0, y1);
    }
    return (unsigned)(int64_t)fn & 3u;
}

double dggs_sin(double x) {
    double ax = fabs(x);
    if (ax <= PIO4) return ax < 0x1p-26 ? x : dmath_kernel_sin(x, 0.0);
    if (!(ax < INFINITY)) return x - x; /* nan for inf and nan */
    double y0, y1;
    switch (reduce(x, &y0, &y1)) {
    case 0: return dmath_kernel_sin(y0, y1);
    case 1: return dmath_kernel_cos(y0, y1);
    case 2: return -dmath_kernel_sin(y0, y1);
    default: return -dmath_kernel_cos(y0, y1);
    }
}

double dggs_cos(double x) {
    double ax = fabs(x);
    if (ax <= PIO4) return ax < 0x1p-27 ? 1.0 : dmath_kernel_cos(x, 0.0);
    if (!(ax < INFINITY)) return x - x;
    double y0, y1;
    switch (reduce(x, &y0, &y1)) {
    case 0: return dmath_kernel_cos(y0, y1);
    case 1: return -dmath_kernel_sin(y0, y1);
    case 2: return -dmath_kernel_cos(y0, y1);
    default: return dmath_kernel_sin(y0, y1);
    }
}

/* sin and cos of one argument, one reduction: the bits of dggs_sin(x) and dggs_cos(x). */
void dggs_sincos(double x, double *s, double *c) {
    double ax = fabs(x);
    if (dmath_sincos_pio4(x, s, c)) return;
    if (!(ax < INFINITY)) {
        *s = *c = x - x;
        return;
    }
    double y0, y1;
    unsigned n = reduce(x, &y0, &y1);
    double sn = dmath_kernel_sin(y0, y1), cs = dmath_kernel_cos(y0, y1);
    switch (n) {
    case 0: *s = sn; *c = cs; break;
    case 1: *s = cs; *c = -sn; break;
    case 2: *s = -sn; *c = -cs; break;
    default: *s = -cs; *c = sn; break;
    }
}

/* ------------------------------------------------------------------------------------------------------------
 * atan2
 * ------------------------------------------------------------------------------------------------------------ */

/* atan(y / x) as hi + lo, for 0 < y, x with 2^-62 < y / x < 2^62, both in [2^-560, 2^560]. Below 7/16 the
 * quotient's rounding is carried as its tail (Dekker's product) into ql / (1 + q^2); above, the reduced argument
 * is formed from x and y themselves, one division (fdlibm forms it from the rounded quotient). */
static void atan_yx(double y, double x, double *hi, double *lo) {
    static const double AT[11] = {
        3.33333333333329318027e-01,  -1.99999999998764832476e-01, 1.42857142725034663711e-01,
        -1.11111104054623557880e-01, 9.09088713343650656196e-02,  -7.69187620504482999495e-02,
        6.66107313738753120669e-02,  -5.83357013379057348645e-02, 4.97687799461593236017e-02,
        -3.65315727442169155270e-02, 1.62858201153657823623e-02,
    };
    /* atan(1/2), atan(1), atan(3/2), pi/2 as head and tail (mpmath) */
    static const double HEAD[4] = {0x1.dac670561bb4fp-2, 0x1.921fb54442d18p-1, 0x1.f730bd281f69bp-1,
                                   0x1.921fb54442d18p+0};
    static const double TAIL[4] = {0x1.a2b7f222f65e2p-56, 0x1.1a62633145c07p-55, 0x1.007887af0cbbdp-56,
                                   0x1.1a62633145c07p-54};
    int id;
    double t, tail = 0.0;
    if (y < 0.4375 * x) {
        id = -1;
        t = y / x;
        double p, pe;
        dmath_two_prod(t, x, &p, &pe);
        tail = ((y - p) - pe) / (x + t * y); /* (y - t x) / x / (1 + t^2); y - p exact (Sterbenz) */
    } else if (y < 0.6875 * x) {
        id = 0;
        t = (2.0 * y - x) / (2.0 * x + y); /* (2q - 1) / (2 + q), the numerator exact (Sterbenz) */
    } else if (y < 1.1875 * x) {
        id = 1;
        t = (y - x) / (y + x);
    } else if (y < 2.4375 * x) {
        id = 2;
        double h, l;
        dmath_fast_two_sum(x, 0.5 * x, &h, &l); /* 1.5 x = h + l exactly; y - h exact (Sterbenz) */
        t = ((y - h) - l) / (x + 1.5 * y);
    } else {
        id = 3;
        t = -x / y;
    }
    double z = t * t;
    double w = z * z;
    double s1 = z * (AT[0] + w * (AT[2] + w * (AT[4] + w * (AT[6] + w * (AT[8] + w * AT[10])))));
    double s2 = w * (AT[1] + w * (AT[3] + w * (AT[5] + w * (AT[7] + w * AT[9]))));
    if (id < 0) {
        dmath_fast_two_sum(t, tail - t * (s1 + s2), hi, lo);
        return;
    }
    double s, e;
    dmath_two_sum(HEAD[id], t, &s, &e);
    dmath_fast_two_sum(s, e + (TAIL[id] - t * (s1 + s2)), hi, lo);
}

double dggs_atan2(double y, double x) {
    double ax = fabs(x), ay = fabs(y);
    double r = 0.0;
    int general = 1; /* atan(ay / ax) by atan_yx, then the quadrant: every call of the core */
    if (!(ax > 0x1p-500 && ax < 0x1p500 && ay > ax * 0x1p-60 && ay < ax * 0x1p60)) {
        if (isnan(x) || isnan(y)) return x + y;
        general = 0;
        if (ay == 0.0) {
            r = signbit(x) ? PI_HI : 0.0; /* atan2(+-0, -0 or x < 0) = +-pi, atan2(+-0, +0 or x > 0) = +-0 */
        } else if (ax == 0.0 || isinf(ay)) {
            r = isinf(ax) ? (x > 0 ? 0.5 * PIO2_HI : 0x1.2d97c7f3321d2p+1) : PIO2_HI; /* pi/4, 3 pi/4 rounded */
        } else if (isinf(ax)) {
            r = x > 0 ? 0.0 : PI_HI;
        } else if (ay > ax * 0x1p60) {
            r = PIO2_HI; /* pi/2 - x/y, x/y < 2^-60: pi/2 rounded */
        } else if (ay < ax * 0x1p-60) {
            r = x > 0 ? ay / ax : PI_HI; /* atan(q) = q (1 - q^2/3): q rounded; pi - q rounds to pi */
        } else { /* a power of two that brings ax near 1: exact, and ay stays normal */
            int e;
            (void)frexp(ax, &e);
            ax = ldexp(ax, -e);
            ay = ldexp(ay, -e);
            general = 1;
        }
    }
    if (general) {
        double hi, lo;
        atan_yx(ay, ax, &hi, &lo);
        if (x < 0) {
            double s, e;
            dmath_two_sum(PI_HI, -hi, &s, &e);
            r = s + (e + (PI_LO - lo));
        } else {
            r = hi + lo;
        }
    }
    return signbit(y) ? -r : r;
}

/* ------------------------------------------------------------------------------------------------------------
 * hypot
 * ------------------------------------------------------------------------------------------------------------ */

double dggs_hypot(double x, double y) { return dmath_hypot(x, y); }

/* ------------------------------------------------------------------------------------------------------------
 * asin
 * ------------------------------------------------------------------------------------------------------------ */

/* R(t) = (asin(sqrt t) - sqrt t) / sqrt t^3, rational minimax on [0, 1/4] (fdlibm e_asin.c). */
static inline double asin_r(double t) {
    static const double PS0 = 1.66666666666666657415e-01, PS1 = -3.25565818622400915405e-01,
                        PS2 = 2.01212532134862925881e-01, PS3 = -4.00555345006794114027e-02,
                        PS4 = 7.91534994289814532176e-04, PS5 = 3.47933107596021167570e-05,
                        QS1 = -2.40339491173441421878e+00, QS2 = 2.02094576023350569471e+00,
                        QS3 = -6.88283971605453293030e-01, QS4 = 7.70381505559019352791e-02;
    double p = t * (PS0 + t * (PS1 + t * (PS2 + t * (PS3 + t * (PS4 + t * PS5)))));
    double q = 1.0 + t * (QS1 + t * (QS2 + t * (QS3 + t * QS4)));
    return p / q;
}

double dggs_asin(double x) {
    double ax = fabs(x);
    if (!(ax < 1.0)) {
        if (ax == 1.0) return x * PIO2_HI + x * PIO2_LO;
        return (x - x) / (x - x); /* nan, |x| > 1 or nan */
    }
    if (ax < 0.5) return ax < 0x1p-26 ? x : x + x * asin_r(x * x);
    double t = 0.5 * (1.0 - ax); /* exact */
    double s = sqrt(t);
    double r = asin_r(t), res;
    if (ax >= 0.975) {
        res = PIO2_HI - (2.0 * (s + s * r) - PIO2_LO);
    } else { /* s = f + c with f s's first 21 bits (f^2 exact) and c = (t - f^2) / (s + f) */
        double f = with_bits(bits_of(s) & 0xffffffff00000000ull);
        double c = (t - f * f) / (s + f);
        double p = 2.0 * s * r - (PIO2_LO - 2.0 * c);
        double q = 0.5 * PIO2_HI - 2.0 * f;
        res = 0.5 * PIO2_HI - (p - q);
    }
    return signbit(x) ? -res : res;
}
