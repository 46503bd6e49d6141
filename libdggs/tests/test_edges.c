/* edges.c: directed edge ids, ends, reverse, lengths and boundaries: the layout's invariants, docs/features.md's
 * examples, the public API's errors, and outputs of the numba kernels frozen by tools/freeze_edges.py (both
 * projections). */
#include <math.h>

#include "bits.h"
#include "check.h"
#include "dggs.h"
#include "edges.h"
#include "grid.h"

#define COUNT(a) ((int)(sizeof(a) / sizeof((a)[0])))

/* BEGIN FROZEN (tools/freeze_edges.py) */
/* edge, origin, destination, reverse; length (m, rad) ISEA, IVEA; boundary (densify 1: 3 (lat, lng)) ISEA then
 * IVEA */
static const struct {
    uint64_t edge, origin, destination, reverse;
    double m_isea, rad_isea, m_ivea, rad_ivea;
    double boundary[12];
} FROZEN_EDGES[] = {
    {0xc040000000000000ULL, 0x4000000000000000ULL, 0x4a00000000000000ULL, 0xca40000000000000ULL, 0x1.ae91baa7de023p+22, 0x1.1b6e191a0b970p+0, 0x1.ae91baae954c8p+22, 0x1.1b6e191e940b5p+0,
     {0x1.d32d5ad561420p+5, -0x1.5180000000000p+7, 0x1.b0f9b1878b548p+5, -0x1.b9deb19cb3c49p+6, 0x1.fd5157b6d117dp+4, -0x1.3b00000000000p+6, 0x1.d32d5ad561424p+5, -0x1.517ffffffffffp+7, 0x1.b0f9b1878b543p+5, -0x1.b9deb19cb3c44p+6, 0x1.fd5157b6d1186p+4, -0x1.3affffffffffep+6}}, /* level 0, north pole, direction 0 */
    {0xe080000000000000ULL, 0x6000000000000000ULL, 0x5e00000000000000ULL, 0xdec0000000000000ULL, 0x1.ae91baa7de020p+22, 0x1.1b6e191a0b96ep+0, 0x1.ae91baae954c8p+22, 0x1.1b6e191e940b5p+0,
     {-0x1.fd5157b6d1181p+4, -0x1.3afffffffffffp+6, -0x1.b0f9b1878b542p+5, -0x1.b9deb19cb3c44p+6, -0x1.d32d5ad561422p+5, -0x1.5180000000000p+7, -0x1.fd5157b6d118ap+4, -0x1.3b00000000001p+6, -0x1.b0f9b1878b544p+5, -0x1.b9deb19cb3c49p+6, -0x1.d32d5ad561422p+5, -0x1.5180000000000p+7}}, /* level 0, south pole, direction 1 */
    {0xdd20000000000000ULL, 0x5d00000000000000ULL, 0x5cc0000000000000ULL, 0xdce0000000000000ULL, 0x1.1b74816de5650p+21, 0x1.759edd04bace1p-2, 0x1.1b74816ddfab9p+21, 0x1.759edd04b3a68p-2,
     {0x1.92df0a994b7e4p-46, -0x1.5180000000001p+7, 0x1.5159e9812e841p+3, -0x1.5180000000001p+7, 0x1.4fda890867731p+4, -0x1.5180000000000p+7, 0x1.cc6c9e660d22ap-47, -0x1.5180000000000p+7, 0x1.5289c1d078294p+3, -0x1.5180000000000p+7, 0x1.4fda890867733p+4, -0x1.5180000000000p+7}}, /* level 1, antimeridian, direction 1 */
    {0xe670000000000000ULL, 0x6640000000000000ULL, 0x6580000000000000ULL, 0xe590000000000000ULL, 0x1.ae5e308a3ef39p+21, 0x1.1b6e192d70a30p-1, 0x1.ae5e308ab0330p+21, 0x1.1b6e192db9455p-1,
     {-0x1.e1c7afe1d37c8p+4, 0x1.54b08f33f72b6p+7, -0x1.67e8d34ae65d6p+5, 0x1.64cb8da1974c1p+7, -0x1.d32d5ad561420p+5, -0x1.5180000000000p+7, -0x1.e1c7afe1d37d7p+4, 0x1.54b08f33f72b6p+7, -0x1.66db72c7c8a45p+5, 0x1.649da5f9354aep+7, -0x1.d32d5ad561422p+5, -0x1.5180000000000p+7}}, /* level 1, antimeridian 45S, direction 2 */
    {0xd37c000000000000ULL, 0x5370000000000000ULL, 0x5db0000000000000ULL, 0xddb4000000000000ULL, 0x1.1bb71caa3a339p+21, 0x1.75a95d2e38d4dp-2, 0x1.1ce1252656939p+21, 0x1.7731f40e9b8bbp-2,
     {0x1.410e1c846ba5cp+5, 0x1.5eb6d63ca672cp+7, 0x1.8d7f49ae601b9p+5, -0x1.641cf1f50d5bdp+7, 0x1.d32d5ad561422p+5, -0x1.517ffffffffffp+7, 0x1.406d2c14d7b48p+5, 0x1.5e9fb9947e26ep+7, 0x1.8c48ecef09c02p+5, -0x1.645d9391cddc5p+7, 0x1.d32d5ad561422p+5, -0x1.5180000000001p+7}}, /* level 2, vertex, direction 2 */
    {0xcf74000000000000ULL, 0x4f70000000000000ULL, 0x4f30000000000000ULL, 0xcf3c000000000000ULL, 0x1.012950d2c9215p+21, 0x1.527a7b73802f7p-2, 0x1.f4bc14eb24ae7p+20, 0x1.49894a3acf5c3p-2,
     {0x1.729603c540b59p-48, 0x1.57bd633967893p+5, -0x1.6861878048f9ap+2, 0x1.199ff0d41574bp+5, -0x1.61786304d3305p+3, 0x1.b73e6cbe3eb90p+4, -0x1.400ce9d3d2fe7p-48, 0x1.57bd63396788fp+5, -0x1.5a410d9a1dbdep+2, 0x1.1c16b5cd85554p+5, -0x1.585af121c4dd5p+3, 0x1.bdf565ae170e0p+4}}, /* level 2, vertex, direction 0 */
    {0xdd99000000000000ULL, 0x5d98000000000000ULL, 0x5d94000000000000ULL, 0xdd97000000000000ULL, 0x1.5cea1bc5e9ce8p+20, 0x1.cbbfc261f80b8p-3, 0x1.5b47e9a28e711p+20, 0x1.c99888b74f4e3p-3,
     {0x1.410e1c846ba5fp+5, 0x1.5eb6d63ca672ep+7, 0x1.0e60320a4fcbap+5, 0x1.61481db4ff1bdp+7, 0x1.b65c978e0f463p+4, 0x1.636f43840c615p+7, 0x1.406d2c14d7b47p+5, 0x1.5e9fb9947e26fp+7, 0x1.0ded31eaa2446p+5, 0x1.6151f8d86c0b7p+7, 0x1.b6398b8a84d20p+4, 0x1.637a13f486222p+7}}, /* level 3, face edge, direction 0 */
    {0xc59e000000000000ULL, 0x459c000000000000ULL, 0x4598000000000000ULL, 0xc59a000000000000ULL, 0x1.631dad301aaf3p+19, 0x1.d362fcc06e963p-4, 0x1.644507ae149adp+19, 0x1.d4e59c527dcd3p-4,
     {0x1.ec1e7d915beacp+4, 0x1.08acdc106af11p+2, 0x1.d2194168b11a1p+4, 0x1.b235e637adfd5p-1, 0x1.b65c978e0f460p+4, -0x1.242f1efce7ac2p+1, 0x1.eb25291b17958p+4, 0x1.0df423e6fc656p+2, 0x1.d1569cb20de5bp+4, 0x1.d3378d5910c03p-1, 0x1.b6398b8a84d1dp+4, -0x1.217b02de7775dp+1}}, /* level 3, vertex, direction 1 */
    {0xc77a800000000000ULL, 0x477a000000000000ULL, 0x477b000000000000ULL, 0xc77b800000000000ULL, 0x1.b16e0571d5b4fp+18, 0x1.1d549b912aeebp-4, 0x1.b18c24b3ae8dcp+18, 0x1.1d670d9369b99p-4,
     {0x1.fd9b6fea0e9d6p+3, 0x1.4cea0de7643b1p+5, 0x1.d1a4fdaab9732p+3, 0x1.40e6ca2dfe928p+5, 0x1.a526bb0881bf8p+3, 0x1.35099e42662efp+5, 0x1.00d3aa9de8158p+4, 0x1.4cb98098590f4p+5, 0x1.d68536bfcaaa3p+3, 0x1.409640add39a5p+5, 0x1.aa08a476856ccp+3, 0x1.349ea370e797fp+5}}, /* level 4, anywhere, direction 1 */
    {0xe066c00000000000ULL, 0x6066000000000000ULL, 0x6065000000000000ULL, 0xe065400000000000ULL, 0x1.b486243f67b63p+19, 0x1.1f61989ee4138p-3, 0x1.9fa5cfe903d50p+19, 0x1.11a3fd88cb910p-3,
     {-0x1.0a0bb6ae8120ep+6, -0x1.078bfdd61f8aap+7, -0x1.15c7b51944476p+6, -0x1.f26980c1ce129p+6, -0x1.20138036bc6d0p+6, -0x1.cc9b62d99457ep+6, -0x1.0a04f6a97a332p+6, -0x1.0778370e407e1p+7, -0x1.15ae742d760f9p+6, -0x1.f43f9caba5e22p+6, -0x1.1feacae453de4p+6, -0x1.d254a6e2eb900p+6}}, /* level 4, anywhere, direction 2 */
    {0xc195700000000000ULL, 0x4195400000000000ULL, 0x4195800000000000ULL, 0xc195900000000000ULL, 0x1.d3923653e0d6bp+18, 0x1.33d25cf66e60dp-4, 0x1.d2ad62dca661fp+18, 0x1.333bb75585aa1p-4,
     {0x1.5ea9ca80874b5p+6, -0x1.3afffffffffc6p+6, 0x1.5f68a57f49e99p+6, -0x1.5b6a7793c4141p+4, 0x1.599d3c49ec152p+6, 0x1.67fffffffff84p+3, 0x1.5ea7f15df9327p+6, -0x1.3b0000000000dp+6, 0x1.5f6a7f0f27298p+6, -0x1.5e55e037a2b4ep+4, 0x1.59a8789e33f52p+6, 0x1.67fffffffff3bp+3}}, /* level 5, north pole, direction 2 */
    {0xe195500000000000ULL, 0x6195400000000000ULL, 0x6255400000000000ULL, 0xe255700000000000ULL, 0x1.88481cd76f938p+18, 0x1.02418be0d658fp-4, 0x1.8715bd38a047cp+18, 0x1.0177d8ca937f8p-4,
     {-0x1.599d3c49ec151p+6, -0x1.517ffffffffffp+7, -0x1.60ce3126160b2p+6, -0x1.517fffffffff0p+7, -0x1.67ffffffffffdp+6, -0x1.156e3a5fa600ep+7, -0x1.59a8789e33f52p+6, -0x1.517fffffffffcp+7, -0x1.60d065eaca5d4p+6, -0x1.517fffffffff1p+7, -0x1.67fffffffffffp+6, -0x1.0e00000000000p+7}}, /* level 5, south pole, direction 0 */
    {0xdd3bf40000000000ULL, 0x5d3bf00000000000ULL, 0x5d37f00000000000ULL, 0xdd37fc0000000000ULL, 0x1.d5aeb22f98a89p+17, 0x1.351322b11c305p-5, 0x1.d14156b9f7173p+17, 0x1.322ba1c8b3edcp-5,
     {-0x1.cc6c9e660d22ap-48, -0x1.671ebb30214a3p+7, 0x1.310fac43d1a72p-1, 0x1.6712cdf7cddc9p+7, 0x1.3196e23e3b983p+0, 0x1.6544a8ede26c3p+7, 0x1.595176cc89d9fp-47, -0x1.66f2cc54d19bep+7, 0x1.34d90eb60a628p-1, 0x1.6747fd722fc55p+7, 0x1.353b799b87a62p+0, 0x1.6581f2cc222eap+7}}, /* level 6, antimeridian, direction 0 */
    {0xe67b780000000000ULL, 0x667b700000000000ULL, 0x667b600000000000ULL, 0xe67b680000000000ULL, 0x1.24e5caeb18563p+17, 0x1.816f0b2c7204fp-6, 0x1.261402391960fp+17, 0x1.82fc7389ac487p-6,
     {-0x1.6395dc9e6f92fp+5, -0x1.64671c0b25689p+7, -0x1.63b56136f4859p+5, -0x1.6649d882e3817p+7, -0x1.63c1f43b93284p+5, 0x1.67d439ac08e7cp+7, -0x1.627bff8f296b6p+5, -0x1.6490bf80e5a6ap+7, -0x1.629214e01d77fp+5, -0x1.66747d363e9b7p+7, -0x1.62a0427e417fdp+5, 0x1.67a8f61f2adc0p+7}}, /* level 6, antimeridian 45S, direction 1 */
    {0xd37daa0000000000ULL, 0x537da80000000000ULL, 0x537dac0000000000ULL, 0xd37dae0000000000ULL, 0x1.6452eea36a70dp+16, 0x1.d50b8b4174148p-7, 0x1.5ebcc84a59450p+16, 0x1.cdb4c0a3b7e85p-7,
     {0x1.9eb6d441dd181p+5, 0x1.66b3e741cbaeap+7, 0x1.9d41c6a808057p+5, 0x1.67e335e33fa11p+7, 0x1.9bc6c629945fep+5, -0x1.66f0af51c83dap+7, 0x1.9de82468e3e86p+5, 0x1.66a1f6a199c52p+7, 0x1.9c542ca775a88p+5, 0x1.67c351fcf0a5fp+7, 0x1.9ac02a8459b95p+5, -0x1.671bfad9fa166p+7}}, /* level 7, vertex, direction 1 */
    {0xcf7a970000000000ULL, 0x4f7a940000000000ULL, 0x4f7a980000000000ULL, 0xcf7a990000000000ULL, 0x1.613b194aff5dcp+17, 0x1.d0b3fd2382c64p-6, 0x1.5d6ceeb6040e7p+17, 0x1.cbb8f7a43d0e8p-6,
     {-0x1.568a83abdd8eap+3, 0x1.18eb0b9cf36b0p+5, -0x1.5f411147b4c99p+3, 0x1.1f2b2dc9de109p+5, -0x1.67e78e64e1577p+3, 0x1.2567d8c9fd96fp+5, -0x1.59398fc98094cp+3, 0x1.18d60b00dc7c6p+5, -0x1.62e92b396b4a2p+3, 0x1.1ee5cc7e40da7p+5, -0x1.6c4975c9cc6c8p+3, 0x1.2503d512d1a42p+5}}, /* level 7, vertex, direction 2 */
    {0xdd9a97c000000000ULL, 0x5d9a970000000000ULL, 0x5d99970000000000ULL, 0xdd99974000000000ULL, 0x1.5e82543c59c2bp+16, 0x1.cdbc726166650p-7, 0x1.5b58038ab99a4p+16, 0x1.c99019d6d9de0p-7,
     {0x1.f1074c5917b8ep+4, 0x1.67683ca8fd72cp+7, 0x1.f6d3a9159cebbp+4, 0x1.67d3b8a4f95e9p+7, 0x1.fc9c4736524fep+4, -0x1.67bfb310aa848p+7, 0x1.f01a68736c225p+4, 0x1.678492f217e15p+7, 0x1.f5d44ac0ab907p+4, 0x1.67f0782110378p+7, 0x1.fb8b5140b3384p+4, -0x1.67a2c23ae2084p+7}}, /* level 8, face edge, direction 2 */
    {0xc59ef54000000000ULL, 0x459ef50000000000ULL, 0x455ef50000000000ULL, 0xc55ef5c000000000ULL, 0x1.5076edba97847p+16, 0x1.bac4256ee10a4p-7, 0x1.520dbf7fb0f6ep+16, 0x1.bcdb848a992b0p-7,
     {0x1.abedf31c8d06cp+4, -0x1.6862ae01dc1e8p-1, 0x1.a947b94f12fbap+4, -0x1.3fe1a7dc87ca5p-2, 0x1.a69d5ab3879b0p+4, 0x1.3edadec4ab186p-4, 0x1.abbc7c6a38aaep+4, -0x1.59b3f9549ee0dp-1, 0x1.a912ad0dbfe1bp+4, -0x1.20aef1bf9480ep-2, 0x1.a664c745adedfp+4, 0x1.c2b773e08dde0p-4}}, /* level 8, vertex, direction 0 */
    {0xc77afd5000000000ULL, 0x477afd4000000000ULL, 0x477afd8000000000ULL, 0xc77afdb000000000ULL, 0x1.9945d4ec07985p+15, 0x1.0d5715a0ed88cp-7, 0x1.b36dae910b114p+15, 0x1.1ea0a43a4af22p-7,
     {0x1.86cda1dbda713p+3, 0x1.7012c71f88165p+5, 0x1.8b183829788d7p+3, 0x1.6e7cd14ba7713p+5, 0x1.8f6af9be94e2dp+3, 0x1.6ce73a38a7ac5p+5, 0x1.7eaf651c07f5cp+3, 0x1.6f40b9e8efb4ep+5, 0x1.8414e4b1f1369p+3, 0x1.6dba8554442e1p+5, 0x1.89702a99ba116p+3, 0x1.6c336699eeb65p+5}}, /* level 9, anywhere, direction 0 */
    {0xe066ae6000000000ULL, 0x6066ae4000000000ULL, 0x60666e4000000000ULL, 0xe0666e6000000000ULL, 0x1.92dfc134d1bcbp+14, 0x1.09306ef31e15ap-8, 0x1.92e8c5cc4013bp+14, 0x1.093678affc21dp-8,
     {-0x1.0de193b40c863p+6, -0x1.ecf8df86dae58p+6, -0x1.0dc8abb9e4026p+6, -0x1.ee266d6013811p+6, -0x1.0daf3542854d4p+6, -0x1.ef535b483e109p+6, -0x1.0df70d898b866p+6, -0x1.ecf789e0612cdp+6, -0x1.0ddd1c3257372p+6, -0x1.ee24cef977f04p+6, -0x1.0dc29d05f197bp+6, -0x1.ef5161c880dc3p+6}}, /* level 9, anywhere, direction 1 */
    {0xc195555800000000ULL, 0x4195555000000000ULL, 0x4855555000000000ULL, 0xc855555800000000ULL, 0x1.d113655697838p+13, 0x1.322dd87a4c49ep-9, 0x1.d16c9db0db24dp+13, 0x1.3268953ff2b35p-9,
     {0x1.67778f2f58c7dp+6, 0x1.67fffffffeaaep+3, 0x1.67bbc796413cbp+6, 0x1.67ffffffff15cp+3, 0x1.67ffffffffffcp+6, -0x1.f4383eb9a450dp+4, 0x1.677775029a6dap+6, 0x1.67fffffffeb0fp+3, 0x1.67bbb90ec44eep+6, 0x1.67fffffffc877p+3, 0x1.67ffffffffffep+6, -0x1.7a532b5ba82c6p+5}}, /* level 10, north pole, direction 1 */
    {0xe195555c00000000ULL, 0x6195555000000000ULL, 0x6155555000000000ULL, 0xe155555400000000ULL, 0x1.c55afd3ac9033p+14, 0x1.2a768d1abd838p-8, 0x1.c508fad646ef8p+14, 0x1.2a408f9b184a8p-8,
     {-0x1.67ffffffffffdp+6, -0x1.156e3a5fa600ep+7, -0x1.677afbdec25f5p+6, -0x1.3b00000000487p+6, -0x1.66f5fed7dacadp+6, -0x1.3b00000000258p+6, -0x1.67fffffffffffp+6, -0x1.0e00000000000p+7, -0x1.677b177127446p+6, -0x1.3affffffffe87p+6, -0x1.66f62ef63be13p+6, -0x1.3b000000000a0p+6}}, /* level 10, south pole, direction 2 */
    {0xdd3bff9700000000ULL, 0x5d3bff9400000000ULL, 0x5d3bff9800000000ULL, 0xdd3bff9900000000ULL, 0x1.12bc104ebeecdp+14, 0x1.69956a4db39fbp-9, 0x1.1316497981003p+14, 0x1.6a0d988006247p-9,
     {0x1.6942e987bc436p-4, -0x1.67eb146ef903ap+7, 0x1.694dbcfdbd16fp-5, 0x1.67f345ed4ce01p+7, -0x1.cc6c9e660d22cp-49, 0x1.67d1a1091b1acp+7, 0x1.6dc51ddbb31b8p-4, -0x1.67bc0d224902dp+7, 0x1.6dcedd3dbb3c8p-5, -0x1.67dd91e83c471p+7, 0x1.cc6c9e660d22ap-48, -0x1.67ff175bd8b4cp+7}}, /* level 11, antimeridian, direction 2 */
    {0xe67b76f900000000ULL, 0x667b76f800000000ULL, 0x667b75f800000000ULL, 0xe67b75fb00000000ULL, 0x1.009709d959e94p+14, 0x1.51e5c04565d76p-9, 0x1.01f84bb0cab4dp+14, 0x1.53b67a4c0dbe1p-9,
     {-0x1.677e711a19c2ap+5, -0x1.67eb7180d3bfcp+7, -0x1.67f6902625943p+5, 0x1.67f4281b8b904p+7, -0x1.686ea1eddc872p+5, 0x1.67d3b0dc47492p+7, -0x1.6658f74d0c052p+5, 0x1.67e6b3f1607c5p+7, -0x1.66d12e4795eafp+5, 0x1.67c5f792d6e22p+7, -0x1.674968e059d50p+5, 0x1.67a52c7fcd22bp+7}}, /* level 11, antimeridian 45S, direction 0 */
    {0xd37dabdb40000000ULL, 0x537dabdb00000000ULL, 0x537dabd700000000ULL, 0xd37dabd7c0000000ULL, 0x1.1016f95b5200bp+13, 0x1.66658babb0500p-10, 0x1.19bb2789952c1p+13, 0x1.7319e98da341cp-10,
     {0x1.a51b50fc494b1p+5, 0x1.67fa6367a4520p+7, 0x1.a4cc4e0fe2a84p+5, 0x1.67ffd5462cf25p+7, 0x1.a47d45fdc8b88p+5, -0x1.67fabef5be395p+7, 0x1.a46b988134ecap+5, 0x1.67f608291f066p+7, 0x1.a4192789cde18p+5, 0x1.67f9e57e9d1adp+7, 0x1.a3c6bfc6223fap+5, 0x1.67fdc4599feb0p+7}}, /* level 12, vertex, direction 0 */
    {0xcf7a977780000000ULL, 0x4f7a977700000000ULL, 0x4f7a977600000000ULL, 0xcf7a977680000000ULL, 0x1.5df2b4b03adc0p+12, 0x1.ccc3a4f7da197p-11, 0x1.5fa3e231c55b3p+12, 0x1.cf08c1b79bfb5p-11,
     {-0x1.5af91e0f16af7p+3, 0x1.204dc5a893cfdp+5, -0x1.5a67a0dd10cb0p+3, 0x1.20286b2517525p+5, -0x1.59d6251d49fd2p+3, 0x1.20030ede69141p+5, -0x1.5eae351999a4bp+3, 0x1.2008b7ce97383p+5, -0x1.5e15ef37f0d46p+3, 0x1.1fe4bfdd5c223p+5, -0x1.5d7d96796b918p+3, 0x1.1fc0cb9fabdbfp+5}}, /* level 12, vertex, direction 1 */
    {0xdd9a97fee0000000ULL, 0x5d9a97fec0000000ULL, 0x5d9a97fe80000000ULL, 0xdd9a97fea0000000ULL, 0x1.6e78f9ff07f31p+11, 0x1.e2e8f43bcab74p-12, 0x1.6be7a2cffe527p+11, 0x1.df86a9dd97457p-12,
     {0x1.fb4d8772ec8dbp+4, -0x1.67f57c1922f47p+7, 0x1.fb83545ac5b72p+4, -0x1.67f6625dca0a2p+7, 0x1.fbb920e6f9f60p+4, -0x1.67f748b2016f8p+7, 0x1.fa41d01cd4ee6p+4, -0x1.67d8cb661f577p+7, 0x1.fa77348283683p+4, -0x1.67d9ba0193fd1p+7, 0x1.faac989fbcd7ap+4, -0x1.67daa8b9615bap+7}}, /* level 13, face edge, direction 1 */
    {0xc59ef569b0000000ULL, 0x459ef56980000000ULL, 0x459ef56940000000ULL, 0xc59ef56950000000ULL, 0x1.8eac7d12c0928p+12, 0x1.0650ca212a1cfp-10, 0x1.90962dfb4d9adp+12, 0x1.079300bdc2a37p-10,
     {0x1.a8e93d56ce6b5p+4, -0x1.7c19311a04351p-6, 0x1.a8b69daca5af5p+4, 0x1.7613514558ca0p-8, 0x1.a883f8399738ap+4, 0x1.1b82eb1cfb601p-5, 0x1.a8ad03d955c5ep+4, 0x1.4a48cd1c2c1cfp-7, 0x1.a87a1fd3ae6d4p+4, 0x1.40763f989de33p-5, 0x1.a847362415bb9p+4, 0x1.172578e8ff86dp-4}}, /* level 13, vertex, direction 2 */
    {0xc77afd569c000000ULL, 0x477afd5690000000ULL, 0x477afd56a0000000ULL, 0xc77afd56a4000000ULL, 0x1.d57620a804d45p+11, 0x1.35091f1a7588dp-11, 0x1.b535830170d55p+11, 0x1.1fc51ee3e64e5p-11,
     {0x1.88fdaa9309807p+3, 0x1.6ca8b0d26d49ap+5, 0x1.895b40a4db1fap+3, 0x1.6cc2d660e92e3p+5, 0x1.89b8d6bf0f379p+3, 0x1.6cdcfce44e4a8p+5, 0x1.82f7475a4ecffp+3, 0x1.6bf3b0c80bebdp+5, 0x1.8348dde72a703p+3, 0x1.6c0d3e4ae6ecap+5, 0x1.839a6efc7e02cp+3, 0x1.6c26cbee471eap+5}}, /* level 14, anywhere, direction 2 */
    {0xe066ae7e94000000ULL, 0x6066ae7e90000000ULL, 0x6066ae7ea0000000ULL, 0xe066ae7eac000000ULL, 0x1.91c0c5baa4a0dp+11, 0x1.08763dec091e6p-11, 0x1.9c68225498c9dp+11, 0x1.0f7925e8a5f34p-11,
     {-0x1.0f3f4e70679b7p+6, -0x1.edcfec63055dap+6, -0x1.0f397ade9c322p+6, -0x1.edac123e6b2a7p+6, -0x1.0f33a57e7d6e7p+6, -0x1.ed883b4985295p+6, -0x1.0f4fcc6cb071ep+6, -0x1.ee060429dd279p+6, -0x1.0f4a36b747ee6p+6, -0x1.ede0c0913f110p+6, -0x1.0f449ef688be3p+6, -0x1.edbb817430f0fp+6}}, /* level 14, anywhere, direction 0 */
    {0xc195555555000000ULL, 0x4195555554000000ULL, 0x4855555554000000ULL, 0xc855555557000000ULL, 0x1.9d669ec667a5dp+10, 0x1.1028c829967f3p-12, 0x1.9dc57c8bfe1f0p+10, 0x1.10673c83e1d68p-12,
     {0x1.67f0d704d87b2p+6, 0x1.67fffffff99a4p+3, 0x1.67f86b826bbdep+6, 0x1.67ffffffe3f9cp+3, 0x1.67ffffffffffcp+6, -0x1.f4383eb9a450dp+4, 0x1.67f0d38a3f31dp+6, 0x1.67ffffffefd39p+3, 0x1.67f869c089b4cp+6, 0x1.67ffffffe8e06p+3, 0x1.67ffffffffffep+6, -0x1.7a532b5ba82c6p+5}}, /* level 15, north pole, direction 0 */
    {0xe195555556000000ULL, 0x6195555554000000ULL, 0x6155555554000000ULL, 0xe155555556000000ULL, 0x1.0cb58c8da36f7p+10, 0x1.61ce2673e6c9bp-13, 0x1.0c773565ce8e0p+10, 0x1.617c1146a311dp-13,
     {-0x1.67ffffffffffdp+6, -0x1.156e3a5fa600ep+7, -0x1.67fb12aec7f7dp+6, -0x1.3b00000007b4fp+6, -0x1.67f6256012f48p+6, -0x1.3b00000003cd7p+6, -0x1.67fffffffffffp+6, -0x1.0e00000000000p+7, -0x1.67fb13d4a91e6p+6, -0x1.3b000000003ecp+6, -0x1.67f627a9527f2p+6, -0x1.3affffffff834p+6}}, /* level 15, south pole, direction 1 */
    {0xdd3bff957f800000ULL, 0x5d3bff957f000000ULL, 0x5d3bff957e000000ULL, 0xdd3bff957e800000ULL, 0x1.3113e54360c99p+9, 0x1.91f3710781abdp-14, 0x1.31b83975fd53ap+9, 0x1.92cfba010fa9fp-14,
     {0x1.cc6c9e660d22ap-49, -0x1.67fc15cc6cdd2p+7, 0x1.4124f97e07671p-9, -0x1.67fcbaf291616p+7, 0x1.41251c6a07d99p-8, -0x1.67fd601910064p+7, 0x1.595176cc89d9fp-47, -0x1.67cd6c99f61e8p+7, 0x1.4525ad2ff2c97p-9, -0x1.67ce0b8ce45d7p+7, 0x1.4525d6117677ap-8, -0x1.67ceaa80ff7fdp+7}}, /* level 16, antimeridian, direction 1 */
    {0xe67b76fb65c00000ULL, 0x667b76fb65000000ULL, 0x667b76fb66000000ULL, 0xe67b76fb66400000ULL, 0x1.301d1229fc51bp+10, 0x1.907af21fff758p-13, 0x1.31b936bb75208p+10, 0x1.92991f002cdb9p-13,
     {-0x1.680c94205cb1bp+5, 0x1.67fe2663f1f5fp+7, -0x1.6803ae48a745dp+5, -0x1.67ff72ac02fbfp+7, -0x1.67fac85e5019dp+5, -0x1.67fd0bd3a5710p+7, -0x1.66e6fe5cf8d4bp+5, 0x1.67cfe7dedafe9p+7, -0x1.66de166bc9656p+5, 0x1.67d2551ca467fp+7, -0x1.66d52e7fb6edbp+5, 0x1.67d4c245c462cp+7}}, /* level 16, antimeridian 45S, direction 2 */
    {0xd37dabdbf9f00000ULL, 0x537dabdbf9c00000ULL, 0x537dabdbfdc00000ULL, 0xd37dabdbfdd00000ULL, 0x1.428bedd351955p+9, 0x1.a897d916b2e30p-14, 0x1.3ccbf79f4944ep+9, 0x1.a105c3a551ab9p-14,
     {0x1.a4fdbe96f48a8p+5, -0x1.67fee027c6fa7p+7, 0x1.a4faf945ee4f3p+5, 0x1.67fef7bb87e6dp+7, 0x1.a4f833e14b88cp+5, 0x1.67fccfa88b89fp+7, 0x1.a44c58f25e8b5p+5, 0x1.67fbfc987540cp+7, 0x1.a449a63278a6ep+5, 0x1.67f9de1dc637ep+7, 0x1.a446f360ad813p+5, 0x1.67f7bfac3a5c5p+7}}, /* level 17, vertex, direction 2 */
    {0xcf7a977756d00000ULL, 0x4f7a977756c00000ULL, 0x4f7a97775ac00000ULL, 0xcf7a97775af00000ULL, 0x1.7451f4b530b10p+9, 0x1.e9d0c2591a411p-14, 0x1.70380ae465958p+9, 0x1.e4728f672ce63p-14,
     {-0x1.5a0060dbc3e6cp+3, 0x1.1ff47ce6c2be4p+5, -0x1.5a09813d0456cp+3, 0x1.1ffb1154f1d05p+5, -0x1.5a12a18ce02d7p+3, 0x1.2001a5bf1f371p+5, -0x1.5da6f0d0f0438p+3, 0x1.1fb24696befa5p+5, -0x1.5db0fb10440e8p+3, 0x1.1fb8b0902115cp+5, -0x1.5dbb04f64e6f5p+3, 0x1.1fbf1a9989b2bp+5}}, /* level 17, vertex, direction 0 */
    {0xdd9a97feea640000ULL, 0x5d9a97feea600000ULL, 0x5d9a97feea500000ULL, 0xdd9a97feea5c0000ULL, 0x1.8dd9805e63c93p+8, 0x1.05fac1fa250f1p-14, 0x1.8ee5c0511ffa4p+8, 0x1.06aa9c93c0b47p-14,
     {0x1.fb7b4f4237ac3p+4, 0x1.67ffdc837e38fp+7, 0x1.fb75720e8b988p+4, -0x1.67ff7db51d8a7p+7, 0x1.fb6f94d7d1556p+4, -0x1.67fed7ef25302p+7, 0x1.fa6fb589e6587p+4, -0x1.67e38d8c45b84p+7, 0x1.fa69dd20f020fp+4, -0x1.67e2e5c437b69p+7, 0x1.fa6404b57d543p+4, -0x1.67e23dfdb74dap+7}}, /* level 18, face edge, direction 0 */
    {0xc59ef56996980000ULL, 0x459ef56996900000ULL, 0x459ef56995900000ULL, 0xc59ef56995980000ULL, 0x1.9075f7ae4c6c9p+7, 0x1.0767ad7f6e990p-15, 0x1.94ff0b40ea834p+7, 0x1.0a634b32c4e3dp-15,
     {0x1.a91145bf220cap+4, 0x1.beca7b6cca721p-10, 0x1.a9112143c83d1p+4, 0x1.6f24e60a9fd6ep-11, 0x1.a910fcc6a1cf6p+4, -0x1.3e95f72c64815p-12, 0x1.a8d3e3eb134d0p+4, 0x1.22043ef97da42p-5, 0x1.a8d3c737497f9p+4, 0x1.19b24c74b5f3ep-5, 0x1.a8d3aa819d16cp+4, 0x1.11605ac4c551ap-5}}, /* level 18, vertex, direction 1 */
    {0xc77afd569f6a0000ULL, 0x477afd569f680000ULL, 0x477afd569f6c0000ULL, 0xc77afd569f6e0000ULL, 0x1.af857a7a04f1bp+6, 0x1.1bfbcb98a1647p-16, 0x1.c9d1548a75924p+6, 0x1.2d5ce4a735111p-16,
     {0x1.89985e28a4fe7p+3, 0x1.6cce07bb33659p+5, 0x1.899aa60ba5bc7p+3, 0x1.6ccd324e7112fp+5, 0x1.899cedf0cf559p+3, 0x1.6ccc5ce1c7775p+5, 0x1.83816ff3097cdp+3, 0x1.6c1837fbceb24p+5, 0x1.8384401d761e6p+3, 0x1.6c1769d8dd3bdp+5, 0x1.83871045238afp+3, 0x1.6c169bb5af1e8p+5}}, /* level 19, anywhere, direction 1 */
    {0xe066ae7e9b6f0000ULL, 0x6066ae7e9b6c0000ULL, 0x6066ae7e9bac0000ULL, 0xe066ae7e9bad0000ULL, 0x1.bb59d7d15a31fp+7, 0x1.23e54c1bba9c2p-15, 0x1.c3a43d15339f5p+7, 0x1.2959584ba5d3ap-15,
     {-0x1.0f341fd7fe751p+6, -0x1.ed9a40d52abb7p+6, -0x1.0f33457b38cb7p+6, -0x1.ed98c93043452p+6, -0x1.0f326b1e114ebp+6, -0x1.ed97518f7dbe4p+6, -0x1.0f45025c36e01p+6, -0x1.edcdd600493e6p+6, -0x1.0f442c849afbap+6, -0x1.edcc3628d777fp+6, -0x1.0f4356ac0c3cep+6, -0x1.edca9659dbc03p+6}}, /* level 19, anywhere, direction 2 */
    {0xc19555555555c000ULL, 0x4195555555550000ULL, 0x4155555555550000ULL, 0xc155555555554000ULL, 0x1.ddb560967c564p+6, 0x1.3a7ee99877d27p-16, 0x1.dd45b454696c4p+6, 0x1.3a3564bbeba63p-16,
     {0x1.67ffffffffffcp+6, -0x1.f4383eb9a450dp+4, 0x1.67ff73da683c9p+6, -0x1.3affffffc087cp+6, 0x1.67fee7b4d86a0p+6, -0x1.3affffffddc6ep+6, 0x1.67ffffffffffep+6, -0x1.7a532b5ba82c6p+5, 0x1.67ff73fb2f3afp+6, -0x1.3afffffff4c8ap+6, 0x1.67fee7f65e762p+6, -0x1.3afffffffa03fp+6}}, /* level 20, north pole, direction 2 */
    {0xe195555555554000ULL, 0x6195555555550000ULL, 0x6195555555560000ULL, 0xe19555555556c000ULL, 0x1.0c6e369b2f207p+7, 0x1.61703939ada13p-16, 0x1.0c49a0f094bc0p+7, 0x1.61400d9869123p-16,
     {-0x1.67fee7b4d86a1p+6, -0x1.3b000000241adp+6, -0x1.67ff627fd6eb7p+6, -0x1.a7993e0ca5d62p+6, -0x1.67ff70428cb5bp+6, -0x1.518000000da61p+7, -0x1.67fee7f65e763p+6, -0x1.3b00000006c2fp+6, -0x1.67ff62954d43bp+6, -0x1.a7c4c7617d5cep+6, -0x1.67ff7020e9141p+6, -0x1.517ffffff56a6p+7}}, /* level 20, south pole, direction 0 */
    {0xdd3bff957ff95000ULL, 0x5d3bff957ff94000ULL, 0x5d3bff957ff98000ULL, 0xdd3bff957ff9b000ULL, 0x1.25008de3e308bp+6, 0x1.819e99db223a9p-17, 0x1.21da9fcf64268p+6, 0x1.7d7d08d1c039bp-17,
     {0x1.cc6c9e660d22ap-49, -0x1.67ffff1ec7720p+7, 0x1.7c9eb6ee1b4d5p-13, 0x1.67ffdcce49bdcp+7, 0x1.7c9ec187d7996p-12, 0x1.67ffb8bb5b309p+7, 0x1.595176cc89d9fp-47, -0x1.67d14998ce865p+7, 0x1.815d17929f410p-13, -0x1.67d16ceaffacbp+7, 0x1.815d2257bf96ep-12, -0x1.67d1903d31994p+7}}, /* level 21, antimeridian, direction 0 */
    {0xe67b76fb65ede000ULL, 0x667b76fb65edc000ULL, 0x667b76fb65ed8000ULL, 0xe67b76fb65eda000ULL, 0x1.23d6e515d7260p+5, 0x1.8025614486c20p-18, 0x1.22c1e5b7d8cd2p+5, 0x1.7eb836c02f8e7p-18,
     {-0x1.67ffc0981e8bap+5, 0x1.67ffd78293613p+7, -0x1.67ffea384eed5p+5, 0x1.67fff20c3cc3fp+7, -0x1.680013d86f052p+5, -0x1.67fff36a14815p+7, -0x1.66da2e14788c2p+5, 0x1.67d1a1e5e1021p+7, -0x1.66da5738bb99cp+5, 0x1.67d1bc55e6e45p+7, -0x1.66da805cf4edfp+5, 0x1.67d1d6c5f2408p+7}}, /* level 21, antimeridian 45S, direction 1 */
    {0xd37dabdbf9e9d800ULL, 0x537dabdbf9e9d000ULL, 0x537dabdbf9ead000ULL, 0xd37dabdbf9ead800ULL, 0x1.71bab852f95ebp+4, 0x1.e6dc0bd2c890dp-19, 0x1.7435b46048ab8p+4, 0x1.ea27c01887684p-19,
     {0x1.a4fb3c4bd6313p+5, 0x1.67ffe7f487544p+7, 0x1.a4fb11f0a3493p+5, 0x1.67fff6009b3f9p+7, 0x1.a4fae7956bc1ep+5, -0x1.67fffbf355fa9p+7, 0x1.a449d803d5035p+5, 0x1.67fac5f90b64ap+7, 0x1.a449aae7b92f7p+5, 0x1.67fad2bb37f8fp+7, 0x1.a4497dcba16c3p+5, 0x1.67fadf7d63d77p+7}}, /* level 22, vertex, direction 1 */
    {0xcf7a977756d5dc00ULL, 0x4f7a977756d5d000ULL, 0x4f7a977756d5e000ULL, 0xcf7a977756d5e400ULL, 0x1.3a5d2fa59467cp+5, 0x1.9e46c6dfbf5f0p-18, 0x1.3e29758788547p+5, 0x1.a3469f9c9d618p-18,
     {-0x1.5a00c446b6e30p+3, 0x1.1fffe2402be65p+5, -0x1.59ff62c906b8fp+3, 0x1.1ffffff69bc13p+5, -0x1.59fe014b64bc5p+3, 0x1.20001dad063d8p+5, -0x1.5da8a1039217fp+3, 0x1.1fbd7672153a8p+5, -0x1.5da73c6eaaeacp+3, 0x1.1fbd956901663p+5, -0x1.5da5d7d9c0d7fp+3, 0x1.1fbdb45fead25p+5}}, /* level 22, vertex, direction 2 */
    {0xdd9a97feea6ff700ULL, 0x5d9a97feea6ff400ULL, 0x5d9a97feea6ff800ULL, 0xdd9a97feea6ff900ULL, 0x1.8217df28230f0p+4, 0x1.fcc3be22ea8f7p-19, 0x1.7f62b675915bfp+4, 0x1.f9323f7c94ab8p-19,
     {0x1.fb7ae45fe84f9p+4, 0x1.67fffd8e687d9p+7, 0x1.fb7a7304585acp+4, 0x1.67ffff7480219p+7, 0x1.fb7a01a8c6cf4p+4, -0x1.67fffea5687fbp+7, 0x1.fa6f49ff87f18p+4, -0x1.67e36c32927a3p+7, 0x1.fa6ed9804624bp+4, -0x1.67e36a3ae7567p+7, 0x1.fa6e690103166p+4, -0x1.67e368433cb0bp+7}}, /* level 23, face edge, direction 2 */
    {0xc59ef569969e9d00ULL, 0x459ef569969e9c00ULL, 0x459ef569969eac00ULL, 0xc59ef569969eaf00ULL, 0x1.63f6a24e522f9p+4, 0x1.d445f20eb344dp-19, 0x1.67fec3189f728p+4, 0x1.d99390706f86fp-19,
     {0x1.a90a43017e5f6p+4, -0x1.5648c9a5555b2p-14, 0x1.a90a470f7a1b6p+4, 0x1.f69a65a9b619fp-16, 0x1.a90a4b1d70276p+4, 0x1.28cb00922f344p-13, 0x1.a8cd023089fd3p+4, 0x1.13042bcee83e7p-5, 0x1.a8cd05614502ep+4, 0x1.13f0d3ca5a878p-5, 0x1.a8cd0891fa135p+4, 0x1.14dd7bc86d6b9p-5}}, /* level 23, vertex, direction 0 */
    {0xc77afd569f69d640ULL, 0x477afd569f69d600ULL, 0x477afd569f69d500ULL, 0xc77afd569f69d5c0ULL, 0x1.976a678b037cbp+3, 0x1.0c720d9045773p-19, 0x1.b1bdcc0988af3p+3, 0x1.1dce08a110ecbp-19,
     {0x1.8999bf268107cp+3, 0x1.6cccc7f1f754ap+5, 0x1.89994cfa639c3p+3, 0x1.6cccd1e26aa5ep+5, 0x1.8998dace49a19p+3, 0x1.6cccdbd2ddd1ap+5, 0x1.83838e543da67p+3, 0x1.6c17022e5bd7dp+5, 0x1.8383135826e60p+3, 0x1.6c170b9ff9c1ep+5, 0x1.8382985c0d856p+3, 0x1.6c17151197607p+5}}, /* level 24, anywhere, direction 0 */
    {0xe066ae7e9b6e6580ULL, 0x6066ae7e9b6e6500ULL, 0x6066ae7e9b6e7500ULL, 0xe066ae7e9b6e7580ULL, 0x1.a7477d6a94c83p+2, 0x1.16a1c7c59c0b7p-20, 0x1.b276476ab7a90p+2, 0x1.1dfdcfe839981p-20,
     {-0x1.0f332ddbbb8b4p+6, -0x1.ed997a0011058p+6, -0x1.0f3330ee5a44bp+6, -0x1.ed998ce07631cp+6, -0x1.0f333400f87dbp+6, -0x1.ed999fc0dc40bp+6, -0x1.0f4414600a753p+6, -0x1.edcce569e2af3p+6, -0x1.0f4417523de4cp+6, -0x1.edccf907b23ddp+6, -0x1.0f441a4470c36p+6, -0x1.edcd0ca5830acp+6}}, /* level 24, anywhere, direction 1 */
    {0xc195555555555560ULL, 0x4195555555555540ULL, 0x4155555555555540ULL, 0xc155555555555560ULL, 0x1.1b1635b83380fp+2, 0x1.74bc6b8f90919p-21, 0x1.1ad3f91573ea6p+2, 0x1.7465350477d83p-21,
     {0x1.67ffffffffffcp+6, -0x1.f4383eb9a450dp+4, 0x1.67fffacf33204p+6, -0x1.3afffff8b1602p+6, 0x1.67fff59e66436p+6, -0x1.3afffffc58c73p+6, 0x1.67ffffffffffep+6, -0x1.7a532b5ba82c6p+5, 0x1.67fffad06a0b9p+6, -0x1.3b000002c7df8p+6, 0x1.67fff5a0d4174p+6, -0x1.3b00000056f04p+6}}, /* level 25, north pole, direction 1 */
    {0xe195555555555570ULL, 0x6195555555555540ULL, 0x6195555555555580ULL, 0xe195555555555590ULL, 0x1.03b7bb1ec1de9p+3, 0x1.55f761a4d402dp-20, 0x1.03d0763590c93p+3, 0x1.5617f1b0c5a8dp-20,
     {-0x1.67fff59e66437p+6, -0x1.3b000003ea394p+6, -0x1.67fff679c9610p+6, -0x1.0f73bec801c22p+7, -0x1.67fff00764f7ap+6, -0x1.517fffff01db4p+7, -0x1.67fff5a0d4175p+6, -0x1.3affffffdbc85p+6, -0x1.67fff678e131dp+6, -0x1.0f8c3fd2d4a8fp+7, -0x1.67fff003a77bcp+6, -0x1.517fffff95977p+7}}, /* level 25, south pole, direction 2 */
    {0xdd3bff957ff97ffcULL, 0x5d3bff957ff97ff0ULL, 0x66fbff957ff97ff0ULL, 0xe6fbff957ff97ff4ULL, 0x1.1ff8d726d6e4bp+2, 0x1.7abe998800143p-21, 0x1.1c6d5e59e8928p+2, 0x1.761514bdcff55p-21,
     {0x0.0p+0, 0x1.67fffb94f1254p+7, 0x0.0p+0, 0x1.67fffe3b14d8fp+7, 0x1.cc6c9e660d22ap-49, -0x1.67ffff1ec7720p+7, 0x1.cc6c9e660d22cp-48, -0x1.67d14ed463f5cp+7, 0x1.cc6c9e660d22cp-48, -0x1.67d14c36993ebp+7, 0x1.595176cc89d9fp-47, -0x1.67d14998ce865p+7}}, /* level 26, antimeridian, direction 2 */
    {0xe67b76fb65eddf54ULL, 0x667b76fb65eddf50ULL, 0x667b76fb65eddf60ULL, 0xe67b76fb65eddf6cULL, 0x1.1bf6888c0b3ebp+2, 0x1.76031bda506ddp-21, 0x1.1a0f70d77460dp+2, 0x1.7381f047e3260p-21,
     {-0x1.6800015862c46p+5, -0x1.67ffff357f446p+7, -0x1.67fff808847c7p+5, 0x1.67ffff1b8942ep+7, -0x1.67ffeeb8a61e0p+5, 0x1.67fffd6c91da7p+7, -0x1.66da6e13f9187p+5, 0x1.67d1cb05ec86ep+7, -0x1.66da64d0c9218p+5, 0x1.67d1c95d21532p+7, -0x1.66da5b8d991a3p+5, 0x1.67d1c7b4562ffp+7}}, /* level 26, antimeridian 45S, direction 0 */
    {0xd37dabdbf9e9db59ULL, 0x537dabdbf9e9db58ULL, 0x537dabdbf9e9db68ULL, 0xd37dabdbf9e9db6bULL, 0x1.48bac7636ef1bp+1, 0x1.b0a791cfba1b0p-22, 0x1.3c7bb8928ccf7p+1, 0x1.a089847354018p-22,
     {0x1.a4fb28290bbe6p+5, -0x1.67fffded1dc8bp+7, 0x1.a4fb2852ff13fp+5, 0x1.67ffff96df2aap+7, 0x1.a4fb287cf2509p+5, 0x1.67fffd1adc1cep+7, 0x1.a449c0f91b790p+5, 0x1.67fadeb5458b4p+7, 0x1.a449c158e3029p+5, 0x1.67fadc53327dfp+7, 0x1.a449c1b8aa7f5p+5, 0x1.67fad9f11f743p+7}}, /* level 27, vertex, direction 0 */
    {0xcf7a977756d5df6eULL, 0x4f7a977756d5df6cULL, 0x4f7a977756d5df68ULL, 0xcf7a977756d5df6aULL, 0x1.883d2510f5340p+0, 0x1.020290346773bp-22, 0x1.83eb97eae1698p+0, 0x1.fe5e1b20adfb9p-23,
     {-0x1.59fe818f0f0a2p+3, 0x1.1ffffbacc89d7p+5, -0x1.59fe865dadd10p+3, 0x1.1fffff240d7d4p+5, -0x1.59fe8b2c4c93ap+3, 0x1.2000029b525c1p+5, -0x1.5da6569a9b986p+3, 0x1.1fbd92573c377p+5, -0x1.5da65be44fe35p+3, 0x1.1fbd95b82b988p+5, -0x1.5da6612e04155p+3, 0x1.1fbd99191afdfp+5}}, /* level 27, vertex, direction 1 */
};
/* END FROZEN */

