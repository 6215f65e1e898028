"""docs/ARCHITECTURE.md against the code: its table of packages names every package of axisopt, in
the layer contract's order (pyproject.toml [tool.importlinter]), each name exists, and every module
file the page names (``search/parts.py``, ``explain.py``) is one of the tree's."""

from __future__ import annotations

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
PAGE = (ROOT / "docs" / "ARCHITECTURE.md").read_text(encoding="utf-8")


def _table_rows() -> list[list[str]]:
    """The layer table's rows: the dotted names of each row's second column, in the page's order."""
    block = PAGE.split("<!-- layers: begin -->")[1].split("<!-- layers: end -->")[0]
    rows = []
    for line in block.splitlines():
        cells = [c.strip() for c in re.split(r"(?<!\\)\|", line.strip().strip("|"))]
        if len(cells) < 3 or not cells[0].isdigit():
            continue
        rows.append(re.findall(r"`(axisopt(?:\.\w+)*)`", cells[1]))
    return rows


def _named() -> set[str]:
    """Every ``axisopt.x.y`` the table names (its second and third columns: sub-packages are named
    there)."""
    block = PAGE.split("<!-- layers: begin -->")[1].split("<!-- layers: end -->")[0]
    return set(re.findall(r"`(axisopt(?:\.\w+)+)`", block))


def _exists(dotted: str) -> bool:
    path = ROOT / dotted.replace(".", "/")
    return path.with_suffix(".py").is_file() or (path / "__init__.py").is_file()


def _packages() -> set[str]:
    return {
        ".".join(p.parent.relative_to(ROOT).parts) for p in (ROOT / "axisopt").rglob("__init__.py")
    } - {"axisopt"}


def test_the_table_follows_the_layer_contract():
    # tomllib is Python 3.11+: the list read as is
    text = (ROOT / "pyproject.toml").read_text(encoding="utf-8")
    block = text.split('type = "layers"')[1].split("layers = [")[1].split("]")[0]
    layers = re.findall(r'"([^"]+)"', block)
    expected = [[m.strip() for m in re.split(r"[|:]", layer)] for layer in layers]
    assert _table_rows() == expected


def test_every_package_is_named():
    missing = sorted(_packages() - _named())
    assert not missing, f"packages docs/ARCHITECTURE.md does not name: {missing}"


def test_every_named_package_or_module_exists():
    gone = sorted(n for n in _named() if not _exists(n))
    assert not gone, f"docs/ARCHITECTURE.md names what does not exist: {gone}"


def test_every_module_file_the_page_names_exists():
    files = {
        p.relative_to(ROOT).as_posix()
        for d in ("axisopt", "tools", "bench", "tests")
        for p in (ROOT / d).rglob("*.py")
    }
    gone = []
    for name in sorted(set(re.findall(r"`([\w/]+\.py)`", PAGE))):
        if not any(f == name or f.endswith("/" + name) for f in files):
            gone.append(name)
    assert not gone, f"docs/ARCHITECTURE.md names module files that do not exist: {gone}"
