/* The outline of a set of cells as polygons on the plane of (lng, lat): dggs_cells_to_multi_polygon (dggs.h's
 * "dissolve" section). index/dissolve.py's assembly, done without a polygon library.
 *
 * dissolve.c gives the outline as rings on the sphere, each with the set on its left, as (lat, lng) points (a
 * pole as two points at latitude +-90, every antimeridian crossing of an edge a point at longitude +-180). Here:
 * 1. corners the outline passes more than once get one coordinate (the set touching itself stays one point);
 * 2. each ring is unwrapped along the sphere (steps the short way, along a pole the way the set lies: west at
 *    the North Pole, east at the South, as shape.c's dggs_cell_ring) and cut where it crosses x = 180 + 360 k into
 *    chains, each mapped into the window -180..180 (its points keep their own longitudes, so no rounding);
 * 3. the chains are joined along the window's frame, counter-clockwise: the set lies left of every chain and
 *    inside the frame, so from a chain's end the set's boundary runs along the frame to the next chain start (a
 *    ring round a pole is closed over the pole this way, as dggs_cell_to_polygon closes a pole cell);
 * 4. rings that pass one point twice are cut there into simple loops (OGC validity);
 * 5. with the set on the left, a counter-clockwise ring is a shell and a clockwise one a hole; each hole goes to
 *    the smallest shell around it, or to the whole window (the frame) when no shell holds it.
 * Rings do not cross (they are the outline of a set of cells), so this is the even-odd rule of index/dissolve.py
 * read off the rings' orientation instead of from a nesting search. */
#include <math.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

#include "bits.h"
#include "dggs.h"
#include "dissolve.h"

/* Most fine cells a set's outline may take (index/dissolve.py's _MAX_FINE); past it DGGS_E_FAILED. */
#define MAX_FINE 50000000
/* Corners closer than this (degrees) are one corner (index/dissolve.py's _SAME_CORNER). */
#define SAME_CORNER 1e-9
/* dggs.cell_to_polygon's default points per edge: the cell's geodesic area within this of the truth. */
#define AREA_TOLERANCE 1e-6
/* The frame's perimeter in its parameter (frame_t): 360 along the bottom, 180 up the right, 360, 180. */
#define FRAME 1080.0

/* ---- growable arrays ---- */

typedef struct {
    double *xy; /* (lng, lat) */
    int64_t n, cap;
} pts_t;

typedef struct {
    pts_t p;
    int64_t *start; /* ring r: points start[r] .. start[r + 1] of p */
    int64_t n, cap;
} rings_t;

static bool pts_push(pts_t *p, double x, double y) {
    if (p->n == p->cap) {
        int64_t cap = p->cap ? 2 * p->cap : 256;
        double *xy = realloc(p->xy, (size_t)cap * 2 * sizeof(double));
        if (!xy) return false;
        p->xy = xy, p->cap = cap;
    }
    p->xy[2 * p->n] = x, p->xy[2 * p->n + 1] = y;
    p->n++;
    return true;
}

/* Close the ring made of the points pushed since the last close (consecutive repeats dropped). */
static bool rings_close(rings_t *r) {
    if (r->n + 2 > r->cap) {
        int64_t cap = r->cap ? 2 * r->cap : 64;
        int64_t *start = realloc(r->start, (size_t)cap * sizeof(int64_t));
        if (!start) return false;
        r->start = start, r->cap = cap;
        if (r->n == 0) r->start[0] = 0;
    }
    int64_t b = r->start[r->n], m = b;
    double *xy = r->p.xy;
    for (int64_t i = b; i < r->p.n; i++) {
        if (m > b && xy[2 * i] == xy[2 * (m - 1)] && xy[2 * i + 1] == xy[2 * (m - 1) + 1]) continue;
        xy[2 * m] = xy[2 * i], xy[2 * m + 1] = xy[2 * i + 1], m++;
    }
    while (m - b > 1 && xy[2 * b] == xy[2 * (m - 1)] && xy[2 * b + 1] == xy[2 * (m - 1) + 1]) m--;
    r->p.n = m;
    if (m - b < 3) { /* no area: dropped */
        r->p.n = b;
        return true;
    }
    r->start[++r->n] = m;
    return true;
}

/* ---- step 1: one coordinate per corner ---- */

typedef struct {
    int64_t lat, lng, row;
} corner_key;

