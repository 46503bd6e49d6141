/* Directed edges between edge neighbours (index/_kernel/edges.py, ivea_edges.py): see edges.h. */
#include "edges.h"

#include <math.h>

#include "bits.h"
#include "dmath.h"
#include "edges_tables.h"
#include "geometry.h"
#include "grid.h"
#include "points.h"

/* edge_of: EDGE_BIT | cell | (direction + 1) << shift(level + 1); 0 at level 28. */
uint64_t dggs_edge_of(uint64_t cell, int direction) {
    int level = dggs_level_of(cell);
    if (level >= DGGS_MAX_LEVEL) return 0;
    return DGGS_EDGE_BIT | cell | ((uint64_t)(direction + 1) << dggs_shift_of(level + 1));
}

/* split: the shadow (sign bit cleared) is a cell one level finer; its parent is the origin, its last digit the
 * direction. */
void dggs_edges_split(uint64_t edge, uint64_t *origin, int *level, int *direction) {
    uint64_t shadow = edge & ~DGGS_EDGE_BIT;
    int lv = dggs_level_of(shadow);
    *origin = dggs_parent_at(shadow, lv - 1);
    *level = lv - 1;
    *direction = dggs_digit_of(shadow, lv);
}

void dggs_origin_edges(uint64_t cell, uint64_t out[3]) {
    for (int d = 0; d < 3; d++) out[d] = dggs_edge_of(cell, d);
}

uint64_t dggs_pair_edges(uint64_t a, uint64_t b) {
    int level = dggs_level_of(a);
    for (int d = 0; d < 3; d++) {
        if (dggs_neighbour(a, level, d) == b && a != b) return dggs_edge_of(a, d);
    }
    return 0;
}

void dggs_edges_ends(uint64_t edge, uint64_t *origin, uint64_t *destination) {
    uint64_t o;
    int level, d;
    dggs_edges_split(edge, &o, &level, &d);
    *origin = o;
    *destination = level < 0 ? 0 : dggs_neighbour(o, level, d); /* a level-0 shadow: no edge (see edges.h) */
}

uint64_t dggs_one_origin(uint64_t edge) {
    uint64_t o;
    int level, d;
    dggs_edges_split(edge, &o, &level, &d);
    return o;
}

uint64_t dggs_one_destination(uint64_t edge) {
    uint64_t o;
    int level, d;
    dggs_edges_split(edge, &o, &level, &d);
    return level < 0 ? 0 : dggs_neighbour(o, level, d);
}

uint64_t dggs_edges_reverse(uint64_t edge) {
    uint64_t o;
    int level, d;
    dggs_edges_split(edge, &o, &level, &d);
    if (level < 0) return 0;
    uint64_t dest = dggs_neighbour(o, level, d);
    for (int k = 0; k < 3; k++) {
        if (dggs_neighbour(dest, level, k) == o) return dggs_edge_of(dest, k);
    }
    return 0;
}

/* The edge's planar ends: corners d and d + 1 of the origin's counter-clockwise corners; -1 for a level-0
 * shadow (no edge). */
static int edge_ends_planar(uint64_t edge, double *x0, double *y0, double *x1, double *y1) {
    uint64_t o;
    int level, d;
    dggs_edges_split(edge, &o, &level, &d);
    if (level < 0 || d < 0) return -1;
    double t[6];
    int face = dggs_corners(o, t);
    int e = (d + 1) % 3;
    *x0 = t[2 * d];
    *y0 = t[2 * d + 1];
    *x1 = t[2 * e];
    *y1 = t[2 * e + 1];
    return face;
}

/* _one_length: see edges.h. nu is the prime vertical radius of curvature; (ex, ey, ez) the point on the
 * ellipsoid, (px, py, pz) on the unit authalic sphere. */
