"""The package's layering, checked statically from the source (ast; nothing of dggs is imported).

Source folders and the names they are installed under: ``dggs/`` (``dggs``),
``index/`` (``dggs.index``), ``storage/`` (``dggs.storage``).  Verb modules
are the public-function modules of ``dggs.index``: ``ids`` and ``cellid``
(the same file, being renamed), ``points``, ``hierarchy``, ``grid``,
``vertex``, ``lines``, ``polyfill``, ``measure``.

The rules:

(a) No module imports a private (underscore) name from a verb module:
    not ``from dggs.index.grid import _pair``, not ``from .grid import _pair``,
    not ``grid._pair`` after ``from . import grid`` (or ``import
    dggs.index.grid as grid``).  What verbs share lives in a private module.
(b) Verbs contain no single-id shortcut of their own: no comparison whose
    operand is a call of ``type(...)`` (``type(x) is str``, ``type(x) in
    (...)``), no ``isinstance`` call whose second argument names ``str`` or
    ``int``, and no call to a converter's scalar helpers (a called name
    containing ``scalar_id``, starting ``one_`` or ending ``_of``).  The
    single-id fast path lives in ``dggs.index._convert``.
(c) Only ``dggs.index`` modules import the kernel: ``dggs.index._kernel``,
    any ``dggs.index._k*`` module, ``dggs.index._bits`` and
    ``dggs.index._codec``.  ``dggs/arrow/__init__.py``, ``dggs/server/*``,
    ``storage/*`` and the rest go through the verbs or the converter and
    shape modules (``dggs.index._convert``, ``dggs.index._shapes``).
(d) The geometry floor: ``dggs/geometry/*`` imports nothing from ``dggs``
    but ``dggs.errors``, ``dggs.geometry.*`` and the compiled core ``dggs._core``.
(f) Only the kernel floors bind the compiled core: ``dggs._core`` is imported
    by ``dggs.geometry`` and ``dggs.index._kernel`` modules alone.
(e) Modules are sized by idea: about 400 lines is the guideline (STYLE.md); a module past it holds one idea
    and says so in :data:`LONG_MODULES`, and none passes :data:`MAX_LINES` (two ideas in one file are split).
(g) No import circle anywhere: the graph of module -> imported module (every import, at any depth of the
    file, a module's own enclosing packages left out since Python loads them anyway) has no cycle.
(i) No integration or the store imports another one's private names: an integration (``dggs.raster``,
    ``dggs.duckdb``, ``dggs.spark``, ``dggs.pandas``, ``dggs.arrow``, ``dggs.polars``, ``dggs.dask``,
    ``dggs.xdggs``, ``dggs.server``) and ``dggs.storage`` take from each other only public modules and names;
    what they share of the grid comes from ``dggs.index`` (its verbs and floors).
(h) The geometry floor loads nothing above it: importing every ``dggs.geometry`` module in a fresh
    interpreter leaves ``dggs.index``, ``dggs.storage`` and the integrations unloaded.

Each check lists every offence as ``file:line: what``.
"""

from __future__ import annotations

import ast
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
PACKAGES = {"dggs": ROOT / "dggs", "dggs.index": ROOT / "index", "dggs.storage": ROOT / "storage"}
VERBS = {f"dggs.index.{m}" for m in ("ids", "cellid", "points", "hierarchy", "grid", "vertex", "lines", "polyfill", "measure")}
GUIDE_LINES = 400
MAX_LINES = 700
#: Modules past GUIDE_LINES, each with the one idea that holds it together (an entry for a module back under the
#: guideline is stale and fails, so the list stays true).
LONG_MODULES: dict[str, str] = {
    "dggs.storage.store": "the CellStore facade: one documented delegate per public verb over its collaborators",
}


def _modules() -> dict[str, Path]:
    out = {}
    for pkg, folder in PACKAGES.items():
        for path in sorted(folder.rglob("*.py")):
            rel = path.relative_to(folder).with_suffix("")
            parts = [p for p in rel.parts if p != "__init__"]
            if pkg == "dggs" and parts and parts[0] in ("index", "storage", "experiments"):
                continue
            out[".".join([pkg, *parts])] = path
    return out


MODULES = _modules()
TREES = {name: ast.parse(path.read_text(encoding="utf-8"), str(path)) for name, path in MODULES.items()}


def _where(module: str, node: ast.AST) -> str:
    return f"{MODULES[module].relative_to(ROOT)}:{getattr(node, 'lineno', 0)}"


def _package_of(module: str) -> str:
    return module if MODULES[module].name == "__init__.py" else module.rpartition(".")[0]


