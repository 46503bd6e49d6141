/* The grid as a graph over 64-bit ids: edge neighbours, disks, rings (a port of index/_kernel/grid.py).
 *
 * Every level is a reflection tiling (docs/grid.md, "Neighbours"; thesis §6.1.7), so the cell across an edge is
 * the cell's mirror image there, and mirror images carry the same edge labels. Walking up from the last digit,
 * the first digit whose edge is shared with a sibling changes and the digits after it stay: a neighbour is the
 * id with one field replaced. At the edge of the level-1 triangle a table gives the (face, level-1 digit)
 * across. The tables (grid_tables.h) are generated from the Python geometry by tools/gen_grid_tables.py.
 *
 * Conventions (as the numba module's):
 * - Ids are uint64 in the layout of bits.h; 0 is the null id. Every function assumes valid ids (the caller
 *   validates).
 * - Neighbour column i is the cell across the edge from corner i to corner i + 1 of the cell's
 *   counter-clockwise corners (as edge_neighbors on string ids).
 * - Disk and ring rows are sorted ascending. Nothing here allocates: scratch space is the caller's, sized by
 *   the *_work_size / *_table_size functions below. */
#ifndef DGGS_GRID_H
#define DGGS_GRID_H

#include <stdbool.h>
#include <stdint.h>

/* _across: the cell across the edge of `label` (a = 0, b = 1, c = 2) of a cell at `level` >= 1. */
uint64_t dggs_across(uint64_t cell, int level, int label);
/* _is_ccw: 1 if the cell's corners A, B, C run counter-clockwise (level-1 orientation XOR parity of digits 0
 * and 2), else 0. */
int dggs_is_ccw(uint64_t cell);
/* _neighbour: column `col` (0..2) of the cell's neighbours (corner col to col + 1); any level, 0 too. */
uint64_t dggs_neighbour(uint64_t cell, int level, int col);

/* neighbours, per item: the three edge neighbours of a valid id of any level into out[0..2]. */
void dggs_neighbours(uint64_t cell, uint64_t out[3]);
/* are_neighbours, per item: whether a and b share an edge (false for different levels, and for a == b). */
bool dggs_are_neighbours(uint64_t a, uint64_t b);

/* _sort_small: sort a[0..n) ascending in place (insertion sort for n <= 48, else an in-place heap sort: the
 * same result as np.sort on integers). */
void dggs_sort_small(uint64_t *a, int64_t n);

/* next_ring: ring j + 1 from rings j (`cur`, sorted) and j - 1 (`prev`, sorted), written sorted into
 * dest[0..dest_len); returns its size, or -1 if it does not fit in dest_len. `cand` needs room for 3 * ncur
 * ids. */
int64_t dggs_next_ring(const uint64_t *cur, int64_t ncur, const uint64_t *prev, int64_t nprev, uint64_t *dest,
                       int64_t dest_len, uint64_t *cand);

/* _disk_row: the disk of radius k around `cell` into row[0..width), sorted; returns its size, or -1 if it
 * outgrows `width`. `table` (table_size ids, all 0, table_size = dggs_disk_table_size(width)) is an
 * open-addressing set; it is all 0 again on return. */
int64_t dggs_disk_row(uint64_t cell, int64_t k, uint64_t *row, int64_t width, uint64_t *table, int64_t table_size);
/* The hash table size _disk_impl uses for rows of `width`: the least power of 2 >= 64 and >= 2 * width. */
int64_t dggs_disk_table_size(int64_t width);

/* The ring of radius k around `cell`, one row of _ring_impl: writes it sorted into out[0..out_width) and
 * returns its size, or -1 if a ring on the way outgrows max(out_width, 6) or the result outgrows out_width.
 * `work` holds dggs_ring_work_size(out_width) ids. */
int64_t dggs_ring_row(uint64_t cell, int64_t k, uint64_t *out, int64_t out_width, uint64_t *work);
/* Scratch ids dggs_ring_row needs for rows of out_width: 6 * max(out_width, 6) (3 rings + candidates). */
int64_t dggs_ring_work_size(int64_t out_width);

/* The head of disk_of (the single-id entry): the row width its disk needs (disk_width), or -1 for a miss: no id,
 * k over 64 (the general path takes any k), or a width over max_cells (the general path counts the real disk). */
int64_t dggs_disk_of_width(uint64_t cell, int64_t k, int64_t max_cells);

/* level_cells: cells at `level`: 20 at level 0, 120 * 3^(level - 1) after. */
int64_t dggs_level_cells(int level);
/* disk_width: most cells within k steps of a cell at `level` (the planar bound, or the whole level). */
int64_t dggs_disk_width(int64_t k, int level);
/* ring_width: most cells exactly k steps from a cell at `level`. */
int64_t dggs_ring_width(int64_t k, int level);

/* disk_sizes, per item: the size of the disk of radius k around `cell`, counted ring after ring (next_ring: the
 * memory of two rings), stopping once it passes `cap` (the count is then the first ring total over cap).
 * `work` (work_len ids) holds the rings: rings j - 1 and j (at most `cap` each, as the count is) and ring j + 1
 * with its candidates (at most 3x ring j each). Returns the count, or -2 if a ring does not fit in `work` (then
 * call again with a larger buffer, as the numba code grows its arrays: dggs_disk_sizes_work_size(r) fits
 * rings of up to r cells, and r = min(cap, level cells) always suffices). */
int64_t dggs_disk_size_count(uint64_t cell, int64_t k, int64_t cap, uint64_t *work, int64_t work_len);
/* Scratch ids that hold the rings of dggs_disk_size_count while the rings it extends have <= r cells: 8 r. */
int64_t dggs_disk_sizes_work_size(int64_t r);

#endif
