/* Point- and circle-against-polygon tests for polygon fill: a uniform bucket grid over the polygon's edges.
 * A port of index/_kernel/polygon.py, operation for operation (its answers must equal the numba kernel's).
 *
 * dggs_polygon_build sorts a polygon's edges (segments in one plane, lng/lat for polygon fill) into the buckets
 * of a uniform grid over their bounding box, and records for each bucket the nearest bucket right of it that no
 * edge meets, and that one's side. dggs_near says whether some edge lies within r of a point (in a plane whose
 * x axis may be scaled first: an ellipse is then a circle). dggs_parity locates a point by the crossing number of
 * the ray to +x, with the sign of every crossing decided by an orientation whose rounding error is bounded: a
 * point within that error of an edge is reported as undecided (-1), never guessed. So 1 (inside) and 0 (outside)
 * are the exact answers; only points on or within about 1e-16 of an edge are left to an exact test. */
#ifndef DGGS_POLYGON_H
#define DGGS_POLYGON_H

#include <stdbool.h>
#include <stdint.h>

#include "dggs.h"

/* polygon.py ORIENT_ERR: relative error bound of a 2x2 orientation determinant in doubles (Shewchuk 1997,
 * ccwerrboundA = (3 + 16 eps) eps = 3.3e-16 with eps = 2^-53), three times that for margin. */
#define DGGS_ORIENT_ERR 1e-15
/* polygon.py _TINY: below this sum of products the bound could be lost to underflow: undecided. */
#define DGGS_ORIENT_TINY 1e-290
/* Entries of a grid's frame: (xmin, ymin, bucket width, bucket height, side, xmax, ymax). */
#define DGGS_FRAME_SIZE 7

/* The edges (x0, y0) - (x1, y1) of a polygon and their bucket grid (dggs_polygon_build's arrays), borrowed. */
typedef struct {
    const double *x0, *y0, *x1, *y1; /* the edges */
    const double *frame;             /* DGGS_FRAME_SIZE entries */
    const int64_t *start;            /* side * side + 1: items[start[b]:start[b + 1]] are bucket b's edges */
    const int64_t *items;            /* start[side * side] edge indices */
    const int64_t *empty;            /* side * side: the next empty bucket of b's row (and its side) */
} dggs_edge_grid;

/* polygon.py ring_edges: the edges of closed rings laid end to end in xy (n points, row-major (x, y)), and
 * whether every ring closed. A ring ends at the next repeat of its first point. x0, y0, x1, y1 take n entries
 * each (at most n - 1 are written); *m is the number of edges (those of the rings closed before an unclosed one). */
void dggs_ring_edges(const double *xy, int64_t n, double *x0, double *y0, double *x1, double *y1, int64_t *m,
                     bool *closed);

/* polygon.py build, first pass: the frame (DGGS_FRAME_SIZE entries) of a side x side grid over n >= 1 edges,
 * and start (side * side + 1 entries), the cumulative counts of the edges overlapping each bucket;
 * start[side * side] is the size of items (and of the scratch of dggs_polygon_build_fill).
 * DGGS_E_DOMAIN when n < 1 (numba's zero-size reduction) or side is not 1..2^31. */
dggs_error dggs_polygon_build_count(const double *x0, const double *y0, const double *x1, const double *y1, int64_t n,
                                    int64_t side, double *frame, int64_t *start);
/* polygon.py build, second pass (and _empty_buckets): items (start[side * side] entries), empty (side * side;
 * also the pass's bucket cursors), from the frame and start of dggs_polygon_build_count. scratch takes
 * start[side * side] doubles (a row's crossings). */
void dggs_polygon_build_fill(const double *x0, const double *y0, const double *x1, const double *y1, int64_t n,
                             const double *frame, const int64_t *start, int64_t *items, int64_t *empty,
                             double *scratch);

/* polygon.py near: whether some edge lies within r of (px, py) once x is multiplied by sx > 0. */
bool dggs_near(double px, double py, double r, double sx, const dggs_edge_grid *g);
/* polygon.py parity: 1 if (px, py) is inside the polygon, 0 if outside, -1 if on or within rounding of an edge. */
int dggs_parity(double px, double py, const dggs_edge_grid *g);
/* polygon.py _classify_impl, one item: *hit, the circle of radius r round (px, py) meets the polygon; *inside,
 * it lies wholly in it. */
void dggs_polygon_classify(double px, double py, double r, const dggs_edge_grid *g, bool *hit, bool *inside);

/* ---- exact predicates, for the public polygon fill's own tests (no numba counterpart) ---- */

/* The exact sign of the orientation of (a, b, p): 1 if p lies left of a -> b, -1 right, 0 on its line. A
 * filtered determinant, else exact expansion arithmetic (Shewchuk 1997: Two-Diff, Two-Product by Dekker's split,
 * Grow-Expansion), exact unless a product underflows (coordinates under 1e-140 apart). */
int dggs_orient_exact(double ax, double ay, double bx, double by, double px, double py);
/* Where (px, py) lies in the polygon of n edges (x0, y0) - (x1, y1): 1 in its interior, 0 outside, -1 on its
 * boundary. GEOS's RayCrossingCounter over every edge, with exact orientations: the answer GEOS's point location
 * (shapely.contains_xy: interior) gives. */
int dggs_locate_exact(double px, double py, const double *x0, const double *y0, const double *x1, const double *y1,
                      int64_t n);
/* The same over a ring of m points (xy interleaved (x, y), closed implicitly: the last joins the first). */
int dggs_locate_ring(double px, double py, const double *xy, int64_t m);
/* The same through the grid: dggs_parity where it decides, else dggs_locate_exact over the n edges. */
int dggs_locate(double px, double py, const dggs_edge_grid *g, int64_t n);
/* Whether closed segments ab and cd meet: 0 apart, 1 touching (an end on the other, or collinear overlap),
 * 2 crossing at one point interior to both. Exact. */
int dggs_segments_meet(double ax, double ay, double bx, double by, double cx, double cy, double dx, double dy);
/* The buckets (columns c0..c1, rows r0..r1) a box overlaps; false if it misses the edges' bounding box. */
bool dggs_grid_span(const dggs_edge_grid *g, double xlo, double xhi, double ylo, double yhi, int64_t *c0, int64_t *c1,
                    int64_t *r0, int64_t *r1);

#endif
