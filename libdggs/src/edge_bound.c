/* Points per edge: how many points each edge of a cell needs, from a bound on its bulge, with no geodesic call.
 *
 * A cell's edge is straight on the face plane and curved on the globe. Drawn through d evenly spaced points
 * joined by geodesics (what pyproj.Geod and every GIS measure), it leaves each piece a bulge that shrinks as
 * 1 / (d + 1)^2 (halving a smooth arc quarters its sagitta), so one number per edge, the bulge b of the edge
 * against the geodesic of its corners, sets every d: (d + 1)^2 >= b / tolerance for a distance, and, since
 * each piece's lune is at most 2/3 of its bulge times its length (a parabolic segment), (d + 1)^2 >=
 * (2/3) sum(b L) / (A area_tolerance) for the cell's area A (opposite bulges not allowed to cancel).
 *
 * b is measured on the authalic sphere the grid is drawn on: the distance of the edge's true midpoint from the
 * great circle through its corners (a dot product), which is exact arithmetic on points the kernel computes
 * anyway. On WGS84 the geodesic is not the image of that great circle; the difference is bounded by
 *   b_WGS84 <= (1 + DGGS_BULGE_RATIO) b_sphere + DGGS_BULGE_FLOOR L^2 / R
 * (for bulges over 1 mm: below, the rounding of the points themselves, ~1e-6 m, is what any measurement sees)
 * with the constants measured against pyproj.Geod on every cell of levels 0-8 and random cells of levels 9-28 of
 * both projections by libdggs/tools/gen_edge_bound.py (which writes them) and rechecked by
 * tests/index/test_edge_bound.py. */
#include "edge_bound.h"

#include <math.h>
#include <stdbool.h>

#include "bits.h"
#include "edge_bound_tables.h"
#include "geometry.h"
#include "points.h"
#include "tables.h"

#define EDGE_PI 3.14159265358979323846