static uint64_t id_of(const char *s) {
    dggs_cell c = 0;
    CHECK(dggs_string_to_cell(s, &c) == DGGS_OK);
    return c;
}

/* An edge id from its string form "C401.1": the shadow's string with the dot taken out, and the sign bit. */
static uint64_t edge_id(const char *s) {
    char buf[40];
    size_t n = strlen(s);
    CHECK(n >= 3 && n < sizeof buf && s[n - 2] == '.');
    memcpy(buf, s, n - 2);
    buf[n - 2] = s[n - 1];
    buf[n - 1] = '\0';
    return id_of(buf) | DGGS_EDGE_BIT;
}

static void frozen(void) {
    for (int i = 0; i < COUNT(FROZEN_EDGES); i++) {
        uint64_t e = FROZEN_EDGES[i].edge, o, d;
        dggs_edges_ends(e, &o, &d);
        CHECK_EQ_U64(o, FROZEN_EDGES[i].origin);
        CHECK_EQ_U64(d, FROZEN_EDGES[i].destination);
        CHECK_EQ_U64(dggs_one_origin(e), FROZEN_EDGES[i].origin);
        CHECK_EQ_U64(dggs_one_destination(e), FROZEN_EDGES[i].destination);
        CHECK_EQ_U64(dggs_edges_reverse(e), FROZEN_EDGES[i].reverse);
        double m, r;
        dggs_one_length(DGGS_ISEA, e, 16, &m, &r);
        CHECK_WITHIN(m, FROZEN_EDGES[i].m_isea, 1e-6); /* metres */
        CHECK_NEAR_DOUBLE(r, FROZEN_EDGES[i].rad_isea);
        dggs_one_length(DGGS_IVEA, e, 16, &m, &r);
        CHECK_WITHIN(m, FROZEN_EDGES[i].m_ivea, 1e-6);
        CHECK_NEAR_DOUBLE(r, FROZEN_EDGES[i].rad_ivea);
        double b[12];
        dggs_edges_one_boundary(DGGS_ISEA, e, 1, b);
        dggs_edges_one_boundary(DGGS_IVEA, e, 1, b + 6);
        for (int k = 0; k < 12; k++) CHECK_NEAR_DOUBLE(b[k], FROZEN_EDGES[i].boundary[k]);
        /* the public verbs agree */
        dggs_cell cells[2];
        CHECK(dggs_directed_edge_to_cells(e, cells) == DGGS_OK);
        CHECK_EQ_U64(cells[0], o);
        CHECK_EQ_U64(cells[1], d);
        double v;
        CHECK(dggs_edge_length_m(e, DGGS_IVEA, &v) == DGGS_OK);
        CHECK_WITHIN(v, FROZEN_EDGES[i].m_ivea, 1e-6);
        CHECK(dggs_edge_length_rads(e, DGGS_ISEA, &v) == DGGS_OK);
        CHECK_NEAR_DOUBLE(v, FROZEN_EDGES[i].rad_isea);
        double pts[6];
        CHECK(dggs_directed_edge_to_boundary(e, 1, DGGS_ISEA, pts, 3) == DGGS_OK);
        for (int k = 0; k < 6; k++) CHECK_NEAR_DOUBLE(pts[k], FROZEN_EDGES[i].boundary[k]);
    }
}

