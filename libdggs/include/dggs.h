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

/* The most parts of a cell's polygon (dggs_cell_to_polygon): two for a cell across the antimeridian. */
#define DGGS_MAX_POLYGON_PARTS 4

/* The room (in points) dggs_cell_to_polygon needs for `densify` into *points: its output and its scratch.
 * DGGS_E_DOMAIN for a densify outside 0..DGGS_MAX_DENSIFY. */
dggs_error dggs_cell_to_polygon_size(int densify, size_t *points);

/* `cell` as the Python package's dggs.cell_to_polygon(cell, densify) draws it (index/_shapes.py): the boundary
 * (dggs_cell_to_boundary) as a polygon in (lng, lat) degrees, where a cell crosses the antimeridian or touches a
 * pole the exact ring unwrapped, closed along the pole where it goes round one, and split at +-180 into parts
 * (a MultiPolygon's), each counter-clockwise. The parts' points, one after another and not closed (the first
 * point is not repeated), are written as (lng, lat) pairs at the start of `lng_lat` (room for `size` points,
 * from dggs_cell_to_polygon_size; all of it is scratch); the points of each part into part_sizes[0 ..
 * *num_parts - 1]. Errors: DGGS_E_CELL, DGGS_E_DOMAIN (densify), DGGS_E_PROJECTION, DGGS_E_BUFFER (`size`
 * under dggs_cell_to_polygon_size's; nothing written then). */
dggs_error dggs_cell_to_polygon(dggs_cell cell, int densify, dggs_projection proj, double *lng_lat, size_t size,
                                size_t part_sizes[DGGS_MAX_POLYGON_PARTS], int *num_parts);

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

/* The outline of a set of cells (dggs.cells_to_polygons' id work and its rings' points), in five steps, each
 * into the caller's buffers:
 *   1. dggs_cells_drop_covered: sort the set (ascending, no duplicates) and drop the cells inside others;
 *   2. dggs_boundary_descendants_size / dggs_boundary_descendants: replace each cell coarser than the set's
 *      finest level by its descendants at that level with an edge on its outline, and sort them with the rest
 *      (the "fine" cells);
 *   3. dggs_outline_edge_mask: the edges (fine cell, column) of the fine cells on the outline;
 *   4. dggs_outline_chain: those edges, sorted by cell then column, chained into rings with the set on their left;
 *   5. dggs_outline_points_size / dggs_outline_points: the rings' (lat, lng) points, each edge densified, a pole
 *      on a ring as two points at latitude +-90, an antimeridian crossing as a point at longitude +-180.
 * An empty outline (step 3 finds no edge) is the whole globe. */

/* keep[i] = 1 where cells[i] is not inside an earlier cell of the array (a descendant of it), else 0.
 * cells: n ids, strictly increasing. DGGS_E_CELL for a non-cell, DGGS_E_DOMAIN if not strictly increasing. */
dggs_error dggs_cells_drop_covered(const dggs_cell *cells, size_t n, uint8_t *keep);

/* The number of descendants of `cell` at `level` (finer than the cell, at most DGGS_MAX_LEVEL) with an edge on
 * the cell's outline, into *size. DGGS_E_CELL, DGGS_E_LEVEL (a level outside the cell's level + 1 .. 28). */
dggs_error dggs_boundary_descendants_size(dggs_cell cell, int level, int64_t *size);
/* Those descendants (depth first, not sorted), into out (size ids, at least dggs_boundary_descendants_size's).
 * DGGS_E_CELL, DGGS_E_LEVEL, DGGS_E_BUFFER. */
dggs_error dggs_boundary_descendants(dggs_cell cell, int level, dggs_cell *out, int64_t size);

/* mask[3 i + col] = 1 where edge `col` (corner col to col + 1, counter-clockwise) of fine[i] is on the outline of
 * `cells` (the cell across it is not covered by them), else 0. cells: n_cells strictly increasing ids, none inside
 * another (step 1); fine: n_fine cells, all at one level at least as fine as every cell of `cells`.
 * DGGS_E_CELL, DGGS_E_DOMAIN (cells not increasing), DGGS_E_LEVEL_MISMATCH (a fine cell coarser than a cell or
 * fine cells of two levels). */