static double edge_dot(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/* Cell area on the authalic sphere, m^2 (the WGS84 ellipsoid's over the level's cell count). */
static double edge_cell_area(int level) {
    double n = 20.0;
    if (level >= 1) n = 120.0 * pow(3.0, (double)(level - 1));
    return 4.0 * EDGE_PI * DGGS_AUTHALIC_RADIUS * DGGS_AUTHALIC_RADIUS / n;
}

void dggs_edge_bounds_of(dggs_projection proj, uint64_t cell, double bulge_m[3], double length_m[3]) {
    double ring[12]; /* (lat, lng): corner, midpoint, corner, midpoint, corner, midpoint */
    dggs_one_boundary(proj, cell, 1, ring, 0);
    double c[3][3], m[3][3];
    for (int i = 0; i < 3; i++) {
        dggs_geodetic_to_unit(ring[4 * i], ring[4 * i + 1], c[i]);
        dggs_geodetic_to_unit(ring[4 * i + 2], ring[4 * i + 3], m[i]);
    }
    const double r = DGGS_AUTHALIC_RADIUS;
    for (int i = 0; i < 3; i++) {
        const double *a = c[i], *b = c[(i + 1) % 3];
        double n[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
        double nn = sqrt(edge_dot(n, n));
        double d[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        double chord = sqrt(edge_dot(d, d));
        double length = 2.0 * r * asin(chord > 2.0 ? 1.0 : chord / 2.0);
        double off = nn > 0.0 ? fabs(edge_dot(m[i], n)) / nn : 0.0; /* sine of the midpoint's angle off the circle */
        double bulge = r * asin(off > 1.0 ? 1.0 : off);
        bulge_m[i] = (1.0 + DGGS_BULGE_RATIO) * bulge + DGGS_BULGE_FLOOR * length * length / r;
        length_m[i] = length * (1.0 + DGGS_LENGTH_RATIO);
    }
}

/* The least d >= 0 with (d + 1)^2 >= need, capped at DGGS_EDGE_POINTS_MAX. */
static int edge_count(double need) {
    if (!(need > 1.0)) return 0;
    double d = ceil(sqrt(need)) - 1.0;
    while ((d + 1.0) * (d + 1.0) < need) d += 1.0; /* sqrt's rounding */
    return d >= DGGS_EDGE_POINTS_MAX ? DGGS_EDGE_POINTS_MAX : (int)d;
}

/* Bound of a piece's bulge on WGS84 from its bulge and length on the authalic sphere (unit vectors a, b, m). */
static double edge_piece(const double a[3], const double b[3], const double m[3], double *length) {
    const double r = DGGS_AUTHALIC_RADIUS;
    double n[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    double nn = sqrt(edge_dot(n, n));
    double d[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    double chord = sqrt(edge_dot(d, d));
    double len = 2.0 * r * asin(chord > 2.0 ? 1.0 : chord / 2.0);
    double off = nn > 0.0 ? fabs(edge_dot(m, n)) / nn : 0.0;
    *length = len * (1.0 + DGGS_LENGTH_RATIO);
    return (1.0 + DGGS_BULGE_RATIO) * r * asin(off > 1.0 ? 1.0 : off) + DGGS_BULGE_FLOOR * len * len / r;
}

/* Whether `d` points per edge meet the tolerances, measured piece by piece: each drawn piece's bulge (its true
 * midpoint off the great circle of its ends) bounded as the whole edge's is. Where the projection bends unevenly
 * (by the icosahedron's vertices) the 1 / (d + 1)^2 law of the first guess errs, and this decides. */
static bool edge_points_meet(dggs_projection proj, uint64_t cell, int d, double tolerance_m, double area_limit) {
    double ring[2 * 3 * (2 * DGGS_EDGE_POINTS_MAX + 2)];
    int per = 2 * d + 2, rows = 3 * per;
    dggs_one_boundary(proj, cell, 2 * d + 1, ring, 0);
    double lune = 0.0, first[3], a[3], m[3], b[3];
    dggs_geodetic_to_unit(ring[0], ring[1], first);
    a[0] = first[0], a[1] = first[1], a[2] = first[2];
    for (int k = 1; k < rows; k += 2) {
        dggs_geodetic_to_unit(ring[2 * k], ring[2 * k + 1], m);
        if (k + 1 < rows)
            dggs_geodetic_to_unit(ring[2 * (k + 1)], ring[2 * (k + 1) + 1], b);
        else
            b[0] = first[0], b[1] = first[1], b[2] = first[2];
        double len, bulge = edge_piece(a, b, m, &len);
        if (tolerance_m > 0.0 && bulge > tolerance_m) return false;
        lune += (2.0 / 3.0) * bulge * len;
        a[0] = b[0], a[1] = b[1], a[2] = b[2];
    }
    return !(area_limit > 0.0) || lune <= area_limit;
}

int dggs_edge_points_of(dggs_projection proj, uint64_t cell, double tolerance_m, double area_tolerance) {
    double b[3], l[3];
    dggs_edge_bounds_of(proj, cell, b, l);
    int out = 0;
    if (tolerance_m > 0.0) {
        double worst = fmax(b[0], fmax(b[1], b[2]));
        int d = edge_count(worst / tolerance_m);
        out = d > out ? d : out;
    }
    if (area_tolerance > 0.0) {
        double lune = (2.0 / 3.0) * (b[0] * l[0] + b[1] * l[1] + b[2] * l[2]);
        int d = edge_count(lune / (edge_cell_area(dggs_level_of(cell)) * area_tolerance));
        out = d > out ? d : out;
    }
    double area_limit = area_tolerance > 0.0 ? edge_cell_area(dggs_level_of(cell)) * area_tolerance : 0.0;
    while (out < DGGS_EDGE_POINTS_MAX && !edge_points_meet(proj, cell, out, tolerance_m, area_limit)) {
        int next = out + 1 + out / 4;
        out = next > DGGS_EDGE_POINTS_MAX ? DGGS_EDGE_POINTS_MAX : next;
    }
    return out;
}

dggs_error dggs_cell_edge_bounds(dggs_cell cell, dggs_projection proj, double bulge_m[3], double length_m[3]) {
    if (!dggs_is_valid(cell)) return DGGS_E_CELL;
    if (proj != DGGS_ISEA && proj != DGGS_IVEA) return DGGS_E_PROJECTION;
    dggs_edge_bounds_of(proj, cell, bulge_m, length_m);
    return DGGS_OK;
}

dggs_error dggs_cell_edge_points(dggs_cell cell, dggs_projection proj, double tolerance_m, double area_tolerance,
                                 int *points) {
    if (!dggs_is_valid(cell)) return DGGS_E_CELL;
    if (proj != DGGS_ISEA && proj != DGGS_IVEA) return DGGS_E_PROJECTION;
    if (!(tolerance_m >= 0.0) || !(area_tolerance >= 0.0) || isinf(tolerance_m) || isinf(area_tolerance) ||
        (tolerance_m == 0.0 && area_tolerance == 0.0))
        return DGGS_E_DOMAIN;
    *points = dggs_edge_points_of(proj, cell, tolerance_m, area_tolerance);
    return DGGS_OK;
}
