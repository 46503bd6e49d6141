/* String <-> 64-bit integer cell id codec: a port of index/_kernel/codec.py (see codec.h). */
#include "codec.h"

#include <stddef.h>

#define CODEC_ORD_A 65 /* "A" */
#define CODEC_ORD_0 48 /* "0" */

/* _parse_span over codes of type T, each read as an int64 (np.int64(buf[j])): the face letter, the level-1
 * digit, then the levels 2.. accumulated as base-4 codes (digit + 1) and shifted into place. */
#define CODEC_PARSE_SPAN(SUFFIX, T)                                                                  \
    uint64_t dggs_parse_span_##SUFFIX(const T *buf, int64_t start, int64_t end) {                    \
        int64_t n = end - start;                                                                     \
        if (n < 1 || n > DGGS_MAX_CHARS) return 0;                                                   \
        int64_t face = (int64_t)buf[start] - CODEC_ORD_A;                                            \
        if (face < 0 || face >= 20) return 0;                                                        \
        uint64_t cell = DGGS_MARKER | ((uint64_t)face << DGGS_FACE_SHIFT);                           \
        if (n == 1) return cell;                                                                     \
        int64_t d = (int64_t)buf[start + 1] - CODEC_ORD_0;                                           \
        if (d < 0 || d > 5) return 0;                                                                \
        cell |= (uint64_t)(d + 1) << DGGS_L1_SHIFT;                                                  \
        uint64_t acc = 0;                                                                            \
        for (int64_t j = start + 2; j < end; j++) {                                                  \
            d = (int64_t)buf[j] - CODEC_ORD_0;                                                       \
            if (d < 0 || d > 2) return 0;                                                            \
            acc = (acc << 2) | (uint64_t)(d + 1);                                                    \
        }                                                                                            \
        return cell | (acc << (2 * (DGGS_MAX_CHARS - n)));                                           \
    }

CODEC_PARSE_SPAN(u8, uint8_t)
CODEC_PARSE_SPAN(u16, uint16_t)
CODEC_PARSE_SPAN(u32, uint32_t)
CODEC_PARSE_SPAN(i64, int64_t)

/* parse_codes: trailing NULs of each row end its id. */
#define CODEC_PARSE_CODES(SUFFIX, T)                                                                 \
    int64_t dggs_parse_codes_##SUFFIX(const T *codes, int64_t n, int64_t width, uint64_t *out) {     \
        int64_t bad = -1;                                                                            \
        for (int64_t i = 0; i < n; i++) {                                                            \
            const T *row = codes + i * width;                                                        \
            int64_t end = width;                                                                     \
            while (end > 0 && row[end - 1] == 0) end--;                                              \
            uint64_t v = dggs_parse_span_##SUFFIX(row, 0, end);                                      \
            out[i] = v;                                                                              \
            if (v == 0 && bad < 0) bad = i;                                                          \
        }                                                                                            \
        return bad;                                                                                  \
    }

CODEC_PARSE_CODES(u8, uint8_t)
CODEC_PARSE_CODES(u32, uint32_t)
CODEC_PARSE_CODES(i64, int64_t)

/* parse_arrow: a null (validity bit clear) is invalid, as is a span the buffers do not hold. */
#define CODEC_PARSE_ARROW(SUFFIX, T)                                                                              \
    int64_t dggs_parse_arrow##SUFFIX(const uint8_t *data, int64_t data_len, const T *offsets,                      \
                                     const uint8_t *validity, int64_t validity_len, int64_t offset, int64_t n,    \
                                     uint64_t *out) {                                                              \
        int64_t bad = -1;                                                                                          \
        bool has_validity = validity_len > 0;                                                                      \
        for (int64_t i = 0; i < n; i++) {                                                                          \
            int64_t j = offset + i;                                                                                \
            uint64_t v;                                                                                            \
            if (has_validity && ((j >> 3) >= validity_len || !((validity[j >> 3] >> (j & 7)) & 1))) {             \
                v = 0;                                                                                             \
            } else {                                                                                               \
                int64_t a = (int64_t)offsets[j], b = (int64_t)offsets[j + 1];                                      \
                v = (a >= 0 && b <= data_len) ? dggs_parse_span_u8(data, a, b) : 0;                                \
            }                                                                                                      \
            out[i] = v;                                                                                            \
            if (v == 0 && bad < 0) bad = i;                                                                        \
        }                                                                                                          \
        return bad;                                                                                                \
    }

CODEC_PARSE_ARROW(32, int32_t)
CODEC_PARSE_ARROW(64, int64_t)

/* parse_joined: each NUL (and the end) closes a piece; pieces past n are counted, not parsed. */
#define CODEC_PARSE_JOINED(SUFFIX, T)                                                                      \
    int64_t dggs_parse_joined_##SUFFIX(const T *data, int64_t m, int64_t n, uint64_t *out, int64_t *pieces) { \
        for (int64_t i = 0; i < n; i++) out[i] = 0;                                                        \
        int64_t bad = -1, i = 0, start = 0;                                                                \
        for (int64_t j = 0; j <= m; j++) {                                                                 \
            if (j == m || data[j] == 0) {                                                                  \
                if (i < n) {                                                                               \
                    uint64_t v = dggs_parse_span_##SUFFIX(data, start, j);                                 \
                    out[i] = v;                                                                            \
                    if (v == 0 && bad < 0) bad = i;                                                        \
                }                                                                                          \
                i++;                                                                                       \
                start = j + 1;                                                                             \
            }                                                                                              \
        }                                                                                                  \
        *pieces = i;                                                                                       \
        return bad;                                                                                        \
    }

