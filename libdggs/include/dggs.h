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

/* The id of string id `s` (a NUL-terminated face letter 'A'..'T', a level-1 digit '0'..'5', then one digit
 * '0'..'2' per further level) into *out. DGGS_E_CELL if `s` is not a string id (empty, too long, another
 * character); *out is then unchanged. */
dggs_error dggs_string_to_cell(const char *s, dggs_cell *out);

/* The string id of `cell` into `buf` of `size` bytes, NUL-terminated. A buffer of DGGS_MAX_CHARS + 1 bytes
 * always suffices (a level-l id takes l + 2). DGGS_E_CELL if `cell` is not a well-formed id, DGGS_E_BUFFER if
 * `buf` is too small (nothing written then). */
dggs_error dggs_cell_to_string(dggs_cell cell, char *buf, size_t size);

/* 1 if `cell` is a well-formed id (marker set, face 0..19, digits in range, no empty level above a filled
 * one), else 0. */
int dggs_is_valid_cell(dggs_cell cell);

/* The level 0..DGGS_MAX_LEVEL of `cell`, or -1 if it is not a well-formed id. */
int dggs_get_level(dggs_cell cell);

/* The face 0..19 (its level-0 ancestor) of `cell`, or -1 if it is not a well-formed id. */
int dggs_get_face(dggs_cell cell);

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

/* Most points per edge dggs_cell_to_boundary adds (Python's DENSIFY_LIMIT). */
#define DGGS_MAX_DENSIFY 100000

/* The id of the level-`level` cell holding the point (lat, lng) (WGS84 geodetic degrees; any longitude) on
 * projection `proj`, into *out. DGGS_E_LATLNG for a latitude outside -90..90 (or NaN) or a longitude that is
 * not finite, DGGS_E_LEVEL for a level outside 0..DGGS_MAX_LEVEL, DGGS_E_PROJECTION for another `proj`. */
dggs_error dggs_latlng_to_cell(double lat, double lng, int level, dggs_projection proj, dggs_cell *out);

/* The centre of `cell` (its planar centroid on the face, mapped back by `proj`) as WGS84 degrees, latitude
 * into *lat and longitude (-180..180) into *lng. DGGS_E_CELL if `cell` is not a well-formed id,
 * DGGS_E_PROJECTION for another `proj`. */
dggs_error dggs_cell_to_latlng(dggs_cell cell, dggs_projection proj, double *lat, double *lng);

/* The number of points dggs_cell_to_boundary writes for `densify`: 3 (densify + 1), into *points.
 * DGGS_E_DOMAIN for a densify outside 0..DGGS_MAX_DENSIFY. */
dggs_error dggs_cell_to_boundary_size(int densify, size_t *points);

/* The boundary of `cell`: its three corners counter-clockwise seen from outside, each followed by `densify`
 * points along the edge (straight on the face plane), as (lat, lng) degree pairs into `lat_lng` (room for
 * `size` points, 2 size doubles; not closed: the first point is not repeated); the count of points into
 * *count. DGGS_E_CELL, DGGS_E_DOMAIN (densify), DGGS_E_PROJECTION, DGGS_E_BUFFER if `size` is under
 * dggs_cell_to_boundary_size's (nothing written then). */
dggs_error dggs_cell_to_boundary(dggs_cell cell, int densify, dggs_projection proj, double *lat_lng, size_t size,
                                 size_t *count);

/* ---- end points ---- */



/* ---- hierarchy and compaction (hierarchy.c, compact.c) ---------------------------------------- */

/* The ancestor of `cell` at `parent_level` (0 .. the cell's level; the cell's own level gives the cell).
 * Errors: DGGS_E_CELL (not a cell), DGGS_E_LEVEL (parent_level outside 0..DGGS_MAX_LEVEL),
 * DGGS_E_LEVEL_MISMATCH (parent_level finer than the cell). */
dggs_error dggs_cell_to_parent(dggs_cell cell, int parent_level, dggs_cell *parent);

/* The number of descendants of `cell` at `child_level` (the cell's level .. DGGS_MAX_LEVEL): 3^(child_level -
 * level), 6 * 3^(child_level - 1) for a base cell, 1 at the cell's own level. Errors: DGGS_E_CELL, DGGS_E_LEVEL,
 * DGGS_E_LEVEL_MISMATCH (child_level coarser than the cell). */
