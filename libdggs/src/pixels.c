/* Exact weights of polygons in cells (index/_kernel/pixels.py): see pixels.h. */
#include "pixels.h"

#include <math.h>
#include <string.h>

#include "bits.h"
#include "clip.h"
#include "dmath.h"
#include "geometry.h"
#include "pixels_tables.h"
#include "points.h"
#include "tables.h"

#define FRAMES (&dggs_isea_frames[0][0][0])
#define CENTRES (&dggs_isea_centres[0][0])

static inline double py_max(double a, double b) { return b > a ? b : a; }

int64_t dggs_pixels_region(int face, double ux, double uy, double uz) {
    const double(*fr)[3] = dggs_isea_frames[face];
    double n = fr[1][0] * ux + fr[1][1] * uy + fr[1][2] * uz;
    double e = fr[2][0] * ux + fr[2][1] * uy + fr[2][2] * uz;
    if (e >= 0.0 && -0.5 * e - DGGS_PIXEL_HALF_SQRT3 * n < 0.0 && !(e == 0.0 && n < 0.0)) return 3 * (int64_t)face;
    if (e < 0.0 && -0.5 * e + DGGS_PIXEL_HALF_SQRT3 * n >= 0.0) return 3 * (int64_t)face + 2;
    return 3 * (int64_t)face + 1;
}

/* chord_errors for one pixel. A chord of length L whose curve's middle lies s off it leaves out 2/3 s L (a
 * parabola's segment). Each half-edge's is measured from its three points, in the face planes of the faces the
 * points lie on; a half across a kink takes the other half's, or, where both are, the bend of the pixel's
 * smoothest-measured half; a whole edge's is 8 times its halves' mean (s grows as L^2). */
double dggs_chord_error(const double *lat, const double *lng) {
    double out = 0.0;
    double ux[16], uy[16], uz[16], x[16], y[16];
    int faces[16];
    int64_t regs[16];
    for (int j = 0; j < 16; j++) {
        double p[3];
        dggs_geodetic_to_unit(lat[j], lng[j], p);
        ux[j] = p[0], uy[j] = p[1], uz[j] = p[2];
        faces[j] = dggs_nearest_face(CENTRES, ux[j], uy[j], uz[j]);
        regs[j] = dggs_pixels_region(faces[j], ux[j], uy[j], uz[j]);
    }
    for (int j = 0; j < 16; j++) {
        int f = faces[j];
        bool seen = false;
        for (int i = 0; i < j; i++) seen = seen || faces[i] == f;
        if (j > 0 && seen) continue;
        for (int q = 0; q < 16; q++) dggs_snyder_face_forward(FRAMES, f, ux[q], uy[q], uz[q], &x[q], &y[q]);
        double twice = 0.0, lost = 0.0;
        double ratio = -1.0; /* the largest lost / length^2 of a smooth half-edge: how the pixel's edges bend */
        double bent = 0.0;   /* the squared lengths of the halves to take that ratio (both halves of an edge kinked) */
        for (int e = 0; e < 4; e++) {
            twice += x[4 * e] * y[(4 * e + 4) % 16] - x[(4 * e + 4) % 16] * y[4 * e];
            double half = 0.0;
            int smooth = 0;
            for (int h = 0; h < 2; h++) {
                int a = 4 * e + 2 * h, m = 4 * e + 2 * h + 1, b = (4 * e + 2 * h + 2) % 16;
                double length = dggs_hypot(x[b] - x[a], y[b] - y[a]);
                if (regs[a] != regs[m] || regs[m] != regs[b]) {
                    if (h == 1 && smooth == 0) bent += 2.0 * length * length;
                    continue;
                }
                double one = 2.0 / 3.0 * dggs_hypot(x[m] - 0.5 * (x[a] + x[b]), y[m] - 0.5 * (y[a] + y[b])) * length;
                half += one;
                smooth += 1;
                if (length > 0.0) ratio = py_max(ratio, one / (length * length));
            }
            if (smooth) lost += 8.0 * half / (double)smooth;
        }
        if (ratio < 0.0) {
            out = NAN; /* no smooth half-edge to measure: the caller takes its neighbours' */
            break;
        }
        lost += 8.0 * ratio * bent;
        if (twice != 0.0 && !isnan(out)) out = py_max(out, lost / fabs(0.5 * twice));
    }
    return out;
}

