/* The line tracer: a port of index/_kernel/line_trace.py and its IVEA build ivea_lines.py (see line_trace.h),
 * and the public dggs_line_to_cells over it (the steps of dggs.index.paths._trace). */
#include "line_trace.h"

#include <math.h>
#include <string.h>

#include "bits.h"
#include "chord.h"
#include "dmath.h"
#include "geometry.h"
#include "grid.h"
#include "line_layout.h"
#include "line_tables.h"
#include "points.h"
#include "vertex.h"
#include "tables.h"

#define LT_A DGGS_LT_A
#define LT_B DGGS_LT_B
#define LT_E2 DGGS_LT_E2
#define LT_EP2 DGGS_LT_EP2

void dggs_ecef(double lat_deg, double lng_deg, double *x, double *y, double *z) {
    double phi = lat_deg * DGGS_LT_DEG2RAD;
    double lam = lng_deg * DGGS_LT_DEG2RAD;
    double sp = dggs_sin(phi), cp = dggs_cos(phi);
    double n = LT_A / sqrt(1.0 - LT_E2 * sp * sp);
    *x = n * cp * dggs_cos(lam);
    *y = n * cp * dggs_sin(lam);
    *z = n * (1.0 - LT_E2) * sp;
}

void dggs_tangent(double lat_deg, double lng_deg, double az_deg, double *x, double *y, double *z) {
    double phi = lat_deg * DGGS_LT_DEG2RAD;
    double lam = lng_deg * DGGS_LT_DEG2RAD;
    double al = az_deg * DGGS_LT_DEG2RAD;
    double sp = dggs_sin(phi), cp = dggs_cos(phi);
    double sl = dggs_sin(lam), cl = dggs_cos(lam);
    double ca = dggs_cos(al), sa = dggs_sin(al);
    *x = -ca * sp * cl - sa * sl;
    *y = -ca * sp * sl + sa * cl;
    *z = ca * cp;
}

void dggs_foot(double x, double y, double z, double *sp, double *cp, double *sl, double *cl) {
    double p = sqrt(x * x + y * y);
    if (p == 0.0) {
        *sp = z >= 0.0 ? 1.0 : -1.0;
        *cp = 0.0;
        *sl = 0.0;
        *cl = 1.0;
        return;
    }
    double u = LT_A * z, v = LT_B * p;
    double r = sqrt(u * u + v * v);
    double sb = u / r, cb = v / r;
    double num = z + LT_EP2 * LT_B * sb * sb * sb;
    double den = p - LT_E2 * LT_A * cb * cb * cb;
    r = sqrt(num * num + den * den);
    *sp = num / r;
    *cp = den / r;
    *sl = y / p;
    *cl = x / p;
}

void dggs_geodetic(double x, double y, double z, double *lat, double *lng) {
    double sp, cp, sl, cl;
    dggs_foot(x, y, z, &sp, &cp, &sl, &cl);
    *lat = dggs_atan2(sp, cp) * DGGS_LT_RAD2DEG;
    *lng = dggs_atan2(sl, cl) * DGGS_LT_RAD2DEG;
}

void dggs_line_trace_span(const double *lat, const double *lng, const double *az_out, const double *az_in,
                          const double *span, size_t k, double c[12]) {
    double s = span[k];
    double tax, tay, taz, tbx, tby, tbz;
    dggs_ecef(lat[k], lng[k], &c[0], &c[1], &c[2]);
    dggs_tangent(lat[k], lng[k], az_out[k], &tax, &tay, &taz);
    dggs_ecef(lat[k + 1], lng[k + 1], &c[6], &c[7], &c[8]);
    dggs_tangent(lat[k + 1], lng[k + 1], az_in[k + 1], &tbx, &tby, &tbz);
    c[3] = s * tax;
    c[4] = s * tay;
    c[5] = s * taz;
    c[9] = s * tbx;
    c[10] = s * tby;
    c[11] = s * tbz;
}

