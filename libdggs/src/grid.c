/* The grid as a graph over 64-bit ids: edge neighbours, disks, rings (a port of index/_kernel/grid.py,
 * operation for operation, so ids, counts and orders equal the numba kernel's). See grid.h. */
#include "grid.h"

#include <string.h>

#include "bits.h"
#include "dggs.h"
#include "grid_tables.h"

/* ---------------------------------------------------------------------------------------------------------
 * Edge neighbours: the digit walk on bits
 * --------------------------------------------------------------------------------------------------------- */

/* _across: the cell across the edge of `label` (a = 0, b = 1, c = 2) of a cell at `level` >= 1. */
uint64_t dggs_across(uint64_t cell, int level, int label) {
    int edge = label;
    int lv = level;
    while (lv >= 4) { /* three levels per lookup while the block stays below level 2 */
        unsigned s = (unsigned)(2 * (DGGS_MAX_LEVEL - lv));
        int r = DGGS_GRID_BLOCK[edge][(cell >> s) & 63u];
        if (r >= 64) return (cell & ~((uint64_t)63 << s)) | ((uint64_t)(r - 64) << s);
        edge = r;
        lv -= 3;
    }
    for (int pos = lv; pos > 1; pos--) { /* then one level at a time */
        unsigned s = (unsigned)(2 * (DGGS_MAX_LEVEL - pos));
        int step = DGGS_GRID_STEP[(int)((cell >> s) & 3u) - 1][edge];
        if (step < 3) /* a sibling shares the edge: replace this digit, keep the later ones */
            return (cell & ~((uint64_t)3 << s)) | ((uint64_t)(step + 1) << s);
        edge = step - 3; /* the edge lies on the parent's edge of this label */
    }
    int face = (int)((cell >> 57) & 31u);
    int d1 = (int)((cell >> 54) & 7u) - 1;
    int nf = DGGS_GRID_L1_TABLE[face][d1][edge][0];
    int nd = DGGS_GRID_L1_TABLE[face][d1][edge][1];
    return (cell & DGGS_LOW54) | DGGS_MARKER | ((uint64_t)nf << 57) | ((uint64_t)(nd + 1) << 54);
}

static inline unsigned grid_popcount64(uint64_t x) {
#if defined(__GNUC__) || defined(__clang__)
    return (unsigned)__builtin_popcountll(x);
#else
    unsigned n = 0;
    while (x) {
        x &= x - 1;
        n++;
    }
    return n;
#endif
}

/* _is_ccw: level-1 orientation XOR the parity of digits 0 and 2 (codes 1 and 3: the mirror children). */
int dggs_is_ccw(uint64_t cell) {
    int d1 = (int)((cell >> 54) & 7u) - 1;
    return (int)(DGGS_GRID_L1_CCW[d1] ^ (grid_popcount64(cell & DGGS_DIGIT_LOW_BITS) & 1u));
}

/* _neighbour: column `col` of the cell's neighbours (corner col to col + 1). */
uint64_t dggs_neighbour(uint64_t cell, int level, int col) {
    if (level == 0) {
        int face = (int)((cell >> 57) & 31u);
        return DGGS_MARKER | ((uint64_t)DGGS_GRID_BASE_ADJ[face][col] << 57);
    }
    return dggs_across(cell, level, DGGS_GRID_COLUMN_LABEL[dggs_is_ccw(cell)][col]);
}

/* neighbours, one row. */
void dggs_neighbours(uint64_t cell, uint64_t out[3]) {
    int level = dggs_level_of(cell);
    if (level == 0) {
        for (int j = 0; j < 3; j++) out[j] = dggs_neighbour(cell, 0, j);
    } else {
        int ccw = dggs_is_ccw(cell);
        for (int j = 0; j < 3; j++) out[j] = dggs_across(cell, level, DGGS_GRID_COLUMN_LABEL[ccw][j]);
    }
}

/* are_neighbours, one pair. */
bool dggs_are_neighbours(uint64_t a, uint64_t b) {
    int level = dggs_level_of(a);
    bool hit = false;
    if (level == dggs_level_of(b)) {
        for (int j = 0; j < 3; j++) {
            if (dggs_neighbour(a, level, j) == b) hit = true;
        }
    }
    return hit;
}

