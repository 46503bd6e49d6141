/* A polyline's points checked, and its anchors laid out: the plain loops before the line tracer
 * (line_trace.c) traces it. A port of index/_kernel/line_layout.py; neither locates a point, so both
 * projections share them. */
#ifndef DGGS_LINE_LAYOUT_H
#define DGGS_LINE_LAYOUT_H

#include <stddef.h>
#include <stdint.h>

/* line_layout.clean: the n (lat, lng) points xy (row-major, 2n doubles) without consecutive repeats, checked.
 * Returns -1 with the kept points in out (room for 2n doubles; may be xy itself) and their number in *count,
 * or the index of the first point that is not a finite latitude in -90..90 and a finite longitude (then
 * nothing is written and *count is 0). The numba function allocates its output; this writes at most n points. */
int64_t dggs_clean(const double *xy, size_t n, double *out, size_t *count);

/* The sizes of dggs_layout's arrays for segments of lengths dist[0..nseg) cut into spans of at most max_span
 * metres: *size anchors (lat, lng, az_out, az_in: size; span: size - 1) of which *inner lie between the
 * polyline's points (at, seg, s: inner). numba's layout allocates these; here the caller does. */
void dggs_layout_size(const double *dist, size_t nseg, double max_span, size_t *size, size_t *inner);

/* line_layout.layout: anchor arrays for a polyline's nseg segments (xy: nseg + 1 points, row-major (lat, lng))
 * cut into spans of at most max_span metres. The polyline's points and their azimuths go in place (az21,
 * pyproj's back azimuth at each segment's end, turned round: az21 + 180); for each anchor between them its
 * index at, segment seg and distance s from the segment's start, for the caller to fill from a geodesic's
 * direct problem (at, seg and s may all be NULL: then they are not written). az_out and az_in are zero where
 * not set (as numba's np.zeros); lat and lng between the points are left for the caller. Sizes:
 * dggs_layout_size. */
void dggs_layout(const double *xy, const double *az12, const double *az21, const double *dist, size_t nseg,
                 double max_span, double *lat, double *lng, double *az_out, double *az_in, double *span, int64_t *at,
                 int64_t *seg, double *s);

/* max(1, int(math.ceil(q))) as numba computes it on x86-64: a NaN or an overflowing ceiling converts to
 * INT64_MIN (cvttsd2si), so gives 1. */
int64_t dggs_span_count(double q);

#endif
