/* dissolve.c: the outline of a cell set, step by step through the public API (drop covered cells, boundary
 * descendants, outline edges, rings, ring points): invariants (a single cell's outline is its boundary, the globe
 * has none, a disk one ring, a ring two), the public API's errors, and outputs of the numba kernel frozen by
 * tools/freeze_dissolve.py (every level 0..28, poles, antimeridian, vertices, mixed levels, both projections). */
#include <math.h>

#include "bits.h"
#include "check.h"
#include "dggs.h"
#include "dissolve.h"
#include "grid.h"
#include "points.h"

#define COUNT(a) ((int)(sizeof(a) / sizeof((a)[0])))

/* BEGIN FROZEN (tools/freeze_dissolve.py) */
#define FROZEN_ROWS 16
/* the sets' cells (each set sorted, unique) */
static const uint64_t FROZEN_CELLS[] = {
    0x4000000000000000ULL, 0x6040000000000000ULL, 0x6140000000000000ULL, 0x6180000000000000ULL,
    0x6240000000000000ULL, 0x5350000000000000ULL, 0x5360000000000000ULL, 0x5390000000000000ULL,
    0x5c60000000000000ULL, 0x5d50000000000000ULL, 0x5d60000000000000ULL, 0x5d80000000000000ULL,
    0x533c000000000000ULL, 0x5378000000000000ULL, 0x5dbc000000000000ULL, 0x4f7a000000000000ULL,
    0x4776c00000000000ULL, 0x4779c00000000000ULL, 0x477a800000000000ULL, 0x477ac00000000000ULL,
    0x4155500000000000ULL, 0x4155600000000000ULL, 0x4195400000000000ULL, 0x4195a00000000000ULL,
    0x4855500000000000ULL, 0x4855600000000000ULL, 0x4895500000000000ULL, 0x6155540000000000ULL,
    0x6195580000000000ULL, 0x6255540000000000ULL, 0x5d99da0000000000ULL, 0x537d9bc000000000ULL,
    0x537da7c000000000ULL, 0x537dab8000000000ULL, 0x537dabc000000000ULL, 0x4f7997b000000000ULL,
    0x4f7a966000000000ULL, 0x4f7a967000000000ULL, 0x4f7a96b000000000ULL, 0x4f7a974000000000ULL,
    0x4f7a97a000000000ULL, 0x4f7a97b000000000ULL, 0x4779fd5400000000ULL, 0x477af95400000000ULL,
    0x477afd5800000000ULL, 0x4195555500000000ULL, 0x6155555540000000ULL, 0x6195555540000000ULL,
    0x6195555580000000ULL, 0x6255555540000000ULL, 0x5d99da96e0000000ULL, 0x5d99da9990000000ULL,
    0x5d99da99d0000000ULL, 0x5d99da99e0000000ULL, 0x5d99da9a90000000ULL, 0x5d99da9aa0000000ULL,
    0x5d99da9ac0000000ULL, 0x537dabdbf4000000ULL, 0x537dabdbfc000000ULL, 0x537dabebf8000000ULL,
    0x4f7a977756000000ULL, 0x477afd569e400000ULL, 0x477afd569f400000ULL, 0x477afd569f800000ULL,
    0x477afd56df400000ULL, 0x4155555555500000ULL, 0x4155555555600000ULL, 0x4195555555400000ULL,
    0x4195555555a00000ULL, 0x4855555555500000ULL, 0x4855555555600000ULL, 0x4895555555500000ULL,
    0x6155555555540000ULL, 0x6195555555580000ULL, 0x6255555555540000ULL, 0x5d99da9adaf60000ULL,
    0x537dabdbf9e98000ULL, 0x537dabdbf9e9c000ULL, 0x537dabdbf9eac000ULL, 0x537dabdbf9edc000ULL,
    0x4f7a97775695e000ULL, 0x4f7a977756d59000ULL, 0x4f7a977756d5a000ULL, 0x4f7a977756d5c000ULL,
    0x4f7a977756d69000ULL, 0x4f7a977756d6d000ULL, 0x4f7a977756d6e000ULL, 0x477afd569f699400ULL,
    0x477afd569f69d800ULL, 0x477afd569f6ad400ULL, 0x4195555555555500ULL, 0x6155555555555540ULL,
    0x6195555555555540ULL, 0x6195555555555580ULL, 0x6255555555555540ULL, 0x5d99da9adaf65e40ULL,
    0x5d99da9adaf65e80ULL, 0x5d99da9adaf65f50ULL, 0x5d99da9adaf65f70ULL, 0x5d99da9adafa5e50ULL,
    0x537dabdbf9e9db54ULL, 0x537dabdbf9e9db5cULL, 0x537dabdbf9e9db68ULL, 0x4f7a977756d5df6eULL,
    0x4000000000000000ULL, 0x4200000000000000ULL, 0x4400000000000000ULL, 0x4600000000000000ULL,
    0x4800000000000000ULL, 0x4a00000000000000ULL, 0x4c00000000000000ULL, 0x4e00000000000000ULL,
    0x5000000000000000ULL, 0x5200000000000000ULL, 0x5400000000000000ULL, 0x5600000000000000ULL,
    0x5800000000000000ULL, 0x5a00000000000000ULL, 0x5c00000000000000ULL, 0x5e00000000000000ULL,
    0x6000000000000000ULL, 0x6200000000000000ULL, 0x6400000000000000ULL, 0x6600000000000000ULL,
    0x4080000000000000ULL, 0x40c0000000000000ULL, 0x4100000000000000ULL, 0x4240000000000000ULL,
    0x4280000000000000ULL, 0x42c0000000000000ULL, 0x4300000000000000ULL, 0x4340000000000000ULL,
    0x4380000000000000ULL, 0x4440000000000000ULL, 0x4480000000000000ULL, 0x44c0000000000000ULL,
    0x4500000000000000ULL, 0x4540000000000000ULL, 0x4580000000000000ULL, 0x4640000000000000ULL,
    0x4680000000000000ULL, 0x46c0000000000000ULL, 0x4700000000000000ULL, 0x4740000000000000ULL,
    0x4780000000000000ULL, 0x4880000000000000ULL, 0x48c0000000000000ULL, 0x4900000000000000ULL,
    0x4940000000000000ULL, 0x4980000000000000ULL, 0x4a40000000000000ULL, 0x4a80000000000000ULL,
    0x4ac0000000000000ULL, 0x4b00000000000000ULL, 0x4b40000000000000ULL, 0x4b80000000000000ULL,
    0x4c40000000000000ULL, 0x4c80000000000000ULL, 0x4cc0000000000000ULL, 0x4d00000000000000ULL,
    0x4d40000000000000ULL, 0x4d80000000000000ULL, 0x4e40000000000000ULL, 0x4e80000000000000ULL,
    0x4ec0000000000000ULL, 0x4f00000000000000ULL, 0x4f40000000000000ULL, 0x4f80000000000000ULL,
    0x5040000000000000ULL, 0x5080000000000000ULL, 0x50c0000000000000ULL, 0x5100000000000000ULL,
    0x5140000000000000ULL, 0x5180000000000000ULL, 0x5240000000000000ULL, 0x5280000000000000ULL,
    0x52c0000000000000ULL, 0x5300000000000000ULL, 0x5340000000000000ULL, 0x5380000000000000ULL,
    0x5440000000000000ULL, 0x5480000000000000ULL, 0x54c0000000000000ULL, 0x5500000000000000ULL,
    0x5540000000000000ULL, 0x5580000000000000ULL, 0x5640000000000000ULL, 0x5680000000000000ULL,
    0x56c0000000000000ULL, 0x5700000000000000ULL, 0x5740000000000000ULL, 0x5780000000000000ULL,
    0x5840000000000000ULL, 0x5880000000000000ULL, 0x58c0000000000000ULL, 0x5900000000000000ULL,
    0x5940000000000000ULL, 0x5980000000000000ULL, 0x5a40000000000000ULL, 0x5a80000000000000ULL,
    0x5ac0000000000000ULL, 0x5b00000000000000ULL, 0x5b40000000000000ULL, 0x5b80000000000000ULL,
    0x5c40000000000000ULL, 0x5c80000000000000ULL, 0x5cc0000000000000ULL, 0x5d00000000000000ULL,
    0x5d40000000000000ULL, 0x5d80000000000000ULL, 0x5e40000000000000ULL, 0x5e80000000000000ULL,
    0x5ec0000000000000ULL, 0x5f00000000000000ULL, 0x5f40000000000000ULL, 0x5f80000000000000ULL,
    0x6040000000000000ULL, 0x6080000000000000ULL, 0x60c0000000000000ULL, 0x6100000000000000ULL,
    0x6140000000000000ULL, 0x6180000000000000ULL, 0x6240000000000000ULL, 0x6280000000000000ULL,
    0x62c0000000000000ULL, 0x6300000000000000ULL, 0x6340000000000000ULL, 0x6380000000000000ULL,
    0x6440000000000000ULL, 0x6480000000000000ULL, 0x64c0000000000000ULL, 0x6500000000000000ULL,
    0x6540000000000000ULL, 0x6580000000000000ULL, 0x6640000000000000ULL, 0x6680000000000000ULL,
    0x66c0000000000000ULL, 0x6700000000000000ULL, 0x6740000000000000ULL, 0x6780000000000000ULL,
    0x4000000000000000ULL, 0x4559000000000000ULL, 0x455a000000000000ULL, 0x455d000000000000ULL,
    0x4569000000000000ULL, 0x4a00000000000000ULL, 0x4200000000000000ULL, 0x4280000000000000ULL,
    0x42b0000000000000ULL, 0x4550000000000000ULL, 0x4558000000000000ULL, 0x455b000000000000ULL,
};
/* per set: its cells (first, count), densify, cells kept by drop_covered, fine cells, outline edges, rings,
 * the rings' starts (at most 8 rings frozen), ring point rows (ISEA, IVEA), its first frozen row (the first
 * min(rows, FROZEN_ROWS) of ISEA's, then of IVEA's, in FROZEN_RING_ROWS) */