/* The id layout and its round trips for cells at every level 0..27, all three directions. */
static void invariants(void) {
    uint64_t state = 0x9e3779b97f4a7c15ULL;
    for (int trial = 0; trial < 400; trial++) {
        int level = trial % 28;
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        uint64_t cell = dggs_base_cell((int)((state >> 33) % 20));
        for (int lv = 1; lv <= level; lv++) {
            state = state * 6364136223846793005ULL + 1442695040888963407ULL;
            unsigned digit = (unsigned)((state >> 33) % (lv == 1 ? 6u : 3u));
            cell |= (uint64_t)(digit + 1) << dggs_shift_of(lv);
        }
        CHECK(dggs_is_valid(cell) && dggs_level_of(cell) == level);
        uint64_t out[3];
        CHECK(dggs_origin_to_directed_edges(cell, out) == DGGS_OK);
        for (int d = 0; d < 3; d++) {
            uint64_t e = out[d];
            CHECK_EQ_U64(e, dggs_edge_of(cell, d));
            CHECK(e >> 63 == 1);
            CHECK(dggs_is_valid(e & ~DGGS_EDGE_BIT) && dggs_level_of(e & ~DGGS_EDGE_BIT) == level + 1);
            CHECK(dggs_is_valid_directed_edge(e));
            uint64_t o;
            int lv, dir;
            dggs_edges_split(e, &o, &lv, &dir);
            CHECK_EQ_U64(o, cell);
            CHECK(lv == level && dir == d);
            uint64_t dest = dggs_one_destination(e);
            CHECK_EQ_U64(dest, dggs_neighbour(cell, level, d));
            CHECK_EQ_U64(dggs_pair_edges(cell, dest), e);
            uint64_t back = dggs_edges_reverse(e);
            CHECK(back != 0);
            CHECK_EQ_U64(dggs_one_origin(back), dest);
            CHECK_EQ_U64(dggs_one_destination(back), cell);
            CHECK_EQ_U64(dggs_edges_reverse(back), e);
            uint64_t viapublic;
            CHECK(dggs_cells_to_directed_edge(cell, dest, &viapublic) == DGGS_OK);
            CHECK_EQ_U64(viapublic, e);
            /* both directions of an edge have the same curve: the same length, up to rounding */
            for (int p = 0; p < 2; p++) {
                double m1, r1, m2, r2;
                dggs_one_length((dggs_projection)p, e, 16, &m1, &r1);
                dggs_one_length((dggs_projection)p, back, 16, &m2, &r2);
                CHECK(m1 > 0.0 && r1 > 0.0 && isfinite(m1));
                CHECK(fabs(m1 - m2) <= 1e-9 * m1 && fabs(r1 - r2) <= 1e-9 * r1);
                /* metres on WGS84 against radians on the authalic sphere (R = 6371007 m): within 0.7 % */
                CHECK(fabs(m1 / (r1 * 6371007.18) - 1.0) < 7e-3);
                /* the ends of the edge are the ends of its reverse, swapped (the same corners) */
                double b1[4], b2[4];
                dggs_edges_one_boundary((dggs_projection)p, e, 0, b1);
                dggs_edges_one_boundary((dggs_projection)p, back, 0, b2);
                CHECK(fabs(b1[0] - b2[2]) < 1e-9 && fabs(b1[2] - b2[0]) < 1e-9);
            }
        }
    }
    /* level 28: no edges */
    uint64_t deep = dggs_base_cell(3);
    for (int lv = 1; lv <= DGGS_MAX_LEVEL; lv++) deep |= (uint64_t)1 << dggs_shift_of(lv);
    CHECK_EQ_U64(dggs_edge_of(deep, 0), 0);
    CHECK_EQ_U64(dggs_pair_edges(deep, dggs_neighbour(deep, DGGS_MAX_LEVEL, 1)), 0);
}

