/* Directed edges (docs/grid.md, "Directed edges"): an edge id is its "shadow" cell (one level finer than the origin)
 * with the sign bit set; its string id is the origin's string, a dot and the direction ("C401.2", shadow "C4012").
 * BIGINT edges are negative. An invalid edge or cell gives NULL, as the h3 extension does; a unit other than 'm',
 * 'km' or 'rads' is an error naming it. */
#include <stdio.h>
#include <stdlib.h>

#include "ext.h"

#define ROWS(n) for (idx_t r = 0; r < (n); r++)
#define EDGE_BIT ((uint64_t)1 << 63)

/* 1 and the edge into *edge if row `row` of `c` is a directed edge id of kind `kind`, else 0. */
static int edge_get(const col_t *c, id_kind kind, idx_t row, uint64_t *edge) {
    if (kind == K_VARCHAR) {
        uint32_t n;
        const char *s = str_data(&((duckdb_string_t *)c->data)[row], &n);
        char buf[DGGS_MAX_CHARS + 2];
        dggs_cell shadow;
        if (n < 3 || n > DGGS_MAX_CHARS + 1 || s[n - 2] != '.' || memchr(s, '\0', n)) return 0;
        memcpy(buf, s, n - 2);
        buf[n - 2] = s[n - 1];
        buf[n - 1] = '\0';
        if (dggs_string_to_cell(buf, &shadow) != DGGS_OK) return 0;
        *edge = shadow | EDGE_BIT;
    } else {
        *edge = ((uint64_t *)c->data)[row];
    }
    return dggs_is_valid_directed_edge(*edge);
}

static void edge_put(duckdb_vector vec, void *data, id_kind kind, idx_t row, uint64_t edge) {
    if (kind == K_VARCHAR) {
        char buf[DGGS_MAX_CHARS + 2];
        size_t n;
        if (dggs_cell_to_string(edge & ~EDGE_BIT, buf, sizeof buf - 1) != DGGS_OK) buf[0] = '\0';
        n = strlen(buf);
        if (n >= 2) { /* "C4012" -> "C401.2" */
            buf[n + 1] = '\0';
            buf[n] = buf[n - 1];
            buf[n - 1] = '.';
            n++;
        }
        duckdb_vector_assign_string_element_len(vec, row, buf, n);
    } else {
        ((uint64_t *)data)[row] = edge;
    }
}

/* One edge in: origin (0), destination (1), reverse (2) -> one id or edge; is_valid (3) -> BOOLEAN; cells (4),
 * boundary (5) -> lists. */
static void edge_unary(duckdb_function_info info, duckdb_data_chunk in, duckdb_vector outv) {
    const fn_extra *x = extra_of(info);
    idx_t n = duckdb_data_chunk_get_size(in);
    col_t c = col_of(in, 0);
    out_t o = out_of(outv);
    list_out_t l;
    if (x->variant >= 4) l = list_of(outv);
    ROWS(n) {
        uint64_t edge, other;
        dggs_cell cells[2];
        double pts[4];
        int ok;
        if (x->variant >= 4) list_empty(&l, r);
        if (is_null(&c, r)) {
            out_null(&o, r);
            continue;
        }
        ok = edge_get(&c, x->kind, r, &edge);
        if (x->variant == 3) {
            ((bool *)o.data)[r] = ok != 0;
            continue;
        }
        if (!ok) {
            out_null(&o, r);
            continue;
        }
        switch (x->variant) {
        case 0:
            ok = dggs_get_directed_edge_origin(edge, &other) == DGGS_OK;
            if (ok) id_put(outv, o.data, x->kind, r, other);
            break;
        case 1:
            ok = dggs_get_directed_edge_destination(edge, &other) == DGGS_OK;
            if (ok) id_put(outv, o.data, x->kind, r, other);
            break;
        case 2:
            ok = dggs_reverse_directed_edge(edge, &other) == DGGS_OK;
            if (ok) edge_put(outv, o.data, x->kind, r, other);
            break;
        case 4:
            ok = dggs_directed_edge_to_cells(edge, cells) == DGGS_OK;
            if (ok) list_push_ids(&l, r, x->kind, cells, 2);
            break;
        default:
            ok = dggs_directed_edge_to_boundary(edge, 0, DGGS_ISEA, pts, 2) == DGGS_OK;
            if (ok) list_push_latlng(&l, r, pts, 2);
            break;
        }
        if (!ok) out_null(&o, r);
    }
}