static const struct {
    int first, count, densify, kept, fine, edges, rings;
    int64_t starts[9];
    int64_t rows[2];
    int row;
} FROZEN_SETS[] = {
    {0, 1, 0, 1, 1, 3, 1, {0, 3}, {5, 5}, 0}, /* level 0: the cell at the north pole */
    {1, 4, 1, 4, 4, 6, 1, {0, 6}, {14, 14}, 10}, /* level 1: disk 1 at the south pole */
    {5, 7, 2, 7, 9, 9, 1, {0, 9}, {29, 29}, 38}, /* level 2: compacted disk 2 at the antimeridian, levels 1..2 */
    {12, 3, 0, 3, 3, 9, 3, {0, 3, 6, 9}, {13, 13}, 70}, /* level 3: ring 1 at the vertex on the antimeridian (a hole) */
    {15, 1, 1, 1, 1, 3, 1, {0, 3}, {6, 6}, 96}, /* level 4: the cell at the vertex */
    {16, 4, 2, 4, 4, 6, 1, {0, 6}, {18, 18}, 108}, /* level 5: disk 1 at the anywhere */
    {20, 7, 0, 7, 9, 9, 1, {0, 9}, {10, 10}, 140}, /* level 6: compacted disk 2 at the north pole, levels 5..6 */
    {27, 3, 1, 3, 3, 9, 3, {0, 3, 6, 9}, {21, 21}, 160}, /* level 7: ring 1 at the south pole (a hole) */
    {30, 1, 2, 1, 1, 3, 1, {0, 3}, {11, 11}, 192}, /* level 8: the cell at the antimeridian */
    {31, 4, 0, 4, 4, 6, 1, {0, 6}, {8, 8}, 214}, /* level 9: disk 1 at the vertex on the antimeridian */
    {35, 7, 1, 7, 9, 9, 1, {0, 9}, {18, 18}, 230}, /* level 10: compacted disk 2 at the vertex, levels 9..10 */
    {42, 3, 2, 3, 3, 9, 3, {0, 3, 6, 9}, {27, 27}, 262}, /* level 11: ring 1 at the anywhere (a hole) */
    {45, 1, 0, 1, 1, 3, 1, {0, 3}, {4, 4}, 294}, /* level 12: the cell at the north pole */
    {46, 4, 1, 4, 4, 6, 1, {0, 6}, {14, 14}, 302}, /* level 13: disk 1 at the south pole */
    {50, 7, 2, 7, 9, 9, 1, {0, 9}, {29, 27}, 330}, /* level 14: compacted disk 2 at the antimeridian, levels 13..14 */
    {57, 3, 0, 3, 3, 9, 3, {0, 3, 6, 9}, {13, 13}, 362}, /* level 15: ring 1 at the vertex on the antimeridian (a hole) */
    {60, 1, 1, 1, 1, 3, 1, {0, 3}, {6, 6}, 388}, /* level 16: the cell at the vertex */
    {61, 4, 2, 4, 4, 6, 1, {0, 6}, {18, 18}, 400}, /* level 17: disk 1 at the anywhere */
    {65, 7, 0, 7, 9, 9, 1, {0, 9}, {10, 10}, 432}, /* level 18: compacted disk 2 at the north pole, levels 17..18 */
    {72, 3, 1, 3, 3, 9, 3, {0, 3, 6, 9}, {21, 21}, 452}, /* level 19: ring 1 at the south pole (a hole) */
    {75, 1, 2, 1, 1, 3, 1, {0, 3}, {11, 9}, 484}, /* level 20: the cell at the antimeridian */
    {76, 4, 0, 4, 4, 6, 1, {0, 6}, {8, 6}, 504}, /* level 21: disk 1 at the vertex on the antimeridian */
    {80, 7, 1, 7, 9, 9, 1, {0, 9}, {18, 18}, 518}, /* level 22: compacted disk 2 at the vertex, levels 21..22 */
    {87, 3, 2, 3, 3, 9, 3, {0, 3, 6, 9}, {27, 27}, 550}, /* level 23: ring 1 at the anywhere (a hole) */
    {90, 1, 0, 1, 1, 3, 1, {0, 3}, {4, 4}, 582}, /* level 24: the cell at the north pole */
    {91, 4, 1, 4, 4, 6, 1, {0, 6}, {14, 14}, 590}, /* level 25: disk 1 at the south pole */
    {95, 5, 2, 5, 9, 9, 1, {0, 9}, {29, 27}, 618}, /* level 26: compacted disk 2 at the antimeridian, levels 25..26 */
    {100, 3, 0, 3, 3, 9, 3, {0, 3, 6, 9}, {13, 9}, 650}, /* level 27: ring 1 at the vertex on the antimeridian (a hole) */
    {103, 1, 1, 1, 1, 3, 1, {0, 3}, {6, 6}, 672}, /* level 28: the cell at the vertex */
    {104, 20, 2, 20, 20, 0, 0, {0}, {0, 0}, 684}, /* the globe */
    {124, 116, 0, 116, 116, 6, 1, {0, 6}, {7, 7}, 684}, /* the globe less a level-1 disk at the north pole */
    {240, 6, 1, 6, 76, 54, 2, {0, 48, 54}, {109, 109}, 698}, /* two whole faces and a level-3 blob */
    {246, 6, 2, 2, 13, 13, 1, {0, 13}, {39, 39}, 730}, /* duplicates and ancestors */
};
/* ring point rows: lat, lng, corner */
static const struct {
    double lat, lng;
    int corner;
} FROZEN_RING_ROWS[] = {
    {0x1.d32d5ad561420p+5, -0x1.5180000000000p+7, 1},
    {0x1.fd5157b6d117dp+4, -0x1.3b00000000000p+6, 1},
    {0x1.d32d5ad561424p+5, 0x1.67ffffffffffbp+3, 1},
    {0x1.6800000000000p+6, 0x1.67fffffff6badp+3, 0},
    {0x1.6800000000000p+6, -0x1.517fffffff9d4p+7, 0},
    {0x1.d32d5ad561424p+5, -0x1.517ffffffffffp+7, 1},
    {0x1.fd5157b6d1186p+4, -0x1.3affffffffffep+6, 1},
    {0x1.d32d5ad561424p+5, 0x1.67ffffffffffcp+3, 1},
    {0x1.6800000000000p+6, 0x1.67ffffffe02f1p+3, 0},
    {0x1.6800000000000p+6, -0x1.517ffffffe318p+7, 0},
    {-0x1.14b888ff2114fp+6, -0x1.3b00000000001p+6, 1},
    {-0x1.f465e8cecc32cp+5, -0x1.8a13b0d4e457ap+6, 0},
    {-0x1.b0f9b1878b542p+5, -0x1.b9deb19cb3c44p+6, 1},
    {-0x1.de2efbb0a81f0p+5, -0x1.14d3d29bd57f0p+7, 0},
    {-0x1.d32d5ad561424p+5, -0x1.5180000000000p+7, 1},
    {-0x1.02726f4003efdp+6, -0x1.6800000000000p+7, 0},
    {-0x1.1a530525210c8p+6, 0x1.38c9c29e1b65cp+7, 0},
    {-0x1.14b888ff2114fp+6, 0x1.9500000000001p+6, 1},
    {-0x1.3e32e406d89d2p+6, 0x1.94ffffffffffap+6, 0},
    {-0x1.6800000000000p+6, 0x1.94ffffffdaaacp+6, 0},
    {-0x1.6800000000000p+6, 0x1.67ffffff66b86p+3, 0},
    {-0x1.27a4dd1fb7dd5p+6, 0x1.67fffffffffd8p+3, 0},
    {-0x1.d32d5ad561420p+5, 0x1.6800000000020p+3, 1},
    {-0x1.1a530525210c8p+6, -0x1.79b1eb0f24d0ap+4, 0},
    {-0x1.14b888ff21150p+6, -0x1.3b00000000001p+6, 1},
    {-0x1.f49e094041961p+5, -0x1.89dd06a196ee3p+6, 0},
    {-0x1.b0f9b1878b544p+5, -0x1.b9deb19cb3c49p+6, 1},
    {-0x1.de03f9d7ac839p+5, -0x1.14414fa24e3b7p+7, 0},
    {-0x1.d32d5ad561424p+5, -0x1.5180000000000p+7, 1},
    {-0x1.02726f4003efdp+6, -0x1.6800000000000p+7, 0},
    {-0x1.198c9f6cb9964p+6, 0x1.3b898d9487b21p+7, 0},
    {-0x1.14b888ff2114ep+6, 0x1.9500000000004p+6, 1},
    {-0x1.3e0d39efc63c4p+6, 0x1.9500000000001p+6, 0},
    {-0x1.6800000000000p+6, 0x1.95000000040c9p+6, 0},
    {-0x1.6800000000000p+6, 0x1.67ffffffc6766p+3, 0},
    {-0x1.2839e9d5ef77bp+6, 0x1.67fffffffffe9p+3, 0},
    {-0x1.d32d5ad561424p+5, 0x1.67ffffffffffbp+3, 1},
    {-0x1.198c9f6cb9965p+6, -0x1.63b3935bc26f0p+4, 0},
    {0x1.410e1c846ba5cp+5, 0x1.5eb6d63ca672cp+7, 1},
    {0x1.59afc703690edp+5, 0x1.57d0103077b89p+7, 0},
    {0x1.7164d978db29ep+5, 0x1.4ffd9fd5e97b4p+7, 0},
    {0x1.870a66656402ap+5, 0x1.46aaee0b5a43fp+7, 1},
    {0x1.654364c29f304p+5, 0x1.39865745b8010p+7, 0},
    {0x1.41149ded102c0p+5, 0x1.2e48833822d79p+7, 0},
    {0x1.1b15687559582p+5, 0x1.2480000000000p+7, 1},
    {0x1.e9a750c78322ap+4, 0x1.33149e3fc3922p+7, 0},
    {0x1.96d129d35ba0cp+4, 0x1.404e3c9e9b2ecp+7, 0},
    {0x1.3ec08e8bc8c34p+4, 0x1.4c87b1faa6d2bp+7, 1},
    {0x1.0f9841ed1ed70p+4, 0x1.524e4b0790028p+7, 0},
    {0x1.bf7e8665b5970p+3, 0x1.580ca6e07f1c4p+7, 0},
    {0x1.61786304d3307p+3, 0x1.5e1832683828ep+7, 1},
    {0x1.ca1cf23467aabp+3, 0x1.6800000000000p+7, 0},
    {0x1.d045b767fc13cp+3, -0x1.676632840abb4p+7, 0},
    {0x1.1d4bba0217562p+4, -0x1.5ca1a49ed1de2p+7, 0},
    {0x1.406d2c14d7b48p+5, 0x1.5e9fb9947e26ep+7, 1},
    {0x1.58e8001e67091p+5, 0x1.5799aa3b10383p+7, 0},
    {0x1.7142e3219aaf2p+5, 0x1.4ffb9b5d45bc0p+7, 0},
    {0x1.89a2f2b9bd1e8p+5, 0x1.47d384934a8a7p+7, 1},
    {0x1.67cc6cf61ea30p+5, 0x1.3a681efa9ca66p+7, 0},
    {0x1.42c7b1ede12b7p+5, 0x1.2ec350ab91b14p+7, 0},
    {0x1.1b15687559582p+5, 0x1.2480000000000p+7, 1},
    {0x1.e9cd2003adb46p+4, 0x1.32e29d02fb163p+7, 0},
    {0x1.980b59933325bp+4, 0x1.402dcb5d5a547p+7, 0},
    {0x1.400da5be555eap+4, 0x1.4c970be803ac0p+7, 1},
    {0x1.1130accc7f5d3p+4, 0x1.52769b20eb0e5p+7, 0},
    {0x1.c006057e45992p+3, 0x1.580e6a05b9438p+7, 0},
    {0x1.585af121c4dd6p+3, 0x1.5d41534a3d1e4p+7, 1},
    {0x1.c86448c2660dbp+3, 0x1.67d51e2554a55p+7, 0},
    {0x1.ca1cf23467aacp+3, 0x1.6800000000000p+7, 0},
    {0x1.1aea8feda4e23p+4, -0x1.5d21a983e6c18p+7, 0},
    {0x1.d32d5ad561422p+5, -0x1.517ffffffffffp+7, 1},
    {0x1.de0d6cf8b4498p+5, -0x1.6800000000000p+7, 0},
    {0x1.e0da82698a8dfp+5, 0x1.56d181a2e429fp+7, 1},
    {0x1.a588065b72318p+5, 0x1.563b57f410287p+7, 1},
    {0x1.be9ddcf0a0036p+5, 0x1.6800000000000p+7, 0},
    {0x1.410e1c846ba5cp+5, 0x1.5eb6d63ca672cp+7, 1},
    {0x1.79d633f66b56bp+5, 0x1.6800000000000p+7, 0},
    {0x1.8d7f49ae601b9p+5, -0x1.641cf1f50d5bdp+7, 1},
    {0x1.92c5a6e94f979p+5, -0x1.6800000000000p+7, 0},
    {0x1.a588065b72318p+5, 0x1.563b57f410287p+7, 1},
    {0x1.d32d5ad561422p+5, -0x1.5180000000000p+7, 1},
    {0x1.8d7f49ae601b8p+5, -0x1.641cf1f50d5bcp+7, 1},
    {0x1.6d9e39e2084e9p+5, -0x1.5180000000000p+7, 1},
    {0x1.d32d5ad561422p+5, -0x1.5180000000001p+7, 1},
    {0x1.de0d6cf8b449ap+5, -0x1.6800000000000p+7, 0},
    {0x1.e0df4249487afp+5, 0x1.5620ff1271d5ap+7, 1},
    {0x1.a78b5a7dbc15ap+5, 0x1.577204b9db9dfp+7, 1},
    {0x1.be9ddcf0a0037p+5, 0x1.6800000000000p+7, 0},
    {0x1.406d2c14d7b48p+5, 0x1.5e9fb9947e26ep+7, 1},
    {0x1.79d633f66b56fp+5, 0x1.6800000000000p+7, 0},
    {0x1.8c48ecef09c02p+5, -0x1.645d9391cddc5p+7, 1},
    {0x1.915abcbcff17ep+5, -0x1.6800000000000p+7, 0},
    {0x1.a78b5a7dbc15ap+5, 0x1.577204b9db9dfp+7, 1},
    {0x1.d32d5ad561424p+5, -0x1.5180000000000p+7, 1},
    {0x1.8c48ecef09c00p+5, -0x1.645d9391cddc4p+7, 1},
    {0x1.712f0ac067fddp+5, -0x1.5180000000000p+7, 1},
    {-0x1.dd9acff5eeaefp+2, 0x1.0505b551a6fcfp+5, 1},
    {-0x1.4ff4cf83cf639p+3, 0x1.0d3386570ba10p+5, 0},
    {-0x1.b3b41d35af3acp+3, 0x1.146f5086bef0bp+5, 1},
    {-0x1.acc752516ab73p+3, 0x1.24bc044f91ebfp+5, 0},
    {-0x1.a526bb0881bf0p+3, 0x1.35099e42662e9p+5, 1},
    {-0x1.493fcbeb5b4c6p+3, 0x1.1d8605e696629p+5, 0},
    {-0x1.cd06d4ccb6acap+2, 0x1.07f46a9443c35p+5, 1},
    {-0x1.508feb94b4349p+3, 0x1.0d929c93689d8p+5, 0},
    {-0x1.b75ebe5d06bb5p+3, 0x1.13f5162eaa9b0p+5, 1},
    {-0x1.b1679be596e4dp+3, 0x1.243b0ef7f96ffp+5, 0},
    {-0x1.aa08a476856cap+3, 0x1.349ea370e797bp+5, 1},
    {-0x1.4c3ac66eba3adp+3, 0x1.1d6ad5cd37445p+5, 0},
    {0x1.8425070b44d9cp+3, 0x1.77a18a5639096p+5, 1},
    {0x1.a5f0047cfd748p+3, 0x1.74a256f4934aep+5, 0},
    {0x1.c817615143b0dp+3, 0x1.71a080540db77p+5, 0},
    {0x1.ea9720df6e13dp+3, 0x1.6e9bcfe0dc939p+5, 1},
    {0x1.e2dae8e79714ap+3, 0x1.681096d91caddp+5, 0},
    {0x1.db31ef219e340p+3, 0x1.6190e38546dc9p+5, 0},
    {0x1.d391e3558247bp+3, 0x1.5b1b9a96a2aeap+5, 1},
    {0x1.c44daf5957ff4p+3, 0x1.4e4c9f9b0a680p+5, 0},
    {0x1.b4deea7fd7085p+3, 0x1.419d840e97227p+5, 0},
    {0x1.a526bb0881bf8p+3, 0x1.35099e42662efp+5, 1},
    {0x1.9f198d59aa59cp+3, 0x1.3ffbb8360a7d5p+5, 0},
    {0x1.990625375b188p+3, 0x1.4af7ec83ef75dp+5, 0},
    {0x1.931086317e3e8p+3, 0x1.5601cea2078c4p+5, 1},
    {0x1.7d832707844a1p+3, 0x1.5450a0ab42fb1p+5, 0},
    {0x1.67eeeb5f5982bp+3, 0x1.52a03af92d9e2p+5, 0},
    {0x1.525396e8480f8p+3, 0x1.50f0766e35b59p+5, 1},
    {0x1.768dde2a9fb4bp+3, 0x1.767af8b015e6dp+5, 1},
    {0x1.9c0ba55a1f62dp+3, 0x1.73b5725bd5e43p+5, 0},
    {0x1.c13e151074fd0p+3, 0x1.70e72e29a60f1p+5, 0},
    {0x1.e63b37f1d6585p+3, 0x1.6e11bf3ff2d9bp+5, 1},
    {0x1.e0f832aa66026p+3, 0x1.67a790df65c55p+5, 0},
    {0x1.db579595cb15fp+3, 0x1.613c898972e0bp+5, 0},
    {0x1.d55a13d4ec034p+3, 0x1.5ad1e454856aap+5, 1},
    {0x1.c84c1d4b9c443p+3, 0x1.4e02ad96e0d07p+5, 0},
    {0x1.b9d798e0b2ffbp+3, 0x1.4143b91106046p+5, 0},
    {0x1.aa08a476856ccp+3, 0x1.349ea370e797fp+5, 1},
    {0x1.a42f4957113cfp+3, 0x1.3f99bd20ab977p+5, 0},
    {0x1.9d7458a1a1364p+3, 0x1.4a9cdc3f3b4dep+5, 0},
    {0x1.95b47ded96b3ap+3, 0x1.55a385ff5792ep+5, 1},
    {0x1.80748ee3df9fap+3, 0x1.53ecf1ce168f4p+5, 0},
    {0x1.6b2e32ee63a8bp+3, 0x1.5237f84f05e2ep+5, 0},
    {0x1.55dfd1aaa12a8p+3, 0x1.508487e8ef8dap+5, 1},
    {0x1.6334134d9b786p+6, -0x1.517ffffffffd6p+7, 1},
    {0x1.5f68a57f49e9ap+6, -0x1.0f92b10d877d0p+7, 1},
    {0x1.5ea9ca80874b5p+6, -0x1.3afffffffffc6p+6, 1},
    {0x1.5a9527e32f4dcp+6, -0x1.0721febae8018p+5, 1},
    {0x1.5f68a57f49e99p+6, -0x1.5b6a7793c4141p+4, 1},
    {0x1.599d3c49ec152p+6, 0x1.67fffffffff84p+3, 1},
    {0x1.6334134d9b786p+6, 0x1.68000000000d5p+3, 1},
    {0x1.5f68a57f49e9bp+6, 0x1.61b53bc9e20adp+5, 1},
    {0x1.5ea9ca80874b6p+6, 0x1.950000000003ap+6, 1},
    {0x1.638f8a0cc46a3p+6, 0x1.6800000000000p+7, 0},
    {0x1.6334b7964fe40p+6, -0x1.517ffffffffd9p+7, 1},
    {0x1.5f6a7f0f27297p+6, -0x1.0f3543f90ba9cp+7, 1},
    {0x1.5ea7f15df9327p+6, -0x1.3b0000000000dp+6, 1},
    {0x1.5a93d2dcf8e95p+6, -0x1.099fa8713fa23p+5, 1},
    {0x1.5f6a7f0f27298p+6, -0x1.5e55e037a2b4ep+4, 1},
    {0x1.59a8789e33f52p+6, 0x1.67fffffffff3bp+3, 1},
    {0x1.6334b7964fe40p+6, 0x1.6800000000036p+3, 1},
    {0x1.5f6a7f0f27297p+6, 0x1.632af01bd1564p+5, 1},
    {0x1.5ea7f15df9329p+6, 0x1.9500000000003p+6, 1},
    {0x1.63901bd074358p+6, 0x1.6800000000000p+7, 0},
    {-0x1.6334134d9b786p+6, 0x1.67ffffffffe78p+3, 1},
    {-0x1.6523727f24828p+6, -0x1.5c02a9d87cff6p+4, 0},
    {-0x1.64e250bb54b05p+6, -0x1.3b000000000bdp+6, 1},
    {-0x1.667108de0e31dp+6, -0x1.3b00000000188p+6, 0},
    {-0x1.6800000000000p+6, -0x1.3b000003dbae3p+6, 0},
    {-0x1.6800000000000p+6, 0x1.680000023958fp+3, 0},
    {-0x1.659a059cbea78p+6, 0x1.67ffffffff96bp+3, 0},
    {-0x1.6334134d9b782p+6, -0x1.517ffffffffe0p+7, 1},
    {-0x1.6523727f24825p+6, -0x1.0f7faac4f05fep+7, 0},
    {-0x1.64e250bb54b05p+6, -0x1.3b000000000bdp+6, 1},
    {-0x1.63ecb230e15eap+6, -0x1.7f8fdfcacacf2p+6, 0},
    {-0x1.62bee0f780e0bp+6, -0x1.a7db55c5eff27p+6, 1},
    {-0x1.63b4f756c7164p+6, -0x1.0f850be317daep+7, 0},
    {-0x1.6334134d9b786p+6, -0x1.518000000000ep+7, 1},
    {-0x1.6441264cae658p+6, -0x1.6800000000000p+7, 0},
    {-0x1.6523727f24828p+6, 0x1.3c7faac4f05e9p+7, 0},
    {-0x1.6334b7964fe40p+6, 0x1.67ffffffffee3p+3, 1},
    {-0x1.65237c3a23decp+6, -0x1.5c8b923794f35p+4, 0},
    {-0x1.64e28f605ad32p+6, -0x1.3affffffffff5p+6, 1},
    {-0x1.667146a32b1d0p+6, -0x1.3b00000000028p+6, 0},
    {-0x1.6800000000000p+6, -0x1.3affffff31c6ep+6, 0},
    {-0x1.6800000000000p+6, 0x1.67fffffc82795p+3, 0},
    {-0x1.6599e9136804ep+6, 0x1.67ffffffffd7cp+3, 0},
    {-0x1.6334b7964fe40p+6, -0x1.517fffffffff5p+7, 1},
    {-0x1.65237c3a23decp+6, -0x1.0f6e8db90d615p+7, 0},
    {-0x1.64e28f605ad32p+6, -0x1.3affffffffff5p+6, 1},
    {-0x1.63ec3bafe9fdep+6, -0x1.7f77249c9c742p+6, 0},
    {-0x1.62bdcb593bd76p+6, -0x1.a79448ff0a0ebp+6, 1},
    {-0x1.63b53f9b826b7p+6, -0x1.0f5ff5b9d1738p+7, 0},
    {-0x1.6334b7964fe40p+6, -0x1.5180000000005p+7, 1},
    {-0x1.64413053f987dp+6, -0x1.6800000000000p+7, 0},
    {-0x1.65237c3a23debp+6, 0x1.3c6e8db90d64fp+7, 0},
    {0x1.e5e2a1f22b95ep+4, -0x1.6760b6df4cecdp+7, 1},
    {0x1.e3e05bf829d4fp+4, -0x1.67db828f84a9bp+7, 0},
    {0x1.e346b8c91bfe7p+4, -0x1.6800000000000p+7, 0},
    {0x1.e1dbbd50b91c1p+4, 0x1.67aa22eb8994dp+7, 0},
    {0x1.dfd4d8ba561d2p+4, 0x1.6730382acbb8ep+7, 1},
    {0x1.ddf9d89b96e15p+4, 0x1.6763dc2b1e883p+7, 0},
    {0x1.dc1e85da0e447p+4, 0x1.67975f010f5bdp+7, 0},
    {0x1.da42e0afab853p+4, 0x1.67cac0f0b5ee5p+7, 1},
    {0x1.dd339481f1582p+4, 0x1.6800000000000p+7, 0},
    {0x1.de24696fbc07dp+4, -0x1.67eee41503701p+7, 0},
    {0x1.e204587a86df4p+4, -0x1.67a80c4266719p+7, 0},
    {0x1.e4ff2c52a4da0p+4, -0x1.6741510b66810p+7, 1},
    {0x1.e307cfcf72946p+4, -0x1.67bd27044ac86p+7, 0},
    {0x1.e1f6a57f896adp+4, -0x1.6800000000000p+7, 0},
    {0x1.e10e8b888cbedp+4, 0x1.67c765938c727p+7, 0},
    {0x1.df135cb7d306fp+4, 0x1.674c544a35bb0p+7, 1},
    {0x1.dd39eaf5083e1p+4, 0x1.67805cbba984bp+7, 0},
    {0x1.db6032eea6de5p+4, 0x1.67b43f96c6c9fp+7, 0},
    {0x1.d986349691cffp+4, 0x1.67e7fd067e51bp+7, 1},
    {0x1.dad187c851b27p+4, 0x1.6800000000000p+7, 0},
    {0x1.dd5a79bb73644p+4, -0x1.67d0d15ad6806p+7, 0},
    {0x1.e12d76d609cadp+4, -0x1.67894124bb0fap+7, 0},
    {0x1.a6ec6a9d2cbe2p+5, -0x1.67a68b4525c48p+7, 1},
    {0x1.a67a82f0ce950p+5, -0x1.6800000000000p+7, 0},
    {0x1.a52a04ed09970p+5, 0x1.66fb7f7f96d42p+7, 1},
    {0x1.a43259aa47741p+5, 0x1.67cb28108a5b0p+7, 1},
    {0x1.a175ce9151bedp+5, 0x1.673ea6df6359ep+7, 1},
    {0x1.a27269a552238p+5, 0x1.6800000000000p+7, 0},
    {0x1.a337ce31a2093p+5, -0x1.6766c1d239176p+7, 1},
    {0x1.a415ddd383dd5p+5, -0x1.66b806d2f2933p+7, 1},
    {0x1.a646e74bb8e07p+5, -0x1.67a66ad8aab3fp+7, 1},
    {0x1.a5d5dfb23a0e0p+5, -0x1.6800000000000p+7, 0},
    {0x1.a490f5237b420p+5, 0x1.6701f81201efcp+7, 1},
    {0x1.a37dc28d3f3b7p+5, 0x1.67c4aa325fca9p+7, 1},
    {0x1.a0b3837b75becp+5, 0x1.673227ada05dbp+7, 1},
    {0x1.a1bdfa2c755a9p+5, 0x1.6800000000000p+7, 0},
    {0x1.a26aa6ef1d237p+5, -0x1.6778d1a0e8ee2p+7, 1},
    {0x1.a343979f68e3ep+5, -0x1.66ccefa5056f4p+7, 1},
    {-0x1.5a45d1141e82cp+3, 0x1.21e96f36ac0fdp+5, 1},
    {-0x1.584e3ec976b29p+3, 0x1.2213c2d2abe4ap+5, 0},
    {-0x1.5656c8c591664p+3, 0x1.223e0be5b30d5p+5, 1},
    {-0x1.54e681d7ee650p+3, 0x1.2133844b349c1p+5, 0},
    {-0x1.5375cd7bc96d8p+3, 0x1.2028e258ba767p+5, 1},
    {-0x1.53fb56ff6f858p+3, 0x1.1ef4058cd1fc3p+5, 0},
    {-0x1.548009a437250p+3, 0x1.1dbf1e352b788p+5, 1},
    {-0x1.56347a9607022p+3, 0x1.1e2f6b5aebc98p+5, 0},
    {-0x1.57e8fd3889f38p+3, 0x1.1e9fa6dee8e0cp+5, 1},
    {-0x1.5a22327216fe7p+3, 0x1.1ddaf9f3e4972p+5, 0},
    {-0x1.5c5b25abd46a4p+3, 0x1.1d164298fac2ap+5, 1},
    {-0x1.5bd718f7113e7p+3, 0x1.1e4b1bae1e87dp+5, 0},
    {-0x1.5b5231e03841cp+3, 0x1.1f7feb1f23c88p+5, 1},
    {-0x1.5d499341d4f39p+3, 0x1.1f5591f3e09a6p+5, 0},
    {-0x1.5f411147b4c99p+3, 0x1.1f2b2dc9de109p+5, 1},
    {-0x1.60b35d54c9ef3p+3, 0x1.20357dbed5083p+5, 0},
    {-0x1.5e24b6d5a1892p+3, 0x1.219e40c3e1409p+5, 1},
    {-0x1.5c294a8b4347bp+3, 0x1.21ca30a309884p+5, 0},
    {-0x1.5a2dd9501c50dp+3, 0x1.21f61aebbf2bfp+5, 1},
    {-0x1.58994db4dbe50p+3, 0x1.20f2151ab1a9fp+5, 0},
    {-0x1.57027bf17083ap+3, 0x1.1fee76b6d342fp+5, 1},
    {-0x1.576575f3a2a31p+3, 0x1.1ebf1f9868b7bp+5, 0},
    {-0x1.57c69b9e280cbp+3, 0x1.1d90066900e0bp+5, 1},
    {-0x1.59926207b7002p+3, 0x1.1dfb57edb4683p+5, 0},
    {-0x1.5b5d7d094ea09p+3, 0x1.1e66cc3cd1fdbp+5, 1},
    {-0x1.5d8a8a9d99076p+3, 0x1.1da2e117a41c6p+5, 0},
    {-0x1.5fb74cec7791cp+3, 0x1.1cdee6e0c3874p+5, 1},
    {-0x1.5f5568910064dp+3, 0x1.1e0e63180e7c8p+5, 0},
    {-0x1.5ef1b3cde9f8cp+3, 0x1.1f3e1b75c0f61p+5, 1},
    {-0x1.60ed727029541p+3, 0x1.1f11f6cd7adebp+5, 0},
    {-0x1.62e92b396b4a2p+3, 0x1.1ee5cc7e40da7p+5, 1},
    {-0x1.647ecdf7fbbd4p+3, 0x1.1fe9d857b30c7p+5, 0},
    {0x1.87cd08f263fdcp+3, 0x1.6d911c3a271c2p+5, 1},
    {0x1.87f8cefc5b078p+3, 0x1.6d26501a6f0bap+5, 0},
    {0x1.8824e963f3941p+3, 0x1.6cbb8e80f1b88p+5, 0},
    {0x1.885156bf6c9d9p+3, 0x1.6c50d756863dbp+5, 1},
    {0x1.8787527299b29p+3, 0x1.6c402421d3846p+5, 0},
    {0x1.86bd4b368fb56p+3, 0x1.6c2f7168a4d87p+5, 0},
    {0x1.85f3410ac559fp+3, 0x1.6c1ebf2a7bb8fp+5, 1},
    {0x1.8690f043ee5e7p+3, 0x1.6c9a2210fdc05p+5, 0},
    {0x1.872edd067b7b2p+3, 0x1.6d1596600e516p+5, 0},
    {0x1.88d882ac1f240p+3, 0x1.6b10ef8c5ce2ep+5, 1},
    {0x1.88ab24c1e775dp+3, 0x1.6b7b87f303b50p+5, 0},
    {0x1.887e15a99e0bdp+3, 0x1.6be62a842aa26p+5, 0},
    {0x1.885156bf6c9d9p+3, 0x1.6c50d756863dbp+5, 1},
    {0x1.891b581d91ba4p+3, 0x1.6c618b073b927p+5, 0},
    {0x1.89e5568d92427p+3, 0x1.6c723f34721ddp+5, 0},
    {0x1.8aaf520ff766bp+3, 0x1.6c82f3dea8883p+5, 1},
    {0x1.8139ac00354ddp+3, 0x1.6cd4a14537517p+5, 1},
    {0x1.81a4083f1db79p+3, 0x1.6c6d24e6a60cep+5, 0},
    {0x1.820dd307c281fp+3, 0x1.6c059f1ed7784p+5, 0},
    {0x1.82770d2cf6df4p+3, 0x1.6b9e1022ed2dcp+5, 1},
    {0x1.81b0b64ba4255p+3, 0x1.6b8d7c02dd4b2p+5, 0},
    {0x1.80ea5fbef3f87p+3, 0x1.6b7ce89e8c9c9p+5, 0},
    {0x1.80240985e9ce9p+3, 0x1.6b6c55f5761eep+5, 1},
    {0x1.808138825e564p+3, 0x1.6be47544c4e31p+5, 0},
    {0x1.80ddc404225e2p+3, 0x1.6c5c8e6ff5a45p+5, 0},
    {0x1.83af5ff2203e5p+3, 0x1.6a672e0049805p+5, 1},
    {0x1.8347d2d254544p+3, 0x1.6aced7601aaa5p+5, 0},
    {0x1.82dfb780593cep+3, 0x1.6b36782764ffdp+5, 0},
    {0x1.82770d2cf6df4p+3, 0x1.6b9e1022ed2dcp+5, 1},
    {0x1.833d6463e7617p+3, 0x1.6baea4ff4155dp+5, 0},
    {0x1.8403bbf16f9c9p+3, 0x1.6bbf3a985ee2bp+5, 0},
    {0x1.84ca13d688374p+3, 0x1.6bcfd0eecb016p+5, 1},
    {0x1.67a751c9d095ep+6, -0x1.3affffffff931p+6, 1},
    {0x1.67d2850ea9531p+6, 0x1.67ffffffff2e8p+3, 1},
    {0x1.6800000000000p+6, 0x1.67fffec736c93p+3, 0},
    {0x1.6800000000000p+6, -0x1.3affffef45700p+6, 0},
    {0x1.67a764f4df477p+6, -0x1.3afffffffff4ap+6, 1},
    {0x1.67d27b0cbcdf3p+6, 0x1.67fffffffc872p+3, 1},
    {0x1.6800000000000p+6, 0x1.67ffff4a60ac3p+3, 0},
    {0x1.6800000000000p+6, -0x1.3b00000296e7dp+6, 0},
    {-0x1.67d2850ea9532p+6, 0x1.6800000001684p+3, 1},
    {-0x1.67e4e0b776193p+6, -0x1.5c5e4be103e25p+4, 0},
    {-0x1.67e2703e59a48p+6, -0x1.3b0000000157dp+6, 1},
    {-0x1.67d9569e310cep+6, -0x1.7f6a982a381abp+6, 0},
    {-0x1.67ce2a9d25c6ap+6, -0x1.a79bb647f0508p+6, 1},
    {-0x1.67d75101e4d06p+6, -0x1.0f7472452010cp+7, 0},
    {-0x1.67d2850ea9532p+6, -0x1.51800000000b6p+7, 1},
    {-0x1.67dc7e718a8e7p+6, -0x1.6800000000000p+7, 0},
    {-0x1.67e4e0b776193p+6, 0x1.3c743683df8efp+7, 0},
    {-0x1.67e2703e59a48p+6, 0x1.94fffffffea40p+6, 1},
    {-0x1.67f13813e0c9ep+6, 0x1.94fffffffd621p+6, 0},
    {-0x1.6800000000000p+6, 0x1.94ffff9ae96e6p+6, 0},
    {-0x1.6800000000000p+6, 0x1.67ffffbbf3430p+3, 0},
    {-0x1.67e9428747365p+6, 0x1.67fffffffdd22p+3, 0},
    {-0x1.67d27b0cbcdf3p+6, 0x1.67fffffffd4c0p+3, 1},
    {-0x1.67e4de3eb3125p+6, -0x1.5ba6e2f2fbc53p+4, 0},
    {-0x1.67e276fbffc8ap+6, -0x1.3b00000000082p+6, 1},
    {-0x1.67d95da56cd59p+6, -0x1.7f86a6e223241p+6, 0},
    {-0x1.67ce30c2d4b91p+6, -0x1.a7c2d475d467bp+6, 1},
    {-0x1.67d74d6212a1dp+6, -0x1.0f8a956cb4389p+7, 0},
    {-0x1.67d27b0cbcdf2p+6, -0x1.518000000009cp+7, 1},
    {-0x1.67dc7a35002b8p+6, -0x1.6800000000000p+7, 0},
    {-0x1.67e4de3eb3125p+6, 0x1.3c8b23a1a0875p+7, 0},
    {-0x1.67e276fbffc8bp+6, 0x1.95000000002b7p+6, 1},
    {-0x1.67f13b7dfc64ap+6, 0x1.9500000000600p+6, 0},
    {-0x1.6800000000000p+6, 0x1.9500002523029p+6, 0},
    {-0x1.6800000000000p+6, 0x1.67ffff0198ed4p+3, 0},
    {-0x1.67e93d5d1fc2ap+6, 0x1.67fffffffce4cp+3, 0},
    {0x1.dfd483f99b8bdp+4, -0x1.67f608372e7a1p+7, 1},
    {0x1.dff945c17600fp+4, -0x1.67f369e38bfbdp+7, 0},
    {0x1.e01e06f8eb2f3p+4, -0x1.67f0cb64175e9p+7, 0},
    {0x1.e042c79fd3e57p+4, -0x1.67ee2cb8ce36fp+7, 1},
    {0x1.e0420789d7103p+4, -0x1.67f163b385a58p+7, 0},
    {0x1.e041472269cc1p+4, -0x1.67f49aab57804p+7, 0},
    {0x1.e0408669935c9p+4, -0x1.67f7d1a0444d5p+7, 1},
    {0x1.e06486da6e493p+4, -0x1.67f86a2160276p+7, 0},
    {0x1.e088871bc724ep+4, -0x1.67f902a6e2372p+7, 0},
    {0x1.e0ac872da6ff9p+4, -0x1.67f99b30ce6f2p+7, 1},
    {0x1.e087c620f2296p+4, -0x1.67fc39c638513p+7, 0},
    {0x1.e0630483f8a88p+4, -0x1.67fed82fd8919p+7, 0},
    {0x1.e052cbabffe20p+4, -0x1.6800000000000p+7, 0},
    {0x1.e03e4256e183fp+4, 0x1.67fe89924e614p+7, 1},
    {0x1.e04fe1adab512p+4, 0x1.67fca1b5a0af4p+7, 0},
    {0x1.e06180e80acfdp+4, 0x1.67fab9cd3f2e2p+7, 0},
    {0x1.df06eea7768a3p+4, -0x1.67d7f7a19c54fp+7, 1},
    {0x1.df2b34cea0177p+4, -0x1.67d55259e362fp+7, 0},
    {0x1.df4f7a82abfcfp+4, -0x1.67d2acf0d15cep+7, 0},
    {0x1.df73bfc39b98dp+4, -0x1.67d0076661f3fp+7, 1},
    {0x1.df732da69f47fp+4, -0x1.67d345b1420dfp+7, 0},
    {0x1.df729b44b7e2bp+4, -0x1.67d683f9ed789p+7, 0},
    {0x1.df72089de0af6p+4, -0x1.67d9c24063d17p+7, 1},
    {0x1.df95bba5ec637p+4, -0x1.67da5b37f2589p+7, 0},
    {0x1.dfb96e88f71a5p+4, -0x1.67daf43b7e05fp+7, 0},
    {0x1.dfdd214707588p+4, -0x1.67db8d4b07ee3p+7, 1},
    {0x1.dfb8dba64b2bap+4, -0x1.67de32aae4827p+7, 0},
    {0x1.df949592782ebp+4, -0x1.67e0d7e961f77p+7, 0},
    {0x1.df704f0b8d090p+4, -0x1.67e37d06849cap+7, 1},
    {0x1.df81dec767453p+4, -0x1.67e568c5a0596p+7, 0},
    {0x1.df936e6b056fbp+4, -0x1.67e75491f768bp+7, 0},
    {0x1.dfa4fdf667be8p+4, -0x1.67e9406b8a5b2p+7, 1},
    {0x1.a4e5b4d29ffa8p+5, -0x1.67f3d57a0797dp+7, 1},
    {0x1.a4f45d151cb2cp+5, -0x1.6800000000000p+7, 0},
    {0x1.a4f833e14b88cp+5, 0x1.67fccfa88b89fp+7, 1},
    {0x1.a4e6a4f1a8eaep+5, 0x1.67fe0554c75d7p+7, 1},
    {0x1.a4e683897445ap+5, 0x1.6800000000000p+7, 0},
    {0x1.a51b50fc494b1p+5, 0x1.67fa6367a4520p+7, 1},
    {0x1.a4f833e14b88cp+5, 0x1.67fccfa88b89fp+7, 1},
    {0x1.a4fc4ccd47de6p+5, 0x1.6800000000000p+7, 0},
    {0x1.a50083d45d986p+5, -0x1.67fcb8016108dp+7, 1},
    {0x1.a50a685579a7cp+5, -0x1.6800000000000p+7, 0},
    {0x1.a4e5b4d29ffa8p+5, -0x1.67f3d57a0797dp+7, 1},
    {0x1.a508d316e3570p+5, -0x1.67f63f53f19b8p+7, 1},
    {0x1.a50083d45d986p+5, -0x1.67fcb8016108dp+7, 1},
    {0x1.a4328060a21f1p+5, -0x1.67f9d23943d89p+7, 1},
    {0x1.a43b41f82e14bp+5, -0x1.6800000000000p+7, 0},
    {0x1.a446f360ad813p+5, 0x1.67f7bfac3a5c5p+7, 1},
    {0x1.a434a18004ef4p+5, 0x1.67f89b8b61947p+7, 1},
    {0x1.a43378c225d17p+5, 0x1.6800000000000p+7, 0},
    {0x1.a46b988134ecap+5, 0x1.67f608291f066p+7, 1},
    {0x1.a446f360ad813p+5, 0x1.67f7bfac3a5c5p+7, 1},
    {0x1.a44f0ba05f2e1p+5, 0x1.67fe1b1c47b36p+7, 1},
    {0x1.a4328060a21f1p+5, -0x1.67f9d23943d89p+7, 1},
    {0x1.a457233f01879p+5, -0x1.67fb89216a1b5p+7, 1},
    {0x1.a45174d8603ddp+5, -0x1.6800000000000p+7, 0},
    {0x1.a44f0ba05f2e1p+5, 0x1.67fe1b1c47b36p+7, 1},
    {0x1.a448591d569bep+5, 0x1.6800000000000p+7, 0},
    {-0x1.5a0060dbc3e6cp+3, 0x1.1ff47ce6c2be4p+5, 1},
    {-0x1.5a0e11671f1c3p+3, 0x1.1ffe5b8a889d3p+5, 0},
    {-0x1.5a1bc1cb52fc5p+3, 0x1.20083a254cb11p+5, 1},
    {-0x1.5a091d90b002ep+3, 0x1.2009cb49e7be7p+5, 0},
    {-0x1.59f6796024205p+3, 0x1.200b5c6ab0ba5p+5, 1},
    {-0x1.59fb6d4469fa3p+3, 0x1.1fffecaa50becp+5, 0},
    {-0x1.5da6f0d0f0438p+3, 0x1.1fb24696befa5p+5, 1},
    {-0x1.5db6000e72a4ap+3, 0x1.1fbbe592d4ab1p+5, 0},
    {-0x1.5dc50e830be12p+3, 0x1.1fc584b2f7619p+5, 1},
    {-0x1.5db240ba995d2p+3, 0x1.1fc726b2c5767p+5, 0},
    {-0x1.5d9f72f0194cap+3, 0x1.1fc8c8b09e7d5p+5, 1},
    {-0x1.5da332342b1c6p+3, 0x1.1fbd8799111c8p+5, 0},
    {0x1.899e92ba45d82p+3, 0x1.6cc868b433636p+5, 1},
    {0x1.899ba7b85551bp+3, 0x1.6cc61f6130e02p+5, 0},
    {0x1.8998bcbbca9c0p+3, 0x1.6cc3d60fb6c93p+5, 0},
    {0x1.8995d1c4a50aap+3, 0x1.6cc18cbfc5103p+5, 1},
    {0x1.898cb1ef6b15dp+3, 0x1.6cc4e26b3d88fp+5, 0},
    {0x1.8983923cb6d38p+3, 0x1.6cc8381840f95p+5, 0},
    {0x1.897a72ac8c0a2p+3, 0x1.6ccb8dc6cf994p+5, 1},
    {0x1.8984d8af550cep+3, 0x1.6cce75997e74dp+5, 0},
    {0x1.898f3eb23bbd4p+3, 0x1.6cd15d6f33e6ap+5, 0},
    {0x1.8999a4b540e77p+3, 0x1.6cd44547f011dp+5, 1},
    {0x1.899e3465b1aa8p+3, 0x1.6cd29a6c61cb2p+5, 0},
    {0x1.89a2c41ec7326p+3, 0x1.6cd0ef9136746p+5, 0},
    {0x1.89a753e08104ep+3, 0x1.6ccf44b66e067p+5, 1},
    {0x1.89b0737ddfa81p+3, 0x1.6ccbef0205c95p+5, 0},
    {0x1.89b9933dc9cc4p+3, 0x1.6cc8994f28db6p+5, 0},
    {0x1.89c2b3203bab7p+3, 0x1.6cc5439dd704cp+5, 1},
    {0x1.838af87e17c49p+3, 0x1.6c12c5dc40a87p+5, 1},
    {0x1.83894061ae263p+3, 0x1.6c108c495bedap+5, 0},
    {0x1.83878837043c2p+3, 0x1.6c0e52b5eeddep+5, 0},
    {0x1.8385cffe1a0acp+3, 0x1.6c0c1921f98ddp+5, 1},
    {0x1.837a8fca5524ap+3, 0x1.6c0f51b6218d1p+5, 0},
    {0x1.836f4f6aa2d76p+3, 0x1.6c128a4680562p+5, 0},
    {0x1.83640edefe54ep+3, 0x1.6c15c2d315451p+5, 1},
    {0x1.836d1f0f0fca8p+3, 0x1.6c1899abf2321p+5, 0},
    {0x1.83762f2ddd655p+3, 0x1.6c1b708535d4cp+5, 0},
    {0x1.837f3f3b67fb8p+3, 0x1.6c1e475ee028ap+5, 1},
    {0x1.8384dfb1deb0ep+3, 0x1.6c1cab1b71955p+5, 0},
    {0x1.838a801d57627p+3, 0x1.6c1b0ed710308p+5, 0},
    {0x1.8390207dd2aa1p+3, 0x1.6c197291bc0ecp+5, 1},
    {0x1.839b611dd362fp+3, 0x1.6c163a043be6ap+5, 0},
    {0x1.83a6a191e5a8cp+3, 0x1.6c130172f1c09p+5, 0},
    {0x1.83b1e1da0e49ep+3, 0x1.6c0fc8ddde405p+5, 1},
    {0x1.67fe50c7a6215p+6, -0x1.517ffffffac8dp+7, 1},
    {0x1.67fcfc886fe73p+6, -0x1.0f73cbf729c12p+7, 1},
    {0x1.67fcb71ee8860p+6, -0x1.3afffffff593bp+6, 1},
    {0x1.67fb4b78b6614p+6, -0x1.0832703c4d589p+5, 1},
    {0x1.67fcfc886fe72p+6, -0x1.5c61a046a2d6fp+4, 1},
    {0x1.67faf256f26efp+6, 0x1.67ffffffe4d97p+3, 1},
    {0x1.67fe50c7a6215p+6, 0x1.6800000000345p+3, 1},
    {0x1.67fcfc886fe74p+6, 0x1.6230d0235535cp+5, 1},
    {0x1.67fcb71ee8860p+6, 0x1.950000000c160p+6, 1},
    {0x1.67fe71077027cp+6, 0x1.6800000000000p+7, 0},
    {0x1.67fe5062e1e47p+6, -0x1.517ffffff7eadp+7, 1},
    {0x1.67fcfc3f51d2cp+6, -0x1.0f8c20955db05p+7, 1},
    {0x1.67fcb7e31b657p+6, -0x1.3b000000025dfp+6, 1},
    {0x1.67fb4b712ae0ep+6, -0x1.07c859ea2ca62p+5, 1},
    {0x1.67fcfc3f51d2cp+6, -0x1.5b9efb55169bep+4, 1},
    {0x1.67faf12a01923p+6, 0x1.67ffffffd23a3p+3, 1},
    {0x1.67fe5062e1e47p+6, 0x1.6800000006d98p+3, 1},
    {0x1.67fcfc3f51d2dp+6, 0x1.61cf7daa7a319p+5, 1},
    {0x1.67fcb7e31b659p+6, 0x1.94ffffffffddcp+6, 1},
    {0x1.67fe70bb7f216p+6, 0x1.6800000000000p+7, 0},
    {-0x1.67fe50c7a6215p+6, 0x1.67ffffffe1bb7p+3, 1},
    {-0x1.67fefed835762p+6, -0x1.5c61e774c3fd2p+4, 0},
    {-0x1.67fee7b4d86a1p+6, -0x1.3b000000241adp+6, 1},
    {-0x1.67ff73da683cap+6, -0x1.3b000000412e8p+6, 0},
    {-0x1.6800000000000p+6, -0x1.3b000afedbea0p+6, 0},
    {-0x1.6800000000000p+6, 0x1.67ffeb3a19c34p+3, 0},
    {-0x1.67ff2863d3107p+6, 0x1.67ffffff29f9bp+3, 0},
    {-0x1.67fe50c7a6215p+6, -0x1.517fffffff6d8p+7, 1},
    {-0x1.67fefed835762p+6, -0x1.0f73c3116bacfp+7, 0},
    {-0x1.67fee7b4d86a1p+6, -0x1.3b000000241adp+6, 1},
    {-0x1.67fe916c34a99p+6, -0x1.7f6934619c337p+6, 0},
    {-0x1.67fe277f8ecdep+6, -0x1.a7994dddbbae3p+6, 1},
    {-0x1.67fe7e444a21ep+6, -0x1.0f73c54ae59b0p+7, 0},
    {-0x1.67fe50c7a6215p+6, -0x1.51800000005c0p+7, 1},
    {-0x1.67feaf5a20e5ep+6, -0x1.6800000000000p+7, 0},
    {-0x1.67fefed835762p+6, 0x1.3c73c3116a997p+7, 0},
    {-0x1.67fe5062e1e47p+6, 0x1.67ffffffb0afep+3, 1},
    {-0x1.67fefebfc219cp+6, -0x1.5b9e52a1d7a06p+4, 0},
    {-0x1.67fee7f65e763p+6, -0x1.3b00000006c2fp+6, 1},
    {-0x1.67ff73fb2f3b1p+6, -0x1.3b0000000bfbdp+6, 0},
    {-0x1.6800000000000p+6, -0x1.3b00017fec08bp+6, 0},
    {-0x1.6800000000000p+6, 0x1.67ffec6b26798p+3, 0},
    {-0x1.67ff283162733p+6, 0x1.67ffffffa894ep+3, 0},
    {-0x1.67fe5062e1e47p+6, -0x1.517ffffffd295p+7, 1},
    {-0x1.67fefebfc219bp+6, -0x1.0f8c35abc17b1p+7, 0},
    {-0x1.67fee7f65e763p+6, -0x1.3b00000006c2fp+6, 1},
    {-0x1.67fe91b2f75a1p+6, -0x1.7f874f1951e8fp+6, 0},
    {-0x1.67fe27bfcabe8p+6, -0x1.a7c4bade04f33p+6, 1},
    {-0x1.67fe7e1fa497ap+6, -0x1.0f8c30661ddc4p+7, 0},
    {-0x1.67fe5062e1e47p+6, -0x1.518000000102bp+7, 1},
    {-0x1.67feaf3054a13p+6, -0x1.6800000000000p+7, 0},
    {-0x1.67fefebfc219bp+6, 0x1.3c8c35abc5568p+7, 0},
    {0x1.dffe40f023ec3p+4, 0x1.67ff991ea6d20p+7, 1},
    {0x1.dffef664af8f2p+4, 0x1.67ffc400191dbp+7, 0},
    {0x1.dfffabd8f2db4p+4, 0x1.67ffeee19939fp+7, 0},
    {0x1.dffff449532bbp+4, 0x1.6800000000000p+7, 0},
    {0x1.e000614cedd07p+4, -0x1.67ffe63cd8d90p+7, 1},
    {0x1.e00108651d786p+4, -0x1.67fff84d5ecffp+7, 0},
    {0x1.e0014f991a805p+4, -0x1.6800000000000p+7, 0},
    {0x1.e001af7d4324bp+4, 0x1.67fff5a2171e7p+7, 0},
    {0x1.e00256955ed6ep+4, 0x1.67ffe39188f1ep+7, 1},
    {0x1.e000fa092867fp+4, 0x1.67ffcac083881p+7, 0},
    {0x1.dfff9d7cbf6ecp+4, 0x1.67ffb1ef8d7d7p+7, 0},
    {0x1.df30d76d1fb57p+4, -0x1.67e26cc020f38p+7, 1},
    {0x1.df3188e02c59cp+4, -0x1.67e241782c9efp+7, 0},
    {0x1.df323a52fcd68p+4, -0x1.67e216302c3e6p+7, 0},
    {0x1.df32ebc5912b5p+4, -0x1.67e1eae81fd1cp+7, 1},
    {0x1.df33924973917p+4, -0x1.67e1fd1d3e6ecp+7, 0},
    {0x1.df3438cd4d73fp+4, -0x1.67e20f5261b07p+7, 0},
    {0x1.df34df511ed20p+4, -0x1.67e221878996dp+7, 1},
    {0x1.df33875a9cdf4p+4, -0x1.67e23a9a72695p+7, 0},
    {0x1.df322f63f2805p+4, -0x1.67e253ad4f883p+7, 0},
    {0x1.a4f9e971bd830p+5, -0x1.67ffa7ab696a1p+7, 1},
    {0x1.a4fb36658294dp+5, -0x1.67ffbe9b061fep+7, 1},
    {0x1.a4fbdcdf42b19p+5, -0x1.67ffca12fd418p+7, 1},
    {0x1.a4fbe06de3e2ap+5, -0x1.6800000000000p+7, 0},
    {0x1.a4fbe5b87396dp+5, 0x1.67ffafc404300p+7, 1},
    {0x1.a4fa98c516f2ap+5, 0x1.67ffc6b478d78p+7, 1},
    {0x1.a4fae2618dee7p+5, 0x1.6800000000000p+7, 0},
    {0x1.a4fae7956bc1ep+5, -0x1.67fffbf355fa9p+7, 1},
    {0x1.a4486f2368363p+5, 0x1.67fb2c0a5c245p+7, 1},
    {0x1.a449ca8bb1cf4p+5, 0x1.67fb1bc3c0066p+7, 1},
    {0x1.a44a7840143abp+5, 0x1.67fb13a07c546p+7, 1},
    {0x1.a44a8c746cfa4p+5, 0x1.67fa92f051f9fp+7, 1},
    {0x1.a449310b587abp+5, 0x1.67faa3372489bp+7, 1},
    {0x1.a4497dcba16c3p+5, 0x1.67fadf7d63d77p+7, 1},
    {-0x1.5a009552a419ap+3, 0x1.20004eafa250ap+5, 1},
    {-0x1.5a007dd89093fp+3, 0x1.200084e75d1aap+5, 0},
    {-0x1.5a00665e764d3p+3, 0x1.2000bb1f179d2p+5, 1},
    {-0x1.59ff33d4ea35fp+3, 0x1.20006c6612e05p+5, 0},
    {-0x1.59fe014b64bc5p+3, 0x1.20001dad063d8p+5, 1},
    {-0x1.59fd7f80a924fp+3, 0x1.1fffc018c02c3p+5, 0},
    {-0x1.59fcfdb5dfcf0p+3, 0x1.1fff628476f06p+5, 1},
    {-0x1.59fdae749e364p+3, 0x1.1fff53a945c28p+5, 0},
    {-0x1.59fe5f336029fp+3, 0x1.1fff44ce133c8p+5, 1},
    {-0x1.59ffc0b0eeb37p+3, 0x1.1fff2717aa29ep+5, 0},
    {-0x1.5a01222e8b6b4p+3, 0x1.1fff09613bb88p+5, 1},
    {-0x1.5a01a3f987331p+3, 0x1.1fff66f57ac7ap+5, 0},
    {-0x1.5a0225c4753bbp+3, 0x1.1fffc489b6accp+5, 1},
    {-0x1.5a0175059449cp+3, 0x1.1fffd364f1f58p+5, 0},
    {-0x1.5a00c446b6e30p+3, 0x1.1fffe2402be65p+5, 1},
    {-0x1.5a01f6d06c2c0p+3, 0x1.200030f92c624p+5, 0},
    {-0x1.5da87d7ee3e2bp+3, 0x1.1fbde126d8919p+5, 1},
    {-0x1.5da86bbc76bfep+3, 0x1.1fbe16813d08cp+5, 0},
    {-0x1.5da859f9faed4p+3, 0x1.1fbe4bdba35d3p+5, 1},
    {-0x1.5da718ea07cc1p+3, 0x1.1fbe001dbed88p+5, 0},
    {-0x1.5da5d7d9c0d7fp+3, 0x1.1fbdb45fead25p+5, 1},
    {-0x1.5da54913a274bp+3, 0x1.1fbd5926b159ep+5, 0},
    {-0x1.5da4ba4d3d826p+3, 0x1.1fbcfded848adp+5, 1},
    {-0x1.5da56c97bf71fp+3, 0x1.1fbcee720ba7cp+5, 0},
    {-0x1.5da61ee240a81p+3, 0x1.1fbcdef69214bp+5, 1},
    {-0x1.5da7837740e84p+3, 0x1.1fbcbfff9cdf2p+5, 0},
    {-0x1.5da8e80c3e432p+3, 0x1.1fbca108a4ea0p+5, 1},
    {-0x1.5da976d27d995p+3, 0x1.1fbcfc41df482p+5, 0},
    {-0x1.5daa059876602p+3, 0x1.1fbd577b264f7p+5, 1},
    {-0x1.5da9534e0498bp+3, 0x1.1fbd66f69e1cfp+5, 0},
    {-0x1.5da8a1039217fp+3, 0x1.1fbd7672153a8p+5, 1},
    {-0x1.5da9e213bd145p+3, 0x1.1fbdc22fef8b3p+5, 0},
    {0x1.8999192211629p+3, 0x1.6ccc45ded1efcp+5, 1},
    {0x1.8999098d101bfp+3, 0x1.6ccc6b5bd2f9cp+5, 0},
    {0x1.8998f9f8190ecp+3, 0x1.6ccc90d8d54d7p+5, 0},
    {0x1.8998ea632c3b9p+3, 0x1.6cccb655d8eabp+5, 1},
    {0x1.8999314ef3872p+3, 0x1.6cccbc348da93p+5, 0},
    {0x1.8999783aba755p+3, 0x1.6cccc21342772p+5, 0},
    {0x1.8999bf268107cp+3, 0x1.6cccc7f1f754ap+5, 1},
    {0x1.899987cfa98dfp+3, 0x1.6ccc9c963e0b8p+5, 0},
    {0x1.89995078d9ac5p+3, 0x1.6ccc713a86ea0p+5, 0},
    {0x1.8998bba4a31c9p+3, 0x1.6ccd26cceb7c9p+5, 1},
    {0x1.89992dd0af754p+3, 0x1.6ccd1cdc783cap+5, 0},
    {0x1.89999ffcbf3f4p+3, 0x1.6ccd12ec04d71p+5, 0},
    {0x1.899a1228d27aap+3, 0x1.6ccd08fb914c2p+5, 1},
    {0x1.8999f67d60192p+3, 0x1.6cccf34db2c51p+5, 0},
    {0x1.8999dad1ef9dep+3, 0x1.6cccdd9fd4c80p+5, 0},
    {0x1.8999bf268107cp+3, 0x1.6cccc7f1f754ap+5, 1},
    {0x1.83832c8ee5025p+3, 0x1.6c16839c608c6p+5, 1},
    {0x1.8383078249cb7p+3, 0x1.6c16a7f9aff41p+5, 0},
    {0x1.8382e2759ccecp+3, 0x1.6c16cc56fe3a0p+5, 0},
    {0x1.8382bd68de0cfp+3, 0x1.6c16f0b44b5e1p+5, 1},
    {0x1.8383030ca88a2p+3, 0x1.6c16f687a619ep+5, 0},
    {0x1.838348b073129p+3, 0x1.6c16fc5b00ed2p+5, 0},
    {0x1.83838e543da67p+3, 0x1.6c17022e5bd7dp+5, 1},
    {0x1.83836dbd341f8p+3, 0x1.6c16d7fdb37e8p+5, 0},
    {0x1.83834d2616937p+3, 0x1.6c16adcd0a656p+5, 0},
    {0x1.83824e423725bp+3, 0x1.6c175dcc2bffbp+5, 1},
    {0x1.8382c93e5edabp+3, 0x1.6c17545a8ff2ap+5, 0},
    {0x1.8383443a83f07p+3, 0x1.6c174ae8f39a1p+5, 0},
    {0x1.8383bf36a6673p+3, 0x1.6c17417756f5ep+5, 1},
    {0x1.8383aeeb33286p+3, 0x1.6c172c5f03714p+5, 0},
    {0x1.83839e9fbae85p+3, 0x1.6c171746afbc8p+5, 0},
    {0x1.83838e543da67p+3, 0x1.6c17022e5bd7dp+5, 1},
    {0x1.67ffe0db32ebfp+6, -0x1.3afffffed14eep+6, 1},
    {0x1.67fff00764f7ap+6, 0x1.67ffffea6af90p+3, 1},
    {0x1.6800000000000p+6, 0x1.67fd98af56735p+3, 0},
    {0x1.6800000000000p+6, -0x1.3affd22059e8ep+6, 0},
    {0x1.67ffe0e27c45fp+6, -0x1.3affffffe0d5dp+6, 1},
    {0x1.67fff003a77bcp+6, 0x1.67fffff195b7ep+3, 1},
    {0x1.6800000000000p+6, 0x1.67fe18395bb10p+3, 0},
    {0x1.6800000000000p+6, -0x1.3afff3b96e92ep+6, 0},
    {-0x1.67fff00764f7ep+6, 0x1.67fffff2c71cap+3, 1},
    {-0x1.67fff679c9613p+6, -0x1.5c6209bd974b5p+4, 0},
    {-0x1.67fff59e66437p+6, -0x1.3b000003ea394p+6, 1},
    {-0x1.67fff26c4d1dep+6, -0x1.7f692731e0f7dp+6, 0},
    {-0x1.67ffee7ffb453p+6, -0x1.a79937060856cp+6, 1},
    {-0x1.67fff1b6ae0f9p+6, -0x1.0f73bedd96f8dp+7, 0},
    {-0x1.67fff00764f7ep+6, -0x1.518000004fe20p+7, 1},
    {-0x1.67fff38814636p+6, -0x1.6800000000000p+7, 0},
    {-0x1.67fff679c9612p+6, 0x1.3c73bec781ec2p+7, 0},
    {-0x1.67fff59e66438p+6, 0x1.94fffffbfe535p+6, 1},
    {-0x1.67fffacf33206p+6, 0x1.94fffff8e4677p+6, 0},
    {-0x1.6800000000000p+6, 0x1.94fed2212f97dp+6, 0},
    {-0x1.6800000000000p+6, 0x1.67ff2675d9287p+3, 0},
    {-0x1.67fff803b27c0p+6, 0x1.67fffff374354p+3, 0},
    {-0x1.67fff003a77bcp+6, 0x1.67fffff8a36d0p+3, 1},
    {-0x1.67fff678e131cp+6, -0x1.5b9e016996b71p+4, 0},
    {-0x1.67fff5a0d4175p+6, -0x1.3affffffdbc85p+6, 1},
    {-0x1.67fff26eed7aep+6, -0x1.7f87555b16f53p+6, 0},
    {-0x1.67ffee825e657p+6, -0x1.a7c4ccf14a53cp+6, 1},
    {-0x1.67fff1b551cb3p+6, -0x1.0f8c3fa0aa214p+7, 0},
    {-0x1.67fff003a77bcp+6, -0x1.518000003c2dfp+7, 1},
    {-0x1.67fff38687827p+6, -0x1.6800000000000p+7, 0},
    {-0x1.67fff678e131cp+6, 0x1.3c8c3fd2e9167p+7, 0},
    {-0x1.67fff5a0d4176p+6, 0x1.95000000af297p+6, 1},
    {-0x1.67fffad06a0bap+6, 0x1.94ffffff72da4p+6, 0},
    {-0x1.6800000000000p+6, 0x1.950064ac38dd3p+6, 0},
    {-0x1.6800000000000p+6, 0x1.67fdf9f65d6a3p+3, 0},
    {-0x1.67fff801d3b8cp+6, 0x1.67fffff462f79p+3, 0},
    {0x1.dffffc7e4ee17p+4, -0x1.67fffe0f7ebbfp+7, 1},
    {0x1.e0000922fbf37p+4, -0x1.67fffe451ffb4p+7, 0},
    {0x1.e00015c7a8ff6p+4, -0x1.67fffe7ac13b1p+7, 0},
    {0x1.e000226c56058p+4, -0x1.67fffeb0627b8p+7, 1},
    {0x1.e000222843e19p+4, -0x1.67ffffd14fe58p+7, 0},
    {0x1.e000221d43fb2p+4, -0x1.6800000000000p+7, 0},
    {0x1.e00021e431b38p+4, 0x1.67ffff0dc2b0dp+7, 0},
    {0x1.e00021a01f7b5p+4, 0x1.67fffdecd5478p+7, 1},
    {0x1.e0002117faecep+4, 0x1.67fffbaafa75dp+7, 0},
    {0x1.e000208fd6367p+4, 0x1.67fff9691fa59p+7, 0},
    {0x1.e0002007b1579p+4, 0x1.67fff72744d6dp+7, 1},
    {0x1.e000136304492p+4, 0x1.67fff75ce6305p+7, 0},
    {0x1.e00006be57346p+4, 0x1.67fff79287894p+7, 0},
    {0x1.dffffa19aa1a3p+4, 0x1.67fff7c828e1bp+7, 1},
    {0x1.dffffa5dbc90fp+4, 0x1.67fff8e916409p+7, 0},
    {0x1.dffffaa1cefe4p+4, 0x1.67fffa0a039fcp+7, 0},
    {0x1.df3289309b860p+4, -0x1.67e202f3b66e6p+7, 1},
    {0x1.df3295ba0e419p+4, -0x1.67e203297a399p+7, 0},
    {0x1.df32a24380f90p+4, -0x1.67e2035f3e063p+7, 0},
    {0x1.df32aeccf3ab9p+4, -0x1.67e2039501d45p+7, 1},
    {0x1.df32ae991fa4dp+4, -0x1.67e204b8829fbp+7, 0},
    {0x1.df32ae654b95fp+4, -0x1.67e205dc036acp+7, 0},
    {0x1.df32ae31777e3p+4, -0x1.67e206ff84359p+7, 1},
    {0x1.df32adc9cf356p+4, -0x1.67e2094685ca6p+7, 0},
    {0x1.df32ad6226ca5p+4, -0x1.67e20b8d875e1p+7, 0},
    {0x1.df32acfa7e3d3p+4, -0x1.67e20dd488f0bp+7, 1},
    {0x1.df32a0710b857p+4, -0x1.67e20d9ec50a9p+7, 0},
    {0x1.df3293e798c91p+4, -0x1.67e20d6901260p+7, 0},
    {0x1.df32875e2608ap+4, -0x1.67e20d333d42fp+7, 1},
    {0x1.df328791fa554p+4, -0x1.67e20c0fbc81bp+7, 0},
    {0x1.df3287c5ce989p+4, -0x1.67e20aec3bc04p+7, 0},
    {0x1.df3287f9a2d41p+4, -0x1.67e209c8bafe8p+7, 1},
    {0x1.a4fb28290bbe6p+5, -0x1.67fffded1dc8bp+7, 1},
    {0x1.a4fb257efd335p+5, -0x1.6800000000000p+7, 0},
    {0x1.a4fb225282edep+5, 0x1.67fffd879a54dp+7, 1},
    {0x1.a4fb1f5927793p+5, 0x1.6800000000000p+7, 0},
    {0x1.a4fb1f1357f56p+5, -0x1.67ffffc6039a4p+7, 1},
    {0x1.a4fb28d0d87f1p+5, 0x1.67fff822d5fe5p+7, 1},
    {0x1.a4fb225282edep+5, 0x1.67fffd879a54dp+7, 1},
    {0x1.a4fb287cf2509p+5, 0x1.67fffd1adc1cep+7, 1},
    {0x1.a4fb28290bbe6p+5, -0x1.67fffded1dc8bp+7, 1},
    {0x1.a4fb2aa8304f3p+5, -0x1.6800000000000p+7, 0},
    {0x1.a4fb2ea761aaep+5, 0x1.67fffcae1ddb5p+7, 1},
    {0x1.a4fb287cf2509p+5, 0x1.67fffd1adc1cep+7, 1},
    {0x1.a4fb284c0ff2dp+5, 0x1.6800000000000p+7, 0},
    {0x1.a449c0f91b790p+5, 0x1.67fadeb5458b4p+7, 1},
    {0x1.a449bb49b021ep+5, 0x1.67fada3e48b42p+7, 1},
    {0x1.a449b7b26b8bbp+5, 0x1.67fadcc6f055cp+7, 1},
    {0x1.a449c27839523p+5, 0x1.67fad52cf96b5p+7, 1},
    {0x1.a449bb49b021ep+5, 0x1.67fada3e48b42p+7, 1},
    {0x1.a449c1b8aa7f5p+5, 0x1.67fad9f11f743p+7, 1},
    {0x1.a449c0f91b790p+5, 0x1.67fadeb5458b4p+7, 1},
    {0x1.a449c827a4eb3p+5, 0x1.67fad9a3f636bp+7, 1},
    {0x1.a449c1b8aa7f5p+5, 0x1.67fad9f11f743p+7, 1},
    {-0x1.59fe8b2c4c93ap+3, 0x1.2000029b525c1p+5, 1},
    {-0x1.59fe7ef347074p+3, 0x1.200001b2f9f7cp+5, 0},
    {-0x1.59fe72ba41808p+3, 0x1.200000caa1915p+5, 1},
    {-0x1.59fe7398d9832p+3, 0x1.1ffffec8911dcp+5, 0},
    {-0x1.59fe747771837p+3, 0x1.1ffffcc680aa1p+5, 1},
    {-0x1.59fe7fd1df0a9p+3, 0x1.1fffffb0e9847p+5, 0},
    {-0x1.5da6612e04155p+3, 0x1.1fbd99191afdfp+5, 1},
    {-0x1.5da654a178c3ep+3, 0x1.1fbd9844d4754p+5, 0},
    {-0x1.5da64814ed68ap+3, 0x1.1fbd97708dee5p+5, 1},
    {-0x1.5da648bd4e581p+3, 0x1.1fbd9576b0857p+5, 0},
    {-0x1.5da64965af424p+3, 0x1.1fbd937cd31d3p+5, 1},
    {-0x1.5da65549d9baap+3, 0x1.1fbd964af70acp+5, 0},
    {0x1.b0f9b1878b541p+5, -0x1.78429cc698778p+5, 1},
    {0x1.14b888ff2114ep+6, -0x1.3affffffffffep+6, 1},
    {0x1.d32d5ad561420p+5, -0x1.5180000000000p+7, 1},
    {0x1.6800000000000p+6, -0x1.5180000000326p+7, 0},
    {0x1.6800000000000p+6, 0x1.9500000011ae0p+6, 0},
    {0x1.14b888ff2114fp+6, 0x1.94fffffffffffp+6, 1},
    {0x1.d32d5ad561420p+5, 0x1.67ffffffffff0p+3, 1},
    {0x1.b0f9b1878b543p+5, -0x1.78429cc69876ep+5, 1},
    {0x1.14b888ff21150p+6, -0x1.3affffffffffep+6, 1},
    {0x1.d32d5ad561425p+5, -0x1.5180000000000p+7, 1},
    {0x1.6800000000000p+6, -0x1.5180000001243p+7, 0},
    {0x1.6800000000000p+6, 0x1.950000000279ap+6, 0},
    {0x1.14b888ff2114ep+6, 0x1.94ffffffffffcp+6, 1},
    {0x1.d32d5ad561422p+5, 0x1.67ffffffffff6p+3, 1},
    {0x1.b0f9b1878b541p+5, -0x1.78429cc698778p+5, 1},
    {0x1.b854890977ad5p+5, -0x1.62dcd07ca667bp+5, 0},
    {0x1.bf30bd8998e11p+5, -0x1.4c82188a8b4f3p+5, 1},
    {0x1.cb4422cd32994p+5, -0x1.1cfe9907f7771p+5, 0},
    {0x1.d4e4cbc2bacb4p+5, -0x1.d4141a47e0ecfp+4, 1},
    {0x1.dbcea0711ab4ep+5, -0x1.689a81857f323p+4, 0},
    {0x1.dfd1bb7ae4f2fp+5, -0x1.f31f6adb66719p+3, 1},
    {0x1.e0b5612273c9bp+5, -0x1.82f218888cf19p+3, 0},
    {0x1.e0da82698a8ddp+5, -0x1.12e7e5d1bd608p+3, 1},
    {0x1.e043ca8208bfap+5, -0x1.4759cb9e5c77dp+2, 0},
    {0x1.def5e254d7573p+5, -0x1.af2d67d1855d2p+0, 1},
    {0x1.da4ff1e2bc63ep+5, 0x1.3e04f0498b66dp+2, 0},
    {0x1.d32d5ad561424p+5, 0x1.67ffffffffffbp+3, 1},
    {0x1.ee265e756a286p+5, 0x1.67fffffffffe9p+3, 0},
    {0x1.04c0660475203p+6, 0x1.67ffffffffff4p+3, 1},
    {0x1.0ba7bb8c9d3e1p+6, 0x1.67ffffffffff2p+3, 0},
    {0x1.b0f9b1878b543p+5, -0x1.78429cc69876ep+5, 1},
    {0x1.b8525a76e22dbp+5, -0x1.62e3860260d76p+5, 0},
    {0x1.bf266c4647746p+5, -0x1.4ca5c6690505dp+5, 1},
    {0x1.cb228f98c0e3cp+5, -0x1.1d9638b6f0d58p+5, 0},
    {0x1.d4b1a716f684bp+5, -0x1.d697402fc227cp+4, 1},
    {0x1.db9b93d2d1179p+5, -0x1.6c8c96749f90fp+4, 0},
    {0x1.dfb3970fb2ddap+5, -0x1.fd4ab9ac8e61dp+3, 1},
    {0x1.e0a7bfabd3042p+5, -0x1.8dc54ca5b6ed6p+3, 0},
    {0x1.e0df4249487adp+5, -0x1.1df00ed8e2a52p+3, 1},
    {0x1.e05a79e6b36eap+5, -0x1.5cc6c97a3c06fp+2, 0},
    {0x1.df1b4dd6e94d0p+5, -0x1.fdaa5af37102bp+0, 1},
    {0x1.da7ca8e22af46p+5, 0x1.31bc7d29dd960p+2, 0},
    {0x1.d32d5ad561424p+5, 0x1.67ffffffffffcp+3, 1},
    {0x1.eef41f5c62854p+5, 0x1.67ffffffffff7p+3, 0},
    {0x1.055f1f41529ccp+6, 0x1.67fffffffffecp+3, 1},
    {0x1.0c535b1664ad9p+6, 0x1.67fffffffffedp+3, 0},
    {0x1.e1c7afe1d37c8p+4, -0x1.34f70cc08d4b8p+3, 1},
    {0x1.0bdeb8220b04fp+5, -0x1.039a216f29878p+3, 0},
    {0x1.269ee456325bdp+5, -0x1.9cc338baf752ep+2, 0},
    {0x1.410e1c846ba59p+5, -0x1.2925386b31a76p+2, 1},
    {0x1.74990f189b8f0p+5, -0x1.ef34a36249060p-2, 0},
    {0x1.a5a8260931dfap+5, 0x1.2a98ae76c2620p+2, 0},
    {0x1.d32d5ad561420p+5, 0x1.67ffffffffff0p+3, 1},
    {0x1.def5e254d7573p+5, -0x1.af2d67d185696p+0, 0},
    {0x1.dfd1bb7ae4f2fp+5, -0x1.f31f6adb66700p+3, 0},
    {0x1.d4e4cbc2bacb2p+5, -0x1.d4141a47e0ec1p+4, 1},
    {0x1.cb4422cd32992p+5, -0x1.1cfe9907f776dp+5, 0},
    {0x1.bf30bd8998e13p+5, -0x1.4c82188a8b4ecp+5, 0},
    {0x1.b0f9b1878b542p+5, -0x1.78429cc698766p+5, 1},
    {0x1.a0f10ca8fb976p+5, -0x1.a035a442447bep+5, 0},
    {0x1.8f661dd99f27bp+5, -0x1.c482b188bc30bp+5, 0},
    {0x1.7ca21a06d790ap+5, -0x1.e56f00bcd0c67p+5, 1},
    {0x1.e1c7afe1d37d7p+4, -0x1.34f70cc08d4a8p+3, 1},
    {0x1.0bc9b66f8ae50p+5, -0x1.03c21fd62f81fp+3, 0},
    {0x1.264d0b3c03943p+5, -0x1.9e17bfe514dd5p+2, 0},
    {0x1.406d2c14d7b46p+5, -0x1.2c08cd703b22fp+2, 1},
    {0x1.7373b0cc55dc1p+5, -0x1.2cde08a167ba6p-1, 0},
    {0x1.a49633e6ce09ap+5, 0x1.224b4d2971fd3p+2, 0},
    {0x1.d32d5ad561422p+5, 0x1.67ffffffffff6p+3, 1},
    {0x1.df1b4dd6e94cep+5, -0x1.fdaa5af3710a7p+0, 0},
    {0x1.dfb3970fb2dd8p+5, -0x1.fd4ab9ac8e633p+3, 0},
    {0x1.d4b1a716f6848p+5, -0x1.d697402fc2280p+4, 1},
    {0x1.cb228f98c0e3ap+5, -0x1.1d9638b6f0d58p+5, 0},
    {0x1.bf266c4647743p+5, -0x1.4ca5c6690505fp+5, 0},
    {0x1.b0f9b1878b541p+5, -0x1.78429cc69876cp+5, 1},
    {0x1.a0fe34ee45285p+5, -0x1.a017df315bb98p+5, 0},
    {0x1.8f9e12f1af2afp+5, -0x1.c41853481a9a3p+5, 0},
    {0x1.7d1849f5a1c7bp+5, -0x1.e4aea31f2a05dp+5, 1},
};
/* END FROZEN */

