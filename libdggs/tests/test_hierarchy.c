/* The hierarchy kernels (hierarchy.c): docs/grid.md's counts and examples, invariants of parents and children
 * on pseudo-random cells of every level, the frozen numba outputs (frozen_hierarchy.h, tools/freeze_hierarchy.py)
 * and the public API's errors. */
#include "hierarchy.h"

#include "check.h"
#include "testutil.h"
#include "dggs.h"
#include "frozen_hierarchy.h"


/* A deterministic pseudo-random valid id of `level` (splitmix64 digits). */
static uint64_t rnd_state = 12345;
static uint64_t rnd(void) { return splitmix64(&rnd_state); }
static uint64_t rnd_cell(int level) {
    uint64_t c = dggs_base_cell((int)(rnd() % 20));
    if (level >= 1) c |= (rnd() % 6 + 1) << DGGS_L1_SHIFT;
    for (int k = 2; k <= level; k++) c |= (rnd() % 3 + 1) << (2 * (DGGS_MAX_LEVEL - k));
    return c;
}

static uint64_t buf[300000];

static void test_docs(void) {
    /* get_num_cells: 20 at level 0, 120 * 3^(level - 1) after */
    uint64_t bases[20];
    for (int f = 0; f < 20; f++) bases[f] = dggs_base_cell(f);
    for (int level = 0; level <= DGGS_MAX_LEVEL; level++) {
        int64_t total, expect = level == 0 ? 20 : 120 * dggs_pow3(level - 1);
        CHECK(dggs_count_children(bases, 20, level, &total) == -1);
        CHECK(total == expect);
    }
    /* cell_to_children("C401") == C4010, C4011, C4012; len(cell_to_children("C", 2)) == 18 */
    uint64_t c401 = sid("C401"), out[18];
    int64_t bad;
    CHECK(dggs_children(&c401, 1, 4, out, 3, &bad) == DGGS_OK && bad == -1);
    CHECK_EQ_U64(out[0], sid("C4010"));
    CHECK_EQ_U64(out[1], sid("C4011"));
    CHECK_EQ_U64(out[2], sid("C4012"));
    uint64_t c = sid("C");
    CHECK(dggs_children(&c, 1, 2, out, 18, &bad) == DGGS_OK);
    CHECK_EQ_U64(out[0], sid("C00"));
    CHECK_EQ_U64(out[17], sid("C52"));
    /* cell_to_parent("C401") == "C40", cell_to_parent("C401", 1) == "C4" */
    CHECK(dggs_parent_of((int64_t)c401, -1) == (int64_t)sid("C40"));
    CHECK(dggs_parent_of((int64_t)c401, 1) == (int64_t)sid("C4"));
    CHECK(dggs_parent_of((int64_t)c401, 4) == 0);
    CHECK(dggs_parent_of((int64_t)sid("T"), -1) == 0);
    CHECK(dggs_parent_of(0, 0) == 0);
    /* levels of "C401", "C4", "C" */
    uint64_t ids[3] = {c401, sid("C4"), sid("C")};
    uint8_t lv[3];
    dggs_levels(ids, 3, lv);
    CHECK(lv[0] == 3 && lv[1] == 1 && lv[2] == 0);
    int lo, hi;
    dggs_level_bounds(ids, 3, &lo, &hi);
    CHECK(lo == 0 && hi == 3);
    dggs_level_bounds(ids, 0, &lo, &hi);
    CHECK(lo == -1 && hi == -1);
    uint64_t junk[4] = {0, c401 | 1, dggs_base_cell(20), c401};
    uint8_t ok[4];
    dggs_valid_mask(junk, 4, ok);
    CHECK(!ok[0] && !ok[1] && !ok[2] && ok[3]);
}

/* hierarchy.py's error positions: a cell coarser than the parent level, a base cell one level up, a cell finer
 * than the children's level, a short buffer. */
static void test_bad(void) {
    uint64_t ids[5] = {sid("C4"), sid("A"), sid("C401"), sid("C40"), sid("C4012")};
    uint64_t out[100];
    int64_t total, bad;
    CHECK(dggs_count_children(ids, 5, 2, &total) == 2 && total == 0);
    CHECK(dggs_children(ids, 5, 2, out, 100, &bad) == DGGS_E_LEVEL_MISMATCH && bad == 2);
    CHECK(dggs_count_children(ids, 5, 3, &total) == 4);
    uint64_t c4 = sid("C4");
    CHECK(dggs_children(&c4, 1, 3, out, 8, &bad) == DGGS_E_BUFFER);
    uint64_t p[4] = {sid("C401"), sid("C4"), sid("A"), sid("T5")};
    CHECK(dggs_parents(p, 4, 2, out) == 1);
    CHECK(dggs_parents(p, 4, 0, out) == -1);
    CHECK_EQ_U64(out[0], sid("C"));
    CHECK_EQ_U64(out[3], sid("T"));
    CHECK(dggs_parents_up(p, 4, out) == 2);
    CHECK_EQ_U64(out[0], sid("C40"));
    CHECK_EQ_U64(out[1], sid("C"));
    /* saturation: 2 * 6 * 3^27 is exact, 300,000 base cells at level 28 saturate */
    uint64_t two[2] = {sid("A"), sid("B")};
    CHECK(dggs_count_children(two, 2, 28, &total) == -1 && total == 12 * dggs_pow3(27));
    for (int i = 0; i < 300000; i++) buf[i] = sid("A"); /* 300,000 * 6 * 3^27 > 2^63 */
    CHECK(dggs_count_children(buf, 300000, 28, &total) == -1 && total == INT64_MAX);
}

/* Children of random cells at every deeper level (up to 9 levels down): count, id order, inside the cell's
 * range, parent back, first and last = digit 0 and digit 2 (5 at level 1) everywhere. */
