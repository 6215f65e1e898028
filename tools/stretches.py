"""How a default solve walks the search package: the search functions in the order they are first
entered.

    python tools/stretches.py [PROBLEM] [--list]

Imports every module of ``axisopt.search``, then profiles ``axisopt.solve(PROBLEM)`` (default
``problems/teaching_problem.yaml``) with ``sys.setprofile``, keeps the functions of
``axisopt.search`` in the order of their first call (comprehensions, lambdas and nested functions
count as their caller), and counts the
stretches: runs of consecutive first entries in one stage module.  A pipeline whose stages are
modules reads as few stretches (entry -> parts -> bounds -> screen -> preload -> polish ->
certificate); helpers scattered across modules read as many.

The task's vocabulary (``axisopt.search.task``: the space, the constraints and the objective every
stage reads) is not a stage: its first entries are listed, and counted, apart (``--all`` counts them
as stretches too).
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def first_entries(problem: str) -> list[tuple[str, str]]:
    import importlib
    import pkgutil

    import axisopt
    import axisopt.search

    # every search module imported first: the walk is the solve's, not the class bodies an import
    # runs
    for info in pkgutil.walk_packages(axisopt.search.__path__, "axisopt.search."):
        importlib.import_module(info.name)

    seen: dict[tuple[str, str], None] = {}

    def prof(frame, event, arg):
        if event != "call":
            return
        mod = frame.f_globals.get("__name__", "")
        if mod.startswith("axisopt.search"):
            key = (
                mod,
                frame.f_code.co_qualname
                if hasattr(frame.f_code, "co_qualname")
                else frame.f_code.co_name,
            )
            # comprehensions, lambdas and nested functions belong to their caller
            if "<" not in key[1] and key not in seen:
                seen[key] = None

    prob = axisopt.load_problem(problem)
    sys.setprofile(prof)
    try:
        axisopt.solve(prob)
    finally:
        sys.setprofile(None)
    return list(seen)


VOCABULARY = "axisopt.search.task"


def stretches(entries, stages_only: bool = True) -> list[tuple[str, int]]:
    out: list[tuple[str, int]] = []
    for mod, _ in entries:
        if stages_only and mod.startswith(VOCABULARY):
            continue
        if out and out[-1][0] == mod:
            out[-1] = (mod, out[-1][1] + 1)
        else:
            out.append((mod, 1))
    return out


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("problem", nargs="?", default=str(ROOT / "problems" / "teaching_problem.yaml"))
    ap.add_argument(
        "--list", action="store_true", help="print every function in the order of first entry"
    )
    ap.add_argument(
        "--all", action="store_true", help="count the task's vocabulary modules as stretches too"
    )
    args = ap.parse_args(argv)
    entries = first_entries(args.problem)
    runs = stretches(entries, stages_only=not args.all)
    if args.list:
        for mod, fn in entries:
            print(f"{mod}.{fn}")
    print(" -> ".join(f"{m.removeprefix('axisopt.search.')}({n})" for m, n in runs))
    mods = {}
    for m, _ in runs:
        mods[m] = mods.get(m, 0) + 1
    vocab = [e for e in entries if e[0].startswith(VOCABULARY)]
    if not args.all:
        print(
            f"task vocabulary: {len(vocab)} functions of "
            + ", ".join(sorted({m.removeprefix(VOCABULARY + ".") for m, _ in vocab}))
        )
    print(
        f"{len(entries)} search functions in {len(runs)} stretches; stretches per module: "
        + ", ".join(
            f"{m.removeprefix('axisopt.search.')} {n}"
            for m, n in sorted(mods.items(), key=lambda t: -t[1])
        )
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
