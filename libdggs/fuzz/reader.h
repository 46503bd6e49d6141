/* The fuzz targets' input reader: bytes taken one at a time (0 once the input is spent), numbers spread over a
 * range from two bytes, now and then the raw double that follows (NaN, infinity, out of range), and REQUIRE,
 * which aborts so libFuzzer (or driver.c) reports the input. Header-only: each target is built on its own. */
#ifndef DGGS_FUZZ_READER_H
#define DGGS_FUZZ_READER_H

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define REQUIRE(cond)         \
    do {                      \
        if (!(cond)) abort(); \
    } while (0)

typedef struct {
    const uint8_t *d;
    size_t n;
} reader;

static inline unsigned take(reader *r) {
    if (!r->n) return 0;
    r->n--;
    return *r->d++;
}

/* A number from lo to hi (two bytes), or, after a byte 255, the raw double that follows. */
static inline double number(reader *r, double lo, double hi) {
    unsigned kind = take(r);
    if (kind == 255 && r->n >= 8) {
        double v;
        memcpy(&v, r->d, 8);
        r->d += 8;
        r->n -= 8;
        return v;
    }
    unsigned v = take(r) | (take(r) << 8);
    return lo + (hi - lo) * (double)v / 65535.0;
}

#endif
