/* Compaction (compact.c): docs/grid.md's and compact.py's examples, the sorts against each other, compaction
 * round trips on pseudo-random cell sets, the frozen numba outputs (frozen_compact.h, tools/freeze_compact.py)
 * and the public API's buffers and errors. */
#include "compact.h"

#include "check.h"
#include "testutil.h"
#include "dggs.h"
#include "frozen_compact.h"
#include "hierarchy.h"


static uint64_t rnd_state = 777;
static uint64_t rnd(void) { return splitmix64(&rnd_state); }

#define BIG 100000
static uint64_t in[BIG], out[BIG], out2[BIG], scratch[BIG + DGGS_RADIX_HIST], work[4 * BIG + DGGS_RADIX_HIST];

/* compact(list of string ids) equals the expected list. */
static int compacts_to(const char **cells, int n, const char **expect, int m) {
    for (int i = 0; i < n; i++) in[i] = sid(cells[i]);
    int64_t k = dggs_compact(in, n, out, scratch);
    if (k != m) return 0;
    for (int i = 0; i < m; i++)
        if (out[i] != sid(expect[i])) return 0;
    return 1;
}

static void test_examples(void) {
    const char *a[] = {"C4010", "C4011", "C4012", "C402"}, *ae[] = {"C401", "C402"};
    CHECK(compacts_to(a, 4, ae, 2));
    const char *b[] = {"A0", "A1", "A2", "A3", "A4", "A5"}, *be[] = {"A"};
    CHECK(compacts_to(b, 6, be, 1));
    const char *c[] = {"A0", "A1", "A2", "A3", "A4"};
    CHECK(compacts_to(c, 5, c, 5));
    const char *d[] = {"C40", "C411", "C42"};
    CHECK(compacts_to(d, 3, d, 3));
    const char *e[] = {"A0", "A1", "A2", "A3", "A40", "A41", "A42", "A5"};
    CHECK(compacts_to(e, 8, be, 1));
    const char *f[] = {"C40", "C410", "C411", "C412", "C42"}, *fe[] = {"C4"};
    CHECK(compacts_to(f, 5, fe, 1));
    const char *g[] = {"C401", "C4", "C4", "C40122", "A"}, *ge[] = {"A", "C4"};
    CHECK(compacts_to(g, 5, ge, 2));
    CHECK(dggs_compact(in, 0, out, scratch) == 0);
    /* uncompact_cells(["C401", "C4020"], 4) == C4010, C4011, C4012, C4020 */
    in[0] = sid("C4020");
    in[1] = sid("C401");
    in[2] = sid("C4012");
    int64_t m, total, bad;
    CHECK(dggs_uncompact_prepare(in, 3, 4, out, scratch, &m, &total) == -1 && m == 2 && total == 4);
    CHECK(dggs_children(out, m, 4, out2, 4, &bad) == DGGS_OK);
    CHECK_EQ_U64(out2[0], sid("C4010"));
    CHECK_EQ_U64(out2[3], sid("C4020"));
    in[3] = sid("T32");
    CHECK(dggs_uncompact_prepare(in, 4, 1, out, scratch, &m, &total) == 0); /* "C4020" is finer than level 1 */
    /* all of T's level-4 descendants, shuffled, compact to T; all 120 level-1 cells to the 20 faces */
    uint64_t t = sid("T");
    dggs_children(&t, 1, 4, in, BIG, &bad);
    int64_t n = dggs_n_desc(0, 4);
    for (int64_t i = n - 1; i > 0; i--) {
        int64_t j = (int64_t)(rnd() % (uint64_t)(i + 1));
        uint64_t x = in[i];
        in[i] = in[j];
        in[j] = x;
    }
    CHECK(dggs_compact(in, n, out, scratch) == 1 && out[0] == t);
    for (int i = 0; i < 120; i++) in[119 - i] = dggs_base_cell(i / 6) | ((uint64_t)(i % 6 + 1) << DGGS_L1_SHIFT);
    CHECK(dggs_compact(in, 120, out, scratch) == 20);
    for (int face = 0; face < 20; face++) CHECK_EQ_U64(out[face], dggs_base_cell(face));
}

