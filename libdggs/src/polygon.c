/* Point- and circle-against-polygon tests for polygon fill (polygon.h): a port of index/_kernel/polygon.py. */
#include "polygon.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* numba's int(math.floor(v)) for a double: fptosi, whose out-of-range and NaN results are x86's cvttsd2si's
 * "integer indefinite", INT64_MIN (C leaves that cast undefined, so it is spelled out). */
static inline int64_t floor_to_i64(double v) {
    double f = floor(v);
    if (!(f >= -0x1p63 && f < 0x1p63)) return INT64_MIN;
    return (int64_t)f;
}

/* Python's (and numba's) min/max of two: the first unless the second is strictly smaller (larger). */
static inline double min2(double a, double b) { return b < a ? b : a; }
static inline double max2(double a, double b) { return b > a ? b : a; }
static inline int64_t imin2(int64_t a, int64_t b) { return b < a ? b : a; }
static inline int64_t imax2(int64_t a, int64_t b) { return b > a ? b : a; }

/* numba's ndarray.min() / .max() of floats: the first NaN met, else the first of the extreme values. */
static double array_min(const double *a, int64_t n) {
    double m = a[0];
    if (isnan(m)) return m;
    for (int64_t i = 1; i < n; i++) {
        double v = a[i];
        if (isnan(v)) return v;
        if (v < m) m = v;
    }
    return m;
}

static double array_max(const double *a, int64_t n) {
    double m = a[0];
    if (isnan(m)) return m;
    for (int64_t i = 1; i < n; i++) {
        double v = a[i];
        if (isnan(v)) return v;
        if (v > m) m = v;
    }
    return m;
}

/* polygon.py _index: bucket of a coordinate along one axis, clipped to the grid (monotone in v). */
static inline int64_t bucket_index(double v, double origin, double size, int64_t side) {
    return imin2(imax2(floor_to_i64((v - origin) / size), 0), side - 1);
}

void dggs_ring_edges(const double *xy, int64_t n, double *x0, double *y0, double *x1, double *y1, int64_t *m,
                     bool *closed) {
    int64_t k = 0;
    int64_t i = 0;
    while (i < n) {
        int64_t j = i + 1;
        while (j < n && !(xy[2 * j] == xy[2 * i] && xy[2 * j + 1] == xy[2 * i + 1])) j++;
        if (j == n) {
            *m = k;
            *closed = false;
            return;
        }
        for (int64_t e = i; e < j; e++) {
            x0[k] = xy[2 * e];
            y0[k] = xy[2 * e + 1];
            x1[k] = xy[2 * e + 2];
            y1[k] = xy[2 * e + 3];
            k++;
        }
        i = j + 1;
    }
    *m = k;
    *closed = true;
}

dggs_error dggs_polygon_build_count(const double *x0, const double *y0, const double *x1, const double *y1, int64_t n,
                                    int64_t side, double *frame, int64_t *start) {
    if (n < 1 || side < 1 || side > ((int64_t)1 << 31)) return DGGS_E_DOMAIN;
    double xmin = min2(array_min(x0, n), array_min(x1, n));
    double ymin = min2(array_min(y0, n), array_min(y1, n));
    double xmax = max2(array_max(x0, n), array_max(x1, n));
    double ymax = max2(array_max(y0, n), array_max(y1, n));
    double w = max2((xmax - xmin) / (double)side, 1e-300);
    double h = max2((ymax - ymin) / (double)side, 1e-300);
    frame[0] = xmin;
    frame[1] = ymin;
    frame[2] = w;
    frame[3] = h;
    frame[4] = (double)side;
    frame[5] = xmax;
    frame[6] = ymax;
    int64_t buckets = side * side;
    memset(start, 0, (size_t)(buckets + 1) * sizeof(int64_t)); /* count, shifted one bucket on */
    for (int64_t i = 0; i < n; i++) {
        int64_t c0 = bucket_index(min2(x0[i], x1[i]), xmin, w, side), c1 = bucket_index(max2(x0[i], x1[i]), xmin, w, side);
        int64_t r0 = bucket_index(min2(y0[i], y1[i]), ymin, h, side), r1 = bucket_index(max2(y0[i], y1[i]), ymin, h, side);
        for (int64_t r = r0; r <= r1; r++)
            for (int64_t c = c0; c <= c1; c++) start[r * side + c + 1] += 1;
    }
    for (int64_t b = 1; b <= buckets; b++) start[b] += start[b - 1]; /* np.cumsum */
    return DGGS_OK;
}

