/* The C tests' assertions: each failed check prints where and what, and the test exits non-zero. */
#ifndef DGGS_TESTS_CHECK_H
#define DGGS_TESTS_CHECK_H

#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int check_failures = 0;

#define CHECK(cond)                                                                  \
    do {                                                                             \
        if (!(cond)) {                                                               \
            fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #cond); \
            check_failures++;                                                        \
        }                                                                            \
    } while (0)

#define CHECK_EQ_U64(a, b)                                                                            \
    do {                                                                                              \
        uint64_t check_a_ = (uint64_t)(a), check_b_ = (uint64_t)(b);                                 \
        if (check_a_ != check_b_) {                                                                   \
            fprintf(stderr, "%s:%d: %s == %s failed: 0x%016" PRIx64 " != 0x%016" PRIx64 "\n", __FILE__, \
                    __LINE__, #a, #b, check_a_, check_b_);                                            \
            check_failures++;                                                                         \
        }                                                                                             \
    } while (0)

/* Bitwise equality of doubles (the core must equal the reference bit for bit, NaN included). */
#define CHECK_SAME_DOUBLE(a, b)                                                                          \
    do {                                                                                                 \
        double check_a_ = (a), check_b_ = (b);                                                           \
        if (memcmp(&check_a_, &check_b_, sizeof(double)) != 0) {                                          \
            fprintf(stderr, "%s:%d: %s == %s failed: %.17g != %.17g\n", __FILE__, __LINE__, #a, #b, check_a_, \
                    check_b_);                                                                           \
            check_failures++;                                                                            \
        }                                                                                                \
    } while (0)

/* Equal to the reference but for the last bits: |a - b| <= 1e-12 |b| + 1e-15 (NaN equals NaN). For values the
 * numba kernel computed with glibc's sin, cos, atan2, hypot and asin, which the core now carries itself
 * (src/dmath.c, issue 34): both are within an ulp of the exact functions and round differently, so results move
 * in their last bits (by more where a difference cancels), never by 1e-12 of their size. */
#define CHECK_NEAR_DOUBLE(a, b)                                                                            \
    do {                                                                                                   \
        double check_a_ = (a), check_b_ = (b);                                                             \
        if (!(check_a_ == check_b_ || (check_a_ != check_a_ && check_b_ != check_b_) ||                    \
              fabs(check_a_ - check_b_) <= 1e-12 * fabs(check_b_) + 1e-15)) {                              \
            fprintf(stderr, "%s:%d: %s ~= %s failed: %.17g != %.17g\n", __FILE__, __LINE__, #a, #b, check_a_, \
                    check_b_);                                                                             \
            check_failures++;                                                                              \
        }                                                                                                  \
    } while (0)

/* |a - b| <= tol, for results that magnify the last bits: lengths in metres from two nearby points, a cell's
 * position inside its level-28 cell, the sagitta of a short chord (NaN equals NaN). */
#define CHECK_WITHIN(a, b, tol)                                                                               \
    do {                                                                                                      \
        double check_a_ = (a), check_b_ = (b);                                                                \
        if (!(fabs(check_a_ - check_b_) <= (tol) || (check_a_ != check_a_ && check_b_ != check_b_))) {       \
            fprintf(stderr, "%s:%d: |%s - %s| <= %s failed: %.17g != %.17g\n", __FILE__, __LINE__, #a, #b, #tol, \
                    check_a_, check_b_);                                                                      \
            check_failures++;                                                                                 \
        }                                                                                                     \
    } while (0)

#define CHECK_DONE()                                                       \
    do {                                                                   \
        if (check_failures) fprintf(stderr, "%d checks failed\n", check_failures); \
        return check_failures ? EXIT_FAILURE : EXIT_SUCCESS;               \
    } while (0)

#endif
