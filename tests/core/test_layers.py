"""Layer rules the import-linter contracts do not express: no private name crosses a module boundary, no module
holds more than one idea's worth of lines, and the layer contract has no exceptions."""

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
                target = ".".join(base[: len(base) - node.level + 1] + ([node.module] if node.module else []))
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
                    bad.append(f"{path.relative_to(PKG.parent)}:{node.lineno} imports {target}.{alias.name}")
    assert not bad, "\n".join(bad)


def test_no_private_name_imported_across_modules():
    # within a package too: a name another module needs is part of its module's public face
    bad = []
    for path in sorted(PKG.rglob("*.py")):
        for module, target, node in _imports(path):
            for alias in node.names:
                private = alias.name.startswith("_") and not alias.name.startswith("__")
                if private and module != target:
                    bad.append(f"{path.relative_to(PKG.parent)}:{node.lineno} imports {target}.{alias.name}")
    assert not bad, "\n".join(bad)


MAX_LINES = 600  # a module past this holds more than one idea: split it along them (docs/ARCHITECTURE.md)


def test_no_module_over_max_lines():
    long = [f"{p.relative_to(PKG.parent)}: {n} lines" for p in sorted(PKG.rglob("*.py"))
            if (n := len(p.read_text(encoding="utf-8").splitlines())) > MAX_LINES]
    assert not long, "\n".join(long)


def test_the_layer_contract_has_no_exceptions():
    # import-linter checks the contracts as written; an exception list would let a layer import upwards
    text = (PKG.parent / "pyproject.toml").read_text(encoding="utf-8")
    assert "[[tool.importlinter.contracts]]" in text
    assert "ignore_imports" not in text
