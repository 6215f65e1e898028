"""Benchmark of the sizing search (not a test): default vs exhaustive vs Bonmin on every shipped
problem and on a synthetic catalog of >= 1 000 000 combinations; screening throughput; Pareto front.

Every shipped problem searches the drive too: ``drives`` is the number of (motor, coupling) pairs
each mechanical combination is multiplied by (pairs whose coupling cannot carry the motor's peak
torque are never formed); ``combos`` counts them in.  The synthetic row searches the mechanics only.

    python bench/bench_search.py [--bonmin-time 100] [--skip-bonmin] [--skip-exhaustive-large] [--skip-exhaustive]
                                [--only NAME ...]
"""  # noqa: E501

from __future__ import annotations

import argparse
import math
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "tests" / "search"))

from search_synthetic import BENCH, make_catalog  # noqa: E402

from axisopt.catalog.loading import Catalog  # noqa: E402
from axisopt.design import Axis  # noqa: E402
from axisopt.model import CHECKS  # noqa: E402
from axisopt.model.goals import Objective  # noqa: E402
from axisopt.problem import Problem, Restrictions, load_problem  # noqa: E402
from axisopt.search import solve  # noqa: E402
from axisopt.search.parts import build_space  # noqa: E402
from axisopt.search.screen import screen  # noqa: E402
from axisopt.search.task.constraints import build_constraints  # noqa: E402
from axisopt.search.task.objective import objective_spec  # noqa: E402


def synthetic_catalog(
    seed=0, n_screws=20, nuts_per_screw=5, n_bearings=100, n_guides=100
) -> Catalog:
    """A large synthetic catalog (plausible SI values; 20*5 nuts x 100 x 100 = 1e6 combinations):
    the search tests' builder (tests/search/search_synthetic.py) with the bench's ranges."""
    return make_catalog(
        np.random.default_rng(seed), n_screws, nuts_per_screw, n_bearings, n_guides, ranges=BENCH
    )


def synthetic_problem(objective=None) -> Problem:
    cat = synthetic_catalog()
    axis = Axis(
        stroke=0.8,
        moving_mass=400.0,
        mounting="fixed-fixed",
        max_speed=0.4,
        axial_load=3000.0,
        acceleration=3.0,
    )
    return Problem(
        axis=axis,
        catalog=cat,
        objective=objective or Objective(mode="frequency"),
        limits=(("max_backlash", 0.0), ("max_cost", 5000.0), ("max_drag_torque", 2.0)),
        margins=tuple((c, 1.0) for c in CHECKS),
        restrictions=Restrictions(mountings=("fixed-fixed",)),
        name="synthetic-1M",
    )


def timed(fn):
    t = time.perf_counter()
    r = fn()
    return r, time.perf_counter() - t


REPEAT = 3  # the default method and the screening are timed as the best of this many runs


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--bonmin-time", type=float, default=100.0)
    ap.add_argument("--skip-bonmin", action="store_true")
    ap.add_argument("--skip-exhaustive-large", action="store_true")
    ap.add_argument("--skip-exhaustive", action="store_true")
    ap.add_argument(
        "--only", nargs="+", metavar="NAME", help="run only these problems (file stems)"
    )
    args = ap.parse_args(argv)

    cases = [(p.stem, load_problem(p)) for p in sorted((ROOT / "problems").glob("*_problem.yaml"))]
    cases.append(("synthetic-1M", synthetic_problem()))
    if args.only:
        cases = [c for c in cases if c[0] in args.only]
    rows = []
    for name, prob in cases:
        pareto = prob.objective.mode == "pareto"
        sp = build_space(prob)
        # warm caches (CasADi functions, solvers)
        solve(prob, "default", top=1, sensitivities=False)
        runs = [
            timed(lambda prob=prob: solve(prob, "default", top=1, sensitivities=False))
            for _ in range(REPEAT)
        ]
        # best of REPEAT: the method's time without machine noise
        d, td = min(runs, key=lambda r: r[1])
        if args.skip_exhaustive or (name == "synthetic-1M" and args.skip_exhaustive_large):
            e, te = None, float("nan")
        else:
            e, te = timed(
                lambda prob=prob: solve(
                    prob, "exhaustive", top=1, sensitivities=False, time_limit=math.inf
                )
            )
        if args.skip_bonmin or pareto:
            b, tb = None, float("nan")
        else:
            b, tb = timed(
                lambda prob=prob: solve(
                    prob, "bonmin", time_limit=args.bonmin_time, sensitivities=False
                )
            )
        spec = objective_spec(
            "stiffness"
            if pareto or prob.objective.mode == "lexicographic"
            else prob.objective.mode,
            prob,
        )
        ts = min(screen(sp, build_constraints(prob), spec)[2] for _ in range(REPEAT))
        rows.append((name, sp.size, sp.n_drives, td, te, tb, d, e, b, sp.size / ts))
        print(
            f"  {name}: default {td:.3f} s, exhaustive {te:.2f} s, bonmin {tb:.1f} s "
            f"({b.status if b else '-'})",
            file=sys.stderr,
            flush=True,
        )

    def obj(r):
        if r is None:
            return "-"
        if r.pareto is not None:
            return f"front {len(r.pareto.points)}"
        return f"{r.objective:.4g}" if r.best is not None else r.status

    print(
        f"{'problem':<22}{'combos':>12}{'drives':>7}{'default s':>10}{'exhaust s':>10}"
        f"{'bonmin s':>10}{'ex/def':>8}"
        f"{'bon/def':>8}  {'obj default':>12}{'obj exhaust':>12}{'obj bonmin':>12}  "
        f"{'bonmin status':<22}"
        f"{'screen M/s':>10}"
    )
    for name, n, nd, td, te, tb, d, e, b, rate in rows:
        print(
            f"{name:<22}{n:>12,}{nd:>7}{td:>10.3f}{te:>10.2f}{tb:>10.1f}{te / td:>8.0f}"
            f"{tb / td:>8.0f}  {obj(d):>12}"
            f"{obj(e):>12} {obj(b):>14}  {(b.status if b else '-'):<22}{rate / 1e6:>10.1f}"
        )

    # 4-objective Pareto front over the synthetic >= 1e6 catalog
    pp = synthetic_problem(
        Objective(mode="pareto", pareto=("stiffness", "frequency", "cost", "total_mass"))
    )
    r, t = timed(lambda: solve(pp, "default"))
    print(
        f"\nPareto (stiffness, frequency, cost, total_mass) over {build_space(pp).size:,} "
        f"combinations: {len(r.pareto.points)} points of {r.pareto.feasible:,} feasible in {t:.2f} "
        "s"
    )


if __name__ == "__main__":
    main()
