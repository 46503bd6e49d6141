/* Child positions and local (i, j) lattice coordinates over 64-bit ids. A port of index/_kernel/local.py,
 * operation for operation (see local.h); the unfolding tables are local_tables.h, generated from the Python
 * floor by tools/gen_local_tables.py. */
#include "local.h"

#include <math.h>

#include "bits.h"
#include "dggs.h"
#include "faces.h"
#include "local_tables.h"
#include "points.h"

/* Python's floor division of int64 (C's / truncates toward zero); b > 0. */
static int64_t floor_div(int64_t a, int64_t b) {
    int64_t q = a / b;
    return (a % b != 0 && a < 0) ? q - 1 : q;
}

/* numba's float -> int64 conversion (fptosi, cvttsd2si on x86-64): out of range or NaN gives INT64_MIN, where
 * a C cast is undefined. */
static int64_t to_int64(double x) {
    if (!(x >= -0x1p63 && x < 0x1p63)) return INT64_MIN;
    return (int64_t)x;
}

/* ---- child positions ---- */

/* local.py child_count: np.int64(3) ** (level - max(parent_level, 1)), times 6 under a face. numba's integer
 * power gives 0 for a negative exponent (a level coarser than the parent). */
int64_t dggs_child_count(int parent_level, int level) {
    if (level == parent_level) return 1;
    int e = level - (parent_level > 1 ? parent_level : 1);
    int64_t n = 0;
    if (e >= 0) {
        n = 1;
        for (int k = 0; k < e; k++) n *= 3;
    }
    return parent_level == 0 ? n * 6 : n;
}

/* local.py _child_pos, one item: the digits below `parent_level` in base 3 (the level-1 digit in base 6). */
int64_t dggs_child_pos(uint64_t cell, int parent_level) {
    int level = dggs_level_of(cell);
    if (level < parent_level || parent_level < 0) return -1;
    int64_t pos = 0;
    for (int lv = parent_level + 1; lv <= level; lv++) {
        int64_t base = lv == 1 ? 6 : 3;
        pos = pos * base + dggs_digit_of(cell, lv);
    }
    return pos;
}

/* local.py one_child_pos: -1 for an invalid id or a cell coarser than `parent_level`. */
int64_t dggs_one_child_pos(int64_t cell, int parent_level) {
    uint64_t c = (uint64_t)cell;
    if (!dggs_is_valid(c)) return -1;
    return dggs_child_pos(c, parent_level);
}

/* local.py _child_pos_cells, one item (and _child_pos_cells_one): the digits of `pos`, lowest level first. */
uint64_t dggs_child_pos_cell(int64_t pos, uint64_t parent, int level) {
    int p = dggs_level_of(parent);
    int64_t q = pos;
    if (p > level || q < 0 || q >= dggs_child_count(p, level)) return 0;
    uint64_t cell = parent;
    for (int lv = level; lv > p; lv--) {
        int64_t base = lv == 1 ? 6 : 3;
        cell |= (uint64_t)(q % base + 1) << dggs_shift_of(lv);
        q /= base; /* q >= 0: truncation is Python's floor */
    }
    return cell;
}

/* local.py one_child_cell: the null id for an invalid parent or position. */
uint64_t dggs_one_child_cell(int64_t parent, int64_t pos, int level) {
    uint64_t p = (uint64_t)parent;
    if (!dggs_is_valid(p)) return 0;
    return dggs_child_pos_cell(pos, p, level);
}

/* ---- local (i, j) ---- */

const int8_t *dggs_unfold_face_table(void) { return &dggs_local_unfold_face[0][0]; }

/* local.py _basis: the anchor's face (returned), centroid (o) and lattice axes (e1, e2) and the scale. */
static int basis(uint64_t anchor, double *ox, double *oy, double *e1x, double *e1y, double *e2x, double *e2y,
                 double *scale) {
    double t[6];
    int face = dggs_triangle(anchor, t);
    double ax = t[0], ay = t[1], bx = t[2], by = t[3], cx = t[4], cy = t[5];
    if (dggs_level_of(anchor) == 0) {
        *e1x = bx - ax;
        *e1y = by - ay;
        *scale = 3.0;
    } else {
        *e1x = 2.0 * (cx - ax);
        *e1y = 2.0 * (cy - ay);
        *scale = 18.0;
    }
    *e2x = 0.5 * *e1x - DGGS_LOCAL_SQ3_2 * *e1y;
    *e2y = DGGS_LOCAL_SQ3_2 * *e1x + 0.5 * *e1y;
    *ox = (ax + bx + cx) / 3.0;
    *oy = (ay + by + cy) / 3.0;
    return face;
}

