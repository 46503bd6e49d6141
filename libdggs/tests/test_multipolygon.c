/* multipolygon.c (dggs_cells_to_multi_polygon): against dggs.cells_to_polygons(cells, densify=0) of the Python
 * package (shapely; the values below printed by it: polygons, holes, area in square degrees). */
#include <math.h>

#include "check.h"
#include "dggs.h"

typedef struct {
    int64_t polygons, holes;
    double area;
} shape_t;

/* The dissolve of the string ids `names` at densify 0: polygons, holes, planar area (shells less holes). */
static shape_t dissolve(const char *const *names, size_t n) {
    dggs_cell cells[64];
    shape_t s = {-1, -1, 0.0};
    for (size_t i = 0; i < n; i++) CHECK(dggs_string_to_cell(names[i], &cells[i]) == DGGS_OK);
    int64_t np, nr, npo, gp, gr, gpo;
    CHECK(dggs_cells_to_multi_polygon_size(cells, n, 0, DGGS_ISEA, &np, &nr, &npo) == DGGS_OK);
    double *xy = malloc((size_t)(np ? np : 1) * 2 * sizeof(double));
    int64_t *rings = malloc((size_t)(nr ? nr : 1) * sizeof(int64_t)), *polys = malloc((size_t)(npo ? npo : 1) * sizeof(int64_t));
    if (np > 0) /* a short buffer: DGGS_E_BUFFER and the sizes to call again with */
        CHECK(dggs_cells_to_multi_polygon(cells, n, 0, DGGS_ISEA, xy, np - 1, rings, nr, polys, npo, &gp, &gr, &gpo) ==
                  DGGS_E_BUFFER &&
              gp == np && gr == nr && gpo == npo);
    CHECK(dggs_cells_to_multi_polygon(cells, n, 0, DGGS_ISEA, xy, np, rings, nr, polys, npo, &gp, &gr, &gpo) == DGGS_OK);
    CHECK(gp == np && gr == nr && gpo == npo);
    s.polygons = npo, s.holes = nr - npo;
    const double *p = xy;
    for (int64_t q = 0, r = 0; q < npo; q++)
        for (int64_t k = 0; k < polys[q]; k++, r++) {
            double a = 0.0;
            for (int64_t i = 0; i < rings[r]; i++) {
                int64_t j = (i + 1) % rings[r];
                a += p[2 * i] * p[2 * j + 1] - p[2 * j] * p[2 * i + 1];
            }
            CHECK(k == 0 ? a > 0.0 : a < 0.0); /* shells counter-clockwise, holes clockwise */
            s.area += a / 2.0;
            p += 2 * rings[r];
        }
    free(xy), free(rings), free(polys);
    return s;
}

int main(void) {
    static const char *const face_a[] = {"A"};
    shape_t s = dissolve(face_a, 1); /* round the North Pole, closed along it: as dggs_cell_to_polygon */
    CHECK(s.polygons == 1 && s.holes == 0 && fabs(s.area - 8079.344554609) < 1e-6);
    static const char *const faces[] = {"A", "B", "C", "D", "E", "F", "G", "H", "I", "J",
                                        "K", "L", "M", "N", "O", "P", "Q", "R", "S", "T"};
    s = dissolve(faces, 20); /* the whole sphere: the window */
    CHECK(s.polygons == 1 && s.holes == 0 && s.area == 64800.0);
    static const char *const frame[] = {"C4000", "C4001", "C4011", "C4012", "C4020", "C4021", "C411",
                                        "C4120", "C5000", "C5001", "C5010", "C5011", "C5020", "C5021"};
    s = dissolve(frame, 14); /* two levels round a hole */
    CHECK(s.polygons == 1 && s.holes == 1 && fabs(s.area - 227.13669942249774) < 1e-9);
    static const char *const across[] = {"O32022", "O32121", "O32122", "T22122"};
    s = dissolve(across, 4); /* across the antimeridian: cut in two */
    CHECK(s.polygons == 2 && s.holes == 0 && fabs(s.area - 17.058183796421506) < 1e-9);
    static const char *const pole[] = {"A400", "A500", "A501", "E000"};
    s = dissolve(pole, 4); /* round the North Pole */
    CHECK(s.polygons == 1 && s.holes == 0 && fabs(s.area - 2563.0648031807514) < 1e-9);
    s = dissolve(faces, 0); /* no cells, no polygon */
    CHECK(s.polygons == 0 && s.holes == 0);
    /* invalid input */
    dggs_cell bad[2] = {0x4000000000000000ULL, 0};
    int64_t a, b, c;
    CHECK(dggs_cells_to_multi_polygon_size(bad, 2, 0, DGGS_ISEA, &a, &b, &c) == DGGS_E_CELL);
    CHECK(dggs_cells_to_multi_polygon_size(bad, 1, -2, DGGS_ISEA, &a, &b, &c) == DGGS_E_DOMAIN);
    CHECK(dggs_cells_to_multi_polygon_size(bad, 1, DGGS_MAX_DENSIFY + 1, DGGS_ISEA, &a, &b, &c) == DGGS_E_DOMAIN);
    CHECK(dggs_cells_to_multi_polygon_size(bad, 1, 0, (dggs_projection)7, &a, &b, &c) == DGGS_E_PROJECTION);
    return check_failures ? 1 : 0;
}
