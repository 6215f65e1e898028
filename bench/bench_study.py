"""Benchmark of ``axisopt study`` (prints figures; not a test).

    python bench/bench_study.py [--n 1000] [--study problems/studies/vmc_random_1000.yaml]

Runs the cases of the study three ways and prints wall-clock times and ratios:

1. a plain loop in this process: build each case's problem and ``solve`` it (no files, no pool),
   with the median, mean and slowest solve time (wall and CPU) of the feasible and of the infeasible
   cases (explanation included) and the ratio of the medians; CPU time is less affected by other
   processes on a loaded machine;
2. ``run_study`` with 1 worker process (case files, table, plots and report included);
3. ``run_study`` with 2 worker processes.

Targets (issues 5, 29): 1000 cases in <= 60 s on 2 cores; infeasible / feasible median <= 2; study
overhead <= 10 % over the plain loop (1 worker against the loop); >= 1.7x faster with 2 workers than
with 1.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import tempfile
import time
from dataclasses import replace
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from axisopt.search import solve  # noqa: E402
from axisopt.study import build_problem, load_study, run_study  # noqa: E402


def plain_loop(study) -> tuple[float, dict]:
    """Total time and each case's (wall, CPU) solve time by outcome ('feasible': a design;
    'infeasible': explained)."""
    ctx = study.context()
    per = {"feasible": [], "infeasible": []}
    t0 = time.perf_counter()
    for c in study.cases:
        try:
            p = build_problem(ctx, c)
        except Exception:  # noqa: BLE001 - an invalid combination counts as a (quick) failed case
            continue
        t, cpu = time.perf_counter(), time.process_time()
        r = solve(p, study.method, top=1, sensitivities=False)
        per["feasible" if r.best is not None else "infeasible"].append(
            (time.perf_counter() - t, time.process_time() - cpu)
        )
    return time.perf_counter() - t0, per


def print_medians(per: dict) -> None:
    """Median, mean and slowest solve time (wall and CPU) of feasible and of infeasible cases (the
    latter include the explanation), and the ratio of the medians."""
    med = {}
    for k in ("feasible", "infeasible"):
        wall = [w for w, _ in per[k]] or [float("nan")]
        cpu = [c for _, c in per[k]] or [float("nan")]
        med[k] = (statistics.median(wall), statistics.median(cpu))
        print(
            f"  {k + ' cases':<18}{len(per[k]):>5}   median {1e3 * med[k][0]:7.1f} ms wall "
            f"{1e3 * med[k][1]:7.1f} ms CPU   mean {1e3 * statistics.fmean(wall):7.1f} ms wall "
            f"{1e3 * statistics.fmean(cpu):7.1f} ms CPU   slowest {max(wall):6.2f} s   total "
            f"{sum(wall):6.1f} s"
        )
    print(
        f"  infeasible / feasible median: {med['infeasible'][0] / med['feasible'][0]:.2f} wall, "
        f"{med['infeasible'][1] / med['feasible'][1]:.2f} CPU  (target <= 2)"
    )


def timed_study(study, workers: int) -> tuple[float, object]:
    with tempfile.TemporaryDirectory() as d:
        t0 = time.perf_counter()
        s = run_study(study, Path(d) / "out", workers=workers)
        return time.perf_counter() - t0, s


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--study", default=str(ROOT / "problems/studies/vmc_random_1000.yaml"))
    ap.add_argument("--n", type=int, default=1000, help="use the first N cases")
    ap.add_argument("--skip-loop", action="store_true", help="skip the plain loop")
    ap.add_argument(
        "--loop-only", action="store_true", help="only the plain loop and its per-case medians"
    )
    args = ap.parse_args(argv)
    study = load_study(args.study)
    study = replace(study, cases=study.cases[: args.n])
    n = len(study.cases)
    print(f"study {study.name}: {n} cases")
    # warm this process (imports, CasADi functions, catalog) so the loop measures solving only
    solve(build_problem(study.context(), study.cases[0]), top=1, sensitivities=False)
    t_loop = None
    if not args.skip_loop:
        t_loop, per = plain_loop(study)
        print(f"plain loop (1 process)        {t_loop:7.1f} s   {1e3 * t_loop / n:6.1f} ms/case")
        print_medians(per)
        if args.loop_only:
            return 0
    t1, s1 = timed_study(study, 1)
    print(
        f"study, 1 worker process       {t1:7.1f} s   {1e3 * t1 / n:6.1f} ms/case   ({s1.failed} "
        "failed cases)"
    )
    t2, s2 = timed_study(study, 2)
    print(f"study, 2 worker processes     {t2:7.1f} s   {1e3 * t2 / n:6.1f} ms/case")
    if t_loop:
        print(
            f"overhead of the study over the plain loop (1 worker): {100 * (t1 / t_loop - 1):+.1f} "
            "%  (target <= +10 %)"
        )
    print(f"speed-up 2 workers / 1 worker: {t1 / t2:.2f}x  (target >= 1.7x)")
    print(
        f"{n} cases on 2 workers: {t2:.1f} s  (target for 1000: <= 60 s; "
        f"scaled to 1000: {t2 * 1000 / n:.1f} s)"
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
