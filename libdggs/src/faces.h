/* The face a point falls in and the 120-degree sector of a face plane a planar point falls in: chosen the same way
 * by Snyder's projection (geometry.c) and IVEA (ivea.c), so both use these. Pure functions: thread-safe. */
#ifndef DGGS_FACES_H
#define DGGS_FACES_H

/* The face (0..19) whose centre is nearest the unit vector (px, py, pz); `centres` is (20, 3), row-major. */
int dggs_nearest_face(const double *centres, double px, double py, double pz);
/* The 120-degree sector (0..2) of a face plane holding (x, y): planar azimuth // 120, clockwise from +y. */
int dggs_sector_of(double x, double y);

#endif
