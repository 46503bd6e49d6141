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
#include <string.h>

#include "bits.h"
#include "dmath.h"
#include "edge_bound_tables.h"
#include "geometry.h"
#include "points.h"
#include "tables.h"

#define EDGE_PI 3.14159265358979323846
/* How evenly an edge must bend for the 1 / (d + 1)^2 law (edge_even): its quarter-point bulges within this
 * fraction of the midpoint's, where a curvature varying by under ~20 % along the edge keeps every piece's bulge
 * within DGGS_EVEN_SAFETY of the law's. */
#define DGGS_EVEN 0.05
#define DGGS_EVEN_SAFETY 1.5
/* The same for the area, where the pieces' errors average out along the edge (their lunes add up). */
#define DGGS_EVEN_AREA_SAFETY 1.1
/* Not modelled: the boundary points' own precision (the projection's inverse; bulges of 0.02-0.3 mm measured on
 * level 24-28 edges, which are straight to far less). No count can go below it, so where 1e-6 of a cell's area is
 * under it (levels 24-28, cells under 50 m^2) "exact" asks for DGGS_EDGE_POINTS_MAX (docs/storage.md). */
/* Bulges this small (m) are the points' rounding (gen_edge_bound.py's NOISE is 1e-3): not compared. */
#define DGGS_EVEN_FLOOR 1e-6

