/* Polygon fill's descent (fill.h): a port of index/_kernel/fill.py and ivea_fill.py (`proj` selects the inverse). */
#include "fill.h"

#include <math.h>
#include <string.h>

#include "bits.h"
#include "dmath.h"
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
    double h = dggs_hypot(ux, uy);
    double norm = sqrt(h * h + uz * uz);
    /* cos(|beta| + rho): the cap's smallest cosine of latitude */
    double cstar = (h * dggs_fill_cos[lv] - fabs(uz) * dggs_fill_sin[lv]) / norm;
    *a = dggs_fill_a_lat[lv];
    if (cstar <= dggs_fill_sin_half[lv]) {
        *lam = -1.0;
        return;
    }
    *lam = (2.0 * dggs_asin(dggs_fill_sin_half[lv] / cstar)) * FILL_DEG_PER_RAD;
}

/* fill.py _classify: (hit, inside) of a cell by its footprint ellipse. */
static void classify_cell(int lv, double lat, double lng, double ux, double uy, double uz, const dggs_edge_grid *g,
                          double miny, double maxy, double inflate, bool *hit, bool *inside) {
    double a, lam;
    dggs_ellipse(lv, ux, uy, uz, &a, &lam);
    if (lam < 0.0) { /* a pole's cap: its latitudes only */
        *hit = !(lat + a < miny || lat - a > maxy);
        *inside = false;
        return;
    }
    if (inflate != 1.0) { /* the public overlapping_bbox only (fill.py has no such step) */
        a *= inflate;
        lam *= inflate;
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
    s->inflate = 1.0;
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
            classify_cell(lv, lat, lng, u[0], u[1], u[2], g, s->miny, s->maxy, s->inflate, &hit, &inside);
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

/* ==== the public verb: dggs_polygon_to_cells (dggs.h) ==========================================================
 * index/polyfill.py _fill over the kernel above: the polygon's edges and their grid (_edge_index), the descent,
 * GEOS's exact point location for the centres on an edge (shapely.contains_xy, here dggs_locate_exact), and the
 * boundary cells' own test in the other modes (shapely contains / intersects of the cell's polygon, and
 * _bbox_fill's boxes; here exact predicates on the cell's lng/lat ring). */

#include <stdlib.h>

#include "points.h"
#include "shape.h"

/* polyfill._DIRECT: levels above the target whose boundary cells have every descendant's centre tested. */
#define FILL_DIRECT 1
/* The overlapping_bbox descent's ellipse scale: a cell's lng/lat box lies in its ellipse's box, which lies in the
 * ellipse sqrt(2) times as large; 1.5 for margin. */
#define FILL_BBOX_INFLATE 1.5

/* A polygon's edges and their bucket grid (polyfill._edge_index, _bucketed), malloc'ed. */
typedef struct {
    double *x0, *y0, *x1, *y1, *frame, *scratch;
    int64_t *start, *items, *empty;
    int64_t n;
    dggs_edge_grid g;
    double miny, maxy;
} fill_polygon;

static void polygon_free(fill_polygon *p) {
    free(p->x0), free(p->y0), free(p->x1), free(p->y1), free(p->frame), free(p->scratch);
    free(p->start), free(p->items), free(p->empty);
}

static dggs_error polygon_check(const double *lat_lng, const int64_t *ring_sizes, int64_t num_rings, int level,
                                dggs_fill_mode mode, dggs_projection proj, int64_t *n_points) {
    if (level < 0 || level > DGGS_MAX_LEVEL) return DGGS_E_LEVEL;
    if (proj != DGGS_ISEA && proj != DGGS_IVEA) return DGGS_E_PROJECTION;
    if ((int)mode < DGGS_FILL_MODE_CENTER || (int)mode > DGGS_FILL_MODE_OVERLAPPING_BBOX || num_rings < 0)
        return DGGS_E_DOMAIN;
    int64_t total = 0;
    for (int64_t r = 0; r < num_rings; r++) {
        int64_t k = ring_sizes[r];
        if (k < 3) return DGGS_E_DOMAIN;
        const double *p = lat_lng + 2 * total;
        for (int64_t i = 0; i < k; i++) {
            double lat = p[2 * i], lng = p[2 * i + 1];
            if (!(lat >= -90.0 && lat <= 90.0) || !(lng >= -180.0 && lng <= 180.0)) return DGGS_E_LATLNG;
        }
        bool closed = p[0] == p[2 * (k - 1)] && p[1] == p[2 * (k - 1) + 1];
        if (k - closed < 3) return DGGS_E_DOMAIN;
        total += k;
    }
    *n_points = total;
    return DGGS_OK;
}

/* The edges (lng/lat) of the rings, each closed, in ring order, and their grid at polyfill._bucketed's side. */
static dggs_error polygon_build(const double *lat_lng, const int64_t *ring_sizes, int64_t num_rings, int64_t points,
                                fill_polygon *p) {
    memset(p, 0, sizeof *p);
    size_t bytes = (size_t)(points > 0 ? points : 1) * sizeof(double);
    p->x0 = malloc(bytes), p->y0 = malloc(bytes), p->x1 = malloc(bytes), p->y1 = malloc(bytes);
    p->frame = malloc(DGGS_FRAME_SIZE * sizeof(double));
    if (!p->x0 || !p->y0 || !p->x1 || !p->y1 || !p->frame) return DGGS_E_FAILED;
    int64_t m = 0, at = 0;
    p->miny = INFINITY, p->maxy = -INFINITY;
    for (int64_t r = 0; r < num_rings; r++) {
        const double *q = lat_lng + 2 * at;
        int64_t k = ring_sizes[r];
        at += k;
        if (q[0] == q[2 * (k - 1)] && q[1] == q[2 * (k - 1) + 1]) k--; /* closed: the repeat is no point */
        for (int64_t i = 0; i < k; i++) {
            int64_t j = i + 1 == k ? 0 : i + 1;
            p->x0[m] = q[2 * i + 1], p->y0[m] = q[2 * i], p->x1[m] = q[2 * j + 1], p->y1[m] = q[2 * j];
            if (q[2 * i] < p->miny) p->miny = q[2 * i];
            if (q[2 * i] > p->maxy) p->maxy = q[2 * i];
            m++;
        }
    }
    p->n = m;
    /* polyfill._bucketed: about two buckets a row per sqrt(edges) */
    double want = 2.0 * sqrt((double)m);
    int64_t side = (int64_t)(want < 1.0 ? 1.0 : (want > 1024.0 ? 1024.0 : want));
    p->start = malloc((size_t)(side * side + 1) * sizeof(int64_t));
    p->empty = malloc((size_t)(side * side) * sizeof(int64_t));
    if (!p->start || !p->empty) return DGGS_E_FAILED;
    if (dggs_polygon_build_count(p->x0, p->y0, p->x1, p->y1, m, side, p->frame, p->start) != DGGS_OK)
        return DGGS_E_DOMAIN;
    int64_t items = p->start[side * side];
    p->items = malloc((size_t)(items + 1) * sizeof(int64_t));
    p->scratch = malloc((size_t)(items + 1) * sizeof(double));
    if (!p->items || !p->scratch) return DGGS_E_FAILED;
    dggs_polygon_build_fill(p->x0, p->y0, p->x1, p->y1, m, p->frame, p->start, p->items, p->empty, p->scratch);
    dggs_edge_grid g = {p->x0, p->y0, p->x1, p->y1, p->frame, p->start, p->items, p->empty};
    p->g = g;
    return DGGS_OK;
}

/* fill.py descend (as the binding runs it): the cells found and their flags, malloc'ed into *ids, *flags. */
static dggs_error run_descent(dggs_projection proj, const fill_polygon *p, int level, dggs_fill_mode mode,
                              dggs_fill_state *s, uint64_t **ids, uint8_t **flags) {
    int64_t room = DGGS_FILL_FIRST_ROOM;
    *ids = malloc((size_t)room * sizeof(uint64_t));
    *flags = malloc((size_t)room);
    if (!*ids || !*flags) return DGGS_E_FAILED;
    dggs_fill_start(s, level, mode == DGGS_FILL_MODE_CENTER, FILL_DIRECT, p->miny, p->maxy, INT64_MAX);
    if (mode == DGGS_FILL_MODE_OVERLAPPING_BBOX) s->inflate = FILL_BBOX_INFLATE;
    for (;;) {
        int status = dggs_fill_walk(proj, s, &p->g, *ids, *flags, room);
        if (status == DGGS_FILL_OK) return DGGS_OK;
        if (status != DGGS_FILL_FULL) return DGGS_E_FAILED;
        room *= 2;
        uint64_t *more_ids = realloc(*ids, (size_t)room * sizeof(uint64_t));
        if (more_ids) *ids = more_ids;
        uint8_t *more_flags = realloc(*flags, (size_t)room);
        if (more_flags) *flags = more_flags;
        if (!more_ids || !more_flags) return DGGS_E_FAILED;
    }
}

/* Whether a point lies in the polygon, its boundary included. */
static inline bool in_polygon(const fill_polygon *p, double x, double y) {
    return dggs_locate(x, y, &p->g, p->n) != 0;
}

/* Whether the polygon has an edge meeting segment ab (kind 1: touching or crossing; kind 2: crossing at one
 * point interior to both, ignoring the polygon's edges along the antimeridian, where a cell is cut). */
static bool edge_meets(const fill_polygon *p, double ax, double ay, double bx, double by, int kind) {
    int64_t c0, c1, r0, r1;
    if (!dggs_grid_span(&p->g, ax < bx ? ax : bx, ax < bx ? bx : ax, ay < by ? ay : by, ay < by ? by : ay, &c0, &c1,
                        &r0, &r1))
        return false;
    int64_t side = (int64_t)p->frame[4];
    for (int64_t row = r0; row <= r1; row++)
        for (int64_t col = c0; col <= c1; col++) {
            int64_t b = row * side + col;
            for (int64_t t = p->start[b]; t < p->start[b + 1]; t++) {
                int64_t i = p->items[t];
                int meet = dggs_segments_meet(ax, ay, bx, by, p->x0[i], p->y0[i], p->x1[i], p->y1[i]);
                if (meet == 0 || meet < kind) continue;
                if (kind == 2 && p->x0[i] == p->x1[i] && fabs(p->x0[i]) == 180.0) continue;
                return true;
            }
        }
    return false;
}

/* Whether some vertex of the polygon in box [xlo, xhi] x [ylo, yhi] lies, shifted by `shift`, in the ring:
 * strictly inside (`strict`, ignoring vertices on the antimeridian) or on it too. */
static bool vertex_in_ring(const fill_polygon *p, const double *ring, int64_t m, double xlo, double xhi, double ylo,
                           double yhi, double shift, bool strict) {
    int64_t c0, c1, r0, r1;
    if (!dggs_grid_span(&p->g, xlo, xhi, ylo, yhi, &c0, &c1, &r0, &r1)) return false;
    int64_t side = (int64_t)p->frame[4];
    for (int64_t row = r0; row <= r1; row++)
        for (int64_t col = c0; col <= c1; col++) {
            int64_t b = row * side + col;
            for (int64_t t = p->start[b]; t < p->start[b + 1]; t++) {
                int64_t i = p->items[t];
                double x = p->x0[i], y = p->y0[i];
                if (x < xlo || x > xhi || y < ylo || y > yhi) continue;
                if (strict && fabs(x) == 180.0) continue;
                int where = dggs_locate_ring(x + shift, y, ring, m);
                if (strict ? where == 1 : where != 0) return true;
            }
        }
    return false;
}

/* The ring's bounding box. */
static void ring_box(const double *ring, int64_t m, double box[4]) {
    box[0] = box[1] = INFINITY, box[2] = box[3] = -INFINITY;
    for (int64_t i = 0; i < m; i++) {
        double x = ring[2 * i], y = ring[2 * i + 1];
        if (x < box[0]) box[0] = x;
        if (x > box[2]) box[2] = x;
        if (y < box[1]) box[1] = y;
        if (y > box[3]) box[3] = y;
    }
}

/* Whether the closed box meets the polygon (shapely.intersects(target, box) of _bbox_fill._box_hits). */
static bool box_meets(const fill_polygon *p, double xlo, double ylo, double xhi, double yhi) {
    if (in_polygon(p, xlo, ylo) || in_polygon(p, xhi, ylo) || in_polygon(p, xhi, yhi) || in_polygon(p, xlo, yhi))
        return true;
    const double box[8] = {xlo, ylo, xhi, ylo, xhi, yhi, xlo, yhi};
    if (vertex_in_ring(p, box, 4, xlo, xhi, ylo, yhi, 0.0, false)) return true;
    for (int e = 0; e < 4; e++) {
        int f = (e + 1) % 4;
        if (edge_meets(p, box[2 * e], box[2 * e + 1], box[2 * f], box[2 * f + 1], 1)) return true;
    }
    return false;
}

/* A boundary cell's test in `mode` (contains, overlaps, overlapping_bbox) on its ring: the ring is cut into the
 * windows [-180 + 360 k, 180 + 360 k] it spans, each piece shifted back by 360 k (ring_to_geometry's parts). */
static bool ring_test(const fill_polygon *p, const double *ring, int64_t m, dggs_fill_mode mode) {
    double box[4];
    ring_box(ring, m, box);
    int k0 = 0, k1 = 0;
    if (!(box[0] >= -180.0 && box[2] <= 180.0)) {
        k0 = (int)floor((box[0] + 180.0) / 360.0);
        k1 = (int)floor((box[2] + 180.0) / 360.0);
    }
    for (int k = k0; k <= k1; k++) {
        double shift = 360.0 * k, wlo = shift - 180.0, whi = shift + 180.0;
        bool whole = k0 == k1; /* one piece: no window bounds */
        if (mode == DGGS_FILL_MODE_OVERLAPPING_BBOX) {
            /* the piece's box: its x span in the window, its y span over the ring's points in the window and the
             * ring's crossings of the window's sides */
            double ylo = INFINITY, yhi = -INFINITY;
            for (int64_t i = 0; i < m; i++) {
                int64_t j = i + 1 == m ? 0 : i + 1;
                double ax = ring[2 * i], ay = ring[2 * i + 1], bx = ring[2 * j], by = ring[2 * j + 1];
                if (whole || (ax >= wlo && ax <= whi)) ylo = ay < ylo ? ay : ylo, yhi = ay > yhi ? ay : yhi;
                for (int side = 0; side < 2 && !whole; side++) {
                    double x = side ? whi : wlo;
                    if ((ax < x) != (bx < x)) {
                        double y = ay + (x - ax) * (by - ay) / (bx - ax);
                        ylo = y < ylo ? y : ylo, yhi = y > yhi ? y : yhi;
                    }
                }
            }
            if (!(ylo <= yhi)) continue;
            double xlo = whole ? box[0] : (box[0] > wlo ? box[0] : wlo) - shift;
            double xhi = whole ? box[2] : (box[2] < whi ? box[2] : whi) - shift;
            if (box_meets(p, xlo, ylo, xhi, yhi)) return true;
            continue;
        }
        if (mode == DGGS_FILL_MODE_OVERLAPS) { /* any point in common, boundaries included */
            for (int64_t i = 0; i < m; i++)
                if (in_polygon(p, ring[2 * i] - shift, ring[2 * i + 1])) return true;
            if (vertex_in_ring(p, ring, m, box[0] - shift, box[2] - shift, box[1], box[3], shift, false)) return true;
            for (int64_t i = 0; i < m; i++) {
                int64_t j = i + 1 == m ? 0 : i + 1;
                if (edge_meets(p, ring[2 * i] - shift, ring[2 * i + 1], ring[2 * j] - shift, ring[2 * j + 1], 1))
                    return true;
            }
            continue;
        }
        /* contains: each piece within the polygon: its points (and edges' middles) in it or on its boundary, no
         * edge crossing the polygon's, no vertex of the polygon strictly inside */
        for (int64_t i = 0; i < m; i++) {
            int64_t j = i + 1 == m ? 0 : i + 1;
            double ax = ring[2 * i], ay = ring[2 * i + 1];
            double mx = 0.5 * (ax + ring[2 * j]), my = 0.5 * (ay + ring[2 * j + 1]);
            if ((whole || (ax >= wlo && ax <= whi)) && !in_polygon(p, ax - shift, ay)) return false;
            if ((whole || (mx >= wlo && mx <= whi)) && !in_polygon(p, mx - shift, my)) return false;
            if (edge_meets(p, ax - shift, ay, ring[2 * j] - shift, ring[2 * j + 1], 2)) return false;
        }
        if (vertex_in_ring(p, ring, m, box[0] - shift, box[2] - shift, box[1], box[3], shift, true)) return false;
    }
    return mode == DGGS_FILL_MODE_CONTAINS;
}

/* The descent, then each undecided cell's test: keep[i] for each cell found. */
static dggs_error fill_cells(const double *lat_lng, const int64_t *ring_sizes, int64_t num_rings, int level,
                             dggs_fill_mode mode, dggs_projection proj, bool test, fill_polygon *p, uint64_t **ids,
                             uint8_t **keep, int64_t *n) {
    int64_t points;
    *ids = NULL, *keep = NULL, *n = 0;
    memset(p, 0, sizeof *p);
    dggs_error err = polygon_check(lat_lng, ring_sizes, num_rings, level, mode, proj, &points);
    if (err != DGGS_OK || points == 0) return err;
    err = polygon_build(lat_lng, ring_sizes, num_rings, points, p);
    if (err != DGGS_OK) return err;
    dggs_fill_state *s = malloc(sizeof *s);
    if (!s) return DGGS_E_FAILED;
    err = run_descent(proj, p, level, mode, s, ids, keep);
    *n = err == DGGS_OK ? s->n : 0; /* s is unset where a first malloc failed */
    free(s);
    if (err != DGGS_OK || !test) return err;
    int densify = dggs_fill_densify[level];
    double *ring = NULL, *tmp = NULL;
    for (int64_t i = 0; i < *n; i++) {
        uint8_t flag = (*keep)[i];
        if (flag == DGGS_FILL_SURE) {
            (*keep)[i] = 1;
        } else if (flag == DGGS_FILL_CENTRE) { /* shapely.contains_xy of the centre: its interior */
            double lat, lng;
            dggs_one_centre(proj, (*ids)[i], &lat, &lng);
            (*keep)[i] = dggs_locate_exact(lng, lat, p->x0, p->y0, p->x1, p->y1, p->n) == 1;
        } else {
            if (!ring) {
                ring = malloc((size_t)dggs_cell_ring_room(densify) * 2 * 2 * sizeof(double));
                tmp = malloc((size_t)dggs_cell_ring_room(densify) * 2 * 2 * sizeof(double));
                if (!ring || !tmp) {
                    free(ring), free(tmp);
                    return DGGS_E_FAILED;
                }
            }
            int64_t m = dggs_cell_ring(proj, (*ids)[i], densify, ring, tmp, NULL);
            (*keep)[i] = ring_test(p, ring, m, mode);
        }
    }
    free(ring), free(tmp);
    return DGGS_OK;
}

dggs_error dggs_polygon_to_cells_size(const double *lat_lng, const int64_t *ring_sizes, int64_t num_rings, int level,
                                      dggs_fill_mode mode, dggs_projection proj, int64_t *size) {
    fill_polygon p;
    uint64_t *ids;
    uint8_t *flags;
    int64_t n;
    dggs_error err = fill_cells(lat_lng, ring_sizes, num_rings, level, mode, proj, false, &p, &ids, &flags, &n);
    int64_t total = 0;
    for (int64_t i = 0; err == DGGS_OK && i < n; i++) total += dggs_n_desc(dggs_level_of(ids[i]), level);
    free(ids), free(flags);
    polygon_free(&p);
    if (err == DGGS_OK) *size = total;
    return err;
}

dggs_error dggs_polygon_to_cells(const double *lat_lng, const int64_t *ring_sizes, int64_t num_rings, int level,
                                 dggs_fill_mode mode, dggs_projection proj, dggs_cell *out, int64_t out_size,
                                 int64_t *count) {
    fill_polygon p;
    uint64_t *ids;
    uint8_t *keep;
    int64_t n;
    dggs_error err = fill_cells(lat_lng, ring_sizes, num_rings, level, mode, proj, true, &p, &ids, &keep, &n);
    polygon_free(&p);
    if (err == DGGS_OK) {
        int64_t m = 0, total = 0;
        for (int64_t i = 0; i < n; i++) /* the kept cells, in place */
            if (keep[i]) {
                ids[m++] = ids[i];
                total += dggs_n_desc(dggs_level_of(ids[i]), level);
            }
        *count = total;
        if (total > out_size) {
            err = DGGS_E_BUFFER;
        } else if (m) {
            int64_t bad;
            err = dggs_children(ids, m, level, out, out_size, &bad);
        }
    }
    free(ids), free(keep);
    return err;
}
