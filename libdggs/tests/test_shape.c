/* shape.c (dggs_cell_to_polygon) and vertex.c (vertices): against dggs.cell_to_polygon and dggs.cell_to_vertexes
 * of the Python package (the values below printed by it: part sizes, shoelace areas in square degrees, names). */
#include <math.h>

#include "check.h"
#include "dggs.h"

/* The parts of cell's polygon at densify 0: their count, the points of each, the sum of their areas. */
static int parts_of(dggs_cell cell, size_t sizes[DGGS_MAX_POLYGON_PARTS], double *area) {
    size_t room;
    CHECK(dggs_cell_to_polygon_size(0, &room) == DGGS_OK);
    double *xy = malloc(2 * room * sizeof(double));
    int parts = -1;
    CHECK(dggs_cell_to_polygon(cell, 0, DGGS_ISEA, xy, room - 1, sizes, &parts) == DGGS_E_BUFFER);
    CHECK(dggs_cell_to_polygon(cell, 0, DGGS_ISEA, xy, room, sizes, &parts) == DGGS_OK);
    const double *p = xy;
    *area = 0.0;
    for (int k = 0; k < parts; k++) {
        double a = 0.0;
        for (size_t i = 0; i < sizes[k]; i++) {
            size_t j = (i + 1) % sizes[k];
            a += p[2 * i] * p[2 * j + 1] - p[2 * j] * p[2 * i + 1];
        }
        CHECK(a > 0.0); /* counter-clockwise */
        *area += a / 2.0;
        p += 2 * sizes[k];
    }
    free(xy);
    return parts;
}

static void check_polygons(void) {
    size_t sizes[DGGS_MAX_POLYGON_PARTS];
    double area;
    CHECK(parts_of(0x4000000000000000ULL, sizes, &area) == 1); /* face A: round the North Pole, closed along it */
    CHECK(sizes[0] == 5 && fabs(area - 8079.344554609) < 1e-6);
    CHECK(parts_of(6718244284568436736ULL, sizes, &area) == 2); /* O321222221000: across the antimeridian */
    CHECK(sizes[0] == 4 && sizes[1] == 4 && fabs(area - 0.001949233) < 1e-9);
    size_t room;
    int parts;
    double xy[8];
    CHECK(dggs_cell_to_polygon_size(-1, &room) == DGGS_E_DOMAIN);
    CHECK(dggs_cell_to_polygon(12345, 0, DGGS_ISEA, xy, 4, sizes, &parts) == DGGS_E_CELL);
    CHECK(dggs_cell_to_polygon(0x4000000000000000ULL, 0, (dggs_projection)7, xy, 4, sizes, &parts) ==
          DGGS_E_PROJECTION);
}

static void check_vertices(void) {
    dggs_cell owners[3];
    int index[3];
    /* dggs.cell_to_vertexes("C401") == ['B100:0', 'C401:1', 'C400:1'] */
    CHECK(dggs_cell_to_vertexes(4996743786567565312ULL, owners, index) == DGGS_OK);
    CHECK_EQ_U64(owners[0], 4797459503056420864ULL);
    CHECK_EQ_U64(owners[1], 4996743786567565312ULL);
    CHECK_EQ_U64(owners[2], 4995617886660722688ULL);
    CHECK(index[0] == 0 && index[1] == 1 && index[2] == 1);
    CHECK(dggs_is_valid_vertex(4996743786567565312ULL, 1) && !dggs_is_valid_vertex(4996743786567565312ULL, 0));
    CHECK(!dggs_is_valid_vertex(4996743786567565312ULL, 3) && !dggs_is_valid_vertex(12345, 0));
    double lat, lng;
    CHECK(dggs_vertex_to_latlng(4996743786567565312ULL, 1, DGGS_ISEA, &lat, &lng) == DGGS_OK);
    CHECK(fabs(lat - 20.91287) < 1e-6 && fabs(lng + 1.220765) < 1e-6); /* vertex_to_latlng("C401:1") */
    CHECK(dggs_vertex_to_latlng(4996743786567565312ULL, 0, DGGS_ISEA, &lat, &lng) == DGGS_E_CELL);
    CHECK(dggs_cell_to_vertexes(12345, owners, index) == DGGS_E_CELL);
}

int main(void) {
    check_polygons();
    check_vertices();
    CHECK_DONE();
}
