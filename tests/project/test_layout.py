"""The layers of :mod:`servofmu.physics` (``docs/development.md``, "Layers"), read from the
source: the import graph of ``physics`` and ``parameters`` (top-level and in-function imports,
and the compiled modules chosen by name) has no cycle, the leaf layer ``kernels`` imports
nothing else from ``physics``, and no module is over 1,500 lines."""

from __future__ import annotations

import ast
from pathlib import Path

from servofmu import parameters, physics

ROOT = Path(physics.__file__).resolve().parent
PACKAGE = "servofmu.physics"
#: The packages whose import graph is read, by name: their folders.
ROOTS = {PACKAGE: ROOT, "servofmu.parameters": Path(parameters.__file__).resolve().parent}
#: The longest module the layout allows [lines].
MAX_LINES = 1500


def _name(package: str, path: Path) -> str:
    """The dotted module name of a source file of ``package``."""
    parts = path.relative_to(ROOTS[package]).with_suffix("").parts
    if parts[-1] == "__init__":
        parts = parts[:-1]
    return ".".join((package, *parts))


MODULES = {_name(k, p): p for k, root in ROOTS.items() for p in sorted(root.rglob("*.py"))}


def _resolve(name: str) -> str | None:
    """The module of :data:`ROOTS` that importing ``name`` runs (a former name: where it
    lives), or None outside them."""
    if name.startswith(PACKAGE + "."):
        head, _, leaf = name.partition(PACKAGE + ".")[2].partition(".")
        if head in physics.MOVED:
            name = ".".join(p for p in (physics.MOVED[head], leaf) if p)
    if not any(name == k or name.startswith(k + ".") for k in ROOTS):
        return None
    while name not in MODULES:  # an attribute of a module: that module
        name = name.rpartition(".")[0]
    return name


def _chosen(call: ast.Call) -> bool:
    """Whether ``call`` is ``compiled.module("X", ...)``: an import of physics module X."""
    f = call.func
    return (
        isinstance(f, ast.Attribute)
        and f.attr == "module"
        and isinstance(f.value, ast.Name)
        and f.value.id == "compiled"
        and bool(call.args)
        and isinstance(call.args[0], ast.Constant)
    )


def imports(module: str) -> set[str]:
    """The modules of :data:`ROOTS` that ``module`` imports anywhere in its source (a function
    body included; ``compiled.module("X")`` imports physics module X; ``cython.cimports`` are
    the compiled twins of modules imported by name beside them)."""
    path = MODULES[module]
    package = module if path.name == "__init__.py" else module.rpartition(".")[0]
    found = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            names = [alias.name for alias in node.names]
        elif isinstance(node, ast.Call) and _chosen(node):
            names = [f"{PACKAGE}.{node.args[0].value}"]
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                anchor = package.rsplit(".", node.level - 1)[0] if node.level > 1 else package
                base = ".".join(p for p in (anchor, base) if p)
            names = [f"{base}.{alias.name}" for alias in node.names]
        else:
            continue
        for name in names:
            if name.startswith("cython"):
                continue
            target = _resolve(name)
            if target is not None and target != module:
                found.add(target)
    return found


def _cycle(graph: dict[str, set[str]]) -> list[str]:
    """One cycle of ``graph`` (its modules in import order), or [] when it has none."""
    colour: dict[str, int] = {}
    stack: list[str] = []

    def visit(node):
        colour[node] = 1
        stack.append(node)
        for nxt in sorted(graph[node]):
            if colour.get(nxt) == 1:
                return [*stack[stack.index(nxt) :], nxt]
            if nxt not in colour and (found := visit(nxt)):
                return found
        stack.pop()
        colour[node] = 2
        return []

    for node in sorted(graph):
        if node not in colour and (found := visit(node)):
            return found
    return []


GRAPH = {module: imports(module) for module in MODULES}


def test_graph_is_read():
    """The reader finds the imports it must: a relative one, an in-function one, a former name."""
    state = f"{PACKAGE}.pair.state"
    assert f"{PACKAGE}.pair.configuration" in GRAPH[state]
    assert f"{PACKAGE}.pair.state" in GRAPH[f"{PACKAGE}.pair.constants"]  # inside a function
    assert _resolve(f"{PACKAGE}.fits.mounted_geometry") == f"{PACKAGE}.thermal.fits"
    assert f"{PACKAGE}.pair.point" in GRAPH[state]  # compiled.module("pair.point")
    assert "servofmu.parameters.catalog" in GRAPH[f"{PACKAGE}.pair.configuration"]


def test_cycle_finder_finds_a_cycle():
    graph = {"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}
    assert _cycle(graph) == ["a", "b", "c", "a"]
    assert _cycle({"a": {"b"}, "b": set()}) == []


def test_no_import_cycle():
    assert _cycle(GRAPH) == []


def test_kernels_import_nothing_else_from_physics():
    leaf = f"{PACKAGE}.kernels"
    outside = {
        module: sorted(t for t in targets if not t.startswith(leaf))
        for module, targets in GRAPH.items()
        if module.startswith(leaf)
    }
    assert {m: t for m, t in outside.items() if t} == {}


def test_no_module_is_too_long():
    lengths = {
        m: p.read_text(encoding="utf-8").count("\n")
        for m, p in MODULES.items()
        if m.startswith(PACKAGE)
    }
    assert {m: n for m, n in lengths.items() if n > MAX_LINES} == {}


def test_one_point_state_class_whichever_path_runs():
    # the continuation of either implementation fills the class the exact path fills
    from kernels import implementations

    from servofmu.physics.bearing import BearingModel, BearingPair
    from servofmu.physics.pair import state

    pair = BearingPair.from_catalog("yu2017_gimbal_printed", "krytox_143aa")
    classes = set()
    for impl in implementations():
        model = BearingModel(pair, impl)
        classes |= {type(model.update(t, 5.0)) for t in (293.15, 293.4, 294.0)}
    assert classes == {state.PointState}
