/* Clipping of polygons by the cells of the hierarchy, in one face plane (index/_kernel/clip.py): see clip.h. */
#include "clip.h"

#include <math.h>
#include <string.h>

#include "bits.h"
#include "geometry.h"
#include "pixels_tables.h"
#include "tables.h"

/* Python's (and numba's) max(a, b) and min(a, b) of two floats: the second only if it compares greater (less). */
static inline double py_max(double a, double b) { return b > a ? b : a; }
static inline double py_min(double a, double b) { return b < a ? b : a; }

double dggs_clip_area(const double *x, const double *y, int64_t n) {
    if (n < 3) return 0.0;
    double x0 = x[0], y0 = y[0];
    double s = 0.0;
    for (int64_t i = 1; i < n - 1; i++) s += (x[i] - x0) * (y[i + 1] - y0) - (x[i + 1] - x0) * (y[i] - y0);
    return 0.5 * s;
}

int64_t dggs_clip_edge(const double *x, const double *y, int64_t n, double ax, double ay, double bx, double by,
                       double *ox, double *oy, int64_t cap) {
    int64_t m = 0;
    if (n == 0) return 0;
    double px = x[n - 1], py = y[n - 1];
    bool pin = (bx - ax) * (py - ay) - (by - ay) * (px - ax) >= 0.0;
    for (int64_t i = 0; i < n; i++) {
        double qx = x[i], qy = y[i];
        bool qin = (bx - ax) * (qy - ay) - (by - ay) * (qx - ax) >= 0.0;
        if (qin != pin) { /* the edge p -> q crosses the line: its crossing point */
            double dpx = qx - px, dpy = qy - py;
            double den = (bx - ax) * dpy - (by - ay) * dpx;
            double t = den != 0.0 ? ((ax - px) * (by - ay) - (ay - py) * (bx - ax)) / den : 0.0;
            t = py_min(py_max(-t, 0.0), 1.0);
            if (m >= cap) return -1;
            ox[m] = px + t * dpx;
            oy[m] = py + t * dpy;
            m += 1;
        }
        if (qin) {
            if (m >= cap) return -1;
            ox[m] = qx;
            oy[m] = qy;
            m += 1;
        }
        px = qx, py = qy, pin = qin;
    }
    return m;
}

int64_t dggs_clip(const double *x, const double *y, int64_t n, double ax, double ay, double bx, double by, double cx,
                  double cy, double *ox, double *oy, double *tx, double *ty, int64_t cap) {
    if ((bx - ax) * (cy - ay) - (by - ay) * (cx - ax) < 0.0) { /* make it counter-clockwise */
        double sx = bx, sy = by;
        bx = cx, by = cy, cx = sx, cy = sy;
    }
    int64_t m = dggs_clip_edge(x, y, n, ax, ay, bx, by, tx, ty, cap);
    if (m < 0) return -1;
    m = dggs_clip_edge(tx, ty, m, bx, by, cx, cy, ox, oy, cap);
    if (m < 0) return -1;
    return m ? dggs_clip_edge(ox, oy, m, cx, cy, ax, ay, tx, ty, cap) : 0;
}

uint64_t dggs_clip_child(uint64_t cell, int level, int digit) {
    return cell | ((uint64_t)(digit + 1) << dggs_shift_of(level + 1));
}

void dggs_pieces_put(dggs_pieces *out, int64_t pixel, uint64_t cell, double area) {
    if (out->n < out->cap) {
        out->pixel[out->n] = pixel;
        out->cell[out->n] = cell;
        out->area[out->n] = area;
    }
    out->n += 1;
}

void dggs_clip_whole(uint64_t cell, int level, int target, double total, int64_t pixel, dggs_pieces *out) {
    int64_t count = 1; /* 3 ** (target - level) */
    for (int lv = level; lv < target; lv++) count *= 3;
    double share = total / (double)count;
    if (out->n > out->cap - count) { /* it does not fit: counted only (the caller calls again) */
        out->n += count;
        return;
    }
    for (int64_t k = 0; k < count; k++) {
        uint64_t cid = cell;
        int64_t rest = k;
        for (int lv = target; lv > level; lv--) { /* base-3 digits, the finest last */
            cid |= (uint64_t)(rest % 3 + 1) << dggs_shift_of(lv);
            rest /= 3;
        }
        out->pixel[out->n] = pixel;
        out->cell[out->n] = cid;
        out->area[out->n] = share;
        out->n += 1;
    }
}

int dggs_clip_split(const double *x, const double *y, int64_t n, double ax, double ay, double bx, double by,
                    double *lx, double *ly, double *rx, double *ry, int64_t cap, int64_t *nl_out, int64_t *nr_out) {
    int64_t nl = 0, nr = 0;
    *nl_out = 0, *nr_out = 0;
    if (n == 0) return 0;
    double px = x[n - 1], py = y[n - 1];
    double ps = (bx - ax) * (py - ay) - (by - ay) * (px - ax);
    for (int64_t i = 0; i < n; i++) {
        double qx = x[i], qy = y[i];
        double qs = (bx - ax) * (qy - ay) - (by - ay) * (qx - ax);
        if ((ps > 0.0 && qs < 0.0) || (ps < 0.0 && qs > 0.0)) { /* the edge crosses the line: both sides get it */
            double t = ps / (ps - qs);
            double ix = px + t * (qx - px), iy = py + t * (qy - py);
            if (nl >= cap || nr >= cap) return -1;
            lx[nl] = ix, ly[nl] = iy;
            rx[nr] = ix, ry[nr] = iy;
            nl += 1;
            nr += 1;
        }
        if (qs >= 0.0) {
            if (nl >= cap) return -1;
            lx[nl] = qx, ly[nl] = qy;
            nl += 1;
        }
        if (qs <= 0.0) {
            if (nr >= cap) return -1;
            rx[nr] = qx, ry[nr] = qy;
            nr += 1;
        }
        px = qx, py = qy, ps = qs;
    }
    *nl_out = nl, *nr_out = nr;
    return 0;
}

