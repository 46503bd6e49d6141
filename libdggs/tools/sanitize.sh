#!/bin/sh
# The Python suite's kernel tests over a dggs._core built with AddressSanitizer and UBSan (make test-core-sanitize).
#
# The package is laid out as installed (dggs/, dggs/index, dggs/storage, dggs/experiments) in build/asan-tree beside
# a copy of the tests, the core compiled there with the sanitizers, and pytest run in that tree (so its dggs is the
# one imported) with gcc's sanitizer runtimes preloaded (the Python interpreter itself is not instrumented).
# ASan and UBSan stop at the first finding.
set -eu
PY=${PY:-.venv/bin/python}
TREE=build/asan-tree
CC=${CC:-cc}
rm -rf "$TREE" build/asan-temp
mkdir -p "$TREE"
cp -r dggs "$TREE/dggs"
rm -rf "$TREE"/dggs/_core.*.so "$TREE/dggs/server/node_modules"
cp -r index "$TREE/dggs/index"
cp -r storage "$TREE/dggs/storage"
cp -r experiments "$TREE/dggs/experiments"
cp -r tests pyproject.toml "$TREE/"
ln -s "$(pwd)/libdggs" "$TREE/libdggs"
SAN="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
CFLAGS="$SAN -g -O1" LDFLAGS="$SAN" "$PY" setup.py --quiet build_ext --build-lib "$TREE" --build-temp build/asan-temp
PRELOAD="$($CC -print-file-name=libasan.so) $($CC -print-file-name=libubsan.so)"
# the sanitized module must be the one imported
PY=$(cd "$(dirname "$PY")" && pwd)/$(basename "$PY")
cd "$TREE"
LD_PRELOAD="$PRELOAD" ASAN_OPTIONS=detect_leaks=0 "$PY" -c \
    "import dggs._core as c, os; assert c.__file__.startswith(os.getcwd()), c.__file__; print('sanitized core:', c.__file__)"
LD_PRELOAD="$PRELOAD" ASAN_OPTIONS=detect_leaks=0:abort_on_error=1 \
    UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    "$PY" -m pytest -q -p no:cacheprovider -x ${SANITIZE_TESTS:-tests/index/kernel tests/geometry tests/index/test_cellid.py tests/index/test_hierarchy.py tests/index/test_paths.py tests/index/test_dissolve.py tests/index/test_fill_modes.py tests/index/test_edges.py tests/index/test_local.py tests/index/test_points.py tests/index/test_polyfill.py tests/index/test_neighbors.py tests/index/test_poles_antimeridian.py tests/index/test_projection_grid.py}
