#!/bin/sh
# A bounded fuzz run of the C core under AddressSanitizer and UBSan (make fuzz): each libdggs/fuzz/fuzz_*.c target
# for FUZZ_SECONDS seconds. With clang (Debian's clang and libclang-rt, installed here when missing and run as
# root), libFuzzer drives it, coverage-guided, from the seeds in libdggs/fuzz/seeds/; otherwise driver.c feeds it
# seeded random inputs, built with the C compiler's own sanitizers. A finding stops the run with a non-zero exit.
set -eu
SECONDS_EACH=${FUZZ_SECONDS:-30}
OUT=build/fuzz
mkdir -p "$OUT"
if ! command -v clang >/dev/null 2>&1 && [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
    (apt-get -o APT::Sandbox::User=root update -q && \
     DEBIAN_FRONTEND=noninteractive apt-get -o APT::Sandbox::User=root install -y -q clang libclang-rt-14-dev) \
        >"$OUT/apt.log" 2>&1 || echo "note: clang could not be installed; fuzzing with the random driver"
fi
SAN="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer -g -O1"
LIBFUZZER=no
if command -v clang >/dev/null 2>&1; then
    printf '#include <stddef.h>\n#include <stdint.h>\nint LLVMFuzzerTestOneInput(const uint8_t *d, size_t n) { (void)d; (void)n; return 0; }\n' \
        >"$OUT/probe.c"
    clang -fsanitize=fuzzer "$OUT/probe.c" -o "$OUT/probe" 2>/dev/null && LIBFUZZER=yes
fi
SRC="libdggs/src/*.c"
for target in libdggs/fuzz/fuzz_*.c; do
    name=$(basename "$target" .c)
    if [ "$LIBFUZZER" = yes ]; then
        clang -std=c11 -ffp-contract=off $SAN -fsanitize=fuzzer -Ilibdggs/include -Ilibdggs/src $target $SRC -lm \
            -o "$OUT/$name"
        corpus="$OUT/$name-corpus"
        mkdir -p "$corpus"
        seeds="libdggs/fuzz/seeds/$name"
        [ -d "$seeds" ] || seeds=""
        echo "libFuzzer: $name for $SECONDS_EACH s"
        "$OUT/$name" -max_total_time="$SECONDS_EACH" -print_final_stats=1 "$corpus" $seeds 2>"$OUT/$name.log" || {
            tail -40 "$OUT/$name.log"; exit 1; }
        grep -E "^(Done|stat::number_of_executed_units)" "$OUT/$name.log" || true
    else
        ${CC:-cc} -std=c11 -ffp-contract=off $SAN -Ilibdggs/include -Ilibdggs/src $target libdggs/fuzz/driver.c $SRC \
            -lm -o "$OUT/$name"
        echo "random driver: $name for $SECONDS_EACH s"
        "$OUT/$name" "$SECONDS_EACH"
    fi
done