static void copy_xy(double *dx, double *dy, const double *sx, const double *sy, int64_t n) {
    if (n > 0) {
        memmove(dx, sx, (size_t)n * sizeof(double));
        memmove(dy, sy, (size_t)n * sizeof(double));
    }
}

int dggs_clip_children(int level, const double t[6], const double *x, const double *y, int64_t n, double *kx,
                       double *ky, int64_t *kn, double *tx, double *ty, int64_t width) {
    if (level == 0) {
        for (int j = 0; j < 6; j++) {
            const double(*c)[2] = dggs_level1_corners[j];
            int64_t got = dggs_clip(x, y, n, c[0][0], c[0][1], c[1][0], c[1][1], c[2][0], c[2][1], kx + j * width,
                                    ky + j * width, tx, ty, width);
            if (got < 0) return -1;
            kn[j] = got;
            copy_xy(kx + j * width, ky + j * width, tx, ty, got);
        }
        return 0;
    }
    double ax = t[0], ay = t[1], bx = t[2], by = t[3], cx = t[4], cy = t[5];
    double dx = cx + (ax - cx) / 3.0, dy = cy + (ay - cy) / 3.0;
    double ex = 0.5 * (ax + bx), ey = 0.5 * (ay + by);
    double *k0x = kx, *k0y = ky, *k1x = kx + width, *k1y = ky + width, *k2x = kx + 2 * width, *k2y = ky + 2 * width;
    int64_t left, right, rest;
    if (dggs_clip_split(x, y, n, bx, by, dx, dy, k0x, k0y, tx, ty, width, &left, &right)) return -1;
    if ((dx - bx) * (cy - by) - (dy - by) * (cx - bx) >= 0.0) { /* C lies left of B -> D: child 0 is the left part */
        kn[0] = left;
        copy_xy(k1x, k1y, tx, ty, right); /* the rest, in child 1's place for now */
        rest = right;
    } else {
        copy_xy(k1x, k1y, k0x, k0y, left);
        copy_xy(k0x, k0y, tx, ty, right);
        kn[0] = right;
        rest = left;
    }
    if (dggs_clip_split(k1x, k1y, rest, dx, dy, ex, ey, k2x, k2y, tx, ty, width, &left, &right)) return -1;
    if ((ex - dx) * (ay - dy) - (ey - dy) * (ax - dx) >= 0.0) { /* A lies left of D -> E: child 2 is the left part */
        kn[2] = left;
        copy_xy(k1x, k1y, tx, ty, right);
        kn[1] = right;
    } else {
        copy_xy(k1x, k1y, k2x, k2y, left);
        kn[1] = left;
        copy_xy(k2x, k2y, tx, ty, right);
        kn[2] = right;
    }
    return 0;
}

int dggs_clip_descend(uint64_t root, int root_level, const double corners[6], int target, const double *px,
                      const double *py, int64_t nv, int64_t pixel, dggs_pieces *out, dggs_clip_work *w) {
    int64_t width = w->width, plane = 6 * width;
    if (w->levels < 1) return -1;
    for (int i = 0; i < 6; i++) w->tri[i] = corners[i];
    w->ids[0] = root;
    if (dggs_clip_children(root_level, w->tri, px, py, nv, w->kx, w->ky, w->kn, w->tx, w->ty, width)) return -1;
    w->nxt[0] = 0;
    int64_t d = 0;
    while (d >= 0) {
        int level = root_level + (int)d;
        if (w->nxt[d] == (level == 0 ? 6 : 3)) {
            d -= 1;
            continue;
        }
        int digit = (int)w->nxt[d];
        w->nxt[d] += 1;
        int64_t m = w->kn[6 * d + digit];
        double *x = w->kx + d * plane + digit * width, *y = w->ky + d * plane + digit * width;
        double got = fabs(dggs_clip_area(x, y, m));
        if (got <= 0.0) continue;
        uint64_t cell = dggs_clip_child(w->ids[d], level, digit);
        if (level + 1 == target) {
            dggs_pieces_put(out, pixel, cell, got);
            continue;
        }
        double t[6];
        if (level == 0) {
            const double(*c)[2] = dggs_level1_corners[digit];
            t[0] = c[0][0], t[1] = c[0][1], t[2] = c[1][0], t[3] = c[1][1], t[4] = c[2][0], t[5] = c[2][1];
        } else {
            memcpy(t, w->tri + 6 * d, sizeof t);
            dggs_child_corners(t, digit);
        }
        double ax = t[0], ay = t[1], bx = t[2], by = t[3], cx = t[4], cy = t[5];
        if (got >= DGGS_CLIP_WHOLE * 0.5 * fabs((bx - ax) * (cy - ay) - (by - ay) * (cx - ax))) {
            dggs_clip_whole(cell, level + 1, target, got, pixel, out);
            continue;
        }
        if (d + 1 >= w->levels) return -1;
        memcpy(w->tri + 6 * (d + 1), t, sizeof t);
        w->ids[d + 1] = cell;
        if (dggs_clip_children(level + 1, w->tri + 6 * (d + 1), x, y, m, w->kx + (d + 1) * plane,
                               w->ky + (d + 1) * plane, w->kn + 6 * (d + 1), w->tx, w->ty, width))
            return -1;
        w->nxt[d + 1] = 0;
        d += 1;
    }
    return 0;
}