dggs_error dggs_cell_to_children_size(dggs_cell cell, int child_level, int64_t *size);
/* The descendants of `cell` at `child_level`, in id order, into `children` (`size` entries, at least
 * dggs_cell_to_children_size's). Errors: those of dggs_cell_to_children_size, DGGS_E_BUFFER (size too small;
 * nothing written). */
dggs_error dggs_cell_to_children(dggs_cell cell, int child_level, dggs_cell *children, int64_t size);
/* The descendant of `cell` at `child_level` (the cell's level .. DGGS_MAX_LEVEL) that holds the cell's centre (its
 * planar centroid, located by the level's tie rules). Errors: DGGS_E_CELL, DGGS_E_LEVEL,
 * DGGS_E_LEVEL_MISMATCH (child_level coarser than the cell). */
dggs_error dggs_cell_to_center_child(dggs_cell cell, int child_level, dggs_cell *child);

/* The size of the buffer dggs_compact_cells needs for `num_cells` cells (num_cells, plus the sort's scratch from
 * 4096 cells on: 2 num_cells + 20480). Errors: DGGS_E_DOMAIN (num_cells < 0). */
dggs_error dggs_compact_cells_size(int64_t num_cells, int64_t *size);
/* Replace every complete set of siblings by their parent, recursively: the fewest cells covering the area of
 * `cells` (any order, any levels, duplicates and cells inside another allowed), sorted, into the first *num_out
 * entries of `out` (`out_size` entries, at least dggs_compact_cells_size's; the rest is scratch; `out` must not
 * overlap `cells`). Errors: DGGS_E_CELL (a cell is not a cell id), DGGS_E_DOMAIN (num_cells < 0), DGGS_E_BUFFER. */
dggs_error dggs_compact_cells(const dggs_cell *cells, int64_t num_cells, dggs_cell *out, int64_t out_size,
                              int64_t *num_out);
/* The size of the buffer dggs_uncompact_cells needs to expand `cells` to `level`: the larger of the number of
 * descendants at `level` of all cells (counted with any overlap; saturated at 2^63 - 1) and the sort's
 * scratch (num_cells, plus 2 num_cells + 20480 from 4096 cells on). Errors: DGGS_E_CELL, DGGS_E_LEVEL,
 * DGGS_E_DOMAIN (num_cells < 0), DGGS_E_LEVEL_MISMATCH (a cell finer than `level`). */
dggs_error dggs_uncompact_cells_size(const dggs_cell *cells, int64_t num_cells, int level, int64_t *size);
/* All descendants at `level` of the area `cells` cover, sorted and unique (the inverse of compaction), into the
 * first *num_out entries of `out` (`out_size` entries, at least dggs_uncompact_cells_size's; `out` must not
 * overlap `cells`). Errors: those of dggs_uncompact_cells_size, DGGS_E_BUFFER. */
dggs_error dggs_uncompact_cells(const dggs_cell *cells, int64_t num_cells, int level, dggs_cell *out,
                                int64_t out_size, int64_t *num_out);

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

/* Which cells dggs_polygon_to_cells returns (the Python verb's `mode`; h3's containment modes). */
typedef enum {
    DGGS_FILL_MODE_CENTER = 0,          /* cells whose centre lies inside the polygon (its boundary excluded) */
    DGGS_FILL_MODE_CONTAINS = 1,        /* cells lying wholly inside the polygon (their boundary may touch its) */
    DGGS_FILL_MODE_OVERLAPS = 2,        /* cells that touch the polygon, its boundary included */
    DGGS_FILL_MODE_OVERLAPPING_BBOX = 3 /* cells whose lng/lat bounding box (of each part, split at +-180) meets it */
} dggs_fill_mode;

