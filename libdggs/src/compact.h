/* Compaction over arrays of 64-bit ids: compact and uncompact cell sets (a port of index/_kernel/compact.py,
 * operation for operation). Same conventions as hierarchy.h: valid ids in, `bad` for a violated level relation.
 * Compaction is one stack pass after a sort; uncompaction writes id ranges in order, with no re-sort.
 *
 * Where compact.py allocates, the caller passes buffers: `out` of n ids (the sorted copy, compacted in place)
 * and `scratch` of dggs_sort_scratch_size(n) ids (the radix sort's second buffer and histograms). */
#ifndef DGGS_COMPACT_H
#define DGGS_COMPACT_H

#include <stdint.h>

/* Radix sort: bits per pass, and the smallest input it is used for (compact.py _RADIX_BITS, _RADIX_MIN; smaller
 * inputs are heap-sorted in place, as compact.py np.sorts them: a sort of integers has one result). */
#define DGGS_RADIX_BITS 12
#define DGGS_RADIX_MIN 4096
/* The largest histogram of dggs_radix_sort: n_pass * 2^width over every span of differing bits (5 * 4096). */
#define DGGS_RADIX_HIST 20480

/* Entries of the scratch buffer dggs_sorted, dggs_compact and dggs_uncompact_prepare need for n ids
 * (n + DGGS_RADIX_HIST from DGGS_RADIX_MIN ids on, else 0: NULL will do). */
int64_t dggs_sort_scratch_size(int64_t n);

/* compact.py _radix_sort: the sorted copy of a[n] into out[n] (LSD radix sort over the bits that differ between
 * keys, in passes of <= 12 bits); scratch holds n + DGGS_RADIX_HIST entries. Any uint64 keys. */
void dggs_radix_sort(const uint64_t *a, int64_t n, uint64_t *out, uint64_t *scratch);
/* compact.py _sorted: out[n] = ids if already non-decreasing, else their sorted copy. */
void dggs_sorted(const uint64_t *ids, int64_t n, uint64_t *out, uint64_t *scratch);

/* compact.py compact: the fewest cells covering the same area as ids[n] (valid ids, any order, any levels,
 * duplicates allowed), sorted, into out (n entries; ids and out must not overlap). Returns their number. */
int64_t dggs_compact(const uint64_t *ids, int64_t n, uint64_t *out, uint64_t *scratch);

/* compact.py uncompact_prepare: the sorted, non-overlapping cover of ids[n] into cells (n entries; *n_cells of
 * them written) and its size at `level` in *total (saturated at 2^63 - 1), for dggs_children, which then writes
 * the uncompacted cells in id order. Returns bad: -1, or the position in ids of the first cell finer than `level`
 * (then *n_cells and *total are 0). */
int64_t dggs_uncompact_prepare(const uint64_t *ids, int64_t n, int level, uint64_t *cells, uint64_t *scratch,
                               int64_t *n_cells, int64_t *total);

#endif