#define MAXC 8192

static int cmp_u64(const void *a, const void *b) {
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return (x > y) - (x < y);
}

/* An outline computed through the public API: every step's output. */
typedef struct {
    size_t kept, fine_n, edges, rings;
    dggs_cell cells[MAXC], fine[MAXC], ecell[3 * MAXC], rcell[3 * MAXC];
    int64_t ecol[3 * MAXC], rcol[3 * MAXC], order[3 * MAXC], starts[3 * MAXC + 1], steps[3 * MAXC];
    uint8_t keep[MAXC], mask[3 * MAXC], visited[3 * MAXC];
    int64_t rows;
    double pts[2 * 8 * 3 * MAXC];
    uint8_t corner[8 * 3 * MAXC];
    int64_t ends[3 * MAXC];
    double scratch[16];
} outline_t;

static outline_t OUT; /* large: static */

/* Steps 1-4 for `n` sorted unique ids; 0 on success. */
static int outline_steps(const dggs_cell *ids, size_t n, outline_t *o) {
    if (n > MAXC) return 1;
    CHECK(dggs_cells_drop_covered(ids, n, o->keep) == DGGS_OK);
    o->kept = 0;
    int finest = 0;
    for (size_t i = 0; i < n; i++) {
        if (o->keep[i]) o->cells[o->kept++] = ids[i];
        if (o->keep[i] && dggs_level_of(ids[i]) > finest) finest = dggs_level_of(ids[i]);
    }
    o->fine_n = 0;
    for (size_t i = 0; i < o->kept; i++) {
        dggs_cell c = o->cells[i];
        if (dggs_level_of(c) == finest) {
            o->fine[o->fine_n++] = c;
            continue;
        }
        int64_t size;
        CHECK(dggs_boundary_descendants_size(c, finest, &size) == DGGS_OK);
        if (o->fine_n + (size_t)size > MAXC) return 1;
        CHECK(dggs_boundary_descendants(c, finest, o->fine + o->fine_n, size) == DGGS_OK);
        o->fine_n += (size_t)size;
    }
    qsort(o->fine, o->fine_n, sizeof(dggs_cell), cmp_u64);
    CHECK(dggs_outline_edge_mask(o->fine, o->fine_n, o->cells, o->kept, o->mask) == DGGS_OK);
    o->edges = 0;
    for (size_t i = 0; i < o->fine_n; i++) {
        for (int col = 0; col < 3; col++) {
            if (o->mask[3 * i + col]) {
                o->ecell[o->edges] = o->fine[i];
                o->ecol[o->edges] = col;
                o->edges++;
            }
        }
    }
    o->rings = 0;
    o->starts[0] = 0;
    if (o->edges == 0) return 0;
    CHECK(dggs_outline_chain(o->ecell, o->ecol, o->edges, o->cells, o->kept, o->visited, o->order, o->starts,
                             &o->rings) == DGGS_OK);
    for (size_t i = 0; i < o->edges; i++) {
        o->rcell[i] = o->ecell[o->order[i]];
        o->rcol[i] = o->ecol[o->order[i]];
    }
    return 0;
}

