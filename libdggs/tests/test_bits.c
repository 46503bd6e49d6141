/* The id layout (bits.h) against ids written out by hand from docs/grid.md's table. */
#include "bits.h"
#include "check.h"
#include "dggs.h"

int main(void) {
    /* "C401": face 2, level-1 digit 4, then digits 0 and 1 (codes 1 and 2) */
    uint64_t c401 = DGGS_MARKER | ((uint64_t)2 << 57) | ((uint64_t)5 << 54) | ((uint64_t)1 << 52) | ((uint64_t)2 << 50);
    CHECK(dggs_is_valid(c401));
    CHECK(dggs_level_of(c401) == 3);
    CHECK(dggs_face_of(c401) == 2);
    CHECK(dggs_digit_of(c401, 1) == 4 && dggs_digit_of(c401, 2) == 0 && dggs_digit_of(c401, 3) == 1);
    CHECK(dggs_digit_of(c401, 4) == -1);
    CHECK_EQ_U64(dggs_parent_at(c401, 1), DGGS_MARKER | ((uint64_t)2 << 57) | ((uint64_t)5 << 54));
    CHECK_EQ_U64(dggs_range_end(c401, 3), c401 + ((uint64_t)1 << 50));
    CHECK(dggs_level_of(dggs_base_cell(19)) == 0 && dggs_is_valid(dggs_base_cell(19)));
    CHECK(!dggs_is_valid(0));
    CHECK(!dggs_is_valid(dggs_base_cell(20)));                   /* face 20 */
    CHECK(!dggs_is_valid(c401 | ((uint64_t)1 << 63)));           /* sign bit */
    CHECK(!dggs_is_valid((c401 & ~((uint64_t)3 << 52)) | 1));    /* a digit below an empty field */
    CHECK(!dggs_is_valid(dggs_base_cell(0) | ((uint64_t)7 << 54))); /* level-1 code 7 */
    CHECK(!dggs_is_valid(dggs_base_cell(0) | 1));                /* digits without a level-1 digit */
    uint64_t deepest = dggs_base_cell(0) | ((uint64_t)1 << 54) | DGGS_DIGIT_LOW_BITS;
    CHECK(dggs_is_valid(deepest) && dggs_level_of(deepest) == 28);
    CHECK(dggs_error_string(DGGS_E_CELL)[0] != '\0');
    CHECK_DONE();
}
