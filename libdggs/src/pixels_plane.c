/* Exact weights of pixels in cells in a raster's own plane (issue 35): each cell's polygon, already in the raster's
 * pixel coordinates (column, row: x right, y down, pixel (r, c) the square [c, c + 1) x [r, r + 1)), cut against
 * the grid's integer rows and columns, as pixels_latlng.c cuts rings in the cylindrical equal-area map.
 *
 * Green's theorem by strips (the same decomposition as pixels_latlng.c, on a uniform grid): the ring is split at
 * every column and row line it crosses; with y = v + r for a point in row r (v = y - r in 0..1), the signed area
 * -closed-integral(y dx) falls into pixels: each piece of boundary in pixel (c, r) adds -integral(v du) to it and
 * -integral(du) (a whole row's height) to every pixel above it in its column (rows r' < r, a suffix sum), so a pixel
 * wholly inside the ring gets its whole area, 1, without any clipping. The first moments come the same way, from
 * -closed-integral(x y dx) and -closed-integral(y^2 / 2 dx), in each pixel's own coordinates (u = x - c, v), so
 * each piece's centroid is known: the caller weights a piece by the map's areal scale there (a CRS that is not
 * equal-area). A piece's ring part is a polygon of straight chords: the caller densifies the cells' curved edges.
 * Areas in pixel units (a pixel's area is 1), of either orientation (counted positive). */
#include <math.h>
#include <string.h>

#include "dggs.h"

typedef struct {
    int64_t rows, cols;
    int64_t c0, c1, r0, r1;       /* the window of the ring being cut (pixels), inclusive */
    double *pa, *px, *py;         /* (r1 - r0 + 2) x (c1 - c0 + 1): a pixel's own trapezoids' area and moments */
    double *wa, *wx;              /* the same: -sum du and -sum of u du of pieces in it (row r1 + 1: below) */
} plane_t;

/* One piece of boundary (ua, va) -> (ub, vb) in pixel (c, r)'s own coordinates, r = r1 + 1 for below the window. */
static inline void add_piece(plane_t *g, int64_t c, int64_t r, double ua, double va, double ub, double vb) {
    double du = ub - ua;
    int64_t nc = g->c1 - g->c0 + 1;
    int64_t at = (r - g->r0) * nc + (c - g->c0);
    if (r <= g->r1) {
        g->pa[at] -= du * 0.5 * (va + vb);
        g->px[at] -= du * (2.0 * ua * va + ua * vb + ub * va + 2.0 * ub * vb) / 6.0;
        g->py[at] -= du * (va * va + va * vb + vb * vb) / 6.0;
    }
    g->wa[at] -= du;
    g->wx[at] -= du * 0.5 * (ua + ub);
}

/* The ring (x, y)[:n] into the window's strip sums. */
static void cut_ring(plane_t *g, const double *x, const double *y, int64_t n) {
    double top = (double)g->r0, bottom = (double)(g->r1 + 1), left = (double)g->c0, right = (double)(g->c1 + 1);
    for (int64_t j = 0; j < n; j++) {
        int64_t i = j + 1 < n ? j + 1 : 0;
        double x1 = x[j], y1 = y[j], x2 = x[i], y2 = y[i];
        if (x1 == x2) continue; /* a vertical piece adds nothing */
        if ((x1 <= left && x2 <= left) || (x1 >= right && x2 >= right)) continue;
        if (y1 <= top && y2 <= top) continue; /* above the window: the grid's top (nothing above it counts) */
        double dx = x2 - x1, dy = y2 - y1;
        int64_t cstep = dx > 0.0 ? 1 : -1;
        double cn = dx > 0.0 ? floor(x1) + 1.0 : ceil(x1) - 1.0; /* the next column line */
        if (dx > 0.0 && cn < left) cn = left;
        if (dx < 0.0 && cn > right) cn = right;
        int64_t rstep = dy > 0.0 ? 1 : (dy < 0.0 ? -1 : 0);
        double rn = dy > 0.0 ? floor(y1) + 1.0 : ceil(y1) - 1.0; /* the next row line */
        if (dy > 0.0 && rn < top) rn = top;
        if (dy < 0.0 && rn > bottom) rn = bottom;
        double ta = 0.0, xa = x1, ya = y1;
        for (;;) {
            double tc = 2.0, tr = 2.0;
            if ((cstep > 0 && cn <= right && cn < x2) || (cstep < 0 && cn >= left && cn > x2)) tc = (cn - x1) / dx;
            if ((rstep > 0 && rn <= bottom && rn < y2) || (rstep < 0 && rn >= top && rn > y2)) tr = (rn - y1) / dy;
            double tb, xb, yb;
            int which;
            if (tc >= 1.0 && tr >= 1.0) {
                tb = 1.0, xb = x2, yb = y2, which = 0;
            } else if (tc <= tr) {
                tb = tc, xb = cn, yb = y1 + tc * dy, which = 1;
            } else {
                tb = tr, xb = x1 + tr * dx, yb = rn, which = 2;
            }
            if (tb > ta) {
                double xm = 0.5 * (xa + xb), ym = 0.5 * (ya + yb);
                if (xm > left && xm < right && ym > top) {
                    int64_t c = (int64_t)floor(xm);
                    if (c > g->c1) c = g->c1;
                    int64_t r = ym >= bottom ? g->r1 + 1 : (int64_t)floor(ym);
                    if (r < g->r0) r = g->r0;
                    double cc = (double)c, rr = (double)r;
                    double va = ya - rr, vb = yb - rr;
                    if (r > g->r1) va = vb = 0.0; /* below the window: only its width counts */
                    add_piece(g, c, r, xa - cc, va, xb - cc, vb);
                }
            }
            if (which == 0) break;
            if (which == 1) cn += (double)cstep;
            else rn += (double)rstep;
            ta = tb, xa = xb, ya = yb;
        }
    }
}