static int cmp_key(const void *a, const void *b) {
    const corner_key *p = a, *q = b;
    if (p->lat != q->lat) return p->lat < q->lat ? -1 : 1;
    if (p->lng != q->lng) return p->lng < q->lng ? -1 : 1;
    return (p->row > q->row) - (p->row < q->row);
}

/* index/dissolve.py's _snap_corners: corner rows within SAME_CORNER of each other take the first one's point. */
static bool snap_corners(double *ll, const uint8_t *corner, int64_t rows) {
    int64_t n = 0;
    for (int64_t i = 0; i < rows; i++) n += corner[i] != 0;
    if (n < 2) return true;
    corner_key *k = malloc((size_t)n * sizeof *k);
    if (!k) return false;
    const int64_t turn = (int64_t)llround(360.0 / SAME_CORNER);
    n = 0;
    for (int64_t i = 0; i < rows; i++) {
        if (!corner[i]) continue;
        int64_t lng = (int64_t)llround(ll[2 * i + 1] / SAME_CORNER) % turn;
        k[n].lat = (int64_t)llround(ll[2 * i] / SAME_CORNER), k[n].lng = lng < 0 ? lng + turn : lng, k[n].row = i;
        n++;
    }
    qsort(k, (size_t)n, sizeof *k, cmp_key);
    for (int64_t i = 1, first = 0; i < n; i++) {
        if (k[i].lat != k[first].lat || k[i].lng != k[first].lng) {
            first = i;
            continue;
        }
        ll[2 * k[i].row] = ll[2 * k[first].row], ll[2 * k[i].row + 1] = ll[2 * k[first].row + 1];
    }
    free(k);
    return true;
}

/* ---- step 2: unwrap and cut at the antimeridian ---- */

static double pymod(double a, double b) {
    double r = fmod(a, b);
    return r != 0.0 && (r < 0.0) != (b < 0.0) ? r + b : r;
}

/* The longitude step from (x0, y0) to (x1, y1): the short way, along a pole the way the set lies (dissolve.py's
 * _steps, shape.c's ring_to_geometry). */
static double lng_step(double x0, double y0, double x1, double y1) {
    double raw = x1 - x0;
    if (fabs(y0) == 90.0 && y1 == y0) return y0 > 0.0 ? -pymod(-raw, 360.0) : pymod(raw, 360.0);
    return pymod(raw + 180.0, 360.0) - 180.0;
}

/* The window (k: -180 + 360 k .. 180 + 360 k) of unwrapped longitude u. */
static double window_of(double u) { return floor((u + 180.0) / 360.0); }

/* A chain: points start .. start + count of the chain store, from the frame (at t0) back to it (at t1). */
typedef struct {
    int64_t start, count;
    double t0, t1;
    bool used;
} chain_t;

typedef struct {
    pts_t cp;        /* the chains' points */
    chain_t *chains; /* and the chains */
    int64_t nchains, cap;
    /* per-ring scratch: points after insertion (x its own longitude, y, m its turn: unwrapped x + 360 m) */
    double *x, *y, *w;
    int64_t *m;
    int64_t room;
} cut_t;

static bool cut_room(cut_t *c, int64_t n) {
    if (n <= c->room) return true;
    double *x = realloc(c->x, (size_t)n * sizeof(double)), *y = x ? realloc(c->y, (size_t)n * sizeof(double)) : NULL;
    if (x) c->x = x;
    if (y) c->y = y;
    double *w = y ? realloc(c->w, (size_t)n * sizeof(double)) : NULL;
    if (w) c->w = w;
    int64_t *m = w ? realloc(c->m, (size_t)n * sizeof(int64_t)) : NULL;
    if (m) c->m = m;
    if (!m) return false;
    c->room = n;
    return true;
}

/* Point i's longitude in window w (its turn m_i + dm): its own, or +-180 on the side of the window it lies on. */
static double window_x(const cut_t *c, int64_t i, double dm, double w) {
    if (fabs(c->x[i]) != 180.0) return c->x[i];
    return c->x[i] + 360.0 * ((double)c->m[i] + dm - w) > 0.0 ? 180.0 : -180.0;
}

/* The frame's parameter of a point on its left or right side: 0 at (-180, -90), counter-clockwise. */
static double frame_t(double x, double y) { return x > 0.0 ? 360.0 + (y + 90.0) : fmod(900.0 + (90.0 - y), FRAME); }

/* One ring of the outline (k (lat, lng) rows): a closed ring into `out` if it stays in one window, else its
 * chains into c. */
