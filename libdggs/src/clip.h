/* Clipping of polygons by the cells of the hierarchy, in one face plane (for pixels.c). A port of
 * index/_kernel/clip.py.
 *
 * A polygon inside a cell is cut into its parts in the cell's children, depth first, down to a target level
 * (dggs_clip_descend): a face's six children by Sutherland-Hodgman clips against each triangle, a finer cell's
 * three by two cuts along the lines that part them (geometry.h's dggs_child_corners). Each part's planar area is
 * a piece; a child the polygon covers wholly gives all its descendants at the target level an equal share (cells
 * are congruent in the plane). Areas are shoelace sums about a vertex of the polygon, for precision at fine
 * levels.
 *
 * Where numba grows its output arrays (clip.grow), the pieces here go to a caller's dggs_pieces: every piece is
 * counted, and written while it fits (the caller then calls again with the count). Where numba writes its
 * scratch arrays unchecked, the functions here check every write against the scratch width and fail (-1)
 * instead of writing past it. */
#ifndef DGGS_CLIP_H
#define DGGS_CLIP_H

#include <stdbool.h>
#include <stdint.h>

#include "dggs.h"

/* area: signed shoelace area of the first n vertices, about the first one. */
double dggs_clip_area(const double *x, const double *y, int64_t n);
/* _clip_edge: the vertices of polygon (x, y)[:n] left of the directed line a -> b, into (ox, oy) (cap vertices);
 * their count, or -1 if they do not fit. */
int64_t dggs_clip_edge(const double *x, const double *y, int64_t n, double ax, double ay, double bx, double by,
                       double *ox, double *oy, int64_t cap);
/* clip: polygon (x, y)[:n] clipped by the triangle (a, b, c) (any orientation); the result in (tx, ty), (ox, oy)
 * scratch, each of cap vertices; the count, or -1 if a stage does not fit. */
int64_t dggs_clip(const double *x, const double *y, int64_t n, double ax, double ay, double bx, double by, double cx,
                  double cy, double *ox, double *oy, double *tx, double *ty, int64_t cap);
/* _child: child `digit` of a cell at `level` (6 children of a face, 3 below). */
uint64_t dggs_clip_child(uint64_t cell, int level, int digit);
/* One piece into the caller's buffers: counted always, written while it fits. */
void dggs_pieces_put(dggs_pieces *out, int64_t pixel, uint64_t cell, double area);
/* _whole: every descendant of `cell` (at `level`) at `target`, `total` shared equally. */
void dggs_clip_whole(uint64_t cell, int level, int target, double total, int64_t pixel, dggs_pieces *out);
/* _split: polygon (x, y)[:n] cut by the line a -> b: its part left of the line into (lx, ly), right into
 * (rx, ry), each of cap vertices. 0, or -1 if a part does not fit. */
int dggs_clip_split(const double *x, const double *y, int64_t n, double ax, double ay, double bx, double by,
                    double *lx, double *ly, double *rx, double *ry, int64_t cap, int64_t *nl, int64_t *nr);

/* descend's scratch: kx, ky (levels, 6, width), kn (levels, 6), tx, ty (width), tri (levels, 6), ids and nxt
 * (levels), levels >= target + 2 - root level (numba: target + 3), width >= the polygon's vertices + 3 (levels). */
typedef struct {
    int64_t levels, width;
    double *kx, *ky;
    int64_t *kn;
    double *tx, *ty;
    double *tri;
    uint64_t *ids;
    int64_t *nxt;
} dggs_clip_work;

/* _children: the parts of polygon (x, y)[:n] in each child of triangle t (ax, ay, bx, by, cx, cy) of a cell at
 * `level` into kx, ky (6 rows of `width`), kn (6). 0, or -1 if a part does not fit in `width`. */
int dggs_clip_children(int level, const double t[6], const double *x, const double *y, int64_t n, double *kx,
                       double *ky, int64_t *kn, double *tx, double *ty, int64_t width);
/* descend: the pieces of polygon (px, py)[:nv] inside cell `root` (at root_level < target, corners `corners`)
 * down to `target`, into `out`. 0, or -1 if the scratch is too small (levels or width). */
int dggs_clip_descend(uint64_t root, int root_level, const double corners[6], int target, const double *px,
                      const double *py, int64_t nv, int64_t pixel, dggs_pieces *out, dggs_clip_work *w);

#endif