def _resolve(module: str, node: ast.ImportFrom) -> str:
    """The absolute module an ``ImportFrom`` reads from."""
    if not node.level:
        return node.module or ""
    base = _package_of(module).split(".")
    base = base[: len(base) - (node.level - 1)]
    return ".".join(base + ([node.module] if node.module else []))


def _imports(module: str):
    """(node, absolute module name, bound name or None) for every import in a module."""
    for node in ast.walk(TREES[module]):
        if isinstance(node, ast.Import):
            for alias in node.names:
                yield node, alias.name, alias.asname
        elif isinstance(node, ast.ImportFrom):
            source = _resolve(module, node)
            for alias in node.names:
                yield node, source, None
                yield node, f"{source}.{alias.name}", alias.asname or alias.name  # a submodule, if it is one


def _report(offences: list[str]) -> None:
    for line in offences:
        print(line)
    assert not offences, f"{len(offences)} offences:\n" + "\n".join(offences)


def test_no_private_names_from_verb_modules():
    offences = []
    for module, tree in TREES.items():
        bound_verbs = {}
        for node, name, bound in _imports(module):
            if isinstance(node, ast.ImportFrom) and name in VERBS and bound:
                bound_verbs[bound] = name
            if isinstance(node, ast.Import) and name in VERBS:
                bound_verbs[bound or name] = name
        for node in ast.walk(tree):
            if isinstance(node, ast.ImportFrom) and _resolve(module, node) in VERBS:
                for alias in node.names:
                    if alias.name.startswith("_"):
                        offences.append(f"{_where(module, node)}: imports {alias.name} from {_resolve(module, node)}")
            if isinstance(node, ast.Attribute) and node.attr.startswith("_") and not node.attr.startswith("__"):
                target = ast.unparse(node.value)
                if target in bound_verbs:
                    offences.append(f"{_where(module, node)}: uses {target}.{node.attr} of {bound_verbs[target]}")
    _report(offences)


def _calls_type(node: ast.AST) -> bool:
    return isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id == "type"


def _called_name(node: ast.Call) -> str:
    if isinstance(node.func, ast.Name):
        return node.func.id
    if isinstance(node.func, ast.Attribute):
        return node.func.attr
    return ""


def test_verbs_have_no_single_id_shortcut():
    offences = []
    for module in sorted(VERBS & set(TREES)):
        for node in ast.walk(TREES[module]):
            if isinstance(node, ast.Compare) and any(_calls_type(x) for x in [node.left, *node.comparators]):
                offences.append(f"{_where(module, node)}: type comparison `{ast.unparse(node)}`")
            if isinstance(node, ast.Call):
                name = _called_name(node)
                if name == "isinstance" and len(node.args) == 2:
                    names = {n.id for n in ast.walk(node.args[1]) if isinstance(n, ast.Name)}
                    if names & {"str", "int"}:
                        offences.append(f"{_where(module, node)}: `{ast.unparse(node)}`")
                if "scalar_id" in name or name.startswith("one_") or name.endswith("_of"):
                    offences.append(f"{_where(module, node)}: scalar helper call `{ast.unparse(node.func)}(...)`")
    _report(offences)


def _is_kernel(name: str) -> bool:
    if not name.startswith("dggs.index."):
        return False
    first = name[len("dggs.index.") :].split(".")[0]
    return first.startswith("_k") or first in ("_bits", "_codec")


def test_only_the_index_package_imports_the_kernel():
    offences = []
    for module in TREES:
        if module == "dggs.index" or module.startswith("dggs.index."):
            continue
        for node, name, _ in _imports(module):
            if _is_kernel(name):
                offences.append(f"{_where(module, node)}: {module} imports {name}")
    _report(sorted(set(offences)))


def test_geometry_imports_only_errors_and_geometry():
    offences = []
    for module in TREES:
        if not module.startswith("dggs.geometry"):
            continue
        for node in ast.walk(TREES[module]):
            if isinstance(node, ast.Import):
                sources = [a.name for a in node.names]
            elif isinstance(node, ast.ImportFrom):
                source = _resolve(module, node)
                sources = [f"{source}.{a.name}" if source == "dggs" else source for a in node.names]
            else:
                continue
            for source in sources:
                if source.split(".")[0] != "dggs":
                    continue
                if source in ("dggs.errors", "dggs._core", "dggs.geometry") or source.startswith("dggs.geometry."):
                    continue
                offences.append(f"{_where(module, node)}: {module} imports {source}")
    _report(offences)


def test_only_the_kernel_floors_bind_the_compiled_core():
    offences = []
    for module in TREES:
        if module.startswith(("dggs.geometry", "dggs.index._kernel")):
            continue
        for node, name, _ in _imports(module):
            if name == "dggs._core" or name.startswith("dggs._core."):
                offences.append(f"{_where(module, node)}: {module} imports {name}")
    _report(sorted(set(offences)))


