/* A stand-in for libFuzzer where clang is not installed: feeds LLVMFuzzerTestOneInput seeded random inputs (and
 * mutations of valid ids) for a given number of seconds. Built with gcc's ASan and UBSan by run.sh. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static uint64_t state = 0x9E3779B97F4A7C15ULL;

static uint64_t next(void) { /* splitmix64 */
    uint64_t z = (state += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

int main(int argc, char **argv) {
    double seconds = argc > 1 ? atof(argv[1]) : 10.0;
    clock_t end = clock() + (clock_t)(seconds * CLOCKS_PER_SEC);
    uint8_t buf[256];
    unsigned long runs = 0;
    while (clock() < end) {
        for (int k = 0; k < 1000; k++, runs++) {
            size_t n = 1 + next() % sizeof buf;
            for (size_t i = 0; i < n; i++) buf[i] = (uint8_t)next();
            if (next() % 4 == 0) { /* a string of id characters, sometimes broken */
                static const char chars[] = "ABCDEFGHIJKLMNOPQRST012345";
                buf[0] = 0;
                for (size_t i = 1; i < n; i++) buf[i] = (uint8_t)chars[next() % (sizeof chars - 1)];
                if (next() % 8 == 0) buf[1 + next() % (n > 1 ? n - 1 : 1)] = (uint8_t)next();
            }
            LLVMFuzzerTestOneInput(buf, n);
        }
    }
    printf("%lu runs in %.0f s: no finding\n", runs, seconds);
    return 0;
}
