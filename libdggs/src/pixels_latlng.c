/* Exact weights of lat/lng pixels in cells, cut the other way round (issue 35): each cell against the pixel grid's
 * rows and columns, instead of each pixel against the cells (pixels.c).
 *
 * On the authalic sphere the cylindrical equal-area map (lambda, q = sin(authalic latitude)) keeps areas (the
 * sphere's area element is d lambda d q), and a pixel of a geographic raster, bounded by two meridians and two
 * parallels, is an exact rectangle there (a parallel of geodetic latitude is one of authalic latitude). So:
 * - the cells of the level that may meet the block are found by descending the hierarchy, keeping the cells whose
 *   bounding cap (from their corners, widened) meets the block's lat/lng box;
 * - each cell's edges (straight in Snyder's face plane) are densified with k chords, their points put exactly on
 *   the sphere by Snyder's inverse, into (column, q): a polygon whose chords leave out at most `tol` of any pixel
 *   they cross (k from each edge's sagitta in pixel units: a chord's sagitta falls as 1/k^2);
 * - the polygon's area in each pixel follows from Green's theorem by strips: split at every column and row line it
 *   crosses, each piece of boundary in one pixel adds the trapezoid under it (down to its row's bottom line) to
 *   that pixel and its width to every pixel below it in its column (a suffix sum), so a pixel wholly inside the
 *   cell gets its closed-form area, row height times width, without any clipping;
 * - each pair of chords' parabolic segment (a third of the triangle the pair makes) is added to the pixel holding
 *   the pair's middle point, as pixels.c arc_pass does round pixels, so the cell's whole area is right to about
 *   1e-9 where the chords alone leave out up to `tol` of a pixel.
 * A cell's ring is unwrapped in longitude; a ring that winds round a pole is closed along q = +-1 (the pole is a
 * line of the map), and a corner at a pole becomes a piece of that line. Areas are on the unit sphere (4 pi in
 * all): times the ellipsoid's area / (4 pi) for m^2. */
#include <math.h>
#include <string.h>

#include "bits.h"
#include "clip.h"
#include "dmath.h"
#include "geometry.h"
#include "pixels.h"
#include "points.h"
#include "tables.h"

#define FRAMES (&dggs_isea_frames[0][0][0])
#define PI 3.14159265358979323846
/* Most chords an edge: a cell edge needing more (a coarse cell over tiny pixels) is DGGS_E_FAILED. */
#define MOST_CHORDS 4096
/* Ring points: three edges, each of MOST_CHORDS chords, plus a pole's closing points. */
#define RING_CAP (3 * MOST_CHORDS + 16)

typedef struct {
    double west, dlng; /* column 0's western edge and the columns' width, degrees (dlng > 0) */
    const double *qe;  /* rows + 1 row lines, q ascending (band b between qe[b] and qe[b + 1]) */
    int64_t rows, cols;
    bool north_up; /* raster row r is band rows - 1 - r */
    const uint8_t *valid;
    double tol;
    double box_west, box_east, beta_lo, beta_hi; /* the block's box: degrees of longitude, radians of latitude */
    double *rx, *ry;                               /* ring: column units, q */
    int64_t *rk;                                   /* ring: the chord count of the edge each point starts (0 else) */
    double *part, *wide;                           /* (bands + 1) x cols scratch of the strip sums */
    int64_t hint; /* the band last found: the next cell's is near it (depth first) */
    double *memo; /* MEMO entries of 6: a face-plane point's x, y, face, and its lng, q, pole (see mapped) */
} grid_t;

/* The lesser and greater of two numbers that are never NaN: libm's fmin and fmax are calls under the core's
 * floating-point flags (-fno-finite-math-only), a few percent of the cut where cells are the pixels' size. */
static inline double min2(double a, double b) { return b < a ? b : a; }
static inline double max2(double a, double b) { return b > a ? b : a; }