/* ---------------------------------------------------------------------------------------------------------
 * Disks and rings
 * --------------------------------------------------------------------------------------------------------- */

static void grid_sift_down(uint64_t *a, int64_t root, int64_t n) {
    for (;;) {
        int64_t child = 2 * root + 1;
        if (child >= n) return;
        if (child + 1 < n && a[child] < a[child + 1]) child++;
        if (!(a[root] < a[child])) return;
        uint64_t t = a[root];
        a[root] = a[child];
        a[child] = t;
        root = child;
    }
}

/* _sort_small: insertion sort for short runs; past 48 numba calls np.sort (a quicksort). Integers sorted
 * ascending are one sequence whatever the algorithm, so an in-place heap sort gives np.sort's result without
 * recursion or allocation. */
void dggs_sort_small(uint64_t *a, int64_t n) {
    if (n > 48) {
        for (int64_t i = n / 2 - 1; i >= 0; i--) grid_sift_down(a, i, n);
        for (int64_t end = n - 1; end > 0; end--) {
            uint64_t t = a[0];
            a[0] = a[end];
            a[end] = t;
            grid_sift_down(a, 0, end);
        }
        return;
    }
    for (int64_t i = 1; i < n; i++) {
        uint64_t x = a[i];
        int64_t j = i - 1;
        while (j >= 0 && a[j] > x) {
            a[j + 1] = a[j];
            j--;
        }
        a[j + 1] = x;
    }
}

/* next_ring: in a graph the neighbours of ring j lie in rings j - 1, j and j + 1, so the fresh neighbours are
 * those in neither of the last two rings. */
int64_t dggs_next_ring(const uint64_t *cur, int64_t ncur, const uint64_t *prev, int64_t nprev, uint64_t *dest,
                       int64_t dest_len, uint64_t *cand) {
    int64_t m = 0;
    for (int64_t i = 0; i < ncur; i++) {
        uint64_t x = cur[i];
        int level = dggs_level_of(x);
        for (int j = 0; j < 3; j++) cand[m++] = dggs_neighbour(x, level, j);
    }
    dggs_sort_small(cand, m);
    int64_t n = 0, ip = 0, ir = 0;
    uint64_t last = 0;
    for (int64_t i = 0; i < m; i++) {
        uint64_t c = cand[i];
        if (c == last) continue;
        last = c;
        while (ip < nprev && prev[ip] < c) ip++;
        while (ir < ncur && cur[ir] < c) ir++;
        if ((ip < nprev && prev[ip] == c) || (ir < ncur && cur[ir] == c)) continue;
        if (n == dest_len) return -1; /* no room: a size bound is wrong */
        dest[n++] = c;
    }
    return n;
}

/* _slot: the hash of an id into a table of mask + 1 slots (Fibonacci hashing, the high bits). */
static inline int64_t grid_slot(uint64_t x, int64_t mask) {
    return (int64_t)((x * (uint64_t)0x9E3779B97F4A7C15ULL) >> 40) & mask;
}

/* _disk_row: breadth-first, ring after ring, an open-addressing set of the cells seen so far. */
int64_t dggs_disk_row(uint64_t cell, int64_t k, uint64_t *row, int64_t width, uint64_t *table, int64_t table_size) {
    if (width < 1) return -1; /* no room even for the origin */
    int64_t mask = table_size - 1;
    row[0] = cell;
    table[grid_slot(cell, mask)] = cell;
    int64_t head = 0, tail = 1;
    for (int64_t step = 0; step < k; step++) {
        int64_t end = tail; /* ring j = row[head:end] */
        if (head == end) break; /* the disk covers the level: later rings are empty */
        while (head < end) {
            uint64_t x = row[head++];
            int level = dggs_level_of(x);
            for (int j = 0; j < 3; j++) {
                uint64_t y = dggs_neighbour(x, level, j);
                int64_t s = grid_slot(y, mask);
                while (table[s] != 0 && table[s] != y) s = (s + 1) & mask;
                if (table[s] == 0) {
                    if (tail == width) {
                        memset(table, 0, (size_t)table_size * sizeof *table);
                        return -1;
                    }
                    table[s] = y;
                    row[tail++] = y;
                }
            }
        }
    }
    for (int64_t t = 0; t < tail; t++) { /* empty the set: clear each cell's probe run */
        int64_t s = grid_slot(row[t], mask);
        while (table[s] != 0) {
            table[s] = 0;
            s = (s + 1) & mask;
        }
    }
    dggs_sort_small(row, tail);
    return tail;
}