dggs_error dggs_outline_edge_mask(const dggs_cell *fine, size_t n_fine, const dggs_cell *cells, size_t n_cells,
                                  uint8_t *mask);

/* The m outline edges (edge_cell[i], edge_col[i]), sorted by cell then column, chained into rings: order[0..m)
 * gets the edges' indices ring after ring, starts[0..*rings] the start of each ring in order and, last, m
 * (starts holds m + 1 entries); visited is m bytes of scratch. cells as for dggs_outline_edge_mask.
 * DGGS_E_CELL, DGGS_E_DOMAIN (edges not sorted, a column outside 0..2), DGGS_E_FAILED (an edge whose successor
 * is not among them: not the outline of `cells`). */
dggs_error dggs_outline_chain(const dggs_cell *edge_cell, const int64_t *edge_col, size_t m, const dggs_cell *cells,
                              size_t n_cells, uint8_t *visited, int64_t *order, int64_t *starts, size_t *rings);

/* Rows of (lat, lng) dggs_outline_points may write for m edges of steps[i] segments each (an edge's densify + 1,
 * 1..100001), into *size. DGGS_E_DOMAIN. */
dggs_error dggs_outline_points_size(const int64_t *steps, size_t m, int64_t *size);
/* The rings' (lat, lng) points (degrees) into latlng (rows of 2 doubles, `size` rows, at least
 * dggs_outline_points_size's): edge_cell, edge_col, steps the m edges in ring order (edge_cell[order[i]] of step
 * 4) and their segments (densify + 1), starts the rings' starts (rings + 1 entries, the last m); ends[r] gets one
 * past ring r's last row, and corner[row] (size bytes) whether the row is a corner of the outline (not a pole, a
 * crossing or a densified point). Rings are not closed. scratch: scratch_len >= max(steps) + 2 doubles.
 * DGGS_E_CELL, DGGS_E_DOMAIN (a step outside 1..100001, a column outside 0..2, starts not increasing from 0 to m),
 * DGGS_E_PROJECTION, DGGS_E_BUFFER. */
dggs_error dggs_outline_points(const dggs_cell *edge_cell, const int64_t *edge_col, const int64_t *steps, size_t m,
                               const int64_t *starts, size_t rings, dggs_projection proj, double *latlng, int64_t size,
                               uint8_t *corner, int64_t *ends, double *scratch, size_t scratch_len);

/* The whole dissolve (multipolygon.c): the outline of `cells` (n ids of any levels, in any order, duplicates and
 * cells inside others allowed) as polygons in (lng, lat) degrees, as the Python package's dggs.cells_to_polygons
 * draws it (the union of the cells' dggs_cell_to_polygon): cut at +-180, closed over a pole the set surrounds,
 * shells counter-clockwise and holes clockwise, rings that touch themselves cut into simple loops. `densify` is
 * the points added along each outline edge (0..DGGS_MAX_DENSIFY), or -1 for each edge the points its cell gets
 * from dggs_cell_to_polygon's default (dggs_cell_edge_points, area within 1e-6). Output: the polygons' rings'
 * points end to end into lng_lat (rows of 2 doubles, not closed), each ring's point count into ring_sizes, each
 * polygon's ring count (its shell, then its holes) into polygon_rings. No cells give no polygon; a set covering
 * the sphere gives one: the rectangle (-180, -90) .. (180, 90). Allocates its working memory and frees it.
 * dggs_cells_to_multi_polygon_size: the exact counts (points, rings, polygons), by doing the work.
 * dggs_cells_to_multi_polygon: writes them, with the counts into *num_points, *num_rings, *num_polygons; where a
 * buffer is short, writes nothing but the counts (the sizes to call again with) and returns DGGS_E_BUFFER.
 * Errors: DGGS_E_CELL (a non-cell), DGGS_E_DOMAIN (densify), DGGS_E_PROJECTION, DGGS_E_FAILED (coarse cells
 * beside fine ones whose outline would take over 50 million fine cells, out of memory). */