static bool cut_ring(const double *ll, int64_t k, cut_t *c, rings_t *out) {
    if (!cut_room(c, 2 * k + 1)) return false;
    /* unwrap, a point where a step crosses x = 180 + 360 j strictly (steps along a pole; the kernel put one on
     * every other crossing) */
    int64_t n = 0;
    double u = ll[1];
    for (int64_t i = 0; i < k; i++) {
        int64_t j = (i + 1) % k;
        double y0 = ll[2 * i], x0 = ll[2 * i + 1], y1 = ll[2 * j], x1 = ll[2 * j + 1];
        double mi = nearbyint((u - x0) / 360.0);
        double a = x0 + 360.0 * mi, s = lng_step(x0, y0, x1, y1), b = a + s;
        c->x[n] = x0, c->y[n] = y0, c->m[n] = (int64_t)mi, n++;
        double wa = window_of(a), wb = window_of(b);
        bool on_a = fmod(a + 180.0, 360.0) == 0.0, on_b = fmod(b + 180.0, 360.0) == 0.0;
        if (wa != wb && !on_a && !on_b) {
            double line = 180.0 + 360.0 * (s > 0.0 ? wa : wb);
            c->x[n] = 180.0, c->y[n] = y0 + (line - a) / s * (y1 - y0), c->m[n] = (int64_t)((line - 180.0) / 360.0);
            n++;
        }
        u = b;
    }
    double turns = nearbyint((u - ll[1]) / 360.0);
    /* each segment's window (a segment on a line takes its predecessor's) */
    bool any = false;
    for (int64_t i = 0; i < n; i++) {
        double a = c->x[i] + 360.0 * (double)c->m[i];
        double b = i + 1 < n ? c->x[i + 1] + 360.0 * (double)c->m[i + 1] : c->x[0] + 360.0 * turns;
        double mid = 0.5 * (a + b);
        c->w[i] = fmod(mid + 180.0, 360.0) == 0.0 ? NAN : window_of(mid);
        any |= !isnan(c->w[i]);
    }
    if (!any) return true; /* no extent: nothing */
    /* the segments unrolled from point `from` on: past point n - 1 they are a turn further round (`turns`) */
#define W_AT(e) (c->w[((e) + n) % n] + ((e) >= n ? turns : (e) < 0 ? -turns : 0.0))
    int64_t first = 0;
    while (isnan(c->w[first])) first++;
    for (int64_t s = 1; s <= n; s++) {
        int64_t i = (first + s) % n;
        if (isnan(c->w[i])) c->w[i] = W_AT(i - 1);
    }
    int64_t cut0 = -1;
    for (int64_t i = 0; i < n && cut0 < 0; i++)
        if (W_AT(i) != W_AT(i - 1)) cut0 = i;
    if (cut0 < 0) { /* one window: a closed ring */
        for (int64_t i = 0; i < n; i++)
            if (!pts_push(&out->p, window_x(c, i, 0.0, c->w[i]), c->y[i])) return false;
        return rings_close(out);
    }
    /* chains from cut to cut, starting at the first */
    for (int64_t s = 0; s < n;) {
        double w = W_AT(cut0 + s);
        if (c->nchains == c->cap) {
            int64_t cap = c->cap ? 2 * c->cap : 16;
            chain_t *ch = realloc(c->chains, (size_t)cap * sizeof *ch);
            if (!ch) return false;
            c->chains = ch, c->cap = cap;
        }
        chain_t *ch = &c->chains[c->nchains++];
        ch->start = c->cp.n, ch->used = false;
        int64_t e = s;
        do {
            int64_t at = cut0 + e;
            if (!pts_push(&c->cp, window_x(c, at % n, at >= n ? turns : 0.0, w), c->y[at % n])) return false;
            e++;
        } while (e < n && W_AT(cut0 + e) == w);
        int64_t at = cut0 + e; /* the cut point that ends the chain */
        if (!pts_push(&c->cp, window_x(c, at % n, at >= n ? turns : 0.0, w), c->y[at % n])) return false;
        ch->count = c->cp.n - ch->start;
        double *p0 = c->cp.xy + 2 * ch->start, *p1 = c->cp.xy + 2 * (c->cp.n - 1);
        p0[0] = p0[0] > 0.0 ? 180.0 : -180.0, p1[0] = p1[0] > 0.0 ? 180.0 : -180.0; /* on the frame */
        ch->t0 = frame_t(p0[0], p0[1]), ch->t1 = frame_t(p1[0], p1[1]);
        s = e;
    }
#undef W_AT
    return true;
}

