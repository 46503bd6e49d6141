/* Polygon fill: dggs_polygon_to_cells(geometry, level, mode) -> BIGINT[] and dggs_polygon_to_cells_str -> VARCHAR[],
 * the geometry a (Multi)Polygon as WKB (BLOB) or WKT (VARCHAR), in (lng, lat) degrees, longitudes in -180..180.
 * A level outside 0..28 gives NULL (as the h3 extension); a geometry that is not a (Multi)Polygon, an unknown mode
 * or coordinates out of range are errors naming them. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "ext.h"

#define ROWS(n) for (idx_t r = 0; r < (n); r++)

/* A polygon being read: (lat, lng) pairs and ring sizes, grown as needed. */
typedef struct {
    double *pts;
    int64_t *rings;
    size_t n_pts, cap_pts, n_rings, cap_rings;
} poly_t;

static bool poly_point(poly_t *p, double lng, double lat) {
    if (p->n_pts == p->cap_pts) {
        size_t cap = p->cap_pts ? 2 * p->cap_pts : 64;
        double *grown = (double *)realloc(p->pts, 2 * cap * sizeof(double));
        if (!grown) return false;
        p->pts = grown;
        p->cap_pts = cap;
    }
    p->pts[2 * p->n_pts] = lat;
    p->pts[2 * p->n_pts + 1] = lng;
    p->n_pts++;
    p->rings[p->n_rings - 1]++;
    return true;
}

static bool poly_ring(poly_t *p) {
    if (p->n_rings == p->cap_rings) {
        size_t cap = p->cap_rings ? 2 * p->cap_rings : 8;
        int64_t *grown = (int64_t *)realloc(p->rings, cap * sizeof(int64_t));
        if (!grown) return false;
        p->rings = grown;
        p->cap_rings = cap;
    }
    p->rings[p->n_rings++] = 0;
    return true;
}

/* ---- WKB: Polygon (3) or MultiPolygon (6) of Polygons, 2D, either byte order ---- */

typedef struct {
    const uint8_t *b;
    size_t len, at;
} reader_t;

static bool rd_u32(reader_t *r, int little, uint32_t *v) {
    if (r->at + 4 > r->len) return false;
    const uint8_t *b = r->b + r->at;
    *v = little ? (uint32_t)b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16 | (uint32_t)b[3] << 24
                : (uint32_t)b[3] | (uint32_t)b[2] << 8 | (uint32_t)b[1] << 16 | (uint32_t)b[0] << 24;
    r->at += 4;
    return true;
}

static bool rd_f64(reader_t *r, int little, double *v) {
    uint8_t b[8];
    if (r->at + 8 > r->len) return false;
    for (int i = 0; i < 8; i++) b[i] = r->b[r->at + (size_t)(little ? i : 7 - i)];
    memcpy(v, b, 8); /* the machine is little-endian (x86, arm64) */
    r->at += 8;
    return true;
}

static bool wkb_polygon(reader_t *r, poly_t *p, int expect) {
    uint32_t type, rings, points;
    if (r->at >= r->len || r->b[r->at] > 1) return false;
    int little = r->b[r->at++];
    if (!rd_u32(r, little, &type) || (expect && type != (uint32_t)expect)) return false;
    if (type == 6) {
        uint32_t parts;
        if (!rd_u32(r, little, &parts)) return false;
        for (uint32_t i = 0; i < parts; i++)
            if (!wkb_polygon(r, p, 3)) return false;
        return true;
    }
    if (type != 3 || !rd_u32(r, little, &rings)) return false;
    for (uint32_t k = 0; k < rings; k++) {
        if (!rd_u32(r, little, &points) || (size_t)points * 16 > r->len - r->at || !poly_ring(p)) return false;
        for (uint32_t i = 0; i < points; i++) {
            double x, y;
            if (!rd_f64(r, little, &x) || !rd_f64(r, little, &y) || !poly_point(p, x, y)) return false;
        }
    }
    return true;
}

/* ---- WKT: POLYGON ((x y, ...), ...) or MULTIPOLYGON (((...)), ...), 2D, case-insensitive ---- */

static void skip_ws(const char *s, size_t n, size_t *at) {
    while (*at < n && (s[*at] == ' ' || s[*at] == '\t' || s[*at] == '\n' || s[*at] == '\r')) (*at)++;
}

