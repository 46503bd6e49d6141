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

/* The pixels' valid flags from `bytes` bytes of input (at most 4): pixel i is left out where bit i % (8 * bytes) is
 * set. */
static inline void valid_mask(reader *r, uint8_t *valid, int64_t n, int bytes) {
    unsigned mask = 0;
    for (int b = 0; b < bytes; b++) mask |= take(r) << (8 * b);
    for (int64_t i = 0; i < n; i++) valid[i] = (mask >> (unsigned)(i % (8 * bytes))) & 1 ? 0 : 1;
}

/* The scratch buffer of `words` doubles a raster cut asks for (its *_work_words). */
static inline double *work_buffer(int64_t words) {
    REQUIRE(words > 0);
    double *work = malloc((size_t)words * sizeof *work);
    REQUIRE(work != NULL);
    return work;
}

#endif
