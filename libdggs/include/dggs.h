/* libdggs: an equal-area triangular discrete global grid (Split (2:6) on the icosahedron, Snyder's equal-area
 * polyhedral projection on the WGS84 authalic sphere). The one public header.
 *
 * Conventions, as H3's:
 * - Cells are 64-bit integer ids (dggs_cell); 0 is the null id and never a cell. String ids ("C401") are a
 *   face letter A-T, a level-1 digit 0-5 and one digit 0-2 per further level (dggs_cell_to_string).
 * - Coordinates are WGS84 geodetic degrees, latitude first, unless a function says otherwise.
 * - Every function that can fail returns a dggs_error (DGGS_OK is 0); outputs go to buffers the caller
 *   allocates, whose size the caller asks first from the matching *_size / *_max function.
 * - No global mutable state: every function is thread-safe and re-entrant; nothing allocates unless it says so.
 */
#ifndef DGGS_H
#define DGGS_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* A cell id (see docs/grid.md, "Integer ids"). */
typedef uint64_t dggs_cell;

/* The deepest level (0.56 m^2 cells). */
#define DGGS_MAX_LEVEL 28
/* The number of icosahedron faces, the level-0 cells. */
#define DGGS_NUM_FACES 20
/* Longest string id, without the terminating NUL: a face letter and DGGS_MAX_LEVEL digits. */
#define DGGS_MAX_CHARS 29

/* The projection between the sphere and the faces: Snyder's (ISEA, the default) or van Leeuwen and Strebe's
 * vertex-oriented great circle projection (IVEA). Both equal-area; the ids and planar cells are the same. */
typedef enum { DGGS_ISEA = 0, DGGS_IVEA = 1 } dggs_projection;

/* Error codes. */
typedef enum {
    DGGS_OK = 0,
    DGGS_E_LATLNG = 1,     /* a latitude outside -90..90 or a coordinate that is not finite */
    DGGS_E_LEVEL = 2,      /* a level outside 0..DGGS_MAX_LEVEL */
    DGGS_E_CELL = 3,       /* not a cell id (or not a valid string id) */
    DGGS_E_LEVEL_MISMATCH = 4, /* a cell coarser or finer than the level asked for */
    DGGS_E_BUFFER = 5,     /* an output buffer smaller than the size asked first */
    DGGS_E_DOMAIN = 6,     /* an argument out of its domain (a negative k, densify, ...) */
    DGGS_E_FAILED = 7,     /* the operation could not complete (a search limit reached, ...) */
    DGGS_E_PROJECTION = 8, /* not a dggs_projection */
    DGGS_E_EDGE = 9,       /* not a directed edge id */
    DGGS_E_VERTEX = 10     /* not a vertex id */
} dggs_error;

/* A short English description of an error code (a static string). */
const char *dggs_error_string(dggs_error err);

/* ---- ids and strings (codec.c) ---------------------------------------------------------------- */

/* ---- end ids and strings ---- */



/* ---- projection (geometry.c, ivea.c) ---------------------------------------------------------- */

/* Geodetic WGS84 (lat, lng) degrees -> the face (0..19) holding the point and its (x, y) in that face's
 * frame (origin at the face centre, +y towards the face's vertex 0, on the unit authalic sphere: multiply by
 * the authalic radius, 6371007.1809 m, for metres), by `proj` (Snyder's ISEA or IVEA) in PROJ's ISEA
 * orientation; the grid's own point location (the authalic latitude by kernel.authalic_sincos). Longitudes
 * wrap. Errors: DGGS_E_LATLNG (a latitude outside -90..90 or a coordinate that is not finite),
 * DGGS_E_PROJECTION (not a dggs_projection); outputs are untouched on error. */
dggs_error dggs_geo_to_face(double lat, double lng, dggs_projection proj, int *face, double *x, double *y);

/* Face (0..19) and face-frame (x, y) on the unit authalic sphere -> geodetic WGS84 (lat, lng) degrees, longitude
 * in -180..180, by `proj`'s closed-form inverse. Errors: DGGS_E_DOMAIN (a face outside 0..19, or a point off
 * its face triangle by more than 1e-9 of the inradius, as dggs.geometry.snyder.inverse),
 * DGGS_E_LATLNG (x or y not finite), DGGS_E_PROJECTION; outputs are untouched on error. */
dggs_error dggs_face_to_geo(int face, double x, double y, dggs_projection proj, double *lat, double *lng);

/* ---- end projection ---- */



/* ---- points, centres, boundaries (points.c) --------------------------------------------------- */

/* ---- end points ---- */



/* ---- hierarchy and compaction (hierarchy.c, compact.c) ---------------------------------------- */

/* ---- end hierarchy ---- */



/* ---- neighbours, disks, rings, distances, paths (grid.c, distance.c, paths.c) ----------------- */

/* ---- end grid ---- */



/* ---- polygon fill (polygon.c, fill.c) ------------------------------------------------------------ */

/* ---- end fill ---- */



/* ---- lines (line_trace.c) ---------------------------------------------------------------------- */

/* ---- end lines ---- */



/* ---- dissolve (dissolve.c) --------------------------------------------------------------------- */

/* ---- end dissolve ---- */



/* ---- local (i, j), child positions, directed edges, vertices (local.c, edges.c) ---------------- */

/* ---- end local ---- */



/* ---- raster pixels (clip.c, pixels.c) ---------------------------------------------------------- */

/* ---- end pixels ---- */

#ifdef __cplusplus
}
#endif

#endif /* DGGS_H */