/* dggs_cells_to_directed_edge(origin, destination) -> edge. */
static void cells_to_edge(duckdb_function_info info, duckdb_data_chunk in, duckdb_vector outv) {
    const fn_extra *x = extra_of(info);
    idx_t n = duckdb_data_chunk_get_size(in);
    col_t a = col_of(in, 0), b = col_of(in, 1);
    out_t o = out_of(outv);
    ROWS(n) {
        dggs_cell ca, cb;
        uint64_t edge;
        if (is_null(&a, r) || is_null(&b, r) || !id_get(&a, x->kind, r, &ca) || !id_get(&b, x->kind, r, &cb) ||
            dggs_cells_to_directed_edge(ca, cb, &edge) != DGGS_OK) {
            out_null(&o, r);
            continue;
        }
        edge_put(outv, o.data, x->kind, r, edge);
    }
}

/* dggs_origin_to_directed_edges(cell) -> list of 3 edges. */
static void origin_to_edges(duckdb_function_info info, duckdb_data_chunk in, duckdb_vector outv) {
    const fn_extra *x = extra_of(info);
    idx_t n = duckdb_data_chunk_get_size(in);
    col_t c = col_of(in, 0);
    out_t o = out_of(outv);
    list_out_t l = list_of(outv);
    ROWS(n) {
        dggs_cell cell;
        uint64_t edges[3];
        list_empty(&l, r);
        if (is_null(&c, r) || !id_get(&c, x->kind, r, &cell) || dggs_origin_to_directed_edges(cell, edges) != DGGS_OK ||
            duckdb_list_vector_reserve(l.vec, l.size + 3) != DuckDBSuccess) {
            out_null(&o, r);
            continue;
        }
        duckdb_vector child = duckdb_list_vector_get_child(l.vec);
        void *data = duckdb_vector_get_data(child);
        for (idx_t i = 0; i < 3; i++) edge_put(child, data, x->kind, l.size + i, edges[i]);
        l.entries[r].offset = l.size;
        l.entries[r].length = 3;
        l.size += 3;
        duckdb_list_vector_set_size(l.vec, l.size);
    }
}

/* dggs_edge_length(edge, unit) -> DOUBLE: 'm', 'km' (WGS84) or 'rads' (the authalic sphere). */
static void edge_length(duckdb_function_info info, duckdb_data_chunk in, duckdb_vector outv) {
    const fn_extra *x = extra_of(info);
    idx_t n = duckdb_data_chunk_get_size(in);
    col_t c = col_of(in, 0), u = col_of(in, 1);
    out_t o = out_of(outv);
    ROWS(n) {
        uint64_t edge;
        uint32_t len;
        const char *unit;
        dggs_error err;
        if (is_null(&c, r) || is_null(&u, r)) {
            out_null(&o, r);
            continue;
        }
        unit = str_data(&((duckdb_string_t *)u.data)[r], &len);
        int which = len == 1 && unit[0] == 'm' ? 0 : len == 2 && !memcmp(unit, "km", 2) ? 1
                  : len == 4 && !memcmp(unit, "rads", 4) ? 2 : -1;
        if (which < 0) {
            char msg[200];
            snprintf(msg, sizeof msg, "%s: unit '%.*s' is not one of 'm', 'km', 'rads'", x->name,
                     (int)(len > 40 ? 40 : len), unit);
            duckdb_scalar_function_set_error(info, msg);
            return;
        }
        if (!edge_get(&c, x->kind, r, &edge)) {
            out_null(&o, r);
            continue;
        }
        double *v = &((double *)o.data)[r];
        err = which == 0 ? dggs_edge_length_m(edge, DGGS_ISEA, v)
            : which == 1 ? dggs_edge_length_km(edge, DGGS_ISEA, v) : dggs_edge_length_rads(edge, DGGS_ISEA, v);
        if (err != DGGS_OK) out_null(&o, r);
    }
}

void register_edges(duckdb_connection con) {
    reg(con, "dggs_get_directed_edge_origin", "I", 'I', edge_unary, 1, K_NONE, 0);
    reg(con, "dggs_get_directed_edge_destination", "I", 'I', edge_unary, 1, K_NONE, 1);
    reg(con, "dggs_reverse_directed_edge", "I", 'I', edge_unary, 1, K_NONE, 2);
    reg(con, "dggs_is_valid_directed_edge", "I", 'O', edge_unary, 1, K_NONE, 3);
    reg(con, "dggs_directed_edge_to_cells", "I", 'E', edge_unary, 1, K_NONE, 4);
    reg(con, "dggs_directed_edge_to_boundary", "I", 'P', edge_unary, 1, K_NONE, 5);
    reg(con, "dggs_cells_to_directed_edge", "II", 'I', cells_to_edge, 1, K_NONE, 0);
    reg(con, "dggs_origin_to_directed_edges", "I", 'E', origin_to_edges, 1, K_NONE, 0);
    reg(con, "dggs_edge_length", "IV", 'D', edge_length, 1, K_NONE, 0);
}