void dggs_one_length(dggs_projection proj, uint64_t edge, int64_t pieces, double *metres, double *rads) {
    double x0, y0, x1, y1;
    int face = edge_ends_planar(edge, &x0, &y0, &x1, &y1);
    if (face < 0) {
        *metres = *rads = NAN;
        return;
    }
    int64_t n = 2 * pieces;
    double fine_m = 0.0, fine_r = 0.0, coarse_m = 0.0, coarse_r = 0.0;
    double qx = 0.0, qy = 0.0, qz = 0.0, ux = 0.0, uy = 0.0, uz = 0.0; /* the previous point (ellipsoid, sphere) */
    double sx = 0.0, sy = 0.0, sz = 0.0, vx = 0.0, vy = 0.0, vz = 0.0; /* the previous even point */
    for (int64_t k = 0; k < n + 1; k++) {
        double t = (double)k / (double)n;
        double p[3];
        dggs_proj_inverse(proj, face, (1.0 - t) * x0 + t * x1, (1.0 - t) * y0 + t * y1, p);
        double px = p[0], py = p[1], pz = p[2];
        double lat, lng;
        dggs_unit_to_geodetic(px, py, pz, &lat, &lng);
        double phi = lat * DGGS_EDGES_RAD_PER_DEG, lam = lng * DGGS_EDGES_RAD_PER_DEG; /* numba's math.radians */
        double sp = dggs_sin(phi), cp = dggs_cos(phi);
        double nu = DGGS_EDGES_A / sqrt(1.0 - DGGS_EDGES_E2 * sp * sp);
        double ex = nu * cp * dggs_cos(lam), ey = nu * cp * dggs_sin(lam), ez = nu * (1.0 - DGGS_EDGES_E2) * sp;
        if (k) {
            fine_m += sqrt((ex - qx) * (ex - qx) + (ey - qy) * (ey - qy) + (ez - qz) * (ez - qz));
            fine_r += sqrt((px - ux) * (px - ux) + (py - uy) * (py - uy) + (pz - uz) * (pz - uz));
        }
        if (k % 2 == 0) {
            if (k) {
                coarse_m += sqrt((ex - sx) * (ex - sx) + (ey - sy) * (ey - sy) + (ez - sz) * (ez - sz));
                coarse_r += sqrt((px - vx) * (px - vx) + (py - vy) * (py - vy) + (pz - vz) * (pz - vz));
            }
            sx = ex, sy = ey, sz = ez, vx = px, vy = py, vz = pz;
        }
        qx = ex, qy = ey, qz = ez, ux = px, uy = py, uz = pz;
    }
    *metres = (4.0 * fine_m - coarse_m) / 3.0;
    *rads = (4.0 * fine_r - coarse_r) / 3.0;
}

void dggs_edges_one_boundary(dggs_projection proj, uint64_t edge, int64_t densify, double *out) {
    double x0, y0, x1, y1;
    int face = edge_ends_planar(edge, &x0, &y0, &x1, &y1);
    int64_t step = densify + 1;
    if (face < 0) {
        for (int64_t k = 0; k < 2 * (step + 1); k++) out[k] = NAN;
        return;
    }
    for (int64_t k = 0; k < step + 1; k++) {
        double t = (double)k / (double)step;
        double p[3];
        dggs_proj_inverse(proj, face, (1.0 - t) * x0 + t * x1, (1.0 - t) * y0 + t * y1, p);
        dggs_unit_to_geodetic(p[0], p[1], p[2], &out[2 * k], &out[2 * k + 1]);
    }
}

/* ---- the public verbs (dggs.h, "directed edges"): checked, over the functions above ---- */

int dggs_is_valid_directed_edge(uint64_t edge) {
    if (!(edge & DGGS_EDGE_BIT)) return 0;
    uint64_t shadow = edge & ~DGGS_EDGE_BIT;
    if (!dggs_is_valid(shadow) || dggs_level_of(shadow) < 1) return 0;
    return dggs_level_of(shadow) > 1 || dggs_digit_of(shadow, 1) <= 2; /* a level-0 origin: directions 0-2 only */
}