/* np.sort's order of doubles: ascending, NaN last (only the count of crossings right of a point is used). */
static int cmp_double(const void *pa, const void *pb) {
    double a = *(const double *)pa, b = *(const double *)pb;
    if (a < b) return -1;
    if (a > b) return 1;
    if (isnan(a)) return isnan(b) ? 0 : 1;
    return isnan(b) ? -1 : 0;
}

/* polygon.py _empty_buckets: per bucket, the next empty bucket of its row and whether that one's centre is
 * inside. A row's crossings with the horizontal line through its buckets' centres, sorted, give each empty
 * bucket's centre its crossing number. No segment meets an empty bucket, so every crossing lies at least half a
 * bucket from its centre, far beyond rounding, and every point of it shares its side. */
static void empty_buckets(const double *x0, const double *y0, const double *x1, const double *y1, const double *frame,
                          const int64_t *start, const int64_t *items, int64_t *out, double *xs) {
    int64_t side = (int64_t)frame[4];
    double xmin = frame[0], ymin = frame[1], w = frame[2], h = frame[3];
    for (int64_t row = 0; row < side; row++) {
        double yc = ymin + ((double)row + 0.5) * h;
        int64_t m = 0;
        for (int64_t col = 0; col < side; col++) {
            int64_t b = row * side + col;
            for (int64_t k = start[b]; k < start[b + 1]; k++) {
                int64_t i = items[k];
                if ((y0[i] > yc) != (y1[i] > yc) && bucket_index(min2(x0[i], x1[i]), xmin, w, side) == col) {
                    xs[m] = x0[i] + (yc - y0[i]) * (x1[i] - x0[i]) / (y1[i] - y0[i]);
                    m++;
                }
            }
        }
        qsort(xs, (size_t)m, sizeof(double), cmp_double);
        int64_t j = m;
        int64_t nxt = side;
        for (int64_t col = side - 1; col >= 0; col--) {
            int64_t b = row * side + col;
            double xc = xmin + ((double)col + 0.5) * w;
            while (j > 0 && xs[j - 1] > xc) j--;
            if (start[b] == start[b + 1]) nxt = col + (side + 1) * ((m - j) & 1);
            out[b] = nxt;
        }
    }
}

void dggs_polygon_build_fill(const double *x0, const double *y0, const double *x1, const double *y1, int64_t n,
                             const double *frame, const int64_t *start, int64_t *items, int64_t *empty,
                             double *scratch) {
    double xmin = frame[0], ymin = frame[1], w = frame[2], h = frame[3];
    int64_t side = (int64_t)frame[4];
    int64_t buckets = side * side;
    int64_t *fill = empty; /* the cursors: start[:-1].copy(), in the array written last */
    memcpy(fill, start, (size_t)buckets * sizeof(int64_t));
    for (int64_t i = 0; i < n; i++) {
        int64_t c0 = bucket_index(min2(x0[i], x1[i]), xmin, w, side), c1 = bucket_index(max2(x0[i], x1[i]), xmin, w, side);
        int64_t r0 = bucket_index(min2(y0[i], y1[i]), ymin, h, side), r1 = bucket_index(max2(y0[i], y1[i]), ymin, h, side);
        for (int64_t r = r0; r <= r1; r++)
            for (int64_t c = c0; c <= c1; c++) {
                items[fill[r * side + c]] = i;
                fill[r * side + c] += 1;
            }
    }
    empty_buckets(x0, y0, x1, y1, frame, start, items, empty, scratch);
}