void dggs_point(const double c[12], double t, double *x, double *y, double *z) {
    double t2 = t * t;
    double t3 = t2 * t;
    double h00 = 2.0 * t3 - 3.0 * t2 + 1.0;
    double h10 = t3 - 2.0 * t2 + t;
    double h01 = 3.0 * t2 - 2.0 * t3;
    double h11 = t3 - t2;
    *x = h00 * c[0] + h10 * c[3] + h01 * c[6] + h11 * c[9];
    *y = h00 * c[1] + h10 * c[4] + h01 * c[7] + h11 * c[10];
    *z = h00 * c[2] + h10 * c[5] + h01 * c[8] + h11 * c[11];
}

void dggs_at(const double c[12], double t, double *lat, double *lng) {
    double x, y, z;
    dggs_point(c, t, &x, &y, &z);
    dggs_geodetic(x, y, z, lat, lng);
}

uint64_t dggs_sample(dggs_projection proj, double x, double y, double z, int level, int hint, int *face, double *fx,
                     double *fy) {
    double sp, cp, sl, cl, sb, cb;
    dggs_foot(x, y, z, &sp, &cp, &sl, &cl);
    dggs_authalic_sincos(sp, cp, &sb, &cb);
    double px = cb * cl, py = cb * sl, pz = sb;
    int f = hint;
    if (f < 0 ||
        px * dggs_isea_centres[f][0] + py * dggs_isea_centres[f][1] + pz * dggs_isea_centres[f][2] <= DGGS_LT_COS_20)
        f = dggs_nearest_face(&dggs_isea_centres[0][0], px, py, pz);
    dggs_proj_face_forward(proj, f, px, py, pz, fx, fy);
    *face = f;
    return dggs_encode_point(f, *fx, *fy, level);
}

uint64_t dggs_cell_at(dggs_projection proj, double x, double y, double z, int level, int hint, int *face) {
    double fx, fy;
    return dggs_sample(proj, x, y, z, level, hint, face, &fx, &fy);
}

uint64_t dggs_anchor(dggs_projection proj, double lat, double lng, int level, int *face, double *fx, double *fy) {
    uint64_t cell = dggs_one_point(proj, lat, lng, level);
    double x, y, z;
    dggs_ecef(lat, lng, &x, &y, &z);
    int f;
    (void)dggs_sample(proj, x, y, z, level, -1, &f, fx, fy);
    *face = f != dggs_face_of(cell) ? -1 : f;
    return cell;
}

void dggs_interpolate(const double *lat, const double *lng, const double *az_out, const double *az_in,
                      const double *span, const int64_t *k, const double *t, size_t m, double *out_lat,
                      double *out_lng) {
    for (size_t i = 0; i < m; i++) {
        double c[12];
        dggs_line_trace_span(lat, lng, az_out, az_in, span, (size_t)k[i], c);
        dggs_at(c, t[i], &out_lat[i], &out_lng[i]);
    }
}

void dggs_cells_at(dggs_projection proj, const double *lat, const double *lng, size_t n, int level, uint64_t *out,
                   bool chained) {
    int hint = -1;
    for (size_t i = 0; i < n; i++) {
        double x, y, z;
        int face;
        dggs_ecef(lat[i], lng[i], &x, &y, &z);
        out[i] = dggs_cell_at(proj, x, y, z, level, hint, &face);
        if (chained) hint = face;
    }
}

bool dggs_adjacent(uint64_t a, uint64_t b, int level) {
    for (int j = 0; j < 3; j++)
        if (dggs_neighbour(a, level, j) == b) return true;
    return false;
}

uint64_t dggs_between(uint64_t a, uint64_t b, int level) {
    uint64_t found = 0;
    for (int i = 0; i < 3; i++) {
        uint64_t x = dggs_neighbour(a, level, i);
        for (int j = 0; j < 3; j++) {
            if (dggs_neighbour(b, level, j) == x) {
                if (found != 0) return 0;
                found = x;
            }
        }
    }
    return found;
}