static bool expect_char(const char *s, size_t n, size_t *at, char c) {
    skip_ws(s, n, at);
    if (*at < n && s[*at] == c) {
        (*at)++;
        return true;
    }
    return false;
}

static bool wkt_number(const char *s, size_t n, size_t *at, double *v) {
    char buf[64];
    size_t k = 0;
    skip_ws(s, n, at);
    while (*at < n && k < sizeof buf - 1 && strchr("0123456789+-.eE", s[*at])) buf[k++] = s[(*at)++];
    buf[k] = '\0';
    char *end;
    *v = strtod(buf, &end);
    return k > 0 && *end == '\0';
}

static bool wkt_rings(const char *s, size_t n, size_t *at, poly_t *p) {
    if (!expect_char(s, n, at, '(')) return false;
    do {
        if (!expect_char(s, n, at, '(') || !poly_ring(p)) return false;
        do {
            double x, y;
            if (!wkt_number(s, n, at, &x) || !wkt_number(s, n, at, &y) || !poly_point(p, x, y)) return false;
        } while (expect_char(s, n, at, ','));
        if (!expect_char(s, n, at, ')')) return false;
    } while (expect_char(s, n, at, ','));
    return expect_char(s, n, at, ')');
}

static bool keyword(const char *s, size_t n, size_t *at, const char *word) {
    size_t k = strlen(word);
    skip_ws(s, n, at);
    if (*at + k > n) return false;
    for (size_t i = 0; i < k; i++)
        if ((s[*at + i] | 0x20) != (word[i] | 0x20)) return false;
    *at += k;
    return true;
}

static bool wkt_polygon(const char *s, size_t n, poly_t *p) {
    size_t at = 0;
    if (keyword(s, n, &at, "MULTIPOLYGON")) {
        if (keyword(s, n, &at, "EMPTY")) return (skip_ws(s, n, &at), at == n);
        if (!expect_char(s, n, &at, '(')) return false;
        do {
            if (!wkt_rings(s, n, &at, p)) return false;
        } while (expect_char(s, n, &at, ','));
        if (!expect_char(s, n, &at, ')')) return false;
    } else if (keyword(s, n, &at, "POLYGON")) {
        if (keyword(s, n, &at, "EMPTY")) return (skip_ws(s, n, &at), at == n);
        if (!wkt_rings(s, n, &at, p)) return false;
    } else {
        return false;
    }
    skip_ws(s, n, &at);
    return at == n;
}

static int mode_of(const char *s, uint32_t n) {
    static const char *names[] = {"center", "contains", "overlaps", "overlapping_bbox"};
    for (int i = 0; i < 4; i++)
        if (strlen(names[i]) == n && !memcmp(names[i], s, n)) return i;
    return -1;
}

/* Most ids the first buffer of a fill is sized to from the polygon's extent (128 MiB; a fill that needs more
 * asks for it: a second descent). */
#define MAX_FIRST_GUESS ((int64_t)1 << 24)

/* The cells at `level` the polygon's lng/lat bounding box could hold, on the sphere, and a tenth more: the first
 * buffer's size, so that a fill runs one descent, not one to count and one to fill (BENCHMARKS.md, "The DuckDB
 * extension"). Level l has 20 * 6 * 3^(l - 1) cells (20 at level 0) of equal area. */
static int64_t fill_guess(const poly_t *p, int level) {
    double lat0 = 90.0, lat1 = -90.0, lng0 = 180.0, lng1 = -180.0;
    for (size_t i = 0; i < p->n_pts; i++) {
        lat0 = fmin(lat0, p->pts[2 * i]), lat1 = fmax(lat1, p->pts[2 * i]);
        lng0 = fmin(lng0, p->pts[2 * i + 1]), lng1 = fmax(lng1, p->pts[2 * i + 1]);
    }
    if (!(lat1 >= lat0 && lng1 >= lng0)) return 4096;
    const double rad = 3.14159265358979323846 / 180.0;
    double share = (lng1 - lng0) * rad * (sin(lat1 * rad) - sin(lat0 * rad)) / (4.0 * 3.14159265358979323846);
    double cells = level == 0 ? 20.0 : 120.0 * pow(3.0, (double)(level - 1));
    double guess = 1.1 * share * cells + 4096.0;
    return guess > (double)MAX_FIRST_GUESS ? MAX_FIRST_GUESS : (int64_t)guess;
}

