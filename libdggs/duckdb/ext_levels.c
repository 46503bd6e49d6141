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

/* The area of the sphere in `unit` ('m^2' or 'km^2' on WGS84, 'rads^2' on the unit sphere) into *total, as
 * dggs.cell_area computes it; false (and the query's error set, naming the unit) for another unit. */
static bool area_total(duckdb_function_info info, const char *name, duckdb_string_t *s, double *total) {
    uint32_t len;
    const char *unit = str_data(s, &len);
    if (len == 3 && !memcmp(unit, "m^2", 3))
        *total = WGS84_AREA_M2;
    else if (len == 4 && !memcmp(unit, "km^2", 4))
        *total = WGS84_AREA_M2 * 1e-6;
    else if (len == 6 && !memcmp(unit, "rads^2", 6))
        *total = 4 * 0x1.921fb54442d18p+1; /* 4 pi */
    else {
        char msg[200];
        snprintf(msg, sizeof msg, "%s: unit '%.*s' is not one of 'm^2', 'km^2', 'rads^2'", name,
                 (int)(len > 40 ? 40 : len), unit);
        duckdb_scalar_function_set_error(info, msg);
        return false;
    }
    return true;
}

/* The number of cells at `level` as a double (exact: at most 120 3^27 < 2^53), as dggs.cell_area divides. */
static double cells_at(int level) {
    double p = 1.0;
    for (int i = 1; i < level; i++) p *= 3.0;
    return level == 0 ? 20.0 : 120.0 * p;
}

/* dggs_cell_area(cell [, unit]) -> DOUBLE, m^2 by default: the sphere's area over the level's number of cells
 * (the planar cells are congruent and the projection equal-area), the same double as dggs.cell_area. */
static void cell_area_unit(duckdb_function_info info, duckdb_data_chunk in, duckdb_vector outv) {
    const fn_extra *x = extra_of(info);
    idx_t n = duckdb_data_chunk_get_size(in);
    int has_unit = duckdb_data_chunk_get_column_count(in) > 1;
    col_t c = col_of(in, 0), u = has_unit ? col_of(in, 1) : c;
    out_t o = out_of(outv);
    ROWS(n) {
        dggs_cell cell;
        double total = WGS84_AREA_M2;
        if (is_null(&c, r) || (has_unit && is_null(&u, r))) {
            out_null(&o, r);
            continue;
        }
        if (has_unit && !area_total(info, x->name, &((duckdb_string_t *)u.data)[r], &total)) return;
        if (!id_get(&c, x->kind, r, &cell)) {
            out_null(&o, r);
            continue;
        }
        ((double *)o.data)[r] = total / cells_at(dggs_get_level(cell));
    }
}

/* dggs_get_base_cells() -> the 20 level-0 cells, BIGINT[] or VARCHAR[] (_str). */
static void base_cells(duckdb_function_info info, duckdb_data_chunk in, duckdb_vector outv) {
    const fn_extra *x = extra_of(info);
    idx_t n = duckdb_data_chunk_get_size(in);
    list_out_t l = list_of(outv);
    dggs_cell faces[DGGS_NUM_FACES];
    for (int f = 0; f < DGGS_NUM_FACES; f++) {
        char s[2] = {(char)('A' + f), '\0'};
        dggs_string_to_cell(s, &faces[f]);
    }
    ROWS(n) list_push_ids(&l, r, x->kind, faces, DGGS_NUM_FACES);
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
        double cells = cells_at(level);
        int64_t count = (int64_t)cells;
        if (x->variant == 0) {
            ((int64_t *)o.data)[r] = count;
            continue;
        }
        double total;
        if (!area_total(info, x->name, &((duckdb_string_t *)u.data)[r], &total)) return;
        ((double *)o.data)[r] = total / cells;
    }
}

void register_levels(duckdb_connection con) {
    reg(con, "dggs_get_face", "I", 'N', face_and_neighbors, 1, K_NONE, 0);
    reg(con, "dggs_edge_neighbors", "I", 'E', face_and_neighbors, 1, K_NONE, 1);
    reg(con, "dggs_are_neighbor_cells", "II", 'O', are_neighbors, 1, K_NONE, 0);
    reg(con, "dggs_get_num_cells", "B", 'B', level_table, 0, K_NONE, 0);
    reg(con, "dggs_level_area", "BV", 'D', level_table, 0, K_NONE, 1);
    reg(con, "dggs_cell_area", "I|IV", 'D', cell_area_unit, 1, K_NONE, 0);
    reg(con, "dggs_get_base_cells", "", 'E', base_cells, 0, K_BIGINT, 0);
    reg(con, "dggs_get_base_cells_str", "", 'E', base_cells, 0, K_VARCHAR, 0);
}