int64_t dggs_trace(dggs_projection proj, const double *lat, const double *lng, const double *az_out,
                   const double *az_in, const double *span, size_t n_anchors, int level, double step, double corner,
                   uint64_t *out, size_t cap, int64_t *fix, size_t fixcap, bool shortcut, int64_t *nfix_out) {
    size_t nfix = 0;
    *nfix_out = 0;
    if (n_anchors == 0 || cap == 0) return -1;
    int pf;
    double px, py;
    uint64_t prev = dggs_anchor(proj, lat[0], lng[0], level, &pf, &px, &py);
    out[0] = prev;
    size_t n = 1;
    /* the bisection stack: each entry a stretch (sa .. sb) of the span, its end cells, faces and planar points */
    double sa[DGGS_TRACE_STACK], sb[DGGS_TRACE_STACK];
    uint64_t ca[DGGS_TRACE_STACK], cb[DGGS_TRACE_STACK];
    int fa[DGGS_TRACE_STACK], fb[DGGS_TRACE_STACK];
    double pa[DGGS_TRACE_STACK][2], pb[DGGS_TRACE_STACK][2];
    int hint = -1;
    uint64_t kc = 0;
    double kt[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    for (size_t k = 0; k + 1 < n_anchors; k++) {
        double s = span[k];
        double c[12];
        dggs_line_trace_span(lat, lng, az_out, az_in, span, k, c);
        int64_t m = dggs_span_count(s / step);
        double t0 = 0.0;
        for (int64_t j = 1; j <= m; j++) {
            double t1, cx, cy;
            uint64_t cur;
            int cf;
            if (j == m) {
                t1 = 1.0;
                cur = dggs_anchor(proj, lat[k + 1], lng[k + 1], level, &cf, &cx, &cy);
            } else {
                double x, y, z;
                t1 = (double)j / (double)m;
                dggs_point(c, t1, &x, &y, &z);
                cur = dggs_sample(proj, x, y, z, level, hint, &cf, &cx, &cy);
                hint = cf;
            }
            if (cur != prev) {
                /* bisect (t0, prev) .. (t1, cur), emitting every cell after prev up to cur */
                sa[0] = t0;
                ca[0] = prev;
                sb[0] = t1;
                cb[0] = cur;
                fa[0] = pf;
                pa[0][0] = px;
                pa[0][1] = py;
                fb[0] = cf;
                pb[0][0] = cx;
                pb[0][1] = cy;
                int top = 1;
                while (top > 0) {
                    top -= 1;
                    double x0 = sa[top], x1 = sb[top];
                    uint64_t c0 = ca[top], c1 = cb[top];
                    if (c0 != c1) {
                        bool near = dggs_adjacent(c0, c1, level);
                        bool ok = false;
                        if (near && fa[top] >= 0 && fa[top] == fb[top] && dggs_face_of(c0) == fa[top] &&
                            dggs_face_of(c1) == fa[top]) {
                            /* chord.clear, the last cell's corners kept (the next pair mostly starts there) */
                            double ta[6];
                            if (c0 == kc)
                                memcpy(ta, kt, sizeof ta);
                            else
                                dggs_corners6(c0, ta);
                            kc = c1;
                            dggs_corners6(c1, kt);
                            ok = dggs_crosses(ta, kt, pa[top][0], pa[top][1], pb[top][0], pb[top][1]);
                        }
                        if (!ok) {
                            uint64_t via = 0;
                            if (!near && shortcut && level > 0 && (x1 - x0) * s <= step) {
                                via = dggs_between(c0, c1, level);
                                if (via != 0 && !dggs_corner_clear(c0, c1, fa[top], pa[top][0], pa[top][1], fb[top],
                                                                   pb[top][0], pb[top][1]))
                                    via = 0;
                            }
                            if (via != 0) {
                                if (n >= cap) return -1;
                                out[n++] = via;
                            } else if ((x1 - x0) * s >= corner && top + 2 <= DGGS_TRACE_STACK) {
                                double xm = 0.5 * (x0 + x1);
                                double x, y, z, mx, my;
                                int mf;
                                dggs_point(c, xm, &x, &y, &z);
                                uint64_t cm = dggs_sample(proj, x, y, z, level, hint, &mf, &mx, &my);
                                hint = mf;
                                /* (x0 .. xm) above (xm .. x1): the first half is taken first */
                                sa[top + 1] = x0;
                                ca[top + 1] = c0;
                                sb[top + 1] = xm;
                                cb[top + 1] = cm;
                                fa[top + 1] = fa[top];
                                pa[top + 1][0] = pa[top][0];
                                pa[top + 1][1] = pa[top][1];
                                fb[top + 1] = mf;
                                pb[top + 1][0] = mx;
                                pb[top + 1][1] = my;
                                sa[top] = xm; /* (xm .. x1) keeps its end */
                                ca[top] = cm;
                                fa[top] = mf;
                                pa[top][0] = mx;
                                pa[top][1] = my;
                                top += 2;
                                continue;
                            } else if (!near) {
                                if (fix != NULL) {
                                    if (nfix >= fixcap) return -1;
                                    fix[nfix] = (int64_t)n;
                                }
                                nfix++;
                            }
                        }
                    }
                    if (c1 != out[n - 1]) {
                        if (n >= cap) return -1;
                        out[n++] = c1;
                    }
                }
                prev = cur;
                pf = cf;
                px = cx;
                py = cy;
            } else {
                pf = cf;
                px = cx;
                py = cy;
            }
            t0 = t1;
        }
    }
    *nfix_out = (int64_t)nfix;
    return (int64_t)n;
}

/* ---- the corner join (dggs.index.paths._around over dggs.index._corners.fans) ---- */

/* _corners.MAX_FAN: the most cells around one corner. */
#define LINES_MAX_FAN DGGS_VERTEX_MAX_FAN

/* _corners.fans for one cell and corner: the cells around corner `corner` of `cell` in walking order from it
 * (vertex.c's walk on the edge adjacency); their number, or -1 if the walk does not close (never). */
static int lines_fan(uint64_t cell, int corner, uint64_t fan[LINES_MAX_FAN]) {
    int corners[LINES_MAX_FAN];
    return dggs_fan(cell, corner, fan, corners);
}

int dggs_line_around(uint64_t a, uint64_t b, uint64_t way[5]) {
    uint64_t rings[3][LINES_MAX_FAN];
    int sizes[3];
    for (int corner = 0; corner < 3; corner++) {
        sizes[corner] = lines_fan(a, corner, rings[corner]);
        if (sizes[corner] < 0) return -1;
    }
    int best = -1;
    for (int corner = 0; corner < 3; corner++) {
        const uint64_t *ring = rings[corner];
        int size = sizes[corner], p = -1;
        for (int i = 0; i < size; i++) {
            if (ring[i] == b) {
                p = i;
                break;
            }
        }
        if (p < 0) continue;
        int len = p <= size - p ? p - 1 : size - p - 1;
        if (len < 0 || len > 5) continue; /* never: p >= 1 (b != a), and the shorter way is at most 5 */
        if (best < 0 || len < best) {
            best = len;
            if (p <= size - p)
                for (int i = 0; i < len; i++) way[i] = ring[1 + i]; /* ring[1:p] */
            else
                for (int i = 0; i < len; i++) way[i] = ring[size - 1 - i]; /* ring[p + 1:][::-1] */
        }
    }
    return best;
}

/* ---- the public polyline verb (dggs.index.paths._trace) ---- */

/* pyproj's back azimuth from GeographicLib's forward azimuth at a geodesic's end (pyproj._geod's
 * _reverse_azimuth, factor 180), which dggs.index.paths turns round again with + 180. */
static inline double lines_reverse_azimuth(double azi) { return azi > 0 ? azi - 180.0 : azi + 180.0; }

static bool lines_geodesic_ok(const dggs_geodesic *geod) {
    return geod != NULL && geod->inverse != NULL && geod->direct != NULL;
}

/* The polyline's distinct consecutive points (dggs_clean's, without a buffer): the sizes both verbs need. */
static dggs_error lines_sizes(const dggs_geodesic *geod, const double *latlng, size_t n, int level, size_t *points,
                              size_t *anchors, double *estimate) {
    *points = 0;
    *anchors = 0;
    *estimate = 0.0;
    for (size_t i = 0; i < n; i++) {
        double la = latlng[2 * i], lo = latlng[2 * i + 1];
        if (!(-90.0 <= la && la <= 90.0) || !isfinite(lo)) return DGGS_E_LATLNG;
    }
    size_t kept = 0, size = 1;
    double est = 0.0, pla = 0.0, plo = 0.0;
    for (size_t i = 0; i < n; i++) {
        double la = latlng[2 * i], lo = latlng[2 * i + 1];
        if (i == 0 || la != latlng[2 * i - 2] || lo != latlng[2 * i - 1]) {
            if (kept > 0) {
                double s12, azi1, azi2;
                geod->inverse(geod->geod, pla, plo, la, lo, &s12, &azi1, &azi2);
                size += (size_t)dggs_span_count(s12 / DGGS_LT_MAX_SPAN[level]);
                est += ceil(DGGS_LT_CELLS_PER_EDGE * s12 / DGGS_LT_SHORT_EDGE[level]) + DGGS_LT_CELLS_EXTRA;
            }
            pla = la;
            plo = lo;
            kept++;
        }
    }
    *points = kept;
    *anchors = kept > 1 ? size : 0;
    *estimate = kept > 1 ? est + 16.0 : (double)kept;
    return DGGS_OK;
}

/* Doubles of work for `points` distinct points and `anchors` anchors: the points, each segment's azimuths and
 * length, the anchors' lat, lng, azimuths out and in, and spans. */
static size_t lines_work_doubles(size_t points, size_t anchors) {
    if (points < 2) return 2 * points;
    return 2 * points + 3 * (points - 1) + 5 * anchors;
}

dggs_error dggs_line_to_cells_size(const double *latlng, size_t n, int level, const dggs_geodesic *geod,
                                   size_t *max_cells, size_t *work_size) {
    *max_cells = 0;
    *work_size = 0;
    if (level < 0 || level > DGGS_MAX_LEVEL) return DGGS_E_LEVEL;
    if (!lines_geodesic_ok(geod)) return DGGS_E_DOMAIN;
    size_t points, anchors;
    double est;
    dggs_error err = lines_sizes(geod, latlng, n, level, &points, &anchors, &est);
    if (err != DGGS_OK) return err;
    *max_cells = est < 1e18 ? (size_t)est : (size_t)1e18;
    *work_size = lines_work_doubles(points, anchors) * sizeof(double);
    return DGGS_OK;
}

dggs_error dggs_line_to_cells(const double *latlng, size_t n, int level, dggs_projection proj,
                              const dggs_geodesic *geod, void *work, size_t work_size, dggs_cell *out,
                              size_t capacity, size_t *count) {
    *count = 0;
    if (level < 0 || level > DGGS_MAX_LEVEL) return DGGS_E_LEVEL;
    if (proj != DGGS_ISEA && proj != DGGS_IVEA) return DGGS_E_PROJECTION;
    if (!lines_geodesic_ok(geod)) return DGGS_E_DOMAIN;
    if (n == 0) return DGGS_OK;
    size_t points, anchors;
    double est;
    dggs_error err = lines_sizes(geod, latlng, n, level, &points, &anchors, &est);
    if (err != DGGS_OK) return err;
    if (work == NULL || work_size < lines_work_doubles(points, anchors) * sizeof(double)) return DGGS_E_DOMAIN;
    double *xy = (double *)work;
    size_t kept;
    if (dggs_clean(latlng, n, xy, &kept) >= 0) return DGGS_E_LATLNG; /* checked above */
    if (kept == 1) {                                                   /* one point: its cell */
        if (capacity < 1) {
            *count = 1;
            return DGGS_E_BUFFER;
        }
        out[0] = dggs_one_point(proj, xy[0], xy[1], level);
        *count = 1;
        return DGGS_OK;
    }
    /* paths._anchors: each segment's geodesic (pyproj's Geod.inv), the anchors laid out, and the points between
     * the polyline's filled from the direct problem (Geod.fwd) with their azimuths */
    size_t nseg = kept - 1;
    double *az12 = xy + 2 * kept, *az21 = az12 + nseg, *dist = az21 + nseg;
    for (size_t i = 0; i < nseg; i++) {
        double azi2;
        geod->inverse(geod->geod, xy[2 * i], xy[2 * i + 1], xy[2 * i + 2], xy[2 * i + 3], &dist[i], &az12[i], &azi2);
        az21[i] = lines_reverse_azimuth(azi2);
    }
    double max_span = DGGS_LT_MAX_SPAN[level];
    size_t size, inner;
    dggs_layout_size(dist, nseg, max_span, &size, &inner);
    if (size != anchors) return DGGS_E_FAILED; /* the solver answered differently twice */
    double *lat = dist + nseg, *lng = lat + size, *az_out = lng + size, *az_in = az_out + size, *span = az_in + size;
    dggs_layout(xy, az12, az21, dist, nseg, max_span, lat, lng, az_out, az_in, span, NULL, NULL, NULL);
    size_t k = 0;
    for (size_t i = 0; i < nseg; i++) {
        int64_t m = dggs_span_count(dist[i] / max_span);
        double step = dist[i] / (double)m;
        for (int64_t j = 1; j < m; j++) {
            double la, lo, azi2;
            geod->direct(geod->geod, xy[2 * i], xy[2 * i + 1], az12[i], (double)j * step, &la, &lo, &azi2);
            lat[k + (size_t)j] = la;
            lng[k + (size_t)j] = lo;
            az_out[k + (size_t)j] = az_in[k + (size_t)j] = lines_reverse_azimuth(azi2) + 180.0;
        }
        k += (size_t)m;
    }
    double edge = DGGS_LT_SHORT_EDGE[level];
    int64_t nfix;
    int64_t got = dggs_trace(proj, lat, lng, az_out, az_in, span, size, level, DGGS_LT_STEP_EDGES * edge,
                             DGGS_LT_CORNER_M, out, capacity, NULL, 0, true, &nfix);
    if (got < 0) { /* out is full: twice the room (at least the estimate) */
        double want = 2.0 * (double)capacity > est ? 2.0 * (double)capacity : est;
        *count = want < 1e18 ? (size_t)want : (size_t)1e18;
        return DGGS_E_BUFFER;
    }
    size_t cells = (size_t)got;
    if (nfix == 0) {
        *count = cells;
        return DGGS_OK;
    }
    /* paths._trace: each pair of cells meeting only at a corner is joined around it the shorter way */
    size_t total = cells;
    uint64_t way[5];
    for (size_t i = 1; i < cells; i++) {
        if (dggs_adjacent(out[i - 1], out[i], level)) continue;
        int len = dggs_line_around(out[i - 1], out[i], way);
        if (len < 0) return DGGS_E_FAILED; /* never for a pair the tracer leaves */
        total += (size_t)len;
    }
    if (total > capacity) {
        *count = total;
        return DGGS_E_BUFFER;
    }
    size_t dst = total;
    for (size_t i = cells; i-- > 0;) { /* from the end: out[i - 1] is still in place when out[i] moves */
        out[--dst] = out[i];
        if (i > 0 && !dggs_adjacent(out[i - 1], out[i], level)) {
            int len = dggs_line_around(out[i - 1], out[i], way);
            for (int w = len; w-- > 0;) out[--dst] = way[w];
        }
    }
    *count = total;
    return DGGS_OK;
}
