/* Points, centres, boundaries, ids and the hierarchy: one id (or point) per row.
 * An invalid id, coordinate or level gives NULL, as the h3 extension does (docs/duckdb.md). */
#include <stdio.h>
#include <stdlib.h>

#include "ext.h"

#define ROWS(n) for (idx_t r = 0; r < (n); r++)

/* dggs_latlng_to_cell(lat, lng, level) -> BIGINT (variant 0) or VARCHAR (its kind K_VARCHAR). */
static void latlng_to_cell(duckdb_function_info info, duckdb_data_chunk in, duckdb_vector outv) {
    const fn_extra *x = extra_of(info);
    idx_t n = duckdb_data_chunk_get_size(in);
    int has_proj = duckdb_data_chunk_get_column_count(in) > 3;
    col_t la = col_of(in, 0), ln = col_of(in, 1), lv = col_of(in, 2), pc = has_proj ? col_of(in, 3) : la;
    out_t o = out_of(outv);
    const double *lat = (const double *)la.data, *lng = (const double *)ln.data;
    dggs_projection proj = DGGS_ISEA;
    ROWS(n) {
        dggs_cell cell;
        int level;
        if (has_proj && !is_null(&pc, r) && !proj_get(info, x->name, &pc, r, &proj)) return;
        if (is_null(&la, r) || is_null(&ln, r) || is_null(&lv, r) || (has_proj && is_null(&pc, r)) ||
            (level = level_get(&lv, r)) < 0 || dggs_latlng_to_cell(lat[r], lng[r], level, proj, &cell) != DGGS_OK) {
            out_null(&o, r);
            continue;
        }
        id_put(outv, o.data, x->kind, r, cell);
    }
}

/* dggs_cell_to_latlng(cell) -> STRUCT(lat, lng) (variant 0), its lat (1) or lng (2). */
static void cell_to_latlng(duckdb_function_info info, duckdb_data_chunk in, duckdb_vector outv) {
    const fn_extra *x = extra_of(info);
    idx_t n = duckdb_data_chunk_get_size(in);
    int has_proj = duckdb_data_chunk_get_column_count(in) > 1;
    col_t c = col_of(in, 0), pc = has_proj ? col_of(in, 1) : c;
    out_t o = out_of(outv);
    dggs_projection proj = DGGS_ISEA;
    double *lat_out = NULL, *lng_out = NULL;
    out_t olat, olng;
    if (x->variant == 0) {
        olat = out_of(duckdb_struct_vector_get_child(outv, 0));
        olng = out_of(duckdb_struct_vector_get_child(outv, 1));
        lat_out = (double *)olat.data;
        lng_out = (double *)olng.data;
    }
    ROWS(n) {
        dggs_cell cell;
        double lat, lng;
        if (has_proj && !is_null(&pc, r) && !proj_get(info, x->name, &pc, r, &proj)) return;
        if (is_null(&c, r) || (has_proj && is_null(&pc, r)) || !id_get(&c, x->kind, r, &cell) ||
            dggs_cell_to_latlng(cell, proj, &lat, &lng) != DGGS_OK) {
            out_null(&o, r);
            if (x->variant == 0) {
                out_null(&olat, r);
                out_null(&olng, r);
            }
            continue;
        }
        if (x->variant == 0) {
            lat_out[r] = lat;
            lng_out[r] = lng;
        } else {
            ((double *)o.data)[r] = x->variant == 1 ? lat : lng;
        }
    }
}

/* dggs_cell_to_parent (variant 0) and dggs_cell_to_center_child (1): (cell, level) -> cell. */
static void cell_at_level(duckdb_function_info info, duckdb_data_chunk in, duckdb_vector outv) {
    const fn_extra *x = extra_of(info);
    idx_t n = duckdb_data_chunk_get_size(in);
    col_t c = col_of(in, 0), lv = col_of(in, 1);
    out_t o = out_of(outv);
    ROWS(n) {
        dggs_cell cell, found;
        int level;
        if (is_null(&c, r) || is_null(&lv, r) || !id_get(&c, x->kind, r, &cell) || (level = level_get(&lv, r)) < 0 ||
            (x->variant == 0 ? dggs_cell_to_parent(cell, level, &found)
                             : dggs_cell_to_center_child(cell, level, &found)) != DGGS_OK) {
            out_null(&o, r);
            continue;
        }
        id_put(outv, o.data, x->kind, r, found);
    }
}

