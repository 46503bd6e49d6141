/* The dggs DuckDB extension: helpers shared by its source files (reading DuckDB vectors, writing results).
 *
 * Built against DuckDB's C extension API (duckdb_extension.h) at the stable version v1.2.0, so one build loads in
 * every DuckDB from 1.2.0 on that keeps the v1 API (docs/duckdb.md). Every scalar function here reads flat input
 * vectors (the C API flattens a chunk before calling) and writes a flat output vector; DuckDB runs them on its own
 * threads, and the core (libdggs) has no global state, so nothing here locks. */
#ifndef DGGS_DUCKDB_EXT_H
#define DGGS_DUCKDB_EXT_H

#include <stdbool.h>
#include <stdint.h>
#include <string.h>

#include "duckdb_extension.h"
#include "dggs.h"

DUCKDB_EXTENSION_EXTERN

/* The three SQL forms of an id (docs/duckdb.md): BIGINT, UBIGINT and VARCHAR ('C401'). */
typedef enum { K_BIGINT = 0, K_UBIGINT = 1, K_VARCHAR = 2, K_NONE = 3 } id_kind;

/* What a registered overload knows about itself: the name (for error messages), its id kind, a variant number. */
typedef struct {
    const char *name;
    id_kind kind;
    int variant;
} fn_extra;

/* An input column: its data and validity (NULL when every row is valid). */
typedef struct {
    duckdb_vector vec;
    void *data;
    uint64_t *validity;
} col_t;

/* The output vector, its data, and its validity once a row was set NULL. */
typedef struct {
    duckdb_vector vec;
    void *data;
    uint64_t *validity;
} out_t;

/* A LIST output: entries, and the size of the child vector so far. */
typedef struct {
    duckdb_vector vec;
    duckdb_list_entry *entries;
    idx_t size;
} list_out_t;

static inline col_t col_of(duckdb_data_chunk chunk, idx_t i) {
    col_t c;
    c.vec = duckdb_data_chunk_get_vector(chunk, i);
    c.data = duckdb_vector_get_data(c.vec);
    c.validity = duckdb_vector_get_validity(c.vec);
    return c;
}

static inline bool is_null(const col_t *c, idx_t row) {
    return c->validity && !((c->validity[row >> 6] >> (row & 63)) & 1);
}

static inline out_t out_of(duckdb_vector v) {
    out_t o;
    o.vec = v;
    o.data = duckdb_vector_get_data(v);
    o.validity = NULL;
    return o;
}

static inline void out_null(out_t *o, idx_t row) {
    if (!o->validity) {
        duckdb_vector_ensure_validity_writable(o->vec);
        o->validity = duckdb_vector_get_validity(o->vec);
    }
    o->validity[row >> 6] &= ~((uint64_t)1 << (row & 63));
}

/* The bytes and length of a VARCHAR or BLOB value. */
static inline const char *str_data(duckdb_string_t *s, uint32_t *len) {
    *len = s->value.inlined.length;
    return *len <= 12 ? s->value.inlined.inlined : s->value.pointer.ptr;
}

/* 1 and the id into *cell if row `row` of `c` (an id of kind `kind`) is a cell id, else 0. */
static inline int id_get(const col_t *c, id_kind kind, idx_t row, dggs_cell *cell) {
    if (kind == K_VARCHAR) {
        uint32_t n;
        const char *s = str_data(&((duckdb_string_t *)c->data)[row], &n);
        char buf[DGGS_MAX_CHARS + 1];
        if (n == 0 || n > DGGS_MAX_CHARS || memchr(s, '\0', n)) return 0; /* 'C401\0x' is no id */
        memcpy(buf, s, n);
        buf[n] = '\0';
        return dggs_string_to_cell(buf, cell) == DGGS_OK;
    }
    *cell = ((uint64_t *)c->data)[row];
    return dggs_is_valid_cell(*cell);
}

/* Write id `cell` at `row` of a vector of ids of kind `kind` (data its data). */
static inline void id_put(duckdb_vector vec, void *data, id_kind kind, idx_t row, dggs_cell cell) {
    if (kind == K_VARCHAR) {
        char buf[DGGS_MAX_CHARS + 1];
        if (dggs_cell_to_string(cell, buf, sizeof buf) != DGGS_OK) buf[0] = '\0';
        duckdb_vector_assign_string_element_len(vec, row, buf, strlen(buf));
    } else {
        ((uint64_t *)data)[row] = cell;
    }
}