dggs_error dggs_cells_to_multi_polygon_size(const dggs_cell *cells, size_t n, int densify, dggs_projection proj,
                                            int64_t *points, int64_t *rings, int64_t *polygons);
dggs_error dggs_cells_to_multi_polygon(const dggs_cell *cells, size_t n, int densify, dggs_projection proj,
                                       double *lng_lat, int64_t points, int64_t *ring_sizes, int64_t rings,
                                       int64_t *polygon_rings, int64_t polygons, int64_t *num_points,
                                       int64_t *num_rings, int64_t *num_polygons);

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
 * coordinates"): the anchor is (0, 0); the cells of its chart, unfolded into its plane, have one pair each. The
 * chart is, at level 0, the anchor's face and the three across its edges; finer, the anchor's 120-degree sector of
 * Snyder's projection (its level-1 digit pair) and the sector across the face edge bounding it (as H3's E_PENTAGON,
 * the grid bends beyond: across the lines from a face's centre to its vertices). Errors: DGGS_E_CELL,
 * DGGS_E_LEVEL_MISMATCH (two levels), DGGS_E_FAILED (a cell outside the chart). */
dggs_error dggs_cell_to_local_ij(dggs_cell anchor, dggs_cell cell, int64_t *i, int64_t *j);
/* The cell at (i, j) around `anchor` (the exact inverse of dggs_cell_to_local_ij). Errors: DGGS_E_CELL (a bad
 * anchor), DGGS_E_DOMAIN (a pair naming no cell: not a centroid of the lattice, or outside the chart). */
dggs_error dggs_local_ij_to_cell(dggs_cell anchor, int64_t i, int64_t j, dggs_cell *cell);

/* -- directed edges (edges.c) --
 * A directed edge from a cell at level l < 28 across its side d (0-2: corner d to corner d + 1 of its
 * counter-clockwise corners, neighbour column d) is the id (1 << 63) | cell | (d + 1) << shift(l + 1): with the
 * sign bit cleared, a valid cell one level finer (its "shadow"), whose parent is the origin. Level-28 cells have
 * no directed edges. */

/* Chords per edge (and twice as many, extrapolated) of the edge lengths: within 1e-8 of the length. */
#define DGGS_EDGE_LENGTH_PIECES 16

/* Whether `edge` is a directed edge id: the sign bit set and the rest a valid cell of level >= 1 (a level-1
 * shadow's digit 0-2). Never fails. */
int dggs_is_valid_directed_edge(uint64_t edge);
/* The directed edge from `origin` to its edge neighbour `destination`. DGGS_E_CELL, DGGS_E_LEVEL (origin at
 * level 28), DGGS_E_DOMAIN (not edge neighbours: another level, the cell itself, not across an edge). */
dggs_error dggs_cells_to_directed_edge(dggs_cell origin, dggs_cell destination, uint64_t *out);
/* out[0] = the origin, out[1] = the destination of a directed edge. DGGS_E_EDGE. */
dggs_error dggs_directed_edge_to_cells(uint64_t edge, dggs_cell out[2]);
/* The origin of a directed edge. DGGS_E_EDGE. */
dggs_error dggs_get_directed_edge_origin(uint64_t edge, dggs_cell *out);
/* The destination of a directed edge (the origin's neighbour across it). DGGS_E_EDGE. */
dggs_error dggs_get_directed_edge_destination(uint64_t edge, dggs_cell *out);
/* The three directed edges from `cell`, out[d] across side d. DGGS_E_CELL, DGGS_E_LEVEL (level 28). */
dggs_error dggs_origin_to_directed_edges(dggs_cell cell, uint64_t out[3]);
/* The edge from the destination back to the origin. DGGS_E_EDGE. */
dggs_error dggs_reverse_directed_edge(uint64_t edge, uint64_t *out);
/* The (lat, lng) points (degrees) of a directed edge from its first corner to its second with `densify` points
 * between (0..100000), into latlng (rows of 2 doubles, `size` rows >= densify + 2). DGGS_E_EDGE, DGGS_E_DOMAIN,
 * DGGS_E_PROJECTION, DGGS_E_BUFFER. */
