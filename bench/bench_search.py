"""Benchmark of the sizing search (not a test): default vs exhaustive vs Bonmin on every shipped
problem and on a synthetic catalog of >= 1 000 000 combinations; screening throughput; Pareto front.

Every shipped problem searches the drive too: ``drives`` is the number of (motor, coupling) pairs
each mechanical combination is multiplied by (pairs whose coupling cannot carry the motor's peak torque
are never formed); ``combos`` counts them in.  The synthetic row searches the mechanics only.

    python bench/bench_search.py [--bonmin-time 100] [--skip-bonmin] [--skip-exhaustive-large] [--skip-exhaustive]
                                [--only NAME ...]
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from pathlib import Path

import numpy as np
import pandas as pd

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from axisopt.catalog.columns import SCHEMA  # noqa: E402
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

RPM = 2 * math.pi / 60


def synthetic_catalog(
    seed=0, n_screws=20, nuts_per_screw=5, n_bearings=100, n_guides=100
) -> Catalog:
    """A large synthetic catalog (plausible SI values; 20*5 nuts x 100 x 100 = 1e6 combinations)."""
    rng = np.random.default_rng(seed)
    screws, nuts, bearings, guides = [], [], [], []
    for i in range(n_screws):
        d = float(rng.choice([25, 32, 40, 50, 63])) * 1e-3
        ball = float(rng.choice([3.175, 4.763, 6.35])) * 1e-3
        screws.append(
            {
                "id": f"S{i}",
                "vendor": "SYN",
                "series": "synthetic",
                "nominal_diameter": d,
                "lead": float(rng.choice([10, 16, 20])) * 1e-3,
                "root_diameter": d - 1.2 * ball,
                "ball_diameter": ball,
                "max_length": rng.uniform(3, 6),
                "mass_per_length": 7850 * math.pi * d**2 / 4,
                "dn_limit": rng.uniform(1.2e5, 2.2e5) * 1e-3 * RPM,
                "support_bore_min": 0.4 * d,
                "support_bore_max": d - 0.002,
                "price_per_length": rng.uniform(60, 250),
                "price_fixed": rng.uniform(100, 300),
            }
        )
        for j in range(nuts_per_screw):
            c = rng.uniform(20e3, 120e3)
            double = bool(rng.random() < 0.7)
            nuts.append(
                {
                    "id": f"N{i}_{j}",
                    "vendor": "SYN",
                    "screw_id": f"S{i}",
                    "type": "double" if double else "single",
                    "stiffness": rng.uniform(200, 1200) * 1e6,
                    "stiffness_preload": (0.1 if double else 0.28) * c,
                    "preload_min": 0.02 * c if double else 0.0,
                    "preload_max": 0.1 * c if double else 0.0,
                    "axial_play": 0.0 if double else 2e-5,
                    "dynamic_load_rating": c,
                    "static_load_rating": 2 * c,
                    "contact_angle": math.radians(45),
                    "mass": rng.uniform(0.5, 4),
                    "price": rng.uniform(200, 900),
                }
            )
    for i in range(n_bearings):
        bore = float(rng.choice([15, 17, 20, 25, 30])) * 1e-3
        bearings.append(
            {
                "id": f"B{i}",
                "vendor": "SYN",
                "series": "synthetic",
                "arrangement": "DB",
                "rows": 2,
                "bore": bore,
                "outer_diameter": bore + 0.03,
                "contact_angle": math.radians(60),
                "preload_class": str(rng.choice(["light", "medium", "heavy"])),
                "preload": rng.uniform(500, 3000),
                "axial_rigidity": rng.uniform(300, 1500) * 1e6,
                "lift_off_load": rng.uniform(5e3, 3e4),
                "dynamic_load_rating": rng.uniform(15e3, 40e3),
                "static_load_rating": 4e4,
                "limiting_speed": rng.uniform(3000, 9000) * RPM,
                "f0": 1.5,
                "starting_torque": rng.uniform(0.1, 0.5) if rng.random() < 0.5 else math.nan,
                "f1": 0.0003,
                "mass": rng.uniform(0.2, 1.0),
                "price": rng.uniform(100, 500),
            }
        )
    for i in range(n_guides):
        kn = rng.uniform(200, 900) * 1e6
        guides.append(
            {
                "id": f"G{i}",
                "vendor": "SYN",
                "series": "synthetic",
                "type": "ball",
                "size": 0.025,
                "preload_class": "Z0",
                "preload_level": str(rng.choice(["light", "medium", "heavy"])),
                "preload": rng.uniform(500, 3000),
                "normal_rigidity": kn,
                "tangential_rigidity": 0.71 * kn,
                "dynamic_load_rating": 3e4,
                "static_load_rating": 5e4,
                "friction_force": rng.uniform(3, 30),
                "friction_coefficient": 0.003,
                "friction_viscous": rng.uniform(3, 20),
                "damping": 3000.0,
                "block_mass": rng.uniform(0.2, 1.5),
                "rail_mass_per_length": rng.uniform(2, 6),
                "block_price": rng.uniform(50, 200),
                "rail_price_per_length": rng.uniform(50, 150),
                "moment_roll": 400.0,
                "moment_pitch": 300.0,
                "moment_yaw": 300.0,
            }
        )

    def df(rows, name):
        d = pd.DataFrame.from_records(rows, columns=list(SCHEMA[name]))
        d["_source"] = "synthetic"
        return d.set_index("id", drop=False)

    return Catalog(
        df(screws, "screws"), df(nuts, "nuts"), df(bearings, "bearings"), df(guides, "guides")
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
        f"{'problem':<22}{'combos':>12}{'drives':>7}{'default s':>10}{'exhaust s':>10}{'bonmin s':>10}{'ex/def':>8}"
        f"{'bon/def':>8}  {'obj default':>12}{'obj exhaust':>12}{'obj bonmin':>12}  {'bonmin status':<22}"
        f"{'screen M/s':>10}"
    )
    for name, n, nd, td, te, tb, d, e, b, rate in rows:
        print(
            f"{name:<22}{n:>12,}{nd:>7}{td:>10.3f}{te:>10.2f}{tb:>10.1f}{te / td:>8.0f}{tb / td:>8.0f}  {obj(d):>12}"
            f"{obj(e):>12} {obj(b):>14}  {(b.status if b else '-'):<22}{rate / 1e6:>10.1f}"
        )

    # 4-objective Pareto front over the synthetic >= 1e6 catalog
    pp = synthetic_problem(
        Objective(mode="pareto", pareto=("stiffness", "frequency", "cost", "total_mass"))
    )
    r, t = timed(lambda: solve(pp, "default"))
    print(
        f"\nPareto (stiffness, frequency, cost, total_mass) over {build_space(pp).size:,} combinations: "
        f"{len(r.pareto.points)} points of {r.pareto.feasible:,} feasible in {t:.2f} s"
    )


if __name__ == "__main__":
    main()
