/* Compaction over arrays of 64-bit ids. A port of index/_kernel/compact.py, operation for operation (see
 * compact.h for the buffers that replace its allocations). */
#include "compact.h"

#include <stdbool.h>
#include <string.h>

#include "bits.h"
#include "hierarchy.h"

#define U1 ((uint64_t)1)

int64_t dggs_sort_scratch_size(int64_t n) { return n >= DGGS_RADIX_MIN ? n + DGGS_RADIX_HIST : 0; }

/* compact.py _radix_sort. Only the bits that differ between keys are sorted (ids share the marker, and ids of one
 * level share their empty low fields), in passes of <= 12 bits. The passes alternate between out and scratch,
 * starting from the one that leaves the result in out. */
void dggs_radix_sort(const uint64_t *a, int64_t n, uint64_t *out, uint64_t *scratch) {
    uint64_t all_and = ~(uint64_t)0;
    uint64_t any_or = 0;
    for (int64_t i = 0; i < n; i++) {
        all_and &= a[i];
        any_or |= a[i];
    }
    uint64_t diff = all_and ^ any_or;
    if (diff == 0) {
        if (n > 0) memmove(out, a, (size_t)n * sizeof(uint64_t));
        return;
    }
    int low = 0;
    while (((diff >> low) & U1) == 0) low += 1;
    int high = 63;
    while (((diff >> high) & U1) == 0) high -= 1;
    int n_pass = (high - low + DGGS_RADIX_BITS) / DGGS_RADIX_BITS;
    int width = (high - low + n_pass) / n_pass; /* ceil(span / n_pass) */
    uint64_t mask = (U1 << width) - U1;
    uint64_t *hist = scratch + n; /* n_pass rows of 2^width counts, at most DGGS_RADIX_HIST */
    int64_t row = (int64_t)1 << width;
    memset(hist, 0, (size_t)(n_pass * row) * sizeof(uint64_t));
    for (int64_t i = 0; i < n; i++) {
        uint64_t x = a[i] >> low;
        for (int p = 0; p < n_pass; p++) hist[p * row + (int64_t)((x >> (width * p)) & mask)] += 1;
    }
    uint64_t *src = (n_pass % 2 == 0) ? out : scratch; /* after n_pass swaps, src is out */
    uint64_t *dst = (n_pass % 2 == 0) ? scratch : out;
    memmove(src, a, (size_t)n * sizeof(uint64_t));
    for (int p = 0; p < n_pass; p++) {
        uint64_t *off = hist + p * row;
        uint64_t total = 0;
        for (int64_t b = 0; b < row; b++) { /* counts -> start offsets */
            uint64_t c = off[b];
            off[b] = total;
            total += c;
        }
        int sh = low + width * p;
        for (int64_t i = 0; i < n; i++) {
            uint64_t b = (src[i] >> sh) & mask;
            dst[off[b]] = src[i];
            off[b] += 1;
        }
        uint64_t *t = src;
        src = dst;
        dst = t;
    }
}

/* Heap sort in place: compact.py np.sorts fewer than DGGS_RADIX_MIN ids (numpy's introsort); the sorted order of
 * integers is unique, so any sort gives its result. */
static void heap_sort(uint64_t *a, int64_t n) {
    for (int64_t start = n / 2 - 1, end = n;; ) {
        int64_t root;
        if (start >= 0) {
            root = start--;
        } else {
            if (--end <= 0) return;
            uint64_t t = a[0];
            a[0] = a[end];
            a[end] = t;
            root = 0;
        }
        for (;;) { /* sift a[root] down within a[0 .. end) */
            int64_t child = 2 * root + 1;
            if (child >= end) break;
            if (child + 1 < end && a[child + 1] > a[child]) child++;
            if (a[root] >= a[child]) break;
            uint64_t t = a[root];
            a[root] = a[child];
            a[child] = t;
            root = child;
        }
    }
}

/* compact.py _sorted. */
void dggs_sorted(const uint64_t *ids, int64_t n, uint64_t *out, uint64_t *scratch) {
    for (int64_t i = 1; i < n; i++) {
        if (ids[i] < ids[i - 1]) {
            if (n < DGGS_RADIX_MIN) {
                memmove(out, ids, (size_t)n * sizeof(uint64_t));
                heap_sort(out, n);
            } else {
                dggs_radix_sort(ids, n, out, scratch);
            }
            return;
        }
    }
    if (n > 0) memmove(out, ids, (size_t)n * sizeof(uint64_t));
}

/* compact.py compact: sorts, then one linear pass: a cell inside the last kept cell's range (a duplicate or a
 * descendant of a kept cell) is dropped; a kept cell is pushed on a stack, and while the top of the stack is a
 * complete sibling set (6 under a base cell, 3 elsewhere; siblings are adjacent in id order) it is replaced by
 * the parent, which may complete its own set. The stack is `out` itself: it never reaches past the sorted entry
 * being read. */