/* ---- step 3: chains joined along the frame ---- */

static bool join_chains(cut_t *c, rings_t *out) {
    static const double corner_t[4] = {0.0, 360.0, 540.0, 900.0};
    static const double corner_xy[4][2] = {{-180.0, -90.0}, {180.0, -90.0}, {180.0, 90.0}, {-180.0, 90.0}};
    for (int64_t a = 0; a < c->nchains; a++) {
        if (c->chains[a].used) continue;
        int64_t cur = a;
        for (int64_t guard = 0; guard <= c->nchains; guard++) {
            chain_t *ch = &c->chains[cur];
            ch->used = true;
            for (int64_t i = 0; i < ch->count; i++)
                if (!pts_push(&out->p, c->cp.xy[2 * (ch->start + i)], c->cp.xy[2 * (ch->start + i) + 1])) return false;
            int64_t next = -1;
            double best = FRAME;
            for (int64_t b = 0; b < c->nchains; b++) {
                if (c->chains[b].used && b != a) continue;
                double d = pymod(c->chains[b].t0 - ch->t1, FRAME);
                if (d < best) best = d, next = b;
            }
            if (next < 0) break; /* cannot happen: chain a is always a candidate */
            int order[4], np = 0; /* the frame's corners passed, in order */
            for (int q = 0; q < 4; q++) {
                double d = pymod(corner_t[q] - ch->t1, FRAME);
                if (d > 0.0 && d < best) order[np++] = q;
            }
            for (int i = 0; i < np; i++)
                for (int j = i + 1; j < np; j++)
                    if (pymod(corner_t[order[j]] - ch->t1, FRAME) < pymod(corner_t[order[i]] - ch->t1, FRAME)) {
                        int t = order[i];
                        order[i] = order[j], order[j] = t;
                    }
            for (int i = 0; i < np; i++)
                if (!pts_push(&out->p, corner_xy[order[i]][0], corner_xy[order[i]][1])) return false;
            if (next == a) break;
            cur = next;
        }
        if (!rings_close(out)) return false;
    }
    return true;
}

/* ---- step 4: rings cut where they pass one point twice ---- */

typedef struct {
    double x, y;
    int64_t i;
} xy_key;

static int cmp_xy(const void *a, const void *b) {
    const xy_key *p = a, *q = b;
    if (p->x != q->x) return p->x < q->x ? -1 : 1;
    if (p->y != q->y) return p->y < q->y ? -1 : 1;
    return (p->i > q->i) - (p->i < q->i);
}

/* Ring `xy` (n points) into `out` as simple loops: walking it, a point seen before closes the loop since then. */
static bool split_pinches(const double *xy, int64_t n, rings_t *out) {
    xy_key *k = malloc((size_t)n * sizeof *k);
    int64_t *grp = malloc((size_t)n * 3 * sizeof(int64_t));
    if (!k || !grp) {
        free(k), free(grp);
        return false;
    }
    int64_t *pos = grp + n, *stack = grp + 2 * n, top = 0;
    for (int64_t i = 0; i < n; i++) k[i].x = xy[2 * i], k[i].y = xy[2 * i + 1], k[i].i = i, grp[i] = -1, pos[i] = -1;
    qsort(k, (size_t)n, sizeof *k, cmp_xy);
    for (int64_t i = 0, run = 0; i <= n; i++) { /* group: the sorted index where a run of equal points starts */
        if (i < n && k[i].x == k[run].x && k[i].y == k[run].y) continue;
        if (i - run > 1)
            for (int64_t j = run; j < i; j++) grp[k[j].i] = run;
        run = i;
    }
    bool ok = true;
    for (int64_t i = 0; i < n && ok; i++) {
        int64_t g = grp[i];
        if (g >= 0 && pos[g] >= 0) { /* a loop: stack[pos[g]] .. top */
            for (int64_t j = pos[g]; j < top && ok; j++) ok = pts_push(&out->p, xy[2 * stack[j]], xy[2 * stack[j] + 1]);
            ok = ok && rings_close(out);
            for (int64_t j = pos[g] + 1; j < top; j++)
                if (grp[stack[j]] >= 0) pos[grp[stack[j]]] = -1;
            top = pos[g] + 1;
            continue;
        }
        if (g >= 0) pos[g] = top;
        stack[top++] = i;
    }
    for (int64_t j = 0; j < top && ok; j++) ok = pts_push(&out->p, xy[2 * stack[j]], xy[2 * stack[j] + 1]);
    ok = ok && rings_close(out);
    free(k), free(grp);
    return ok;
}

