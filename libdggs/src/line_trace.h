/* Compiled tracing of a polyline of WGS84 geodesics through the cells of a level: a port of
 * index/_kernel/line_trace.py (and of its IVEA build index/_kernel/ivea_lines.py: the same code, with `proj`
 * selecting the forward projection), operation for operation.
 *
 * The caller gives exact geodesic points, anchors, with the geodesic's azimuth at each; the tracer fills the
 * spans between anchors, locates the points and bisects the gaps (dggs_trace). Between two anchors A and B a
 * span s apart, the geodesic P(u) is replaced by the cubic Hermite curve in Earth-centred (ECEF) coordinates
 * with A's and B's positions and the geodesic's unit tangents there (times s); it errs by at most
 * s^4 / (96 rho^3), rho = b^2 / a (line_trace.py's docstring derives it). The interpolated point is taken back
 * to geodetic latitude and longitude along the ellipsoid's normal (dggs_foot: one round of Bowring's
 * iteration), as sines and cosines that go straight into the authalic series and the face projection
 * (dggs_sample, no trigonometric call). Anchors themselves are located as dggs_one_point locates them. */
#ifndef DGGS_LINE_TRACE_H
#define DGGS_LINE_TRACE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "dggs.h"

/* line_trace._STACK: the depth of the tracer's bisection stack. */
#define DGGS_TRACE_STACK 256

/* line_trace.ecef: geodetic WGS84 (lat, lng) degrees on the surface -> ECEF metres. */
void dggs_ecef(double lat_deg, double lng_deg, double *x, double *y, double *z);
/* line_trace.tangent: the unit vector (ECEF) at a point heading at azimuth az_deg (clockwise from north). */
void dggs_tangent(double lat_deg, double lng_deg, double az_deg, double *x, double *y, double *z);
/* line_trace._foot: sine and cosine of the geodetic latitude and longitude of an ECEF point near the surface
 * (one round of Bowring's iteration, 1976, from his starting reduced latitude; a pole gives lng's 0 and 1). */
void dggs_foot(double x, double y, double z, double *sp, double *cp, double *sl, double *cl);
/* line_trace.geodetic: ECEF metres -> geodetic (lat, lng) degrees of the foot of the normal. */
void dggs_geodetic(double x, double y, double z, double *lat, double *lng);

/* line_trace._span: the Hermite coefficients of span k (A, s TA, B, s TB: 12 numbers) of the anchors. */
void dggs_line_trace_span(const double *lat, const double *lng, const double *az_out, const double *az_in,
                          const double *span, size_t k, double c[12]);
/* line_trace._point: the ECEF point of the Hermite curve c at t in 0..1. */
void dggs_point(const double c[12], double t, double *x, double *y, double *z);
/* line_trace._at: (lat, lng) degrees of the Hermite curve c at t in 0..1. */
void dggs_at(const double c[12], double t, double *lat, double *lng);

/* line_trace._sample: the cell holding the foot of ECEF point (x, y, z) at `level` (as dggs_one_point), its
 * face (*face) and the point in that face's plane (*fx, *fy). A point within 20 degrees of face `hint`'s
 * centre (the previous point's face; -1 for none) is on that face without the nearest-face search. */
uint64_t dggs_sample(dggs_projection proj, double x, double y, double z, int level, int hint, int *face, double *fx,
                     double *fy);
/* line_trace._cell_at: dggs_sample's cell, its face in *face. */
uint64_t dggs_cell_at(dggs_projection proj, double x, double y, double z, int level, int hint, int *face);
/* line_trace._anchor: the cell of a polyline's or geodesic's point as dggs_one_point gives it, and the point's
 * face and face-plane point as dggs_sample's; the face is -1 where it is not the cell's (a point on a face
 * edge, a tie), so that no planar test trusts it. */
uint64_t dggs_anchor(dggs_projection proj, double lat, double lng, int level, int *face, double *fx, double *fy);

/* line_trace.interpolate: out_lat[i], out_lng[i] = the interpolated point at fraction t[i] of span k[i] of the
 * anchors, for i < m (for tests). */
void dggs_interpolate(const double *lat, const double *lng, const double *az_out, const double *az_in,
                      const double *span, const int64_t *k, const double *t, size_t m, double *out_lat,
                      double *out_lng);
/* line_trace.cells_at: out[i] = the cell of point i located as the tracer locates interpolated points (for
 * tests); with `chained` each point's face search starts from the one before's, as along a line. */
void dggs_cells_at(dggs_projection proj, const double *lat, const double *lng, size_t n, int level, uint64_t *out,
                   bool chained);

/* line_trace._adjacent: whether b is one of a's three edge neighbours at `level`. */
bool dggs_adjacent(uint64_t a, uint64_t b, int level);
/* line_trace._between: the one edge neighbour a and b have in common, or 0 (none, or two). */
uint64_t dggs_between(uint64_t a, uint64_t b, int level);

/* line_trace.trace: the cells along a chain of n anchors (lat[k], lng[k]; az_out[k] leaving, az_in[k]
 * arriving; span[k] metres to anchor k + 1) into out (room for cap), consecutive cells distinct. Each span is
 * sampled every `step` metres or less; pairs of samples whose cells are not shown by the planar tests
 * (chord.h) to have crossed only a shared edge are bisected down to `corner` metres; then a pair sharing no
 * edge is recorded in fix (room for fixcap) as the index in out of its second cell (a corner between them,
 * for the caller to join around). `shortcut` joins two cells at most a step apart through their one common
 * edge neighbour where dggs_corner_clear allows (line_trace.py's docstring). Returns the cells written, the
 * corner gaps in *nfix; or -1 (and *nfix 0) if out or fix is full (the numba function's (-1, 0)): the caller
 * grows them and calls again. fix may be NULL (fixcap ignored): the gaps are then only counted (each is an
 * index i with out[i - 1] and out[i] not edge neighbours). n must be >= 1. Uses a bisection stack of
 * DGGS_TRACE_STACK entries on the C stack (about 20 kB). */
int64_t dggs_trace(dggs_projection proj, const double *lat, const double *lng, const double *az_out,
                   const double *az_in, const double *span, size_t n, int level, double step, double corner,
                   uint64_t *out, size_t cap, int64_t *fix, size_t fixcap, bool shortcut, int64_t *nfix);

/* dggs.index.paths._around: the cells strictly between a and b (cells sharing a corner, not an edge) the
 * shorter way around that corner, into way (room for 5: half a fan of 12, minus its ends); returns their
 * number, or -1 if a and b share no corner or a walk around one did not close. */
int dggs_line_around(uint64_t a, uint64_t b, uint64_t way[5]);

#endif
