/* Cell corners (vertices) and their ids: index/_corners.py's walk round a corner in C (dggs.h, "vertices").
 *
 * The cells round a corner are found by walking round it: from a cell, cross one of the two edges that end at the
 * corner, then, in the new cell, cross the other edge that ends there, until the walk is back. The corner is
 * recognised in each cell as the nearest of its three corners (unit vectors of the corners of
 * dggs_cell_to_boundary), so the walk follows the grid's edge adjacency (dggs_neighbours) and needs no tolerance.
 * A vertex is named by the smallest cell round it and its corner index there. */
#include <math.h>

#include "dggs.h"
#include "grid.h"
#include "tables.h"

/* _corners.MAX_FAN: most cells round one corner. */
#define MAX_FAN 12

/* _corners.corners_xyz: the unit vectors of a valid cell's three corners (ISEA's; the ids are the same on IVEA). */
static void corners_xyz(dggs_cell cell, double xyz[3][3]) {
    double b[6];
    size_t count;
    dggs_cell_to_boundary(cell, 0, DGGS_ISEA, b, 3, &count);
    for (int i = 0; i < 3; i++) {
        double lat = b[2 * i] * DGGS_RAD_PER_DEG, lng = b[2 * i + 1] * DGGS_RAD_PER_DEG;
        xyz[i][0] = cos(lat) * cos(lng);
        xyz[i][1] = cos(lat) * sin(lng);
        xyz[i][2] = sin(lat);
    }
}

/* The corner of `xyz` nearest v (the first of equals, as numpy's argmin). */
static int nearest(double xyz[3][3], const double v[3]) {
    int best = 0;
    double best_d = INFINITY;
    for (int i = 0; i < 3; i++) {
        double dx = xyz[i][0] - v[0], dy = xyz[i][1] - v[1], dz = xyz[i][2] - v[2];
        double d = dx * dx + dy * dy + dz * dz;
        if (d < best_d) best = i, best_d = d;
    }
    return best;
}

/* _corners.vertex_keys for one corner: the smallest cell round corner `corner` of a valid cell, and the corner's
 * index in it. DGGS_E_FAILED if the walk does not close (a broken grid: never for valid ids). */
static dggs_error vertex_key(dggs_cell cell, int corner, dggs_cell *owner, int *index) {
    double xyz[3][3], v[3];
    corners_xyz(cell, xyz);
    v[0] = xyz[corner][0], v[1] = xyz[corner][1], v[2] = xyz[corner][2];
    dggs_cell cur = cell, low = cell, nb[3], next[3];
    int edge = corner; /* edge i runs from corner i to corner i + 1 */
    for (int step = 1; step <= MAX_FAN; step++) {
        dggs_neighbours(cur, nb);
        dggs_cell nxt = nb[edge];
        if (nxt == cell) {
            corners_xyz(low, xyz);
            *owner = low;
            *index = nearest(xyz, v);
            return DGGS_OK;
        }
        if (nxt < low) low = nxt;
        corners_xyz(nxt, xyz);
        int m = nearest(xyz, v);
        dggs_neighbours(nxt, next);
        edge = next[m] == cur ? (m + 2) % 3 : m;
        cur = nxt;
    }
    return DGGS_E_FAILED;
}

dggs_error dggs_cell_to_vertexes(dggs_cell cell, dggs_cell owners[3], int index[3]) {
    if (!dggs_is_valid_cell(cell)) return DGGS_E_CELL;
    for (int i = 0; i < 3; i++) {
        dggs_error err = vertex_key(cell, i, &owners[i], &index[i]);
        if (err != DGGS_OK) return err;
    }
    return DGGS_OK;
}

int dggs_is_valid_vertex(dggs_cell owner, int index) {
    dggs_cell o;
    int i;
    if (!dggs_is_valid_cell(owner) || index < 0 || index > 2) return 0;
    return vertex_key(owner, index, &o, &i) == DGGS_OK && o == owner && i == index;
}

dggs_error dggs_vertex_to_latlng(dggs_cell owner, int index, dggs_projection proj, double *lat, double *lng) {
    if (!dggs_is_valid_vertex(owner, index)) return DGGS_E_CELL;
    double b[6];
    size_t count;
    dggs_error err = dggs_cell_to_boundary(owner, 0, proj, b, 3, &count);
    if (err != DGGS_OK) return err;
    *lat = b[2 * index];
    *lng = b[2 * index + 1];
    return DGGS_OK;
}
