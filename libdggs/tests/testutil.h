/* Helpers shared by the C tests: string ids written out by the layout (bits.h), and a seeded PRNG. */
#ifndef DGGS_TESTS_TESTUTIL_H
#define DGGS_TESTS_TESTUTIL_H

#include <stdint.h>

#include "bits.h"

/* The id of a well-formed string id ("C401"), by the layout of docs/grid.md (no parser of the core's). */
static inline uint64_t sid(const char *s) {
    uint64_t c = dggs_base_cell(s[0] - 'A');
    if (!s[1]) return c;
    c |= (uint64_t)(s[1] - '0' + 1) << DGGS_L1_SHIFT;
    for (int k = 2; s[k]; k++) c |= (uint64_t)(s[k] - '0' + 1) << (2 * (DGGS_MAX_LEVEL - k));
    return c;
}

/* splitmix64 on a caller's state: a deterministic pseudo-random stream. */
static inline uint64_t splitmix64(uint64_t *state) {
    uint64_t z = (*state += UINT64_C(0x9e3779b97f4a7c15));
    z = (z ^ (z >> 30)) * UINT64_C(0xbf58476d1ce4e5b9);
    z = (z ^ (z >> 27)) * UINT64_C(0x94d049bb133111eb);
    return z ^ (z >> 31);
}

#endif