dggs_error dggs_cells_to_directed_edge(dggs_cell origin, dggs_cell destination, uint64_t *out) {
    if (!dggs_is_valid(origin) || !dggs_is_valid(destination)) return DGGS_E_CELL;
    if (dggs_level_of(origin) >= DGGS_MAX_LEVEL) return DGGS_E_LEVEL;
    uint64_t e = dggs_pair_edges(origin, destination);
    if (!e) return DGGS_E_DOMAIN;
    *out = e;
    return DGGS_OK;
}

dggs_error dggs_directed_edge_to_cells(uint64_t edge, dggs_cell out[2]) {
    if (!dggs_is_valid_directed_edge(edge)) return DGGS_E_EDGE;
    dggs_edges_ends(edge, &out[0], &out[1]);
    return DGGS_OK;
}

dggs_error dggs_get_directed_edge_origin(uint64_t edge, dggs_cell *out) {
    if (!dggs_is_valid_directed_edge(edge)) return DGGS_E_EDGE;
    *out = dggs_one_origin(edge);
    return DGGS_OK;
}

dggs_error dggs_get_directed_edge_destination(uint64_t edge, dggs_cell *out) {
    if (!dggs_is_valid_directed_edge(edge)) return DGGS_E_EDGE;
    *out = dggs_one_destination(edge);
    return DGGS_OK;
}

dggs_error dggs_origin_to_directed_edges(dggs_cell cell, uint64_t out[3]) {
    if (!dggs_is_valid(cell)) return DGGS_E_CELL;
    if (dggs_level_of(cell) >= DGGS_MAX_LEVEL) return DGGS_E_LEVEL;
    dggs_origin_edges(cell, out);
    return DGGS_OK;
}

dggs_error dggs_reverse_directed_edge(uint64_t edge, uint64_t *out) {
    if (!dggs_is_valid_directed_edge(edge)) return DGGS_E_EDGE;
    *out = dggs_edges_reverse(edge);
    return DGGS_OK;
}

dggs_error dggs_directed_edge_to_boundary(uint64_t edge, int densify, dggs_projection proj, double *latlng,
                                          size_t size) {
    if (!dggs_is_valid_directed_edge(edge)) return DGGS_E_EDGE;
    if (densify < 0 || densify > 100000) return DGGS_E_DOMAIN;
    if (proj != DGGS_ISEA && proj != DGGS_IVEA) return DGGS_E_PROJECTION;
    if (size < (size_t)densify + 2) return DGGS_E_BUFFER;
    dggs_edges_one_boundary(proj, edge, densify, latlng);
    return DGGS_OK;
}

/* which: 0 metres, 1 radians (index/edges.py's edge_length; km = metres * 1e-3 as it scales). */
static dggs_error edge_length(uint64_t edge, dggs_projection proj, int which, double *out) {
    if (!dggs_is_valid_directed_edge(edge)) return DGGS_E_EDGE;
    if (proj != DGGS_ISEA && proj != DGGS_IVEA) return DGGS_E_PROJECTION;
    double m, r;
    dggs_one_length(proj, edge, DGGS_EDGE_LENGTH_PIECES, &m, &r);
    *out = which ? r : m;
    return DGGS_OK;
}

dggs_error dggs_edge_length_rads(uint64_t edge, dggs_projection proj, double *out) {
    return edge_length(edge, proj, 1, out);
}

dggs_error dggs_edge_length_m(uint64_t edge, dggs_projection proj, double *out) {
    return edge_length(edge, proj, 0, out);
}

dggs_error dggs_edge_length_km(uint64_t edge, dggs_projection proj, double *out) {
    dggs_error err = edge_length(edge, proj, 0, out);
    if (err == DGGS_OK) *out = *out * 1e-3;
    return err;
}
