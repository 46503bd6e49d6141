/* Vertices (cell corners): dggs_cell_to_vertexes, dggs_vertex_to_latlng, dggs_is_valid_vertex (index/vertex.py's
 * names and vertex ids, "<owner>:<index>", over the core's dggs_cell_to_vertexes). A vertex id that names no
 * corner gives NULL (dggs_is_valid_vertex false), as the extension's other functions do for a non-id. */
#include <stdio.h>

#include "ext.h"

/* (owner, index) of the vertex id in row `row` of a VARCHAR column: 1 if it is of the form '<cell>:<0-2>'. */
static int vertex_get(const col_t *c, idx_t row, dggs_cell *owner, int *index) {
    uint32_t n;
    const char *s = str_data(&((duckdb_string_t *)c->data)[row], &n);
    char buf[DGGS_MAX_CHARS + 1];
    if (n < 3 || n - 2 > DGGS_MAX_CHARS || s[n - 2] != ':' || s[n - 1] < '0' || s[n - 1] > '2') return 0;
    if (memchr(s, '\0', n) || memchr(s, ':', n - 2)) return 0;
    memcpy(buf, s, n - 2);
    buf[n - 2] = '\0';
    *index = s[n - 1] - '0';
    return dggs_string_to_cell(buf, owner) == DGGS_OK;
}

/* dggs_cell_to_vertexes(cell) -> VARCHAR[]: the three vertex ids. */
static void cell_to_vertexes(duckdb_function_info info, duckdb_data_chunk in, duckdb_vector outv) {
    const fn_extra *x = extra_of(info);
    idx_t n = duckdb_data_chunk_get_size(in);
    col_t c = col_of(in, 0);
    out_t o = out_of(outv);
    list_out_t l = list_of(outv);
    for (idx_t r = 0; r < n; r++) {
        dggs_cell cell, owners[3];
        int index[3];
        list_empty(&l, r);
        if (is_null(&c, r) || !id_get(&c, x->kind, r, &cell) || dggs_cell_to_vertexes(cell, owners, index) != DGGS_OK) {
            out_null(&o, r);
            continue;
        }
        if (duckdb_list_vector_reserve(l.vec, l.size + 3) != DuckDBSuccess) {
            duckdb_scalar_function_set_error(info, "dggs_cell_to_vertexes: out of memory");
            return;
        }
        duckdb_vector child = duckdb_list_vector_get_child(l.vec);
        for (int i = 0; i < 3; i++) {
            char buf[DGGS_MAX_CHARS + 4];
            if (dggs_cell_to_string(owners[i], buf, DGGS_MAX_CHARS + 1) != DGGS_OK) buf[0] = '\0';
            size_t len = strlen(buf);
            buf[len] = ':', buf[len + 1] = (char)('0' + index[i]);
            duckdb_vector_assign_string_element_len(child, l.size + (idx_t)i, buf, len + 2);
        }
        l.entries[r].offset = l.size;
        l.entries[r].length = 3;
        l.size += 3;
        duckdb_list_vector_set_size(l.vec, l.size);
    }
}

/* dggs_vertex_to_latlng(vertex[, projection]) -> STRUCT(lat, lng) (variant 0); dggs_is_valid_vertex -> BOOLEAN (1). */
static void vertex_fn(duckdb_function_info info, duckdb_data_chunk in, duckdb_vector outv) {
    const fn_extra *x = extra_of(info);
    idx_t n = duckdb_data_chunk_get_size(in);
    int has_proj = duckdb_data_chunk_get_column_count(in) > 1;
    col_t c = col_of(in, 0), pc = has_proj ? col_of(in, 1) : c;
    out_t o = out_of(outv), olat, olng;
    dggs_projection proj = DGGS_ISEA;
    if (x->variant == 0) {
        olat = out_of(duckdb_struct_vector_get_child(outv, 0));
        olng = out_of(duckdb_struct_vector_get_child(outv, 1));
    }
    for (idx_t r = 0; r < n; r++) {
        dggs_cell owner;
        int index;
        double lat, lng;
        if (has_proj && !is_null(&pc, r) && !proj_get(info, x->name, &pc, r, &proj)) return;
        int ok = !is_null(&c, r) && !(has_proj && is_null(&pc, r)) && vertex_get(&c, r, &owner, &index);
        if (x->variant == 1) {
            if (is_null(&c, r))
                out_null(&o, r);
            else
                ((bool *)o.data)[r] = ok && dggs_is_valid_vertex(owner, index);
        } else if (!ok || dggs_vertex_to_latlng(owner, index, proj, &lat, &lng) != DGGS_OK) {
            out_null(&o, r);
            out_null(&olat, r);
            out_null(&olng, r);
        } else {
            ((double *)olat.data)[r] = lat;
            ((double *)olng.data)[r] = lng;
        }
    }
}

void register_vertex(duckdb_connection con) {
    reg(con, "dggs_cell_to_vertexes", "I", 'W', cell_to_vertexes, 1, K_NONE, 0);
    reg(con, "dggs_vertex_to_latlng", "V|VV", 'S', vertex_fn, 0, K_VARCHAR, 0);
    reg(con, "dggs_is_valid_vertex", "V", 'O', vertex_fn, 0, K_VARCHAR, 1);
}
