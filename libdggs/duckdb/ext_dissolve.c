/* Dissolve: dggs_cells_to_multi_polygon_wkt / _wkb / _geometry (h3's h3_cells_to_multi_polygon_wkt) over a LIST
 * of ids, through the core's dggs_cells_to_multi_polygon (libdggs/src/multipolygon.c), as the Python package's
 * dggs.cells_to_polygons draws it: always a MULTIPOLYGON (EMPTY for an empty list), shells counter-clockwise,
 * holes clockwise, (lng, lat). A NULL list gives NULL and NULL elements are skipped; a list with an invalid id
 * gives NULL, as dggs_compact_cells (and the h3 extension's list functions) do (docs/duckdb.md). */
#include <stdio.h>
#include <stdlib.h>

#include "ext.h"

#define ROWS(n) for (idx_t r = 0; r < (n); r++)

/* Most points per edge a query may ask for (as dggs_cell_to_boundary_wkt's). */
#define MAX_SQL_DENSIFY 1000

/* The answer's buffers, reused from row to row and grown to the sizes the core asks for. */
typedef struct {
    double *pts;
    int64_t *rings, *polys;
    char *text;
    int64_t np, nr, npo;
    size_t ntext;
} mp_buf;

static bool grow(mp_buf *b, int64_t np, int64_t nr, int64_t npo) {
    if (np > b->np) {
        double *p = (double *)realloc(b->pts, (size_t)np * 2 * sizeof(double));
        if (!p) return false;
        b->pts = p, b->np = np;
    }
    if (nr > b->nr) {
        int64_t *p = (int64_t *)realloc(b->rings, (size_t)nr * sizeof(int64_t));
        if (!p) return false;
        b->rings = p, b->nr = nr;
    }
    if (npo > b->npo) {
        int64_t *p = (int64_t *)realloc(b->polys, (size_t)npo * sizeof(int64_t));
        if (!p) return false;
        b->polys = p, b->npo = npo;
    }
    /* WKT: under 52 bytes a point ("%.17g %.17g, ", the closing point again), 8 a ring, 8 a polygon; WKB less */
    size_t text = (size_t)(np + nr) * 52 + (size_t)(nr + npo) * 8 + 64;
    if (text > b->ntext) {
        char *t = (char *)realloc(b->text, text);
        if (!t) return false;
        b->text = t, b->ntext = text;
    }
    return true;
}

/* The MULTIPOLYGON's WKT (variant 1) or WKB (2) into b->text; its length. */
static size_t write_multi(const mp_buf *b, int64_t npolys, int variant) {
    const double *p = b->pts;
    const int64_t *ring = b->rings;
    if (variant == 1) {
        char *t = b->text;
        if (npolys == 0) return (size_t)sprintf(t, "MULTIPOLYGON EMPTY");
        size_t len = (size_t)sprintf(t, "MULTIPOLYGON (");
        for (int64_t q = 0; q < npolys; q++) {
            len += (size_t)sprintf(t + len, q ? ", (" : "(");
            for (int64_t k = 0; k < b->polys[q]; k++, ring++) {
                len = wkt_ring(t, len, p, (size_t)*ring, k == 0);
                p += 2 * *ring;
            }
            len += (size_t)sprintf(t + len, ")");
        }
        return len + (size_t)sprintf(t + len, ")");
    }
    uint8_t *w = (uint8_t *)b->text;
    size_t len = wkb_head(w, 0, 6, (uint32_t)npolys);
    for (int64_t q = 0; q < npolys; q++) {
        len = wkb_head(w, len, 3, (uint32_t)b->polys[q]);
        for (int64_t k = 0; k < b->polys[q]; k++, ring++) {
            len = wkb_ring(w, len, p, (size_t)*ring);
            p += 2 * *ring;
        }
    }
    return len;
}

/* (cells [, densify] [, projection]): densify the points added along each outline edge, by default each edge
 * gets its cell's dggs_cell_to_boundary_wkt(cell) default. */