dggs_error dggs_directed_edge_to_boundary(uint64_t edge, int densify, dggs_projection proj, double *latlng,
                                          size_t size);
/* The length of a directed edge's true curve (a straight segment on its face, mapped by the projection): on the
 * unit authalic sphere (radians), on WGS84 (metres, kilometres): chord sums of DGGS_EDGE_LENGTH_PIECES and twice
 * as many pieces, extrapolated. DGGS_E_EDGE, DGGS_E_PROJECTION. */
dggs_error dggs_edge_length_rads(uint64_t edge, dggs_projection proj, double *out);
dggs_error dggs_edge_length_m(uint64_t edge, dggs_projection proj, double *out);
dggs_error dggs_edge_length_km(uint64_t edge, dggs_projection proj, double *out);
/* -- end directed edges -- */

/* ---- end local ---- */



/* ---- vertices (vertex.c) ---------------------------------------------------------------------- */

/* Most cells around one corner: 12 at a 30-degree corner (4 at a right angle, 6 at 60 degrees, 10 at an
 * icosahedron vertex from level 1, 5 there at level 0). */
#define DGGS_MAX_FAN 12

/* The cells around corner `corner` (0..2, in dggs_cell_to_boundary's order) of `cell`, in walking order from
 * `cell` (counter-clockwise round the corner), into fan[0..*count), and the index of that corner among each
 * cell's corners into corners[0..*count) (corners[0] = corner). On the edge adjacency alone (the cell across the
 * edge that starts at the corner, then the next such edge there), so no tolerance. dggs.vertex_to_cells and
 * dggs.cell_to_vertexes (the smallest cell of the fan names the corner) are this function.
 * Errors: DGGS_E_CELL, DGGS_E_DOMAIN (corner outside 0..2), DGGS_E_FAILED (a walk that does not close: never). */
dggs_error dggs_cell_to_vertex_fan(dggs_cell cell, int corner, dggs_cell fan[DGGS_MAX_FAN], int corners[DGGS_MAX_FAN],
                                   int *count);

/* The ids the buffer of dggs_grid_disk_vertex must hold for radius k (0 <= k <= 2^31) round a cell of `cell`'s
 * level: room for the largest disk (the edge disk of radius 6 k, as one corner-sharing step crosses at most 6
 * edges; or the whole level) and for the hash table of the search (twice the least power of 2 >= 64 and >= twice
 * that). Errors: DGGS_E_CELL, DGGS_E_DOMAIN (k). */
dggs_error dggs_grid_disk_vertex_size(dggs_cell cell, int64_t k, int64_t *size);
/* The cells within k corner-sharing steps of `cell` (a step joins two cells with a corner in common; the cell
 * included), sorted ascending, into out[0..*count); the rest of out[0..size) is set to 0 (it is the work space).
 * `size` >= dggs_grid_disk_vertex_size(cell, k). Breadth-first, each corner walked once. Allocates nothing.
 * Errors: DGGS_E_CELL, DGGS_E_DOMAIN (k), DGGS_E_BUFFER (size too small), DGGS_E_FAILED (never). */
dggs_error dggs_grid_disk_vertex(dggs_cell cell, int64_t k, dggs_cell *out, int64_t size, int64_t *count);

/* A vertex (a cell corner) is named by the smallest cell id round it (the owner) and the corner's index (0-2)
 * there, in dggs_cell_to_boundary's order: the Python package's vertex id "<owner>:<index>" (index/vertex.py).
 * Every cell round a corner gives the same name. */

/* The vertices of `cell`'s three corners, in dggs_cell_to_boundary's order: owners[i] and index[i]. Errors:
 * DGGS_E_CELL, DGGS_E_FAILED (a walk round a corner that does not close: never for valid ids). */
dggs_error dggs_cell_to_vertexes(dggs_cell cell, dggs_cell owners[3], int index[3]);
/* 1 if (owner, index) is the name of a corner (owner a cell, index 0-2, and owner the smallest cell round its
 * corner `index`), else 0. */