bool dggs_near(double px, double py, double r, double sx, const dggs_edge_grid *g) {
    const double *frame = g->frame;
    if (px + r / sx < frame[0] || px - r / sx > frame[5] || py + r < frame[1] || py - r > frame[6])
        return false; /* the ellipse's box misses the edges' box */
    int64_t side = (int64_t)frame[4];
    int64_t c0 = bucket_index(px - r / sx, frame[0], frame[2], side), c1 = bucket_index(px + r / sx, frame[0], frame[2], side);
    int64_t r0 = bucket_index(py - r, frame[1], frame[3], side), r1 = bucket_index(py + r, frame[1], frame[3], side);
    double rr = r * r;
    for (int64_t row = r0; row <= r1; row++) {
        for (int64_t col = c0; col <= c1; col++) {
            int64_t b = row * side + col;
            for (int64_t k = g->start[b]; k < g->start[b + 1]; k++) {
                int64_t i = g->items[k];
                double ex = (g->x1[i] - g->x0[i]) * sx, ey = g->y1[i] - g->y0[i];
                double wx = (px - g->x0[i]) * sx, wy = py - g->y0[i];
                double ee = ex * ex + ey * ey;
                double t = ee == 0.0 ? 0.0 : min2(1.0, max2(0.0, (wx * ex + wy * ey) / ee));
                double dx = wx - t * ex, dy = wy - t * ey;
                if (dx * dx + dy * dy <= rr) return true;
            }
        }
    }
    return false;
}

/* polygon.py _orient: orientation of (a, b, p), positive if p lies left of a -> b; 0.0 where rounding could flip
 * its sign. */
static inline double orient(double ax, double ay, double bx, double by, double px, double py) {
    double left = (ax - px) * (by - py);
    double right = (ay - py) * (bx - px);
    double det = left - right;
    double bound = DGGS_ORIENT_ERR * (fabs(left) + fabs(right));
    if (fabs(det) <= bound || bound < DGGS_ORIENT_TINY) return 0.0;
    return det;
}

/* polygon.py parity: the ray from the point to +x, up to the centre of the first bucket of its row at or right
 * of its own that holds no segment (whose side is known; without one, to infinity), crosses edge i when
 * (y0 > py) != (y1 > py) (the half-open rule) and the point and the ray's end lie on either side of it, by
 * orientations trusted only beyond their error bound. An edge spanning several buckets of the row is counted in
 * the first of them at or right of the point's. An edge whose bounding box holds the point, found in the point's
 * own bucket, makes the answer undecided when the point may lie on it. */
int dggs_parity(double px, double py, const dggs_edge_grid *g) {
    const double *frame = g->frame;
    if (!(frame[0] <= px && px <= frame[5] && frame[1] <= py && py <= frame[6]))
        return 0; /* outside the edges' bounding box (exact bounds): outside every ring */
    int64_t side = (int64_t)frame[4];
    double xmin = frame[0], ymin = frame[1], w = frame[2], h = frame[3];
    int64_t row = bucket_index(py, ymin, h, side);
    int64_t first = bucket_index(px, xmin, w, side);
    int64_t stop = g->empty[row * side + first];
    bool odd = stop > side; /* the side of the stop bucket's centre */
    if (odd) stop = stop - (side + 1);
    if (stop == first) return odd ? 1 : 0; /* no segment in the point's bucket: the side of its centre */
    double end = stop < side ? xmin + ((double)stop + 0.5) * w : INFINITY;
    for (int64_t col = first; col < stop; col++) {
        int64_t b = row * side + col;
        for (int64_t k = g->start[b]; k < g->start[b + 1]; k++) {
            int64_t i = g->items[k];
            double ax = g->x0[i], ay = g->y0[i], bx = g->x1[i], by = g->y1[i];
            bool crosses = (ay > py) != (by > py);
            if (crosses) {
                if (imax2(bucket_index(min2(ax, bx), xmin, w, side), first) != col)
                    continue; /* counted in an earlier bucket of this row */
            } else if (col != first || !(min2(ax, bx) <= px && px <= max2(ax, bx) && min2(ay, by) <= py &&
                                         py <= max2(ay, by))) {
                continue; /* neither crosses the ray nor can hold the point (exact comparisons) */
            }
            double det = orient(ax, ay, bx, by, px, py);
            if (det == 0.0) return -1; /* the point may lie on this edge */
            /* the crossing lies right of the point iff the point is left of an upward edge (right of a downward one) */
            if (crosses && (det > 0.0) == (by > ay)) {
                if (end < INFINITY) {
                    double beyond = orient(ax, ay, bx, by, end, py);
                    if (beyond == 0.0) return -1; /* cannot happen: the end is half a bucket off every edge */
                    if ((beyond > 0.0) == (by > ay)) continue; /* the crossing lies beyond the ray's end */
                }
                odd = !odd;
            }
        }
    }
    return odd ? 1 : 0;
}