@pytest.mark.parametrize("folder", list(PACKAGES.values()), ids=list(PACKAGES))
def test_modules_are_sized_by_idea(folder):
    offences = []
    for module, path in MODULES.items():
        if not path.is_relative_to(folder):
            continue
        n = len(path.read_text(encoding="utf-8").splitlines())
        where = f"{path.relative_to(ROOT)}:{n}"
        if n > MAX_LINES:
            offences.append(f"{where}: {n} lines, over {MAX_LINES}: more than one idea, split it")
        elif n > GUIDE_LINES and module not in LONG_MODULES:
            offences.append(f"{where}: {n} lines, over the guideline {GUIDE_LINES}: split it, or name its one idea in "
                            "LONG_MODULES")
        elif n <= GUIDE_LINES and module in LONG_MODULES:
            offences.append(f"{where}: back under {GUIDE_LINES} lines: take it out of LONG_MODULES")
    _report(offences)


def test_long_modules_are_modules():
    assert set(LONG_MODULES) <= set(MODULES), sorted(set(LONG_MODULES) - set(MODULES))


def _import_graph() -> dict[str, set[str]]:
    """module -> the modules it imports (the deepest known module an import names)."""

    def known(name: str) -> str:
        while name and name not in MODULES:
            name = name.rpartition(".")[0]
        return name

    graph: dict[str, set[str]] = {module: set() for module in MODULES}
    for module in MODULES:
        for _, name, _ in _imports(module):
            target = known(name)
            if target and target != module and not module.startswith(target + "."):
                graph[module].add(target)
    return graph


def _cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components of more than one module (iterative Tarjan)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    found = []
    for root in sorted(graph):
        if root in index:
            continue
        work = [(root, iter(sorted(graph[root])))]
        index[root] = low[root] = len(index)
        stack.append(root)
        on_stack.add(root)
        while work:
            node, edges = work[-1]
            for nxt in edges:
                if nxt not in index:
                    index[nxt] = low[nxt] = len(index)
                    stack.append(nxt)
                    on_stack.add(nxt)
                    work.append((nxt, iter(sorted(graph[nxt]))))
                    break
                if nxt in on_stack:
                    low[node] = min(low[node], index[nxt])
            else:
                work.pop()
                if work:
                    low[work[-1][0]] = min(low[work[-1][0]], low[node])
                if low[node] == index[node]:
                    component = []
                    while True:
                        member = stack.pop()
                        on_stack.discard(member)
                        component.append(member)
                        if member == node:
                            break
                    if len(component) > 1:
                        found.append(sorted(component))
    return found


def test_cycle_finder_finds_a_planted_circle():
    """The finder is able to fail: a planted three-module circle is reported, a chain is not."""
    assert _cycles({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == [["a", "b", "c"]]
    assert _cycles({"a": {"b"}, "b": {"c"}, "c": set()}) == []


def test_no_import_circle():
    _report([" -> ".join(component) for component in _cycles(_import_graph())])


INTEGRATIONS = ("dggs.raster", "dggs.duckdb", "dggs.spark", "dggs.pandas", "dggs.arrow", "dggs.polars", "dggs.dask",
                "dggs.xdggs", "dggs.server", "dggs.storage")


def _integration_of(module: str) -> str | None:
    return next((i for i in INTEGRATIONS if module == i or module.startswith(i + ".")), None)


def test_no_integration_imports_anothers_private_names():
    offences = []
    for module in TREES:
        own = _integration_of(module)
        for node, name, _ in _imports(module):
            other = _integration_of(name)
            if other is None or other == own:
                continue
            private = [p for p in name[len(other):].split(".") if p.startswith("_") and p != "__init__"]
            if private:
                offences.append(f"{_where(module, node)}: {module} imports {name}, private to {other}")
    _report(sorted(set(offences)))


def test_geometry_floor_loads_nothing_above_it_in_a_fresh_process():
    geometry = sorted(m for m in MODULES if m == "dggs.geometry" or m.startswith("dggs.geometry."))
    code = (
        "import importlib, sys\n"
        f"for m in {geometry!r}: importlib.import_module(m)\n"
        "print('\\n'.join(sorted(m for m in sys.modules if m.startswith('dggs'))))"
    )
    loaded = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout.split()
    assert "dggs.geometry.kernel" in loaded
    above = [m for m in loaded if not (m in ("dggs", "dggs.errors", "dggs._core") or m.startswith("dggs.geometry"))]
    assert not above, f"importing the geometry floor loaded {above}"


def test_the_checks_see_the_package():
    """The folders are where the checks look (an empty scan would pass every rule)."""
    assert "dggs.index.grid" in MODULES and "dggs.storage.store" in MODULES and "dggs.geometry.snyder" in MODULES
    assert VERBS & set(MODULES)
