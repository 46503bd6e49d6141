/* Fuzz target: string ids, integer ids, point location and boundaries through the public header (dggs.h).
 *
 * The input's first byte picks the operation; the rest is its argument: a string to parse, or raw bytes read as
 * ids, levels, densify counts and doubles (NaN, infinities and subnormals included). Every call must return an
 * error code or an answer that holds its contract: no crash, no read or write outside a buffer (ASan), no
 * undefined behaviour (UBSan), round trips exact. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "dggs.h"

#define REQUIRE(cond)        \
    do {                     \
        if (!(cond)) abort(); \
    } while (0)

static uint64_t take_u64(const uint8_t **d, size_t *n) {
    uint64_t v = 0;
    size_t k = *n < 8 ? *n : 8;
    memcpy(&v, *d, k);
    *d += k;
    *n -= k;
    return v;
}

static double take_double(const uint8_t **d, size_t *n) {
    uint64_t bits = take_u64(d, n);
    double v;
    memcpy(&v, &bits, sizeof v);
    return v;
}

static void parse_string(const uint8_t *d, size_t n) {
    char s[64];
    size_t k = n < sizeof s - 1 ? n : sizeof s - 1;
    memcpy(s, d, k);
    s[k] = '\0';
    dggs_cell cell = 0;
    if (dggs_string_to_cell(s, &cell) != DGGS_OK) return;
    REQUIRE(dggs_is_valid_cell(cell));
    char back[DGGS_MAX_CHARS + 1];
    REQUIRE(dggs_cell_to_string(cell, back, sizeof back) == DGGS_OK);
    REQUIRE(strcmp(back, s) == 0);
    char tiny[3];
    dggs_error e = dggs_cell_to_string(cell, tiny, sizeof tiny);
    REQUIRE(e == DGGS_OK || e == DGGS_E_BUFFER);
}

static void integer_id(const uint8_t *d, size_t n) {
    dggs_cell cell = take_u64(&d, &n);
    char s[DGGS_MAX_CHARS + 1];
    dggs_error e = dggs_cell_to_string(cell, s, sizeof s);
    REQUIRE((e == DGGS_OK) == (dggs_is_valid_cell(cell) != 0));
    if (e != DGGS_OK) return;
    dggs_cell back = 0;
    REQUIRE(dggs_string_to_cell(s, &back) == DGGS_OK && back == cell);
    REQUIRE(dggs_get_level(cell) == (int)strlen(s) - 1);
    double lat, lng;
    dggs_projection proj = (n && (d[0] & 1)) ? DGGS_IVEA : DGGS_ISEA;
    REQUIRE(dggs_cell_to_latlng(cell, proj, &lat, &lng) == DGGS_OK);
    REQUIRE(lat >= -90.0 && lat <= 90.0 && lng >= -180.0 && lng <= 180.0);
}

static void locate(const uint8_t *d, size_t n) {
    double lat = take_double(&d, &n), lng = take_double(&d, &n);
    int level = n ? (int)(int8_t)d[0] : 0;
    dggs_projection proj = (n > 1) ? (dggs_projection)(d[1] % 3) : DGGS_ISEA; /* 2: not a projection */
    dggs_cell cell = 0;
    dggs_error e = dggs_latlng_to_cell(lat, lng, level, proj, &cell);
    if (e != DGGS_OK) {
        REQUIRE(e == DGGS_E_LATLNG || e == DGGS_E_LEVEL || e == DGGS_E_PROJECTION);
        return;
    }
    REQUIRE(dggs_is_valid_cell(cell) && dggs_get_level(cell) == level);
}

static void boundary(const uint8_t *d, size_t n) {
    dggs_cell cell = take_u64(&d, &n);
    int densify = n ? (int)(d[0] % 40) - 2 : 0; /* -2..37: negatives must be refused */
    dggs_projection proj = (n > 1 && (d[1] & 1)) ? DGGS_IVEA : DGGS_ISEA;
    size_t points = 0;
    if (dggs_cell_to_boundary_size(densify, &points) != DGGS_OK) {
        REQUIRE(densify < 0);
        return;
    }
    size_t room = (n > 2 && (d[2] & 1)) ? points - 1 : points; /* sometimes one point short: DGGS_E_BUFFER */
    double *buf = malloc(2 * room * sizeof *buf);
    REQUIRE(buf != NULL);
    size_t count = 0;
    dggs_error e = dggs_cell_to_boundary(cell, densify, proj, buf, room, &count);
    if (e == DGGS_OK) {
        REQUIRE(count <= room);
        for (size_t i = 0; i < count; i++) REQUIRE(fabs(buf[2 * i]) <= 90.0 && fabs(buf[2 * i + 1]) <= 180.0);
    } else {
        REQUIRE(e == DGGS_E_CELL || e == DGGS_E_BUFFER);
    }
    free(buf);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    if (size < 1) return 0;
    switch (data[0] % 4) {
        case 0: parse_string(data + 1, size - 1); break;
        case 1: integer_id(data + 1, size - 1); break;
        case 2: locate(data + 1, size - 1); break;
        default: boundary(data + 1, size - 1); break;
    }
    return 0;
}
