/* The helpers the extension's function files share (ext.h): LIST outputs and inputs, the projection argument,
 * the GEOMETRY probe and the registration of a function's overloads. */
#include <stdio.h>
#include <stdlib.h>

#include "ext.h"

/* ---- LIST outputs ---- */

list_out_t list_of(duckdb_vector v) {
    list_out_t l;
    l.vec = v;
    l.entries = (duckdb_list_entry *)duckdb_vector_get_data(v);
    l.size = duckdb_list_vector_get_size(v);
    return l;
}

void list_empty(list_out_t *l, idx_t row) {
    l->entries[row].offset = l->size;
    l->entries[row].length = 0;
}

bool list_push_ids(list_out_t *l, idx_t row, id_kind kind, const dggs_cell *cells, idx_t n) {
    if (duckdb_list_vector_reserve(l->vec, l->size + n) != DuckDBSuccess) return false;
    duckdb_vector child = duckdb_list_vector_get_child(l->vec);
    void *data = duckdb_vector_get_data(child); /* after the reserve, which may move it */
    for (idx_t i = 0; i < n; i++) id_put(child, data, kind, l->size + i, cells[i]);
    l->entries[row].offset = l->size;
    l->entries[row].length = n;
    l->size += n;
    duckdb_list_vector_set_size(l->vec, l->size);
    return true;
}

bool list_push_latlng(list_out_t *l, idx_t row, const double *lat_lng, idx_t n) {
    if (duckdb_list_vector_reserve(l->vec, l->size + n) != DuckDBSuccess) return false;
    duckdb_vector child = duckdb_list_vector_get_child(l->vec);
    double *lat = (double *)duckdb_vector_get_data(duckdb_struct_vector_get_child(child, 0));
    double *lng = (double *)duckdb_vector_get_data(duckdb_struct_vector_get_child(child, 1));
    for (idx_t i = 0; i < n; i++) {
        lat[l->size + i] = lat_lng[2 * i];
        lng[l->size + i] = lat_lng[2 * i + 1];
    }
    l->entries[row].offset = l->size;
    l->entries[row].length = n;
    l->size += n;
    duckdb_list_vector_set_size(l->vec, l->size);
    return true;
}

int list_ids_get(const col_t *c, id_kind kind, idx_t row, dggs_cell **out, idx_t *n) {
    duckdb_list_entry e = ((duckdb_list_entry *)c->data)[row];
    col_t child;
    child.vec = duckdb_list_vector_get_child(c->vec);
    child.data = duckdb_vector_get_data(child.vec);
    child.validity = duckdb_vector_get_validity(child.vec);
    dggs_cell *ids = (dggs_cell *)malloc((e.length ? e.length : 1) * sizeof(dggs_cell));
    if (!ids) return -1;
    idx_t m = 0;
    for (idx_t i = e.offset; i < e.offset + e.length; i++) {
        if (is_null(&child, i)) continue; /* NULL elements are skipped */
        if (!id_get(&child, kind, i, &ids[m])) {
            free(ids);
            *out = NULL;
            return 0;
        }
        m++;
    }
    *out = ids;
    *n = m;
    return 1;
}

bool proj_get(duckdb_function_info info, const char *name, const col_t *c, idx_t row, dggs_projection *proj) {
    uint32_t n;
    const char *s = str_data(&((duckdb_string_t *)c->data)[row], &n);
    if (n == 4 && (s[0] | 0x20) == 'i' && (s[2] | 0x20) == 'e' && (s[3] | 0x20) == 'a' &&
        ((s[1] | 0x20) == 's' || (s[1] | 0x20) == 'v')) {
        *proj = (s[1] | 0x20) == 's' ? DGGS_ISEA : DGGS_IVEA;
        return true;
    }
    char msg[160];
    snprintf(msg, sizeof msg, "%s: projection '%.*s' is not 'ISEA' or 'IVEA'", name, (int)(n > 40 ? 40 : n), s);
    duckdb_scalar_function_set_error(info, msg);
    return false;
}

/* ---- registration ---- */

/* duckdb.h (1.5 on): DUCKDB_TYPE_GEOMETRY = 40, stored as WKB; the v1.2.0 headers do not name it. */
#define TYPE_GEOMETRY ((duckdb_type)40)

bool geometry_type_exists(void) {
    duckdb_logical_type t = duckdb_create_logical_type(TYPE_GEOMETRY);
    bool ok = t && duckdb_get_type_id(t) == TYPE_GEOMETRY;
    if (t) duckdb_destroy_logical_type(&t);
    return ok;
}