/* ---- step 5: shells and holes ---- */

static double ring_area(const double *xy, int64_t n) { /* shoelace, about the first point */
    double s = 0.0, x0 = xy[0], y0 = xy[1];
    for (int64_t i = 1; i + 1 < n; i++)
        s += (xy[2 * i] - x0) * (xy[2 * i + 3] - y0) - (xy[2 * i + 2] - x0) * (xy[2 * i + 1] - y0);
    return 0.5 * s;
}

/* A ring's edges bucketed by latitude, for many point-in-ring tests (a hole's point against the shells): an edge
 * is in every bucket its latitude range meets, so the edges a horizontal ray from (px, py) can cross are in py's. */
typedef struct {
    int64_t nb, *start, *items;
    double y0, h;
} ring_index;

static bool index_ring(const double *xy, int64_t n, const double *box, ring_index *ix) {
    ix->nb = n / 8 < 1 ? 1 : n / 8 > 4096 ? 4096 : n / 8;
    ix->y0 = box[1], ix->h = (box[3] - box[1]) / (double)ix->nb;
    if (!(ix->h > 0.0)) ix->nb = 1, ix->h = 1.0;
    ix->start = calloc((size_t)ix->nb + 1, sizeof(int64_t));
    if (!ix->start) return false;
#define BUCKET(y) ((int64_t)fmin(fmax(floor(((y) - ix->y0) / ix->h), 0.0), (double)(ix->nb - 1)))
    for (int pass = 0; pass < 2; pass++) {
        for (int64_t i = 0, j = n - 1; i < n; j = i++) {
            int64_t b0 = BUCKET(fmin(xy[2 * i + 1], xy[2 * j + 1])), b1 = BUCKET(fmax(xy[2 * i + 1], xy[2 * j + 1]));
            for (int64_t b = b0; b <= b1; b++) {
                if (pass == 0)
                    ix->start[b + 1]++;
                else
                    ix->items[ix->start[b]++] = i;
            }
        }
        if (pass == 0) {
            for (int64_t b = 0; b < ix->nb; b++) ix->start[b + 1] += ix->start[b];
            ix->items = malloc((size_t)(ix->start[ix->nb] ? ix->start[ix->nb] : 1) * sizeof(int64_t));
            if (!ix->items) return false;
        }
    }
    for (int64_t b = ix->nb; b > 0; b--) ix->start[b] = ix->start[b - 1]; /* the fill moved each start to its end */
    ix->start[0] = 0;
    return true;
}

/* Whether (px, py) is inside ring xy (n points): crossing number over the edges of py's bucket. */
static bool in_ring(const double *xy, int64_t n, const ring_index *ix, double px, double py) {
    bool in = false;
    int64_t b = BUCKET(py);
#undef BUCKET
    for (int64_t k = ix->start[b]; k < ix->start[b + 1]; k++) {
        int64_t i = ix->items[k], j = i ? i - 1 : n - 1;
        double xi = xy[2 * i], yi = xy[2 * i + 1], xj = xy[2 * j], yj = xy[2 * j + 1];
        if ((yi > py) != (yj > py) && px < xj + (py - yj) / (yi - yj) * (xi - xj)) in = !in;
    }
    return in;
}

/* The answer: points (lng, lat) of rings end to end, each ring's size, each polygon's ring count (shell first). */
typedef struct {
    pts_t p;
    int64_t *ring_size, *poly_rings, nrings, npolys;
} mp_t;

static const double GLOBE_RING[8] = {-180.0, -90.0, 180.0, -90.0, 180.0, 90.0, -180.0, 90.0};

