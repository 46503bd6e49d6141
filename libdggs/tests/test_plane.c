/* pixels_plane.c: rings cut against a raster's rows and columns in its own plane. Areas and centroids worked out by
 * hand (squares, triangles, a ring partly off the grid, both orientations), the valid mask, the buffer-growing
 * resume giving the same pieces, and the public API's errors. */
#include <math.h>

#include "check.h"
#include "dggs.h"

#define CAP 64

typedef struct {
    int64_t pixel[CAP];
    uint64_t cell[CAP];
    double area[CAP], cu[CAP], cv[CAP];
    double work[5 * 16 * 16];
    dggs_plane_pieces_out out;
} pieces_t;

static dggs_error cut(pieces_t *p, const double *x, const double *y, const int64_t *start, const uint64_t *cells,
                      int64_t rings, int64_t rows, int64_t cols, const uint8_t *valid, int64_t cap) {
    p->out.pixel = p->pixel, p->out.cell = p->cell, p->out.area = p->area, p->out.cu = p->cu, p->out.cv = p->cv;
    p->out.cap = cap, p->out.n = 0;
    int64_t resume = 0, need = 0;
    return dggs_plane_pieces(x, y, start, cells, rings, rows, cols, valid, &p->out, p->work,
                             dggs_plane_pieces_work_words(rows, cols), &resume, &need);
}

static double area_of(const pieces_t *p, int64_t pixel, uint64_t cell, int64_t *at) {
    double a = 0.0;
    for (int64_t i = 0; i < p->out.n; i++) {
        if (p->pixel[i] == pixel && p->cell[i] == cell) a += p->area[i], *at = i;
    }
    return a;
}

#define NEAR(a, b) (fabs((a) - (b)) < 1e-12)

static void squares_and_triangles(void) {
    static const uint8_t all[9] = {1, 1, 1, 1, 1, 1, 1, 1, 1};
    static pieces_t p;
    int64_t at = -1;
    /* pixel (1, 1) of a 3 x 3 grid exactly, clockwise and counter-clockwise: one piece, its centroid the middle */
    const double sx[4] = {1, 2, 2, 1}, sy[4] = {1, 1, 2, 2}, rx[4] = {1, 1, 2, 2}, ry[4] = {1, 2, 2, 1};
    const int64_t one[2] = {0, 4};
    const uint64_t c7 = 7;
    for (int turn = 0; turn < 2; turn++) {
        CHECK(cut(&p, turn ? rx : sx, turn ? ry : sy, one, &c7, 1, 3, 3, all, CAP) == DGGS_OK);
        CHECK(p.out.n == 1 && p.pixel[0] == 4 && p.cell[0] == 7 && NEAR(p.area[0], 1.0));
        CHECK(NEAR(p.cu[0], 0.5) && NEAR(p.cv[0], 0.5));
    }
    /* the triangle (0, 0), (2, 0), (0, 2) on a 2 x 2 grid: pixel 0 whole, pixels 1 and 2 halves (centroids a third
     * in from their corner at the grid's origin side), pixel 3 nothing */
    const double tx[3] = {0, 2, 0}, ty[3] = {0, 0, 2};
    const int64_t three[2] = {0, 3};
    CHECK(cut(&p, tx, ty, three, &c7, 1, 2, 2, all, CAP) == DGGS_OK);
    CHECK(p.out.n == 3);
    CHECK(NEAR(area_of(&p, 0, 7, &at), 1.0));
    CHECK(NEAR(area_of(&p, 1, 7, &at), 0.5) && NEAR(p.cu[at], 1.0 / 3.0) && NEAR(p.cv[at], 1.0 / 3.0));
    CHECK(NEAR(area_of(&p, 2, 7, &at), 0.5) && NEAR(p.cu[at], 1.0 / 3.0) && NEAR(p.cv[at], 1.0 / 3.0));
    CHECK(area_of(&p, 3, 7, &at) == 0.0);
    /* a square (-1, -1)..(1.5, 1) partly off a 2 x 2 grid: pixel 0 whole, pixel 1 its left half (centroid u 1/4) */
    const double ox[4] = {-1, 1.5, 1.5, -1}, oy[4] = {-1, -1, 1, 1};
    const int64_t four[2] = {0, 4};
    CHECK(cut(&p, ox, oy, four, &c7, 1, 2, 2, all, CAP) == DGGS_OK);
    CHECK(p.out.n == 2 && NEAR(area_of(&p, 0, 7, &at), 1.0) && NEAR(area_of(&p, 1, 7, &at), 0.5));
    CHECK(NEAR(p.cu[at], 0.25) && NEAR(p.cv[at], 0.5));
    /* a diamond over the middle of a 2 x 2 grid, (1, 0), (2, 1), (1, 2), (0, 1): half of each pixel */
    const double dx[4] = {1, 2, 1, 0}, dy[4] = {0, 1, 2, 1};
    CHECK(cut(&p, dx, dy, four, &c7, 1, 2, 2, all, CAP) == DGGS_OK);
    CHECK(p.out.n == 4);
    for (int64_t k = 0; k < 4; k++) CHECK(NEAR(area_of(&p, k, 7, &at), 0.5));
    /* a triangle inside pixel (1, 1) of a 3 x 3 grid: its area (half the cross product) and centroid (the mean of
     * its corners, less the pixel's corner), in both orientations */
    const double ix[3] = {1.2, 1.8, 1.4}, iy[3] = {1.2, 1.3, 1.9}, jx[3] = {1.4, 1.8, 1.2}, jy[3] = {1.9, 1.3, 1.2};
    const double half_cross = 0.5 * ((1.8 - 1.2) * (1.9 - 1.2) - (1.4 - 1.2) * (1.3 - 1.2));
    for (int turn = 0; turn < 2; turn++) {
        CHECK(cut(&p, turn ? jx : ix, turn ? jy : iy, three, &c7, 1, 3, 3, all, CAP) == DGGS_OK);
        CHECK(p.out.n == 1 && p.pixel[0] == 4 && NEAR(p.area[0], half_cross));
        CHECK(NEAR(p.cu[0], (0.2 + 0.8 + 0.4) / 3.0) && NEAR(p.cv[0], (0.2 + 0.3 + 0.9) / 3.0));
    }
    /* no piece where a pixel has no data */
    const uint8_t some[4] = {1, 0, 1, 1};
    CHECK(cut(&p, dx, dy, four, &c7, 1, 2, 2, some, CAP) == DGGS_OK);
    CHECK(p.out.n == 3 && area_of(&p, 1, 7, &at) == 0.0);
}