static int sorted_equal(const uint64_t *a, const uint64_t *b, int64_t n) {
    for (int64_t i = 0; i < n; i++)
        if (a[i] != b[i] || (i && a[i] < a[i - 1])) return 0;
    return 1;
}

/* The radix sort against the heap sort (dggs_sorted below DGGS_RADIX_MIN) on keys differing in every span of
 * bits at every position, and the in-order and all-equal inputs. */
static void test_sorts(void) {
    for (int span = 1; span <= 64; span++) {
        int lows[3] = {0, 64 - span, (64 - span) / 2};
        for (int l = 0; l < 3; l++) {
            int n = 3000;
            for (int i = 0; i < n; i++) in[i] = (rnd() >> (64 - span)) << lows[l];
            dggs_radix_sort(in, n, out, scratch);
            dggs_sorted(in, n, out2, scratch);
            CHECK(sorted_equal(out, out2, n));
        }
    }
    for (int i = 0; i < 5000; i++) in[i] = sid("C401");
    dggs_radix_sort(in, 5000, out, scratch);
    CHECK(sorted_equal(in, out, 5000));
    for (int i = 0; i < 5000; i++) in[i] = (uint64_t)i * 77;
    dggs_sorted(in, 5000, out, scratch);
    CHECK(sorted_equal(in, out, 5000));
}

/* Random sets: uncompact(compact(x)) == uncompact(x), compact(uncompact(x)) == compact(x), and compact is
 * sorted, non-overlapping and has no complete sibling set. */
static void test_round_trips(void) {
    for (int trial = 0; trial < 40; trial++) {
        int level = (int)(rnd() % 29);
        int64_t n = trial % 2 ? 60 : 6000; /* the heap sort and the radix sort */
        for (int64_t i = 0; i < n; i++) {
            int lv = level - (int)(rnd() % 3);
            if (lv < 0) lv = 0;
            uint64_t c = dggs_base_cell((int)(rnd() % 2));
            if (lv >= 1) c |= (rnd() % 6 + 1) << DGGS_L1_SHIFT;
            for (int k = 2; k <= lv; k++) c |= (k < 4 ? rnd() % 3 + 1 : 1) << (2 * (DGGS_MAX_LEVEL - k));
            in[i] = c;
        }
        int64_t k = dggs_compact(in, n, out, scratch);
        int good = 1;
        for (int64_t i = 1; i < k; i++)
            if (out[i] < dggs_range_end(out[i - 1], dggs_level_of(out[i - 1]))) good = 0;
        CHECK(good);
        int64_t m1, t1, m2, t2, bad;
        CHECK(dggs_uncompact_prepare(in, n, level, out2, scratch, &m1, &t1) == -1);
        CHECK(dggs_uncompact_prepare(out, k, level, work, scratch, &m2, &t2) == -1);
        CHECK(t1 == t2);
        if (t1 > BIG) continue;
        CHECK(dggs_children(out2, m1, level, in, BIG, &bad) == DGGS_OK);
        CHECK(dggs_children(work, m2, level, work + BIG, BIG, &bad) == DGGS_OK);
        CHECK(sorted_equal(in, work + BIG, t1));
        CHECK(dggs_compact(in, t1, out2, scratch) == k);
        CHECK(sorted_equal(out, out2, k));
    }
}

