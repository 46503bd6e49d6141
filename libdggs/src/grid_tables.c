/* The grid graph's size bounds and the planar charts that give exact distances (a port of the compiled part of
 * index/_kernel/grid_tables.py, operation for operation; the tables are grid_tables.h, generated). */
#include "grid_tables.h"

#include <math.h>
#include <stdint.h>

#include "bits.h"

/* Python's divmod(k, 5), flooring (numba's too). */
static void grid_divmod5(int64_t k, int64_t *m, int64_t *r) {
    int64_t q = k / 5, s = k % 5;
    if (s < 0) {
        s += 5;
        q -= 1;
    }
    *m = q;
    *r = s;
}

/* ring_size_bound: away from the icosahedron vertices every level is the truncated trihexagonal (4.6.12) graph,
 * whose rings hold 12 m + (0, 3, 5, 7, 9)[r] cells for k = 5 m + r >= 1; only level 0 (the dodecahedron graph:
 * 1, 3, 6, 6, 3, 1) exceeds it, at k = 2. The arithmetic wraps as numba's int64 does (uint64_t: no UB). */
int64_t dggs_ring_size_bound(int64_t k) {
    static const int64_t tail[5] = {0, 3, 5, 7, 9};
    if (k == 0) return 1;
    if (k == 2) return 6;
    int64_t m, r;
    grid_divmod5(k, &m, &r);
    return (int64_t)(12u * (uint64_t)m + (uint64_t)tail[r]);
}

/* disk_size_bound: the planar 4.6.12 disk 1 + 30 m^2 + 6 m + 12 m r + (0, 3, 8, 15, 24)[r] for k = 5 m + r;
 * level 0 has 10 cells within 2 steps (planar: 9). */
int64_t dggs_disk_size_bound(int64_t k) {
    static const int64_t tail[5] = {0, 3, 8, 15, 24};
    if (k == 2) return 10;
    int64_t m, r;
    grid_divmod5(k, &m, &r);
    uint64_t um = (uint64_t)m;
    return (int64_t)(1u + 30u * um * um + 6u * um + 12u * um * (uint64_t)r + (uint64_t)tail[r]);
}

/* numba's int_power_impl for a float base and an integer exponent (numba/cpython/numbers.py): r = 1; square and
 * multiply from the low bit; 1 / r for a negative exponent; math.pow past 0x10000. */
double dggs_grid_powi(double a, int64_t b) {
    double r = 1.0;
    int invert = b < 0;
    uint64_t exp = invert ? 0u - (uint64_t)b : (uint64_t)b;
    if (exp > 0x10000u) return pow(a, (double)b);
    while (exp != 0) {
        if (exp & 1u) r *= a;
        exp >>= 1;
        a *= a;
    }
    return invert ? 1.0 / r : r;
}

/* _centroid: planar centroid of a cell at level >= 1 in its face frame (D and E per level, thesis 6.1.7). */
void dggs_grid_centroid(uint64_t cell, int level, double *x, double *y) {
    int d1 = (int)((cell >> 54) & 7u) - 1;
    double ax = DGGS_GRID_L1_CORNERS[d1][0][0], ay = DGGS_GRID_L1_CORNERS[d1][0][1];
    double bx = DGGS_GRID_L1_CORNERS[d1][1][0], by = DGGS_GRID_L1_CORNERS[d1][1][1];
    double cx = DGGS_GRID_L1_CORNERS[d1][2][0], cy = DGGS_GRID_L1_CORNERS[d1][2][1];
    for (int lv = 2; lv <= level; lv++) {
        int dig = (int)((cell >> (2 * (DGGS_MAX_LEVEL - lv))) & 3u) - 1;
        double dx = cx + (ax - cx) / 3.0, dy = cy + (ay - cy) / 3.0; /* D: a third of the way from C to A */
        double ex = 0.5 * (ax + bx), ey = 0.5 * (ay + by);           /* E: the midpoint of AB */
        if (dig == 0) { /* BCD */
            ax = bx;
            ay = by;
            bx = dx;
            by = dy;
        } else if (dig == 1) { /* BDE */
            ax = bx;
            ay = by;
            bx = dx;
            by = dy;
            cx = ex;
            cy = ey;
        } else { /* ADE */
            bx = dx;
            by = dy;
            cx = ex;
            cy = ey;
        }
    }
    *x = (ax + bx + cx) / 3.0;
    *y = (ay + by + cy) / 3.0;
}