/* The face edge k (corner k to corner k + 1 of dggs_local_corners) that bounds Snyder's 120-degree sector s of a
 * face (dggs_sector_of: planar azimuth // 120 clockwise from +y): sector 0 runs from corner 2 (azimuth 0) to
 * corner 1 (120), sector 1 from corner 1 to corner 0 (240), sector 2 from corner 0 back to corner 2. */
static const int edge_of_sector[3] = {1, 0, 2};

/* Whether a cell at level >= 1 on face g with face-frame centroid (px, py) is in the chart of an anchor on face f
 * in sector s (docs/grid.md, "Local coordinates"): the anchor's sector, or the sector across the face edge that
 * bounds it (its mirror image on the face across that edge). Snyder's projection is one smooth map within a
 * sector and mirror-symmetric across a face edge, but bends across the lines from a face's centre to its
 * vertices (the radial scale's derivative changes sign there, most near the vertex), so no affine map of the
 * cells' centres on the sphere fits a chart that crosses them (issue 32 item 4). Every cell lies in one sector
 * (the lines are edges of the level-1 cells), so its centroid decides. */
static bool in_chart(int f, int s, int g, double px, double py) {
    int t = dggs_sector_of(px, py);
    if (g == f) return t == s;
    return g == dggs_local_unfold_face[f][edge_of_sector[s]] && dggs_local_unfold_face[g][edge_of_sector[t]] == f;
}

/* local.py _one_ij. round() is numba's llvm.rint (half to even), then a conversion to int64. At level >= 1 only
 * the cells of the anchor's chart (in_chart) answer; at level 0 the anchor's face and the three across its
 * edges. */
bool dggs_one_ij(uint64_t anchor, uint64_t cell, int64_t *i, int64_t *j) {
    double ox, oy, e1x, e1y, e2x, e2y, scale;
    int f = basis(anchor, &ox, &oy, &e1x, &e1y, &e2x, &e2y, &scale);
    double t[6];
    int g = dggs_triangle(cell, t);
    double px = (t[0] + t[2] + t[4]) / 3.0, py = (t[1] + t[3] + t[5]) / 3.0;
    if (dggs_level_of(anchor) > 0 && !in_chart(f, dggs_sector_of(ox, oy), g, px, py)) {
        *i = DGGS_OUT_OF_RANGE;
        *j = 0;
        return false;
    }
    if (g != f) {
        int k = -1;
        for (int e = 0; e < 3; e++)
            if (dggs_local_unfold_face[f][e] == g) k = e;
        if (k < 0) {
            *i = DGGS_OUT_OF_RANGE;
            *j = 0;
            return false;
        }
        const double *mo = dggs_local_motion[f][k];
        double co = mo[0], si = mo[1], tx = mo[2], ty = mo[3];
        double qx = co * px - si * py + tx;
        double qy = si * px + co * py + ty;
        px = qx;
        py = qy;
    }
    double dx = px - ox, dy = py - oy;
    double det = e1x * e2y - e1y * e2x;
    int64_t u = to_int64(rint(scale * (dx * e2y - dy * e2x) / det));
    int64_t v = to_int64(rint(scale * (e1x * dy - e1y * dx) / det));
    *i = floor_div((int64_t)(2 * (uint64_t)u + (uint64_t)v), 3); /* int64 wraps in numba */
    *j = floor_div((int64_t)((uint64_t)u + 2 * (uint64_t)v), 3);
    return true;
}

/* local.py one_local_ij: (i, j, ok), not ok for invalid ids, two levels or no pair. */
bool dggs_one_local_ij(int64_t anchor, int64_t cell, int64_t *i, int64_t *j) {
    uint64_t a = (uint64_t)anchor, c = (uint64_t)cell;
    if (!dggs_is_valid(a) || !dggs_is_valid(c) || dggs_level_of(a) != dggs_level_of(c)) {
        *i = 0;
        *j = 0;
        return false;
    }
    dggs_one_ij(a, c, i, j);
    return *i != DGGS_OUT_OF_RANGE;
}

/* local.py _inside: -1 inside the face triangle (edges included), else the first edge k whose outside holds
 * (x, y). */