/* _disk_impl's table: size = 64, doubled while below 2 * width. */
int64_t dggs_disk_table_size(int64_t width) {
    int64_t size = 64;
    while (size < 2 * width) size *= 2;
    return size;
}

/* One row of _ring_impl: breadth-first rings deduplicated against the last two rings only, in three buffers of
 * max(out_width, 6) ids and candidates of 3x that. */
int64_t dggs_ring_row(uint64_t cell, int64_t k, uint64_t *out, int64_t out_width, uint64_t *work) {
    int64_t width = out_width > 6 ? out_width : 6; /* no ring is wider than ring_size_bound(k) or its level */
    uint64_t *cand = work;
    uint64_t *bufs[3] = {work + 3 * width, work + 4 * width, work + 5 * width};
    bufs[1][0] = cell;
    int a = 0, b = 1;
    int64_t nprev = 0, ncur = 1; /* buffers of rings j - 1 and j */
    for (int64_t step = 0; step < k; step++) {
        if (ncur == 0) break; /* past the far side of the level: every later ring is empty */
        int d = 3 - a - b;
        int64_t nn = dggs_next_ring(bufs[b], ncur, bufs[a], nprev, bufs[d], width, cand);
        if (nn < 0 || nn > out_width) {
            ncur = -1;
            break;
        }
        a = b;
        b = d;
        nprev = ncur;
        ncur = nn;
    }
    if (ncur > out_width) return -1; /* k = 0 into an empty row */
    if (ncur > 0) memcpy(out, bufs[b], (size_t)ncur * sizeof *out);
    return ncur;
}

int64_t dggs_ring_work_size(int64_t out_width) {
    int64_t width = out_width > 6 ? out_width : 6;
    return 6 * width;
}

/* level_cells: 20 at level 0, 120 * 3^(level - 1) after (docs/grid.md). */
int64_t dggs_level_cells(int level) {
    if (level == 0) return 20;
    int64_t p = 1;
    for (int i = 1; i < level; i++) p *= 3;
    return 120 * p;
}

/* disk_width: the planar bound, or the whole level. */
int64_t dggs_disk_width(int64_t k, int level) {
    int64_t cells = dggs_level_cells(level);
    if (k >= cells) return cells;
    int64_t b = dggs_disk_size_bound(k);
    return b < cells ? b : cells;
}

/* ring_width: the planar bound, or the whole level. */
int64_t dggs_ring_width(int64_t k, int level) {
    int64_t cells = dggs_level_cells(level);
    if (k >= cells) return cells;
    int64_t b = dggs_ring_size_bound(k);
    return b < cells ? b : cells;
}

/* disk_of's checks, before it runs one row of disk. */
int64_t dggs_disk_of_width(uint64_t cell, int64_t k, int64_t max_cells) {
    if (k > 64 || !dggs_is_valid(cell)) return -1;
    int64_t width = dggs_disk_width(k, dggs_level_of(cell));
    return width > max_cells ? -1 : width;
}

/* One id of disk_sizes: rings j - 1 and j in two buffers of r ids, ring j + 1 and its candidates in two of 3 r
 * (the numba code allocates 3 * len(cur) for each, so next_ring never runs out of room there either). */
