"""Screening throughput of the default search (a benchmark, not a test).

Times :func:`axisopt.search.screen.screen` (every nut of every mounting, each covering all its
bearings, guides and drives) on the shipped problems and on the synthetic catalogs of
bench/bench_scale.py, and prints the designs screened per second: the combinations the screened nuts
cover / seconds.  Each timing is the best of ``--repeat`` runs (the machine may be shared).
``--check FILE`` saves (or, when FILE exists, compares) the survivors and bounds, so that a faster
screening can be shown to keep the same survivors (and bounds within float32 rounding, far inside
the screening's slack SCREEN_RTOL).

    python bench/bench_screen.py [--repeat 5] [--synthetic 1e6 1e7] [--check /tmp/screen.npz]
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "bench"))

PROBLEMS = ("vmc_x_problem", "gantry_problem", "highspeed_problem", "teaching_problem")


def cases(synthetic):
    from axisopt.problem import load_problem

    for name in PROBLEMS:
        yield name, load_problem(ROOT / "problems" / f"{name}.yaml")
    if synthetic:
        from bench_scale import problem

        for s in synthetic:
            yield f"synthetic-{s:.0e}", problem(s)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--synthetic", nargs="*", type=float, default=[1e6, 1e7])
    ap.add_argument(
        "--check", help="npz file of survivors and bounds: written if absent, else compared"
    )
    args = ap.parse_args(argv)
    from axisopt.search.parts import build_space
    from axisopt.search.screen import screen
    from axisopt.search.task.constraints import build_constraints
    from axisopt.search.task.objective import objective_spec

    saved = dict(np.load(args.check)) if args.check and Path(args.check).exists() else None
    new = {}
    print(f"{'problem':>20}{'combinations':>15}{'survivors':>12}{'best s':>9}{'M designs/s':>13}")
    for name, p in cases(args.synthetic):
        sp, cons = build_space(p), build_constraints(p)
        mode = p.objective.mode
        spec = objective_spec(
            mode if mode in ("stiffness", "frequency", "weighted") else "stiffness", p
        )
        screen(sp, cons, spec)  # warm the parameter cache and the imports
        best = np.inf
        for _ in range(args.repeat):
            t = time.perf_counter()
            idx, bnd, _ = screen(sp, cons, spec)
            best = min(best, time.perf_counter() - t)
        order = np.argsort(idx, kind="stable")
        new[f"{name}_idx"], new[f"{name}_bound"] = idx[order], bnd[order]
        same = ""
        if saved is not None and f"{name}_idx" in saved:
            si, sb = saved[f"{name}_idx"], saved[f"{name}_bound"]
            if np.array_equal(si, idx[order]):
                rel = np.max(np.abs(bnd[order] - sb) / np.maximum(np.abs(sb), 1e-30), initial=0.0)
                same = f"  same survivors, bounds within {rel:.1e}"
            else:
                same = f"  DIFFERENT survivors: {len(si)} -> {len(idx)}"
        print(
            f"{name:>20}{sp.size:>15,}{len(idx):>12,}{best:>9.3f}{sp.size / best / 1e6:>13.1f}"
            f"{same}"
        )
    if args.check and saved is None:
        np.savez(args.check, **new)
        print(f"saved survivors and bounds to {args.check}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
