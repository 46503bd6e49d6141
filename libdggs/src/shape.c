/* Cells as dggs.cell_to_polygon draws them (shape.h): index/_shapes.py's ring_to_geometry in C. */
#include "shape.h"

#include <string.h>

#include "points.h"

bool dggs_ring_is_special(const double *lng_lat, int64_t rows) {
    for (int64_t i = 0; i < rows; i++) {
        if (fabs(lng_lat[2 * i + 1]) > 89.0) return true;
        if (i + 1 < rows && fabs(lng_lat[2 * i + 2] - lng_lat[2 * i]) > 90.0) return true;
    }
    return false;
}

int64_t dggs_cell_ring_room(int densify) { return 2 * (3 * (int64_t)(densify + 1) + DGGS_SPECIAL_EXTRA) + 8; }

int64_t dggs_cell_ring(dggs_projection proj, uint64_t cell, int densify, double *ring, double *tmp,
                       bool *special_out) {
    int64_t rows = dggs_boundary_rows(densify, 1);
    if (rows < 2) return 0; /* cannot happen: 3 (densify + 1) + 1 rows */
    dggs_one_boundary(proj, cell, densify, tmp, 1);
    bool special = dggs_ring_is_special(tmp, rows);
    if (special_out) *special_out = special;
    if (!special) {
        memcpy(ring, tmp, (size_t)(rows - 1) * 2 * sizeof(double));
        return rows - 1;
    }
    int m = dggs_special_ring(proj, cell, densify, tmp, dggs_special_ring_rows(densify)); /* (lat, lng) rows */
    /* _pole_pairs: every point at a pole given as two, arriving and leaving longitude */
    int64_t k = 0;
    /* the second half of ring, as scratch for latitudes */
    double *xs = ring, *ys = ring + dggs_cell_ring_room(densify);
    for (int i = 0; i < m;) {
        double lat = tmp[2 * i], lng = tmp[2 * i + 1];
        if (fabs(fabs(lat) - 90.0) < DGGS_POLE_TOL) {
            double pole = copysign(90.0, lat);
            if (i + 1 < m && fabs(fabs(tmp[2 * i + 2]) - 90.0) < DGGS_POLE_TOL) {
                xs[k] = lng, ys[k++] = pole;
                xs[k] = tmp[2 * i + 3], ys[k++] = pole;
                i += 2;
            } else {
                xs[k] = tmp[2 * (i > 0 ? i - 1 : m - 1) + 1], ys[k++] = pole;
                xs[k] = tmp[2 * ((i + 1) % m) + 1], ys[k++] = pole;
                i += 1;
            }
        } else {
            xs[k] = lng, ys[k++] = lat;
            i += 1;
        }
    }
    /* ring_to_geometry: steps under 180 degrees, west along the North Pole and east along the South */
    double x0 = xs[0], sum = 0.0, winding = 0.0, ysum = 0.0;
    for (int64_t i = 0; i < k; i++) {
        int64_t j = (i + 1) % k;
        double raw = xs[j] - xs[i];
        double step = dggs_pymod(raw + 180.0, 360.0) - 180.0;
        if (fabs(ys[i]) == 90.0 && ys[j] == ys[i])
            step = ys[i] > 0.0 ? -dggs_pymod(-raw, 360.0) : dggs_pymod(raw, 360.0);
        tmp[i] = step;
        winding += step;
        ysum += ys[i];
    }
    for (int64_t i = 0; i < k; i++) { /* xs[0] + cumsum of the steps before */
        double x = x0 + sum;
        sum += tmp[i];
        tmp[k + 2 * i] = x, tmp[k + 2 * i + 1] = ys[i];
    }
    memcpy(ring, tmp + k, (size_t)k * 2 * sizeof(double));
    if (fabs(winding) > 180.0) { /* round a pole: close it over the pole */
        double pole = ysum / (double)k > 0.0 ? 90.0 : -90.0, y0 = ring[1];
        ring[2 * k] = ring[2 * (k - 1)], ring[2 * k + 1] = pole;
        ring[2 * k + 2] = x0 + winding, ring[2 * k + 3] = pole;
        ring[2 * k + 4] = x0 + winding, ring[2 * k + 5] = y0;
        k += 3;
    }
    return k;
}

/* ---- the split at +-180 (ring_to_geometry's windows) ---- */

/* Sutherland-Hodgman: the points of ring (in, n) on the kept side of the vertical line x = at (keep_right: x >=
 * at, else x <= at) into out (room 2 n points); the count. */
static int64_t clip_x(const double *in, int64_t n, double at, bool keep_right, double *out) {
    int64_t m = 0;
    for (int64_t i = 0; i < n; i++) {
        const double *a = in + 2 * i, *b = in + 2 * ((i + 1) % n);
        bool ina = keep_right ? a[0] >= at : a[0] <= at, inb = keep_right ? b[0] >= at : b[0] <= at;
        if (ina) out[2 * m] = a[0], out[2 * m + 1] = a[1], m++;
        if (ina != inb && a[0] != at && b[0] != at) { /* a strict crossing (a point on the line is kept as is) */
            double t = (at - a[0]) / (b[0] - a[0]);
            out[2 * m] = at, out[2 * m + 1] = a[1] + t * (b[1] - a[1]), m++;
        }
    }
    return m;
}