/* numba's lt_floats: NaNs last. */
static inline bool lt_floats(double a, double b) { return a < b || (isnan(b) && !isnan(a)); }

#define SMALL_QUICKSORT 15
#define MAX_STACK 100

static void argsort_insertion(const double *a, int64_t *r, int64_t low, int64_t high) {
    if (high <= low) return;
    for (int64_t i = low + 1; i < high + 1; i++) {
        int64_t k = r[i];
        double v = a[k];
        int64_t j = i;
        while (j > low && lt_floats(v, a[r[j - 1]])) {
            r[j] = r[j - 1];
            j -= 1;
        }
        r[j] = k;
    }
}

static int64_t argsort_partition(const double *a, int64_t *r, int64_t low, int64_t high) {
    int64_t mid = (low + high) >> 1, s;
    if (lt_floats(a[r[mid]], a[r[low]])) s = r[low], r[low] = r[mid], r[mid] = s;
    if (lt_floats(a[r[high]], a[r[mid]])) s = r[high], r[high] = r[mid], r[mid] = s;
    if (lt_floats(a[r[mid]], a[r[low]])) s = r[low], r[low] = r[mid], r[mid] = s;
    double pivot = a[r[mid]];
    s = r[high], r[high] = r[mid], r[mid] = s; /* stash the pivot at the end */
    int64_t i = low, j = high - 1;
    for (;;) {
        while (i < high && lt_floats(a[r[i]], pivot)) i += 1;
        while (j >= low && lt_floats(pivot, a[r[j]])) j -= 1;
        if (i >= j) break;
        s = r[i], r[i] = r[j], r[j] = s;
        i += 1;
        j -= 1;
    }
    s = r[i], r[i] = r[high], r[high] = s;
    return i;
}

/* numba/misc/quicksort.py's run_quicksort1 with is_argsort. */
void dggs_numba_argsort(const double *a, int64_t n, int64_t *r) {
    for (int64_t i = 0; i < n; i++) r[i] = i;
    if (n < 2) return;
    int64_t stack_lo[MAX_STACK], stack_hi[MAX_STACK];
    stack_lo[0] = 0, stack_hi[0] = n - 1;
    int sp = 1;
    while (sp > 0) {
        sp -= 1;
        int64_t low = stack_lo[sp], high = stack_hi[sp];
        while (high - low >= SMALL_QUICKSORT) {
            if (sp >= MAX_STACK) return; /* numba asserts; the larger part is always the one pushed: unreachable */
            int64_t i = argsort_partition(a, r, low, high);
            if (high - i > i - low) { /* push the larger part */
                if (high > i) stack_lo[sp] = i + 1, stack_hi[sp] = high, sp += 1;
                high = i - 1;
            } else {
                if (i > low) stack_lo[sp] = low, stack_hi[sp] = i - 1, sp += 1;
                low = i + 1;
            }
        }
        argsort_insertion(a, r, low, high);
    }
}

