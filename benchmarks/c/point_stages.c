/* Where point location's time goes in the C core (issue 31's profile of a missed target): per point, one thread,
 * the stages of dggs_one_point in turn over the same N uniform points, each stage timed on its own, with a
 * checksum so no stage is optimised away. Built and run by benchmarks/bench_point_stages.py. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "geometry.h"
#include "points.h"
#include "tables.h"

static double now(void) {
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

int main(int argc, char **argv) {
    size_t n = argc > 1 ? (size_t)atol(argv[1]) : 1000000;
    double *lat = malloc(n * sizeof *lat), *lng = malloc(n * sizeof *lng), *p = malloc(3 * n * sizeof *p);
    double *x = malloc(n * sizeof *x), *y = malloc(n * sizeof *y);
    int *face = malloc(n * sizeof *face);
    if (!lat || !lng || !p || !x || !y || !face) return 1;
    uint64_t s = 88172645463325252ULL;
    for (size_t i = 0; i < n; i++) { /* xorshift64: uniform on the sphere */
        s ^= s << 13, s ^= s >> 7, s ^= s << 17;
        double u = (double)(s >> 11) / 9007199254740992.0 * 2.0 - 1.0;
        s ^= s << 13, s ^= s >> 7, s ^= s << 17;
        lat[i] = asin(u) * 57.29577951308232;
        lng[i] = (double)(s >> 11) / 9007199254740992.0 * 360.0 - 180.0;
    }
    double sum = 0.0, t0 = now();
    for (size_t i = 0; i < n; i++) dggs_geodetic_to_unit(lat[i], lng[i], p + 3 * i);
    double t1 = now();
    for (size_t i = 0; i < n; i++) face[i] = dggs_nearest_face(&dggs_isea_centres[0][0], p[3 * i], p[3 * i + 1], p[3 * i + 2]);
    double t2 = now();
    for (size_t i = 0; i < n; i++) dggs_proj_face_forward(DGGS_ISEA, face[i], p[3 * i], p[3 * i + 1], p[3 * i + 2], x + i, y + i);
    double t3 = now();
    printf("{\"points\": %zu, \"geodetic_to_unit\": %.2f, \"nearest_face\": %.2f, \"face_forward\": %.2f", n,
           (t1 - t0) / (double)n * 1e9, (t2 - t1) / (double)n * 1e9, (t3 - t2) / (double)n * 1e9);
    int levels[] = {0, 1, 5, 9, 13, 17, 21, 28};
    for (size_t k = 0; k < sizeof levels / sizeof *levels; k++) {
        double a = now();
        uint64_t acc = 0;
        for (size_t i = 0; i < n; i++) acc ^= dggs_encode_point(face[i], x[i], y[i], levels[k]);
        double b = now();
        uint64_t acc2 = 0;
        for (size_t i = 0; i < n; i++) acc2 ^= dggs_one_point(DGGS_ISEA, lat[i], lng[i], levels[k]);
        double c = now();
        sum += (double)(acc & 1) + (double)(acc2 & 1);
        printf(", \"encode_%d\": %.2f, \"one_point_%d\": %.2f", levels[k], (b - a) / (double)n * 1e9, levels[k],
               (c - b) / (double)n * 1e9);
    }
    for (int lv = 0; lv <= 28; lv += 28) { /* IVEA's forward: hypot, atan2 and asin besides ISEA's sines */
        double a = now();
        uint64_t acc = 0;
        for (size_t i = 0; i < n; i++) acc ^= dggs_one_point(DGGS_IVEA, lat[i], lng[i], lv);
        double b = now();
        sum += (double)(acc & 1);
        printf(", \"one_point_ivea_%d\": %.2f", lv, (b - a) / (double)n * 1e9);
    }
    for (size_t i = 0; i < n; i++) sum += x[i] + y[i] + p[3 * i];
    printf(", \"checksum\": %.6g}\n", sum);
    return 0;
}
