"""The tests mirror the package: share of modules with a test file at the mirrored path.

Counting rule: a module axisopt/a/b.py is mirrored by tests/a/test_b.py or
tests/a/test_b_<topic>.py; a module at the package root, axisopt/b.py, by tests/core/test_b.py or
tests/core/test_b_<topic>.py (tests/core holds the tests of the root modules); __init__.py modules
are left out of the count.  Run as a script to print the share, the unmirrored modules and the test
file mirroring each module: `python tests/core/test_mirror.py [-v]`.
"""

from __future__ import annotations

import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
LEAST_SHARE = 0.70


def mirrors(module: Path) -> list[Path]:
    """The test files mirroring one module (a path relative to axisopt/)."""
    folder = ROOT / "tests" / (module.parent if module.parent != Path(".") else Path("core"))
    stem = module.stem
    found = folder.glob(f"test_{stem}*.py")
    return sorted(
        p for p in found if p.stem == f"test_{stem}" or p.stem.startswith(f"test_{stem}_")
    )


def modules() -> list[Path]:
    package = ROOT / "axisopt"
    return sorted(p.relative_to(package) for p in package.rglob("*.py") if p.name != "__init__.py")


def share() -> tuple[float, list[Path]]:
    mods = modules()
    unmirrored = [m for m in mods if not mirrors(m)]
    return 1 - len(unmirrored) / len(mods), unmirrored


def test_most_modules_have_a_mirrored_test_file():
    got, unmirrored = share()
    assert got >= LEAST_SHARE, (
        f"{got:.0%} of modules mirrored, unmirrored: {[str(m) for m in unmirrored]}"
    )


def test_the_rule_sees_a_mirrored_and_an_unmirrored_module():
    assert mirrors(Path("units.py")) == [ROOT / "tests" / "core" / "test_units.py"]
    assert mirrors(Path("physics") / "screw.py")  # tests/physics/test_screw_published.py
    assert not mirrors(Path("no_such_module.py"))


if __name__ == "__main__":
    got, unmirrored = share()
    mods = modules()
    print(f"{len(mods) - len(unmirrored)} of {len(mods)} modules mirrored ({got:.1%}); unmirrored:")
    for m in unmirrored:
        print(f"  axisopt/{m.as_posix()}")
    if "-v" in sys.argv:
        for m in mods:
            print(f"{m.as_posix():40} {' '.join(str(p.relative_to(ROOT)) for p in mirrors(m))}")
