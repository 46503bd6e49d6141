/* Hierarchy kernels over arrays of 64-bit ids: levels, parents, children. A port of index/_kernel/hierarchy.py,
 * operation for operation (see hierarchy.h for the conventions); compaction is in compact.c.
 *
 * Children are serial: they run at memory speed (a few ns per output cell). */
#include "hierarchy.h"

#include <stdint.h>

#define U1 ((uint64_t)1)

/* hierarchy.py _ones: code 1 (digit 0) in every 2-bit field of levels first .. last (2 <= first; empty if
 * first > last). */
static uint64_t ones(int first, int last) {
    if (first > last) return 0;
    uint64_t hi = (U1 << (dggs_shift_of(first) + 2u)) - U1; /* bits up to the top of level `first` */
    uint64_t lo = (U1 << dggs_shift_of(last)) - U1;         /* bits below level `last` */
    return DGGS_DIGIT_LOW_BITS & hi & ~lo;
}

/* hierarchy.py _offset_table: entry n spreads the base-3 digits of n into consecutive 2-bit fields ending at
 * level `level`; added to a cell whose fields down to `level` hold code 1 (digit 0) it gives its n-th descendant
 * in id order (codes 1..3 never carry). The first 3^m entries serve any m. */
int64_t dggs_offset_table(int level, uint64_t table[DGGS_OFFSET_TABLE_SIZE]) {
    int m = level - 1 > 0 ? level - 1 : 0; /* only 2-bit fields (levels >= 2) */
    if (m > DGGS_TABLE_LEVELS) m = DGGS_TABLE_LEVELS;
    int64_t size = dggs_pow3(m);
    unsigned s = dggs_shift_of(level);
    for (int64_t n = 0; n < size; n++) {
        uint64_t v = 0;
        int64_t x = n;
        unsigned k = 0;
        while (x) {
            v |= (uint64_t)(x % 3) << k;
            x /= 3;
            k += 2;
        }
        table[n] = v << s;
    }
    return size;
}

/* hierarchy.py levels: the level of every (valid) id. */
void dggs_levels(const uint64_t *ids, int64_t n, uint8_t *out) {
    for (int64_t i = 0; i < n; i++) out[i] = (uint8_t)dggs_level_of(ids[i]);
}

/* hierarchy.py valid_mask: bits.is_valid of every integer (rejects 0, bit 63 set, a clear marker bit, faces
 * 20..31, level-1 code 7, and an empty field above a filled one). */
void dggs_valid_mask(const uint64_t *ids, int64_t n, uint8_t *out) {
    for (int64_t i = 0; i < n; i++) out[i] = dggs_is_valid(ids[i]) ? 1 : 0;
}

/* hierarchy.py level_bounds: (lowest, highest) level among ids; (-1, -1) when empty. */
void dggs_level_bounds(const uint64_t *ids, int64_t n, int *lo, int *hi) {
    if (n == 0) {
        *lo = -1;
        *hi = -1;
        return;
    }
    int l = 99, h = -1;
    for (int64_t i = 0; i < n; i++) {
        int lv = dggs_level_of(ids[i]);
        if (lv < l) l = lv;
        if (lv > h) h = lv;
    }
    *lo = l;
    *hi = h;
}

/* hierarchy.py parents: ancestor of every id at `level` (a cell at `level` is its own): the id with every field
 * below level `level` cleared. */
int64_t dggs_parents(const uint64_t *ids, int64_t n, int level, uint64_t *out) {
    uint64_t keep = ~((U1 << dggs_shift_of(level)) - U1);
    if (level > 0) {
        /* the cell reaches `level` iff level `level`'s field is filled (bits 56..54 at level 1, 2 bits after) */
        uint64_t field = (level == 1 ? (uint64_t)7 : (uint64_t)3) << dggs_shift_of(level);
        for (int64_t i = 0; i < n; i++)
            if ((ids[i] & field) == 0) return i;
    }
    for (int64_t i = 0; i < n; i++) out[i] = ids[i] & keep;
    return -1;
}

/* hierarchy.py parents_up: parent of every id, one level up each (mixed levels allowed). */
int64_t dggs_parents_up(const uint64_t *ids, int64_t n, uint64_t *out) {
    for (int64_t i = 0; i < n; i++) {
        int lv = dggs_level_of(ids[i]);
        if (lv == 0) return i;
        out[i] = dggs_parent_at(ids[i], lv - 1);
    }
    return -1;
}

/* hierarchy.py count_children: a base cell has 6 * 3^(level - 1) descendants, a cell at level k >= 1 has
 * 3^(level - k), a cell at `level` counts itself. */
int64_t dggs_count_children(const uint64_t *ids, int64_t n, int level, int64_t *total) {
    int64_t t = 0;
    for (int64_t i = 0; i < n; i++) {
        int lv = dggs_level_of(ids[i]);
        if (lv > level) {
            *total = 0;
            return i;
        }
        int64_t c = dggs_n_desc(lv, level);
        t = t > INT64_MAX - c ? INT64_MAX : t + c;
    }
    *total = t;
    return -1;
}