/* dggs_cell_to_children(cell, level) -> list of ids. */
static void cell_to_children(duckdb_function_info info, duckdb_data_chunk in, duckdb_vector outv) {
    const fn_extra *x = extra_of(info);
    idx_t n = duckdb_data_chunk_get_size(in);
    col_t c = col_of(in, 0), lv = col_of(in, 1);
    out_t o = out_of(outv);
    list_out_t l = list_of(outv);
    ROWS(n) {
        dggs_cell cell, *kids;
        int level;
        int64_t size;
        list_empty(&l, r);
        if (is_null(&c, r) || is_null(&lv, r) || !id_get(&c, x->kind, r, &cell) || (level = level_get(&lv, r)) < 0 ||
            dggs_cell_to_children_size(cell, level, &size) != DGGS_OK) {
            out_null(&o, r);
            continue;
        }
        if (size > MAX_LIST_CELLS) {
            char msg[160];
            snprintf(msg, sizeof msg, "dggs_cell_to_children: a level-%d cell has more than %lld descendants at level %d",
                     dggs_get_level(cell), (long long)MAX_LIST_CELLS, level);
            duckdb_scalar_function_set_error(info, msg);
            return;
        }
        kids = (dggs_cell *)malloc((size_t)size * sizeof(dggs_cell));
        if (!kids) {
            duckdb_scalar_function_set_error(info, "dggs_cell_to_children: out of memory");
            return;
        }
        if (dggs_cell_to_children(cell, level, kids, size) != DGGS_OK) {
            out_null(&o, r);
        } else if (!list_push_ids(&l, r, x->kind, kids, (idx_t)size)) {
            free(kids);
            duckdb_scalar_function_set_error(info, "dggs_cell_to_children: too many cells for one list");
            return;
        }
        free(kids);
    }
}

/* dggs_get_level -> INTEGER (NULL for a non-id), dggs_is_valid_cell -> BOOLEAN (never NULL for a value). */
static void get_level(duckdb_function_info info, duckdb_data_chunk in, duckdb_vector outv) {
    const fn_extra *x = extra_of(info);
    idx_t n = duckdb_data_chunk_get_size(in);
    col_t c = col_of(in, 0);
    out_t o = out_of(outv);
    ROWS(n) {
        dggs_cell cell;
        int ok = !is_null(&c, r) && id_get(&c, x->kind, r, &cell);
        if (x->variant == 1) { /* is_valid */
            if (is_null(&c, r))
                out_null(&o, r);
            else
                ((bool *)o.data)[r] = ok != 0;
        } else if (!ok) {
            out_null(&o, r);
        } else {
            ((int32_t *)o.data)[r] = dggs_get_level(cell);
        }
    }
}

/* dggs_str_to_int -> BIGINT (the id checked), dggs_int_to_str -> VARCHAR: the output kind is x->variant. */
static void convert_id(duckdb_function_info info, duckdb_data_chunk in, duckdb_vector outv) {
    const fn_extra *x = extra_of(info);
    idx_t n = duckdb_data_chunk_get_size(in);
    col_t c = col_of(in, 0);
    out_t o = out_of(outv);
    ROWS(n) {
        dggs_cell cell;
        if (is_null(&c, r) || !id_get(&c, x->kind, r, &cell)) {
            out_null(&o, r);
            continue;
        }
        id_put(outv, o.data, (id_kind)x->variant, r, cell);
    }
}

/* Room for one row's boundary: `pts` (doubles) and `text` (bytes), grown to the densify a row asks. */
typedef struct {
    double *pts;
    char *text;
    size_t points; /* pts holds 2 points doubles */
} shape_buf;

