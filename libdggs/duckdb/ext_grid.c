/* Disks, rings, distances, paths, compaction and local (i, j). An invalid id, k or level, or cells the core cannot
 * pair (two levels, out of range), give NULL, as the h3 extension does (docs/duckdb.md). */
#include <stdio.h>
#include <stdlib.h>

#include "ext.h"

#define ROWS(n) for (idx_t r = 0; r < (n); r++)

/* dggs_grid_disk (variant 0) and dggs_grid_ring (1): (cell, k) -> sorted list of ids. */
static void disk(duckdb_function_info info, duckdb_data_chunk in, duckdb_vector outv) {
    const fn_extra *x = extra_of(info);
    idx_t n = duckdb_data_chunk_get_size(in);
    col_t c = col_of(in, 0), kc = col_of(in, 1);
    out_t o = out_of(outv);
    list_out_t l = list_of(outv);
    ROWS(n) {
        dggs_cell cell, *buf;
        int64_t k, size, count;
        list_empty(&l, r);
        if (is_null(&c, r) || is_null(&kc, r) || !id_get(&c, x->kind, r, &cell) ||
            (k = ((int64_t *)kc.data)[r]) < 0 ||
            (x->variant == 0 ? dggs_grid_disk_size(cell, k, &size) : dggs_grid_ring_size(cell, k, &size)) != DGGS_OK) {
            out_null(&o, r);
            continue;
        }
        if (size > MAX_LIST_CELLS) {
            char msg[160];
            snprintf(msg, sizeof msg, "%s: k %lld at level %d needs more than %lld cells of work space", x->name,
                     (long long)k, dggs_get_level(cell), (long long)MAX_LIST_CELLS);
            duckdb_scalar_function_set_error(info, msg);
            return;
        }
        buf = (dggs_cell *)malloc((size_t)size * sizeof(dggs_cell));
        if (!buf) {
            duckdb_scalar_function_set_error(info, "dggs_grid_disk: out of memory");
            return;
        }
        if ((x->variant == 0 ? dggs_grid_disk(cell, k, buf, size, &count) : dggs_grid_ring(cell, k, buf, size, &count)) !=
            DGGS_OK) {
            out_null(&o, r);
        } else if (!list_push_ids(&l, r, x->kind, buf, (idx_t)count)) {
            free(buf);
            duckdb_scalar_function_set_error(info, "dggs_grid_disk: too many cells for one list");
            return;
        }
        free(buf);
    }
}

/* dggs_grid_distance (variant 0) -> BIGINT and dggs_grid_path_cells (1) -> list: (a, b) of one level. */
static void pair(duckdb_function_info info, duckdb_data_chunk in, duckdb_vector outv) {
    const fn_extra *x = extra_of(info);
    idx_t n = duckdb_data_chunk_get_size(in);
    col_t a = col_of(in, 0), b = col_of(in, 1);
    out_t o = out_of(outv);
    list_out_t l;
    if (x->variant == 1) l = list_of(outv);
    ROWS(n) {
        dggs_cell ca, cb, *path;
        int64_t d;
        if (x->variant == 1) list_empty(&l, r);
        if (is_null(&a, r) || is_null(&b, r) || !id_get(&a, x->kind, r, &ca) || !id_get(&b, x->kind, r, &cb) ||
            dggs_grid_distance(ca, cb, &d) != DGGS_OK) {
            out_null(&o, r);
            continue;
        }
        if (x->variant == 0) {
            ((int64_t *)o.data)[r] = d;
            continue;
        }
        if (d + 1 > MAX_LIST_CELLS) {
            char msg[160];
            snprintf(msg, sizeof msg, "dggs_grid_path_cells: a path of %lld cells is longer than %lld", (long long)(d + 1),
                     (long long)MAX_LIST_CELLS);
            duckdb_scalar_function_set_error(info, msg);
            return;
        }
        path = (dggs_cell *)malloc((size_t)(d + 1) * sizeof(dggs_cell));
        if (!path) {
            duckdb_scalar_function_set_error(info, "dggs_grid_path_cells: out of memory");
            return;
        }
        if (dggs_grid_path_cells(ca, cb, path, d + 1) != DGGS_OK)
            out_null(&o, r);
        else
            list_push_ids(&l, r, x->kind, path, (idx_t)(d + 1));
        free(path);
    }
}

/* dggs_compact_cells(list) (variant 0) and dggs_uncompact_cells(list, level) (1) -> sorted list. A list holding a
 * value that is not a cell id gives NULL; NULL elements are skipped. */