int dggs_is_valid_vertex(dggs_cell owner, int index);
/* The (lat, lng) of a vertex: corner `index` of dggs_cell_to_boundary(owner). DGGS_E_CELL for a (owner, index)
 * that names no vertex (dggs_is_valid_vertex), DGGS_E_PROJECTION. */
dggs_error dggs_vertex_to_latlng(dggs_cell owner, int index, dggs_projection proj, double *lat, double *lng);

/* ---- end vertices ---- */



/* ---- raster pixels (clip.c, pixels.c) ---------------------------------------------------------- */

/* Pieces of raster pixels in cells: pixel (r C + c), cell, and the planar area they share (in a face frame of the
 * unit sphere: DGGS_FACE_AREA a face; times (WGS84 area / 20) / DGGS_FACE_AREA for m^2). The caller allocates the
 * three arrays of `cap` rows; `n` is the count of pieces in them. */
typedef struct {
    int64_t *pixel;
    dggs_cell *cell;
    double *area;
    int64_t cap;
    int64_t n;
} dggs_pieces;

/* Planar area of a face triangle in the unit-sphere face frame (a twentieth of the sphere's 4 pi). */
#define DGGS_FACE_AREA 0x1.41b2f769cf0e0p-1
/* Most arc (radians) from a pixel's corners to any of its points dggs_raster_pieces takes (10 degrees). */
#define DGGS_PIXEL_MAX_RADIUS 0x1.657184ae74487p-3

/* 8-byte words of scratch (`work`) dggs_raster_pieces needs for rows x cols pixels of k points an edge at `level`
 * (0 for arguments out of their domain). */
int64_t dggs_raster_pieces_work_words(int64_t rows, int64_t cols, int64_t k, int level);
/* The cells at `level` each valid pixel of a rows x cols grid meets, and the planar area they share (each pixel
 * cut along the cells' edges in Snyder's face planes: exact for its chord polygon). The pixels' edges, densified
 * with k >= 1 points each (degrees, WGS84, row-major): hlat, hlng ((rows + 1) x (cols k + 1)) along the grid lines
 * of constant row; vlat, vlng ((rows k + 1) x (cols + 1)) along those of constant column (unused for k = 1; each
 * corner in both). valid: rows x cols bytes (0: no pieces). The pieces go to `out`, each pixel's together in pixel
 * order; coarse (rows cols) gets, for an even k, each pixel's planar area drawn through every other of its points
 * (for a Richardson extrapolation of its area), NaN for pixels across a kink of the plane and for an odd k.
 * A pixel must lie within DGGS_PIXEL_MAX_RADIUS of its corners (split larger ones).
 * Set *resume = 0 for the first call. If the pieces outgrow out->cap it returns DGGS_E_BUFFER with out->n the
 * pieces kept (those of the pixels before *resume) and *need the room needed to go on: grow the three arrays to at
 * least *need rows (cap), keeping their first out->n rows, and call again with the same other arguments (work,
 * coarse, out->n and *resume as left). On DGGS_OK, out->n is the count of pieces.
 * DGGS_E_LEVEL, DGGS_E_DOMAIN (k < 1, negative rows or cols), DGGS_E_LATLNG (a point not finite or a latitude
 * outside -90..90), DGGS_E_BUFFER (work smaller than dggs_raster_pieces_work_words, or the pieces outgrew
 * out->cap), DGGS_E_FAILED (a pixel too ragged for the clipping scratch). */
dggs_error dggs_raster_pieces(const double *hlat, const double *hlng, const double *vlat, const double *vlng,
                              int64_t rows, int64_t cols, int64_t k, const uint8_t *valid, int level,
                              dggs_pieces *out, double *coarse, void *work, int64_t work_words, int64_t *resume,
                              int64_t *need);
/* dggs_raster_pieces with, for an even k, the area between each pixel's curved edges and their chords added
 * where it lies: round each pixel, each pair of chords' parabolic segment (a third of the triangle the pair makes)
 * goes to the piece of the cell holding the pair's middle point (the pixel's largest piece where it has none
 * there), so an edge shared by two pixels gives one what it takes from the other, in the same cell, and a cell
 * wholly under the grid gets its whole area. Pairs across a kink of the plane are left as drawn. The same
 * arguments, errors and resuming as dggs_raster_pieces (the areas are final once it returns DGGS_OK). */