int64_t dggs_disk_size_count(uint64_t cell, int64_t k, int64_t cap, uint64_t *work, int64_t work_len) {
    int64_t r = work_len / 8;
    if (r < 1) return -2;
    uint64_t *prev = work, *cur = work + r, *dest = work + 2 * r, *cand = work + 5 * r;
    int64_t nprev = 0, ncur = 1;
    cur[0] = cell;
    int64_t size = 1;
    for (int64_t step = 0; step < k; step++) {
        if (ncur == 0 || size > cap) break;
        int64_t m = dggs_next_ring(cur, ncur, prev, nprev, dest, 3 * ncur, cand); /* three neighbours a cell */
        size += m;
        /* prev, cur = cur, dest[:m]: kept only if the loop goes on */
        if (step + 1 < k && m != 0 && size <= cap) {
            if (m > r) return -2;
            uint64_t *t = prev;
            prev = cur;
            cur = t;
            memcpy(cur, dest, (size_t)m * sizeof *cur);
        }
        nprev = ncur;
        ncur = m;
    }
    return size;
}

int64_t dggs_disk_sizes_work_size(int64_t r) { return 8 * r; }

/* ---------------------------------------------------------------------------------------------------------
 * Public API (dggs.h, "grid")
 * --------------------------------------------------------------------------------------------------------- */

/* The largest k the verbs take (index/_checks.py K_LIMIT): a disk of this radius covers the globe. */
#define GRID_K_LIMIT ((int64_t)1 << 31)

dggs_error dggs_edge_neighbors(dggs_cell cell, dggs_cell out[3]) {
    if (!dggs_is_valid(cell)) return DGGS_E_CELL;
    dggs_neighbours(cell, out);
    return DGGS_OK;
}

dggs_error dggs_are_neighbor_cells(dggs_cell a, dggs_cell b, int *out) {
    if (!dggs_is_valid(a) || !dggs_is_valid(b)) return DGGS_E_CELL;
    *out = dggs_are_neighbours(a, b) ? 1 : 0;
    return DGGS_OK;
}

dggs_error dggs_grid_disk_size(dggs_cell cell, int64_t k, int64_t *size) {
    if (!dggs_is_valid(cell)) return DGGS_E_CELL;
    if (k < 0 || k > GRID_K_LIMIT) return DGGS_E_DOMAIN;
    int64_t width = dggs_disk_width(k, dggs_level_of(cell));
    *size = width + dggs_disk_table_size(width);
    return DGGS_OK;
}

dggs_error dggs_grid_disk(dggs_cell cell, int64_t k, dggs_cell *out, int64_t size, int64_t *count) {
    int64_t need;
    dggs_error err = dggs_grid_disk_size(cell, k, &need);
    if (err) return err;
    if (size < need) return DGGS_E_BUFFER;
    int64_t width = dggs_disk_width(k, dggs_level_of(cell));
    int64_t tsize = dggs_disk_table_size(width);
    uint64_t *table = out + width;
    memset(table, 0, (size_t)tsize * sizeof *table);
    int64_t m = dggs_disk_row(cell, k, out, width, table, tsize);
    if (m < 0) return DGGS_E_FAILED; /* a disk outgrew disk_size_bound(k): never seen */
    memset(out + m, 0, (size_t)(size - m) * sizeof *out);
    *count = m;
    return DGGS_OK;
}

dggs_error dggs_grid_ring_size(dggs_cell cell, int64_t k, int64_t *size) {
    if (!dggs_is_valid(cell)) return DGGS_E_CELL;
    if (k < 0 || k > GRID_K_LIMIT) return DGGS_E_DOMAIN;
    int64_t width = dggs_ring_width(k, dggs_level_of(cell));
    *size = width + dggs_ring_work_size(width);
    return DGGS_OK;
}

dggs_error dggs_grid_ring(dggs_cell cell, int64_t k, dggs_cell *out, int64_t size, int64_t *count) {
    int64_t need;
    dggs_error err = dggs_grid_ring_size(cell, k, &need);
    if (err) return err;
    if (size < need) return DGGS_E_BUFFER;
    int64_t width = dggs_ring_width(k, dggs_level_of(cell));
    int64_t m = dggs_ring_row(cell, k, out, width, out + width);
    if (m < 0) return DGGS_E_FAILED; /* a ring outgrew ring_size_bound(k): never seen */
    memset(out + m, 0, (size_t)(size - m) * sizeof *out);
    *count = m;
    return DGGS_OK;
}