static void compaction(duckdb_function_info info, duckdb_data_chunk in, duckdb_vector outv) {
    const fn_extra *x = extra_of(info);
    idx_t n = duckdb_data_chunk_get_size(in);
    col_t c = col_of(in, 0), lv = x->variant ? col_of(in, 1) : c;
    out_t o = out_of(outv);
    list_out_t l = list_of(outv);
    ROWS(n) {
        dggs_cell *ids = NULL, *out = NULL;
        idx_t m = 0;
        int64_t size, count;
        int level = 0, got;
        list_empty(&l, r);
        if (is_null(&c, r) || (x->variant && (is_null(&lv, r) || (level = level_get(&lv, r)) < 0))) {
            out_null(&o, r);
            continue;
        }
        got = list_ids_get(&c, x->kind, r, &ids, &m);
        if (got < 0) {
            duckdb_scalar_function_set_error(info, "dggs_compact_cells: out of memory");
            return;
        }
        if (got == 0 || (x->variant == 0 ? dggs_compact_cells_size((int64_t)m, &size)
                                         : dggs_uncompact_cells_size(ids, (int64_t)m, level, &size)) != DGGS_OK) {
            free(ids);
            out_null(&o, r);
            continue;
        }
        if (size > MAX_LIST_CELLS) {
            free(ids);
            char msg[160];
            snprintf(msg, sizeof msg, "%s: more than %lld cells", x->name, (long long)MAX_LIST_CELLS);
            duckdb_scalar_function_set_error(info, msg);
            return;
        }
        out = (dggs_cell *)malloc((size_t)(size ? size : 1) * sizeof(dggs_cell));
        if (!out) {
            free(ids);
            duckdb_scalar_function_set_error(info, "dggs_uncompact_cells: too many cells (out of memory)");
            return;
        }
        if ((x->variant == 0 ? dggs_compact_cells(ids, (int64_t)m, out, size, &count)
                             : dggs_uncompact_cells(ids, (int64_t)m, level, out, size, &count)) != DGGS_OK)
            out_null(&o, r);
        else
            list_push_ids(&l, r, x->kind, out, (idx_t)count);
        free(ids);
        free(out);
    }
}

/* dggs_cell_to_local_ij(anchor, cell) -> STRUCT(i, j). */
static void cell_to_local_ij(duckdb_function_info info, duckdb_data_chunk in, duckdb_vector outv) {
    const fn_extra *x = extra_of(info);
    idx_t n = duckdb_data_chunk_get_size(in);
    col_t a = col_of(in, 0), c = col_of(in, 1);
    out_t o = out_of(outv);
    out_t oi = out_of(duckdb_struct_vector_get_child(outv, 0)), oj = out_of(duckdb_struct_vector_get_child(outv, 1));
    ROWS(n) {
        dggs_cell anchor, cell;
        int64_t i, j;
        if (is_null(&a, r) || is_null(&c, r) || !id_get(&a, x->kind, r, &anchor) || !id_get(&c, x->kind, r, &cell) ||
            dggs_cell_to_local_ij(anchor, cell, &i, &j) != DGGS_OK) {
            out_null(&o, r);
            out_null(&oi, r);
            out_null(&oj, r);
            continue;
        }
        ((int64_t *)oi.data)[r] = i;
        ((int64_t *)oj.data)[r] = j;
    }
}

/* dggs_local_ij_to_cell(anchor, i, j) -> id. */
static void local_ij_to_cell(duckdb_function_info info, duckdb_data_chunk in, duckdb_vector outv) {
    const fn_extra *x = extra_of(info);
    idx_t n = duckdb_data_chunk_get_size(in);
    col_t a = col_of(in, 0), ci = col_of(in, 1), cj = col_of(in, 2);
    out_t o = out_of(outv);
    ROWS(n) {
        dggs_cell anchor, cell;
        if (is_null(&a, r) || is_null(&ci, r) || is_null(&cj, r) || !id_get(&a, x->kind, r, &anchor) ||
            dggs_local_ij_to_cell(anchor, ((int64_t *)ci.data)[r], ((int64_t *)cj.data)[r], &cell) != DGGS_OK) {
            out_null(&o, r);
            continue;
        }
        id_put(outv, o.data, x->kind, r, cell);
    }
}

void register_grid(duckdb_connection con) {
    reg(con, "dggs_grid_disk", "IB", 'E', disk, 1, K_NONE, 0);
    reg(con, "dggs_grid_ring", "IB", 'E', disk, 1, K_NONE, 1);
    reg(con, "dggs_grid_distance", "II", 'B', pair, 1, K_NONE, 0);
    reg(con, "dggs_grid_path_cells", "II", 'E', pair, 1, K_NONE, 1);
    reg(con, "dggs_compact_cells", "L", 'E', compaction, 1, K_NONE, 0);
    reg(con, "dggs_uncompact_cells", "LB", 'E', compaction, 1, K_NONE, 1);
    reg(con, "dggs_cell_to_local_ij", "II", 'J', cell_to_local_ij, 1, K_NONE, 0);
    reg(con, "dggs_local_ij_to_cell", "IBB", 'I', local_ij_to_cell, 1, K_NONE, 0);
}
