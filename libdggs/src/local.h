/* Child positions and local (i, j) lattice coordinates over 64-bit ids (a port of index/_kernel/local.py,
 * operation for operation).
 *
 * Child positions (docs/grid.md, "Child positions"): the position of a cell among the descendants of its ancestor
 * at level p, at the cell's own level, in digit order: the digits below level p read as a number in base 3,
 * except that the level-1 digit (0-5) is a base-6 digit when p is 0.
 *
 * Local coordinates (docs/grid.md, "Local coordinates"): with the anchor's e1 = 2 (C - A) and e2 = e1 turned 60
 * degrees counter-clockwise, a cell's centroid relative to the anchor's centroid is (u e1 + v e2) / 18 with
 * integers u = v (mod 3); i = (2u + v) / 3 and j = (u + 2v) / 3. At level 0 e1 is a face edge and the centroid
 * is (u e1 + v e2) / 3. Cells on the anchor's face and on the faces across its edges are unfolded into the
 * anchor's face plane by the rigid motion fixing the two shared vertices (local_tables.h). The chart (the cells
 * that answer) is, at level 0, the anchor's face and the three across its edges; finer, the anchor's sector of
 * Snyder's projection and its mirror image across the face edge bounding it (local.c in_chart); other cells are
 * out of range. A kernel marks what it cannot answer: DGGS_OUT_OF_RANGE in i, or the null id.
 *
 * Ids are valid and levels 0..DGGS_MAX_LEVEL unless a function says otherwise. */
#ifndef DGGS_LOCAL_H
#define DGGS_LOCAL_H

#include <stdbool.h>
#include <stdint.h>

/* local.py OUT_OF_RANGE: marks a cell that has no coordinates around its anchor (in i). */
#define DGGS_OUT_OF_RANGE INT64_MIN

/* local.py child_count: descendants at `level` of one cell at `parent_level` (0 where level < parent_level, as
 * numba's integer power with a negative exponent). */
int64_t dggs_child_count(int parent_level, int level);
/* local.py _child_pos (per item): the position of `cell` below its ancestor at `parent_level`; -1 if that is
 * finer than the cell (or parent_level < 0). */
int64_t dggs_child_pos(uint64_t cell, int parent_level);
/* local.py one_child_pos: the single-id entry of dggs_child_pos, -1 also for an invalid id. */
int64_t dggs_one_child_pos(int64_t cell, int parent_level);
/* local.py _child_pos_cells (per item): the descendant of `parent` at `level` at position `pos`; 0 if `level` is
 * coarser than the parent or `pos` is out of range. */
uint64_t dggs_child_pos_cell(int64_t pos, uint64_t parent, int level);
/* local.py one_child_cell: the single-id entry of dggs_child_pos_cell, the null id also for an invalid parent. */
uint64_t dggs_one_child_cell(int64_t parent, int64_t pos, int level);

/* local.py _one_ij: (i, j) of `cell` around `anchor` (valid ids of one level); false with
 * (DGGS_OUT_OF_RANGE, 0) for a cell outside the anchor's chart. */
bool dggs_one_ij(uint64_t anchor, uint64_t cell, int64_t *i, int64_t *j);
/* local.py one_local_ij: the single-pair entry: false, with (0, 0), for invalid ids or two levels, and false
 * with (DGGS_OUT_OF_RANGE, 0) for no pair. */
bool dggs_one_local_ij(int64_t anchor, int64_t cell, int64_t *i, int64_t *j);
/* local.py _one_cell: the cell at (i, j) around a valid `anchor`, or the null id where no cell of the range has
 * those coordinates. */
uint64_t dggs_one_cell(uint64_t anchor, int64_t i, int64_t j);
/* local.py one_local_cell: the single-id entry of dggs_one_cell, the null id also for an invalid anchor. */
uint64_t dggs_one_local_cell(int64_t anchor, int64_t i, int64_t j);

/* local.py UNFOLD_FACE: the face across edge k (corner k to k + 1) of face f, a (20, 3) row-major table. */
const int8_t *dggs_unfold_face_table(void);

#endif
