"""Layer rules the import-linter contracts do not express: no private name crosses a module
boundary, no module holds more than one idea's worth of lines, and the layer contract has no
exceptions."""

from __future__ import annotations

import ast
from pathlib import Path

PKG = Path(__file__).resolve().parents[2] / "axisopt"


def _package(module: str) -> str:
    parts = module.split(".")
    return parts[1] if len(parts) > 1 else parts[0]


def _imports(path: Path):
    rel = path.relative_to(PKG.parent).with_suffix("")
    module = ".".join(rel.parts)
    base = module.split(".") if path.name == "__init__.py" else module.split(".")[:-1]
    if path.name == "__init__.py":
        module = module[: -len(".__init__")]
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.ImportFrom):
            if node.level:
                target = ".".join(
                    base[: len(base) - node.level + 1] + ([node.module] if node.module else [])
                )
            else:
                target = node.module or ""
            if target.startswith("axisopt"):
                yield module, target, node


def test_no_private_name_imported_across_packages():
    bad = []
    for path in sorted(PKG.rglob("*.py")):
        for module, target, node in _imports(path):
            for alias in node.names:
                private = alias.name.startswith("_") and not alias.name.startswith("__")
                if private and _package(module) != _package(target):
                    bad.append(
                        f"{path.relative_to(PKG.parent)}:{node.lineno} imports "
                        f"{target}.{alias.name}"
                    )
    assert not bad, "\n".join(bad)


def test_no_private_name_imported_across_modules():
    # within a package too: a name another module needs is part of its module's public face
    bad = []
    for path in sorted(PKG.rglob("*.py")):
        for module, target, node in _imports(path):
            for alias in node.names:
                private = alias.name.startswith("_") and not alias.name.startswith("__")
                if private and module != target:
                    bad.append(
                        f"{path.relative_to(PKG.parent)}:{node.lineno} imports "
                        f"{target}.{alias.name}"
                    )
    assert not bad, "\n".join(bad)


# a module past this holds more than one idea: split it along them (docs/ARCHITECTURE.md)
MAX_LINES = 600


def test_no_module_over_max_lines():
    long = [
        f"{p.relative_to(PKG.parent)}: {n} lines"
        for p in sorted(PKG.rglob("*.py"))
        if (n := len(p.read_text(encoding="utf-8").splitlines())) > MAX_LINES
    ]
    assert not long, "\n".join(long)


def test_the_layer_contract_has_no_exceptions():
    # import-linter checks the contracts as written; an exception list would let a layer import
    # upwards
    text = (PKG.parent / "pyproject.toml").read_text(encoding="utf-8")
    assert "[[tool.importlinter.contracts]]" in text
    assert "ignore_imports" not in text


def _runtime_imports(tree: ast.AST):
    """Every import statement a module can run: top level and inside functions (deferred), not the
    ones under ``if TYPE_CHECKING:`` (never run)."""
    stack = [tree]
    while stack:
        node = stack.pop()
        for child in ast.iter_child_nodes(node):
            if isinstance(child, ast.If) and "TYPE_CHECKING" in ast.unparse(child.test):
                stack.extend(child.orelse)
                continue
            if isinstance(child, (ast.Import, ast.ImportFrom)):
                yield child
            stack.append(child)


def module_graph() -> dict[str, set[str]]:
    """axisopt's import graph: module -> the axisopt modules it imports, deferred imports included.
    ``from pkg import name`` reaches the module ``pkg.name`` when there is one (else the package); a
    module's own package ``__init__`` is not an edge of its own (Python runs it first, but the
    package only re-exports)."""
    modules = {}
    for path in sorted(PKG.rglob("*.py")):
        parts = list(path.relative_to(PKG.parent).with_suffix("").parts)
        is_pkg = parts[-1] == "__init__"
        if is_pkg:
            parts = parts[:-1]
        modules[".".join(parts)] = (path, is_pkg)
    graph: dict[str, set[str]] = {}
    for module, (path, is_pkg) in modules.items():
        package = module.split(".") if is_pkg else module.split(".")[:-1]
        edges = graph.setdefault(module, set())
        for node in _runtime_imports(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Import):
                targets = [a.name for a in node.names]
            else:
                if node.level:
                    base = package[: len(package) - node.level + 1]
                    target = ".".join(base + ([node.module] if node.module else []))
                else:
                    target = node.module or ""
                targets = [
                    f"{target}.{a.name}" if f"{target}.{a.name}" in modules else target
                    for a in node.names
                ]
            edges.update(t for t in targets if t in modules and t != module)
    return graph


def import_cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components of more than one module (Tarjan), each a cycle or a knot of
    them."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    on, stack, out = set(), [], []

    def visit(v):
        index[v] = low[v] = len(index)
        stack.append(v)
        on.add(v)
        for w in sorted(graph.get(v, ())):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return out


def test_the_graph_sees_deferred_imports():
    # the walk must see an import inside a function: the front door imports its stages only when a
    # solve reaches them
    graph = module_graph()
    assert "axisopt.search.parts" in graph["axisopt.search.front"]
    assert "axisopt.search.front" in graph["axisopt.search"]


def test_no_import_cycle_deferred_imports_included():
    cycles = import_cycles(module_graph())
    assert not cycles, "import cycles:\n" + "\n".join(" <-> ".join(c) for c in cycles)


def test_the_cycle_finder_finds_a_cycle():
    assert import_cycles({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == [["a", "b", "c"]]