static bool assign(const rings_t *r, bool frame_is_set, mp_t *mp) {
    int64_t n = r->n;
    double *area = malloc((size_t)(n ? n : 1) * 5 * sizeof(double));
    int64_t *parent = malloc((size_t)(n ? n : 1) * sizeof(int64_t));
    mp->ring_size = malloc((size_t)(n + 1) * sizeof(int64_t));
    mp->poly_rings = malloc((size_t)(n + 1) * sizeof(int64_t));
    if (!area || !parent || !mp->ring_size || !mp->poly_rings) {
        free(area), free(parent);
        return false;
    }
    double *box = area + n; /* xmin, ymin, xmax, ymax per ring */
    for (int64_t i = 0; i < n; i++) {
        const double *xy = r->p.xy + 2 * r->start[i];
        int64_t m = r->start[i + 1] - r->start[i];
        area[i] = ring_area(xy, m);
        double *bx = box + 4 * i;
        bx[0] = bx[2] = xy[0], bx[1] = bx[3] = xy[1];
        for (int64_t j = 1; j < m; j++) {
            bx[0] = fmin(bx[0], xy[2 * j]), bx[2] = fmax(bx[2], xy[2 * j]);
            bx[1] = fmin(bx[1], xy[2 * j + 1]), bx[3] = fmax(bx[3], xy[2 * j + 1]);
        }
    }
    bool globe = frame_is_set, ok = true;
    ring_index *ix = calloc((size_t)(n ? n : 1), sizeof *ix); /* built for a shell when a hole is first tested */
    if (!ix) {
        free(area), free(parent);
        return false;
    }
    for (int64_t h = 0; h < n && ok; h++) {
        parent[h] = -1;
        if (area[h] >= 0.0) continue;
        const double *xy = r->p.xy + 2 * r->start[h];
        double px = 0.5 * (xy[0] + xy[2]), py = 0.5 * (xy[1] + xy[3]); /* on the hole, off every other ring */
        double best = INFINITY;
        for (int64_t s = 0; s < n; s++) {
            const double *bx = box + 4 * s;
            if (area[s] <= 0.0 || area[s] >= best || px < bx[0] || px > bx[2] || py < bx[1] || py > bx[3]) continue;
            const double *sxy = r->p.xy + 2 * r->start[s];
            int64_t sn = r->start[s + 1] - r->start[s];
            if (!ix[s].start && !index_ring(sxy, sn, bx, &ix[s])) {
                ok = false;
                break;
            }
            if (in_ring(sxy, sn, &ix[s], px, py)) best = area[s], parent[h] = s;
        }
        if (parent[h] < 0) globe = true;
    }
    for (int64_t i = 0; i < n; i++) free(ix[i].start), free(ix[i].items);
    free(ix);
    /* polygons: the frame first when the set holds it, then each shell, each with its holes */
    for (int64_t s = -1; s < n && ok; s++) {
        if (s < 0 ? !globe : area[s] <= 0.0) continue;
        int64_t rings = 1;
        if (s < 0) {
            for (int q = 0; q < 4 && ok; q++) ok = pts_push(&mp->p, GLOBE_RING[2 * q], GLOBE_RING[2 * q + 1]);
            mp->ring_size[mp->nrings++] = 4;
        } else {
            for (int64_t j = r->start[s]; j < r->start[s + 1] && ok; j++)
                ok = pts_push(&mp->p, r->p.xy[2 * j], r->p.xy[2 * j + 1]);
            mp->ring_size[mp->nrings++] = r->start[s + 1] - r->start[s];
        }
        for (int64_t h = 0; h < n && ok; h++) {
            if (area[h] >= 0.0 || parent[h] != s) continue;
            for (int64_t j = r->start[h]; j < r->start[h + 1] && ok; j++)
                ok = pts_push(&mp->p, r->p.xy[2 * j], r->p.xy[2 * j + 1]);
            mp->ring_size[mp->nrings++] = r->start[h + 1] - r->start[h];
            rings++;
        }
        mp->poly_rings[mp->npolys++] = rings;
    }
    free(area), free(parent);
    return ok;
}

/* ---- the whole: ids to polygons ---- */

static int cmp_u64(const void *a, const void *b) {
    uint64_t p = *(const uint64_t *)a, q = *(const uint64_t *)b;
    return (p > q) - (p < q);
}

/* The outline's rings on the sphere ((lat, lng) rows, corner flags, ring ends), malloc'ed into *ll, *corner,
 * *ends (*nrings rings); *nrings = 0 for a set with no outline (the whole sphere). ids: n sorted disjoint cells. */