/* Entries of the memo of mapped points (a power of 2; 96 KiB). Over a block of pixel-size cells 2048 leave 8% of the
 * points mapped twice (neighbours across a coarse cell's edge are far apart depth first) and 8192 3%, but 8192 ran
 * 3% slower: its look-ups (17 a cell) miss the cache. */
#define MEMO 2048

/* The band (0..rows - 1) holding q, -1 below the grid, rows above it (near `guess` first, then a binary search). */
static int64_t band_of(const grid_t *g, double q, int64_t guess) {
    if (q < g->qe[0]) return -1;
    if (q >= g->qe[g->rows]) return g->rows;
    if (guess >= 0 && guess < g->rows) { /* a few steps from the guess, then a binary search */
        int64_t b = guess;
        for (int step = 0; step < 4; step++) {
            if (q < g->qe[b]) {
                if (b == 0) break;
                b--;
            } else if (q >= g->qe[b + 1]) {
                if (b == g->rows - 1) break;
                b++;
            } else {
                return b;
            }
        }
    }
    int64_t lo = 0, hi = g->rows; /* qe[lo] <= q < qe[hi] */
    while (hi - lo > 1) {
        int64_t mid = lo + (hi - lo) / 2;
        if (q >= g->qe[mid]) lo = mid;
        else hi = mid;
    }
    return lo;
}

static void to_map(int face, double x, double y, double *lng, double *q, bool *pole) {
    double p[3];
    dggs_snyder_inverse_unit(FRAMES, face, x, y, p);
    *pole = p[0] * p[0] + p[1] * p[1] < 1e-26;
    *lng = *pole ? 0.0 : dggs_atan2(p[1], p[0]) * (180.0 / PI);
    *q = p[2] > 1.0 ? 1.0 : (p[2] < -1.0 ? -1.0 : p[2]);
}

/* to_map, remembered by the point's bits: a corner is in 6 cells and an edge's points in 2, met again soon in the
 * depth-first order. A pure function remembered: the same bits as computing it again. */
static void mapped(grid_t *g, int face, double x, double y, double *lng, double *q, bool *pole) {
    uint64_t bx, by;
    memcpy(&bx, &x, sizeof bx);
    memcpy(&by, &y, sizeof by);
    uint64_t h = (bx * 0x9E3779B97F4A7C15u) ^ (by * 0xC2B2AE3D27D4EB4Fu) ^ (uint64_t)face;
    double *m = g->memo + 6 * (int64_t)((h >> 32) & (MEMO - 1));
    if (m[2] == (double)face && memcmp(&m[0], &bx, sizeof bx) == 0 && memcmp(&m[1], &by, sizeof by) == 0) {
        *lng = m[3], *q = m[4], *pole = m[5] != 0.0;
        return;
    }
    to_map(face, x, y, lng, q, pole);
    memcpy(&m[0], &bx, sizeof bx);
    memcpy(&m[1], &by, sizeof by);
    m[2] = (double)face, m[3] = *lng, m[4] = *q, m[5] = *pole ? 1.0 : 0.0;
}

/* acos from the core's own atan2 and an exact sqrt (dmath.h: the same bits on every platform). */
static double pixels_acos(double x) { return dggs_atan2(sqrt((1.0 - x) * (1.0 + x)), x); }

/* Does the cap round the cell of triangle t on `face` (its corners' widest angle from its centre, widened by a fifth for its curved edges)
 * meet the block's box? *inside: does the box hold it whole? */
