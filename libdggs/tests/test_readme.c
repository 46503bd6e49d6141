/* The README's C example, run: Calgary (51.05 N, 114.07 W) at level 9 is F200021102 (README "Use", whose Python
 * example gives the same id). */
#include <string.h>

#include "check.h"
#include "dggs.h"

int main(void) {
    dggs_cell cell;
    char id[DGGS_MAX_CHARS + 1];
    CHECK(dggs_latlng_to_cell(51.05, -114.07, 9, DGGS_ISEA, &cell) == DGGS_OK);
    CHECK(dggs_cell_to_string(cell, id, sizeof id) == DGGS_OK);
    CHECK(strcmp(id, "F200021102") == 0);
    CHECK_EQ_U64(cell, 5392473139689029632ULL); /* the README's dggs.str_to_int(cell) */
    CHECK_DONE();
}