/* The cells of geometry `gs` (len bytes; WKT if `wkt`, else WKB) at `level` by `mode` and `proj` into *cells (a
 * malloc'd buffer of *cap ids, grown as needed and kept for the next call; the caller frees it), their count into
 * *count: true, or false with the message into msg (naming `name`). One descent when the buffer is large enough
 * (the core says how many it needs when it is not: DGGS_E_BUFFER), two otherwise. */
static bool fill(const char *name, const char *gs, uint32_t len, int wkt, int level, int mode, dggs_projection proj,
                 poly_t *p, dggs_cell **cells, int64_t *cap, int64_t *count, char *msg, size_t msg_size) {
    dggs_error err;
    p->n_pts = p->n_rings = 0;
    reader_t rd = {(const uint8_t *)gs, len, 0};
    if (!(wkt ? wkt_polygon(gs, len, p) : wkb_polygon(&rd, p, 0) && rd.at == len)) {
        snprintf(msg, msg_size, "%s: not a %s (Multi)Polygon in (lng, lat)%s%.*s%s", name, wkt ? "WKT" : "WKB",
                 wkt ? ": '" : "", wkt ? (int)(len > 60 ? 60 : len) : 0, gs, wkt ? "'" : "");
        return false;
    }
    int64_t guess = fill_guess(p, level);
    if (*cells && *cap < guess) {
        free(*cells);
        *cells = NULL;
    }
    for (int attempt = 0; attempt < 2; attempt++) {
        if (!*cells) {
            *cap = guess;
            *cells = (dggs_cell *)malloc((size_t)*cap * sizeof(dggs_cell));
            if (!*cells) {
                snprintf(msg, msg_size, "%s: out of memory", name);
                return false;
            }
        }
        err = dggs_polygon_to_cells(p->pts, p->rings, (int64_t)p->n_rings, level, (dggs_fill_mode)mode, proj, *cells,
                                    *cap, count);
        if (err != DGGS_E_BUFFER) break;
        if (*count > MAX_LIST_CELLS) {
            snprintf(msg, msg_size, "%s: the polygon holds more than %lld cells at level %d", name,
                     (long long)MAX_LIST_CELLS, level);
            return false;
        }
        free(*cells);
        *cap = *count;
        *cells = (dggs_cell *)malloc((size_t)(*cap ? *cap : 1) * sizeof(dggs_cell));
        if (!*cells) {
            snprintf(msg, msg_size, "%s: out of memory", name);
            return false;
        }
    }
    if (err != DGGS_OK) {
        snprintf(msg, msg_size, "%s: %s", name,
                 err == DGGS_E_LATLNG ? "a coordinate is not a longitude in -180..180 and a latitude in -90..90 "
                                        "(split a polygon that crosses the antimeridian)"
                                      : dggs_error_string(err));
        return false;
    }
    return true;
}

/* The message for an unknown mode into msg; false (the mode is refused). */
static bool mode_error(const char *name, const char *ms, uint32_t mlen, char *msg, size_t msg_size) {
    snprintf(msg, msg_size, "%s: mode '%.*s' is not one of 'center', 'contains', 'overlaps', 'overlapping_bbox'", name,
             (int)(mlen > 40 ? 40 : mlen), ms);
    return false;
}