/* The level in row `row` of a BIGINT column, or -1 outside 0..DGGS_MAX_LEVEL. */
static inline int level_get(const col_t *c, idx_t row) {
    int64_t v = ((int64_t *)c->data)[row];
    return v < 0 || v > DGGS_MAX_LEVEL ? -1 : (int)v;
}

/* The projection named in row `row` of a VARCHAR column ('ISEA' or 'IVEA', any case) into *proj: false, and the
 * query's error set naming the value, for another name. */
bool proj_get(duckdb_function_info info, const char *name, const col_t *c, idx_t row, dggs_projection *proj);

static inline const fn_extra *extra_of(duckdb_function_info info) {
    return (const fn_extra *)duckdb_scalar_function_get_extra_info(info);
}

/* The WGS84 ellipsoid's area in m^2 (dggs.geometry.authalic.WGS84.area): a level's cells share it equally. */
#define WGS84_AREA_M2 0x1.cfe6e831ebb87p+48

/* Most ids one row's list may hold (2^27 ids, 1 GiB): past it the query fails with an error naming the function. */
#define MAX_LIST_CELLS ((int64_t)1 << 27)

/* LIST outputs: start, append n ids of kind `kind` as row `row`'s list, or n doubles pairs (lat, lng structs). */
list_out_t list_of(duckdb_vector v);
/* Returns false if DuckDB could not reserve the room. */
bool list_push_ids(list_out_t *l, idx_t row, id_kind kind, const dggs_cell *cells, idx_t n);
bool list_push_latlng(list_out_t *l, idx_t row, const double *lat_lng, idx_t n);
void list_empty(list_out_t *l, idx_t row);

/* The ids of row `row` of a LIST column of ids (NULL elements skipped) into a malloc'd array (*out, *n): 1 if all
 * are cell ids, 0 if one is not (*out is then freed and NULL), -1 if malloc failed. */
int list_ids_get(const col_t *c, id_kind kind, idx_t row, dggs_cell **out, idx_t *n);

/* Geometry writers (ext_common.c) for the polygons of ext_cells.c and the dissolve of ext_dissolve.c; each
 * returns the length written so far. Points are (lng, lat) pairs, a ring's n points not closed: the writers close
 * it. WKB is little-endian (OGC Simple Features' well-known binary): wkb_head writes a geometry's byte order and
 * type (3 Polygon, 6 MultiPolygon) and its count of parts (rings, or polygons); wkb_ring a ring's point count and
 * points. wkt_ring writes "(x y, ..., x0 y0)", prefixed by ", " unless it is the first. */
size_t wkb_head(uint8_t *b, size_t at, uint32_t type, uint32_t count);
size_t wkb_ring(uint8_t *b, size_t at, const double *pts, size_t n);
size_t wkt_ring(char *t, size_t at, const double *pts, size_t n, bool first);

/* Registration (ext_common.c): one overload per id kind unless per_kind is 0 (then kind is `kind`). Parameter and
 * return codes: I an id, L a list of ids, E a list of ids (same kind) as output, W a list of VARCHAR, D DOUBLE,
 * B BIGINT, N INTEGER, V VARCHAR, X BLOB, G GEOMETRY (WKB, DuckDB 1.5 on: geometry_type_exists), O BOOLEAN,
 * S STRUCT(lat, lng), P a list of STRUCT(lat, lng), J STRUCT(i, j); overloads with other parameters are separated
 * by '|' ("I|IB"). */
void reg(duckdb_connection con, const char *name, const char *params, char ret, duckdb_scalar_function_t fn,
         int per_kind, id_kind kind, int variant);

/* Whether this DuckDB has the GEOMETRY type in its core (1.5 on; duckdb.h's DUCKDB_TYPE_GEOMETRY, a WKB blob). */
bool geometry_type_exists(void);

void register_cells(duckdb_connection con);
void register_grid(duckdb_connection con);
void register_edges(duckdb_connection con);
void register_fill(duckdb_connection con);
void register_levels(duckdb_connection con);
void register_vertex(duckdb_connection con);
void register_dissolve(duckdb_connection con);

#endif