int64_t dggs_compact(const uint64_t *ids, int64_t n, uint64_t *out, uint64_t *scratch) {
    dggs_sorted(ids, n, out, scratch);
    const uint64_t *s = out;
    uint64_t *stack = out;
    int64_t top = 0;
    uint64_t end = 0; /* one past the last kept cell's descendants */
    for (int64_t i = 0; i < n; i++) {
        uint64_t cell = s[i];
        if (cell < end) continue;
        int lv = dggs_level_of(cell);
        end = dggs_range_end(cell, lv);
        stack[top] = cell;
        top += 1;
        while (lv > 0) {
            int k = lv == 1 ? 6 : 3;
            unsigned sh = dggs_shift_of(lv);
            uint64_t parent = dggs_parent_at(cell, lv - 1);
            /* `cell` must be the last sibling and the k entries below it the earlier ones */
            if (top < k || cell != (parent | ((uint64_t)k << sh))) break;
            int complete = 1;
            for (int j = 0; j < k - 1; j++) {
                if (stack[top - k + j] != (parent | ((uint64_t)(j + 1) << sh))) {
                    complete = 0;
                    break;
                }
            }
            if (!complete) break;
            top -= k;
            stack[top] = parent;
            top += 1;
            cell = parent;
            lv -= 1;
        }
    }
    return top;
}

/* compact.py uncompact_prepare: sorts ids (unless already sorted) and drops every cell inside the range of the
 * previous kept one (duplicates, descendants of a kept cell), in place in `cells`. */
int64_t dggs_uncompact_prepare(const uint64_t *ids, int64_t n, int level, uint64_t *cells, uint64_t *scratch,
                               int64_t *n_cells, int64_t *total) {
    for (int64_t i = 0; i < n; i++) {
        if (dggs_finer_than(ids[i], level)) {
            *n_cells = 0;
            *total = 0;
            return i;
        }
    }
    dggs_sorted(ids, n, cells, scratch);
    int64_t m = 0;
    int64_t t = 0;
    uint64_t end = 0;
    for (int64_t i = 0; i < n; i++) {
        uint64_t cell = cells[i];
        if (cell < end) continue;
        int lv = dggs_level_of(cell);
        end = dggs_range_end(cell, lv);
        cells[m] = cell;
        m += 1;
        int64_t c = dggs_n_desc(lv, level);
        t = t > INT64_MAX - c ? INT64_MAX : t + c;
    }
    *n_cells = m;
    *total = t;
    return -1;
}

/* ---- public API (dggs.h, "hierarchy"): the ids validated, the buffers checked, then the kernels ---- */

static bool all_valid(const dggs_cell *cells, int64_t n) {
    for (int64_t i = 0; i < n; i++)
        if (!dggs_is_valid(cells[i])) return false;
    return true;
}

dggs_error dggs_compact_cells_size(int64_t num_cells, int64_t *size) {
    if (num_cells < 0) return DGGS_E_DOMAIN;
    *size = num_cells + dggs_sort_scratch_size(num_cells);
    return DGGS_OK;
}

dggs_error dggs_compact_cells(const dggs_cell *cells, int64_t num_cells, dggs_cell *out, int64_t out_size,
                              int64_t *num_out) {
    int64_t need;
    dggs_error err = dggs_compact_cells_size(num_cells, &need);
    if (err != DGGS_OK) return err;
    if (!all_valid(cells, num_cells)) return DGGS_E_CELL;
    if (out_size < need) return DGGS_E_BUFFER;
    *num_out = dggs_compact(cells, num_cells, out, out + num_cells);
    return DGGS_OK;
}

dggs_error dggs_uncompact_cells_size(const dggs_cell *cells, int64_t num_cells, int level, int64_t *size) {
    if (num_cells < 0) return DGGS_E_DOMAIN;
    if (!all_valid(cells, num_cells)) return DGGS_E_CELL;
    if (level < 0 || level > DGGS_MAX_LEVEL) return DGGS_E_LEVEL;
    int64_t total;
    if (dggs_count_children(cells, num_cells, level, &total) >= 0) return DGGS_E_LEVEL_MISMATCH;
    int64_t scratch = num_cells + dggs_sort_scratch_size(num_cells);
    *size = total > scratch ? total : scratch;
    return DGGS_OK;
}

/* compact.py uncompact: uncompact_prepare into `out` (the sorted cover in front, the sort's scratch after it),
 * the cover moved to the end of `out`, then children written from the front. Block k ends at or before the
 * cover's entry k (every later cover cell has at least one descendant), which dggs_children reads first. */
dggs_error dggs_uncompact_cells(const dggs_cell *cells, int64_t num_cells, int level, dggs_cell *out,
                                int64_t out_size, int64_t *num_out) {
    int64_t need;
    dggs_error err = dggs_uncompact_cells_size(cells, num_cells, level, &need);
    if (err != DGGS_OK) return err;
    if (out_size < need) return DGGS_E_BUFFER;
    int64_t m, total;
    dggs_uncompact_prepare(cells, num_cells, level, out, out + num_cells, &m, &total);
    uint64_t *cover = out + (out_size - m);
    if (m > 0) memmove(cover, out, (size_t)m * sizeof(uint64_t));
    int64_t bad;
    err = dggs_children(cover, m, level, out, out_size, &bad);
    if (err != DGGS_OK) return err;
    *num_out = total;
    return DGGS_OK;
}