static void put(dggs_plane_pieces_out *out, int64_t pixel, uint64_t cell, double area, double cu, double cv) {
    if (out->n < out->cap) {
        out->pixel[out->n] = pixel, out->cell[out->n] = cell, out->area[out->n] = area;
        out->cu[out->n] = cu, out->cv[out->n] = cv;
    }
    out->n++;
}

/* The window's strip sums into pieces, row by row (pixel order). */
static void emit(plane_t *g, uint64_t cell, double orient, const uint8_t *valid, dggs_plane_pieces_out *out) {
    int64_t nc = g->c1 - g->c0 + 1;
    for (int64_t c = 0; c < nc; c++) { /* suffix sums up each column: wa[r] becomes the widths below row r */
        double below = g->wa[(g->r1 + 1 - g->r0) * nc + c], below_x = g->wx[(g->r1 + 1 - g->r0) * nc + c];
        for (int64_t r = g->r1 - g->r0; r >= 0; r--) {
            int64_t at = r * nc + c;
            double mine = g->wa[at], mine_x = g->wx[at];
            g->wa[at] = below, g->wx[at] = below_x;
            below += mine, below_x += mine_x;
        }
    }
    for (int64_t r = 0; r <= g->r1 - g->r0; r++) {
        for (int64_t c = 0; c < nc; c++) {
            int64_t at = r * nc + c;
            double area = orient * (g->pa[at] + g->wa[at]);
            int64_t pixel = (g->r0 + r) * g->cols + g->c0 + c;
            if (!(area > 0.0) || !valid[pixel]) continue;
            double mu = orient * (g->px[at] + g->wx[at]), mv = orient * (g->py[at] + 0.5 * g->wa[at]);
            /* the centroid lies in the pixel: a sliver of rounding's size (1e-20 of a pixel) has moments of no
             * digits, put back inside */
            put(out, pixel, cell, area, fmin(fmax(mu / area, 0.0), 1.0), fmin(fmax(mv / area, 0.0), 1.0));
        }
    }
}

int64_t dggs_plane_pieces_work_words(int64_t rows, int64_t cols) {
    if (rows < 1 || cols < 1) return 0;
    return 5 * (rows + 1) * cols;
}

dggs_error dggs_plane_pieces(const double *x, const double *y, const int64_t *ring_start, const uint64_t *cells,
                             int64_t n_rings, int64_t rows, int64_t cols, const uint8_t *valid,
                             dggs_plane_pieces_out *out, void *work, int64_t work_words, int64_t *resume,
                             int64_t *need) {
    if (rows < 1 || cols < 1 || n_rings < 0 || *resume < 0) return DGGS_E_DOMAIN;
    if (work_words < dggs_plane_pieces_work_words(rows, cols)) return DGGS_E_BUFFER;
    for (int64_t k = 0; k < n_rings; k++) {
        if (ring_start[k] < 0 || ring_start[k + 1] < ring_start[k]) return DGGS_E_DOMAIN;
    }
    for (int64_t j = ring_start[0]; j < ring_start[n_rings]; j++) {
        if (!(fabs(x[j]) <= DGGS_PLANE_MAX_COORD) || !(fabs(y[j]) <= DGGS_PLANE_MAX_COORD)) return DGGS_E_DOMAIN;
    }
    double *w = (double *)work;
    plane_t g = {0};
    g.rows = rows, g.cols = cols;
    for (int64_t k = *resume; k < n_rings; k++) {
        const double *rx = x + ring_start[k], *ry = y + ring_start[k];
        int64_t n = ring_start[k + 1] - ring_start[k];
        if (n < 3) continue;
        double xlo = INFINITY, xhi = -INFINITY, ylo = INFINITY, yhi = -INFINITY, twice = 0.0;
        for (int64_t j = 0; j < n; j++) {
            int64_t i = j + 1 < n ? j + 1 : 0;
            xlo = fmin(xlo, rx[j]), xhi = fmax(xhi, rx[j]), ylo = fmin(ylo, ry[j]), yhi = fmax(yhi, ry[j]);
            twice += (rx[j] - rx[0]) * (ry[i] - ry[0]) - (rx[i] - rx[0]) * (ry[j] - ry[0]);
        }
        if (xhi <= 0.0 || xlo >= (double)cols || yhi <= 0.0 || ylo >= (double)rows || twice == 0.0) continue;
        /* -closed-integral(y dx) is the shoelace sum's half: counted positive in either orientation */
        double orient = twice > 0.0 ? 1.0 : -1.0;
        g.c0 = (int64_t)fmax(0.0, floor(xlo)), g.c1 = (int64_t)fmin((double)(cols - 1), floor(xhi));
        g.r0 = (int64_t)fmax(0.0, floor(ylo)), g.r1 = (int64_t)fmin((double)(rows - 1), floor(yhi));
        int64_t size = (g.r1 - g.r0 + 2) * (g.c1 - g.c0 + 1);
        g.pa = w, g.px = w + size, g.py = w + 2 * size, g.wa = w + 3 * size, g.wx = w + 4 * size;
        memset(w, 0, (size_t)(5 * size) * sizeof(double));
        int64_t n0 = out->n;
        cut_ring(&g, rx, ry, n);
        emit(&g, cells[k], orient, valid, out);
        if (out->n > out->cap) {
            *need = out->n;
            out->n = n0;
            *resume = k;
            return DGGS_E_BUFFER;
        }
    }
    *resume = n_rings;
    *need = out->n;
    return DGGS_OK;
}
