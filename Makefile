# Two entry points for a fresh machine with only Python: `make demo` and `make test`.
PYTHON ?= python3
VENV   := .venv
PY     := $(VENV)/bin/python
STAMP  := $(VENV)/.installed

BENCH_VENV := .venv-bench
BENCH_PY   := $(BENCH_VENV)/bin/python
BENCH_STAMP := $(BENCH_VENV)/.installed

.PHONY: demo test test-all bench clean

$(STAMP): pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip
	$(PY) -m pip install --quiet -e '.[test,demo,plot,dask,pandas,duckdb,xarray,vector]'
	touch $(STAMP)

demo: $(STAMP)
	$(VENV)/bin/dggs demo

test: $(STAMP)
	$(PY) -m ruff check dggs index storage tests examples
	$(PY) -m mypy
	$(PY) -m pytest -q

test-all: $(STAMP)
	$(PY) -m ruff check dggs index storage tests examples
	$(PY) -m mypy
	$(PY) -m pytest -q -m ''

# Benchmarks against the peers (h3, h3ronpy, pya5, PROJ via pyproj) in their own environment.
$(BENCH_STAMP): pyproject.toml benchmarks/requirements.txt
	$(PYTHON) -m venv $(BENCH_VENV)
	$(BENCH_PY) -m pip install --quiet --upgrade pip
	$(BENCH_PY) -m pip install --quiet -e '.[test]' -r benchmarks/requirements.txt
	touch $(BENCH_STAMP)

bench: $(BENCH_STAMP)
	$(BENCH_PY) benchmarks/run_all.py

clean:
	rm -rf $(VENV) $(BENCH_VENV) build *.egg-info demo.db demo-cells.geojson demo-map.png
	find . -path ./.venv -prune -o \( -name "*.nbi" -o -name "*.nbc" \) -print | xargs rm -f  # numba caches