static void test_invariants(void) {
    for (int level = 0; level <= DGGS_MAX_LEVEL; level++) {
        for (int down = 0; down <= 9 && level + down <= DGGS_MAX_LEVEL; down++) {
            uint64_t c = rnd_cell(level);
            int target = level + down;
            int64_t total, bad;
            CHECK(dggs_count_children(&c, 1, target, &total) == -1);
            CHECK(total == dggs_n_desc(level, target));
            if (total > 200000) continue;
            CHECK(dggs_children(&c, 1, target, buf, total, &bad) == DGGS_OK && bad == -1);
            int good = 1;
            for (int64_t i = 0; i < total; i++) {
                if (dggs_level_of(buf[i]) != target || !dggs_is_valid(buf[i])) good = 0;
                if (dggs_parent_at(buf[i], level) != c) good = 0;
                if (buf[i] < c || buf[i] >= dggs_range_end(c, level)) good = 0;
                if (i && buf[i] <= buf[i - 1]) good = 0;
                if (dggs_finer_than(buf[i], level) != (down > 0)) good = 0;
            }
            CHECK(good);
            for (int k = level + 1; k <= target; k++) {
                CHECK(dggs_digit_of(buf[0], k) == 0);
                CHECK(dggs_digit_of(buf[total - 1], k) == (k == 1 ? 5 : 2));
            }
            uint64_t parents[1];
            if (total) CHECK(dggs_parents(&buf[total - 1], 1, level, parents) == -1 && parents[0] == c);
        }
    }
}

static void test_frozen(void) {
    uint8_t lv[FROZEN_NCELLS];
    dggs_levels(frozen_cells, FROZEN_NCELLS, lv);
    for (int i = 0; i < FROZEN_NCELLS; i++) CHECK(lv[i] == frozen_levels[i]);
    for (size_t r = 0; r < sizeof frozen_parent_of / sizeof frozen_parent_of[0]; r++) {
        const frozen_parent_row *row = &frozen_parent_of[r];
        CHECK(dggs_parent_of(row->cell, row->level) == row->parent);
    }
    for (size_t r = 0; r < sizeof frozen_children / sizeof frozen_children[0]; r++) {
        const frozen_children_row *row = &frozen_children[r];
        int64_t total, bad;
        CHECK(dggs_count_children(&row->cell, 1, row->level, &total) == -1);
        CHECK(total == row->total);
        if (row->total > 200000) continue;
        CHECK(dggs_children(&row->cell, 1, row->level, buf, 200000, &bad) == DGGS_OK);
        uint64_t sum = 0;
        for (int64_t i = 0; i < total; i++) sum += buf[i];
        CHECK_EQ_U64(buf[0], row->first);
        CHECK_EQ_U64(buf[total - 1], row->last);
        CHECK_EQ_U64(sum, row->sum);
    }
    for (size_t r = 0; r < sizeof frozen_small_children / sizeof frozen_small_children[0]; r++) {
        const frozen_small_row *row = &frozen_small_children[r];
        uint64_t out[6];
        int64_t bad;
        CHECK(dggs_children(&row->cell, 1, row->level, out, 6, &bad) == DGGS_OK);
        for (int i = 0; i < row->n; i++) CHECK_EQ_U64(out[i], row->out[i]);
    }
}

static void test_public(void) {
    dggs_cell p, out[6];
    int64_t size;
    CHECK(dggs_cell_to_parent(sid("C401"), 2, &p) == DGGS_OK && p == sid("C40"));
    CHECK(dggs_cell_to_parent(sid("C401"), 3, &p) == DGGS_OK && p == sid("C401"));
    CHECK(dggs_cell_to_parent(sid("C401"), 4, &p) == DGGS_E_LEVEL_MISMATCH);
    CHECK(dggs_cell_to_parent(sid("C401"), -1, &p) == DGGS_E_LEVEL);
    CHECK(dggs_cell_to_parent(sid("C401") | 1, 1, &p) == DGGS_E_CELL);
    CHECK(dggs_cell_to_children_size(sid("T"), 1, &size) == DGGS_OK && size == 6);
    CHECK(dggs_cell_to_children_size(sid("T3"), 0, &size) == DGGS_E_LEVEL_MISMATCH);
    CHECK(dggs_cell_to_children_size(sid("T3"), 29, &size) == DGGS_E_LEVEL);
    CHECK(dggs_cell_to_children_size(0, 3, &size) == DGGS_E_CELL);
    CHECK(dggs_cell_to_children(sid("T"), 1, out, 5) == DGGS_E_BUFFER);
    CHECK(dggs_cell_to_children(sid("T"), 1, out, 6) == DGGS_OK);
    CHECK_EQ_U64(out[5], sid("T5"));
    /* cell_to_center_child("C401") == "C4011", cell_to_center_child("C", 1) == "C1" (the level-1 tie rule) */
    CHECK(dggs_cell_to_center_child(sid("C401"), 4, &p) == DGGS_OK && p == sid("C4011"));
    CHECK(dggs_cell_to_center_child(sid("C401"), 3, &p) == DGGS_OK && p == sid("C401"));
    CHECK(dggs_cell_to_center_child(sid("C"), 1, &p) == DGGS_OK && p == sid("C1"));
    CHECK(dggs_cell_to_center_child(sid("C401"), 2, &p) == DGGS_E_LEVEL_MISMATCH);
    CHECK(dggs_cell_to_center_child(sid("C401"), 29, &p) == DGGS_E_LEVEL);
    CHECK(dggs_cell_to_center_child(0, 5, &p) == DGGS_E_CELL);
}

int main(void) {
    test_docs();
    test_bad();
    test_invariants();
    test_frozen();
    test_public();
    CHECK_DONE();
}