/* A polygon: `num_rings` rings of (lat, lng) degrees laid end to end in `lat_lng` (2 doubles a point), ring k
 * having ring_sizes[k] points (a last point equal to its first is allowed and ignored). Rings are the shells
 * and holes of one or more polygons that do not overlap (a valid (Multi)Polygon): a point is inside when the
 * ray from it crosses the rings an odd number of times. Edges are straight in the lng/lat plane; longitudes
 * must lie in -180..180 (split a polygon that crosses the antimeridian there). The polygon is not checked for
 * validity.
 *
 * dggs_polygon_to_cells_size: an upper bound on the number of cells dggs_polygon_to_cells returns (the cells
 * the footprint descent keeps or cannot decide; it costs one descent).
 * Errors (both functions): DGGS_E_LEVEL, DGGS_E_PROJECTION, DGGS_E_DOMAIN (an unknown mode, a negative count,
 * a ring of fewer than 3 points), DGGS_E_LATLNG (a latitude outside -90..90, a longitude outside
 * -180..180, a coordinate not finite), DGGS_E_FAILED (out of memory). */
dggs_error dggs_polygon_to_cells_size(const double *lat_lng, const int64_t *ring_sizes, int64_t num_rings, int level,
                                      dggs_fill_mode mode, dggs_projection proj, int64_t *size);
/* The cells at `level` of a polygon (above) by `mode`, sorted, into `out` (`out_size` entries), their count
 * into *count. DGGS_E_BUFFER when they do not fit: *count is then the number needed (nothing useful in out).
 * Allocates its working memory (the polygon's edges, their bucket grid, the descent's cells) and frees it.
 *
 * The cells far from the polygon's boundary are decided by footprints that provably hold them, and the centres
 * within rounding of an edge by exact arithmetic, exactly as the Python verb (dggs.polygon_to_cells): in
 * DGGS_FILL_MODE_CENTER the result is the Python verb's, cell for cell. The boundary cells of the other modes
 * are tested on their lng/lat polygon as dggs_cell_to_boundary draws it, with exact predicates, with the most
 * points per edge the Python default gives a cell of that level (it chooses per cell, by geodesics): a cell
 * whose boundary passes within that densification's error (under 1e-6 of the cell's size) of the polygon's may
 * be judged otherwise than there. */
dggs_error dggs_polygon_to_cells(const double *lat_lng, const int64_t *ring_sizes, int64_t num_rings, int level,
                                 dggs_fill_mode mode, dggs_projection proj, dggs_cell *out, int64_t out_size,
                                 int64_t *count);

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

/* The position of `cell` among the descendants, at its own level, of its ancestor at `parent_level`, in id order
 * (docs/grid.md, "Child positions"): the digits below parent_level in base 3, the level-1 digit in base 6 when
 * parent_level is 0. Errors: DGGS_E_CELL, DGGS_E_LEVEL (parent_level outside 0..DGGS_MAX_LEVEL),
 * DGGS_E_LEVEL_MISMATCH (parent_level finer than the cell). */
dggs_error dggs_cell_to_child_pos(dggs_cell cell, int parent_level, int64_t *pos);
/* The descendant of `parent` at `child_level` at position `pos` (the inverse of dggs_cell_to_child_pos).
 * Errors: DGGS_E_CELL, DGGS_E_LEVEL, DGGS_E_LEVEL_MISMATCH (child_level coarser than the parent), DGGS_E_DOMAIN
 * (pos outside 0 .. the parent's number of descendants at child_level - 1). */
dggs_error dggs_child_pos_to_cell(int64_t pos, dggs_cell parent, int child_level, dggs_cell *child);

/* Integer lattice coordinates (i, j) of `cell` around `anchor`, a cell of the same level (docs/grid.md, "Local
 * coordinates"): the anchor is (0, 0); the cells of the anchor's face and of the three faces across its edges,
 * unfolded into its plane, have one pair each. Errors: DGGS_E_CELL, DGGS_E_LEVEL_MISMATCH (two levels),
 * DGGS_E_FAILED (a cell outside that range). */
dggs_error dggs_cell_to_local_ij(dggs_cell anchor, dggs_cell cell, int64_t *i, int64_t *j);
/* The cell at (i, j) around `anchor` (the exact inverse of dggs_cell_to_local_ij). Errors: DGGS_E_CELL (a bad
 * anchor), DGGS_E_DOMAIN (a pair naming no cell: not a centroid of the lattice, or out of range). */
dggs_error dggs_local_ij_to_cell(dggs_cell anchor, int64_t i, int64_t j, dggs_cell *cell);

/* ---- end local ---- */



/* ---- raster pixels (clip.c, pixels.c) ---------------------------------------------------------- */

/* ---- end pixels ---- */

#ifdef __cplusplus
}
#endif

#endif /* DGGS_H */
