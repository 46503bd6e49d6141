/* codec.c: string <-> id parsers and formatters: round trips at every level, each container's parser, the
 * branch-free validity against bits.h's, the public API, and outputs of the numba codec frozen by
 * tools/freeze_codec.py. */
#include "bits.h"
#include "check.h"
#include "codec.h"
#include "dggs.h"
#include "hierarchy.h"

#define COUNT(a) ((int)(sizeof(a) / sizeof((a)[0])))

/* BEGIN FROZEN (tools/freeze_codec.py) */
/* parse_one: string, id (0: not a string id) */
static const struct { const char *s; uint64_t id; } FROZEN_STRINGS[] = {
    {"A", 0x4000000000000000ULL},
    {"A", 0x4000000000000000ULL},
    {"Q", 0x6000000000000000ULL},
    {"B5", 0x4380000000000000ULL},
    {"B0", 0x4240000000000000ULL},
    {"B1", 0x4280000000000000ULL},
    {"C52", 0x45b0000000000000ULL},
    {"C00", 0x4450000000000000ULL},
    {"D40", 0x4750000000000000ULL},
    {"D522", 0x47bc000000000000ULL},
    {"D000", 0x4654000000000000ULL},
    {"A021", 0x4078000000000000ULL},
    {"E5222", 0x49bf000000000000ULL},
    {"E0000", 0x4855000000000000ULL},
    {"J1011", 0x529a000000000000ULL},
    {"F52222", 0x4bbfc00000000000ULL},
    {"F00000", 0x4a55400000000000ULL},
    {"C20220", 0x44df400000000000ULL},
    {"G522222", 0x4dbff00000000000ULL},
    {"G000000", 0x4c55500000000000ULL},
    {"N312111", 0x5b2ea00000000000ULL},
    {"H5222222", 0x4fbffc0000000000ULL},
    {"H0000000", 0x4e55540000000000ULL},
    {"G3022220", 0x4d1ff40000000000ULL},
    {"I52222222", 0x51bfff0000000000ULL},
    {"I00000000", 0x5055550000000000ULL},
    {"T51220200", 0x67af750000000000ULL},
    {"J522222222", 0x53bfffc000000000ULL},
    {"J000000000", 0x5255554000000000ULL},
    {"J100002110", 0x52957a4000000000ULL},
    {"K5222222222", 0x55bffff000000000ULL},
    {"K0000000000", 0x5455555000000000ULL},
    {"M3210021100", 0x59397a5000000000ULL},
    {"L52222222222", 0x57bffffc00000000ULL},
    {"L00000000000", 0x5655555400000000ULL},
    {"F41220110012", 0x4b6f696c00000000ULL},
    {"M522222222222", 0x59bfffff00000000ULL},
    {"M000000000000", 0x5855555500000000ULL},
    {"I510122102022", 0x51a6f9df00000000ULL},
    {"N5222222222222", 0x5bbfffffc0000000ULL},
    {"N0000000000000", 0x5a55555540000000ULL},
    {"C1202101211211", 0x44b79bae80000000ULL},
    {"O52222222222222", 0x5dbffffff0000000ULL},
    {"O00000000000000", 0x5c55555550000000ULL},
    {"S12201200111101", 0x64bdb5aa60000000ULL},
    {"P522222222222222", 0x5fbffffffc000000ULL},
    {"P000000000000000", 0x5e55555554000000ULL},
    {"L120020201221002", 0x56b5ddbe5c000000ULL},
    {"Q5222222222222222", 0x61bfffffff000000ULL},
    {"Q0000000000000000", 0x6055555555000000ULL},
    {"H0222121121212201", 0x4e7fbaeef6000000ULL},
    {"R52222222222222222", 0x63bfffffffc00000ULL},
    {"R00000000000000000", 0x6255555555400000ULL},
    {"T50002012100011021", 0x6795db95a7800000ULL},
    {"S522222222222222222", 0x65bffffffff00000ULL},
    {"S000000000000000000", 0x6455555555500000ULL},
    {"Q420021222002110102", 0x6175efd7a6700000ULL},
    {"T5222222222222222222", 0x67bffffffffc0000ULL},
    {"T0000000000000000000", 0x6655555555540000ULL},
    {"N0010120011021212211", 0x5a59b5a7bbe80000ULL},
    {"A52222222222222222222", 0x41bfffffffff0000ULL},
    {"A00000000000000000000", 0x4055555555550000ULL},
    {"J01100022121020101211", 0x52695fb9d9ba0000ULL},
    {"B522222222222222222222", 0x43bfffffffffc000ULL},
    {"B000000000000000000000", 0x4255555555554000ULL},
    {"F300102212202022202222", 0x4b167ef77f7fc000ULL},
    {"C5222222222222222222222", 0x45bffffffffff000ULL},
    {"C0000000000000000000000", 0x4455555555555000ULL},
    {"R0121101110110120112102", 0x626e9a9a6dae7000ULL},
    {"D52222222222222222222222", 0x47bffffffffffc00ULL},
    {"D00000000000000000000000", 0x4655555555555400ULL},
    {"F10011112100002210200011", 0x4a96ab957e756800ULL},
    {"E522222222222222222222222", 0x49bfffffffffff00ULL},
    {"E000000000000000000000000", 0x4855555555555500ULL},
    {"L011122021220222001102002", 0x566af7bdfd69d700ULL},
    {"F5222222222222222222222222", 0x4bbfffffffffffc0ULL},
    {"F0000000000000000000000000", 0x4a55555555555540ULL},
    {"O3022220110000122100221002", 0x5d1ff6956f97e5c0ULL},
    {"G52222222222222222222222222", 0x4dbffffffffffff0ULL},
    {"G00000000000000000000000000", 0x4c55555555555550ULL},
    {"E40211211020110010211021011", 0x495eba76967a79a0ULL},
    {"H522222222222222222222222222", 0x4fbffffffffffffcULL},
    {"H000000000000000000000000000", 0x4e55555555555554ULL},
    {"A022011122221101111012011211", 0x407dabfe9aa6dae8ULL},
    {"I5222222222222222222222222222", 0x51bfffffffffffffULL},
    {"I0000000000000000000000000000", 0x5055555555555555ULL},
    {"R0011201110101022002220210200", 0x625ada999f5fde75ULL},
    {"", 0x0000000000000000ULL},
    {"Z", 0x0000000000000000ULL},
    {"U1", 0x0000000000000000ULL},
    {"A6", 0x0000000000000000ULL},
    {"A03", 0x0000000000000000ULL},
    {"A0 1", 0x0000000000000000ULL},
    {"a01", 0x0000000000000000ULL},
    {"A00000000000000000000000000000", 0x0000000000000000ULL},
    {"T52222222222222222222222222222", 0x0000000000000000ULL},
    {"+A0", 0x0000000000000000ULL},
    {"A_0", 0x0000000000000000ULL},
    {"@", 0x0000000000000000ULL},
    {"[", 0x0000000000000000ULL},
    {"A/", 0x0000000000000000ULL},
    {"A:", 0x0000000000000000ULL},
    {"T52223", 0x0000000000000000ULL},
    {"Q5222222222222222222222222222", 0x61bfffffffffffffULL},
};
/* valid_ints and format_one: integer, valid, string ("" when not an id) */
static const struct { uint64_t v; int valid; const char *s; } FROZEN_INTS[] = {
    {0x0000000000000000ULL, 0, ""},
    {0x0000000000000001ULL, 0, ""},
    {0x4000000000000000ULL, 1, "A"},
    {0x6600000000000000ULL, 1, "T"},
    {0x6800000000000000ULL, 0, ""},
    {0x41c0000000000000ULL, 0, ""},
    {0x4040000000000001ULL, 0, ""},
    {0x4000000000000001ULL, 0, ""},
    {0x7fffffffffffffffULL, 0, ""},
    {0x41b0000000000001ULL, 0, ""},
    {0x41bc000000000000ULL, 1, "A522"},
    {0x4558000000000000ULL, 1, "C401"},
    {0x4558040000000000ULL, 0, ""},
    {0x4558000000000001ULL, 0, ""},
    {0x67bfffffffffffffULL, 1, "T5222222222222222222222222222"},
    {0x67bbffffffffffffULL, 1, "T5212222222222222222222222222"},
    {0x67bfffffffffffffULL, 1, "T5222222222222222222222222222"},
    {0x406aaaaaaaaaaaaaULL, 1, "A0111111111111111111111111111"},
    {0x406aaaaaaaaaaaa8ULL, 1, "A011111111111111111111111111"},
    {0x406aaaaaaaaaaaabULL, 1, "A0111111111111111111111111112"},
    {0x5300000000000000ULL, 1, "J3"},
    {0x5304000000000000ULL, 0, ""},
    {0x5300000000000001ULL, 0, ""},
};
/* max_level: count, ids, level, bad */
static const struct { int n; uint64_t ids[4]; int level; int64_t bad; } FROZEN_MAX_LEVEL[] = {
    {1, {0x0000000000000000ULL}, -1, -1},
    {1, {0x4000000000000000ULL}, 0, -1},
    {2, {0x4000000000000000ULL, 0x4300000000000000ULL}, 1, -1},
    {4, {0x0000000000000000ULL, 0x67bf000000000000ULL, 0x0000000000000000ULL, 0x4480000000000000ULL}, 4, -1},
    {2, {0x4055555555555555ULL, 0x4200000000000000ULL}, 28, -1},
    {4, {0x0000000000000000ULL, 0x0000000000000000ULL, 0x0000000000000000ULL, 0x0000000000000000ULL}, -1, -1},
    {3, {0x4550000000000000ULL, 0x0000000000003039ULL, 0x4600000000000000ULL}, -1, 1},
    {3, {0x4550000000000000ULL, 0x0000000000000000ULL, 0x41c0000000000000ULL}, -1, 2},
    {1, {0x4980000000000000ULL}, 1, -1},
};
/* END FROZEN */