CODEC_PARSE_JOINED(u8, uint8_t)
CODEC_PARSE_JOINED(u32, uint32_t)
CODEC_PARSE_JOINED(i64, int64_t)

int64_t dggs_check_ints(const uint64_t *ids, int64_t n) {
    bool ok = true;
    for (int64_t i = 0; i < n; i++) ok &= dggs_ok(ids[i]);
    if (ok) return -1;
    for (int64_t i = 0; i < n; i++)
        if (!dggs_ok(ids[i])) return i;
    return -1;
}

void dggs_valid_ints(const uint64_t *ids, int64_t n, uint8_t *out) {
    for (int64_t i = 0; i < n; i++) out[i] = dggs_ok(ids[i]);
}

int dggs_max_level(const uint64_t *ids, int64_t n, int64_t *bad) {
    bool ok = true;
    const uint64_t none = (uint64_t)1 << 63;
    uint64_t lowest = none; /* the lowest bit of the deepest filled field seen */
    for (int64_t i = 0; i < n; i++) {
        uint64_t c = ids[i];
        ok &= dggs_ok(c) | (c == 0);
        uint64_t low = c & DGGS_LOW54;
        uint64_t m = (low | (low >> 1)) & DGGS_DIGIT_LOW_BITS;
        uint64_t bit = m & (~m + 1u);
        if (m == 0)
            bit = c == 0 ? none
                  : ((c >> DGGS_L1_SHIFT) & 7u) ? (uint64_t)1 << DGGS_L1_SHIFT
                                                 : (uint64_t)1 << DGGS_FACE_SHIFT;
        if (bit < lowest) lowest = bit;
    }
    *bad = -1;
    if (!ok) {
        for (int64_t i = 0; i < n; i++) {
            if (ids[i] != 0 && !dggs_ok(ids[i])) {
                *bad = i;
                return -1;
            }
        }
    }
    if (lowest == none) return -1;
    if (lowest == (uint64_t)1 << DGGS_FACE_SHIFT) return 0;
    if (lowest == (uint64_t)1 << DGGS_L1_SHIFT) return 1;
    int k = DGGS_MAX_LEVEL;
    while (lowest > 1) {
        lowest >>= 2;
        k--;
    }
    return k;
}

/* fill_codes: column 0 the face letter (NUL for the null id), 1 the level-1 digit, k the level-k digit. */
#define CODEC_FILL_CODES(SUFFIX, T)                                                                  \
    void dggs_fill_codes_##SUFFIX(const uint64_t *ids, int64_t n, T *out, int64_t width) {           \
        for (int64_t i = 0; i < n; i++) {                                                            \
            uint64_t c = ids[i];                                                                     \
            T *row = out + i * width;                                                                \
            if (width < 1) continue;                                                                 \
            row[0] = (T)(c != 0 ? CODEC_ORD_A + (int64_t)((c >> DGGS_FACE_SHIFT) & 31u) : 0);        \
            if (width > 1) {                                                                         \
                int64_t code = (int64_t)((c >> DGGS_L1_SHIFT) & 7u);                                 \
                row[1] = (T)(code ? CODEC_ORD_0 - 1 + code : 0);                                     \
            }                                                                                        \
            for (int64_t k = 2; k < width; k++) {                                                    \
                int64_t code = k <= DGGS_MAX_LEVEL ? (int64_t)((c >> (2 * (DGGS_MAX_LEVEL - k))) & 3u) : 0; \
                row[k] = (T)(code ? CODEC_ORD_0 - 1 + code : 0);                                     \
            }                                                                                        \
        }                                                                                            \
    }

CODEC_FILL_CODES(u8, uint8_t)
CODEC_FILL_CODES(u32, uint32_t)

int dggs_format_one(uint64_t cell, char *buf) {
    if (!dggs_is_valid(cell)) return 0;
    int level = dggs_level_of(cell);
    buf[0] = (char)(CODEC_ORD_A + dggs_face_of(cell));
    for (int k = 1; k <= level; k++) buf[k] = (char)(CODEC_ORD_0 + dggs_digit_of(cell, k));
    return level + 1;
}

/* ---- public API (dggs.h, "ids and strings") ---- */

dggs_error dggs_string_to_cell(const char *s, dggs_cell *out) {
    int64_t n = 0;
    while (n <= DGGS_MAX_CHARS && s[n]) n++; /* longer than DGGS_MAX_CHARS: invalid, read no further */
    uint64_t v = dggs_parse_span_u8((const uint8_t *)s, 0, n);
    if (!v) return DGGS_E_CELL;
    *out = v;
    return DGGS_OK;
}

dggs_error dggs_cell_to_string(dggs_cell cell, char *buf, size_t size) {
    char tmp[DGGS_MAX_CHARS];
    int n = dggs_format_one(cell, tmp);
    if (!n) return DGGS_E_CELL;
    if (size < (size_t)n + 1) return DGGS_E_BUFFER;
    for (int k = 0; k < n; k++) buf[k] = tmp[k];
    buf[n] = '\0';
    return DGGS_OK;
}

int dggs_is_valid_cell(dggs_cell cell) { return dggs_is_valid(cell); }

int dggs_get_level(dggs_cell cell) { return dggs_is_valid(cell) ? dggs_level_of(cell) : -1; }

int dggs_get_face(dggs_cell cell) { return dggs_is_valid(cell) ? dggs_face_of(cell) : -1; }