static bool cap_meets(const grid_t *g, int face, const double t[6], bool *inside) {
    double c[3], p[3];
    dggs_snyder_inverse_unit(FRAMES, face, (t[0] + t[2] + t[4]) / 3.0, (t[1] + t[3] + t[5]) / 3.0, c);
    double least = 1.0;
    for (int j = 0; j < 3; j++) {
        dggs_snyder_inverse_unit(FRAMES, face, t[2 * j], t[2 * j + 1], p);
        double d = c[0] * p[0] + c[1] * p[1] + c[2] * p[2];
        if (d < least) least = d;
    }
    double rho = 1.2 * pixels_acos(least > 1.0 ? 1.0 : least) + 1e-9;
    double beta = dggs_asin(c[2] > 1.0 ? 1.0 : (c[2] < -1.0 ? -1.0 : c[2]));
    *inside = false;
    if (beta + rho < g->beta_lo || beta - rho > g->beta_hi) return false;
    bool rows_in = beta - rho > g->beta_lo && beta + rho < g->beta_hi;
    if (fabs(beta) + rho >= 0.5 * PI) return true;
    double half = dggs_asin(min2(1.0, dggs_sin(rho) / dggs_cos(beta))) * (180.0 / PI);
    if (g->box_east - g->box_west >= 360.0) {
        *inside = rows_in;
        return true;
    }
    double mid = 0.5 * (g->box_west + g->box_east), width = 0.5 * (g->box_east - g->box_west);
    double d = fmod(dggs_atan2(c[1], c[0]) * (180.0 / PI) - mid, 360.0);
    if (d > 180.0) d -= 360.0;
    if (d < -180.0) d += 360.0;
    *inside = rows_in && fabs(d) + half < width; /* its descendants need no test */
    return fabs(d) <= half + width;
}

/* The least row height among the bands q0..q1 (in either order) meets, or 0 where they miss the grid. */
static double least_height(grid_t *g, double q0, double q1) {
    int64_t b0 = band_of(g, min2(q0, q1), g->hint), b1 = band_of(g, max2(q0, q1), b0);
    g->hint = b0;
    if (b1 < 0 || b0 >= g->rows) return 0.0;
    if (b0 < 0) b0 = 0;
    if (b1 >= g->rows) b1 = g->rows - 1;
    double h = INFINITY;
    for (int64_t b = b0; b <= b1; b++) h = min2(h, g->qe[b + 1] - g->qe[b]);
    return h;
}

static inline double unwrap_near(double lng, double ref) {
    while (lng - ref > 180.0) lng -= 360.0;
    while (lng - ref < -180.0) lng += 360.0;
    return lng;
}

/* The points of the planar edge (ax, ay) -> (bx, by) into the ring from point n: its start (given, mapped: lng
 * NaN at a pole), then k - 1 inside (the end is the next edge's start). k, even, is the fewest found (from 2,
 * grown by the sagittas seen) whose every pair of chords has its middle point within 8/3 tol pixels of the pair's
 * outer chord: a chord's sagitta is a quarter of that, and a chord leaves out at most 1.5 sagittas of a pixel it
 * crosses (a pixel's diagonal; in pixel units, rows of the least height the edge meets). k, or -1 past
 * MOST_CHORDS chords or the ring's room. */
static int64_t edge_points(grid_t *g, int face, double ax, double ay, double bx, double by, double alng, double aq,
                           double blng, double bq, int64_t n) {
    int64_t k = 2;
    for (;;) {
        if (n + k + 8 > RING_CAP) return -1;
        g->rx[n] = alng, g->ry[n] = aq;
        for (int64_t j = 1; j < k; j++) {
            bool pole;
            mapped(g, face, ax + (bx - ax) * (double)j / (double)k, ay + (by - ay) * (double)j / (double)k, &g->rx[n + j],
                   &g->ry[n + j], &pole);
            if (pole) g->rx[n + j] = NAN;
        }
        double qlo = bq, qhi = bq; /* the rows the points meet (an edge bulges past its ends: poleward) */
        for (int64_t j = 0; j < k; j++) qlo = min2(qlo, g->ry[n + j]), qhi = max2(qhi, g->ry[n + j]);
        double h = least_height(g, qlo, qhi);
        if (!(h > 0.0)) return k; /* the edge misses the grid's rows: its chords add to no pixel */
        double worst = 0.0;
        for (int64_t j = 0; j + 2 <= k; j += 2) {
            double l0 = g->rx[n + j], l1 = g->rx[n + j + 1], l2 = j + 2 < k ? g->rx[n + j + 2] : blng;
            double q0 = g->ry[n + j], q1 = g->ry[n + j + 1], q2 = j + 2 < k ? g->ry[n + j + 2] : bq;
            if (!isfinite(l0) || !isfinite(l1) || !isfinite(l2)) continue; /* a pole: its pieces have no width */
            l0 = unwrap_near(l0, l1), l2 = unwrap_near(l2, l1);
            double du = (l1 - 0.5 * (l0 + l2)) / g->dlng, dv = (q1 - 0.5 * (q0 + q2)) / h;
            worst = max2(worst, du * du + dv * dv);
        }
        double need = 1.5 * 0.25 * sqrt(worst) / g->tol; /* the chords' error now, in units of tol */
        if (need <= 1.0) return k;
        double grow = ceil((double)k * sqrt(need) * 1.05);
        if (!(grow <= MOST_CHORDS)) return -1;
        int64_t next = (int64_t)grow;
        next += next % 2;
        k = next > k ? next : k + 2;
    }
}