static dggs_error outline(const uint64_t *ids, int64_t n, int densify, dggs_projection proj, double **ll,
                          uint8_t **corner, int64_t **ends, int64_t *nrings) {
    dggs_error err = DGGS_OK;
    int finest = 0;
    *ll = NULL, *corner = NULL, *ends = NULL, *nrings = 0;
    int64_t nfine = 0;
    for (int64_t i = 0; i < n; i++) finest = dggs_level_of(ids[i]) > finest ? dggs_level_of(ids[i]) : finest;
    double bound = 0.0; /* index/dissolve.py's check: l levels coarser, at most 6 * 3 ** ceil(l / 2) + 12 */
    for (int64_t i = 0; i < n; i++) {
        int l = finest - dggs_level_of(ids[i]);
        if (l) bound += 6.0 * pow(3.0, (double)((l + 1) / 2)) + 12.0;
    }
    if (bound > MAX_FINE) return DGGS_E_FAILED;
    for (int64_t i = 0; i < n; i++)
        nfine += dggs_level_of(ids[i]) == finest ? 1 : dggs_dissolve_descend(ids[i], finest, NULL, 0);
    uint64_t *fine = malloc((size_t)(nfine ? nfine : 1) * sizeof(uint64_t));
    uint64_t *ecell = malloc((size_t)(3 * nfine + 1) * sizeof(uint64_t));
    int64_t *ecol = malloc((size_t)(3 * nfine + 1) * sizeof(int64_t));
    int64_t *order = malloc((size_t)(3 * nfine + 1) * sizeof(int64_t)), *starts = malloc((size_t)(3 * nfine + 2) * sizeof(int64_t));
    uint64_t *rcell = malloc((size_t)(3 * nfine + 1) * sizeof(uint64_t));
    int64_t *rcol = malloc((size_t)(3 * nfine + 1) * sizeof(int64_t)), *steps = malloc((size_t)(3 * nfine + 1) * sizeof(int64_t));
    uint8_t *visited = malloc((size_t)(3 * nfine + 1));
    double *ts = NULL;
    if (!fine || !ecell || !ecol || !order || !starts || !rcell || !rcol || !steps || !visited) {
        err = DGGS_E_FAILED;
        goto done;
    }
    int64_t f = 0;
    for (int64_t i = 0; i < n; i++) {
        if (dggs_level_of(ids[i]) == finest)
            fine[f++] = ids[i];
        else
            f += dggs_dissolve_descend(ids[i], finest, fine + f, nfine - f);
    }
    qsort(fine, (size_t)nfine, sizeof(uint64_t), cmp_u64);
    int64_t m = 0;
    for (int64_t i = 0; i < nfine; i++) {
        uint8_t mask[3];
        dggs_outline_mask(fine[i], ids, n, mask);
        for (int col = 0; col < 3; col++)
            if (mask[col]) ecell[m] = fine[i], ecol[m] = col, m++;
    }
    if (m == 0) goto done;
    int64_t nstarts = 0;
    if (dggs_chain(ecell, ecol, m, ids, n, visited, order, starts, &nstarts) >= 0) { /* a broken grid */
        err = DGGS_E_FAILED;
        goto done;
    }
    int64_t most = 1;
    uint64_t last = 0;
    int points = 0;
    for (int64_t i = 0; i < m; i++) {
        rcell[i] = ecell[order[i]], rcol[i] = ecol[order[i]];
        if (densify >= 0) {
            points = densify;
        } else if (i == 0 || rcell[i] != last) {
            if ((err = dggs_cell_edge_points(rcell[i], proj, 0.0, AREA_TOLERANCE, &points)) != DGGS_OK) goto done;
        }
        last = rcell[i];
        steps[i] = points + 1;
        most = steps[i] > most ? steps[i] : most;
    }
    int64_t rows = dggs_ring_point_bound(steps, m);
    *ll = malloc((size_t)rows * 2 * sizeof(double));
    *corner = malloc((size_t)rows);
    *ends = malloc((size_t)nstarts * sizeof(int64_t));
    ts = malloc((size_t)(most + 2) * sizeof(double));
    if (!*ll || !*corner || !*ends || !ts) {
        err = DGGS_E_FAILED;
        goto done;
    }
    memset(*corner, 0, (size_t)rows);
    if ((err = dggs_ring_points(proj, rcell, rcol, steps, starts, nstarts, *ll, rows, *corner, *ends, ts,
                                most + 2)) != DGGS_OK)
        goto done;
    *nrings = nstarts - 1;
    if (!snap_corners(*ll, *corner, (*ends)[*nrings - 1])) err = DGGS_E_FAILED;
done:
    free(fine), free(ecell), free(ecol), free(order), free(starts), free(rcell), free(rcol), free(steps);
    free(visited), free(ts);
    return err;
}

static void mp_free(mp_t *mp) {
    free(mp->p.xy), free(mp->ring_size), free(mp->poly_rings);
    memset(mp, 0, sizeof *mp);
}