/* Step 5 with `densify` points an edge on `proj`. */
static void outline_points(outline_t *o, int densify, dggs_projection proj) {
    for (size_t i = 0; i < o->edges; i++) o->steps[i] = densify + 1;
    int64_t size;
    CHECK(dggs_outline_points_size(o->steps, o->edges, &size) == DGGS_OK);
    CHECK(size <= COUNT(o->corner));
    CHECK(dggs_outline_points(o->rcell, o->rcol, o->steps, o->edges, o->starts, o->rings, proj, o->pts, size,
                              o->corner, o->ends, o->scratch, COUNT(o->scratch)) == DGGS_OK);
    o->rows = o->rings ? o->ends[o->rings - 1] : 0;
}

static void frozen(void) {
    for (int s = 0; s < COUNT(FROZEN_SETS); s++) {
        outline_t *o = &OUT;
        CHECK(outline_steps(FROZEN_CELLS + FROZEN_SETS[s].first, (size_t)FROZEN_SETS[s].count, o) == 0);
        CHECK((int)o->kept == FROZEN_SETS[s].kept);
        CHECK((int)o->fine_n == FROZEN_SETS[s].fine);
        CHECK((int)o->edges == FROZEN_SETS[s].edges);
        CHECK((int)o->rings == FROZEN_SETS[s].rings);
        for (int r = 0; r <= FROZEN_SETS[s].rings && r < 9; r++) CHECK(o->starts[r] == FROZEN_SETS[s].starts[r]);
        int row = FROZEN_SETS[s].row;
        for (int p = 0; p < 2; p++) {
            if (!o->edges) break;
            outline_points(o, FROZEN_SETS[s].densify, (dggs_projection)p);
            CHECK(o->rows == FROZEN_SETS[s].rows[p]);
            for (int64_t i = 0; i < o->rows && i < FROZEN_ROWS; i++, row++) {
                CHECK_NEAR_DOUBLE(o->pts[2 * i], FROZEN_RING_ROWS[row].lat);
                CHECK_NEAR_DOUBLE(o->pts[2 * i + 1], FROZEN_RING_ROWS[row].lng);
                CHECK(o->corner[i] == FROZEN_RING_ROWS[row].corner);
            }
        }
    }
}