void dggs_polygon_classify(double px, double py, double r, const dggs_edge_grid *g, bool *hit, bool *inside) {
    if (dggs_near(px, py, r, 1.0, g)) {
        *hit = true;
        *inside = false;
    } else {
        bool c = dggs_parity(px, py, g) != 0; /* -1 only within r of an edge */
        *hit = c;
        *inside = c;
    }
}

/* ---- exact predicates (the public polygon fill's own; no numba counterpart) ---- */

/* Shewchuk 1997, "Adaptive precision floating-point arithmetic and fast robust geometric predicates": the
 * error-free transformations, exact under round-to-nearest without contraction (-ffp-contract=off). */
static inline void two_sum(double a, double b, double *x, double *y) {
    *x = a + b;
    double bvirt = *x - a, avirt = *x - bvirt;
    *y = (a - avirt) + (b - bvirt);
}

static inline void two_diff(double a, double b, double *x, double *y) {
    *x = a - b;
    double bvirt = a - *x, avirt = *x + bvirt;
    *y = (a - avirt) + (bvirt - b);
}

static inline void split(double a, double *hi, double *lo) {
    double c = 134217729.0 * a; /* 2^27 + 1 */
    double abig = c - a;
    *hi = c - abig;
    *lo = a - *hi;
}

static inline void two_product(double a, double b, double *x, double *y) {
    *x = a * b;
    double ahi, alo, bhi, blo;
    split(a, &ahi, &alo);
    split(b, &bhi, &blo);
    double err1 = *x - ahi * bhi, err2 = err1 - alo * bhi, err3 = err2 - ahi * blo;
    *y = alo * blo - err3;
}

/* Grow-Expansion with zero elimination: h = e + b (h has room for elen + 1 components); returns its length. */
static int grow_expansion(int elen, const double *e, double b, double *h) {
    double q = b;
    int hlen = 0;
    for (int i = 0; i < elen; i++) {
        double qnew, hh;
        two_sum(q, e[i], &qnew, &hh);
        q = qnew;
        if (hh != 0.0) h[hlen++] = hh;
    }
    if (q != 0.0 || hlen == 0) h[hlen++] = q;
    return hlen;
}

int dggs_orient_exact(double ax, double ay, double bx, double by, double px, double py) {
    double left = (ax - px) * (by - py), right = (ay - py) * (bx - px);
    double det = left - right;
    double bound = 3.3306690738754716e-16 * (fabs(left) + fabs(right)); /* ccwerrboundA */
    if (det > bound || -det > bound) return det > 0.0 ? 1 : -1;
    /* exact: (acx + acxt)(bcy + bcyt) - (acy + acyt)(bcx + bcxt) as 16 products' components */
    double acx, acxt, bcy, bcyt, acy, acyt, bcx, bcxt;
    two_diff(ax, px, &acx, &acxt);
    two_diff(by, py, &bcy, &bcyt);
    two_diff(ay, py, &acy, &acyt);
    two_diff(bx, px, &bcx, &bcxt);
    const double l[4][2] = {{acx, bcy}, {acx, bcyt}, {acxt, bcy}, {acxt, bcyt}};
    const double r[4][2] = {{acy, bcx}, {acy, bcxt}, {acyt, bcx}, {acyt, bcxt}};
    double e[17], h[17];
    int elen = 0;
    for (int k = 0; k < 4; k++) {
        double x, y;
        two_product(l[k][0], l[k][1], &x, &y);
        elen = grow_expansion(elen, e, x, h), memcpy(e, h, (size_t)elen * sizeof(double));
        elen = grow_expansion(elen, e, y, h), memcpy(e, h, (size_t)elen * sizeof(double));
        two_product(r[k][0], r[k][1], &x, &y);
        elen = grow_expansion(elen, e, -x, h), memcpy(e, h, (size_t)elen * sizeof(double));
        elen = grow_expansion(elen, e, -y, h), memcpy(e, h, (size_t)elen * sizeof(double));
    }
    double top = e[elen - 1]; /* the largest component carries the sign */
    return (top > 0.0) - (top < 0.0);
}

