/* Polygon fill: the whole descent through the levels for one polygon, depth first, in id order. A port of
 * index/_kernel/fill.py (and ivea_fill.py: the same code on IVEA's inverse, selected by `proj`), operation for
 * operation.
 *
 * The walk goes down the hierarchy from the 20 base cells, carrying each cell's planar corners down (one
 * dggs_child_corners a level). A cell is classified by its footprint: every point of a level-l cell lies within
 * the arc RHO[l] of its footprint centre, which bounds its latitudes and longitudes by an ellipse round that
 * centre in the lng/lat plane (fill.py's module docstring derives the bound: K_INV = 1.17 bounds the inverse
 * projection's scale, Snyder 1992's largest angular deformation 17.27 degrees; K_LAT = 1.005 bounds WGS84's
 * d(phi)/d(beta)). The polygon's edges sit in polygon.h's bucket grid: an ellipse that meets no edge lies wholly
 * inside the polygon (its centre inside) or wholly outside. Cells wholly inside are emitted whole, cells outside
 * dropped, the others descended. In "center" mode every descendant at the target level of a cell `direct`
 * levels above it is tested by its centre (exactly as points' centres), with dggs_parity; in the other modes the
 * boundary cells at the target level are flagged for the caller's test of their polygons. Children in digit
 * order: the output comes out sorted. */
#ifndef DGGS_FILL_H
#define DGGS_FILL_H

#include <stdbool.h>
#include <stdint.h>

#include "dggs.h"
#include "polygon.h"

/* fill.py K_INV: the largest scale factor of Snyder's inverse on a face (1.1633), rounded up. */
#define DGGS_FILL_K_INV 1.17
/* fill.py K_LAT: the largest ratio of geodetic to authalic latitude change on WGS84 (1.00449), rounded up. */
#define DGGS_FILL_K_LAT 1.005
/* fill.py _STACK: room for the depth-first stack (at most 5 + 2 a level siblings wait beside the 20 base cells). */
#define DGGS_FILL_STACK 128
/* Length of the per-level counts cand and insides (fill.py: MAX_LEVEL + 2). */
#define DGGS_FILL_LEVELS (DGGS_MAX_LEVEL + 2)
/* Initial room of fill.py descend's output (it doubles it when full). */
#define DGGS_FILL_FIRST_ROOM 1024

/* Status of dggs_fill_walk: done (fill.py OK), stopped by a count over the limit (TOO_MANY), or the output
 * buffer is full (_FULL): grow it (keeping its first n entries) and call dggs_fill_walk again. */
#define DGGS_FILL_OK 0
#define DGGS_FILL_TOO_MANY 1
#define DGGS_FILL_FULL (-1)
/* The stack overflowed (cannot happen: at most 25 + 2 * 27 entries wait; numba's would write past its array). */
#define DGGS_FILL_FAILED 2
/* Flags of the cells found (fill.py): certain, a centre within rounding of an edge (test it exactly), a
 * boundary cell at the level (the caller tests its polygon). */
#define DGGS_FILL_SURE 0
#define DGGS_FILL_CENTRE 1
#define DGGS_FILL_EDGE 2

/* fill.py tables, the exact doubles of the numpy floor: RHO[l] the largest arc (radians) from a level-l cell's
 * footprint centre to its points; sin(RHO / 2), cos(RHO), sin(RHO); K_LAT degrees(RHO), the ellipse's semi-axis
 * in latitude. */
extern const double dggs_fill_rho[DGGS_MAX_LEVEL + 1];
extern const double dggs_fill_sin_half[DGGS_MAX_LEVEL + 1];
extern const double dggs_fill_cos[DGGS_MAX_LEVEL + 1];
extern const double dggs_fill_sin[DGGS_MAX_LEVEL + 1];
extern const double dggs_fill_a_lat[DGGS_MAX_LEVEL + 1];
/* The public verb's points per edge of a boundary cell at each level (tools/gen_fill_tables.py). */
extern const int dggs_fill_densify[DGGS_MAX_LEVEL + 1];

/* The state of one descent (fill.py descend's locals), resumable after DGGS_FILL_FULL. About 7 KB. */
typedef struct {
    int level;       /* the target level */
    int test_from;   /* cells at this level or finer have every descendant's centre tested */
    double miny, maxy; /* the polygon's latitude bounds */
    double inflate;    /* the footprint ellipses' scale off the poles: 1 (fill.py's), or more (the public verb's
                        * overlapping_bbox, whose cells' boxes lie in the ellipse sqrt(2) times as large) */
    int64_t limit;
    int top; /* the stack's height */
    uint64_t stack_id[DGGS_FILL_STACK];
    double stack_xy[DGGS_FILL_STACK][6]; /* the corners (ax, ay, bx, by, cx, cy) */
    int64_t cand[DGGS_FILL_LEVELS];    /* cells looked at on each level */
    int64_t insides[DGGS_FILL_LEVELS]; /* descendants at level of the cells emitted whole on each level */
    int64_t n, whole, tested, classified; /* found, whole, centres (or EDGE cells) tested, classified */
} dggs_fill_state;

/* fill.py centre: (lat, lng) degrees and the unit vector u of the centre of the cell with these planar corners
 * on `face`, exactly as points' centres. */
void dggs_fill_centre(dggs_projection proj, int face, int lv, double ax, double ay, double bx, double by, double cx,
                      double cy, double *lat, double *lng, double u[3]);
/* fill.py footprint: the same for the centre of the cell's footprint, the middle of AB (the face's centre at
 * level 0). */
void dggs_footprint(dggs_projection proj, int face, int lv, double ax, double ay, double bx, double by, double cx,
                    double cy, double *lat, double *lng, double u[3]);
/* fill.py ellipse: semi-axes (*a latitude, *lam longitude; degrees) of the footprint ellipse of a level-lv cell
 * centred on (ux, uy, uz); *lam is -1 where the cap holds a pole or comes too near one. */
void dggs_ellipse(int lv, double ux, double uy, double uz, double *a, double *lam);

/* fill.py descend's set-up: the 20 base cells on the stack, the counts zero, inflate 1. lv in 0..DGGS_MAX_LEVEL (the
 * caller checks), center: "center" mode, direct: levels above `level` from which every centre is tested. */
void dggs_fill_start(dggs_fill_state *s, int level, bool center, int direct, double miny, double maxy,
                     int64_t limit);
/* fill.py _walk: run the descent until its stack is empty (DGGS_FILL_OK), a count passes the limit
 * (DGGS_FILL_TOO_MANY) or s->n reaches `room` (DGGS_FILL_FULL: grow ids and flags, call again). Writes
 * ids[s->n..] and flags[s->n..] (sorted cells of mixed levels, a coarser one standing for all its descendants;
 * flags DGGS_FILL_SURE / CENTRE / EDGE). DGGS_FILL_FAILED never happens. After DGGS_FILL_OK or TOO_MANY the
 * counts are in s (n, tested, classified, cand, insides). */
int dggs_fill_walk(dggs_projection proj, dggs_fill_state *s, const dggs_edge_grid *g, uint64_t *ids, uint8_t *flags,
                   int64_t room);
/* fill.py first_over: the first count a level-by-level search would have found over `limit`, or -1. */
int64_t dggs_first_over(const int64_t *cand, const int64_t *insides, int64_t tested, int last, bool center,
                        int64_t limit);

#endif