static bool shape_room(shape_buf *b, int densify) {
    size_t points;
    if (dggs_cell_to_polygon_size(densify, &points) != DGGS_OK) return false;
    if (points <= b->points) return true;
    double *pts = (double *)realloc(b->pts, 2 * points * sizeof(double));
    if (pts) b->pts = pts;
    /* WKT: under 52 bytes a point ("%.17g %.17g, "), the parts' brackets; WKB: 16 bytes a point, 9 a part */
    char *text = (char *)realloc(b->text, points * 52 + 64 * DGGS_MAX_POLYGON_PARTS + 32);
    if (text) b->text = text;
    if (!pts || !text) return false;
    b->points = points;
    return true;
}

/* The WKT of parts (pts: (lng, lat), one part after another, not closed) into text; its length. */
static size_t polygon_wkt(const double *pts, const size_t *sizes, int parts, char *text) {
    size_t len = (size_t)sprintf(text, parts == 1 ? "POLYGON (" : "MULTIPOLYGON (");
    for (int p = 0; p < parts; p++) {
        if (parts > 1) len += (size_t)sprintf(text + len, p ? ", (" : "(");
        len = wkt_ring(text, len, pts, sizes[p], true);
        if (parts > 1) len += (size_t)sprintf(text + len, ")");
        pts += 2 * sizes[p];
    }
    return len + (size_t)sprintf(text + len, ")");
}

/* WKB: a Polygon (type 3) of one ring, or a MultiPolygon (6) of such Polygons; its length. */
static size_t polygon_wkb(const double *pts, const size_t *sizes, int parts, uint8_t *b) {
    size_t len = parts > 1 ? wkb_head(b, 0, 6, (uint32_t)parts) : 0;
    for (int p = 0; p < parts; p++) {
        len = wkb_ring(b, wkb_head(b, len, 3, 1), pts, sizes[p]);
        pts += 2 * sizes[p];
    }
    return len;
}

/* The boundary: dggs_cell_to_boundary -> list of STRUCT(lat, lng) (variant 0, dggs.cell_to_boundary: the 3
 * corners counter-clockwise, `densify` points along each edge), _wkt -> VARCHAR (1), _wkb -> BLOB and _geometry
 * -> GEOMETRY (2): the polygon of dggs.cell_to_polygon(cell, densify) (dggs_cell_to_polygon: lng/lat, a
 * MultiPolygon split at +-180 for a cell across the antimeridian, closed along a pole). densify is the second
 * argument; without it the list has the corners (densify 0, as dggs.cell_to_boundary) and the polygons have the
 * points per edge of dggs.cell_to_polygon(cell)'s default, from the same core function (dggs_cell_edge_points:
 * the polygon's geodesic area within DEFAULT_AREA_TOLERANCE of the cell's; index/_densify.py). The polygons also
 * take (cell, projection) for that default on IVEA. */
#define MAX_SQL_DENSIFY 1000
#define DEFAULT_AREA_TOLERANCE 1e-6 /* index/_densify.py's AREA_TOLERANCE */

/* Whether column i of the chunk is a VARCHAR (the projection of (cell, projection), not a densify). */
static bool is_varchar_column(duckdb_data_chunk in, idx_t i) {
    duckdb_logical_type t = duckdb_vector_get_column_type(duckdb_data_chunk_get_vector(in, i));
    bool yes = duckdb_get_type_id(t) == DUCKDB_TYPE_VARCHAR;
    duckdb_destroy_logical_type(&t);
    return yes;
}