static void cells_to_multi_polygon(duckdb_function_info info, duckdb_data_chunk in, duckdb_vector outv) {
    const fn_extra *x = extra_of(info);
    idx_t n = duckdb_data_chunk_get_size(in), ncol = duckdb_data_chunk_get_column_count(in);
    bool has_densify = false;
    if (ncol > 1) {
        duckdb_logical_type t = duckdb_vector_get_column_type(duckdb_data_chunk_get_vector(in, 1));
        has_densify = duckdb_get_type_id(t) != DUCKDB_TYPE_VARCHAR;
        duckdb_destroy_logical_type(&t);
    }
    idx_t proj_at = has_densify ? 2 : 1;
    bool has_proj = ncol > proj_at;
    col_t c = col_of(in, 0), d = has_densify ? col_of(in, 1) : c, pc = has_proj ? col_of(in, proj_at) : c;
    out_t o = out_of(outv);
    mp_buf b;
    memset(&b, 0, sizeof b);
    if (!grow(&b, 1024, 16, 16)) {
        duckdb_scalar_function_set_error(info, "dggs_cells_to_multi_polygon: out of memory");
        return;
    }
    ROWS(n) {
        dggs_projection proj = DGGS_ISEA;
        if (is_null(&c, r) || (has_densify && is_null(&d, r)) || (has_proj && is_null(&pc, r))) {
            out_null(&o, r);
            continue;
        }
        if (has_proj && !proj_get(info, x->name, &pc, r, &proj)) break;
        int64_t densify = has_densify ? ((int64_t *)d.data)[r] : -1;
        if (has_densify && (densify < 0 || densify > MAX_SQL_DENSIFY)) {
            char msg[160];
            snprintf(msg, sizeof msg, "%s: densify %lld is out of range 0..%d", x->name, (long long)densify,
                     MAX_SQL_DENSIFY);
            duckdb_scalar_function_set_error(info, msg);
            break;
        }
        dggs_cell *ids = NULL;
        idx_t m = 0;
        int got = list_ids_get(&c, x->kind, r, &ids, &m);
        if (got < 0) {
            duckdb_scalar_function_set_error(info, "dggs_cells_to_multi_polygon: out of memory");
            break;
        }
        if (got == 0) { /* an invalid id */
            out_null(&o, r);
            continue;
        }
        int64_t np, nr, npo;
        dggs_error err = dggs_cells_to_multi_polygon(ids, m, (int)densify, proj, b.pts, b.np, b.rings, b.nr, b.polys,
                                                     b.npo, &np, &nr, &npo);
        if (err == DGGS_E_BUFFER) {
            if (!grow(&b, np, nr, npo)) {
                free(ids);
                duckdb_scalar_function_set_error(info, "dggs_cells_to_multi_polygon: out of memory");
                break;
            }
            err = dggs_cells_to_multi_polygon(ids, m, (int)densify, proj, b.pts, b.np, b.rings, b.nr, b.polys, b.npo,
                                              &np, &nr, &npo);
        }
        free(ids);
        if (err == DGGS_E_FAILED) {
            char msg[200];
            snprintf(msg, sizeof msg,
                     "%s: the outline of these %llu cells (coarse cells beside much finer ones) needs more than "
                     "50000000 cells of the finest level, or memory ran out",
                     x->name, (unsigned long long)m);
            duckdb_scalar_function_set_error(info, msg);
            break;
        }
        if (err != DGGS_OK || !grow(&b, np, nr, npo)) {
            out_null(&o, r);
            continue;
        }
        size_t len = write_multi(&b, npo, x->variant);
        duckdb_vector_assign_string_element_len(outv, r, b.text, len);
    }
    free(b.pts), free(b.rings), free(b.polys), free(b.text);
}

void register_dissolve(duckdb_connection con) {
    reg(con, "dggs_cells_to_multi_polygon_wkt", "L|LB|LBV|LV", 'V', cells_to_multi_polygon, 1, K_NONE, 1);
    reg(con, "dggs_cells_to_multi_polygon_wkb", "L|LB|LBV|LV", 'X', cells_to_multi_polygon, 1, K_NONE, 2);
    if (geometry_type_exists())
        reg(con, "dggs_cells_to_multi_polygon_geometry", "L|LB|LBV|LV", 'G', cells_to_multi_polygon, 1, K_NONE, 2);
}