/* _separating_lines: lines of the level's planar arrangement between two cell centroids (face-frame chart). */
int64_t dggs_separating_lines(double px, double py, double qx, double qy, int level) {
    int64_t total = 0;
    for (int f = 0; f < 6; f++) {
        double nx = DGGS_GRID_LINE_NORMALS[f][0], ny = DGGS_GRID_LINE_NORMALS[f][1];
        double h, tp, tq;
        if (f < 3) { /* edge families: the face edge r - <p, n> = 0 is a line */
            h = DGGS_GRID_SPACING[level][0];
            tp = (DGGS_GRID_R - (px * nx + py * ny)) / h;
            tq = (DGGS_GRID_R - (qx * nx + qy * ny)) / h;
        } else { /* median families: through the face centre */
            h = DGGS_GRID_SPACING[level][1];
            tp = (px * nx + py * ny) / h;
            tq = (qx * nx + qy * ny) / h;
        }
        int64_t diff = (int64_t)floor(tp) - (int64_t)floor(tq);
        total += diff < 0 ? -diff : diff;
    }
    return total;
}

/* chart_distance: the chart is a's face with its 3 neighbours unfolded, a triangle of twice the size whose
 * corners and edge midpoints are the only icosahedron vertices it touches. In the plane the cells are the
 * alcoves of the affine reflection group G2~ (the kisrhombille), and the distance between two alcoves is the
 * number of mirror lines separating them. If every cell within that many steps of a lies inside the chart (a
 * disk of radius rho around the centroid), the count is the distance on the sphere; else -1. */
int64_t dggs_chart_distance(uint64_t a, uint64_t b, int level) {
    int fa = (int)((a >> 57) & 31u);
    int fb = (int)((b >> 57) & 31u);
    double px, py, qx, qy;
    dggs_grid_centroid(a, level, &px, &py);
    dggs_grid_centroid(b, level, &qx, &qy);
    if (fb != fa) {
        int k = -1;
        for (int j = 0; j < 3; j++) {
            if (DGGS_GRID_FACE_ADJ[fa][j] == fb) k = DGGS_GRID_FACE_BACK[fa][j]; /* b's face edge bordering a's */
        }
        if (k < 0) return -1;
        const double(*rot)[2] = DGGS_GRID_CHART_ROT[fb][k];
        const double *off = DGGS_GRID_CHART_OFF[fb][k];
        double nqx = rot[0][0] * qx + rot[0][1] * qy + off[0];
        double nqy = rot[1][0] * qx + rot[1][1] * qy + off[1];
        qx = nqx;
        qy = nqy;
    }
    int64_t d = dggs_separating_lines(px, py, qx, qy, level);
    double shrt = DGGS_GRID_R / dggs_grid_powi(sqrt(3.0), (int64_t)level - 1); /* edge BC of a cell here */
    /* centroids move at most 2/sqrt3 BC per step; a corner is sqrt13/3 BC from the centroid */
    double rho = ((double)d * 2.0 / sqrt(3.0) + sqrt(13.0) / 3.0) * shrt * (1.0 + 1e-9) + 1e-12;
    for (int j = 0; j < 3; j++) { /* the chart: <p, n_j> >= -2 r */
        if (px * DGGS_GRID_LINE_NORMALS[j][0] + py * DGGS_GRID_LINE_NORMALS[j][1] + 2.0 * DGGS_GRID_R <= rho)
            return -1;
    }
    return d;
}
