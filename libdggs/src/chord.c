/* The line tracer's planar crossing tests: a port of index/_kernel/chord.py (see chord.h). */
#include "chord.h"

#include <math.h>

#include "bits.h"
#include "points.h"

/* numba's min(a, b, c) on floats: each next value replaces the accumulator where it is smaller. */
static inline double chord_min3(double a, double b, double c) {
    double acc = a;
    acc = b < acc ? b : acc;
    acc = c < acc ? c : acc;
    return acc;
}

/* (cx, cy)'s squared distance to the nearest of t's three corners (chord.py's min of three `** 2` sums). */
static inline double chord_nearest2(double cx, double cy, const double t[6]) {
    return chord_min3((cx - t[0]) * (cx - t[0]) + (cy - t[1]) * (cy - t[1]),
                      (cx - t[2]) * (cx - t[2]) + (cy - t[3]) * (cy - t[3]),
                      (cx - t[4]) * (cx - t[4]) + (cy - t[5]) * (cy - t[5]));
}

double dggs_dist_to_segment(double px, double py, double x0, double y0, double x1, double y1) {
    double dx = x1 - x0, dy = y1 - y0;
    double ll = dx * dx + dy * dy;
    double t = 0.0;
    if (ll != 0.0) {
        double q = ((px - x0) * dx + (py - y0) * dy) / ll;
        double lo = q < 1.0 ? q : 1.0; /* min(1.0, q) */
        t = lo > 0.0 ? lo : 0.0;        /* max(0.0, ...) */
    }
    double ex = x0 + t * dx - px, ey = y0 + t * dy - py;
    return sqrt(ex * ex + ey * ey);
}

void dggs_corners6(uint64_t cell, double t[6]) { (void)dggs_triangle(cell, t); }

bool dggs_crosses(const double ta[6], const double tb[6], double xa, double ya, double xb, double yb) {
    /* a's corner that is not b's is the one farthest from all of b's corners */
    double far = -1.0;
    double rx = 0.0, ry = 0.0;
    double px = 0.0, py = 0.0, qx = 0.0, qy = 0.0;
    for (int i = 0; i < 3; i++) {
        double cx = ta[2 * i], cy = ta[2 * i + 1];
        double d = chord_nearest2(cx, cy, tb);
        if (d > far) {
            far = d;
            rx = cx;
            ry = cy;
        }
    }
    bool first = true;
    for (int i = 0; i < 3; i++) {
        double cx = ta[2 * i], cy = ta[2 * i + 1];
        if (cx == rx && cy == ry) continue;
        if (first) {
            px = cx;
            py = cy;
            first = false;
        } else {
            qx = cx;
            qy = cy;
        }
    }
    double ex = qx - px, ey = qy - py;
    double d0 = ex * (ya - py) - ey * (xa - px);
    double d1 = ex * (yb - py) - ey * (xb - px);
    if (d0 * d1 > 0.0 || d0 == d1) return false; /* the chord does not cross PQ's line */
    double t = d0 / (d0 - d1);
    double cx = xa + t * (xb - xa), cy = ya + t * (yb - ya); /* X */
    double ln = sqrt((xb - xa) * (xb - xa) + (yb - ya) * (yb - ya));
    double eps = DGGS_BEND * ln + DGGS_BEND_FLOOR;
    if (sqrt((cx - px) * (cx - px) + (cy - py) * (cy - py)) <= 2.0 * eps ||
        sqrt((cx - qx) * (cx - qx) + (cy - qy) * (cy - qy)) <= 2.0 * eps)
        return false;
    if ((cx - px) * ex + (cy - py) * ey <= 0.0 || (cx - qx) * ex + (cy - qy) * ey >= 0.0)
        return false; /* X beyond P or Q */
    return dggs_dist_to_segment(px, py, xa, ya, xb, yb) > eps && dggs_dist_to_segment(qx, qy, xa, ya, xb, yb) > eps;
}

bool dggs_clear(uint64_t a, uint64_t b, int fa, double xa, double ya, int fb, double xb, double yb) {
    if (fa < 0 || fa != fb || dggs_face_of(a) != fa || dggs_face_of(b) != fb) return false;
    double ta[6], tb[6];
    dggs_corners6(a, ta);
    dggs_corners6(b, tb);
    return dggs_crosses(ta, tb, xa, ya, xb, yb);
}

bool dggs_corner_clear(uint64_t a, uint64_t b, int fa, double xa, double ya, int fb, double xb, double yb) {
    if (fa < 0 || fa != fb || dggs_face_of(a) != fa || dggs_face_of(b) != fb) return false;
    double ta[6], tb[6];
    (void)dggs_triangle(a, ta);
    (void)dggs_triangle(b, tb);
    double best = -1.0;
    double vx = 0.0, vy = 0.0;
    for (int i = 0; i < 3; i++) {
        double cx = ta[2 * i], cy = ta[2 * i + 1];
        double d = chord_nearest2(cx, cy, tb);
        if (best < 0.0 || d < best) {
            best = d;
            vx = cx;
            vy = cy;
        }
    }
    double eps = DGGS_BEND * sqrt((xb - xa) * (xb - xa) + (yb - ya) * (yb - ya)) + DGGS_BEND_FLOOR;
    return dggs_dist_to_segment(vx, vy, xa, ya, xb, yb) > eps;
}