/* variant 0: WKB (BLOB), 1: WKT (VARCHAR); x->kind: the ids' kind out. */
static void polygon_to_cells(duckdb_function_info info, duckdb_data_chunk in, duckdb_vector outv) {
    const fn_extra *x = extra_of(info);
    idx_t n = duckdb_data_chunk_get_size(in);
    int has_proj = duckdb_data_chunk_get_column_count(in) > 3;
    col_t g = col_of(in, 0), lv = col_of(in, 1), m = col_of(in, 2), pc = has_proj ? col_of(in, 3) : g;
    dggs_projection proj = DGGS_ISEA;
    out_t o = out_of(outv);
    list_out_t l = list_of(outv);
    char msg[256];
    poly_t p = {0};
    dggs_cell *cells = NULL;
    int64_t cap = 0;
    ROWS(n) {
        int level, mode;
        uint32_t len, mlen;
        int64_t count;
        list_empty(&l, r);
        if (has_proj && !is_null(&pc, r) && !proj_get(info, x->name, &pc, r, &proj)) break;
        if (is_null(&g, r) || is_null(&lv, r) || is_null(&m, r) || (has_proj && is_null(&pc, r)) ||
            (level = level_get(&lv, r)) < 0) {
            out_null(&o, r);
            continue;
        }
        const char *ms = str_data(&((duckdb_string_t *)m.data)[r], &mlen);
        const char *gs = str_data(&((duckdb_string_t *)g.data)[r], &len);
        bool ok = (mode = mode_of(ms, mlen)) >= 0 ? fill(x->name, gs, len, x->variant, level, mode, proj, &p, &cells,
                                                         &cap, &count, msg, sizeof msg)
                                                  : mode_error(x->name, ms, mlen, msg, sizeof msg);
        if (!ok) {
            duckdb_scalar_function_set_error(info, msg);
            break;
        }
        if (!list_push_ids(&l, r, x->kind, cells, (idx_t)count)) {
            duckdb_scalar_function_set_error(info, "dggs_polygon_to_cells: too many cells for one list");
            break;
        }
    }
    free(cells);
    free(p.pts);
    free(p.rings);
}

/* ---- the same as table functions: SELECT cell FROM dggs_polygon_to_cells(geometry, level, mode [, projection :=
 * 'IVEA']), one row a cell, in id order; a NULL argument or a level outside 0..28 gives no rows ---- */

typedef struct {
    dggs_cell *cells;
    int64_t cap, count;
} fill_rows;

static void fill_rows_free(void *data) {
    fill_rows *f = (fill_rows *)data;
    free(f->cells);
    free(f);
}

static void fill_rows_bind(duckdb_bind_info info) {
    const fn_extra *x = (const fn_extra *)duckdb_bind_get_extra_info(info);
    duckdb_value g = duckdb_bind_get_parameter(info, 0), lv = duckdb_bind_get_parameter(info, 1),
                 m = duckdb_bind_get_parameter(info, 2), pv = duckdb_bind_get_named_parameter(info, "projection");
    fill_rows *f = (fill_rows *)calloc(1, sizeof *f);
    duckdb_logical_type t = duckdb_create_logical_type(x->kind == K_VARCHAR ? DUCKDB_TYPE_VARCHAR : DUCKDB_TYPE_BIGINT);
    duckdb_bind_add_result_column(info, "cell", t);
    duckdb_destroy_logical_type(&t);
    char msg[256];
    poly_t p = {0};
    dggs_projection proj = DGGS_ISEA;
    bool ok = f != NULL;
    if (ok && pv && !duckdb_is_null_value(pv)) {
        char *name = duckdb_get_varchar(pv);
        size_t n = strlen(name);
        ok = n == 4 && (name[0] | 0x20) == 'i' && ((name[1] | 0x20) == 's' || (name[1] | 0x20) == 'v') &&
             (name[2] | 0x20) == 'e' && (name[3] | 0x20) == 'a';
        if (ok)
            proj = (name[1] | 0x20) == 's' ? DGGS_ISEA : DGGS_IVEA;
        else
            snprintf(msg, sizeof msg, "%s: projection '%.40s' is not 'ISEA' or 'IVEA'", x->name, name);
        duckdb_free(name);
    }
    if (ok && !duckdb_is_null_value(g) && !duckdb_is_null_value(lv) && !duckdb_is_null_value(m)) {
        int64_t level = duckdb_get_int64(lv);
        char *ms = duckdb_get_varchar(m);
        int mode = mode_of(ms, (uint32_t)strlen(ms));
        if (mode < 0) ok = mode_error(x->name, ms, (uint32_t)strlen(ms), msg, sizeof msg);
        duckdb_free(ms);
        if (ok && level >= 0 && level <= DGGS_MAX_LEVEL) {
            if (x->variant == 1) {
                char *gs = duckdb_get_varchar(g);
                ok = fill(x->name, gs, (uint32_t)strlen(gs), 1, (int)level, mode, proj, &p, &f->cells, &f->cap, &f->count,
                          msg, sizeof msg);
                duckdb_free(gs);
            } else {
                duckdb_blob b = duckdb_get_blob(g);
                ok = fill(x->name, (const char *)b.data, (uint32_t)b.size, 0, (int)level, mode, proj, &p, &f->cells,
                          &f->cap, &f->count, msg, sizeof msg);
                duckdb_free(b.data);
            }
        }
    }
    free(p.pts);
    free(p.rings);
    duckdb_destroy_value(&g);
    duckdb_destroy_value(&lv);
    duckdb_destroy_value(&m);
    if (pv) duckdb_destroy_value(&pv);
    if (!f) {
        duckdb_bind_set_error(info, "dggs_polygon_to_cells: out of memory");
        return;
    }
    if (!ok) {
        fill_rows_free(f);
        duckdb_bind_set_error(info, msg);
        return;
    }
    duckdb_bind_set_cardinality(info, (idx_t)f->count, true);
    duckdb_bind_set_bind_data(info, f, fill_rows_free);
}

