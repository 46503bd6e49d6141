/* Fuzz target: the lat/lng raster cut through the public header (dggs_latlng_pieces_work_words, dggs_latlng_pieces).
 *
 * The input is read as a level, a grid (its west edge anywhere in two turns, its pixel width from 0.001 to 40
 * degrees, 1-4 rows of 0.001-40 degrees from a top latitude, north-up or south-up, 1-4 columns), a mask of valid
 * pixels, and sometimes a raw double (NaN, infinity, out of range) in place of a number. The cut must answer or
 * refuse with a documented error, never read or write out of bounds (the level-0 pole edge did); resumed through
 * a small buffer; when it answers, every piece is a valid pixel's, with positive area, in a valid cell at the level,
 * and each pixel's pieces add up to at most its share of the sphere. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "dggs.h"
#include "reader.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    reader r = {data, size};
    int level = (int)(take(&r) % 10) - 1; /* -1..8: -1 must be refused */
    int64_t rows = 1 + (int64_t)(take(&r) % 4), cols = 1 + (int64_t)(take(&r) % 4);
    double west = number(&r, -360.0, 360.0), dlng = number(&r, 0.001, 40.0);
    int south_up = take(&r) & 1;
    double lat[5];
    lat[0] = number(&r, -90.0, 90.0);
    for (int64_t i = 1; i <= rows; i++) {
        double step = number(&r, 0.001, 40.0);
        double next = south_up ? lat[i - 1] + step : lat[i - 1] - step;
        lat[i] = (take(&r) == 9) ? lat[i - 1] : fmax(-90.0, fmin(90.0, next)); /* now and then not monotonic */
    }
    uint8_t valid[16];
    valid_mask(&r, valid, rows * cols, 2);
    int64_t words = dggs_latlng_pieces_work_words(rows, cols);
    double *work = work_buffer(words);
    int64_t cap = 8;
    dggs_pieces out = {malloc((size_t)cap * sizeof(int64_t)), malloc((size_t)cap * sizeof(dggs_cell)),
                       malloc((size_t)cap * sizeof(double)), cap, 0};
    REQUIRE(out.pixel && out.cell && out.area);
    int64_t resume = 0, need = 0;
    dggs_error e;
    while ((e = dggs_latlng_pieces(west, dlng, lat, rows, cols, valid, level, 1e-5, &out, work, words, &resume,
                                   &need)) == DGGS_E_BUFFER) {
        REQUIRE(need > out.cap && need <= 50000000);
        if (need > 2000000) break; /* keep a run short */
        out.cap = need;
        out.pixel = realloc(out.pixel, (size_t)need * sizeof(int64_t));
        out.cell = realloc(out.cell, (size_t)need * sizeof(dggs_cell));
        out.area = realloc(out.area, (size_t)need * sizeof(double));
        REQUIRE(out.pixel && out.cell && out.area);
    }
    if (e == DGGS_OK) {
        double sums[16] = {0};
        for (int64_t i = 0; i < out.n; i++) {
            int64_t p = out.pixel[i];
            REQUIRE(p >= 0 && p < rows * cols && valid[p]);
            REQUIRE(out.area[i] > 0.0 && isfinite(out.area[i]));
            REQUIRE(dggs_is_valid_cell(out.cell[i]) && dggs_get_level(out.cell[i]) == level);
            sums[p] += out.area[i];
        }
        for (int64_t p = 0; p < rows * cols; p++) REQUIRE(sums[p] <= 4.0 * 3.14159265358979323846 * (1.0 + 1e-9));
    } else if (e != DGGS_E_BUFFER) {
        REQUIRE(e == DGGS_E_LEVEL || e == DGGS_E_DOMAIN || e == DGGS_E_LATLNG || e == DGGS_E_FAILED);
    }
    free(out.pixel), free(out.cell), free(out.area), free(work);
    return 0;
}
