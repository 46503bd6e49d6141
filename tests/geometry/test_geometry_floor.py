"""The geometry package is the ground floor and the package face is lazy (issue 16).

dggs/geometry imports only the standard library, numpy, the compiled core
(dggs._core, which imports nothing of the package) and dggs.errors besides itself, and no module of it takes an underscore name from
a sibling; ``import dggs`` and ``import dggs.geometry.authalic`` load none of
the heavy libraries.  No timings here: speed belongs to the benchmarks.
"""

from __future__ import annotations

import ast
import subprocess
import sys
from pathlib import Path

import pytest

GEOMETRY = Path(__file__).resolve().parents[2] / "dggs" / "geometry"
ALLOWED_THIRD_PARTY = {"numpy"}


def _imports(path: Path):
    """(module imported, names taken from it, line) of every import statement, relative ones resolved."""
    tree = ast.parse(path.read_text(), filename=str(path))
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            for alias in node.names:
                yield alias.name, [], node.lineno
        elif isinstance(node, ast.ImportFrom):
            if node.level:  # relative: from . import x / from .kernel import y
                base = "dggs.geometry"
                module = f"{base}.{node.module}" if node.module else base
            else:
                module = node.module or ""
            yield module, [a.name for a in node.names], node.lineno


MODULES = sorted(GEOMETRY.glob("*.py"))


def test_the_geometry_package_has_modules():
    names = {p.stem for p in MODULES}
    assert {"constants", "kernel", "snyder", "split26", "authalic", "icosahedron"} <= names


@pytest.mark.parametrize("path", MODULES, ids=lambda p: p.name)
def test_geometry_imports_only_the_floor(path):
    for module, names, line in _imports(path):
        top = module.split(".")[0]
        ok = (
            top in sys.stdlib_module_names
            or top in ALLOWED_THIRD_PARTY
            or module == "dggs.errors"
            or module == "dggs._core"
            or (module == "dggs" and names == ["_core"])
            or module == "dggs.geometry"
            or module.startswith("dggs.geometry.")
        )
        assert ok, f"{path.name}:{line} imports {module}"


@pytest.mark.parametrize("path", MODULES, ids=lambda p: p.name)
def test_no_underscore_names_from_a_sibling(path):
    for module, names, line in _imports(path):
        if module == "dggs.geometry" or module.startswith("dggs.geometry."):
            private = [n for n in names if n.startswith("_")]
            assert not private, f"{path.name}:{line} takes private {private} from {module}"


def _run(code: str) -> None:
    subprocess.run([sys.executable, "-c", code], check=True)


def test_authalic_loads_no_numba_shapely_or_index():
    _run(
        "import sys, dggs.geometry.authalic; "
        "bad = [m for m in ('numba', 'shapely', 'dggs.index') if m in sys.modules]; assert not bad, bad"
    )


def test_import_dggs_is_lazy_and_complete():
    _run(
        "import sys, dggs; "
        "heavy = ('numba', 'shapely', 'pyproj', 'pandas', 'pyarrow', 'dggs.index'); "
        "bad = [m for m in heavy if m in sys.modules]; assert not bad, bad; "
        "cell = dggs.latlng_to_cell(51.05, -114.07, 3); assert dggs.get_level(cell) == 3, cell; "
        "assert set(dir(dggs)) >= set(dggs.__all__); "
        "missing = [n for n in dggs.__all__ if getattr(dggs, n, None) is None]; assert not missing, missing"
    )


def test_submodules_are_attributes_after_a_bare_import():
    _run("import dggs; assert dggs.index.hierarchy.cell_to_parent('C401') == 'C40'; "
         "import dggs.geometry.kernel; assert dggs.geometry.kernel.ISEA_FRAMES.shape == (20, 3, 3)")


def test_unknown_attribute_raises_attribute_error():
    import dggs

    with pytest.raises(AttributeError, match="no_such_name"):
        dggs.no_such_name  # noqa: B018
    assert not hasattr(dggs, "icosahedron")