/* The ring of the cell of triangle t on `face` (dggs_triangle) in (column, q), unwrapped, closed through a pole where it winds round one; its count, or -1.
 * rk[j] is the chord count of the edge starting at point j (0 elsewhere, and on edges from or to a pole, whose
 * points near it are not evenly spread in the map: no parabolic segments there). */
static int64_t cell_ring(grid_t *g, int face, const double t[6], double *orient) {
    int64_t n = 0;
    int64_t start[3], chords[3];
    bool at_pole[3] = {false, false, false};
    double clng[3], cq[3];
    for (int e = 0; e < 3; e++) {
        mapped(g, face, t[2 * e], t[2 * e + 1], &clng[e], &cq[e], &at_pole[e]);
        if (at_pole[e]) clng[e] = NAN; /* only a corner lies on a pole: its longitude set below */
    }
    for (int e = 0; e < 3; e++) {
        int f = (e + 1) % 3;
        int64_t k = edge_points(g, face, t[2 * e], t[2 * e + 1], t[2 * f], t[2 * f + 1], clng[e], cq[e], clng[f],
                                cq[f], n);
        if (k < 0) return -1;
        start[e] = n, chords[e] = k;
        for (int64_t j = 0; j < k; j++) g->rk[n + j] = 0;
        n += k;
    }
    for (int e = 0; e < 3; e++) {
        if (!at_pole[e] && !at_pole[(e + 1) % 3]) g->rk[start[e]] = chords[e];
    }
    /* A pole inside an edge (an edge point, not a corner, mapped onto it: coarse cells, whose edges pass through a
     * pole): which way the ring runs along the pole's line is not settled by its neighbours' longitudes (half a turn
     * apart). Not cut here: -1 sends the block to the pixel-by-pixel cut (dggs/raster/pieces.py). */
    for (int64_t j = 0; j < n; j++) {
        if (isnan(g->rx[j]) && !(j == start[0] && at_pole[0]) && !(j == start[1] && at_pole[1]) &&
            !(j == start[2] && at_pole[2]))
            return -1;
    }
    for (int e = 2; e >= 0; e--) { /* a corner at a pole: a piece of the line q = +-1, from the longitude the ring
                                    * comes in at to the one it leaves at (its neighbours' along the edges) */
        if (!at_pole[e]) continue;
        int64_t at = start[e];
        int64_t before = (at + n - 1) % n, after = (at + 1) % n;
        double lin = g->rx[before], lout = g->rx[after];
        memmove(g->rx + at + 1, g->rx + at, (size_t)(n - at) * sizeof(double));
        memmove(g->ry + at + 1, g->ry + at, (size_t)(n - at) * sizeof(double));
        memmove(g->rk + at + 1, g->rk + at, (size_t)(n - at) * sizeof(int64_t));
        n++;
        g->rx[at] = lin, g->rx[at + 1] = lout, g->rk[at] = 0, g->rk[at + 1] = 0;
    }
    for (int64_t j = 1; j < n; j++) { /* unwrap */
        while (g->rx[j] - g->rx[j - 1] > 180.0) g->rx[j] -= 360.0;
        while (g->rx[j] - g->rx[j - 1] < -180.0) g->rx[j] += 360.0;
    }
    double wind = g->rx[0] - g->rx[n - 1];
    double shift = 0.0;
    while (wind + shift > 180.0) shift -= 360.0;
    while (wind + shift < -180.0) shift += 360.0;
    if (shift != 0.0) { /* winds round a pole: close along it (the first point again, a turn on, then the pole) */
        double qs = 0.0;
        for (int64_t j = 0; j < n; j++) qs += g->ry[j];
        double qp = qs > 0.0 ? 1.0 : -1.0;
        g->rx[n] = g->rx[0] - shift, g->ry[n] = g->ry[0], g->rk[n] = 0;
        g->rx[n + 1] = g->rx[0] - shift, g->ry[n + 1] = qp, g->rk[n + 1] = 0;
        g->rx[n + 2] = g->rx[0], g->ry[n + 2] = qp, g->rk[n + 2] = 0;
        n += 3;
    }
    double twice = 0.0;
    for (int64_t j = 0; j < n; j++) {
        int64_t i = (j + 1) % n;
        twice += (g->rx[j] - g->rx[0]) * (g->ry[i] - g->ry[0]) - (g->rx[i] - g->rx[0]) * (g->ry[j] - g->ry[0]);
    }
    *orient = twice >= 0.0 ? 1.0 : -1.0;
    for (int64_t j = 0; j < n; j++) g->rx[j] = (g->rx[j] - g->west) / g->dlng;
    return n;
}