dggs_error dggs_raster_pieces_arcs(const double *hlat, const double *hlng, const double *vlat, const double *vlng,
                                   int64_t rows, int64_t cols, int64_t k, const uint8_t *valid, int level,
                                   dggs_pieces *out, double *coarse, void *work, int64_t work_words,
                                   int64_t *resume, int64_t *need);
/* 8-byte words of scratch (`work`) dggs_latlng_pieces needs for a rows x cols lat/lng grid (0 for a bad size). */
int64_t dggs_latlng_pieces_work_words(int64_t rows, int64_t cols);
/* The cells at `level` each valid pixel of a geographic (lat/lng, WGS84) grid meets, and the area they share, on
 * the unit sphere (4 pi in all; times the ellipsoid's area / (4 pi) for m^2). The grid: `cols` columns of `dlng`
 * degrees (> 0, at most 360 in all) from longitude `west` (any turn: -180..180, 0..360, across 180), `rows` rows
 * between the rows + 1 latitudes `lat_edges` (strictly monotonic, within -90..90; row r between lat_edges[r] and
 * lat_edges[r + 1]); pixel r cols + c; valid as dggs_raster_pieces. Each cell is cut against the grid's rows and
 * columns in the cylindrical equal-area map, where the pixels are exact rectangles (pixels_latlng.c): its edges
 * densified so that their chords leave out at most `tol` of any pixel they cross, each pair of chords' parabolic
 * segment added in the pixel holding its middle point. The pieces go to `out` cell by cell (a cell's in pixel
 * order, the cells depth first through the hierarchy). Resuming as dggs_raster_pieces (*resume counts cells).
 * DGGS_E_LEVEL, DGGS_E_DOMAIN (rows or cols < 1, dlng <= 0 or columns past 360, tol <= 0, latitudes not strictly
 * monotonic), DGGS_E_LATLNG, DGGS_E_BUFFER, DGGS_E_FAILED (a cell edge needing more than 4096 chords: a cell far
 * coarser than the pixels; or a cell edge passing through a pole; cut such grids with dggs_raster_pieces). */
dggs_error dggs_latlng_pieces(double west, double dlng, const double *lat_edges, int64_t rows, int64_t cols,
                              const uint8_t *valid, int level, double tol, dggs_pieces *out, void *work,
                              int64_t work_words, int64_t *resume, int64_t *need);
/* The fraction of a pixel's area the chords of its edges leave out, into *out: lat, lng its 16 points round it,
 * four an edge (its first corner, then at a quarter, half and three quarters), degrees. NaN where no half-edge is
 * smooth. DGGS_E_LATLNG (a point not finite or a latitude outside -90..90). */
dggs_error dggs_pixel_chord_error(const double *lat, const double *lng, double *out);

/* Pieces of pixels in a raster's own plane (pixels_plane.c): pixel (r C + c), cell, area in pixel units (a whole
 * pixel is 1) and the piece's centroid in its pixel's own coordinates (cu, cv in 0..1: column and row offsets from
 * the pixel's corner at (c, r)). The caller's arrays, `cap` each; n pieces written. */
typedef struct {
    int64_t *pixel;
    uint64_t *cell;
    double *area, *cu, *cv;
    int64_t cap;
    int64_t n;
} dggs_plane_pieces_out;