static void test_frozen(void) {
    for (size_t r = 0; r < sizeof frozen_compact / sizeof frozen_compact[0]; r++) {
        const frozen_compact_row *row = &frozen_compact[r];
        const uint64_t *ids = frozen_compact_ids + row->in;
        int64_t k = dggs_compact(ids, row->n_in, out, scratch);
        CHECK(k == row->n_comp);
        for (int64_t i = 0; i < k && i < row->n_comp; i++) CHECK_EQ_U64(out[i], frozen_compact_ids[row->comp + i]);
        int64_t m, total;
        int64_t bad = dggs_uncompact_prepare(ids, row->n_in, row->level, out, scratch, &m, &total);
        CHECK(bad == row->bad && total == row->total && m == row->n_cover);
        for (int64_t i = 0; i < m && i < row->n_cover; i++) CHECK_EQ_U64(out[i], frozen_compact_ids[row->cover + i]);
    }
}

static void test_public(void) {
    dggs_cell cells[4] = {sid("C4012"), sid("C4010"), sid("C4011"), sid("C402")};
    int64_t size, n_out;
    CHECK(dggs_compact_cells_size(4, &size) == DGGS_OK && size == 4);
    CHECK(dggs_compact_cells_size(-1, &size) == DGGS_E_DOMAIN);
    CHECK(dggs_compact_cells_size(5000, &size) == DGGS_OK && size == 10000 + DGGS_RADIX_HIST);
    CHECK(dggs_compact_cells_size(4095, &size) == DGGS_OK && size == 4095);
    CHECK(dggs_compact_cells(cells, 4, out, 3, &n_out) == DGGS_E_BUFFER);
    CHECK(dggs_compact_cells(cells, 4, out, 4, &n_out) == DGGS_OK && n_out == 2);
    CHECK(out[0] == sid("C401") && out[1] == sid("C402"));
    cells[3] |= 1;
    CHECK(dggs_compact_cells(cells, 4, out, 4, &n_out) == DGGS_E_CELL);
    dggs_cell u[3] = {sid("C4020"), sid("C401"), sid("C4012")};
    CHECK(dggs_uncompact_cells_size(u, 3, 3, &size) == DGGS_E_LEVEL_MISMATCH);
    CHECK(dggs_uncompact_cells_size(u, 3, 29, &size) == DGGS_E_LEVEL);
    CHECK(dggs_uncompact_cells_size(u, 3, 4, &size) == DGGS_OK && size == 5); /* 1 + 3 + 1, with the overlap */
    CHECK(dggs_uncompact_cells(u, 3, 4, out, 4, &n_out) == DGGS_E_BUFFER);
    CHECK(dggs_uncompact_cells(u, 3, 4, out, size, &n_out) == DGGS_OK && n_out == 4);
    CHECK(out[0] == sid("C4010") && out[1] == sid("C4011") && out[2] == sid("C4012") && out[3] == sid("C4020"));
    /* a large input: the buffer holds the sort's scratch, the cover moves to its end */
    for (int i = 0; i < 5000; i++) in[i] = dggs_base_cell(i / 6 % 20) | ((uint64_t)(i % 6 + 1) << DGGS_L1_SHIFT);
    CHECK(dggs_uncompact_cells_size(in, 5000, 2, &size) == DGGS_OK && size == 10000 + DGGS_RADIX_HIST);
    CHECK(dggs_uncompact_cells(in, 5000, 2, work, size, &n_out) == DGGS_OK && n_out == 360);
    int good = 1;
    for (int i = 0; i < 360; i++) {
        if (dggs_level_of(work[i]) != 2 || (i && work[i] <= work[i - 1])) good = 0;
    }
    CHECK(good && work[0] == sid("A00") && work[359] == sid("T52"));
    CHECK(dggs_uncompact_cells_size(in, 5000, 1, &size) == DGGS_OK && size == 10000 + DGGS_RADIX_HIST);
    CHECK(dggs_uncompact_cells(in, 5000, 1, work, size, &n_out) == DGGS_OK && n_out == 120);
    CHECK(work[0] == sid("A0") && work[119] == sid("T5"));
}

int main(void) {
    test_examples();
    test_sorts();
    test_round_trips();
    test_frozen();
    test_public();
    CHECK_DONE();
}