/* One piece of boundary, (xa, ya) -> (xb, yb), within column c and band b (or above the grid, b = rows). */
static inline void add_piece(grid_t *g, int64_t c0, int64_t nc, int64_t b0, double xa, double ya, double xb,
                             double yb, int64_t c, int64_t b) {
    double dx = xb - xa;
    int64_t at = (b - b0) * nc + (c - c0);
    if (b < g->rows) {
        double lo = g->qe[b], hi = g->qe[b + 1];
        double ym = 0.5 * (min2(max2(ya, lo), hi) + min2(max2(yb, lo), hi));
        g->part[at] -= dx * (ym - lo);
    }
    g->wide[at] -= dx;
}

/* The ring (shifted by `shift` columns) over columns c0..c1, bands b0..b1 (b1 + 1: above them), into the strip
 * sums (zeroed by the caller, added to over every turn of longitudes the ring meets the grid in). */
static void cut_ring(grid_t *g, int64_t n, double shift, int64_t c0, int64_t c1, int64_t b0, int64_t b1) {
    int64_t nc = c1 - c0 + 1;
    int64_t band = b0;
    for (int64_t j = 0; j < n; j++) {
        int64_t i = (j + 1) % n;
        double x1 = g->rx[j] + shift, y1 = g->ry[j], x2 = g->rx[i] + shift, y2 = g->ry[i];
        if (x1 == x2) continue; /* a vertical piece adds nothing */
        if ((x1 < (double)c0 && x2 < (double)c0) || (x1 > (double)(c1 + 1) && x2 > (double)(c1 + 1))) continue;
        if (y1 < g->qe[b0] && y2 < g->qe[b0]) continue;
        double dxs = x2 - x1, dys = y2 - y1;
        /* the column lines and row lines crossed, in order along the segment */
        int64_t cstep = dxs > 0.0 ? 1 : -1;
        int64_t cn = dxs > 0.0 ? (int64_t)floor(x1) + 1 : (int64_t)ceil(x1) - 1; /* next column line */
        if (dxs > 0.0 && cn < c0) cn = c0;
        if (dxs < 0.0 && cn > c1 + 1) cn = c1 + 1;
        int64_t bstep = dys > 0.0 ? 1 : (dys < 0.0 ? -1 : 0);
        int64_t lb = band_of(g, y1, band); /* y1's band; the next row line is qe[lb + 1] going up, qe[lb] down */
        band = lb;
        int64_t rn = bstep > 0 ? lb + 1 : lb; /* index into qe of the next row line */
        if (bstep > 0 && rn < b0) rn = b0;
        if (bstep < 0 && rn > b1 + 1) rn = b1 + 1;
        double ta = 0.0, xa = x1, ya = y1;
        for (;;) {
            double tc = 2.0, tr = 2.0;
            if ((cstep > 0 && cn <= c1 + 1 && (double)cn < x2) || (cstep < 0 && cn >= c0 && (double)cn > x2))
                tc = ((double)cn - x1) / dxs;
            if (bstep != 0 && rn >= b0 && rn <= b1 + 1) {
                double ql = g->qe[rn];
                if ((bstep > 0 && ql < y2) || (bstep < 0 && ql > y2)) tr = (ql - y1) / dys;
            }
            double tb, xb, yb;
            int which;
            if (tc >= 1.0 && tr >= 1.0) {
                tb = 1.0, xb = x2, yb = y2, which = 0;
            } else if (tc <= tr) {
                tb = tc, xb = (double)cn, yb = y1 + tc * dys, which = 1;
            } else {
                tb = tr, xb = x1 + tr * dxs, yb = g->qe[rn], which = 2;
            }
            if (tb > ta) {
                double xm = 0.5 * (xa + xb), ym = 0.5 * (ya + yb);
                int64_t c = (int64_t)floor(xm);
                if (c >= c0 && c <= c1 && ym >= g->qe[b0]) {
                    int64_t b = band_of(g, ym, band);
                    band = b < b0 ? b0 : b;
                    if (b > b1) b = b1 + 1;
                    if (b >= b0) add_piece(g, c0, nc, b0, xa, ya, xb, yb, c, b);
                }
            }
            if (which == 0) break;
            if (which == 1) cn += cstep;
            else rn += bstep;
            ta = tb, xa = xb, ya = yb;
        }
    }
    /* each pair of chords' parabolic segment, to the pixel holding its middle point */
    for (int64_t j = 0; j < n; j++) {
        int64_t k = g->rk[j];
        if (k <= 0) continue;
        for (int64_t p = 0; p + 2 <= k; p += 2) {
            int64_t a = (j + p) % n, m = (j + p + 1) % n, c = (j + p + 2) % n;
            double ax = g->rx[a] + shift, ay = g->ry[a], mx = g->rx[m] + shift, my = g->ry[m];
            double cx = g->rx[c] + shift, cy = g->ry[c];
            int64_t col = (int64_t)floor(mx);
            if (col < c0 || col > c1) continue;
            int64_t b = band_of(g, my, b0);
            if (b < b0 || b > b1) continue;
            g->part[(b - b0) * nc + (col - c0)] += ((mx - ax) * (cy - ay) - (cx - ax) * (my - ay)) / 6.0;
        }
    }
}