int64_t dggs_kinked(const double *ux, const double *uy, const double *uz, const int64_t *ring, int64_t m,
                    const int64_t *regions, const bool *near, double *ox, double *oy, double *oz, int64_t cap) {
    int64_t out = 0;
    double ts[6 * DGGS_NUM_FACES], cx[6 * DGGS_NUM_FACES], cy[6 * DGGS_NUM_FACES], cz[6 * DGGS_NUM_FACES];
    int64_t order[6 * DGGS_NUM_FACES];
    for (int64_t j = 0; j < m; j++) {
        int64_t a = ring[j], b = ring[(j + 1) % m];
        if (out >= cap) return -1;
        ox[out] = ux[a], oy[out] = uy[a], oz[out] = uz[a];
        out += 1;
        if (regions[a] == regions[b]) continue;
        double mx = uy[a] * uz[b] - uz[a] * uy[b]; /* the normal of the great circle through a and b */
        double my = uz[a] * ux[b] - ux[a] * uz[b];
        double mz = ux[a] * uy[b] - uy[a] * ux[b];
        int64_t found = 0;
        for (int f = 0; f < DGGS_NUM_FACES; f++) {
            if (!near[f]) continue;
            for (int q = 0; q < 6; q++) {
                double nx = dggs_pixel_bounds[f][q][0], ny = dggs_pixel_bounds[f][q][1], nz = dggs_pixel_bounds[f][q][2];
                double dx = my * nz - mz * ny, dy = mz * nx - mx * nz, dz = mx * ny - my * nx;
                double norm = sqrt(dx * dx + dy * dy + dz * dz);
                if (norm == 0.0) continue;
                if (dx * (ux[a] + ux[b]) + dy * (uy[a] + uy[b]) + dz * (uz[a] + uz[b]) < 0.0) norm = -norm;
                dx = dx / norm, dy = dy / norm, dz = dz / norm;
                /* strictly between a and b along their arc */
                double sa = (uy[a] * dz - uz[a] * dy) * mx + (uz[a] * dx - ux[a] * dz) * my + (ux[a] * dy - uy[a] * dx) * mz;
                double sb = (dy * uz[b] - dz * uy[b]) * mx + (dz * ux[b] - dx * uz[b]) * my + (dx * uy[b] - dy * ux[b]) * mz;
                if (sa <= 0.0 || sb <= 0.0) continue;
                ts[found] = sa / (sa + sb);
                cx[found] = dx, cy[found] = dy, cz[found] = dz;
                found += 1;
            }
        }
        dggs_numba_argsort(ts, found, order);
        for (int64_t i = 0; i < found; i++) {
            if (out >= cap) return -1;
            ox[out] = cx[order[i]], oy[out] = cy[order[i]], oz[out] = cz[order[i]];
            out += 1;
        }
    }
    return out;
}

int dggs_pixels_common(const uint64_t *cells, int64_t count, int target) {
    for (int lv = 1; lv < target + 1; lv++) {
        uint64_t first = dggs_parent_at(cells[0], lv);
        for (int64_t i = 1; i < count; i++) {
            if (dggs_parent_at(cells[i], lv) != first) return lv - 1;
        }
    }
    return target;
}

int64_t dggs_pixels_ring(int64_t r, int64_t col, int64_t k, int64_t hw, int64_t hsize, int64_t vw, int64_t *ring) {
    if (k == 1) { /* the four corners, all on the lines of constant row (the others are the same points) */
        ring[0] = r * hw + col, ring[1] = r * hw + col + 1;
        ring[2] = (r + 1) * hw + col + 1, ring[3] = (r + 1) * hw + col;
        return 4;
    }
    int64_t m = 0;
    for (int64_t j = 0; j < k; j++) ring[m++] = r * hw + col * k + j;                /* top edge, left to right */
    for (int64_t j = 0; j < k; j++) ring[m++] = hsize + (r * k + j) * vw + col + 1;  /* right edge, top to bottom */
    for (int64_t j = 0; j < k; j++) ring[m++] = (r + 1) * hw + (col + 1) * k - j;    /* bottom edge, right to left */
    for (int64_t j = 0; j < k; j++) ring[m++] = hsize + ((r + 1) * k - j) * vw + col; /* left edge, bottom to top */
    return m;
}

/* ---- the arcs' area beyond the chords ---- */

static int64_t largest_piece(const double *area, int64_t first, int64_t last) {
    int64_t best = first;
    for (int64_t i = first + 1; i < last; i++) {
        if (area[i] > area[best]) best = i;
    }
    return best;
}

/* The piece of cell `want` among pieces [first, last), or -1: binary search where the cells are increasing (one
 * descent gives them in id order), else a scan. */
static int64_t piece_of(const uint64_t *cell, int64_t first, int64_t last, uint64_t want) {
    int64_t lo = first, hi = last;
    while (lo < hi) {
        int64_t mid = lo + (hi - lo) / 2;
        if (cell[mid] < want)
            lo = mid + 1;
        else
            hi = mid;
    }
    if (lo < last && cell[lo] == want) return lo;
    for (int64_t i = first; i < last; i++) {
        if (cell[i] == want) return i;
    }
    return -1;
}

static double corner_turn(const double *ux, const double *uy, const double *uz, int64_t a, int64_t b, int64_t c) {
    double px = ux[b] - ux[a], py = uy[b] - uy[a], pz = uz[b] - uz[a];
    double qx = ux[c] - ux[a], qy = uy[c] - uy[a], qz = uz[c] - uz[a];
    return (py * qz - pz * qy) * ux[a] + (pz * qx - px * qz) * uy[a] + (px * qy - py * qx) * uz[a];
}

