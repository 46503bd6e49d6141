/* Exact weights of polygons in cells: each polygon cut along cell edges in Snyder's face planes. A port of
 * index/_kernel/pixels.py (ISEA only, as the numba module: raster weights have no IVEA variant).
 *
 * Snyder's projection is equal-area and maps every cell to a planar triangle with straight edges (thesis
 * §6.1.7): the area of a polygon's part inside a cell is the planar area, in the cell's face plane, of the
 * polygon clipped by the cell's triangle, times one constant. So dggs_grid_pieces finds, for each polygon (a
 * raster pixel, its edges densified by the caller), every cell of a level it meets and the planar area they
 * share, by descending the hierarchy (clip.h):
 * - a polygon whose vertices all lie in one cell of the level lies wholly in it (cells are convex): one piece;
 * - otherwise it is clipped from the smallest cell holding all its vertices down to the level;
 * - a polygon across face edges is projected onto each face near it (Snyder's forward on that face: the sector
 *   formulas hold past the face's edges) and clipped by that face's triangle first.
 * Areas are planar, in the unit-sphere face frame (DGGS_FACE_AREA a face); the caller scales them to m^2. */
#ifndef DGGS_PIXELS_H
#define DGGS_PIXELS_H

#include <stdbool.h>
#include <stdint.h>

#include "dggs.h"

/* region: 3 face + sector (0..2), the sector as Snyder's face_forward picks it, of a unit vector. */
int64_t dggs_pixels_region(int face, double ux, double uy, double uz);

/* chord_errors, per pixel: the fraction of its area its edges' chords leave out. lat, lng: its 16 points round
 * it, four an edge (its first corner, then at a quarter, half and three quarters), degrees. NaN where no
 * half-edge is smooth. */
double dggs_chord_error(const double *lat, const double *lng);

/* numba's np.argsort(a[:n]) (kind "quicksort": its insertion sort below 15 items, median-of-three partitions
 * above, NaN last), into r[0..n). The order of ties is numba's. */
void dggs_numba_argsort(const double *a, int64_t n, int64_t *r);

/* _kinked: the ring's points (unit vectors ux, uy, uz at the indices ring[0..m)) with, between two in different
 * regions, the crossings of the bending circles of the faces where near[f] (sorted along the edge), into
 * (ox, oy, oz) (cap points). Their count, or -1 if they do not fit. (numba's `faces` argument is unused.) */
int64_t dggs_kinked(const double *ux, const double *uy, const double *uz, const int64_t *ring, int64_t m,
                    const int64_t *regions, const bool *near, double *ox, double *oy, double *oz, int64_t cap);

/* _common: the finest level (<= target) at which cells[0..count) share an ancestor. */
int dggs_pixels_common(const uint64_t *cells, int64_t count, int target);

/* _ring: indices into the flattened point arrays (hlat's hsize points, then vlat's) of pixel (r, col)'s ring:
 * top, right, bottom, left edges, k points each (4 corners for k = 1); hw, vw the row widths; returns 4 k. */
int64_t dggs_pixels_ring(int64_t r, int64_t col, int64_t k, int64_t hw, int64_t hsize, int64_t vw, int64_t *ring);

/* 8-byte words of scratch dggs_grid_pieces needs for npts points (hrows hcols, plus vrows vcols if k > 1). */
int64_t dggs_grid_pieces_work_words(int64_t npts, int64_t k, int target);

/* grid_pieces: cells at level `target` met by each pixel of a grid, and the planar area they share.
 * The pixels' edges, densified with k points each: hlat, hlng (hrows = R + 1, hcols = C k + 1) along the grid
 * lines of constant row, vlat, vlng (vrows = R k + 1, vcols = C + 1) along those of constant column (degrees,
 * WGS84, row-major; each corner in both). Pixel (r, c) is number r C + c; pixels where valid (R, C) is 0 are left
 * out. The pieces (pixel, cell, area) go to `out` from out->n on, each pixel's together in pixel order; coarse
 * (R C) is, for an even k, the planar area of each pixel drawn through every other of its points, NaN for pixels
 * across a kink of the plane (and all with an odd k).
 * Where numba grows its arrays, this stops: *resume (0 on the first call) is the pixel to start from; when a
 * pixel's pieces do not fit in out->cap it returns DGGS_E_BUFFER with out->n the pieces before that pixel,
 * *resume that pixel and *need the room needed to hold its pieces too. The caller grows the arrays (keeping the
 * first out->n rows) and calls again with the same work, coarse and *resume. On DGGS_OK *need = out->n.
 * DGGS_E_DOMAIN for shapes that do not match, k < 1 or a bad *resume; DGGS_E_FAILED if a clipped polygon outgrew
 * its scratch width (numba would write past it). */
dggs_error dggs_grid_pieces(const double *hlat, const double *hlng, int64_t hrows, int64_t hcols, const double *vlat,
                            const double *vlng, int64_t vrows, int64_t vcols, int64_t k, const uint8_t *valid,
                            int64_t rows, int64_t cols, int target, dggs_pieces *out, double *coarse, void *work,
                            int64_t work_words, int64_t *resume, int64_t *need);

/* grid_pieces, and with `arcs` (an even k) each piece given the area between its pixel's curved edges and their
 * chords where it lies (pixels.c arc_pass): each pair of chords' parabolic segment, to the cell of its middle point. */
dggs_error dggs_grid_pieces_arcs(const double *hlat, const double *hlng, int64_t hrows, int64_t hcols,
                                 const double *vlat, const double *vlng, int64_t vrows, int64_t vcols, int64_t k,
                                 const uint8_t *valid, int64_t rows, int64_t cols, int target, bool arcs,
                                 dggs_pieces *out, double *coarse, void *work, int64_t work_words, int64_t *resume,
                                 int64_t *need);

#endif