static void check_frozen(void) {
    for (int i = 0; i < COUNT(FROZEN_STRINGS); i++) {
        const char *s = FROZEN_STRINGS[i].s;
        int64_t n = (int64_t)strlen(s);
        uint16_t w16[40];
        uint32_t w32[40];
        int64_t w64[40];
        for (int64_t k = 0; k < n && k < 40; k++) {
            w16[k] = (uint8_t)s[k];
            w32[k] = (uint8_t)s[k];
            w64[k] = (uint8_t)s[k];
        }
        CHECK_EQ_U64(dggs_parse_span_u8((const uint8_t *)s, 0, n), FROZEN_STRINGS[i].id);
        if (n <= 40) {
            CHECK_EQ_U64(dggs_parse_span_u16(w16, 0, n), FROZEN_STRINGS[i].id);
            CHECK_EQ_U64(dggs_parse_span_u32(w32, 0, n), FROZEN_STRINGS[i].id);
            CHECK_EQ_U64(dggs_parse_span_i64(w64, 0, n), FROZEN_STRINGS[i].id);
        }
        dggs_cell c = 0;
        dggs_error err = dggs_string_to_cell(s, &c);
        CHECK(err == (FROZEN_STRINGS[i].id ? DGGS_OK : DGGS_E_CELL));
        if (!err) CHECK_EQ_U64(c, FROZEN_STRINGS[i].id);
    }
    for (int i = 0; i < COUNT(FROZEN_INTS); i++) {
        uint64_t v = FROZEN_INTS[i].v;
        uint8_t ok = 9;
        dggs_valid_ints(&v, 1, &ok);
        CHECK(ok == FROZEN_INTS[i].valid);
        CHECK(dggs_is_valid_cell(v) == FROZEN_INTS[i].valid);
        CHECK((dggs_check_ints(&v, 1) == -1) == FROZEN_INTS[i].valid);
        char buf[DGGS_MAX_CHARS + 1];
        int n = dggs_format_one(v, buf);
        buf[n] = '\0';
        CHECK(strcmp(buf, FROZEN_INTS[i].s) == 0);
    }
    for (int i = 0; i < COUNT(FROZEN_MAX_LEVEL); i++) {
        int64_t bad = 99;
        int level = dggs_max_level(FROZEN_MAX_LEVEL[i].ids, FROZEN_MAX_LEVEL[i].n, &bad);
        CHECK(level == FROZEN_MAX_LEVEL[i].level);
        CHECK(bad == FROZEN_MAX_LEVEL[i].bad);
    }
}

