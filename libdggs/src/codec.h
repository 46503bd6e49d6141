/* String <-> 64-bit integer cell id codec. A port of index/_kernel/codec.py (and the string half of
 * index/_kernel/scalar.py), operation for operation.
 *
 * A string id is a face letter 'A'..'T', a level-1 digit '0'..'5', then one digit '0'..'2' per further level
 * (at most DGGS_MAX_CHARS characters). Strings reach the parsers as arrays of character codes of any width
 * (uint8: bytes, Arrow data, ASCII str; uint16 / uint32: wider Python str and numpy U arrays; int64: any
 * other integer codes): one id per NUL-padded row, Arrow buffers (data, offsets, validity) or NUL-joined.
 * Parsers give the null id 0 for an invalid entry and return the index of the first one (or -1). */
#ifndef DGGS_CODEC_H
#define DGGS_CODEC_H

#include <stdbool.h>
#include <stdint.h>

#include "bits.h"
#include "dggs.h"

/* _ok: whether a uint64 is a well-formed id, branch-free (loops over it vectorize). The same answer as
 * bits.h's dggs_is_valid. */
static inline bool dggs_ok(uint64_t cell) {
    uint64_t l1 = (cell >> DGGS_L1_SHIFT) & 7u;
    uint64_t low = cell & DGGS_LOW54;
    /* one bit per non-empty field of levels 2..28: the filled ones must be the top ones */
    uint64_t m = (low | (low >> 1)) & DGGS_DIGIT_LOW_BITS;
    uint64_t lsb = m & (~m + 1u);
    return ((cell >> 62) == 1u) & (((cell >> DGGS_FACE_SHIFT) & 31u) < 20u) & (l1 != 7u) & ((l1 != 0u) | (low == 0u)) &
           (m == (DGGS_DIGIT_LOW_BITS & ~(lsb - 1u)));
}

/* _parse_span: the id of the characters buf[start:end], or 0 if they are not a string id. */
uint64_t dggs_parse_span_u8(const uint8_t *buf, int64_t start, int64_t end);
uint64_t dggs_parse_span_u16(const uint16_t *buf, int64_t start, int64_t end);
uint64_t dggs_parse_span_u32(const uint32_t *buf, int64_t start, int64_t end);
uint64_t dggs_parse_span_i64(const int64_t *buf, int64_t start, int64_t end);

/* parse_codes: parse `n` rows of `width` character codes (row-major, one id per row, NUL padded: trailing
 * NULs end an id) into out[n]; return the index of the first invalid row or -1. An empty row is invalid;
 * so is a NUL followed by another character. */
int64_t dggs_parse_codes_u8(const uint8_t *codes, int64_t n, int64_t width, uint64_t *out);
int64_t dggs_parse_codes_u32(const uint32_t *codes, int64_t n, int64_t width, uint64_t *out);
int64_t dggs_parse_codes_i64(const int64_t *codes, int64_t n, int64_t width, uint64_t *out);

/* parse_arrow: parse `n` Arrow strings from element `offset` into out[n]: `data` the character buffer
 * (`data_len` bytes), `offsets` the int32 (dggs_parse_arrow32) or int64 offsets buffer, `validity` the validity
 * bitmap (`validity_len` bytes; 0 when there are no nulls). Nulls are invalid, and so (unlike the numba code,
 * which read past its buffers there) is a span outside `data` or an element past the bitmap. Return the
 * index of the first invalid element or -1. The offsets buffer must hold offset + n + 1 entries. */
int64_t dggs_parse_arrow32(const uint8_t *data, int64_t data_len, const int32_t *offsets, const uint8_t *validity,
                           int64_t validity_len, int64_t offset, int64_t n, uint64_t *out);
int64_t dggs_parse_arrow64(const uint8_t *data, int64_t data_len, const int64_t *offsets, const uint8_t *validity,
                           int64_t validity_len, int64_t offset, int64_t n, uint64_t *out);

/* parse_joined: parse `n` ids joined by NUL codes ("\0".join(strings)) from data[m] into out[n] (entries
 * beyond the pieces found are 0); return the index of the first invalid one or -1, and in *pieces the
 * number of NUL-separated pieces (!= n: an element held a NUL itself and the ids are meaningless). */
int64_t dggs_parse_joined_u8(const uint8_t *data, int64_t m, int64_t n, uint64_t *out, int64_t *pieces);
int64_t dggs_parse_joined_u32(const uint32_t *data, int64_t m, int64_t n, uint64_t *out, int64_t *pieces);
int64_t dggs_parse_joined_i64(const int64_t *data, int64_t m, int64_t n, uint64_t *out, int64_t *pieces);

/* check_ints: index of the first id of ids[n] that is not well formed, or -1. */
int64_t dggs_check_ints(const uint64_t *ids, int64_t n);
/* valid_ints: out[i] = 1 where ids[i] is well formed, else 0. */
void dggs_valid_ints(const uint64_t *ids, int64_t n, uint8_t *out);
/* max_level: the deepest level of ids[n] (the null id 0 allowed; -1 when there are only nulls), *bad = -1;
 * or -1 and *bad = the index of the first id that is neither well formed nor the null id. */
int dggs_max_level(const uint64_t *ids, int64_t n, int64_t *bad);

/* fill_codes: the characters of valid-or-null ids ids[n] into the rows of out (n rows of `width` codes,
 * row-major): an empty field gives a NUL (and so do columns past DGGS_MAX_CHARS). */
void dggs_fill_codes_u8(const uint64_t *ids, int64_t n, uint8_t *out, int64_t width);
void dggs_fill_codes_u32(const uint64_t *ids, int64_t n, uint32_t *out, int64_t width);

/* format_one: the characters of a well-formed id into buf (at least DGGS_MAX_CHARS bytes; no NUL written);
 * return their count, or 0 (the empty string) if `cell` is not an id. */
int dggs_format_one(uint64_t cell, char *buf);


#endif