/* Drop points equal to the one before (the last compared with the first); the count left. */
static int64_t drop_repeats(double *ring, int64_t n) {
    int64_t m = 0;
    for (int64_t i = 0; i < n; i++) {
        const double *prev = m ? ring + 2 * (m - 1) : NULL;
        if (prev && prev[0] == ring[2 * i] && prev[1] == ring[2 * i + 1]) continue;
        ring[2 * m] = ring[2 * i], ring[2 * m + 1] = ring[2 * i + 1], m++;
    }
    while (m > 1 && ring[0] == ring[2 * (m - 1)] && ring[1] == ring[2 * (m - 1) + 1]) m--;
    return m;
}

/* Twice the signed area (shoelace, about the first point: exactly 0 for points on one vertical line). */
static double twice_area(const double *ring, int64_t n) {
    double s = 0.0, x0 = ring[0], y0 = ring[1];
    for (int64_t i = 1; i + 1 < n; i++)
        s += (ring[2 * i] - x0) * (ring[2 * i + 3] - y0) - (ring[2 * i + 2] - x0) * (ring[2 * i + 1] - y0);
    return s;
}

/* Reverse a ring in place, keeping its first point first (shapely's orient). */
static void reverse_ring(double *ring, int64_t n) {
    for (int64_t i = 1, j = n - 1; i < j; i++, j--) {
        double x = ring[2 * i], y = ring[2 * i + 1];
        ring[2 * i] = ring[2 * j], ring[2 * i + 1] = ring[2 * j + 1];
        ring[2 * j] = x, ring[2 * j + 1] = y;
    }
}

/* Layout of dggs_cell_to_polygon's buffer, in points of R = dggs_cell_ring_room: the ring (2 R, as dggs_cell_ring
 * asks), its scratch (2 R), one clip (2 R) and a second (4 R), then the parts (at most 4 R each). */
static int64_t polygon_room(int densify) { return (10 + 4 * DGGS_MAX_POLYGON_PARTS) * dggs_cell_ring_room(densify); }

dggs_error dggs_cell_to_polygon_size(int densify, size_t *points) {
    if (densify < 0 || densify > DGGS_MAX_DENSIFY) return DGGS_E_DOMAIN;
    *points = (size_t)polygon_room(densify);
    return DGGS_OK;
}

dggs_error dggs_cell_to_polygon(dggs_cell cell, int densify, dggs_projection proj, double *lng_lat, size_t size,
                                size_t part_sizes[DGGS_MAX_POLYGON_PARTS], int *num_parts) {
    if (!dggs_is_valid_cell(cell)) return DGGS_E_CELL;
    if (densify < 0 || densify > DGGS_MAX_DENSIFY) return DGGS_E_DOMAIN;
    if (proj != DGGS_ISEA && proj != DGGS_IVEA) return DGGS_E_PROJECTION;
    int64_t room = dggs_cell_ring_room(densify);
    if (size < (size_t)polygon_room(densify)) return DGGS_E_BUFFER;
    double *ring = lng_lat, *tmp = ring + 4 * room, *half = tmp + 4 * room, *piece = half + 4 * room;
    double *parts = piece + 8 * room;
    bool special;
    int64_t n = dggs_cell_ring(proj, cell, densify, ring, tmp, &special);
    double lo = INFINITY, hi = -INFINITY;
    for (int64_t i = 0; i < n; i++) {
        if (ring[2 * i] < lo) lo = ring[2 * i];
        if (ring[2 * i] > hi) hi = ring[2 * i];
    }
    int k0 = 0, k1 = 0;
    if (!(lo >= -180.0 && hi <= 180.0)) {
        k0 = (int)floor((lo + 180.0) / 360.0);
        k1 = (int)floor((hi + 180.0) / 360.0);
    }
    if (k1 - k0 + 1 > DGGS_MAX_POLYGON_PARTS) return DGGS_E_FAILED; /* a ring over 3 turns wide: never seen */
    int count = 0;
    int64_t used = 0;
    for (int k = k0; k <= k1; k++) {
        double shift = 360.0 * k;
        const double *src = ring;
        int64_t m = n;
        if (k0 != k1) { /* the window [-180 + 360 k, 180 + 360 k], shifted back by 360 k */
            int64_t h = clip_x(ring, n, shift - 180.0, true, half);
            m = clip_x(half, h, shift + 180.0, false, piece);
            for (int64_t i = 0; i < m; i++) piece[2 * i] -= shift;
            m = drop_repeats(piece, m);
            src = piece;
        }
        if (m < 3) continue;
        double *out = parts + 2 * used;
        memmove(out, src, (size_t)m * 2 * sizeof(double));
        if (special) { /* orient(g, 1.0): counter-clockwise exteriors, pieces of no area dropped */
            double a = twice_area(out, m);
            if (a == 0.0) continue;
            if (a < 0.0) reverse_ring(out, m);
        }
        part_sizes[count++] = (size_t)m;
        used += m;
    }
    memmove(lng_lat, parts, (size_t)used * 2 * sizeof(double));
    *num_parts = count;
    return DGGS_OK;
}