static void boundary(duckdb_function_info info, duckdb_data_chunk in, duckdb_vector outv) {
    const fn_extra *x = extra_of(info);
    idx_t n = duckdb_data_chunk_get_size(in), ncol = duckdb_data_chunk_get_column_count(in);
    int has_densify = ncol > 1 && !is_varchar_column(in, 1), proj_at = has_densify ? 2 : 1;
    int has_proj = ncol > (idx_t)proj_at;
    col_t c = col_of(in, 0), d = has_densify ? col_of(in, 1) : c, pc = has_proj ? col_of(in, (idx_t)proj_at) : c;
    dggs_projection proj = DGGS_ISEA;
    out_t o = out_of(outv);
    list_out_t l;
    if (x->variant == 0) l = list_of(outv);
    shape_buf b = {NULL, NULL, 0};
    ROWS(n) {
        dggs_cell cell;
        size_t count, sizes[DGGS_MAX_POLYGON_PARTS];
        int parts;
        int64_t densify = has_densify && !is_null(&d, r) ? ((int64_t *)d.data)[r] : 0;
        if (x->variant == 0) list_empty(&l, r);
        if (has_proj && !is_null(&pc, r) && !proj_get(info, x->name, &pc, r, &proj)) break;
        if (is_null(&c, r) || (has_densify && is_null(&d, r)) || (has_proj && is_null(&pc, r))) {
            out_null(&o, r);
            continue;
        }
        if (densify < 0 || densify > MAX_SQL_DENSIFY) {
            char msg[160];
            snprintf(msg, sizeof msg, "%s: densify %lld is out of range 0..%d", x->name, (long long)densify,
                     MAX_SQL_DENSIFY);
            duckdb_scalar_function_set_error(info, msg);
            break;
        }
        if (!id_get(&c, x->kind, r, &cell)) {
            out_null(&o, r);
            continue;
        }
        if (!has_densify && x->variant != 0) { /* dggs.cell_to_polygon(cell)'s default count */
            int points;
            if (dggs_cell_edge_points(cell, proj, 0.0, DEFAULT_AREA_TOLERANCE, &points) != DGGS_OK) {
                out_null(&o, r);
                continue;
            }
            densify = points;
        }
        if (!shape_room(&b, (int)densify)) {
            duckdb_scalar_function_set_error(info, "dggs_cell_to_boundary: out of memory");
            break;
        }
        if ((x->variant == 0 ? dggs_cell_to_boundary(cell, (int)densify, proj, b.pts, b.points, &count)
                             : dggs_cell_to_polygon(cell, (int)densify, proj, b.pts, b.points, sizes, &parts)) !=
            DGGS_OK) {
            out_null(&o, r);
            continue;
        }
        if (x->variant == 0) {
            if (!list_push_latlng(&l, r, b.pts, count)) {
                duckdb_scalar_function_set_error(info, "dggs_cell_to_boundary: too many points for one list");
                break;
            }
            continue;
        }
        size_t len = x->variant == 1 ? polygon_wkt(b.pts, sizes, parts, b.text)
                                     : polygon_wkb(b.pts, sizes, parts, (uint8_t *)b.text);
        duckdb_vector_assign_string_element_len(outv, r, b.text, len);
    }
    free(b.pts);
    free(b.text);
}

/* dggs_cell_to_child_pos(cell, parent_level) -> BIGINT. */
static void cell_to_child_pos(duckdb_function_info info, duckdb_data_chunk in, duckdb_vector outv) {
    const fn_extra *x = extra_of(info);
    idx_t n = duckdb_data_chunk_get_size(in);
    col_t c = col_of(in, 0), lv = col_of(in, 1);
    out_t o = out_of(outv);
    ROWS(n) {
        dggs_cell cell;
        int level;
        int64_t pos;
        if (is_null(&c, r) || is_null(&lv, r) || !id_get(&c, x->kind, r, &cell) || (level = level_get(&lv, r)) < 0 ||
            dggs_cell_to_child_pos(cell, level, &pos) != DGGS_OK) {
            out_null(&o, r);
            continue;
        }
        ((int64_t *)o.data)[r] = pos;
    }
}