static void fill_rows_init(duckdb_init_info info) {
    int64_t *at = (int64_t *)calloc(1, sizeof *at);
    duckdb_init_set_init_data(info, at, free);
}

static void fill_rows_scan(duckdb_function_info info, duckdb_data_chunk out) {
    const fn_extra *x = (const fn_extra *)duckdb_function_get_extra_info(info);
    fill_rows *f = (fill_rows *)duckdb_function_get_bind_data(info);
    int64_t *at = (int64_t *)duckdb_function_get_init_data(info);
    int64_t n = f->count - *at;
    if (n > (int64_t)duckdb_vector_size()) n = (int64_t)duckdb_vector_size();
    duckdb_vector v = duckdb_data_chunk_get_vector(out, 0);
    void *data = duckdb_vector_get_data(v);
    for (int64_t i = 0; i < n; i++) id_put(v, data, x->kind, (idx_t)i, f->cells[*at + i]);
    *at += n;
    duckdb_data_chunk_set_size(out, (idx_t)n);
}

static void reg_rows(duckdb_connection con, const char *name, int wkt, id_kind kind) {
    duckdb_table_function tf = duckdb_create_table_function();
    duckdb_table_function_set_name(tf, name);
    duckdb_type types[3] = {wkt ? DUCKDB_TYPE_VARCHAR : DUCKDB_TYPE_BLOB, DUCKDB_TYPE_BIGINT, DUCKDB_TYPE_VARCHAR};
    for (int i = 0; i < 3; i++) {
        duckdb_logical_type t = duckdb_create_logical_type(types[i]);
        duckdb_table_function_add_parameter(tf, t);
        duckdb_destroy_logical_type(&t);
    }
    duckdb_logical_type vt = duckdb_create_logical_type(DUCKDB_TYPE_VARCHAR);
    duckdb_table_function_add_named_parameter(tf, "projection", vt);
    duckdb_destroy_logical_type(&vt);
    fn_extra *x = (fn_extra *)malloc(sizeof *x);
    x->name = name;
    x->kind = kind;
    x->variant = wkt;
    duckdb_table_function_set_extra_info(tf, x, free);
    duckdb_table_function_set_bind(tf, fill_rows_bind);
    duckdb_table_function_set_init(tf, fill_rows_init);
    duckdb_table_function_set_function(tf, fill_rows_scan);
    duckdb_register_table_function(con, tf);
    duckdb_destroy_table_function(&tf);
}

void register_fill(duckdb_connection con) {
    reg_rows(con, "dggs_polygon_to_cells", 0, K_BIGINT);
    reg_rows(con, "dggs_polygon_to_cells_str", 0, K_VARCHAR);
    reg_rows(con, "dggs_polygon_wkt_to_cells", 1, K_BIGINT);
    reg_rows(con, "dggs_polygon_wkt_to_cells_str", 1, K_VARCHAR);
    /* GEOMETRY is WKB in a string vector: the BLOB code reads it as it is */
    const char *wkb_in = geometry_type_exists() ? "XBV|XBVV|GBV|GBVV" : "XBV|XBVV";
    reg(con, "dggs_polygon_to_cells", wkb_in, 'E', polygon_to_cells, 0, K_BIGINT, 0);
    reg(con, "dggs_polygon_to_cells_str", wkb_in, 'E', polygon_to_cells, 0, K_VARCHAR, 0);
    reg(con, "dggs_polygon_wkt_to_cells", "VBV|VBVV", 'E', polygon_to_cells, 0, K_BIGINT, 1);
    reg(con, "dggs_polygon_wkt_to_cells_str", "VBV|VBVV", 'E', polygon_to_cells, 0, K_VARCHAR, 1);
}