static int inside(double x, double y) {
    for (int k = 0; k < 3; k++) {
        double x0 = dggs_local_corners[k][0], y0 = dggs_local_corners[k][1];
        double x1 = dggs_local_corners[(k + 1) % 3][0], y1 = dggs_local_corners[(k + 1) % 3][1];
        if ((x1 - x0) * (y - y0) - (y1 - y0) * (x - x0) < -1e-15) return k;
    }
    return -1;
}

/* local.py _one_cell: the cell at (i, j) around `anchor`, or the null id where no cell of the range has those
 * coordinates. u and v are numba's wrapping int64 arithmetic (here in uint64), then converted to float64. */
uint64_t dggs_one_cell(uint64_t anchor, int64_t i, int64_t j) {
    double ox, oy, e1x, e1y, e2x, e2y, scale;
    int f = basis(anchor, &ox, &oy, &e1x, &e1y, &e2x, &e2y, &scale);
    int64_t u = (int64_t)(2 * (uint64_t)i - (uint64_t)j), v = (int64_t)(2 * (uint64_t)j - (uint64_t)i);
    double px = ox + ((double)u * e1x + (double)v * e2x) / scale;
    double py = oy + ((double)u * e1y + (double)v * e2y) / scale;
    int face = f, k = inside(px, py);
    if (k >= 0) { /* across edge k: back into that face's own frame */
        face = dggs_local_unfold_face[f][k];
        const double *mo = dggs_local_motion[f][k];
        double co = mo[0], si = mo[1], tx = mo[2], ty = mo[3];
        double qx = px - tx, qy = py - ty;
        px = co * qx + si * qy;
        py = -si * qx + co * qy;
        if (inside(px, py) >= 0) return 0;
    }
    uint64_t cell = dggs_encode_point(face, px, py, dggs_level_of(anchor));
    int64_t ci, cj;
    dggs_one_ij(anchor, cell, &ci, &cj);
    return (ci == i && cj == j) ? cell : 0;
}

/* local.py one_local_cell: the null id for an invalid anchor or a pair naming no cell. */
uint64_t dggs_one_local_cell(int64_t anchor, int64_t i, int64_t j) {
    uint64_t a = (uint64_t)anchor;
    if (!dggs_is_valid(a)) return 0;
    return dggs_one_cell(a, i, j);
}

/* ---- public API (dggs.h, "local") ---- */

dggs_error dggs_cell_to_child_pos(dggs_cell cell, int parent_level, int64_t *pos) {
    if (!dggs_is_valid(cell)) return DGGS_E_CELL;
    if (parent_level < 0 || parent_level > DGGS_MAX_LEVEL) return DGGS_E_LEVEL;
    int64_t p = dggs_child_pos(cell, parent_level);
    if (p < 0) return DGGS_E_LEVEL_MISMATCH;
    *pos = p;
    return DGGS_OK;
}

dggs_error dggs_child_pos_to_cell(int64_t pos, dggs_cell parent, int child_level, dggs_cell *child) {
    if (!dggs_is_valid(parent)) return DGGS_E_CELL;
    if (child_level < 0 || child_level > DGGS_MAX_LEVEL) return DGGS_E_LEVEL;
    if (dggs_level_of(parent) > child_level) return DGGS_E_LEVEL_MISMATCH;
    uint64_t c = dggs_child_pos_cell(pos, parent, child_level);
    if (c == 0) return DGGS_E_DOMAIN;
    *child = c;
    return DGGS_OK;
}

dggs_error dggs_cell_to_local_ij(dggs_cell anchor, dggs_cell cell, int64_t *i, int64_t *j) {
    if (!dggs_is_valid(anchor) || !dggs_is_valid(cell)) return DGGS_E_CELL;
    if (dggs_level_of(anchor) != dggs_level_of(cell)) return DGGS_E_LEVEL_MISMATCH;
    int64_t ci, cj;
    if (!dggs_one_ij(anchor, cell, &ci, &cj)) return DGGS_E_FAILED;
    *i = ci;
    *j = cj;
    return DGGS_OK;
}

dggs_error dggs_local_ij_to_cell(dggs_cell anchor, int64_t i, int64_t j, dggs_cell *cell) {
    if (!dggs_is_valid(anchor)) return DGGS_E_CELL;
    uint64_t c = dggs_one_cell(anchor, i, j);
    if (c == 0) return DGGS_E_DOMAIN;
    *cell = c;
    return DGGS_OK;
}
