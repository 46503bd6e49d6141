/* Dissolve a set of cells into its outline (index/_kernel/dissolve.py, ivea_edges.ring_points): see dissolve.h. */
#include "dissolve.h"

#include <math.h>

#include "bits.h"
#include "geometry.h"
#include "grid.h"
#include "points.h"

void dggs_drop_covered(const uint64_t *ids, int64_t n, uint8_t *keep) {
    uint64_t end = 0;
    for (int64_t i = 0; i < n; i++) {
        uint64_t c = ids[i];
        keep[i] = 0;
        if (c >= end) {
            keep[i] = 1;
            end = dggs_range_end(c, dggs_level_of(c));
        }
    }
}

/* np.searchsorted(a, y, side="right"): the number of entries <= y. */
static int64_t search_right(const uint64_t *a, int64_t n, uint64_t y) {
    int64_t lo = 0, hi = n;
    while (lo < hi) {
        int64_t mid = lo + (hi - lo) / 2;
        if (a[mid] <= y)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

/* np.searchsorted(a, y) (side="left"): the number of entries < y. */
static int64_t search_left(const uint64_t *a, int64_t n, uint64_t y) {
    int64_t lo = 0, hi = n;
    while (lo < hi) {
        int64_t mid = lo + (hi - lo) / 2;
        if (a[mid] < y)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

bool dggs_covered(const uint64_t *cells, int64_t n, uint64_t y) {
    int64_t i = search_right(cells, n, y) - 1;
    if (i < 0) return false;
    uint64_t x = cells[i];
    return y < dggs_range_end(x, dggs_level_of(x));
}

int64_t dggs_dissolve_descend(uint64_t cell, int level, uint64_t *out, int64_t cap) {
    int top = dggs_level_of(cell);
    if (level <= top || level > DGGS_MAX_LEVEL) return -1; /* numba's stack would overflow: refused */
    uint64_t end = dggs_range_end(cell, top);
    uint64_t stack[DGGS_DESCEND_STACK]; /* numba: np.empty(6 * (level - top + 1)) */
    stack[0] = cell;
    int sp = 1;
    int64_t n = 0;
    while (sp > 0) {
        sp -= 1;
        uint64_t c = stack[sp];
        int lv = dggs_level_of(c);
        unsigned s = dggs_shift_of(lv + 1);
        for (int code = lv == 0 ? 6 : 3; code > 0; code--) { /* pushed in reverse: popped in id order */
            uint64_t ch = c | ((uint64_t)code << s);
            bool edge = false;
            for (int col = 0; col < 3; col++) {
                uint64_t nb = dggs_neighbour(ch, lv + 1, col);
                if (nb < cell || nb >= end) edge = true;
            }
            if (!edge) continue;
            if (lv + 1 == level) {
                if (n < cap) out[n] = ch;
                n += 1;
            } else {
                stack[sp] = ch; /* at most 6 + 3 (level - top - 1) < DGGS_DESCEND_STACK entries */
                sp += 1;
            }
        }
    }
    return n;
}

void dggs_outline_mask(uint64_t cell, const uint64_t *cells, int64_t n, uint8_t mask[3]) {
    int lv = dggs_level_of(cell);
    for (int col = 0; col < 3; col++) mask[col] = !dggs_covered(cells, n, dggs_neighbour(cell, lv, col));
}

int64_t dggs_dissolve_find(const uint64_t *ecell, const int64_t *ecol, int64_t m, uint64_t cell, int64_t col) {
    int64_t i = search_left(ecell, m, cell);
    while (i < m && ecell[i] == cell) {
        if (ecol[i] == col) return i;
        i += 1;
    }
    return -1;
}

int64_t dggs_chain(const uint64_t *ecell, const int64_t *ecol, int64_t m, const uint64_t *cells, int64_t n,
                   uint8_t *visited, int64_t *order, int64_t *starts, int64_t *nstarts) {
    for (int64_t i = 0; i < m; i++) visited[i] = 0;
    int64_t pos = 0, r = 0;
    for (int64_t s = 0; s < m; s++) {
        if (visited[s]) continue;
        starts[r] = pos;
        r += 1;
        int64_t k = s;
        for (;;) {
            visited[k] = 1;
            order[pos] = k;
            pos += 1;
            uint64_t cur = ecell[k];
            int lv = dggs_level_of(cur);
            int e = (int)((ecol[k] + 1) % 3);
            for (int it = 0; it < 16; it++) { /* at most 12 cells around a corner */
                uint64_t c = dggs_neighbour(cur, lv, e);
                if (!dggs_covered(cells, n, c)) break;
                int j = 0;
                while (j < 3 && dggs_neighbour(c, lv, j) != cur) j += 1;
                e = (j + 1) % 3;
                cur = c;
            }
            k = dggs_dissolve_find(ecell, ecol, m, cur, e);
            if (k == s) break;
            if (k < 0 || visited[k]) {
                starts[r] = pos; /* numba leaves this entry unset (np.empty): the caller raises on it */
                *nstarts = r + 1;
                return order[pos - 1];
            }
        }
    }
    starts[r] = pos;
    *nstarts = r + 1;
    return -1;
}

int64_t dggs_ring_point_bound(const int64_t *steps, int64_t m) {
    int64_t sum = 0;
    for (int64_t i = 0; i < m; i++) sum += steps[i];
    return 2 * sum + 4 * m;
}

/* _edge: face and planar ends of edge `col` of a cell (corner col to corner col + 1, counter-clockwise). */
static int ring_edge(uint64_t cell, int64_t col, double *x0, double *y0, double *x1, double *y1) {
    double t[6];
    int face = dggs_corners(cell, t);
    if (col == 0) {
        *x0 = t[0], *y0 = t[1], *x1 = t[2], *y1 = t[3];
    } else if (col == 1) {
        *x0 = t[2], *y0 = t[3], *x1 = t[4], *y1 = t[5];
    } else {
        *x0 = t[4], *y0 = t[5], *x1 = t[0], *y1 = t[1];
    }
    return face;
}

void dggs_grid_point(dggs_projection proj, int face, double x0, double y0, double x1, double y1, int64_t j,
                     int64_t step, double *lat, double *lng) {
    double p[3];
    dggs_proj_inverse(proj, face, x0 + (double)j * ((x1 - x0) / (double)step),
                      y0 + (double)j * ((y1 - y0) / (double)step), p);
    dggs_unit_to_geodetic(p[0], p[1], p[2], lat, lng);
}

dggs_error dggs_ring_points(dggs_projection proj, const uint64_t *cell, const int64_t *col, const int64_t *steps,
                            const int64_t *starts, int64_t nstarts, double *out, int64_t rows, uint8_t *corner,
                            int64_t *ends, double *ts, int64_t ts_len) {
    int64_t n = 0;
    for (int64_t r = 0; r < nstarts - 1; r++) {
        int64_t a = starts[r], b = starts[r + 1];
        for (int64_t k = a; k < b; k++) {
            double x0, y0, x1, y1;
            int face = ring_edge(cell[k], col[k], &x0, &y0, &x1, &y1);
            int64_t step = steps[k];
            if (step < 1 || step + 2 > ts_len || step > INT32_MAX - 2) return DGGS_E_BUFFER;
            int64_t kn = k + 1 == b ? a : k + 1;
            double nx0, ny0, nx1, ny1;
            int fn = ring_edge(cell[kn], col[kn], &nx0, &ny0, &nx1, &ny1);
            bool end_at_pole = dggs_pole_on(fn, nx0, ny0, nx1, ny1) == 0.0;
            double tp = dggs_pole_on(face, x0, y0, x1, y1);
            int m = dggs_edge_params(ts, (int)step, tp);
            double lead = DGGS_POLE_LEAD / (double)step;
            for (int q = 0; q < m - 1; q++) {
                double ta = ts[q], tb = ts[q + 1];
                double lat, lng;
                if (ta == tp) {
                    double lin, lout, plat;
                    if (ta > 0.0) {
                        dggs_lat_lng_at(proj, face, x0, y0, x1, y1, ta - lead, &plat, &lin);
                    } else { /* the ring arrives at the pole along the previous edge */
                        int64_t kp = k == a ? b - 1 : k - 1;
                        double px0, py0, px1, py1;
                        int fp = ring_edge(cell[kp], col[kp], &px0, &py0, &px1, &py1);
                        dggs_lat_lng_at(proj, fp, px0, py0, px1, py1, 1.0 - DGGS_POLE_LEAD / (double)steps[kp], &plat,
                                        &lin);
                    }
                    dggs_lat_lng_at(proj, face, x0, y0, x1, y1, ta + lead, &plat, &lout);
                    dggs_lat_lng_at(proj, face, x0, y0, x1, y1, ta, &lat, &lng);
                    double sign = lat > 0.0 ? 1.0 : -1.0;
                    if (n + 2 > rows) return DGGS_E_BUFFER;
                    out[2 * n] = 90.0 * sign, out[2 * n + 1] = lin;
                    out[2 * n + 2] = 90.0 * sign, out[2 * n + 3] = lout;
                    corner[n] = 0;
                    corner[n + 1] = 0;
                    n += 2;
                    continue;
                }
                dggs_grid_point(proj, face, x0, y0, x1, y1, (int64_t)nearbyint(ta * (double)step), step, &lat, &lng);
                if (n + 1 > rows) return DGGS_E_BUFFER;
                out[2 * n] = lat, out[2 * n + 1] = lng;
                corner[n] = q == 0;
                n += 1;
                if (tb == tp || (q == m - 2 && end_at_pole)) continue;
                double lat_b, lng_b;
                dggs_lat_lng_at(proj, face, x0, y0, x1, y1, tb, &lat_b, &lng_b);
                if (fabs(lng_b - lng) > 180.0 && fabs(lng) < 180.0 && fabs(lng_b) < 180.0) {
                    if (n + 1 > rows) return DGGS_E_BUFFER;
                    out[2 * n] = dggs_crossing(proj, face, x0, y0, x1, y1, ta, tb, lng);
                    out[2 * n + 1] = lng > 0.0 ? 180.0 : -180.0;
                    corner[n] = 0;
                    n += 1;
                }
            }
        }
        ends[r] = n;
    }
    return DGGS_OK;
}

/* ---- the public verbs (dggs.h, "dissolve"): checked, over the functions above ---- */

/* Every id valid and strictly increasing. */
static dggs_error check_sorted_cells(const dggs_cell *cells, size_t n) {
    for (size_t i = 0; i < n; i++) {
        if (!dggs_is_valid(cells[i])) return DGGS_E_CELL;
        if (i && cells[i] <= cells[i - 1]) return DGGS_E_DOMAIN;
    }
    return DGGS_OK;
}

dggs_error dggs_cells_drop_covered(const dggs_cell *cells, size_t n, uint8_t *keep) {
    dggs_error err = check_sorted_cells(cells, n);
    if (err) return err;
    dggs_drop_covered(cells, (int64_t)n, keep);
    return DGGS_OK;
}

dggs_error dggs_boundary_descendants_size(dggs_cell cell, int level, int64_t *size) {
    if (!dggs_is_valid(cell)) return DGGS_E_CELL;
    if (level <= dggs_level_of(cell) || level > DGGS_MAX_LEVEL) return DGGS_E_LEVEL;
    *size = dggs_dissolve_descend(cell, level, NULL, 0);
    return DGGS_OK;
}

dggs_error dggs_boundary_descendants(dggs_cell cell, int level, dggs_cell *out, int64_t size) {
    int64_t need;
    dggs_error err = dggs_boundary_descendants_size(cell, level, &need);
    if (err) return err;
    if (size < need) return DGGS_E_BUFFER;
    dggs_dissolve_descend(cell, level, out, size);
    return DGGS_OK;
}

dggs_error dggs_outline_edge_mask(const dggs_cell *fine, size_t n_fine, const dggs_cell *cells, size_t n_cells,
                                  uint8_t *mask) {
    dggs_error err = check_sorted_cells(cells, n_cells);
    if (err) return err;
    int finest = 0;
    for (size_t i = 0; i < n_cells; i++) {
        int lv = dggs_level_of(cells[i]);
        if (lv > finest) finest = lv;
    }
    for (size_t i = 0; i < n_fine; i++) {
        if (!dggs_is_valid(fine[i])) return DGGS_E_CELL;
        int lv = dggs_level_of(fine[i]);
        if (lv < finest || lv != dggs_level_of(fine[0])) return DGGS_E_LEVEL_MISMATCH;
    }
    for (size_t i = 0; i < n_fine; i++) dggs_outline_mask(fine[i], cells, (int64_t)n_cells, mask + 3 * i);
    return DGGS_OK;
}

dggs_error dggs_outline_chain(const dggs_cell *edge_cell, const int64_t *edge_col, size_t m, const dggs_cell *cells,
                              size_t n_cells, uint8_t *visited, int64_t *order, int64_t *starts, size_t *rings) {
    dggs_error err = check_sorted_cells(cells, n_cells);
    if (err) return err;
    for (size_t i = 0; i < m; i++) {
        if (!dggs_is_valid(edge_cell[i])) return DGGS_E_CELL;
        if (edge_col[i] < 0 || edge_col[i] > 2) return DGGS_E_DOMAIN;
        if (i && (edge_cell[i] < edge_cell[i - 1] || (edge_cell[i] == edge_cell[i - 1] && edge_col[i] <= edge_col[i - 1])))
            return DGGS_E_DOMAIN;
    }
    int64_t nstarts = 0;
    int64_t bad = dggs_chain(edge_cell, edge_col, (int64_t)m, cells, (int64_t)n_cells, visited, order, starts, &nstarts);
    if (bad >= 0) return DGGS_E_FAILED;
    *rings = (size_t)(nstarts - 1);
    return DGGS_OK;
}

dggs_error dggs_outline_points_size(const int64_t *steps, size_t m, int64_t *size) {
    for (size_t i = 0; i < m; i++) {
        if (steps[i] < 1 || steps[i] > 100001) return DGGS_E_DOMAIN;
    }
    *size = dggs_ring_point_bound(steps, (int64_t)m);
    return DGGS_OK;
}

dggs_error dggs_outline_points(const dggs_cell *edge_cell, const int64_t *edge_col, const int64_t *steps, size_t m,
                               const int64_t *starts, size_t rings, dggs_projection proj, double *latlng, int64_t size,
                               uint8_t *corner, int64_t *ends, double *scratch, size_t scratch_len) {
    if (proj != DGGS_ISEA && proj != DGGS_IVEA) return DGGS_E_PROJECTION;
    int64_t need, most = 0;
    dggs_error err = dggs_outline_points_size(steps, m, &need);
    if (err) return err;
    for (size_t i = 0; i < m; i++) {
        if (!dggs_is_valid(edge_cell[i])) return DGGS_E_CELL;
        if (edge_col[i] < 0 || edge_col[i] > 2) return DGGS_E_DOMAIN;
        if (steps[i] > most) most = steps[i];
    }
    if (starts[0] != 0 || starts[rings] != (int64_t)m) return DGGS_E_DOMAIN;
    for (size_t r = 0; r < rings; r++) {
        if (starts[r + 1] <= starts[r]) return DGGS_E_DOMAIN;
    }
    if (size < need || scratch_len < (size_t)most + 2) return DGGS_E_BUFFER;
    return dggs_ring_points(proj, edge_cell, edge_col, steps, starts, (int64_t)rings + 1, latlng, size, corner, ends,
                            scratch, (int64_t)scratch_len);
}