/* For an even k, adds to each piece the area between its pixel's curved edges and their chords: round the ring,
 * each pair of chords (points 2i, 2i + 1, 2i + 2, in one sector of one face) bounds with the arc through its
 * points a third of the triangle they make (Archimedes: the parabolic segment under the long chord is 4/3 of
 * it); that goes to the piece of the cell holding the middle point (the pixel's largest piece where it has none
 * there). A neighbour runs the same pair the other way round: what one pixel gains, the other loses, in the same
 * cell. Pairs across a kink (the kernel cuts their chords at it) are left as drawn. */
static void arc_pass(const double *ux, const double *uy, const double *uz, const double *fx, const double *fy,
                     const int64_t *regions, const uint64_t *cells, int64_t k, const uint8_t *valid, int64_t rows,
                     int64_t cols, int64_t hw, int64_t hsize, int64_t vw, int64_t *ring, dggs_pieces *out) {
    int64_t at = 0, n = out->n;
    for (int64_t r = 0; r < rows; r++) {
        for (int64_t col = 0; col < cols; col++) {
            int64_t p = r * cols + col;
            while (at < n && out->pixel[at] < p) at++;
            int64_t first = at, last = at;
            while (last < n && out->pixel[last] == p) last++;
            if (!valid[p] || first == last) continue;
            int64_t m = dggs_pixels_ring(r, col, k, hw, hsize, vw, ring);
            /* the ring's orientation in the face planes is its corners' on the sphere (the projection keeps it) */
            double turn = corner_turn(ux, uy, uz, ring[0], ring[k], ring[2 * k]) +
                          corner_turn(ux, uy, uz, ring[0], ring[2 * k], ring[3 * k]);
            double sign = turn > 0.0 ? 1.0 : -1.0;
            for (int64_t j = 0; j < m; j += 2) {
                int64_t a = ring[j], b = ring[j + 1], c = ring[(j + 2) % m];
                if (regions[a] != regions[b] || regions[b] != regions[c]) continue;
                double t = ((fx[b] - fx[a]) * (fy[c] - fy[a]) - (fx[c] - fx[a]) * (fy[b] - fy[a])) / 6.0;
                if (t == 0.0) continue;
                int64_t i = piece_of(out->cell, first, last, cells[b]);
                if (i < 0) i = largest_piece(out->area, first, last); /* its point on a cell's edge or corner */
                out->area[i] += sign * t;
            }
            for (int64_t i = first; i < last; i++) { /* a sliver's correction larger than the sliver */
                if (out->area[i] >= 0.0) continue;
                int64_t big = largest_piece(out->area, first, last);
                out->area[big] += out->area[i];
                out->area[i] = 0.0;
            }
        }
    }
}

/* Drops the pieces the corrections left with no area (a sliver whose correction was larger than it, folded into
 * its pixel's largest piece above): a pixel's pieces are the cells it shares a positive area with (docs/raster.md),
 * and the pixels' sums are unchanged. */
static void drop_empty_pieces(dggs_pieces *out) {
    int64_t kept = 0;
    for (int64_t i = 0; i < out->n; i++) {
        if (!(out->area[i] > 0.0)) continue;
        out->pixel[kept] = out->pixel[i];
        out->cell[kept] = out->cell[i];
        out->area[kept] = out->area[i];
        kept++;
    }
    out->n = kept;
}

/* The scratch sizes of grid_pieces (numba's np.empty calls): ring points m = 4 k, `most` with the kinks'
 * crossings, `width` of a clipped polygon, `levels` of descend's stack. */
static void work_dims(int64_t k, int target, int64_t *m, int64_t *most, int64_t *width, int64_t *levels) {
    *m = 4 * k;
    *most = 8 * *m + 64;
    *width = *most + 3 * ((int64_t)target + 4) + 8;
    *levels = (int64_t)target + 3;
}

int64_t dggs_grid_pieces_work_words(int64_t npts, int64_t k, int target) {
    int64_t m, most, width, levels;
    work_dims(k, target, &m, &most, &width, &levels);
    return 8 * npts + 2 * m + 6 * width + 2 * levels * 6 * width + 2 * levels * 6 + 2 * levels + 3 * most +
           DGGS_NUM_FACES;
}