/* The strip sums over columns c0..c1, bands b0..b1 into pieces: each pixel's trapezoids, and its row's height
 * times the widths of the ring's pieces above it in its column (a pixel wholly inside: its closed-form area). */
static void emit(grid_t *g, uint64_t cell, double orient, int64_t c0, int64_t c1, int64_t b0, int64_t b1,
                 dggs_pieces *out) {
    int64_t nc = c1 - c0 + 1;
    double scale = orient * g->dlng * (PI / 180.0);
    /* suffix sums down each column, in place: wide[b] becomes the widths above band b */
    for (int64_t c = c0; c <= c1; c++) {
        double above = g->wide[(b1 + 1 - b0) * nc + (c - c0)];
        for (int64_t b = b1; b >= b0; b--) {
            int64_t at = (b - b0) * nc + (c - c0);
            double mine = g->wide[at];
            g->wide[at] = above;
            above += mine;
        }
    }
    for (int64_t i = 0; i <= b1 - b0; i++) { /* row by row, in pixel order */
        int64_t b = g->north_up ? b1 - i : b0 + i;
        int64_t r = g->north_up ? g->rows - 1 - b : b;
        double h = g->qe[b + 1] - g->qe[b];
        for (int64_t c = c0; c <= c1; c++) {
            int64_t at = (b - b0) * nc + (c - c0);
            double area = (g->part[at] + h * g->wide[at]) * scale;
            int64_t pixel = r * g->cols + c;
            if (area > 0.0 && g->valid[pixel]) dggs_pieces_put(out, pixel, cell, area);
        }
    }
}