/* docs/features.md and index/edges.py's examples. */
static void examples(void) {
    uint64_t out[3];
    CHECK(dggs_origin_to_directed_edges(id_of("C401"), out) == DGGS_OK);
    CHECK_EQ_U64(out[0], edge_id("C401.0"));
    CHECK_EQ_U64(out[1], edge_id("C401.1"));
    CHECK_EQ_U64(out[2], edge_id("C401.2"));
    uint64_t e;
    CHECK(dggs_cells_to_directed_edge(id_of("C401"), id_of("C402"), &e) == DGGS_OK);
    CHECK_EQ_U64(e, edge_id("C401.1"));
    CHECK(dggs_cells_to_directed_edge(id_of("C401"), id_of("C411"), &e) == DGGS_OK);
    CHECK_EQ_U64(e, edge_id("C401.0"));
    CHECK(dggs_cells_to_directed_edge(id_of("C401"), id_of("C400"), &e) == DGGS_OK);
    CHECK_EQ_U64(e, edge_id("C401.2"));
    dggs_cell cells[2];
    CHECK(dggs_directed_edge_to_cells(edge_id("C401.1"), cells) == DGGS_OK);
    CHECK_EQ_U64(cells[0], id_of("C401"));
    CHECK_EQ_U64(cells[1], id_of("C402"));
    CHECK(dggs_reverse_directed_edge(edge_id("C401.1"), &e) == DGGS_OK);
    CHECK_EQ_U64(e, edge_id("C402.1"));
    double pts[4];
    CHECK(dggs_directed_edge_to_boundary(edge_id("A.0"), 0, DGGS_ISEA, pts, 2) == DGGS_OK);
    CHECK(fabs(pts[0] - 58.3971) < 5e-5 && fabs(pts[1] + 168.75) < 5e-5);
    CHECK(fabs(pts[2] - 31.8324) < 5e-5 && fabs(pts[3] + 78.75) < 5e-5);
    double km;
    CHECK(dggs_edge_length_km(edge_id("C401.1"), DGGS_ISEA, &km) == DGGS_OK);
    CHECK(fabs(km - 726.3) < 0.05);
}

