/* Corners (vertices): fans and corner-sharing disks on the edge adjacency. See vertex.h. */
#include "vertex.h"

#include <string.h>

#include "bits.h"
#include "dggs.h"
#include "grid.h"

int dggs_fan(uint64_t cell, int corner, uint64_t fan[DGGS_VERTEX_MAX_FAN], int corners[DGGS_VERTEX_MAX_FAN]) {
    uint64_t nb[3], next_nb[3];
    dggs_neighbours(cell, nb);
    fan[0] = cell;
    corners[0] = corner;
    uint64_t cur = cell;
    int edge = corner;
    for (int n = 1; n <= DGGS_VERTEX_MAX_FAN; n++) {
        uint64_t nxt = nb[edge];
        if (nxt == cell) return n;
        if (n == DGGS_VERTEX_MAX_FAN) break;
        dggs_neighbours(nxt, next_nb);
        int back = next_nb[0] == cur ? 0 : next_nb[1] == cur ? 1 : next_nb[2] == cur ? 2 : -1;
        if (back < 0) return -1;
        edge = (back + 1) % 3; /* the corner is the far end of the edge back */
        fan[n] = nxt;
        corners[n] = edge;
        cur = nxt;
        memcpy(nb, next_nb, sizeof nb);
    }
    return -1;
}

/* Past this radius the bound's 6 k exceeds every level's cells (level 28: 9.2e14 cells; the edge disk of radius
 * 5e7 already holds 7.5e16), and disk_size_bound(6 k) would overflow. */
#define VERTEX_BIG_K ((int64_t)50000000)

int64_t dggs_disk_vertex_width(int64_t k, int level) {
    if (k > VERTEX_BIG_K) return dggs_level_cells(level);
    return dggs_disk_width(6 * k, level);
}

int64_t dggs_disk_vertex_table_size(int64_t width) { return 2 * dggs_disk_table_size(width); }

/* The slot of `x` in keys (mask + 1 slots, Fibonacci hashing as grid.c's), or of the empty slot where it goes. */
static inline int64_t vertex_slot(const uint64_t *keys, uint64_t x, int64_t mask) {
    int64_t s = (int64_t)((x * (uint64_t)0x9E3779B97F4A7C15ULL) >> 40) & mask;
    while (keys[s] != 0 && keys[s] != x) s = (s + 1) & mask;
    return s;
}

int64_t dggs_disk_vertex_row(uint64_t cell, int64_t k, uint64_t *row, int64_t width, uint64_t *table,
                             int64_t table_size) {
    if (width < 1) return -1;
    int64_t half = table_size / 2, mask = half - 1;
    uint64_t *keys = table, *walked = table + half; /* walked[s]: bit c set once corner c of keys[s] is walked */
    row[0] = cell;
    keys[vertex_slot(keys, cell, mask)] = cell;
    int64_t head = 0, tail = 1;
    for (int64_t step = 0; step < k && head < tail; step++) {
        int64_t end = tail; /* ring `step` is row[head:end]; the cells found now are ring step + 1 */
        for (; head < end; head++) {
            uint64_t x = row[head];
            int64_t sx = vertex_slot(keys, x, mask);
            for (int c = 0; c < 3; c++) {
                if (walked[sx] & (1u << c)) continue; /* walked from another cell of its fan: its cells are in */
                uint64_t fan[DGGS_VERTEX_MAX_FAN];
                int corners[DGGS_VERTEX_MAX_FAN];
                int n = dggs_fan(x, c, fan, corners);
                if (n < 0) return -2;
                for (int i = 0; i < n; i++) {
                    int64_t s = vertex_slot(keys, fan[i], mask);
                    if (keys[s] == 0) {
                        if (tail == width) return -1;
                        keys[s] = fan[i];
                        row[tail++] = fan[i];
                    }
                    walked[s] |= 1u << corners[i];
                }
            }
        }
    }
    dggs_sort_small(row, tail);
    return tail;
}

/* ---- public API (dggs.h, "vertices") ---- */

