/* The native half of js/tools/libm/ties.py: dggs_latlng_to_cell on points (stdin: "lat lng" lines) on both
 * projections at levels 0-28, recording every call the core makes to glibc's libm (linked with -Wl,--wrap=NAME
 * for each function below) as (function, point, projection, level, x, y, result) to trace.bin, and the cells to
 * cells.txt ("point projection level id" lines). sincos, which gcc makes of a sin and a cos of one argument, is
 * recorded as the two calls. */
#include <stdint.h>
#include <stdio.h>

#include "dggs.h"

enum { F_SIN, F_COS, F_ASIN, F_ATAN2, F_HYPOT, F_POW, F_ACOS, F_ATAN, F_TAN };

static FILE *trace;
static int32_t now[3]; /* point, projection, level */

static void record(int32_t fn, double x, double y, double r) {
    struct {
        int32_t fn, point, proj, level;
        double x, y, r;
    } e = {fn, now[0], now[1], now[2], x, y, r};
    fwrite(&e, sizeof e, 1, trace);
}

double __real_sin(double);
double __real_cos(double);
double __real_asin(double);
double __real_atan2(double, double);
double __real_hypot(double, double);
double __real_pow(double, double);
double __real_acos(double);
double __real_atan(double);
double __real_tan(double);
void __real_sincos(double, double *, double *);
double __wrap_sin(double x);
double __wrap_cos(double x);
double __wrap_asin(double x);
double __wrap_atan2(double y, double x);
double __wrap_hypot(double x, double y);
double __wrap_pow(double x, double y);
double __wrap_acos(double x);
double __wrap_atan(double x);
double __wrap_tan(double x);
void __wrap_sincos(double x, double *s, double *c);

double __wrap_sin(double x) { double r = __real_sin(x); record(F_SIN, x, 0.0, r); return r; }
double __wrap_cos(double x) { double r = __real_cos(x); record(F_COS, x, 0.0, r); return r; }
double __wrap_asin(double x) { double r = __real_asin(x); record(F_ASIN, x, 0.0, r); return r; }
double __wrap_atan2(double y, double x) { double r = __real_atan2(y, x); record(F_ATAN2, y, x, r); return r; }
double __wrap_hypot(double x, double y) { double r = __real_hypot(x, y); record(F_HYPOT, x, y, r); return r; }
double __wrap_pow(double x, double y) { double r = __real_pow(x, y); record(F_POW, x, y, r); return r; }
double __wrap_acos(double x) { double r = __real_acos(x); record(F_ACOS, x, 0.0, r); return r; }
double __wrap_atan(double x) { double r = __real_atan(x); record(F_ATAN, x, 0.0, r); return r; }
double __wrap_tan(double x) { double r = __real_tan(x); record(F_TAN, x, 0.0, r); return r; }
void __wrap_sincos(double x, double *s, double *c) {
    __real_sincos(x, s, c);
    record(F_SIN, x, 0.0, *s);
    record(F_COS, x, 0.0, *c);
}

int main(int argc, char **argv) {
    if (argc != 3) {
        fprintf(stderr, "usage: %s TRACE_BIN CELLS_TXT < points\n", argv[0]);
        return 2;
    }
    trace = fopen(argv[1], "wb");
    FILE *cells = fopen(argv[2], "w");
    if (!trace || !cells) return 1;
    double lat, lng;
    for (int32_t i = 0; scanf("%lf %lf", &lat, &lng) == 2; i++) {
        for (int32_t proj = 0; proj < 2; proj++) {
            for (int32_t level = 0; level <= 28; level++) {
                dggs_cell cell = 0;
                now[0] = i;
                now[1] = proj;
                now[2] = level;
                if (dggs_latlng_to_cell(lat, lng, level, (dggs_projection)proj, &cell) != DGGS_OK) return 1;
                fprintf(cells, "%d %d %d %llu\n", i, proj, level, (unsigned long long)cell);
            }
        }
    }
    return fclose(trace) | fclose(cells);
}