static duckdb_logical_type type_of(char code, id_kind kind) {
    static const duckdb_type ids[] = {DUCKDB_TYPE_BIGINT, DUCKDB_TYPE_UBIGINT, DUCKDB_TYPE_VARCHAR, DUCKDB_TYPE_BIGINT};
    duckdb_logical_type t, inner;
    switch (code) {
    case 'I':
        return duckdb_create_logical_type(ids[kind]);
    case 'L':
    case 'E':
        inner = duckdb_create_logical_type(ids[kind]);
        t = duckdb_create_list_type(inner);
        duckdb_destroy_logical_type(&inner);
        return t;
    case 'W':
        inner = duckdb_create_logical_type(DUCKDB_TYPE_VARCHAR);
        t = duckdb_create_list_type(inner);
        duckdb_destroy_logical_type(&inner);
        return t;
    case 'D':
        return duckdb_create_logical_type(DUCKDB_TYPE_DOUBLE);
    case 'B':
        return duckdb_create_logical_type(DUCKDB_TYPE_BIGINT);
    case 'N':
        return duckdb_create_logical_type(DUCKDB_TYPE_INTEGER);
    case 'V':
        return duckdb_create_logical_type(DUCKDB_TYPE_VARCHAR);
    case 'G':
        return duckdb_create_logical_type(TYPE_GEOMETRY);
    case 'X':
        return duckdb_create_logical_type(DUCKDB_TYPE_BLOB);
    case 'O':
        return duckdb_create_logical_type(DUCKDB_TYPE_BOOLEAN);
    case 'S':
    case 'P':
    case 'J': {
        const char *names_ll[] = {"lat", "lng"}, *names_ij[] = {"i", "j"};
        duckdb_logical_type members[2];
        members[0] = duckdb_create_logical_type(code == 'J' ? DUCKDB_TYPE_BIGINT : DUCKDB_TYPE_DOUBLE);
        members[1] = duckdb_create_logical_type(code == 'J' ? DUCKDB_TYPE_BIGINT : DUCKDB_TYPE_DOUBLE);
        t = duckdb_create_struct_type(members, code == 'J' ? names_ij : names_ll, 2);
        duckdb_destroy_logical_type(&members[0]);
        duckdb_destroy_logical_type(&members[1]);
        if (code == 'P') {
            inner = t;
            t = duckdb_create_list_type(inner);
            duckdb_destroy_logical_type(&inner);
        }
        return t;
    }
    default:
        return duckdb_create_logical_type(DUCKDB_TYPE_SQLNULL);
    }
}

void reg(duckdb_connection con, const char *name, const char *params, char ret, duckdb_scalar_function_t fn,
         int per_kind, id_kind kind, int variant) {
    duckdb_scalar_function_set set = duckdb_create_scalar_function_set(name);
    for (const char *alt = params; alt; alt = strchr(alt, '|') ? strchr(alt, '|') + 1 : NULL)
    for (int k = per_kind ? 0 : (int)kind; k <= (per_kind ? 2 : (int)kind); k++) {
        duckdb_scalar_function f = duckdb_create_scalar_function();
        duckdb_scalar_function_set_name(f, name);
        for (const char *p = alt; *p && *p != '|'; p++) {
            duckdb_logical_type t = type_of(*p, (id_kind)k);
            duckdb_scalar_function_add_parameter(f, t);
            duckdb_destroy_logical_type(&t);
        }
        duckdb_logical_type r = type_of(ret, (id_kind)k);
        duckdb_scalar_function_set_return_type(f, r);
        duckdb_destroy_logical_type(&r);
        fn_extra *x = (fn_extra *)malloc(sizeof *x);
        x->name = name;
        x->kind = (id_kind)k;
        x->variant = variant;
        duckdb_scalar_function_set_extra_info(f, x, free);
        duckdb_scalar_function_set_function(f, fn);
        duckdb_add_scalar_function_to_set(set, f);
        duckdb_destroy_scalar_function(&f);
    }
    duckdb_register_scalar_function_set(con, set);
    duckdb_destroy_scalar_function_set(&set);
}

static size_t put_u32(uint8_t *b, size_t at, uint32_t v) {
    memcpy(b + at, &v, 4);
    return at + 4;
}

size_t wkb_head(uint8_t *b, size_t at, uint32_t type, uint32_t count) {
    b[at++] = 1; /* little-endian (NDR) */
    return put_u32(b, put_u32(b, at, type), count);
}

size_t wkb_ring(uint8_t *b, size_t at, const double *pts, size_t n) {
    at = put_u32(b, at, (uint32_t)n + 1);
    for (size_t i = 0; i <= n; i++, at += 16) memcpy(b + at, pts + 2 * (i % n), 16);
    return at;
}

size_t wkt_ring(char *t, size_t at, const double *pts, size_t n, bool first) {
    at += (size_t)sprintf(t + at, first ? "(" : ", (");
    for (size_t i = 0; i <= n; i++) {
        const double *xy = pts + 2 * (i % n);
        at += (size_t)sprintf(t + at, "%s%.17g %.17g", i ? ", " : "", xy[0], xy[1]);
    }
    return at + (size_t)sprintf(t + at, ")");
}