/* A cell at `level` from a seed. */
static dggs_cell some_cell(uint64_t *state, int level) {
    *state = *state * 6364136223846793005ULL + 1442695040888963407ULL;
    dggs_cell cell = dggs_base_cell((int)((*state >> 33) % 20));
    for (int lv = 1; lv <= level; lv++) {
        *state = *state * 6364136223846793005ULL + 1442695040888963407ULL;
        cell |= (uint64_t)((*state >> 33) % (lv == 1 ? 6u : 3u) + 1) << dggs_shift_of(lv);
    }
    return cell;
}

static void invariants(void) {
    outline_t *o = &OUT;
    uint64_t state = 12345;
    /* one cell: three edges, one ring, its corners in order, the cell's own boundary where it has no pole or
     * antimeridian point (points.c's dggs_one_boundary) */
    for (int level = 0; level <= DGGS_MAX_LEVEL; level++) {
        dggs_cell c = some_cell(&state, level);
        CHECK(outline_steps(&c, 1, o) == 0);
        CHECK(o->kept == 1 && o->fine_n == 1 && o->edges == 3 && o->rings == 1);
        CHECK(o->starts[0] == 0 && o->starts[1] == 3);
        for (int p = 0; p < 2; p++) {
            outline_points(o, 1, (dggs_projection)p);
            double b[12];
            dggs_one_boundary((dggs_projection)p, c, 1, b, 0);
            if (o->rows == 6) {
                /* the ring starts at some edge of the cell: find the rotation */
                int shift = -1;
                for (int k = 0; k < 6; k += 2)
                    if (o->pts[0] == b[2 * k] && o->pts[1] == b[2 * k + 1]) shift = k;
                CHECK(shift >= 0);
                for (int k = 0; k < 6 && shift >= 0; k++) {
                    CHECK_SAME_DOUBLE(o->pts[2 * k], b[2 * ((k + shift) % 6)]);
                    CHECK_SAME_DOUBLE(o->pts[2 * k + 1], b[2 * ((k + shift) % 6) + 1]);
                    CHECK(o->corner[k] == (k % 2 == 0));
                }
            }
        }
    }
    /* the globe: every base cell, or all the children of the base cells: no outline */
    dggs_cell all[120];
    for (int f = 0; f < 20; f++) all[f] = dggs_base_cell(f);
    CHECK(outline_steps(all, 20, o) == 0);
    CHECK(o->edges == 0 && o->rings == 0);
    for (int f = 0; f < 20; f++)
        for (int d = 0; d < 6; d++) all[6 * f + d] = dggs_base_cell(f) | ((uint64_t)(d + 1) << dggs_shift_of(1));
    CHECK(outline_steps(all, 120, o) == 0);
    CHECK(o->fine_n == 120 && o->edges == 0);
    /* a cell and its neighbours: one ring (the neighbours share an edge with the cell only: 6 outer edges) */
    for (int level = 1; level <= DGGS_MAX_LEVEL; level += 3) {
        dggs_cell c = some_cell(&state, level), set[4];
        set[0] = c;
        for (int col = 0; col < 3; col++) set[col + 1] = dggs_neighbour(c, level, col);
        qsort(set, 4, sizeof(dggs_cell), cmp_u64);
        CHECK(outline_steps(set, 4, o) == 0);
        CHECK(o->edges == 6 && o->rings == 1);
    }
    /* a cell's parent given with the cell: the parent alone (drop_covered), a coarse cell beside nothing: its
     * boundary descendants are all its descendants with an edge on it */
    dggs_cell c = some_cell(&state, 5), pair[2] = {dggs_parent_at(c, 3), c};
    uint8_t keep[2];
    CHECK(dggs_cells_drop_covered(pair, 2, keep) == DGGS_OK);
    CHECK(keep[0] == 1 && keep[1] == 0);
    for (int level = 0; level <= 6; level++) {
        dggs_cell top = some_cell(&state, level);
        for (int fine = level + 1; fine <= level + 4 && fine <= DGGS_MAX_LEVEL; fine++) {
            int64_t size;
            dggs_cell desc[4096];
            CHECK(dggs_boundary_descendants_size(top, fine, &size) == DGGS_OK);
            /* index/dissolve.py's bound: 6 * 3 ** ceil(l / 2) + 12 for l levels down */
            int64_t bound = 12, p3 = 1;
            for (int k = 0; k < (fine - level + 1) / 2; k++) p3 *= 3;
            bound += 6 * p3;
            CHECK(size > 0 && size <= bound);
            CHECK(dggs_boundary_descendants(top, fine, desc, size) == DGGS_OK);
            for (int64_t i = 0; i < size; i++) {
                CHECK(dggs_level_of(desc[i]) == fine && dggs_parent_at(desc[i], level) == top);
                CHECK(i == 0 || desc[i] != desc[i - 1]); /* depth first, not sorted: distinct */
                int out = 0;
                for (int col = 0; col < 3; col++) out |= dggs_parent_at(dggs_neighbour(desc[i], fine, col), level) != top;
                CHECK(out);
            }
            /* the coarse cell's outline equals its fine boundary descendants' (the whole set at the fine level) */
            CHECK(outline_steps(&top, 1, o) == 0);
        }
    }
}