/* Rings sharing their edges share each pixel's area: a 4 x 4 grid tiled by 8 triangles over a skewed lattice. */
static void tiling_and_resume(void) {
    static const uint8_t all[16] = {1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1};
    double x[24], y[24];
    int64_t start[9];
    uint64_t cells[8];
    const double gx[3][3] = {{-0.5, 2.3, 4.5}, {-0.5, 1.7, 4.5}, {-0.5, 2.6, 4.5}};
    const double gy[3] = {-0.5, 1.9, 4.5};
    int64_t n = 0, k = 0;
    for (int i = 0; i < 2; i++) {
        for (int j = 0; j < 2; j++) {
            double ax = gx[i][j], ay = gy[i], bx = gx[i][j + 1], by = gy[i], cx = gx[i + 1][j + 1], cy = gy[i + 1];
            double ex = gx[i + 1][j], ey = gy[i + 1];
            start[k] = n, cells[k] = (uint64_t)k, k++;
            x[n] = ax, y[n++] = ay, x[n] = bx, y[n++] = by, x[n] = cx, y[n++] = cy;
            start[k] = n, cells[k] = (uint64_t)k, k++;
            x[n] = ax, y[n++] = ay, x[n] = ex, y[n++] = ey, x[n] = cx, y[n++] = cy; /* the other way round */
        }
    }
    start[k] = n;
    static pieces_t p, q;
    CHECK(cut(&p, x, y, start, cells, 8, 4, 4, all, CAP) == DGGS_OK);
    double sum[16] = {0};
    for (int64_t i = 0; i < p.out.n; i++) {
        sum[p.pixel[i]] += p.area[i];
        CHECK(p.area[i] > 0.0 && p.cu[i] >= 0.0 && p.cu[i] <= 1.0 && p.cv[i] >= 0.0 && p.cv[i] <= 1.0);
    }
    for (int i = 0; i < 16; i++) CHECK(fabs(sum[i] - 1.0) < 1e-13);
    /* resumed through a buffer of 3 pieces, grown as asked: the same pieces */
    q.out.pixel = q.pixel, q.out.cell = q.cell, q.out.area = q.area, q.out.cu = q.cu, q.out.cv = q.cv, q.out.n = 0;
    int64_t resume = 0, need = 0, cap = 3;
    dggs_error err;
    int rounds = 0;
    while ((err = dggs_plane_pieces(x, y, start, cells, 8, 4, 4, all, &q.out, q.work,
                                    dggs_plane_pieces_work_words(4, 4), &resume, &need)) == DGGS_E_BUFFER) {
        CHECK(need > q.out.n && need <= CAP);
        q.out.cap = cap = need;
        rounds++;
    }
    q.out.cap = cap;
    CHECK(err == DGGS_OK && rounds > 0 && q.out.n == p.out.n);
    for (int64_t i = 0; i < p.out.n; i++) {
        CHECK(q.pixel[i] == p.pixel[i] && q.cell[i] == p.cell[i]);
        CHECK_SAME_DOUBLE(q.area[i], p.area[i]);
    }
}

static void errors(void) {
    static pieces_t p;
    const uint8_t all[4] = {1, 1, 1, 1};
    const double x[3] = {0, 2, 0}, y[3] = {0, 0, 2}, bad[3] = {0, NAN, 0};
    const int64_t start[2] = {0, 3}, backwards[2] = {3, 0};
    const uint64_t c = 1;
    int64_t resume = 0, need = 0;
    CHECK(dggs_plane_pieces_work_words(0, 3) == 0);
    CHECK(cut(&p, x, y, start, &c, 1, 0, 2, all, CAP) == DGGS_E_DOMAIN);
    CHECK(cut(&p, x, bad, start, &c, 1, 2, 2, all, CAP) == DGGS_E_DOMAIN);
    CHECK(cut(&p, x, y, backwards, &c, 1, 2, 2, all, CAP) == DGGS_E_DOMAIN);
    p.out.n = 0, p.out.cap = CAP;
    CHECK(dggs_plane_pieces(x, y, start, &c, 1, 2, 2, all, &p.out, p.work, 3, &resume, &need) == DGGS_E_BUFFER);
    CHECK(cut(&p, x, y, start, &c, 0, 2, 2, all, CAP) == DGGS_OK && p.out.n == 0); /* no rings, no pieces */
}

int main(void) {
    squares_and_triangles();
    tiling_and_resume();
    errors();
    CHECK_DONE();
}