static void errors(void) {
    uint64_t e, out3[3];
    dggs_cell c, cells[2];
    double v, pts[8];
    uint64_t good = edge_id("C401.1");
    CHECK(!dggs_is_valid_directed_edge(id_of("C4011")));            /* no sign bit */
    CHECK(!dggs_is_valid_directed_edge(id_of("C") | DGGS_EDGE_BIT)); /* a level-0 shadow */
    CHECK(!dggs_is_valid_directed_edge(0));
    CHECK(!dggs_is_valid_directed_edge(~(uint64_t)0));
    CHECK(!dggs_is_valid_directed_edge(id_of("C4") | DGGS_EDGE_BIT)); /* a level-0 origin, direction 4 */
    CHECK(dggs_is_valid_directed_edge(id_of("C2") | DGGS_EDGE_BIT));
    CHECK(dggs_get_directed_edge_origin(id_of("C4011"), &c) == DGGS_E_EDGE);
    CHECK(dggs_get_directed_edge_destination(0, &c) == DGGS_E_EDGE);
    CHECK(dggs_directed_edge_to_cells(id_of("C") | DGGS_EDGE_BIT, cells) == DGGS_E_EDGE);
    CHECK(dggs_reverse_directed_edge(1, &e) == DGGS_E_EDGE);
    CHECK(dggs_edge_length_m(3, DGGS_ISEA, &v) == DGGS_E_EDGE);
    CHECK(dggs_edge_length_m(good, (dggs_projection)7, &v) == DGGS_E_PROJECTION);
    CHECK(dggs_directed_edge_to_boundary(good, 2, DGGS_ISEA, pts, 3) == DGGS_E_BUFFER);
    CHECK(dggs_directed_edge_to_boundary(good, -1, DGGS_ISEA, pts, 4) == DGGS_E_DOMAIN);
    CHECK(dggs_directed_edge_to_boundary(good, 0, (dggs_projection)2, pts, 4) == DGGS_E_PROJECTION);
    CHECK(dggs_cells_to_directed_edge(id_of("C401"), id_of("C401"), &e) == DGGS_E_DOMAIN);
    CHECK(dggs_cells_to_directed_edge(id_of("C401"), id_of("C40"), &e) == DGGS_E_DOMAIN);
    CHECK(dggs_cells_to_directed_edge(id_of("C401"), id_of("D401"), &e) == DGGS_E_DOMAIN);
    CHECK(dggs_cells_to_directed_edge(5, id_of("C401"), &e) == DGGS_E_CELL);
    CHECK(dggs_origin_to_directed_edges(7, out3) == DGGS_E_CELL);
    uint64_t deep = id_of("A0");
    for (int lv = 2; lv <= DGGS_MAX_LEVEL; lv++) deep |= (uint64_t)1 << dggs_shift_of(lv);
    CHECK(dggs_origin_to_directed_edges(deep, out3) == DGGS_E_LEVEL);
    CHECK(dggs_cells_to_directed_edge(deep, dggs_neighbour(deep, DGGS_MAX_LEVEL, 0), &e) == DGGS_E_LEVEL);
    /* the internal functions stay in bounds for a level-0 shadow (Python's converter lets it through) */
    uint64_t bad = id_of("F") | DGGS_EDGE_BIT, o, d;
    dggs_edges_ends(bad, &o, &d);
    CHECK_EQ_U64(d, 0);
    CHECK_EQ_U64(dggs_edges_reverse(bad), 0);
    double m, r;
    dggs_one_length(DGGS_ISEA, bad, 16, &m, &r);
    CHECK(isnan(m) && isnan(r));
}

int main(void) {
    frozen();
    invariants();
    examples();
    errors();
    CHECK_DONE();
}