static void errors(void) {
    dggs_cell ids[3] = {dggs_base_cell(2), dggs_base_cell(1), dggs_base_cell(3)};
    uint8_t keep[3], mask[9], visited[4];
    int64_t size, order[4], starts[5], col[3] = {0, 1, 2}, steps[3] = {1, 1, 1}, ends[2];
    size_t rings;
    double pts[64], scratch[4];
    uint8_t corner[32];
    dggs_cell out[4];
    CHECK(dggs_cells_drop_covered(ids, 3, keep) == DGGS_E_DOMAIN); /* not increasing */
    ids[1] = 12345;
    CHECK(dggs_cells_drop_covered(ids, 3, keep) == DGGS_E_CELL);
    CHECK(dggs_boundary_descendants_size(12345, 3, &size) == DGGS_E_CELL);
    CHECK(dggs_boundary_descendants_size(dggs_base_cell(4), 0, &size) == DGGS_E_LEVEL);
    CHECK(dggs_boundary_descendants_size(dggs_base_cell(4), 29, &size) == DGGS_E_LEVEL);
    CHECK(dggs_boundary_descendants_size(dggs_base_cell(4), 1, &size) == DGGS_OK && size == 6);
    CHECK(dggs_boundary_descendants(dggs_base_cell(4), 1, out, 4) == DGGS_E_BUFFER);
    dggs_cell a = dggs_base_cell(4), fine[2] = {a | ((uint64_t)1 << dggs_shift_of(1)), a};
    CHECK(dggs_outline_edge_mask(fine, 2, &a, 1, mask) == DGGS_E_LEVEL_MISMATCH);
    CHECK(dggs_outline_edge_mask(&a, 1, &a, 1, mask) == DGGS_OK && mask[0] && mask[1] && mask[2]);
    dggs_cell three[3] = {a, a, a};
    CHECK(dggs_outline_chain(three, col, 3, &a, 1, visited, order, starts, &rings) == DGGS_OK && rings == 1);
    int64_t badcol[3] = {0, 3, 2};
    CHECK(dggs_outline_chain(three, badcol, 3, &a, 1, visited, order, starts, &rings) == DGGS_E_DOMAIN);
    int64_t unsorted[3] = {0, 2, 1};
    CHECK(dggs_outline_chain(three, unsorted, 3, &a, 1, visited, order, starts, &rings) == DGGS_E_DOMAIN);
    /* two of a cell's edges: not an outline of it (the chain breaks) */
    CHECK(dggs_outline_chain(three, col, 2, &a, 1, visited, order, starts, &rings) == DGGS_E_FAILED);
    CHECK(dggs_outline_chain(three, col, 3, &a, 1, visited, order, starts, &rings) == DGGS_OK);
    CHECK(dggs_outline_points_size(steps, 3, &size) == DGGS_OK && size == 18);
    int64_t zero[1] = {0};
    CHECK(dggs_outline_points_size(zero, 1, &size) == DGGS_E_DOMAIN);
    dggs_cell ring_cells[3] = {a, a, a};
    int64_t ring_cols[3] = {order[0], order[1], order[2]};
    CHECK(dggs_outline_points(ring_cells, ring_cols, steps, 3, starts, 1, DGGS_ISEA, pts, 17, corner, ends, scratch,
                              4) == DGGS_E_BUFFER);
    CHECK(dggs_outline_points(ring_cells, ring_cols, steps, 3, starts, 1, DGGS_ISEA, pts, 18, corner, ends, scratch,
                              2) == DGGS_E_BUFFER);
    CHECK(dggs_outline_points(ring_cells, ring_cols, steps, 3, starts, 1, (dggs_projection)3, pts, 18, corner, ends,
                              scratch, 4) == DGGS_E_PROJECTION);
    int64_t bad_starts[2] = {0, 2};
    CHECK(dggs_outline_points(ring_cells, ring_cols, steps, 3, bad_starts, 1, DGGS_ISEA, pts, 18, corner, ends,
                              scratch, 4) == DGGS_E_DOMAIN);
    CHECK(dggs_outline_points(ring_cells, ring_cols, steps, 3, starts, 1, DGGS_IVEA, pts, 18, corner, ends, scratch,
                              4) == DGGS_OK);
    CHECK(ends[0] >= 3);
    /* the internal descent refuses a level that is not finer (numba's stack would overflow) */
    CHECK(dggs_dissolve_descend(a, 0, NULL, 0) == -1);
    CHECK(dggs_dissolve_descend(a, 29, NULL, 0) == -1);
}

int main(void) {
    frozen();
    invariants();
    errors();
    CHECK_DONE();
}