/* One cell of the level (its triangle t on `face`): its pieces in the block's pixels. 0, or -1 for an edge needing too many chords. */
static int cell_pieces(grid_t *g, uint64_t cell, int face, const double t[6], dggs_pieces *out) {
    double orient;
    int64_t n = cell_ring(g, face, t, &orient);
    if (n < 0) return -1;
    double xlo = INFINITY, xhi = -INFINITY, ylo = INFINITY, yhi = -INFINITY;
    for (int64_t j = 0; j < n; j++) {
        xlo = min2(xlo, g->rx[j]), xhi = max2(xhi, g->rx[j]);
        ylo = min2(ylo, g->ry[j]), yhi = max2(yhi, g->ry[j]);
    }
    if (yhi <= g->qe[0] || ylo >= g->qe[g->rows]) return 0;
    int64_t b0 = band_of(g, ylo, g->hint), b1 = band_of(g, yhi, b0);
    if (b0 < 0) b0 = 0;
    if (b1 >= g->rows) b1 = g->rows - 1;
    double period = 360.0 / g->dlng;
    /* every turn of longitudes the ring's columns meet the grid's in, added into one set of strip sums (a ring
     * round a pole spans a whole turn: the column where two turns meet gets its part from each) */
    double first = ceil(-xhi / period) * period;
    if (xhi + first <= 0.0) first += period;
    if (!(xlo + first < (double)g->cols)) return 0;
    int64_t c0 = g->cols, c1 = -1;
    for (double s = first; xlo + s < (double)g->cols; s += period) {
        int64_t lo = (int64_t)floor(max2(xlo + s, 0.0)), hi = (int64_t)floor(min2(xhi + s, (double)g->cols - 0.5));
        if (lo < c0) c0 = lo;
        if (hi > c1) c1 = hi;
    }
    if (c1 > g->cols - 1) c1 = g->cols - 1;
    if (c0 > c1) return 0;
    int64_t cells = (b1 - b0 + 2) * (c1 - c0 + 1);
    memset(g->part, 0, (size_t)cells * sizeof(double));
    memset(g->wide, 0, (size_t)cells * sizeof(double));
    for (double s = first; xlo + s < (double)g->cols; s += period) cut_ring(g, n, s, c0, c1, b0, b1);
    emit(g, cell, orient, c0, c1, b0, b1, out);
    return 0;
}

int64_t dggs_latlng_pieces_work_words(int64_t rows, int64_t cols) {
    if (rows < 1 || cols < 1) return 0;
    return 3 * (int64_t)RING_CAP + 2 * (rows + 2) * cols + (rows + 1) + 6 * (int64_t)MEMO;
}