dggs_error dggs_grid_pieces_arcs(const double *hlat, const double *hlng, int64_t hrows, int64_t hcols,
                                 const double *vlat, const double *vlng, int64_t vrows, int64_t vcols, int64_t k,
                                 const uint8_t *valid, int64_t rows, int64_t cols, int target, bool arcs,
                                 dggs_pieces *out, double *coarse, void *work, int64_t work_words, int64_t *resume,
                                 int64_t *need) {
    if (k < 1 || target < 0 || target > DGGS_MAX_LEVEL || rows < 0 || cols < 0 || hrows != rows + 1 ||
        hcols != cols * k + 1 || (k > 1 && (vrows != rows * k + 1 || vcols != cols + 1)))
        return DGGS_E_DOMAIN;
    int64_t hsize = hrows * hcols, vsize = vrows * vcols;
    int64_t npts = hsize + (k > 1 ? vsize : 0); /* with one point an edge, the corners are all in hlat */
    if (work_words < dggs_grid_pieces_work_words(npts, k, target)) return DGGS_E_BUFFER;
    int64_t m, most, width, levels;
    work_dims(k, target, &m, &most, &width, &levels);
    /* carve the scratch: every array of 8-byte items */
    double *wd = (double *)work;
    double *ux = wd, *uy = ux + npts, *uz = uy + npts, *fx = uz + npts, *fy = fx + npts;
    int64_t *faces = (int64_t *)(fy + npts), *regions = faces + npts;
    uint64_t *cells = (uint64_t *)(regions + npts);
    int64_t *ring = (int64_t *)(cells + npts);
    uint64_t *rc = (uint64_t *)(ring + m);
    double *px = (double *)(rc + m), *py = px + width, *tx = py + width, *ty = tx + width, *qx = ty + width,
           *qy = qx + width;
    double *kx = qy + width, *ky = kx + levels * 6 * width;
    int64_t *kn = (int64_t *)(ky + levels * 6 * width);
    double *tri6 = (double *)(kn + levels * 6);
    uint64_t *ids = (uint64_t *)(tri6 + levels * 6);
    int64_t *nxt = (int64_t *)(ids + levels);
    double *wx = (double *)(nxt + levels), *wy = wx + most, *wz = wy + most;
    bool near[DGGS_NUM_FACES];
    memset(kn, 0, (size_t)(levels * 6) * sizeof(int64_t));
    memset(nxt, 0, (size_t)levels * sizeof(int64_t));
    memset(near, 0, sizeof near);
    dggs_clip_work cw = {levels, width, kx, ky, kn, tx, ty, tri6, ids, nxt};

    int64_t first = *resume;
    if (first < 0 || first > rows * cols) return DGGS_E_DOMAIN;
    for (int64_t i = 0; i < (first ? 0 : npts); i++) { /* every point once: shared by the pixels on both sides */
        double la = i < hsize ? hlat[i] : vlat[i - hsize], lo = i < hsize ? hlng[i] : vlng[i - hsize];
        double p[3];
        dggs_geodetic_to_unit(la, lo, p);
        ux[i] = p[0], uy[i] = p[1], uz[i] = p[2];
        int f = dggs_nearest_face(CENTRES, ux[i], uy[i], uz[i]);
        faces[i] = f;
        regions[i] = dggs_pixels_region(f, ux[i], uy[i], uz[i]);
        dggs_snyder_face_forward(FRAMES, f, ux[i], uy[i], uz[i], &fx[i], &fy[i]);
        cells[i] = dggs_encode_point(f, fx[i], fy[i], target);
    }
    const double face_tri[6] = {dggs_face_corners_ccw[0][0], dggs_face_corners_ccw[0][1], dggs_face_corners_ccw[1][0],
                                dggs_face_corners_ccw[1][1], dggs_face_corners_ccw[2][0], dggs_face_corners_ccw[2][1]};
    for (int64_t i = 0; i < (first ? 0 : rows * cols); i++) coarse[i] = NAN;
    double root_tri[6];
    int64_t half = k >= 2 && k % 2 == 0 ? m / 2 : 0;
    int64_t n0 = out->n; /* the pieces before this pixel */
    for (int64_t r = first / (cols ? cols : 1); r < rows; r++) {
        for (int64_t col = r == first / (cols ? cols : 1) ? first % (cols ? cols : 1) : 0; col < cols; col++) {
            if (out->n > out->cap) { /* the last pixel's pieces did not fit: the caller grows and resumes there */
                *need = out->n;
                out->n = n0;
                return DGGS_E_BUFFER;
            }
            n0 = out->n;
            *resume = r * cols + col;
            if (!valid[r * cols + col]) continue;
            int64_t pixel = r * cols + col;
            dggs_pixels_ring(r, col, k, hcols, hsize, vcols, ring);
            int64_t f = faces[ring[0]];
            bool one_face = true, one_region = true, one_cell = true;
            for (int64_t j = 0; j < m; j++) {
                int64_t q = ring[j];
                px[j] = fx[q], py[j] = fy[q], rc[j] = cells[q];
                one_face &= faces[q] == f;
                one_region &= regions[q] == regions[ring[0]];
                one_cell &= cells[q] == rc[0];
            }
            if (one_region) { /* in one sector of one face, where the plane does not bend */
                if (half) {   /* the ring through every other point (corners included) */
                    for (int64_t j = 0; j < half; j++) qx[j] = px[2 * j], qy[j] = py[2 * j];
                    coarse[pixel] = fabs(dggs_clip_area(qx, qy, half));
                }
                if (one_cell) { /* every vertex in one cell: the pixel lies in it (cells are convex) */
                    double got = fabs(dggs_clip_area(px, py, m));
                    if (got > 0.0) dggs_pieces_put(out, pixel, rc[0], got);
                    continue;
                }
                int level = dggs_pixels_common(rc, m, target);
                uint64_t root = dggs_parent_at(rc[0], level);
                if (level == 0)
                    memcpy(root_tri, face_tri, sizeof root_tri);
                else
                    dggs_triangle(root, root_tri);
                if (dggs_clip_descend(root, level, root_tri, target, px, py, m, pixel, out, &cw)) return DGGS_E_FAILED;
                continue;
            }
            for (int g = 0; g < DGGS_NUM_FACES; g++) { /* across sectors or faces: the faces near a vertex */
                near[g] = g == f;
                for (int64_t j = 0; j < m; j++) {
                    if (one_face) break;
                    int64_t q = ring[j];
                    if (ux[q] * dggs_isea_centres[g][0] + uy[q] * dggs_isea_centres[g][1] +
                            uz[q] * dggs_isea_centres[g][2] >=
                        DGGS_PIXEL_REACH) {
                        near[g] = true;
                        break;
                    }
                }
            }
            int64_t mk = dggs_kinked(ux, uy, uz, ring, m, regions, near, wx, wy, wz, most);
            if (mk < 0) return DGGS_E_FAILED;
            for (int g = 0; g < DGGS_NUM_FACES; g++) {
                if (!near[g]) continue;
                for (int64_t j = 0; j < mk; j++) dggs_snyder_face_forward(FRAMES, g, wx[j], wy[j], wz[j], &px[j], &py[j]);
                int64_t got_n = dggs_clip(px, py, mk, face_tri[0], face_tri[1], face_tri[2], face_tri[3], face_tri[4],
                                          face_tri[5], qx, qy, tx, ty, width);
                if (got_n < 0) return DGGS_E_FAILED;
                double got = fabs(dggs_clip_area(tx, ty, got_n));
                if (got <= 0.0) continue;
                if (target == 0) {
                    dggs_pieces_put(out, pixel, dggs_base_cell(g), got);
                    continue;
                }
                memcpy(px, tx, (size_t)got_n * sizeof(double));
                memcpy(py, ty, (size_t)got_n * sizeof(double));
                if (dggs_clip_descend(dggs_base_cell(g), 0, face_tri, target, px, py, got_n, pixel, out, &cw))
                    return DGGS_E_FAILED;
            }
        }
    }
    if (out->n > out->cap) {
        *need = out->n;
        out->n = n0;
        return DGGS_E_BUFFER;
    }
    *resume = rows * cols;
    *need = out->n;
    if (arcs && k >= 2 && k % 2 == 0) {
        arc_pass(ux, uy, uz, fx, fy, regions, cells, k, valid, rows, cols, hcols, hsize, vcols, ring, out);
        drop_empty_pieces(out);
        *need = out->n;
    }
    return DGGS_OK;
}

