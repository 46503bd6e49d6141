/* Grid distances over the straight face strips (a port of index/_kernel/strips.py, operation for operation). */
#include "strips.h"

#include "grid_tables.h"

/* A crossing this close to an icosahedron vertex (of an edge's length) does not count. */
static const double STRIP_EPS = 1e-9;

bool dggs_strip_straight(double px, double py, double bx, double by, const double (*edges)[4], int m) {
    double dx = bx - px, dy = by - py;
    double last = 0.0;
    for (int i = 1; i <= m; i++) {
        double x0 = edges[i][0], y0 = edges[i][1], x1 = edges[i][2], y1 = edges[i][3];
        double ex = x1 - x0, ey = y1 - y0;
        double den = dx * ey - dy * ex;
        if (den == 0.0) return false;
        double wx = x0 - px, wy = y0 - py;
        double t = (wx * ey - wy * ex) / den; /* along the segment */
        double u = (wx * dy - wy * dx) / den; /* along the edge */
        if (!(last < t && t < 1.0) || !(STRIP_EPS < u && u < 1.0 - STRIP_EPS)) return false;
        last = t;
    }
    return true;
}

/* strip_distance: a depth-first search over the simple face chains from a's face, each edge crossed mapped
 * into a's frame, the chain's frame composed edge by edge (CHART_ROT/OFF). */
int64_t dggs_strip_distance(uint64_t a, uint64_t b, int level) {
    enum { TOP = DGGS_MAX_STRIP + 1 };
    int fa = (int)((a >> 57) & 31u);
    int fb = (int)((b >> 57) & 31u);
    double px, py, qx, qy;
    dggs_grid_centroid(a, level, &px, &py);
    dggs_grid_centroid(b, level, &qx, &qy);
    int64_t best = -1;
    if (fa == fb) best = dggs_separating_lines(px, py, qx, qy, level); /* the face itself: convex, straight */
    int faces[TOP];
    int tried[TOP] = {0}; /* edges of faces[i] tried so far */
    double rot[TOP][2][2]; /* faces[i]'s frame -> a's frame */
    double off[TOP][2];
    double edges[TOP][4]; /* edges[i]: the edge between faces[i - 1] and faces[i], in a's frame */
    faces[0] = fa;
    rot[0][0][0] = 1.0;
    rot[0][0][1] = 0.0;
    rot[0][1][0] = 0.0;
    rot[0][1][1] = 1.0;
    off[0][0] = 0.0;
    off[0][1] = 0.0;
    int depth = 0;
    while (depth >= 0) {
        if (tried[depth] == 3 || depth == DGGS_MAX_STRIP) {
            tried[depth] = 0;
            depth--;
            continue;
        }
        int j = tried[depth]++;
        int f = faces[depth];
        int g = DGGS_GRID_FACE_ADJ[f][j];
        bool seen = false;
        for (int i = 0; i <= depth; i++) seen = seen || faces[i] == g;
        if (seen) continue;
        double(*r)[2] = rot[depth];
        double *o = off[depth];
        const double *v0 = DGGS_GRID_FACE_VERTICES[j], *v1 = DGGS_GRID_FACE_VERTICES[(j + 1) % 3];
        int n = depth + 1;
        edges[n][0] = r[0][0] * v0[0] + r[0][1] * v0[1] + o[0];
        edges[n][1] = r[1][0] * v0[0] + r[1][1] * v0[1] + o[1];
        edges[n][2] = r[0][0] * v1[0] + r[0][1] * v1[1] + o[0];
        edges[n][3] = r[1][0] * v1[0] + r[1][1] * v1[1] + o[1];
        int back = DGGS_GRID_FACE_BACK[f][j];
        const double(*cr)[2] = DGGS_GRID_CHART_ROT[g][back]; /* g's frame -> f's frame */
        const double *co = DGGS_GRID_CHART_OFF[g][back];
        for (int x = 0; x < 2; x++) {
            for (int y = 0; y < 2; y++) rot[n][x][y] = r[x][0] * cr[0][y] + r[x][1] * cr[1][y];
            off[n][x] = r[x][0] * co[0] + r[x][1] * co[1] + o[x];
        }
        if (g == fb) { /* a strip ends here: the path never leaves b's face again */
            double bx = rot[n][0][0] * qx + rot[n][0][1] * qy + off[n][0];
            double by = rot[n][1][0] * qx + rot[n][1][1] * qy + off[n][1];
            if (dggs_strip_straight(px, py, bx, by, (const double(*)[4])edges, n)) {
                int64_t d = dggs_separating_lines(px, py, bx, by, level);
                if (best < 0 || d < best) best = d;
            }
            continue;
        }
        faces[n] = g;
        tried[n] = 0;
        depth = n;
    }
    return best;
}
