/* Fuzz target: lines through the public header (dggs_line_to_cells_size, dggs_line_to_cells, its grow protocol).
 *
 * The geodesics come from a spherical solver written here (great circles on a sphere of WGS84's major radius):
 * the tracer takes whatever curve its solver gives, so the contract checked holds for any: the first cell holds
 * the first point, every cell is valid and at the level, consecutive cells are edge neighbours and never equal,
 * and the count fits the buffer; a buffer too small gives DGGS_E_BUFFER and a capacity that works. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "dggs.h"

#define REQUIRE(cond)         \
    do {                      \
        if (!(cond)) abort(); \
    } while (0)

#define RADIUS 6378137.0
#define DEG (3.14159265358979323846 / 180.0)

static void sphere_inverse(const void *g, double lat1, double lng1, double lat2, double lng2, double *s12,
                           double *azi1, double *azi2) {
    (void)g;
    double p1 = lat1 * DEG, p2 = lat2 * DEG, dl = (lng2 - lng1) * DEG;
    double a = sin((p2 - p1) / 2), b = sin(dl / 2);
    double h = a * a + cos(p1) * cos(p2) * b * b;
    *s12 = 2 * RADIUS * asin(sqrt(fmin(1.0, h)));
    *azi1 = atan2(sin(dl) * cos(p2), cos(p1) * sin(p2) - sin(p1) * cos(p2) * cos(dl)) / DEG;
    *azi2 = atan2(sin(dl) * cos(p1), -cos(p2) * sin(p1) + sin(p2) * cos(p1) * cos(dl)) / DEG;
}

static void sphere_direct(const void *g, double lat1, double lng1, double azi1, double s12, double *lat2,
                          double *lng2, double *azi2) {
    (void)g;
    double p1 = lat1 * DEG, t = azi1 * DEG, d = s12 / RADIUS;
    double sp2 = sin(p1) * cos(d) + cos(p1) * sin(d) * cos(t);
    double p2 = asin(fmax(-1.0, fmin(1.0, sp2)));
    double l2 = lng1 * DEG + atan2(sin(t) * sin(d) * cos(p1), cos(d) - sin(p1) * sp2);
    *lat2 = p2 / DEG;
    *lng2 = remainder(l2 / DEG, 360.0);
    double back = atan2(sin(t) * cos(p1), cos(d) * cos(p1) * cos(t) - sin(p1) * sin(d));
    *azi2 = back / DEG;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    if (size < 3) return 0;
    int level = (int)(data[0] % 16) - 1; /* -1..14 */
    dggs_projection proj = (data[1] & 1) ? DGGS_IVEA : DGGS_ISEA;
    double scale = (data[1] & 2) ? 1.0 : 0.05; /* long lines, or short ones (many cells at a fine level) */
    size_t n = 1 + data[2] % 5;
    double pts[10];
    size_t pos = 3;
    for (size_t i = 0; i < n; i++) {
        unsigned a = pos + 1 < size ? data[pos] | (data[pos + 1] << 8) : 0;
        unsigned b = pos + 3 < size ? data[pos + 2] | (data[pos + 3] << 8) : 0;
        pos += 4;
        pts[2 * i] = (i ? pts[0] : 0.0) + (180.0 * a / 65535.0 - 90.0) * (i ? scale : 1.0);
        pts[2 * i + 1] = (i ? pts[1] : 0.0) + (360.0 * b / 65535.0 - 180.0) * (i ? scale : 1.0);
        pts[2 * i] = fmax(-90.0, fmin(90.0, pts[2 * i]));
    }
    if (level > 9 && scale == 1.0) level = 9; /* bound the work of one input */
    dggs_geodesic geod = {sphere_inverse, sphere_direct, NULL};
    size_t max_cells = 0, work_size = 0;
    dggs_error e = dggs_line_to_cells_size(pts, n, level, &geod, &max_cells, &work_size);
    if (e != DGGS_OK) {
        REQUIRE(e == DGGS_E_LEVEL);
        return 0;
    }
    void *work = malloc(work_size ? work_size : 1);
    size_t capacity = (data[1] & 4) ? 1 : max_cells; /* sometimes start too small: the grow protocol */
    dggs_cell *out = malloc((capacity ? capacity : 1) * sizeof *out);
    REQUIRE(work != NULL && out != NULL);
    size_t count = 0;
    for (int round = 0; round < 40; round++) {
        e = dggs_line_to_cells(pts, n, level, proj, &geod, work, work_size, out, capacity, &count);
        if (e != DGGS_E_BUFFER) break;
        REQUIRE(count > capacity);
        capacity = count;
        free(out);
        out = malloc(capacity * sizeof *out);
        REQUIRE(out != NULL);
    }
    REQUIRE(e == DGGS_OK || e == DGGS_E_FAILED);
    if (e == DGGS_OK) {
        REQUIRE(count >= 1 && count <= capacity);
        dggs_cell first = 0;
        REQUIRE(dggs_latlng_to_cell(pts[0], pts[1], level, proj, &first) == DGGS_OK && out[0] == first);
        for (size_t i = 0; i < count; i++) {
            REQUIRE(dggs_is_valid_cell(out[i]) && dggs_get_level(out[i]) == level);
            if (i) {
                int adjacent = 0;
                REQUIRE(out[i] != out[i - 1]);
                REQUIRE(dggs_are_neighbor_cells(out[i - 1], out[i], &adjacent) == DGGS_OK && adjacent);
            }
        }
    }
    free(out);
    free(work);
    return 0;
}
