/* Whether a line between samples in two edge-neighbouring cells crosses only their shared edge: the line
 * tracer's planar test. A port of index/_kernel/chord.py, operation for operation.
 *
 * The tracer (line_trace.c) samples each geodesic every half short edge. Two consecutive samples in cells that
 * share an edge do not prove that the line went straight across it: passing near an end of that edge it can
 * clip the cells on the other side of the corner. dggs_clear decides, in the face plane where the samples
 * were located, whether the line cannot have done so; where it is not sure the tracer bisects.
 *
 * The bound on the line's bend (chord.py's measurement): in the face plane the image of a geodesic strays
 * from its chord by at most 0.137 of the chord's length on ISEA, 0.068 on IVEA (the kink where it crosses a
 * sector boundary). DGGS_BEND is 0.25; the floor covers the interpolation's 0.1 mm and rounding. */
#ifndef DGGS_CHORD_H
#define DGGS_CHORD_H

#include <stdbool.h>
#include <stdint.h>

/* chord.BEND: bound on how far the face-plane image of a geodesic strays from its chord, per chord length. */
#define DGGS_BEND 0.25
/* chord._BEND_FLOOR: absolute floor of the bend bound (plane units of the unit sphere: 0.6 mm). */
#define DGGS_BEND_FLOOR 0x1.b7cdfd9d7bdbbp-34 /* 1e-10 */

/* chord.dist_to_segment: the distance from point (px, py) to the segment (x0, y0) - (x1, y1) in the plane. */
double dggs_dist_to_segment(double px, double py, double x0, double y0, double x1, double y1);

/* chord.corners6: the planar corners of a cell (points.triangle's, without the face) into t. */
void dggs_corners6(uint64_t cell, double t[6]);

/* chord.crosses: dggs_clear's test on the corners ta and tb (dggs_corners6) of two cells on the samples' face. */
bool dggs_crosses(const double ta[6], const double tb[6], double xa, double ya, double xb, double yb);

/* chord.clear: whether the line from a sample (xa, ya) in a to one (xb, yb) in b (edge neighbours; the samples
 * located on faces fa and fb, -1 for none) crosses only their shared edge. False where the samples are on
 * different faces or anything is in doubt (the caller then bisects). */
bool dggs_clear(uint64_t a, uint64_t b, int fa, double xa, double ya, int fb, double xb, double yb);

/* chord.corner_clear: whether the line from a sample in a to one in b (cells meeting at one corner V) stays
 * farther from V than its bend. False where the samples are on different faces or the chord passes near V. */
bool dggs_corner_clear(uint64_t a, uint64_t b, int fa, double xa, double ya, int fb, double xb, double yb);

#endif