dggs_error dggs_grid_pieces(const double *hlat, const double *hlng, int64_t hrows, int64_t hcols, const double *vlat,
                            const double *vlng, int64_t vrows, int64_t vcols, int64_t k, const uint8_t *valid,
                            int64_t rows, int64_t cols, int target, dggs_pieces *out, double *coarse, void *work,
                            int64_t work_words, int64_t *resume, int64_t *need) {
    return dggs_grid_pieces_arcs(hlat, hlng, hrows, hcols, vlat, vlng, vrows, vcols, k, valid, rows, cols, target, false,
                                 out, coarse, work, work_words, resume, need);
}

/* ---- the public verbs (dggs.h, "raster pixels"): checked, over the functions above ---- */

static bool good_latlng(double lat, double lng) { return lat >= -90.0 && lat <= 90.0 && isfinite(lng); }

int64_t dggs_raster_pieces_work_words(int64_t rows, int64_t cols, int64_t k, int level) {
    if (rows < 0 || cols < 0 || k < 1 || level < 0 || level > DGGS_MAX_LEVEL) return 0;
    int64_t npts = (rows + 1) * (cols * k + 1) + (k > 1 ? (rows * k + 1) * (cols + 1) : 0);
    return dggs_grid_pieces_work_words(npts, k, level);
}