/* The largest coordinate (pixels) dggs_plane_pieces takes: products of two stay far from overflow. */
#define DGGS_PLANE_MAX_COORD 1e15
/* 8-byte words of scratch (`work`) dggs_plane_pieces needs for a rows x cols grid (0 for an empty grid). */
int64_t dggs_plane_pieces_work_words(int64_t rows, int64_t cols);
/* The pixels of a rows x cols grid each ring meets, the area they share and its centroid: ring k (of n_rings,
 * cells[k] its cell) is the polygon (x, y)[ring_start[k] .. ring_start[k + 1]) (closed implicitly, either
 * orientation, straight chords) in pixel coordinates: x the column, y the row (pixel (r, c) is [c, c + 1) x
 * [r, r + 1)). Each ring is cut against the grid's rows and columns by Green's theorem in strips, so a pixel wholly
 * inside a ring is one piece of area 1 and rings that share their edges share each pixel's area exactly (a
 * raster in a projected CRS, its cells' edges densified and taken into the CRS by the caller). valid: rows x cols
 * bytes (0: no pieces). The pieces go to `out` ring by ring (a ring's in pixel order). Resuming as
 * dggs_raster_pieces (*resume counts rings). Errors: DGGS_E_DOMAIN (rows or cols < 1, ring_start decreasing, a
 * point not finite or past DGGS_PLANE_MAX_COORD), DGGS_E_BUFFER (work smaller than dggs_plane_pieces_work_words,
 * or the pieces outgrew out->cap: *need says the room needed, *resume the ring to go on from). */
dggs_error dggs_plane_pieces(const double *x, const double *y, const int64_t *ring_start, const uint64_t *cells,
                             int64_t n_rings, int64_t rows, int64_t cols, const uint8_t *valid,
                             dggs_plane_pieces_out *out, void *work, int64_t work_words, int64_t *resume,
                             int64_t *need);

/* ---- end pixels ---- */



/* ---- points per edge (edge_bound.c) ------------------------------------------------------------ */

/* Most points per edge dggs_cell_edge_points asks for. */
#define DGGS_EDGE_POINTS_MAX 256

/* Bounds, in metres on WGS84, of each edge's bulge (the distance of the true edge, straight on the face plane,
 * from the geodesic of its two corners, at its middle) into bulge_m[3], and of its length into length_m[3]; edge
 * i runs from corner i to corner i + 1 of dggs_cell_to_boundary. From the edge's midpoint on the authalic sphere,
 * no geodesic computed (the bound's constants were measured against a geodesic library: edge_bound.c).
 * DGGS_E_CELL, DGGS_E_PROJECTION. */
dggs_error dggs_cell_edge_bounds(dggs_cell cell, dggs_projection proj, double bulge_m[3], double length_m[3]);

/* The fewest points per edge (dggs_cell_to_boundary's densify, at most DGGS_EDGE_POINTS_MAX) for which the
 * boundary drawn with geodesics between its points stays within tolerance_m metres of the true edge (0: no
 * distance asked) and the geodesic area of the polygon within area_tolerance of the cell's area, relative
 * (0: none asked), into *points; with an area asked, rounded up to one less than a power of two (at most
 * DGGS_EDGE_POINTS_MAX - 1), so that neighbours share the coarser one's points and their polygons tile.
 * DGGS_E_CELL, DGGS_E_PROJECTION, DGGS_E_DOMAIN (a tolerance negative, not finite, or both 0). */
dggs_error dggs_cell_edge_points(dggs_cell cell, dggs_projection proj, double tolerance_m, double area_tolerance,
                                 int *points);

/* dggs_cell_edge_points and the boundary it asks for, in one call: the points per edge into *points, and the
 * boundary dggs_cell_to_boundary(cell, *points) draws as a closed ring of (lng, lat) degree pairs (lng first, the
 * first point repeated at the end: 3 (*points + 1) + 1 points, at most 3 (DGGS_EDGE_POINTS_MAX + 1) + 1) into
 * `lng_lat`, room for `size` points. The same numbers as those two calls, bit for bit, for less work: where the
 * count is 0, 1 or 3 every point of the ring is one the count has projected already. Errors as
 * dggs_cell_edge_points's, and DGGS_E_BUFFER if `size` is under the ring's points (*points is set then, nothing
 * else written: ask again with room for 3 (*points + 1) + 1). */
dggs_error dggs_cell_edge_ring(dggs_cell cell, dggs_projection proj, double tolerance_m, double area_tolerance,
                               double *lng_lat, size_t size, int *points);

/* ---- end points per edge ---- */

#ifdef __cplusplus
}
#endif

#endif /* DGGS_H */
