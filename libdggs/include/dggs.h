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

/* A geodesic solver on the WGS84 ellipsoid, which dggs_line_to_cells calls for each segment (the inverse
 * problem) and for points along it (the direct problem). The signatures are GeographicLib's C library's
 * (PROJ's geodesic.h: geod_inverse and geod_direct, with `const struct geod_geodesic *` for `const void *`):
 * wrap those, on geod_init(&g, 6378137, 1 / 298.257223563), and the cells equal the Python package's
 * line_to_cells (which calls them through pyproj.Geod) bit for bit. Azimuths are degrees clockwise from
 * north; both azi2 are the forward azimuth at the second point (GeographicLib's, not pyproj's back azimuth). */
typedef struct {
    /* The inverse problem: *s12 metres from (lat1, lng1) to (lat2, lng2) (degrees) along the geodesic, the
     * azimuths *azi1 at the start and *azi2 at the end. */
    void (*inverse)(const void *geod, double lat1, double lng1, double lat2, double lng2, double *s12, double *azi1,
                    double *azi2);
    /* The direct problem: the point (*lat2, *lng2) s12 metres from (lat1, lng1) along the geodesic leaving at
     * azimuth azi1, and the azimuth *azi2 there. */
    void (*direct)(const void *geod, double lat1, double lng1, double azi1, double s12, double *lat2, double *lng2,
                   double *azi2);
    /* Passed first to both (GeographicLib's struct geod_geodesic *). */
    const void *geod;
} dggs_geodesic;

/* The sizes dggs_line_to_cells needs for the polyline of n points latlng (row-major (lat, lng) degrees, 2n
 * doubles) at `level`: *work_size, the bytes of its work buffer (exact), and *max_cells, an estimate of the
 * cells (3 per short edge of length plus 24 per segment and 16; it holds for every line the tests trace, but
 * is not proven: dggs_line_to_cells asks for more when it is short). Calls geod's inverse once per segment.
 * Errors: DGGS_E_LEVEL, DGGS_E_LATLNG (a point that is not a finite latitude in -90..90 and a finite
 * longitude), DGGS_E_DOMAIN (geod or one of its functions NULL). */
dggs_error dggs_line_to_cells_size(const double *latlng, size_t n, int level, const dggs_geodesic *geod,
                                   size_t *max_cells, size_t *work_size);

/* The cells of `level` along a polyline, in order; each segment is the WGS84 geodesic between its points
 * (the short way across the antimeridian), given by `geod`. The first cell holds the first point, the last
 * the last point, every cell meets the line, consecutive cells share an edge (a line within 0.1 mm of a
 * corner goes round it the shorter way) and none repeats in a row; a cell can come back later. Repeated
 * consecutive points add no segment; one point gives its cell (as dggs_latlng_to_cell), none no cells.
 * The tracer samples a cubic curve within 0.1 mm of each geodesic (1e-6 of the short edge from level 20)
 * every half short edge, between exact geodesic points at most 39 km apart, and bisects the gaps
 * (docs/features.md; dggs.line_to_cells is this function).
 *
 * Buffers: `work` (work_size bytes, aligned for double, as malloc gives) and `out` (room for `capacity`
 * cells), both from dggs_line_to_cells_size. Grow protocol: where `out` is too small this returns
 * DGGS_E_BUFFER with *count the capacity to call again with (the exact size where the tracer finished, else
 * twice `capacity`, at least the estimate); nothing else changes between the calls. Nothing is allocated.
 * On success *count is the number of cells written.
 * Errors: DGGS_E_LEVEL, DGGS_E_PROJECTION, DGGS_E_LATLNG (as dggs_line_to_cells_size), DGGS_E_DOMAIN (geod
 * or one of its functions NULL, or work NULL or smaller than asked), DGGS_E_BUFFER (above), DGGS_E_FAILED
 * (cells meeting only at a corner the grid's fans do not join, never seen; or a solver that gives different
 * answers for the same segment). */
dggs_error dggs_line_to_cells(const double *latlng, size_t n, int level, dggs_projection proj,
                              const dggs_geodesic *geod, void *work, size_t work_size, dggs_cell *out,
                              size_t capacity, size_t *count);

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
