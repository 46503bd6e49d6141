/* Polygon fill: dggs_polygon_to_cells(geometry, level, mode) -> BIGINT[] and dggs_polygon_to_cells_str -> VARCHAR[],
 * the geometry a (Multi)Polygon as WKB (BLOB) or WKT (VARCHAR), in (lng, lat) degrees, longitudes in -180..180.
 * A level outside 0..28 gives NULL (as the h3 extension); a geometry that is not a (Multi)Polygon, an unknown mode
 * or coordinates out of range are errors naming them. */
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
    ROWS(n) {
        int level, mode;
        uint32_t len, mlen;
        int64_t size, count;
        dggs_error err;
        list_empty(&l, r);
        if (has_proj && !is_null(&pc, r) && !proj_get(info, x->name, &pc, r, &proj)) break;
        if (is_null(&g, r) || is_null(&lv, r) || is_null(&m, r) || (has_proj && is_null(&pc, r)) ||
            (level = level_get(&lv, r)) < 0) {
            out_null(&o, r);
            continue;
        }
        const char *ms = str_data(&((duckdb_string_t *)m.data)[r], &mlen);
        if ((mode = mode_of(ms, mlen)) < 0) {
            snprintf(msg, sizeof msg, "%s: mode '%.*s' is not one of 'center', 'contains', 'overlaps', "
                     "'overlapping_bbox'", x->name, (int)(mlen > 40 ? 40 : mlen), ms);
            duckdb_scalar_function_set_error(info, msg);
            break;
        }
        const char *gs = str_data(&((duckdb_string_t *)g.data)[r], &len);
        p.n_pts = p.n_rings = 0;
        reader_t rd = {(const uint8_t *)gs, len, 0};
        bool ok = x->variant == 0 ? wkb_polygon(&rd, &p, 0) && rd.at == len : wkt_polygon(gs, len, &p);
        if (!ok) {
            snprintf(msg, sizeof msg, "%s: not a %s (Multi)Polygon in (lng, lat): %s%.*s", x->name,
                     x->variant == 0 ? "WKB" : "WKT", x->variant == 0 ? "" : "'",
                     x->variant == 0 ? 0 : (int)(len > 60 ? 60 : len), gs);
            if (x->variant == 1) strncat(msg, "'", sizeof msg - strlen(msg) - 1);
            duckdb_scalar_function_set_error(info, msg);
            break;
        }
        err = dggs_polygon_to_cells_size(p.pts, p.rings, (int64_t)p.n_rings, level, (dggs_fill_mode)mode, proj,
                                         &size);
        if (err == DGGS_OK && size > MAX_LIST_CELLS) {
            snprintf(msg, sizeof msg, "%s: the polygon holds more than %lld cells at level %d", x->name,
                     (long long)MAX_LIST_CELLS, level);
            duckdb_scalar_function_set_error(info, msg);
            break;
        }
        if (err == DGGS_OK) {
            free(cells);
            cells = (dggs_cell *)malloc((size_t)(size ? size : 1) * sizeof(dggs_cell));
            err = cells ? dggs_polygon_to_cells(p.pts, p.rings, (int64_t)p.n_rings, level, (dggs_fill_mode)mode,
                                                proj, cells, size, &count)
                        : DGGS_E_FAILED;
        }
        if (err != DGGS_OK) {
            snprintf(msg, sizeof msg, "%s: %s", x->name,
                     err == DGGS_E_LATLNG ? "a coordinate is not a longitude in -180..180 and a latitude in -90..90 "
                                            "(split a polygon that crosses the antimeridian)"
                                          : dggs_error_string(err));
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

void register_fill(duckdb_connection con) {
    reg(con, "dggs_polygon_to_cells", "XBV|XBVV", 'E', polygon_to_cells, 0, K_BIGINT, 0);
    reg(con, "dggs_polygon_to_cells_str", "XBV|XBVV", 'E', polygon_to_cells, 0, K_VARCHAR, 0);
    reg(con, "dggs_polygon_wkt_to_cells", "VBV|VBVV", 'E', polygon_to_cells, 0, K_BIGINT, 1);
    reg(con, "dggs_polygon_wkt_to_cells_str", "VBV|VBVV", 'E', polygon_to_cells, 0, K_VARCHAR, 1);
}
