/* Helpers shared by the grid part's C tests: a small PRNG, random valid ids, random walks. */
#ifndef DGGS_TESTS_GRID_TESTUTIL_H
#define DGGS_TESTS_GRID_TESTUTIL_H

#include <stdint.h>

#include "bits.h"
#include "grid.h"
#include "testutil.h"

/* splitmix64 on a caller's state (testutil.h). */
static inline uint64_t gt_next(uint64_t *state) { return splitmix64(state); }

static inline int gt_below(uint64_t *state, int n) { return (int)(gt_next(state) % (uint64_t)n); }

/* A uniformly random valid id at `level`. */
static inline uint64_t gt_random_id(uint64_t *state, int level) {
    uint64_t id = dggs_base_cell(gt_below(state, 20));
    if (level >= 1) id |= (uint64_t)(gt_below(state, 6) + 1) << 54;
    for (int lv = 2; lv <= level; lv++) id |= (uint64_t)(gt_below(state, 3) + 1) << dggs_shift_of(lv);
    return id;
}

/* The end of a random walk of `steps` edge steps from `cell`. */
static inline uint64_t gt_walk(uint64_t *state, uint64_t cell, int steps) {
    int level = dggs_level_of(cell);
    for (int s = 0; s < steps; s++) cell = dggs_neighbour(cell, level, gt_below(state, 3));
    return cell;
}

#endif