static uint64_t xorshift(uint64_t *s) {
    *s ^= *s << 13;
    *s ^= *s >> 7;
    *s ^= *s << 17;
    return *s;
}

/* A random well-formed id of `level`. */
static uint64_t random_cell(uint64_t *s, int level) {
    uint64_t c = dggs_base_cell((int)(xorshift(s) % 20));
    if (level >= 1) c |= (xorshift(s) % 6 + 1) << DGGS_L1_SHIFT;
    for (int k = 2; k <= level; k++) c |= (xorshift(s) % 3 + 1) << (2 * (DGGS_MAX_LEVEL - k));
    return c;
}

static void check_round_trips(void) {
    uint64_t seed = 0x9E3779B97F4A7C15ULL;
    for (int level = 0; level <= DGGS_MAX_LEVEL; level++) {
        for (int i = 0; i < 200; i++) {
            uint64_t c = random_cell(&seed, level);
            CHECK(dggs_ok(c) && dggs_is_valid(c));
            char s[DGGS_MAX_CHARS + 1];
            CHECK(dggs_cell_to_string(c, s, sizeof s) == DGGS_OK);
            CHECK((int)strlen(s) == level + 1);
            dggs_cell back = 0;
            CHECK(dggs_string_to_cell(s, &back) == DGGS_OK);
            CHECK_EQ_U64(back, c);
            CHECK(dggs_get_level(c) == level);
            CHECK(dggs_get_face(c) == s[0] - 'A');
            /* fill_codes gives the same characters, NUL padded */
            uint8_t row[DGGS_MAX_CHARS];
            dggs_fill_codes_u8(&c, 1, row, DGGS_MAX_CHARS);
            for (int k = 0; k < DGGS_MAX_CHARS; k++) CHECK(row[k] == (k <= level ? (uint8_t)s[k] : 0));
            /* parent_of is the prefix */
            if (level > 0) {
                int64_t p = dggs_parent_of((int64_t)c, -1);
                char ps[DGGS_MAX_CHARS + 1];
                CHECK(dggs_cell_to_string((uint64_t)p, ps, sizeof ps) == DGGS_OK);
                CHECK(strncmp(ps, s, (size_t)level) == 0 && (int)strlen(ps) == level);
            }
            CHECK(dggs_parent_of((int64_t)c, level + 1) == 0);
            CHECK(dggs_parent_of((int64_t)c, 0) == (int64_t)dggs_base_cell(s[0] - 'A'));
            /* a buffer one byte short is refused */
            CHECK(dggs_cell_to_string(c, s, (size_t)level + 1) == DGGS_E_BUFFER);
        }
    }
    /* the branch-free check equals the loop, on random integers and flipped bits of ids */
    for (int i = 0; i < 200000; i++) {
        uint64_t v = xorshift(&seed);
        if (i & 1) v = random_cell(&seed, i % 29) ^ ((uint64_t)1 << (xorshift(&seed) % 64));
        if (i % 7 == 0) v = (v & ~((uint64_t)3 << 62)) | DGGS_MARKER;
        CHECK(dggs_ok(v) == dggs_is_valid(v));
    }
    char s[DGGS_MAX_CHARS + 1];
    CHECK(dggs_cell_to_string(0, s, sizeof s) == DGGS_E_CELL);
    CHECK(dggs_get_level(0) == -1 && dggs_get_face(1) == -1);
    dggs_cell c = 7;
    CHECK(dggs_string_to_cell("A000000000000000000000000000000000", &c) == DGGS_E_CELL && c == 7);
}