dggs_error dggs_latlng_pieces(double west, double dlng, const double *lat_edges, int64_t rows, int64_t cols,
                              const uint8_t *valid, int level, double tol, dggs_pieces *out, void *work,
                              int64_t work_words, int64_t *resume, int64_t *need) {
    if (level < 0 || level > DGGS_MAX_LEVEL) return DGGS_E_LEVEL;
    if (rows < 1 || cols < 1 || !(dlng > 0.0) || !(tol > 0.0) || !isfinite(west) || *resume < 0)
        return DGGS_E_DOMAIN;
    if (dlng * (double)cols > 360.0 * (1.0 + 1e-12)) return DGGS_E_DOMAIN; /* a column would be counted twice */
    for (int64_t r = 0; r <= rows; r++) {
        if (!(lat_edges[r] >= -90.0 && lat_edges[r] <= 90.0)) return DGGS_E_LATLNG;
    }
    bool north_up = lat_edges[0] > lat_edges[rows];
    for (int64_t r = 0; r < rows; r++) {
        if (north_up ? !(lat_edges[r] > lat_edges[r + 1]) : !(lat_edges[r] < lat_edges[r + 1])) return DGGS_E_DOMAIN;
    }
    if (work_words < dggs_latlng_pieces_work_words(rows, cols)) return DGGS_E_BUFFER;
    double *w = (double *)work;
    grid_t g = {0};
    g.west = west, g.dlng = dlng, g.rows = rows, g.cols = cols, g.north_up = north_up, g.valid = valid, g.tol = tol;
    g.rx = w, g.ry = w + RING_CAP, g.rk = (int64_t *)(w + 2 * RING_CAP);
    g.part = w + 3 * RING_CAP, g.wide = g.part + (rows + 2) * cols;
    double *qe = g.wide + (rows + 2) * cols;
    g.memo = qe + rows + 1;
    for (int64_t i = 0; i < MEMO; i++) g.memo[6 * i + 2] = -1.0; /* no face: empty */
    for (int64_t b = 0; b <= rows; b++) {
        double phi = lat_edges[north_up ? rows - b : b] * (PI / 180.0), sb, cb;
        dggs_authalic_sincos(dggs_sin(phi), dggs_cos(phi), &sb, &cb);
        qe[b] = sb;
    }
    g.qe = qe;
    g.box_west = west, g.box_east = west + dlng * (double)cols;
    g.beta_lo = dggs_asin(qe[0]), g.beta_hi = dggs_asin(qe[rows]);

    /* depth first over the hierarchy, the cells whose caps meet the box; the target cells counted for *resume.
     * Each cell's triangle is its parent's child (dggs_child_corners), the steps dggs_triangle takes from the
     * face: the same bits, without walking every level again for every cell. */
    enum { DEPTH = 6 * (DGGS_MAX_LEVEL + 2) };
    uint64_t stack[DEPTH];
    int levels[DEPTH];
    bool held[DEPTH]; /* inside a cell the box holds whole: no test */
    double tri[DEPTH][6];
    int64_t top = 0, seen = 0;
    for (int f = DGGS_NUM_FACES - 1; f >= 0; f--) {
        stack[top] = dggs_base_cell(f), levels[top] = 0, held[top] = false;
        dggs_triangle(stack[top], tri[top]);
        top++;
    }
    while (top > 0) {
        uint64_t cell = stack[--top];
        int lv = levels[top];
        bool inside = held[top];
        int face = dggs_face_of(cell);
        double t[6];
        memcpy(t, tri[top], sizeof t);
        if (lv < level) {
            if (!inside && !cap_meets(&g, face, t, &inside)) continue;
            int kids = lv == 0 ? 6 : 3;
            for (int d = kids - 1; d >= 0; d--) {
                stack[top] = dggs_clip_child(cell, lv, d), levels[top] = lv + 1, held[top] = inside;
                if (lv == 0) {
                    dggs_triangle(stack[top], tri[top]);
                } else {
                    memcpy(tri[top], t, sizeof t);
                    dggs_child_corners(tri[top], d);
                }
                top++;
            }
            continue;
        }
        if (seen++ < *resume) continue;
        int64_t n0 = out->n;
        if (cell_pieces(&g, cell, face, t, out)) return DGGS_E_FAILED;
        if (out->n > out->cap) {
            *need = out->n;
            out->n = n0;
            *resume = seen - 1;
            return DGGS_E_BUFFER;
        }
    }
    *resume = seen;
    *need = out->n;
    return DGGS_OK;
}
