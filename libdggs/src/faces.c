/* Which face and which 120-degree sector of it a point falls in: the two choices Snyder's (ISEA, geometry.c) and
 * the IVEA projection (ivea.c) both make before projecting, kept below both. See faces.h. */
#include "faces.h"

#include "dggs.h"
#include "tables.h"

/* kernel.nearest_face: the face whose centre is nearest; near-ties go to the lower face (icosahedron.face_of). */
int dggs_nearest_face(const double *centres, double px, double py, double pz) {
    int best = 0;
    double best_dot = -4.0;
    for (int f = 0; f < DGGS_NUM_FACES; f++) {
        const double *c = centres + 3 * f;
        double d = px * c[0] + py * c[1] + pz * c[2] + dggs_tie_bias[f];
        if (d > best_dot) {
            best_dot = d;
            best = f;
        }
    }
    return best;
}

/* kernel.sector_of: 120-degree sector (planar azimuth // 120, clockwise from +y) by half-planes. */
int dggs_sector_of(double x, double y) {
    if (x > 0.0 || (x == 0.0 && y >= 0.0)) { /* azimuth in [0, 180] */
        if (x == 0.0 && y == 0.0) return 0;
        return -0.5 * x - DGGS_HALF_SQRT3 * y >= 0.0 ? 1 : 0; /* azimuth >= 120 */
    }
    return -0.5 * x + DGGS_HALF_SQRT3 * y >= 0.0 ? 2 : 1; /* azimuth >= 240 */
}
