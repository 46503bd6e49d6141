/* The core's own sin, cos, atan2, hypot and asin (libdggs/src/dmath.c) against the platform's libm, alone: CPU ns
 * a call over N arguments in the ranges point location gives them (radians of latitudes and longitudes, unit
 * vector components, IVEA's asin argument), one thread, each loop summed so nothing is optimised away, libm and
 * dmath alternating over R rounds (the fastest round kept). Built and run by benchmarks/bench_dmath.py. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "dmath.h"

static double now(void) {
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static uint64_t state = 88172645463325252ULL;
static double uniform(double a, double b) { /* xorshift64 */
    state ^= state << 13, state ^= state >> 7, state ^= state << 17;
    return a + (b - a) * ((double)(state >> 11) / 9007199254740992.0);
}

typedef double (*f1)(double);
typedef double (*f2)(double, double);

/* volatile function pointers: neither loop is specialised (gcc would fold a libm sin and cos into sincos) */
static double time1(f1 volatile f, const double *x, size_t n, double *sum) {
    f1 g = f;
    double s = 0.0, t0 = now();
    for (size_t i = 0; i < n; i++) s += g(x[i]);
    double t = now() - t0;
    *sum += s;
    return t / (double)n * 1e9;
}

static double time2(f2 volatile f, const double *x, const double *y, size_t n, double *sum) {
    f2 g = f;
    double s = 0.0, t0 = now();
    for (size_t i = 0; i < n; i++) s += g(x[i], y[i]);
    double t = now() - t0;
    *sum += s;
    return t / (double)n * 1e9;
}

static double best(double a, double b) { return a < b ? a : b; }

int main(int argc, char **argv) {
    size_t n = argc > 1 ? (size_t)atol(argv[1]) : 1000000;
    int rounds = argc > 2 ? atoi(argv[2]) : 5;
    double *ang = malloc(n * sizeof *ang), *ux = malloc(n * sizeof *ux), *uy = malloc(n * sizeof *uy);
    double *as = malloc(n * sizeof *as);
    if (!ang || !ux || !uy || !as) return 1;
    for (size_t i = 0; i < n; i++) {
        ang[i] = uniform(-3.141592653589793, 3.141592653589793);
        ux[i] = uniform(-1.0, 1.0);
        uy[i] = uniform(-1.0, 1.0);
        as[i] = uniform(0.0, 0.8);
    }
    const char *names[5] = {"sin", "cos", "atan2", "hypot", "asin"};
    double libm[5], own[5], sum = 0.0;
    for (int k = 0; k < 5; k++) libm[k] = own[k] = INFINITY;
    for (int r = 0; r < rounds; r++) {
        libm[0] = best(libm[0], time1(sin, ang, n, &sum));
        own[0] = best(own[0], time1(dggs_sin, ang, n, &sum));
        libm[1] = best(libm[1], time1(cos, ang, n, &sum));
        own[1] = best(own[1], time1(dggs_cos, ang, n, &sum));
        libm[2] = best(libm[2], time2(atan2, ux, uy, n, &sum));
        own[2] = best(own[2], time2(dggs_atan2, ux, uy, n, &sum));
        libm[3] = best(libm[3], time2(hypot, ux, uy, n, &sum));
        own[3] = best(own[3], time2(dggs_hypot, ux, uy, n, &sum));
        libm[4] = best(libm[4], time1(asin, as, n, &sum));
        own[4] = best(own[4], time1(dggs_asin, as, n, &sum));
    }
    printf("{\"points\": %zu", n);
    for (int k = 0; k < 5; k++) printf(", \"libm_%s\": %.2f, \"dmath_%s\": %.2f", names[k], libm[k], names[k], own[k]);
    printf(", \"checksum\": %.6g}\n", sum);
    return 0;
}