static double edge_dot(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/* Cell area on the authalic sphere, m^2 (the WGS84 ellipsoid's over the level's cell count). */
static double edge_cell_area(int level) {
    double n = 20.0;
    if (level >= 1) n = 120.0 * pow(3.0, (double)(level - 1));
    return 4.0 * EDGE_PI * DGGS_AUTHALIC_RADIUS * DGGS_AUTHALIC_RADIUS / n;
}

/* The least d >= 0 with (d + 1)^2 >= need, capped at DGGS_EDGE_POINTS_MAX. */
static int edge_count(double need) {
    if (!(need > 1.0)) return 0;
    double d = ceil(sqrt(need)) - 1.0;
    while ((d + 1.0) * (d + 1.0) < need) d += 1.0; /* sqrt's rounding */
    return d >= DGGS_EDGE_POINTS_MAX ? DGGS_EDGE_POINTS_MAX : (int)d;
}

/* A piece's bulge on the authalic sphere, m (its point m off the great circle of its ends a, b: unit vectors), and
 * its length into *length. */
static double edge_raw(const double a[3], const double b[3], const double m[3], double *length) {
    const double r = DGGS_AUTHALIC_RADIUS;
    double n[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    double nn = sqrt(edge_dot(n, n));
    double d[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    double chord = sqrt(edge_dot(d, d));
    *length = 2.0 * r * dggs_asin(chord > 2.0 ? 1.0 : chord / 2.0);
    double off = nn > 0.0 ? fabs(edge_dot(m, n)) / nn : 0.0;
    return r * dggs_asin(off > 1.0 ? 1.0 : off);
}

/* edge_raw's bulge and length bounded on WGS84 (the constants of edge_bound_tables.h). */
static double edge_piece(const double a[3], const double b[3], const double m[3], double *length) {
    double len, raw = edge_raw(a, b, m, &len);
    *length = len * (1.0 + DGGS_LENGTH_RATIO);
    return (1.0 + DGGS_BULGE_RATIO) * raw + DGGS_BULGE_FLOOR * len * len / DGGS_AUTHALIC_RADIUS;
}

/* The cell's boundary points as unit vectors on the authalic sphere: dggs_one_boundary's points (the same planar
 * points, x0 + j (x1 - x0) / step along each edge, step = densify + 1) straight from the projection's inverse,
 * without the round trip through (lat, lng) that dggs_geodetic_to_unit would undo (it costs more than the
 * inverse). p holds 3 (densify + 1) rows. */
static void edge_units(dggs_projection proj, uint64_t cell, int densify, double (*p)[3]) {
    double t[6], x[DGGS_INVERSE_LANES], y[DGGS_INVERSE_LANES];
    int face = dggs_corners(cell, t), step = densify + 1, m = 0, start = 0;
    for (int i = 0; i < 3; i++) {
        double x0 = t[2 * i], y0 = t[2 * i + 1], x1 = t[(2 * i + 2) % 6], y1 = t[(2 * i + 3) % 6];
        double dx = (x1 - x0) / step, dy = (y1 - y0) / step;
        for (int j = 0; j < step; j++) {
            x[m] = x0 + j * dx;
            y[m++] = y0 + j * dy;
            if (m == DGGS_INVERSE_LANES) { /* several at once: their chains overlap (dggs_proj_inverse_many) */
                dggs_proj_inverse_many(proj, face, m, x, y, p + start);
                start += m;
                m = 0;
            }
        }
    }
    if (m > 0) dggs_proj_inverse_many(proj, face, m, x, y, p + start);
}

void dggs_edge_bounds_of(dggs_projection proj, uint64_t cell, double bulge_m[3], double length_m[3]) {
    double p[6][3]; /* corner, midpoint, corner, midpoint, corner, midpoint */
    edge_units(proj, cell, 1, p);
    for (int i = 0; i < 3; i++) bulge_m[i] = edge_piece(p[2 * i], p[(2 * i + 2) % 6], p[2 * i + 1], &length_m[i]);
}

/* Whether `d` points per edge meet the tolerances, measured piece by piece: each drawn piece's bulge (its true
 * midpoint off the great circle of its ends) bounded as the whole edge's is. Where the projection bends unevenly
 * (by the icosahedron's vertices) the 1 / (d + 1)^2 law of the first guess errs, and this decides. */
static bool edge_points_meet(dggs_projection proj, uint64_t cell, int d, double tolerance_m, double area_limit) {
    double p[3 * (2 * DGGS_EDGE_POINTS_MAX + 2)][3];
    int rows = 3 * (2 * d + 2);
    edge_units(proj, cell, 2 * d + 1, p);
    double lune = 0.0;
    for (int k = 1; k < rows; k += 2) { /* piece (k - 1, k + 1) with its midpoint k; the last ends at row 0 */
        double len, bulge = edge_piece(p[k - 1], p[(k + 1) % rows], p[k], &len);
        if (tolerance_m > 0.0 && bulge > tolerance_m) return false;
        lune += (2.0 / 3.0) * bulge * len;
    }
    return !(area_limit > 0.0) || lune <= area_limit;
}

/* For an area asked: d rounded up so that d + 1 is a power of two (at most DGGS_EDGE_POINTS_MAX - 1). Two cells
 * drawn with different counts then share the coarser one's points on their common edge (the finer one's pieces
 * halve the coarser one's), so the union of area-exact polygons leaves no sliver wider than the coarser one's own
 * lune: they tile, up to the tolerance (the overlaps fill's cover test, tests/index/test_fill_modes.py). */
static int edge_ladder(int d) {
    int pieces = 1;
    while (pieces < d + 1 && pieces < DGGS_EDGE_POINTS_MAX) pieces *= 2;
    return pieces - 1;
}

/* Whether the edges bend evenly enough for the 1 / (d + 1)^2 law: the bulges at a quarter and three quarters of
 * each edge within DGGS_EVEN of 3/4 of the midpoint's (a parabola's; a circle's arc to within its sagitta), the
 * midpoint bulges into b[3] and the lengths into l[3]. Where the projection bends unevenly (by the icosahedron's
 * vertices, across the sectors of Snyder's construction) they are not, and edge_points_meet decides instead.
 * p holds the boundary's 12 unit vectors (edge_units with densify 3: corner, quarter, half, three quarters of each
 * edge). Each edge's great circle and length are computed once for its three bulges (edge_raw's arithmetic, the
 * same numbers). */
static bool edge_even(const double (*p)[3], double b[3], double l[3]) {
    const double r = DGGS_AUTHALIC_RADIUS;
    bool even = true;
    for (int i = 0; i < 3; i++) {
        const double *a = p[4 * i], *z = p[(4 * i + 4) % 12];
        double n[3] = {a[1] * z[2] - a[2] * z[1], a[2] * z[0] - a[0] * z[2], a[0] * z[1] - a[1] * z[0]};
        double nn = sqrt(edge_dot(n, n));
        double d[3] = {z[0] - a[0], z[1] - a[1], z[2] - a[2]};
        double chord = sqrt(edge_dot(d, d));
        double len = 2.0 * r * dggs_asin(chord > 2.0 ? 1.0 : chord / 2.0);
        double raw[3]; /* the quarter, half and three-quarter points' bulges, edge_raw's */
        for (int k = 0; k < 3; k++) {
            double off = nn > 0.0 ? fabs(edge_dot(p[4 * i + 1 + k], n)) / nn : 0.0;
            raw[k] = r * dggs_asin(off > 1.0 ? 1.0 : off);
        }
        double q1 = raw[0], half = raw[1], q3 = raw[2];
        /* edge_piece's bound of the half-point piece */
        l[i] = len * (1.0 + DGGS_LENGTH_RATIO);
        b[i] = (1.0 + DGGS_BULGE_RATIO) * half + DGGS_BULGE_FLOOR * len * len / DGGS_AUTHALIC_RADIUS;
        double slack = DGGS_EVEN * half + DGGS_EVEN_FLOOR;
        if (fabs(q1 - 0.75 * half) > slack || fabs(q3 - 0.75 * half) > slack) even = false;
    }
    return even;
}

/* dggs_edge_points_of on the boundary's 12 unit vectors p (edge_units with densify 3), which it fills. */
static int edge_points_from(dggs_projection proj, uint64_t cell, double tolerance_m, double area_tolerance,
                            double (*p)[3]) {
    double b[3], l[3];
    edge_units(proj, cell, 3, p);
    bool even = edge_even((const double(*)[3])p, b, l);
    int out = 0;
    if (tolerance_m > 0.0) {
        double worst = fmax(b[0], fmax(b[1], b[2]));
        int d = edge_count(DGGS_EVEN_SAFETY * worst / tolerance_m);
        out = d > out ? d : out;
    }
    double area_limit = area_tolerance > 0.0 ? edge_cell_area(dggs_level_of(cell)) * area_tolerance : 0.0;
    if (area_limit > 0.0) {
        double lune = (2.0 / 3.0) * (b[0] * l[0] + b[1] * l[1] + b[2] * l[2]);
        int d = edge_count(DGGS_EVEN_AREA_SAFETY * lune / area_limit);
        out = d > out ? d : out;
    }
    if (!even) {
        while (out < DGGS_EDGE_POINTS_MAX && !edge_points_meet(proj, cell, out, tolerance_m, area_limit)) {
            int next = out + 1 + out / 4;
            out = next > DGGS_EDGE_POINTS_MAX ? DGGS_EDGE_POINTS_MAX : next;
        }
    }
    if (area_limit > 0.0) return edge_ladder(out);
    return out;
}

int dggs_edge_points_of(dggs_projection proj, uint64_t cell, double tolerance_m, double area_tolerance) {
    double p[12][3];
    return edge_points_from(proj, cell, tolerance_m, area_tolerance, p);
}

/* Row k of the closed (lng, lat) ring, from the unit vector q: dggs_edge_points' conversion. */
static void edge_ring_row(const double q[3], double *ring, int k) {
    double lat, lng;
    dggs_unit_to_geodetic(q[0], q[1], q[2], &lat, &lng);
    ring[2 * k] = lng;
    ring[2 * k + 1] = lat;
}

int dggs_edge_ring_of(dggs_projection proj, uint64_t cell, double tolerance_m, double area_tolerance, double *ring,
                      bool *drawn) {
    double p[12][3];
    int d = edge_points_from(proj, cell, tolerance_m, area_tolerance, p);
    /* dggs_one_boundary's point j of an edge with step d + 1 is x0 + j (x1 - x0) / (d + 1); with d + 1 = 1, 2 or 4
     * that is, bit for bit, point 4 j / (d + 1) of the count's step 4 (dividing by 2 or 4 and multiplying by 2 are
     * exact), so the count's unit vectors are the ring's. */
    bool reused = d == 0 || d == 1 || d == 3;
    if (drawn) *drawn = reused;
    if (!reused) return d;
    int stride = 4 / (d + 1), rows = 3 * (d + 1);
    for (int k = 0; k < rows; k++) edge_ring_row(p[k * stride], ring, k);
    ring[2 * rows] = ring[0]; /* closed */
    ring[2 * rows + 1] = ring[1];
    return d;
}

dggs_error dggs_cell_edge_bounds(dggs_cell cell, dggs_projection proj, double bulge_m[3], double length_m[3]) {
    if (!dggs_is_valid(cell)) return DGGS_E_CELL;
    if (proj != DGGS_ISEA && proj != DGGS_IVEA) return DGGS_E_PROJECTION;
    dggs_edge_bounds_of(proj, cell, bulge_m, length_m);
    return DGGS_OK;
}

dggs_error dggs_cell_edge_ring(dggs_cell cell, dggs_projection proj, double tolerance_m, double area_tolerance,
                               double *lng_lat, size_t size, int *points) {
    int d;
    dggs_error e = dggs_cell_edge_points(cell, proj, tolerance_m, area_tolerance, &d);
    if (e != DGGS_OK) return e;
    *points = d;
    size_t need = (size_t)dggs_boundary_rows(d, 1);
    if (size < need) return DGGS_E_BUFFER;
    double ring[2 * DGGS_EDGE_RING_REUSED];
    bool drawn;
    dggs_edge_ring_of(proj, cell, tolerance_m, area_tolerance, ring, &drawn);
    if (drawn)
        memcpy(lng_lat, ring, need * 2 * sizeof(double));
    else
        dggs_one_boundary(proj, cell, d, lng_lat, 1);
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