dggs_error dggs_cell_to_vertex_fan(dggs_cell cell, int corner, dggs_cell fan[DGGS_MAX_FAN], int corners[DGGS_MAX_FAN],
                                   int *count) {
    if (!dggs_is_valid(cell)) return DGGS_E_CELL;
    if (corner < 0 || corner > 2) return DGGS_E_DOMAIN;
    int n = dggs_fan(cell, corner, fan, corners);
    if (n < 0) return DGGS_E_FAILED;
    *count = n;
    return DGGS_OK;
}

/* index/_checks.py K_LIMIT, as grid.c's. */
#define VERTEX_K_LIMIT ((int64_t)1 << 31)

dggs_error dggs_grid_disk_vertex_size(dggs_cell cell, int64_t k, int64_t *size) {
    if (!dggs_is_valid(cell)) return DGGS_E_CELL;
    if (k < 0 || k > VERTEX_K_LIMIT) return DGGS_E_DOMAIN;
    int64_t width = dggs_disk_vertex_width(k, dggs_level_of(cell));
    *size = width + dggs_disk_vertex_table_size(width);
    return DGGS_OK;
}

dggs_error dggs_grid_disk_vertex(dggs_cell cell, int64_t k, dggs_cell *out, int64_t size, int64_t *count) {
    int64_t need;
    dggs_error err = dggs_grid_disk_vertex_size(cell, k, &need);
    if (err) return err;
    if (size < need) return DGGS_E_BUFFER;
    int64_t width = dggs_disk_vertex_width(k, dggs_level_of(cell));
    int64_t tsize = dggs_disk_vertex_table_size(width);
    uint64_t *table = out + width;
    memset(table, 0, (size_t)tsize * sizeof *table);
    int64_t m = dggs_disk_vertex_row(cell, k, out, width, table, tsize);
    if (m < 0) return DGGS_E_FAILED; /* outgrew the proven bound, or a corner's walk did not close: never */
    memset(out + m, 0, (size_t)(size - m) * sizeof *out);
    *count = m;
    return DGGS_OK;
}

/* ---- vertex ids: a corner is named by the smallest cell of its fan and the corner's index there ---- */

/* The name of corner `corner` of the valid id `cell`: the smallest cell of its fan and the corner's index there
 * (index/_corners.vertex_keys). DGGS_E_FAILED if the walk does not close (never for valid ids). */
static dggs_error vertex_key(dggs_cell cell, int corner, dggs_cell *owner, int *index) {
    dggs_cell fan[DGGS_MAX_FAN];
    int corners[DGGS_MAX_FAN];
    int n = dggs_fan(cell, corner, fan, corners);
    if (n < 0) return DGGS_E_FAILED;
    int low = 0;
    for (int i = 1; i < n; i++)
        if (fan[i] < fan[low]) low = i;
    *owner = fan[low];
    *index = corners[low];
    return DGGS_OK;
}

dggs_error dggs_cell_to_vertexes(dggs_cell cell, dggs_cell owners[3], int index[3]) {
    if (!dggs_is_valid_cell(cell)) return DGGS_E_CELL;
    for (int i = 0; i < 3; i++) {
        dggs_error err = vertex_key(cell, i, &owners[i], &index[i]);
        if (err != DGGS_OK) return err;
    }
    return DGGS_OK;
}

int dggs_is_valid_vertex(dggs_cell owner, int index) {
    dggs_cell o;
    int i;
    if (!dggs_is_valid_cell(owner) || index < 0 || index > 2) return 0;
    return vertex_key(owner, index, &o, &i) == DGGS_OK && o == owner && i == index;
}

dggs_error dggs_vertex_to_latlng(dggs_cell owner, int index, dggs_projection proj, double *lat, double *lng) {
    if (!dggs_is_valid_vertex(owner, index)) return DGGS_E_CELL;
    double b[6];
    size_t count;
    dggs_error err = dggs_cell_to_boundary(owner, 0, proj, b, 3, &count);
    if (err != DGGS_OK) return err;
    *lat = b[2 * index];
    *lng = b[2 * index + 1];
    return DGGS_OK;
}
