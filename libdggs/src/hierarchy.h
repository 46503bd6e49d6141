/* Hierarchy kernels over arrays of 64-bit ids: levels, parents, children (a port of index/_kernel/hierarchy.py,
 * operation for operation).
 *
 * Every kernel takes VALID ids (the caller validates, e.g. with dggs_valid_mask) and levels already range-checked
 * to 0..DGGS_MAX_LEVEL. The layout is bits.h's: a field of 0 means "no digit", so the descendants of c at level l
 * are the ints [c, c + 2^shift_of(l)) and int order is the depth-first string order.
 *
 * Error convention (hierarchy.py's): a kernel that can meet a violated level relation gives `bad`: -1 when every
 * cell is fine, else the position in the INPUT array of the first offending cell (the outputs are then
 * meaningless). Violations: a cell finer than the requested level (dggs_parents below it, dggs_count_children,
 * dggs_children) and a base cell passed to dggs_parents_up. Counts are exact int64 and saturate at 2^63 - 1. */
#ifndef DGGS_HIERARCHY_H
#define DGGS_HIERARCHY_H

#include <stdbool.h>
#include <stdint.h>

#include "bits.h"
#include "dggs.h"

/* Levels enumerated by the precomputed offset table of dggs_children (hierarchy.py _TABLE_LEVELS), and the
 * table's size, 3^6. */
#define DGGS_TABLE_LEVELS 6
#define DGGS_OFFSET_TABLE_SIZE 729

/* 3^k for k = 0..28 (hierarchy.py _POW3; 3^28 < 2^45, exact in int64). */
static inline int64_t dggs_pow3(int k) {
    static const int64_t pow3[29] = {
        1, 3, 9, 27, 81, 243, 729, 2187, 6561, 19683, 59049, 177147, 531441, 1594323, 4782969, 14348907, 43046721,
        129140163, 387420489, 1162261467, INT64_C(3486784401), INT64_C(10460353203), INT64_C(31381059609),
        INT64_C(94143178827), INT64_C(282429536481), INT64_C(847288609443), INT64_C(2541865828329),
        INT64_C(7625597484987), INT64_C(22876792454961)};
    return pow3[k];
}

/* hierarchy.py n_desc: descendants at `level` of one cell at `cell_level` <= `level` (6 children under a base
 * cell). Inline, as numba's inline="always". */
static inline int64_t dggs_n_desc(int cell_level, int level) {
    if (cell_level == level) return 1;
    if (cell_level == 0) return 6 * dggs_pow3(level - 1);
    return dggs_pow3(level - cell_level);
}

/* hierarchy.py finer_than: whether `cell` is finer than `level` (some field below level `level`'s is filled). */
static inline bool dggs_finer_than(uint64_t cell, int level) {
    return (cell & (((uint64_t)1 << dggs_shift_of(level)) - 1)) != 0;
}

/* hierarchy.py _offset_table: the offsets of the descendants at `level` under a cell m levels up, for every
 * m <= min(DGGS_TABLE_LEVELS, level - 1): entry n spreads the base-3 digits of n into consecutive 2-bit fields
 * ending at level `level`. Writes 3^m entries (at most DGGS_OFFSET_TABLE_SIZE) and returns that count. */
int64_t dggs_offset_table(int level, uint64_t table[DGGS_OFFSET_TABLE_SIZE]);

/* hierarchy.py levels: the level of every (valid) id. */
void dggs_levels(const uint64_t *ids, int64_t n, uint8_t *out);
/* hierarchy.py valid_mask: whether each integer (any uint64) is a well-formed id, 1 or 0; never fails. */
void dggs_valid_mask(const uint64_t *ids, int64_t n, uint8_t *out);
/* hierarchy.py level_bounds: (*lo, *hi) the lowest and highest level among ids; (-1, -1) when n is 0. */
void dggs_level_bounds(const uint64_t *ids, int64_t n, int *lo, int *hi);
/* hierarchy.py parents: ancestor of every id at `level` into out[n]. Returns bad: -1, or the position of the
 * first cell coarser than `level` (out then holds nothing). */
int64_t dggs_parents(const uint64_t *ids, int64_t n, int level, uint64_t *out);
/* hierarchy.py parents_up: parent of every id, one level up each, into out[n]. Returns bad: -1, or the position
 * of the first base cell (the entries before it are written). */
int64_t dggs_parents_up(const uint64_t *ids, int64_t n, uint64_t *out);
/* hierarchy.py count_children: *total = exact number of descendants at `level` over all ids (saturated at
 * 2^63 - 1). Returns bad: -1, or the position of the first cell finer than `level` (*total is then 0). */
int64_t dggs_count_children(const uint64_t *ids, int64_t n, int level, int64_t *total);
/* hierarchy.py children: the descendants at `level` of every id into out (out_size entries, at least
 * dggs_count_children's total; entries past the total are untouched). Each cell's block is contiguous and in id
 * order; blocks follow the input order. *bad = -1, or the position of the first cell finer than `level` (the
 * blocks before it are written). Returns DGGS_OK, DGGS_E_LEVEL_MISMATCH (*bad >= 0) or DGGS_E_BUFFER when
 * out_size is too short (hierarchy.py's ValueError; *bad is the cell whose block did not fit). */
dggs_error dggs_children(const uint64_t *ids, int64_t n, int level, uint64_t *out, int64_t out_size, int64_t *bad);
/* hierarchy.py parent_of: ancestor of one id (as an int64) at `level` (-1: one level up); 0 where there is none
 * or `cell` is no id. */
int64_t dggs_parent_of(int64_t cell, int level);

#endif
