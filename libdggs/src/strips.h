/* Grid distances at any range over the straight face strips (a port of index/_kernel/strips.py).
 *
 * Unfold a chain of icosahedron faces f0 = face(a), ..., fm = face(b) (each across an edge of the one before)
 * into a's face frame: the level's six families of mirror lines extend over the plane, and if the straight
 * segment between the centroids runs through exactly those faces, the count of lines separating them is the
 * length of a real path. The least over the simple chains of at most DGGS_MAX_STRIP face edges is the distance
 * (checked against breadth-first search; see the Python module's doc). */
#ifndef DGGS_STRIPS_H
#define DGGS_STRIPS_H

#include <stdbool.h>
#include <stdint.h>

/* MAX_STRIP: most face edges a searched strip crosses. */
#define DGGS_MAX_STRIP 6

/* _straight: whether the segment p -> b crosses edges 1..m (rows of `edges`: x0, y0, x1, y1) in order, inside
 * each (away from the ends by 1e-9 of the edge). */
bool dggs_strip_straight(double px, double py, double bx, double by, const double (*edges)[4], int m);
/* strip_distance: the fewest separating lines over the straight face strips from a to b (level >= 1), or -1 if
 * none. Allocates nothing (fixed arrays of DGGS_MAX_STRIP + 1 rows on the stack). */
int64_t dggs_strip_distance(uint64_t a, uint64_t b, int level);

#endif