/* dggs_child_pos_to_cell(pos, parent, level) -> id. */
static void child_pos_to_cell(duckdb_function_info info, duckdb_data_chunk in, duckdb_vector outv) {
    const fn_extra *x = extra_of(info);
    idx_t n = duckdb_data_chunk_get_size(in);
    col_t p = col_of(in, 0), c = col_of(in, 1), lv = col_of(in, 2);
    out_t o = out_of(outv);
    ROWS(n) {
        dggs_cell cell, child;
        int level;
        if (is_null(&p, r) || is_null(&c, r) || is_null(&lv, r) || !id_get(&c, x->kind, r, &cell) ||
            (level = level_get(&lv, r)) < 0 ||
            dggs_child_pos_to_cell(((int64_t *)p.data)[r], cell, level, &child) != DGGS_OK) {
            out_null(&o, r);
            continue;
        }
        id_put(outv, o.data, x->kind, r, child);
    }
}

void register_cells(duckdb_connection con) {
    reg(con, "dggs_latlng_to_cell", "DDB|DDBV", 'I', latlng_to_cell, 0, K_BIGINT, 0);
    reg(con, "dggs_latlng_to_cell_ubigint", "DDB|DDBV", 'I', latlng_to_cell, 0, K_UBIGINT, 0);
    reg(con, "dggs_latlng_to_cell_str", "DDB|DDBV", 'I', latlng_to_cell, 0, K_VARCHAR, 0);
    reg(con, "dggs_latlng_to_cell_string", "DDB|DDBV", 'I', latlng_to_cell, 0, K_VARCHAR, 0);
    reg(con, "dggs_cell_to_latlng", "I|IV", 'S', cell_to_latlng, 1, K_NONE, 0);
    reg(con, "dggs_cell_to_latlng_lat", "I|IV", 'D', cell_to_latlng, 1, K_NONE, 1);
    reg(con, "dggs_cell_to_latlng_lng", "I|IV", 'D', cell_to_latlng, 1, K_NONE, 2);
    reg(con, "dggs_cell_to_lat", "I|IV", 'D', cell_to_latlng, 1, K_NONE, 1);
    reg(con, "dggs_cell_to_lng", "I|IV", 'D', cell_to_latlng, 1, K_NONE, 2);
    reg(con, "dggs_cell_to_parent", "IB", 'I', cell_at_level, 1, K_NONE, 0);
    reg(con, "dggs_cell_to_center_child", "IB", 'I', cell_at_level, 1, K_NONE, 1);
    reg(con, "dggs_cell_to_children", "IB", 'E', cell_to_children, 1, K_NONE, 0);
    reg(con, "dggs_get_level", "I", 'N', get_level, 1, K_NONE, 0);
    reg(con, "dggs_is_valid_cell", "I", 'O', get_level, 1, K_NONE, 1);
    reg(con, "dggs_str_to_int", "I", 'B', convert_id, 1, K_NONE, K_BIGINT);
    reg(con, "dggs_string_to_cell", "I", 'B', convert_id, 1, K_NONE, K_BIGINT);
    reg(con, "dggs_int_to_str", "I", 'V', convert_id, 1, K_NONE, K_VARCHAR);
    reg(con, "dggs_cell_to_string", "I", 'V', convert_id, 1, K_NONE, K_VARCHAR);
    reg(con, "dggs_cell_to_boundary", "I|IB|IBV", 'P', boundary, 1, K_NONE, 0);
    reg(con, "dggs_cell_to_boundary_wkt", "I|IB|IBV|IV", 'V', boundary, 1, K_NONE, 1);
    reg(con, "dggs_cell_to_boundary_wkb", "I|IB|IBV|IV", 'X', boundary, 1, K_NONE, 2);
    if (geometry_type_exists()) reg(con, "dggs_cell_to_boundary_geometry", "I|IB|IBV|IV", 'G', boundary, 1, K_NONE, 2);
    reg(con, "dggs_cell_to_child_pos", "IB", 'B', cell_to_child_pos, 1, K_NONE, 0);
    reg(con, "dggs_child_pos_to_cell", "BIB", 'I', child_pos_to_cell, 1, K_NONE, 0);
}
