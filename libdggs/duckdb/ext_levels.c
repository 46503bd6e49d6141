/* Faces, edge neighbours and the level table (counts and areas of the cells of a level). An invalid id or level gives
 * NULL, as the h3 extension does; an unknown unit is an error naming it. */
#include <stdio.h>
#include <stdlib.h>

#include "ext.h"

#define ROWS(n) for (idx_t r = 0; r < (n); r++)

/* dggs_get_face(cell) -> INTEGER 0..19 (variant 0); dggs_edge_neighbors(cell) -> the 3 cells across its edges (1). */
static void face_and_neighbors(duckdb_function_info info, duckdb_data_chunk in, duckdb_vector outv) {
    const fn_extra *x = extra_of(info);
    idx_t n = duckdb_data_chunk_get_size(in);
    col_t c = col_of(in, 0);
    out_t o = out_of(outv);
    list_out_t l;
    if (x->variant == 1) l = list_of(outv);
    ROWS(n) {
        dggs_cell cell, nb[3];
        if (x->variant == 1) list_empty(&l, r);
        if (is_null(&c, r) || !id_get(&c, x->kind, r, &cell) ||
            (x->variant == 1 && dggs_edge_neighbors(cell, nb) != DGGS_OK)) {
            out_null(&o, r);
            continue;
        }
        if (x->variant == 0)
            ((int32_t *)o.data)[r] = dggs_get_face(cell);
        else
            list_push_ids(&l, r, x->kind, nb, 3);
    }
}

/* dggs_are_neighbor_cells(a, b) -> BOOLEAN: whether they share an edge (false across levels). */
static void are_neighbors(duckdb_function_info info, duckdb_data_chunk in, duckdb_vector outv) {
    const fn_extra *x = extra_of(info);
    idx_t n = duckdb_data_chunk_get_size(in);
    col_t a = col_of(in, 0), b = col_of(in, 1);
    out_t o = out_of(outv);
    ROWS(n) {
        dggs_cell ca, cb;
        int yes;
        if (is_null(&a, r) || is_null(&b, r) || !id_get(&a, x->kind, r, &ca) || !id_get(&b, x->kind, r, &cb) ||
            dggs_are_neighbor_cells(ca, cb, &yes) != DGGS_OK) {
            out_null(&o, r);
            continue;
        }
        ((bool *)o.data)[r] = yes != 0;
    }
}

/* The level table: dggs_get_num_cells(level) -> BIGINT (variant 0), dggs_level_area(level, unit) -> DOUBLE (1):
 * 'm^2', 'km^2' (WGS84) or 'rads^2' (the unit sphere), as dggs.cell_area(level, unit). */
static void level_table(duckdb_function_info info, duckdb_data_chunk in, duckdb_vector outv) {
    const fn_extra *x = extra_of(info);
    idx_t n = duckdb_data_chunk_get_size(in);
    col_t lv = col_of(in, 0), u = x->variant ? col_of(in, 1) : lv;
    out_t o = out_of(outv);
    ROWS(n) {
        int level;
        if (is_null(&lv, r) || (x->variant && is_null(&u, r)) || (level = level_get(&lv, r)) < 0) {
            out_null(&o, r);
            continue;
        }
        int64_t count = 20;
        double cells = 20.0, p = 1.0;
        for (int i = 1; i < level; i++) p *= 3.0;
        if (level > 0) {
            cells = 120.0 * p;
            count = (int64_t)cells;
        }
        if (x->variant == 0) {
            ((int64_t *)o.data)[r] = count;
            continue;
        }
        uint32_t len;
        const char *unit = str_data(&((duckdb_string_t *)u.data)[r], &len);
        double total;
        if (len == 3 && !memcmp(unit, "m^2", 3))
            total = WGS84_AREA_M2;
        else if (len == 4 && !memcmp(unit, "km^2", 4))
            total = WGS84_AREA_M2 * 1e-6;
        else if (len == 6 && !memcmp(unit, "rads^2", 6))
            total = 4 * 0x1.921fb54442d18p+1; /* 4 pi */
        else {
            char msg[200];
            snprintf(msg, sizeof msg, "%s: unit '%.*s' is not one of 'm^2', 'km^2', 'rads^2'", x->name,
                     (int)(len > 40 ? 40 : len), unit);
            duckdb_scalar_function_set_error(info, msg);
            return;
        }
        ((double *)o.data)[r] = total / cells;
    }
}

void register_levels(duckdb_connection con) {
    reg(con, "dggs_get_face", "I", 'N', face_and_neighbors, 1, K_NONE, 0);
    reg(con, "dggs_edge_neighbors", "I", 'E', face_and_neighbors, 1, K_NONE, 1);
    reg(con, "dggs_are_neighbor_cells", "II", 'O', are_neighbors, 1, K_NONE, 0);
    reg(con, "dggs_get_num_cells", "B", 'B', level_table, 0, K_NONE, 0);
    reg(con, "dggs_level_area", "BV", 'D', level_table, 0, K_NONE, 1);
}