/* GEOS's RayCrossingCounter::countSegment with exact orientations. */
typedef struct {
    int64_t crossings;
    bool on;
} ray_counter;

static inline void count_segment(ray_counter *rc, double px, double py, double x1, double y1, double x2, double y2) {
    if (x1 < px && x2 < px) return; /* strictly left of the point */
    if (px == x2 && py == y2) {
        rc->on = true;
        return;
    }
    if (y1 == py && y2 == py) { /* horizontal: on it, or not counted */
        double lo = x1 < x2 ? x1 : x2, hi = x1 < x2 ? x2 : x1;
        if (px >= lo && px <= hi) rc->on = true;
        return;
    }
    if ((y1 > py && y2 <= py) || (y2 > py && y1 <= py)) {
        int sign = dggs_orient_exact(x1, y1, x2, y2, px, py);
        if (sign == 0) {
            rc->on = true;
            return;
        }
        if (y2 < y1) sign = -sign;
        if (sign > 0) rc->crossings++;
    }
}

int dggs_locate_exact(double px, double py, const double *x0, const double *y0, const double *x1, const double *y1,
                      int64_t n) {
    ray_counter rc = {0, false};
    for (int64_t i = 0; i < n && !rc.on; i++) count_segment(&rc, px, py, x0[i], y0[i], x1[i], y1[i]);
    return rc.on ? -1 : (int)(rc.crossings & 1);
}

int dggs_locate_ring(double px, double py, const double *xy, int64_t m) {
    ray_counter rc = {0, false};
    for (int64_t i = 0; i < m && !rc.on; i++) {
        int64_t j = i + 1 == m ? 0 : i + 1;
        count_segment(&rc, px, py, xy[2 * i], xy[2 * i + 1], xy[2 * j], xy[2 * j + 1]);
    }
    return rc.on ? -1 : (int)(rc.crossings & 1);
}

int dggs_locate(double px, double py, const dggs_edge_grid *g, int64_t n) {
    int p = dggs_parity(px, py, g);
    if (p >= 0) return p;
    return dggs_locate_exact(px, py, g->x0, g->y0, g->x1, g->y1, n);
}

/* Whether c, known collinear with ab, lies on the closed segment ab. */
static inline bool on_segment(double ax, double ay, double bx, double by, double cx, double cy) {
    return min2(ax, bx) <= cx && cx <= max2(ax, bx) && min2(ay, by) <= cy && cy <= max2(ay, by);
}

int dggs_segments_meet(double ax, double ay, double bx, double by, double cx, double cy, double dx, double dy) {
    if (max2(ax, bx) < min2(cx, dx) || max2(cx, dx) < min2(ax, bx) || max2(ay, by) < min2(cy, dy) ||
        max2(cy, dy) < min2(ay, by))
        return 0; /* boxes apart */
    int o1 = dggs_orient_exact(ax, ay, bx, by, cx, cy), o2 = dggs_orient_exact(ax, ay, bx, by, dx, dy);
    int o3 = dggs_orient_exact(cx, cy, dx, dy, ax, ay), o4 = dggs_orient_exact(cx, cy, dx, dy, bx, by);
    if (o1 * o2 < 0 && o3 * o4 < 0) return 2;
    if ((o1 == 0 && on_segment(ax, ay, bx, by, cx, cy)) || (o2 == 0 && on_segment(ax, ay, bx, by, dx, dy)) ||
        (o3 == 0 && on_segment(cx, cy, dx, dy, ax, ay)) || (o4 == 0 && on_segment(cx, cy, dx, dy, bx, by)))
        return 1;
    return 0;
}

bool dggs_grid_span(const dggs_edge_grid *g, double xlo, double xhi, double ylo, double yhi, int64_t *c0, int64_t *c1,
                    int64_t *r0, int64_t *r1) {
    const double *frame = g->frame;
    if (xhi < frame[0] || xlo > frame[5] || yhi < frame[1] || ylo > frame[6]) return false;
    int64_t side = (int64_t)frame[4];
    *c0 = bucket_index(xlo, frame[0], frame[2], side);
    *c1 = bucket_index(xhi, frame[0], frame[2], side);
    *r0 = bucket_index(ylo, frame[1], frame[3], side);
    *r1 = bucket_index(yhi, frame[1], frame[3], side);
    return true;
}
