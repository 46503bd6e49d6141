/* The 64-bit integer cell id: layout and bit operations (docs/grid.md, "Integer ids").
 *
 * Most significant bit first:
 *   bit 63        0            (every id is a positive int64 too)
 *   bit 62        1            (marker: 0 is never an id, it is the null id)
 *   bits 61..57   face 0..19
 *   bits 56..54   level-1 code: 0 = none, 1..6 = digit 0..5
 *   bits 2(28-k)+1 .. 2(28-k)   level-k code (k = 2..28): 0 = none, 1..3 = digit 0..2
 * A field of 0 means "no digit", so numeric order is the string order, the descendants of c at level l are
 * [c, c + 2^shift(l)), and level, parent and children are bit operations. */
#ifndef DGGS_BITS_H
#define DGGS_BITS_H

#include <stdbool.h>
#include <stdint.h>

#define DGGS_MAX_LEVEL 28
#define DGGS_MARKER ((uint64_t)1 << 62)
#define DGGS_FACE_SHIFT 57
#define DGGS_L1_SHIFT 54
#define DGGS_NUM_FACES 20
/* The level-2..28 fields. */
#define DGGS_LOW54 (((uint64_t)1 << DGGS_L1_SHIFT) - 1)
/* The low bit of every 2-bit digit field (levels 2..28): codes 1 and 3 (digits 0 and 2) set it. */
#define DGGS_DIGIT_LOW_BITS ((uint64_t)0x0015555555555555ULL)

/* Lowest bit of level `level`'s field. */
static inline unsigned dggs_shift_of(int level) {
    if (level == 0) return DGGS_FACE_SHIFT;
    if (level == 1) return DGGS_L1_SHIFT;
    return (unsigned)(2 * (DGGS_MAX_LEVEL - level));
}

static inline int dggs_ctz64(uint64_t x) { /* x != 0 */
#if defined(__GNUC__) || defined(__clang__)
    return __builtin_ctzll(x);
#else
    int n = 0;
    while (!(x & 1)) {
        x >>= 1;
        n++;
    }
    return n;
#endif
}

/* Level of a well-formed id: its lowest filled field. */
static inline int dggs_level_of(uint64_t cell) {
    uint64_t low = cell & DGGS_LOW54;
    if (low) return DGGS_MAX_LEVEL - dggs_ctz64(low) / 2;
    return ((cell >> DGGS_L1_SHIFT) & 7u) ? 1 : 0;
}

/* Whether an integer is a well-formed id (never fails). */
static inline bool dggs_is_valid(uint64_t cell) {
    if (cell >> 62 != 1) return false; /* sign bit clear, marker set */
    if (((cell >> DGGS_FACE_SHIFT) & 31u) >= DGGS_NUM_FACES) return false;
    uint64_t l1 = (cell >> DGGS_L1_SHIFT) & 7u;
    uint64_t low = cell & DGGS_LOW54;
    if (l1 == 0) return low == 0;
    if (l1 == 7) return false;
    bool seen_empty = false; /* every empty field must have only empty fields below it */
    for (int k = 2; k <= DGGS_MAX_LEVEL; k++) {
        uint64_t code = (low >> (2 * (DGGS_MAX_LEVEL - k))) & 3u;
        if (code == 0)
            seen_empty = true;
        else if (seen_empty)
            return false;
    }
    return true;
}

static inline int dggs_face_of(uint64_t cell) { return (int)((cell >> DGGS_FACE_SHIFT) & 31u); }

/* Digit of `cell` at `level` >= 1 (0..5 at level 1, 0..2 after); -1 where empty. */
static inline int dggs_digit_of(uint64_t cell, int level) {
    if (level == 1) return (int)((cell >> DGGS_L1_SHIFT) & 7u) - 1;
    return (int)((cell >> (2 * (DGGS_MAX_LEVEL - level))) & 3u) - 1;
}

static inline uint64_t dggs_base_cell(int face) { return DGGS_MARKER | ((uint64_t)face << DGGS_FACE_SHIFT); }

/* Ancestor at `level` (no checks): clear every field below it. */
static inline uint64_t dggs_parent_at(uint64_t cell, int level) {
    return cell & ~(((uint64_t)1 << dggs_shift_of(level)) - 1);
}

/* One past the last descendant of `cell` (at `level`). */
static inline uint64_t dggs_range_end(uint64_t cell, int level) {
    return cell + ((uint64_t)1 << dggs_shift_of(level));
}

#endif
