/* Polygon fill's descent (fill.h): a port of index/_kernel/fill.py and ivea_fill.py (`proj` selects the inverse). */
#include "fill.h"

#include <math.h>
#include <string.h>

#include "bits.h"
#include "geometry.h"
#include "hierarchy.h"
#include "tables.h"

/* numba's math.degrees: x * (180 / pi), the constant rounded once. */
#define FILL_DEG_PER_RAD 0x1.ca5dc1a63c1f8p+5

/* fill.py _on_globe: (lat, lng) and the unit vector of face-frame (x, y). */
static void on_globe(dggs_projection proj, int face, double x, double y, double *lat, double *lng, double u[3]) {
    dggs_proj_inverse(proj, face, x, y, u);
    dggs_unit_to_geodetic(u[0], u[1], u[2], lat, lng);
}

void dggs_fill_centre(dggs_projection proj, int face, int lv, double ax, double ay, double bx, double by, double cx,
                      double cy, double *lat, double *lng, double u[3]) {
    if (lv > 0 && !((bx - ax) * (cy - ay) - (by - ay) * (cx - ax) > 0.0)) {
        /* counter-clockwise first, as points.corners orders them */
        double tx = bx, ty = by;
        bx = cx;
        by = cy;
        cx = tx;
        cy = ty;
    }
    on_globe(proj, face, (ax + bx + cx) / 3.0, (ay + by + cy) / 3.0, lat, lng, u);
}

void dggs_footprint(dggs_projection proj, int face, int lv, double ax, double ay, double bx, double by, double cx,
                    double cy, double *lat, double *lng, double u[3]) {
    if (lv == 0) {
        on_globe(proj, face, (ax + bx + cx) / 3.0, (ay + by + cy) / 3.0, lat, lng, u);
        return;
    }
    on_globe(proj, face, 0.5 * (ax + bx), 0.5 * (ay + by), lat, lng, u);
}

/* fill.py _in_grid: (hit, inside) of the ellipse round (px, py): it meets the polygon, it lies wholly in it. */
static void in_grid(double px, double py, double r, double sx, const dggs_edge_grid *g, bool *hit, bool *inside) {
    if (dggs_near(px, py, r, sx, g)) {
        *hit = true;
        *inside = false;
        return;
    }
    int p = dggs_parity(px, py, g);
    *hit = p != 0; /* -1 (on an edge) cannot happen off the edges; a hit if it did */
    *inside = p == 1;
}

void dggs_ellipse(int lv, double ux, double uy, double uz, double *a, double *lam) {
    double h = hypot(ux, uy);
    double norm = sqrt(h * h + uz * uz);
    /* cos(|beta| + rho): the cap's smallest cosine of latitude */
    double cstar = (h * dggs_fill_cos[lv] - fabs(uz) * dggs_fill_sin[lv]) / norm;
    *a = dggs_fill_a_lat[lv];
    if (cstar <= dggs_fill_sin_half[lv]) {
        *lam = -1.0;
        return;
    }
    *lam = (2.0 * asin(dggs_fill_sin_half[lv] / cstar)) * FILL_DEG_PER_RAD;
}

/* fill.py _classify: (hit, inside) of a cell by its footprint ellipse. */
static void classify_cell(int lv, double lat, double lng, double ux, double uy, double uz, const dggs_edge_grid *g,
                          double miny, double maxy, bool *hit, bool *inside) {
    double a, lam;
    dggs_ellipse(lv, ux, uy, uz, &a, &lam);
    if (lam < 0.0) { /* a pole's cap: its latitudes only */
        *hit = !(lat + a < miny || lat - a > maxy);
        *inside = false;
        return;
    }
    in_grid(lng, lat, a, a / lam, g, hit, inside);
    if (fabs(lng) + lam > 180.0) { /* across the antimeridian: the other side too */
        /* never wholly inside (already so: the target ends at 180 by an edge, or has one nearer the centre) */
        *inside = false;
        if (!*hit) {
            bool other_inside;
            in_grid(lng - copysign(360.0, lng), lat, a, a / lam, g, hit, &other_inside);
        }
    }
}

/* fill.py _push: one cell and its corners onto the stack; false (never) when the stack is full. */
static inline bool push(dggs_fill_state *s, uint64_t cell, double ax, double ay, double bx, double by, double cx,
                        double cy) {
    if (s->top >= DGGS_FILL_STACK) return false;
    s->stack_id[s->top] = cell;
    double *xy = s->stack_xy[s->top];
    xy[0] = ax;
    xy[1] = ay;
    xy[2] = bx;
    xy[3] = by;
    xy[4] = cx;
    xy[5] = cy;
    s->top++;
    return true;
}

