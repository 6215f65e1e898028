"""SCIP (global MINLP, ``--method scip``) against the default method on the shipped problems.

    python bench/bench_scip.py [--time-limit S] [--max-combinations N]

Prints, per problem: the default method's time and objective, SCIP's time, status, objective, node
count and the ratio of SCIP's time to the default's (both measured here, in this process).  Needs
pyscipopt."""

from __future__ import annotations

import argparse
import time
from pathlib import Path

from axisopt.problem import load_problem
from axisopt.search import solve
from axisopt.search.parts import build_space

PROBLEMS = sorted((Path(__file__).resolve().parents[1] / "problems").glob("*_problem.yaml"))


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument(
        "--time-limit", type=float, default=60.0, help="SCIP time limit per problem [s]"
    )
    ap.add_argument("--max-combinations", type=float, default=5e6, help="skip larger search spaces")
    args = ap.parse_args(argv)
    print(
        f"{'problem':<22}{'combinations':>13}{'default s':>11}{'default obj':>13}{'scip s':>9}"
        f"{'status':>12}{'scip obj':>12}{'nodes':>9}{'scip/default':>14}"
    )
    for path in PROBLEMS:
        p = load_problem(path)
        if p.objective.mode == "pareto":
            print(f"{path.stem.removesuffix('_problem'):<22}  Pareto: not supported by scip")
            continue
        size = build_space(p).size
        name = path.stem.removesuffix("_problem")
        t = time.perf_counter()
        d = solve(p, "default", top=1, sensitivities=False)
        td = time.perf_counter() - t
        if size > args.max_combinations:
            print(
                f"{name:<22}{size:>13,}{td:>11.2f}{d.objective:>13.4g}  scip skipped (> "
                "--max-combinations)"
            )
            continue
        t = time.perf_counter()
        s = solve(p, "scip", top=1, time_limit=args.time_limit)
        ts = time.perf_counter() - t
        nodes = s.certificate.notes[0].split("; ")[-1].split()[0] if s.certificate.notes else "-"
        print(
            f"{name:<22}{size:>13,}{td:>11.2f}{d.objective:>13.4g}{ts:>9.1f}{s.status:>12}"
            f"{s.objective:>12.4g}"
            f"{nodes:>9}{ts / td:>14.0f}",
            flush=True,
        )
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