static void check_containers(void) {
    /* rows of codes: trailing NULs end an id; an empty row or a NUL inside is invalid */
    const uint32_t codes[4][5] = {{'C', '4', '0', '1', 0}, {'A', 0, 0, 0, 0}, {0, 0, 0, 0, 0}, {'B', 0, '1', 0, 0}};
    uint64_t out[5];
    CHECK(dggs_parse_codes_u32(&codes[0][0], 4, 5, out) == 2);
    CHECK(out[0] != 0 && out[1] == dggs_base_cell(0) && out[2] == 0 && out[3] == 0);
    CHECK(dggs_parse_codes_u32(&codes[0][0], 2, 5, out) == -1);
    /* Arrow: "C401", null, "A", "" with validity 0b1101; a span past the data is invalid */
    const uint8_t data[] = {'C', '4', '0', '1', 'A'};
    const int32_t off32[] = {0, 4, 4, 5, 5, 9};
    const int64_t off64[] = {0, 4, 4, 5, 5, 9};
    const uint8_t validity[] = {0x2D}; /* elements 0, 2, 3, 5 valid */
    CHECK(dggs_parse_arrow32(data, 5, off32, validity, 1, 0, 5, out) == 1);
    CHECK(out[0] != 0 && out[1] == 0 && out[2] == dggs_base_cell(0) && out[3] == 0 && out[4] == 0);
    uint64_t out64[5];
    CHECK(dggs_parse_arrow64(data, 5, off64, NULL, 0, 0, 5, out64) == 1); /* element 1 is empty, not null */
    CHECK(out64[0] == out[0] && out64[1] == 0 && out64[2] == out[2] && out64[4] == 0);
    CHECK(dggs_parse_arrow64(data, 5, off64, NULL, 0, 2, 1, out64) == -1 && out64[0] == dggs_base_cell(0));
    /* NUL-joined: pieces counted past n */
    const uint8_t joined[] = {'C', '4', '0', '1', 0, 'A', 0, 'T', '5'};
    int64_t pieces = 0;
    CHECK(dggs_parse_joined_u8(joined, 9, 3, out, &pieces) == -1 && pieces == 3);
    CHECK(out[0] != 0 && out[1] == dggs_base_cell(0) && out[2] == (dggs_base_cell(19) | ((uint64_t)6 << DGGS_L1_SHIFT)));
    CHECK(dggs_parse_joined_u8(joined, 9, 2, out, &pieces) == -1 && pieces == 3);
    CHECK(dggs_parse_joined_u8(joined, 9, 4, out, &pieces) == -1 && pieces == 3 && out[3] == 0);
    CHECK(dggs_parse_joined_u8(joined, 0, 1, out, &pieces) == 0 && pieces == 1 && out[0] == 0);
    /* max_level: nulls allowed, -1 when only nulls */
    const uint64_t ids[3] = {0, out[0], 0};
    int64_t bad = 5;
    CHECK(dggs_max_level(ids, 3, &bad) == -1 && bad == -1);
    uint64_t c401 = 0;
    CHECK(dggs_string_to_cell("C401", &c401) == DGGS_OK);
    const uint64_t ids2[3] = {0, c401, dggs_base_cell(3)};
    CHECK(dggs_max_level(ids2, 3, &bad) == 3 && bad == -1);
    const uint64_t ids3[3] = {0, c401, 1};
    CHECK(dggs_max_level(ids3, 3, &bad) == -1 && bad == 2);
    CHECK(dggs_check_ints(ids2, 3) == 0 && dggs_check_ints(ids2 + 1, 2) == -1);
    uint32_t rows[2][3];
    dggs_fill_codes_u32(ids2, 2, &rows[0][0], 3);
    CHECK(rows[0][0] == 0 && rows[0][1] == 0 && rows[0][2] == 0);
    CHECK(rows[1][0] == 'C' && rows[1][1] == '4' && rows[1][2] == '0');
}

int main(void) {
    check_frozen();
    check_round_trips();
    check_containers();
    CHECK_DONE();
}
