/* Points <-> 64-bit cell ids: location, planar corners, centres, boundaries, and the exact boundaries of the
 * few cells at a pole or across the antimeridian. A port of index/_kernel/points.py and ivea_points.py,
 * operation for operation: one C function per numba function, `proj` selecting Snyder's (ISEA) or IVEA's
 * forward and inverse (ivea_points.py is points.py recompiled with IVEA's projection).
 *
 * Inputs are assumed checked (valid ids, levels 0..28, densify >= 0) except where a function says otherwise:
 * dggs_one_point takes any coordinates (the null id 0 for a point not on the globe), dggs_centre_of any int64
 * (NaNs for a non-id). */
#ifndef DGGS_POINTS_H
#define DGGS_POINTS_H

#include <stdint.h>

#include "dggs.h"

/* _ON_EDGE: a pole this close (relative to the edge, planar) to a cell's edge lies on it. */
#define DGGS_ON_EDGE 1e-9
/* _POLE_LEAD: the direction in which an edge leaves a pole: the point this fraction of a densify step away. */
#define DGGS_POLE_LEAD 1e-4
/* SPECIAL_EXTRA: extra rows of a special ring: two per pole corner, one per antimeridian crossing. */
#define DGGS_SPECIAL_EXTRA 16

/* encode_point: the id of the level-`level` cell holding face-frame point (x, y) on `face`. */
uint64_t dggs_encode_point(int face, double x, double y, int level);
/* one_point: the id of the cell holding one point (geodetic degrees); the null id 0 for a point that is not
 * on the globe (a latitude outside -90..90 or NaN, a longitude not finite). */
uint64_t dggs_one_point(dggs_projection proj, double lat, double lng, int level);

/* triangle: the face (returned) and face-frame corners t = (ax, ay, bx, by, cx, cy) of a cell as Split (2:6)
 * labels them: a base cell's are its face's vertices; a finer cell's its 30-60-90 triangle (A, B, C). */
int dggs_triangle(uint64_t cell, double t[6]);
/* corners: triangle's corners, reordered (A, C, B) where that is the counter-clockwise order. */
int dggs_corners(uint64_t cell, double t[6]);

/* _one_centre: the centre (lat, lng) of a valid id: its planar centroid mapped back. */
void dggs_one_centre(dggs_projection proj, uint64_t cell, double *lat, double *lng);
/* centre_of: the centre of one id given as an int64 (the single-id entry); NaNs if it is no id. */
void dggs_centre_of(dggs_projection proj, int64_t cell, double *lat, double *lng);

/* _edge_points: write `step` points from (x0, y0) towards (x1, y1), straight on the face plane, into rows
 * start.. of `out` (rows of 2 doubles: (lat, lng), or (lng, lat) with `lnglat`). */
void dggs_edge_points(dggs_projection proj, double *out, int start, int face, double x0, double y0, double x1,
                      double y1, int step, int lnglat);
/* _one_boundary: the corners and `densify` points per edge into `out` (rows of 2 doubles): 3 (densify + 1)
 * rows of (lat, lng), or with `lnglat` 3 (densify + 1) + 1 rows of (lng, lat), closed. */
void dggs_one_boundary(dggs_projection proj, uint64_t cell, int densify, double *out, int lnglat);
/* Rows dggs_one_boundary writes. */
int dggs_boundary_rows(int densify, int lnglat);

/* _one_center_child: the descendant at `level` of a valid id holding its (planar) centre. */
uint64_t dggs_one_center_child(uint64_t cell, int level);

/* POLES: per face the face-frame (x, y) of a pole on its boundary and the pole's sign (0: none); a (20, 3)
 * row-major table, the same for both projections. */
const double *dggs_pole_table(void);
/* _lat_lng_at: (lat, lng) of the planar point at parameter t from (x0, y0) to (x1, y1) on `face`. */
void dggs_lat_lng_at(dggs_projection proj, int face, double x0, double y0, double x1, double y1, double t,
                     double *lat, double *lng);
/* _pole_on: parameter t in [0, 1) at which the face's pole lies on the planar segment, or -1. */
double dggs_pole_on(int face, double x0, double y0, double x1, double y1);
/* _edge_params: fill `ts` (step + 2 doubles) with a densified edge's parameters j / step (j = 0..step),
 * sorted, the pole's parameter `tp` among them where it falls inside a step; return how many. */
int dggs_edge_params(double *ts, int step, double tp);
/* _crossing: latitude where the curve from parameter lo (longitude lng_lo) to hi reaches +-180 (bisection). */
double dggs_crossing(dggs_projection proj, int face, double x0, double y0, double x1, double y1, double lo,
                     double hi, double lng_lo);
/* special_ring: write the (lat, lng) boundary of a cell with its exact pole and antimeridian points into
 * `out` (`rows` rows of 2 doubles; it needs dggs_special_ring_rows(densify)); return the count of rows
 * written, or -1 if `rows` is too small (never written past). */
int dggs_special_ring(dggs_projection proj, uint64_t cell, int densify, double *out, int rows);
/* 3 (densify + 1) + DGGS_SPECIAL_EXTRA: the rows special_ring needs. */
int dggs_special_ring_rows(int densify);

#endif