static dggs_error raster_pieces(const double *hlat, const double *hlng, const double *vlat, const double *vlng,
                                int64_t rows, int64_t cols, int64_t k, const uint8_t *valid, int level, bool arcs,
                                dggs_pieces *out, double *coarse, void *work, int64_t work_words, int64_t *resume,
                                int64_t *need) {
    if (level < 0 || level > DGGS_MAX_LEVEL) return DGGS_E_LEVEL;
    if (k < 1 || rows < 0 || cols < 0) return DGGS_E_DOMAIN;
    int64_t hsize = (rows + 1) * (cols * k + 1), vsize = k > 1 ? (rows * k + 1) * (cols + 1) : 0;
    for (int64_t i = 0; i < hsize; i++) {
        if (!good_latlng(hlat[i], hlng[i])) return DGGS_E_LATLNG;
    }
    for (int64_t i = 0; i < vsize; i++) {
        if (!good_latlng(vlat[i], vlng[i])) return DGGS_E_LATLNG;
    }
    if (work_words < dggs_raster_pieces_work_words(rows, cols, k, level)) return DGGS_E_BUFFER;
    if (*resume == 0) out->n = 0;
    return dggs_grid_pieces_arcs(hlat, hlng, rows + 1, cols * k + 1, vlat, vlng, rows * k + 1, cols + 1, k, valid,
                                 rows, cols, level, arcs, out, coarse, work, work_words, resume, need);
}

dggs_error dggs_raster_pieces(const double *hlat, const double *hlng, const double *vlat, const double *vlng,
                              int64_t rows, int64_t cols, int64_t k, const uint8_t *valid, int level,
                              dggs_pieces *out, double *coarse, void *work, int64_t work_words, int64_t *resume,
                              int64_t *need) {
    return raster_pieces(hlat, hlng, vlat, vlng, rows, cols, k, valid, level, false, out, coarse, work, work_words,
                         resume, need);
}

dggs_error dggs_raster_pieces_arcs(const double *hlat, const double *hlng, const double *vlat, const double *vlng,
                                   int64_t rows, int64_t cols, int64_t k, const uint8_t *valid, int level,
                                   dggs_pieces *out, double *coarse, void *work, int64_t work_words,
                                   int64_t *resume, int64_t *need) {
    return raster_pieces(hlat, hlng, vlat, vlng, rows, cols, k, valid, level, true, out, coarse, work, work_words,
                         resume, need);
}

dggs_error dggs_pixel_chord_error(const double *lat, const double *lng, double *out) {
    for (int j = 0; j < 16; j++) {
        if (!good_latlng(lat[j], lng[j])) return DGGS_E_LATLNG;
    }
    *out = dggs_chord_error(lat, lng);
    return DGGS_OK;
}

