"""Scaling benchmark of the default search (not a test): synthetic multi-vendor catalogs
(bench/synthetic_catalogs.py) at 10^6, 10^7 and 10^8 combinations, motors, couplings and reductions
included, each size solved in a fresh process so that its peak memory is its own.  Prints one row
per size: combinations, solve time, peak memory (max RSS), pruning by kind (combinations never
formed because their drive pair is left out, pruned by their block's bound, screened one by one,
pruned by bound after screening), exact 1-D solves, feasible among the screened, and the objective;
`--exhaustive-check` also runs --method exhaustive on the smallest size and prints the ratio;
`--pareto SIZE` the 4-objective Pareto front (stiffness, frequency, cost, total mass) at one of the
sizes.

    python bench/bench_scale.py [--sizes 1e6 1e7 1e8] [--exhaustive-check] [--pareto 1e7]
"""

from __future__ import annotations

import argparse
import json
import math
import resource
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "bench"))

# (screws, nuts per screw, bearings, guides, motors, couplings, reductions): about nuts x bearings x
# guides x drives (motor, coupling, reduction or none; issue 39: reductions in every size)
SHAPES = {
    1e6: (10, 5, 50, 40, 6, 3, 2),
    1e7: (20, 5, 100, 35, 5, 2, 3),
    1e8: (40, 5, 200, 40, 8, 4, 4),
    1e9: (60, 6, 300, 45, 12, 6, 6),
}
# a reduction's backlash is lost motion at the table (jt P_h / 2 pi): 5 um admits the synthetic
# planetaries (3 arcmin) and belts (5 arcmin) on leads up to 36 mm and 21 mm, and still no nut with
# play (20 um)
MAX_BACKLASH = 5e-6


def problem(size: float):
    from synthetic_catalogs import catalog

    from axisopt.design import Axis
    from axisopt.model import CHECKS
    from axisopt.model.goals import Objective
    from axisopt.problem import Problem, Restrictions

    s, n, b, g, m, c, r = SHAPES[size]
    cat = catalog(s, n, b, g, m, c, seed=int(math.log10(size)), n_reductions=r)
    axis = Axis(
        stroke=0.8,
        moving_mass=400.0,
        mounting="fixed-supported",
        max_speed=0.4,
        axial_load=2000.0,
        # 20 000 h: no synthetic bearing set since issue 38
        acceleration=3.0,
        required_life=15000 * 3600.0,
    )
    return Problem(
        axis=axis,
        catalog=cat,
        objective=Objective(mode="frequency"),
        limits=(("max_backlash", MAX_BACKLASH), ("max_cost", 6000.0), ("max_drag_torque", 2.5)),
        margins=tuple((k, 1.0) for k in CHECKS),
        restrictions=Restrictions(mountings=("fixed-supported",), drive=True),
        name=f"synthetic-{size:.0e}",
    )


def one(size: float, method: str) -> dict:
    from dataclasses import replace

    from axisopt.model.goals import Objective
    from axisopt.search import solve

    p = problem(size)
    if method == "pareto":  # the 4-objective front with the default method
        p = replace(
            p,
            objective=Objective(
                mode="pareto", pareto=("stiffness", "frequency", "cost", "total_mass")
            ),
        )
        t = time.perf_counter()
        res = solve(p, "default")
        dt = time.perf_counter() - t
        c = res.certificate
        return {
            "size": size,
            "method": method,
            "combinations": c.combinations,
            "time_s": dt,
            "peak_MB": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024,
            "exact": c.exact_evaluations,
            "pruned": 0,
            "feasible": res.pareto.feasible,
            "status": f"front of {len(res.pareto.points)} points",
            "objective": float("nan"),
            "unit": "",
            "screened": c.screened,
            "proven": c.proven,
            "never_formed": c.pruned_by_dominance,
            "by_block": c.pruned_by_block,
        }
    t, cpu = time.perf_counter(), time.process_time()
    # the whole search, however long
    res = solve(p, method, top=1, sensitivities=False, time_limit=math.inf)
    # CPU: what a loaded machine does not inflate
    dt, cpu = time.perf_counter() - t, time.process_time() - cpu
    c = res.certificate
    return {
        "size": size,
        "method": method,
        "combinations": c.combinations,
        "time_s": dt,
        "cpu_s": cpu,
        "rate_M_per_s": c.screening_rate / 1e6,
        "screening_s": c.screening_time,
        "peak_MB": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024,
        "exact": c.exact_evaluations,
        "pruned": c.pruned_by_bound,
        "feasible": c.feasible,
        "status": res.status,
        "objective": res.objective,
        "screened": c.screened if c.screened is not None else c.combinations,
        "unit": res.objective_unit,
        "proven": c.proven,
        "never_formed": c.pruned_by_dominance,
        "by_block": c.pruned_by_block,
    }


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sizes", nargs="+", type=float, default=[1e6, 1e7, 1e8])
    ap.add_argument("--exhaustive-check", action="store_true")
    ap.add_argument(
        "--pareto", type=float, metavar="SIZE", help="also the 4-objective Pareto front at SIZE"
    )
    ap.add_argument("--child", nargs=2, metavar=("SIZE", "METHOD"), help=argparse.SUPPRESS)
    args = ap.parse_args(argv)
    if args.child:
        print(json.dumps(one(float(args.child[0]), args.child[1])))
        return 0
    runs = [(s, "default") for s in args.sizes]
    if args.exhaustive_check:
        runs.append((min(args.sizes), "exhaustive"))
    if args.pareto:
        runs.append((args.pareto, "pareto"))
    # pruning by kind: pairs never formed (dominated coupling, coupling too weak for the motor),
    # blocks pruned by their bound, combinations screened one by one, survivors pruned by bound,
    # exact 1-D solves every column is at least one space wider than its widest number (11-digit
    # counts with commas), so that two numbers never run together (an exhaustive row's "0" and
    # "1,600,000" printed as "01,600,000")
    print(
        f"{'combinations':>15} {'method':>11} {'time s':>8} {'CPU s':>8} {'peak MB':>8} "
        f"{'never formed':>14}"
        f" {'by block':>14} {'screened':>14} {'by bound':>14} {'exact':>14} {'feasible':>14}  "
        "objective"
    )
    rows = []
    for size, method in runs:
        out = subprocess.run(
            [sys.executable, __file__, "--child", str(size), method],
            capture_output=True,
            text=True,
            check=True,
        )
        r = json.loads(out.stdout.strip().splitlines()[-1])
        rows.append(r)
        print(
            f"{r['combinations']:>15,} {method:>11} {r['time_s']:>8.2f} "
            f"{r.get('cpu_s', math.nan):>8.2f}"
            f" {r['peak_MB']:>8.0f}"
            f" {r['never_formed']:>14,} {r['by_block']:>14,} {r['screened']:>14,} "
            f"{r['pruned']:>14,}"
            f" {r['exact']:>14,} {(r['feasible'] or 0):>14,}  "
            f"{r['status']}" + ("" if method == "pareto" else f" {r['objective']:.4f} {r['unit']}")
        )
    ex = [r for r in rows if r["method"] == "exhaustive"]
    if ex:
        d = next(r for r in rows if r["method"] == "default" and r["size"] == ex[0]["size"])
        same = math.isclose(d["objective"], ex[0]["objective"], rel_tol=1e-6)
        print(
            f"exhaustive / default time at {d['combinations']:,}: "
            f"{ex[0]['time_s'] / d['time_s']:.0f}x; same optimum: {same}"
        )
    return 0


if __name__ == "__main__":
    sys.exit(main())
