/* Corners (vertices) of cells: the cells around a corner (its fan) and the disk of corner-sharing steps, on the
 * grid's edge adjacency alone (no projection). A port of index/_corners.fans and index/vertex._disk_vertex.
 *
 * The walk round a corner: cross the edge that starts at the corner (column c of a cell runs from its corner c
 * to corner c + 1), and in the new cell find the column b that leads back; both cells' corners run
 * counter-clockwise, so the shared edge runs the other way in the new cell and the corner is its corner b + 1,
 * where the next edge to cross starts. The walk closes when it is back at the first cell. */
#ifndef DGGS_VERTEX_H
#define DGGS_VERTEX_H

#include <stdint.h>

#include "dggs.h"

/* _corners.MAX_FAN: most cells around one corner (a 30-degree corner off the icosahedron vertices). */
#define DGGS_VERTEX_MAX_FAN DGGS_MAX_FAN

/* The cells around corner `corner` (0..2) of the valid id `cell`, in walking order from it, into fan[0..n), and
 * the index of that corner among each one's corners into corners[0..n); returns n (4, 5, 6, 10 or 12), or -1 if
 * the walk does not close within DGGS_VERTEX_MAX_FAN cells or a cell has no way back (a broken grid: never). */
int dggs_fan(uint64_t cell, int corner, uint64_t fan[DGGS_VERTEX_MAX_FAN], int corners[DGGS_VERTEX_MAX_FAN]);

/* Width of the row dggs_disk_vertex_row needs for radius k round a cell of `level`: the edge disk of radius 6 k
 * (one corner-sharing step crosses at most 6 edges, the shorter way round a 12-cell corner), capped by the
 * level's cells (vertex._disk_bound). k >= 0. */
int64_t dggs_disk_vertex_width(int64_t k, int level);
/* Scratch ids dggs_disk_vertex_row needs for rows of `width`: an open-addressing table of the cells seen and,
 * beside it, the corners walked of each: 2 dggs_disk_table_size(width). */
int64_t dggs_disk_vertex_table_size(int64_t width);
/* The cells within k corner-sharing steps of `cell`, sorted, into row[0..width); returns their number, -1 if they
 * outgrow `width`, -2 if a walk round a corner does not close (never). `table` (table_size ids from
 * dggs_disk_vertex_table_size) must be all 0; it is left dirty. Breadth-first, ring after ring; each corner of
 * the disk is walked once (a corner walked from one cell is marked in every cell of its fan). */
int64_t dggs_disk_vertex_row(uint64_t cell, int64_t k, uint64_t *row, int64_t width, uint64_t *table,
                             int64_t table_size);

#endif
