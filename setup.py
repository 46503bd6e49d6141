"""The compiled core: ``dggs._core``, the Cython binding of libdggs (libdggs/), built by the machine's C compiler.

Everything else about the package is in pyproject.toml; this file only declares the extension, because its
compiler flags depend on the compiler. The C sources are compiled into the extension itself (no shared library
to find at run time). Floating point as written (``-ffp-contract=off``: no fused multiply-add), so the ids equal
the C tests' and every other binding's bit for bit. Batch loops run on OpenMP threads where the compiler has
OpenMP (gcc, clang with libomp); elsewhere they run on one thread.
"""

from __future__ import annotations

import glob
import importlib.util
import os
import subprocess
import sys
import tempfile

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

HERE = os.path.dirname(os.path.abspath(__file__))
CORE = os.path.join("libdggs")
FP_FLAGS = ["-ffp-contract=off", "-fno-fast-math"]


def _has_openmp(compiler: list[str]) -> bool:
    """Whether the C compiler builds and links a program with -fopenmp."""
    with tempfile.TemporaryDirectory() as tmp:
        src = os.path.join(tmp, "omp.c")
        with open(src, "w") as f:
            f.write("#include <omp.h>\nint main(void) { return omp_get_max_threads() > 0 ? 0 : 1; }\n")
        try:
            done = subprocess.run([*compiler, "-fopenmp", src, "-o", os.path.join(tmp, "omp")], capture_output=True)
        except OSError:
            return False
        return done.returncode == 0


class BuildExt(build_ext):
    """Adds the flags that depend on the compiler (OpenMP where it links; MSVC's own spelling)."""

    def build_extensions(self) -> None:
        if self.compiler.compiler_type == "msvc":
            for ext in self.extensions:
                ext.extra_compile_args = ["/O2", "/fp:precise", "/openmp"]
        else:
            omp = _has_openmp(list(self.compiler.compiler_so[:1]))
            for ext in self.extensions:
                # Cython's prange loops leave a variable set but unused in the generated C (not in libdggs)
                ext.extra_compile_args = ["-O3", "-std=c11", *FP_FLAGS, "-Wno-unused-but-set-variable"] + (
                    ["-fopenmp"] if omp else [])
                ext.extra_link_args = ["-fopenmp"] if omp else []
            if not omp:
                print("note: no OpenMP in this C compiler; dggs's batch loops will run on one thread", file=sys.stderr)
        super().build_extensions()
        if os.environ.get("DGGS_WITH_DUCKDB_EXTENSION") == "1" and not self.inplace:
            self._duckdb_extension()

    def _duckdb_extension(self) -> None:
        """Build the DuckDB extension (libdggs/duckdb/build.py) into the wheel, in the dggs.duckdb package.

        ``dggs.duckdb.load`` looks there first. Built only when asked (``DGGS_WITH_DUCKDB_EXTENSION=1 pip wheel .``),
        as it downloads DuckDB's headers (the duckdb sdist, by pip) and compiles the core once more.
        """
        out = os.path.join(os.path.abspath(self.build_lib), "dggs", "duckdb", "dggs.duckdb_extension")
        subprocess.run([sys.executable, os.path.join(HERE, "libdggs", "duckdb", "build.py"), "--out", out], check=True)


def _core_extension() -> list[Extension]:
    from Cython.Build import cythonize

    sources = [os.path.join(CORE, "python", "core.pyx")] + sorted(glob.glob(os.path.join(CORE, "src", "*.c")))
    ext = Extension(
        "dggs._core",
        sources=sources,
        include_dirs=[os.path.join(CORE, "include"), os.path.join(CORE, "src")],
        define_macros=[("NPY_NO_DEPRECATED_API", "NPY_1_7_API_VERSION")],
    )
    return cythonize(
        [ext],
        compiler_directives={"language_level": "3", "boundscheck": False, "wraparound": False, "cdivision": True,
                             "initializedcheck": False, "embedsignature": True},
        build_dir="build/cython",
    )


def _build_py() -> type:
    """The web map's build step (dggs/server/_build.py), loaded by path: importing dggs itself needs the core."""
    spec = importlib.util.spec_from_file_location("_dggs_build", os.path.join(HERE, "dggs", "server", "_build.py"))
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module.BuildPy


# The web map's vendor folder is a package of pyproject.toml's list (so setuptools does not warn about it) filled from
# npm at build time (dggs/server/_build.py); without npm it stays empty, but it must exist.
os.makedirs(os.path.join(HERE, "dggs", "server", "static", "vendor"), exist_ok=True)

setup(ext_modules=_core_extension(), cmdclass={"build_ext": BuildExt, "build_py": _build_py()})
