/* Fuzz target: the plane raster cut through the public header (dggs_plane_pieces_work_words, dggs_plane_pieces).
 *
 * The input is read as a grid (1-6 rows, 1-6 columns, a mask of valid pixels) and 1-3 rings of 0-12 points each,
 * their coordinates from -3 to 10 pixels, now and then a raw double (NaN, infinity, huge) or a repeated point; the
 * rings may cross themselves. The cut must answer or refuse with a documented error, never read or write out of
 * bounds; resumed through a small buffer; when it answers, every piece is a valid pixel's, of finite positive area,
 * its centroid inside its pixel, and no pixel gets more than the rings' points could wind round it. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "dggs.h"
#include "reader.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    reader r = {data, size};
    int64_t rows = 1 + (int64_t)(take(&r) % 6), cols = 1 + (int64_t)(take(&r) % 6);
    int64_t rings = 1 + (int64_t)(take(&r) % 3);
    double x[36], y[36];
    int64_t start[4] = {0};
    uint64_t cells[3] = {11, 12, 13};
    int64_t n = 0;
    for (int64_t k = 0; k < rings; k++) {
        int64_t m = (int64_t)(take(&r) % 13);
        for (int64_t j = 0; j < m; j++, n++) {
            if (j > 0 && take(&r) == 7) { /* a repeated point */
                x[n] = x[n - 1], y[n] = y[n - 1];
                continue;
            }
            x[n] = number(&r, -3.0, 10.0), y[n] = number(&r, -3.0, 10.0);
        }
        start[k + 1] = n;
    }
    uint8_t valid[36];
    valid_mask(&r, valid, rows * cols, 3);
    int64_t words = dggs_plane_pieces_work_words(rows, cols);
    double *work = work_buffer(words);
    int64_t cap = 2;
    dggs_plane_pieces_out out = {malloc((size_t)cap * sizeof(int64_t)), malloc((size_t)cap * sizeof(uint64_t)),
                                 malloc((size_t)cap * sizeof(double)), malloc((size_t)cap * sizeof(double)),
                                 malloc((size_t)cap * sizeof(double)), cap, 0};
    REQUIRE(out.pixel && out.cell && out.area && out.cu && out.cv);
    int64_t resume = 0, need = 0;
    dggs_error e;
    while ((e = dggs_plane_pieces(x, y, start, cells, rings, rows, cols, valid, &out, work, words, &resume,
                                  &need)) == DGGS_E_BUFFER) {
        REQUIRE(need > out.cap && need <= 3 * 36);
        out.cap = need;
        out.pixel = realloc(out.pixel, (size_t)need * sizeof(int64_t));
        out.cell = realloc(out.cell, (size_t)need * sizeof(uint64_t));
        out.area = realloc(out.area, (size_t)need * sizeof(double));
        out.cu = realloc(out.cu, (size_t)need * sizeof(double));
        out.cv = realloc(out.cv, (size_t)need * sizeof(double));
        REQUIRE(out.pixel && out.cell && out.area && out.cu && out.cv);
    }
    if (e == DGGS_OK) {
        double sums[36] = {0};
        for (int64_t i = 0; i < out.n; i++) {
            int64_t p = out.pixel[i];
            REQUIRE(p >= 0 && p < rows * cols && valid[p]);
            REQUIRE(out.area[i] > 0.0 && isfinite(out.area[i]));
            REQUIRE(out.cu[i] >= 0.0 && out.cu[i] <= 1.0 && out.cv[i] >= 0.0 && out.cv[i] <= 1.0);
            REQUIRE(out.cell[i] >= 11 && out.cell[i] <= 13);
            sums[p] += out.area[i];
        }
        /* a ring of m points winds at most m / 2 times round any point: each ring's share of a pixel is at most
         * that (with rounding) */
        for (int64_t p = 0; p < rows * cols; p++) REQUIRE(sums[p] <= 3.0 * 6.0 * (1.0 + 1e-9) + 1e-9);
    } else {
        REQUIRE(e == DGGS_E_DOMAIN);
    }
    free(out.pixel), free(out.cell), free(out.area), free(out.cu), free(out.cv), free(work);
    return 0;
}