/* hierarchy.py children: the block of cell i is contiguous and in id order; blocks follow the input order (so
 * sorted, non-overlapping input gives sorted output). */
dggs_error dggs_children(const uint64_t *ids, int64_t n, int level, uint64_t *out, int64_t out_size, int64_t *bad) {
    uint64_t table[DGGS_OFFSET_TABLE_SIZE];
    dggs_offset_table(level, table);
    int64_t pos = 0;
    for (int64_t i = 0; i < n; i++) {
        uint64_t cell = ids[i];
        int lv = dggs_level_of(cell);
        if (lv > level) {
            *bad = i;
            return DGGS_E_LEVEL_MISMATCH;
        }
        if (pos + dggs_n_desc(lv, level) > out_size) { /* hierarchy.py: ValueError, output buffer too short */
            *bad = i;
            return DGGS_E_BUFFER;
        }
        if (lv == level) {
            out[pos] = cell;
            pos += 1;
            continue;
        }
        if (lv + 1 == level && lv > 0) { /* one level down: the three codes of the next field */
            unsigned sh = dggs_shift_of(level);
            out[pos] = cell | (U1 << sh);
            out[pos + 1] = cell | ((uint64_t)2 << sh);
            out[pos + 2] = cell | ((uint64_t)3 << sh);
            pos += 3;
            continue;
        }
        int n_sub = 1; /* a base cell goes through its six level-1 children (3-bit codes 1..6, bits 56..54) */
        if (lv == 0) {
            cell |= U1 << DGGS_L1_SHIFT;
            lv = 1;
            n_sub = 6;
        }
        /* The lowest m levels come from `table`; the levels lv+1 .. level-m above them are an odometer over the
         * 2-bit code fields: add one at its lowest field, then reset to code 1 every field the carry left at
         * code 0. */
        int m = level - lv < DGGS_TABLE_LEVELS ? level - lv : DGGS_TABLE_LEVELS;
        int64_t nt = dggs_pow3(m);
        int64_t n_odo = dggs_pow3(level - lv - m);
        uint64_t fill = ones(lv + 1, level); /* digit 0 everywhere below the cell: its first descendant */
        uint64_t odo_step = U1 << dggs_shift_of(level - m);
        uint64_t odo_mask = ones(lv + 1, level - m);
        for (int b = 0; b < n_sub; b++) {
            uint64_t q = (cell + (uint64_t)b * (U1 << DGGS_L1_SHIFT)) | fill;
            for (int64_t o = 0; o < n_odo; o++) {
                for (int64_t j = 0; j < nt; j++) out[pos + j] = q + table[j];
                pos += nt;
                uint64_t y = q + odo_step;
                q = y | (~(y | (y >> 1)) & odo_mask);
            }
        }
    }
    *bad = -1;
    return DGGS_OK;
}

/* hierarchy.py parent_of: ancestor of one id (int64) at `level` (-1: one level up); 0 where there is none or
 * `cell` is no id. */
int64_t dggs_parent_of(int64_t cell, int level) {
    uint64_t c = (uint64_t)cell;
    if (!dggs_is_valid(c)) return 0;
    int lv = dggs_level_of(c);
    if (level < 0) level = lv - 1;
    if (level < 0 || level > lv) return 0;
    return (int64_t)dggs_parent_at(c, level);
}

/* ---- public API (dggs.h, "hierarchy") ---- */

dggs_error dggs_cell_to_parent(dggs_cell cell, int parent_level, dggs_cell *parent) {
    if (!dggs_is_valid(cell)) return DGGS_E_CELL;
    if (parent_level < 0 || parent_level > DGGS_MAX_LEVEL) return DGGS_E_LEVEL;
    if (parent_level > dggs_level_of(cell)) return DGGS_E_LEVEL_MISMATCH;
    *parent = (dggs_cell)dggs_parent_of((int64_t)cell, parent_level);
    return DGGS_OK;
}

dggs_error dggs_cell_to_children_size(dggs_cell cell, int child_level, int64_t *size) {
    if (!dggs_is_valid(cell)) return DGGS_E_CELL;
    if (child_level < 0 || child_level > DGGS_MAX_LEVEL) return DGGS_E_LEVEL;
    int64_t bad = dggs_count_children(&cell, 1, child_level, size);
    return bad >= 0 ? DGGS_E_LEVEL_MISMATCH : DGGS_OK;
}

dggs_error dggs_cell_to_children(dggs_cell cell, int child_level, dggs_cell *children, int64_t size) {
    int64_t need;
    dggs_error err = dggs_cell_to_children_size(cell, child_level, &need);
    if (err != DGGS_OK) return err;
    if (size < need) return DGGS_E_BUFFER;
    int64_t bad;
    return dggs_children(&cell, 1, child_level, children, size, &bad);
}
