/* Fuzz target: polygon fill through the public header (dggs_polygon_to_cells_size, dggs_polygon_to_cells).
 *
 * The input is read as a level, a mode (4 is no mode), a projection, 1-3 rings of 3-8 points with coordinates
 * spread over the globe from two bytes each, and sometimes a raw double (NaN, infinity, out of range) in their
 * place. The size must bound the count; the cells must be valid, at the level, strictly increasing; a buffer one
 * short must give DGGS_E_BUFFER with the count needed. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "dggs.h"
#include "reader.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    reader r = {data, size};
    int level = (int)(take(&r) % 12) - 1; /* -1..10: -1 must be refused */
    dggs_fill_mode mode = (dggs_fill_mode)(take(&r) % 5);
    dggs_projection proj = (take(&r) & 1) ? DGGS_IVEA : DGGS_ISEA;
    int64_t rings = 1 + (int64_t)(take(&r) % 3), sizes[3];
    double pts[2 * 3 * 8];
    size_t k = 0;
    for (int64_t i = 0; i < rings; i++) {
        sizes[i] = 3 + (int64_t)(take(&r) % 6);
        double clat = number(&r, -90.0, 90.0), clng = number(&r, -180.0, 180.0);
        double radius = 0.01 + 30.0 * (double)take(&r) / 255.0;
        for (int64_t j = 0; j < sizes[i]; j++) {
            double a = 6.283185307179586 * (double)j / (double)sizes[i] + 0.3 * (double)take(&r) / 255.0;
            double lat = clat + radius * sin(a), lng = clng + radius * cos(a);
            pts[k++] = fmax(-90.0, fmin(90.0, lat)) + ((take(&r) == 7) ? 200.0 : 0.0); /* sometimes off the globe */
            pts[k++] = isfinite(lng) ? fmax(-180.0, fmin(180.0, lng)) : lng;
        }
    }
    int64_t bound = 0;
    dggs_error e = dggs_polygon_to_cells_size(pts, sizes, rings, level, mode, proj, &bound);
    if (e != DGGS_OK) {
        REQUIRE(e == DGGS_E_LEVEL || e == DGGS_E_DOMAIN || e == DGGS_E_LATLNG);
        return 0;
    }
    REQUIRE(bound >= 0);
    if (bound > 200000) return 0; /* keep a run short */
    dggs_cell *out = malloc((size_t)(bound + 1) * sizeof *out);
    REQUIRE(out != NULL);
    int64_t count = -1;
    e = dggs_polygon_to_cells(pts, sizes, rings, level, mode, proj, out, bound, &count);
    REQUIRE(e == DGGS_OK);
    REQUIRE(count >= 0 && count <= bound);
    for (int64_t i = 0; i < count; i++) {
        REQUIRE(dggs_is_valid_cell(out[i]) && dggs_get_level(out[i]) == level);
        if (i) REQUIRE(out[i - 1] < out[i]);
    }
    if (count > 0) {
        int64_t need = -1;
        REQUIRE(dggs_polygon_to_cells(pts, sizes, rings, level, mode, proj, out, count - 1, &need) == DGGS_E_BUFFER);
        REQUIRE(need == count);
    }
    free(out);
    return 0;
}