static dggs_error multi_polygon(const dggs_cell *cells, size_t n, int densify, dggs_projection proj, mp_t *mp) {
    memset(mp, 0, sizeof *mp);
    if (proj != DGGS_ISEA && proj != DGGS_IVEA) return DGGS_E_PROJECTION;
    if (densify < -1 || densify > DGGS_MAX_DENSIFY) return DGGS_E_DOMAIN;
    for (size_t i = 0; i < n; i++)
        if (!dggs_is_valid_cell(cells[i])) return DGGS_E_CELL;
    if (n == 0) return DGGS_OK;
    uint64_t *ids = malloc(n * sizeof(uint64_t));
    uint8_t *keep = malloc(n);
    if (!ids || !keep) {
        free(ids), free(keep);
        return DGGS_E_FAILED;
    }
    memcpy(ids, cells, n * sizeof(uint64_t));
    qsort(ids, n, sizeof(uint64_t), cmp_u64);
    int64_t u = 0;
    for (size_t i = 0; i < n; i++)
        if (u == 0 || ids[i] != ids[u - 1]) ids[u++] = ids[i];
    dggs_drop_covered(ids, u, keep);
    int64_t k = 0;
    for (int64_t i = 0; i < u; i++)
        if (keep[i]) ids[k++] = ids[i];
    free(keep);
    double *ll = NULL;
    uint8_t *corner = NULL;
    int64_t *ends = NULL, nrings = 0;
    dggs_error err = outline(ids, k, densify, proj, &ll, &corner, &ends, &nrings);
    free(ids);
    if (err != DGGS_OK) {
        free(ll), free(corner), free(ends);
        return err;
    }
    cut_t c;
    rings_t raw, simple;
    memset(&c, 0, sizeof c), memset(&raw, 0, sizeof raw), memset(&simple, 0, sizeof simple);
    bool ok = true;
    for (int64_t r = 0, b = 0; r < nrings && ok; b = ends[r++]) ok = cut_ring(ll + 2 * b, ends[r] - b, &c, &raw);
    ok = ok && join_chains(&c, &raw);
    for (int64_t r = 0; r < raw.n && ok; r++)
        ok = split_pinches(raw.p.xy + 2 * raw.start[r], raw.start[r + 1] - raw.start[r], &simple);
    if (ok && simple.n == 0 && simple.cap == 0) { /* start[0] exists for assign */
        simple.start = malloc(sizeof(int64_t));
        ok = simple.start != NULL;
        if (ok) simple.start[0] = 0;
    }
    ok = ok && assign(&simple, nrings == 0, mp);
    free(ll), free(corner), free(ends);
    free(c.cp.xy), free(c.chains), free(c.x), free(c.y), free(c.w), free(c.m);
    free(raw.p.xy), free(raw.start), free(simple.p.xy), free(simple.start);
    if (!ok) {
        mp_free(mp);
        return DGGS_E_FAILED;
    }
    return DGGS_OK;
}

dggs_error dggs_cells_to_multi_polygon_size(const dggs_cell *cells, size_t n, int densify, dggs_projection proj,
                                            int64_t *points, int64_t *rings, int64_t *polygons) {
    mp_t mp;
    dggs_error err = multi_polygon(cells, n, densify, proj, &mp);
    if (err == DGGS_OK) *points = mp.p.n, *rings = mp.nrings, *polygons = mp.npolys;
    mp_free(&mp);
    return err;
}

dggs_error dggs_cells_to_multi_polygon(const dggs_cell *cells, size_t n, int densify, dggs_projection proj,
                                       double *lng_lat, int64_t points, int64_t *ring_sizes, int64_t rings,
                                       int64_t *polygon_rings, int64_t polygons, int64_t *num_points,
                                       int64_t *num_rings, int64_t *num_polygons) {
    mp_t mp;
    dggs_error err = multi_polygon(cells, n, densify, proj, &mp);
    if (err != DGGS_OK) {
        mp_free(&mp);
        return err;
    }
    *num_points = mp.p.n, *num_rings = mp.nrings, *num_polygons = mp.npolys;
    if (mp.p.n > points || mp.nrings > rings || mp.npolys > polygons) {
        mp_free(&mp);
        return DGGS_E_BUFFER;
    }
    if (mp.p.n) memcpy(lng_lat, mp.p.xy, (size_t)mp.p.n * 2 * sizeof(double));
    if (mp.nrings) memcpy(ring_sizes, mp.ring_size, (size_t)mp.nrings * sizeof(int64_t));
    if (mp.npolys) memcpy(polygon_rings, mp.poly_rings, (size_t)mp.npolys * sizeof(int64_t));
    mp_free(&mp);
    return DGGS_OK;
}
