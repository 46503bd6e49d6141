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

/* The three cells sharing an edge with `cell` (any level, 0 too), into out[0..2]: out[i] is the cell across the
 * edge from corner i to corner i + 1 of the cell's counter-clockwise corners (as edge_neighbors in Python).
 * Errors: DGGS_E_CELL. */
dggs_error dggs_edge_neighbors(dggs_cell cell, dggs_cell out[3]);

/* *out = 1 if cells a and b share an edge, else 0 (0 for cells of different levels and for a cell and itself).
 * Errors: DGGS_E_CELL (either is not a cell). */
dggs_error dggs_are_neighbor_cells(dggs_cell a, dggs_cell b, int *out);

/* The ids the buffer of dggs_grid_disk must hold for radius k (0 <= k <= 2^31) around a cell of `cell`'s level:
 * room for the largest disk there (the planar bound, or the whole level) and for the hash set the breadth-first
 * search works in (the least power of 2 >= 64 and >= twice that). Errors: DGGS_E_CELL, DGGS_E_DOMAIN (k). */
dggs_error dggs_grid_disk_size(dggs_cell cell, int64_t k, int64_t *size);
/* The cells within k edge steps of `cell` (the cell included), sorted ascending, into out[0..*count); the rest
 * of out[0..size) is set to 0 (it is the work space). `size` >= dggs_grid_disk_size(cell, k). Allocates nothing.
 * Errors: DGGS_E_CELL, DGGS_E_DOMAIN (k), DGGS_E_BUFFER (size too small). */
dggs_error dggs_grid_disk(dggs_cell cell, int64_t k, dggs_cell *out, int64_t size, int64_t *count);

/* The ids the buffer of dggs_grid_ring must hold for radius k (0 <= k <= 2^31) around a cell of `cell`'s level:
 * the largest ring there (w, the planar bound or the whole level) and the work space of three rings and their
 * candidates (6 max(w, 6)). Errors: DGGS_E_CELL, DGGS_E_DOMAIN (k). */
dggs_error dggs_grid_ring_size(dggs_cell cell, int64_t k, int64_t *size);
/* The cells exactly k edge steps from `cell`, sorted ascending, into out[0..*count) (an empty ring past the far
 * side of the level: *count = 0); the rest of out[0..size) is set to 0. `size` >= dggs_grid_ring_size(cell, k).
 * Allocates nothing. Errors: DGGS_E_CELL, DGGS_E_DOMAIN (k), DGGS_E_BUFFER (size too small). */
dggs_error dggs_grid_ring(dggs_cell cell, int64_t k, dggs_cell *out, int64_t size, int64_t *count);

/* The number of edge steps on a shortest path between cells a and b of one level: exact at any range, in
 * O(level) time (mirror lines of the level's planar arrangement over the straight face strips between them;
 * docs/grid.md, "Distances"). A pair no strip serves (none known) falls back on a breadth-first search within
 * 4096 steps, which allocates its work space (708 KB) with malloc and frees it. Errors: DGGS_E_CELL,
 * DGGS_E_LEVEL_MISMATCH, DGGS_E_FAILED (the fallback search found no path within 4096 steps, a ring of it
 * outgrew its work space, or malloc failed: none of them ever seen). */
dggs_error dggs_grid_distance(dggs_cell a, dggs_cell b, int64_t *out);

/* The cells on the shortest path from a to b (both included): dggs_grid_distance(a, b) + 1. Errors: as
 * dggs_grid_distance. */
dggs_error dggs_grid_path_cells_size(dggs_cell a, dggs_cell b, int64_t *size);
/* A shortest path of cells from a to b, both ends included, each an edge neighbour of the one before, into
 * out[0..n) (n = dggs_grid_path_cells_size(a, b)): at each cell the first neighbour (in dggs_edge_neighbors
 * order) one step nearer. Allocates only as dggs_grid_distance does. Errors: as dggs_grid_distance,
 * DGGS_E_BUFFER (size < n). */
dggs_error dggs_grid_path_cells(dggs_cell a, dggs_cell b, dggs_cell *out, int64_t size);

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
