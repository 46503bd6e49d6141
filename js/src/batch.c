/* The JS package's batch loops: one call from JS per array instead of one per item (a call into wasm and the
 * BigInt of each id cost more than the work of small cells). Thin loops over the public functions of dggs.h,
 * exported by name; compiled only into js/dist/dggs.wasm (make wasm). Each returns the index of the first item
 * it could not take (its output row is then 0 or NaN and the loop goes on), or -1. */
#include <math.h>
#include <stdint.h>

#include "dggs.h"

#define EXPORT(name) __attribute__((export_name(name)))

EXPORT("dggsjs_latlng_to_cells")
int32_t dggsjs_latlng_to_cells(const double *lat, const double *lng, int32_t n, int level, int proj, dggs_cell *out) {
    int32_t bad = -1;
    for (int32_t i = 0; i < n; i++) {
        if (dggs_latlng_to_cell(lat[i], lng[i], level, (dggs_projection)proj, &out[i]) != DGGS_OK) {
            out[i] = 0;
            if (bad < 0) bad = i;
        }
    }
    return bad;
}

/* Centres as (lat, lng) pairs, 2 n doubles. */
EXPORT("dggsjs_cells_to_latlngs")
int32_t dggsjs_cells_to_latlngs(const dggs_cell *cells, int32_t n, int proj, double *out) {
    int32_t bad = -1;
    for (int32_t i = 0; i < n; i++) {
        if (dggs_cell_to_latlng(cells[i], (dggs_projection)proj, &out[2 * i], &out[2 * i + 1]) != DGGS_OK) {
            out[2 * i] = out[2 * i + 1] = NAN;
            if (bad < 0) bad = i;
        }
    }
    return bad;
}

/* Boundaries of 3 (densify + 1) (lat, lng) points each, 6 (densify + 1) n doubles. */
EXPORT("dggsjs_cells_to_boundaries")
int32_t dggsjs_cells_to_boundaries(const dggs_cell *cells, int32_t n, int densify, int proj, double *out) {
    size_t points, count;
    if (dggs_cell_to_boundary_size(densify, &points) != DGGS_OK) return n > 0 ? 0 : -1;
    int32_t bad = -1;
    for (int32_t i = 0; i < n; i++) {
        double *row = out + 2 * points * (size_t)i;
        if (dggs_cell_to_boundary(cells[i], densify, (dggs_projection)proj, row, points, &count) != DGGS_OK) {
            for (size_t k = 0; k < 2 * points; k++) row[k] = NAN;
            if (bad < 0) bad = i;
        }
    }
    return bad;
}