void dggs_fill_start(dggs_fill_state *s, int level, bool center, int direct, double miny, double maxy,
                     int64_t limit) {
    s->level = level;
    s->miny = miny;
    s->maxy = maxy;
    s->limit = limit;
    s->top = 0;
    memset(s->cand, 0, sizeof s->cand);
    memset(s->insides, 0, sizeof s->insides);
    s->n = s->whole = s->tested = s->classified = 0;
    const double(*f)[2] = dggs_face_corners_ccw;
    for (int face = 19; face >= 0; face--)
        push(s, dggs_base_cell(face), f[0][0], f[0][1], f[1][0], f[1][1], f[2][0], f[2][1]);
    int from = level - direct;
    s->test_from = center ? (from > 0 ? from : 0) : level + 1;
}

int dggs_fill_walk(dggs_projection proj, dggs_fill_state *s, const dggs_edge_grid *g, uint64_t *ids, uint8_t *flags,
                   int64_t room) {
    int64_t n = s->n, whole = s->whole, tested = s->tested, classified = s->classified;
    const int level = s->level, test_from = s->test_from;
    const int64_t limit = s->limit;
    int status = DGGS_FILL_OK;
    while (s->top > 0) {
        if (n == room) {
            status = DGGS_FILL_FULL;
            break;
        }
        s->top--;
        uint64_t cell = s->stack_id[s->top];
        const double *xy = s->stack_xy[s->top];
        double ax = xy[0], ay = xy[1], bx = xy[2], by = xy[3], cx = xy[4], cy = xy[5];
        int lv = dggs_level_of(cell);
        int face = dggs_face_of(cell);
        int keep = -1;
        if (lv <= test_from) {
            s->cand[lv] += 1;
            if (lv >= 1 && s->cand[lv] > limit) {
                status = DGGS_FILL_TOO_MANY;
                break;
            }
        }
        if (lv >= test_from) { /* every descendant's centre is tested */
            if (lv == level) {
                tested += 1;
                double lat, lng, u[3];
                dggs_fill_centre(proj, face, lv, ax, ay, bx, by, cx, cy, &lat, &lng, u);
                int p = dggs_parity(lng, lat, g);
                if (p == 1)
                    keep = DGGS_FILL_SURE;
                else if (p == -1)
                    keep = DGGS_FILL_CENTRE;
                if (whole + tested > limit) {
                    status = DGGS_FILL_TOO_MANY;
                    break;
                }
            }
        } else {
            classified += 1;
            double lat, lng, u[3];
            bool hit, inside;
            dggs_footprint(proj, face, lv, ax, ay, bx, by, cx, cy, &lat, &lng, u);
            classify_cell(lv, lat, lng, u[0], u[1], u[2], g, s->miny, s->maxy, &hit, &inside);
            if (!hit) continue;
            if (inside) {
                keep = DGGS_FILL_SURE;
                if (lv < level) {
                    int64_t count = dggs_n_desc(lv, level);
                    s->insides[lv] += count;
                    whole += count;
                    if (whole > limit) {
                        status = DGGS_FILL_TOO_MANY;
                        break;
                    }
                }
            } else if (lv == level) {
                tested += 1;
                keep = DGGS_FILL_EDGE;
            }
        }
        if (keep >= 0) {
            ids[n] = cell;
            flags[n] = (uint8_t)keep;
            n++;
            continue;
        }
        if (lv >= level) continue;
        /* the children, pushed last first so that they come off the stack in id order */
        bool pushed = true;
        if (lv == 0) {
            for (int d = 5; d >= 0; d--) {
                const double(*t)[2] = dggs_level1_corners[d];
                pushed &= push(s, cell | ((uint64_t)(d + 1) << DGGS_L1_SHIFT), t[0][0], t[0][1], t[1][0], t[1][1],
                               t[2][0], t[2][1]);
            }
        } else {
            unsigned shift = dggs_shift_of(lv + 1);
            for (int d = 2; d >= 0; d--) {
                double t[6] = {ax, ay, bx, by, cx, cy};
                dggs_child_corners(t, d);
                pushed &= push(s, cell | ((uint64_t)(d + 1) << shift), t[0], t[1], t[2], t[3], t[4], t[5]);
            }
        }
        if (!pushed) { /* cannot happen: at most 25 + 2 * 27 entries */
            status = DGGS_FILL_FAILED;
            break;
        }
    }
    s->n = n;
    s->whole = whole;
    s->tested = tested;
    s->classified = classified;
    return status;
}

int64_t dggs_first_over(const int64_t *cand, const int64_t *insides, int64_t tested, int last, bool center,
                        int64_t limit) {
    int64_t total = 0;
    for (int lv = 0; lv < last; lv++) {
        total += insides[lv];
        if (total > limit) return total;
        if (total + cand[lv + 1] > limit) return total + cand[lv + 1];
    }
    if (center && total + tested > limit) return total + tested;
    return -1;
}
