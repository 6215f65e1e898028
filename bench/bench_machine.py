"""Benchmark of the machine search (not a test): every shipped machine solved jointly with the full
shipped catalogs; prints the nominal joint combinations (the product of every axis's catalog
combinations), the axis solves, wall and CPU time, the joint optimum and the sequential sizing
beside it.

    python bench/bench_machine.py [--only vmc gantry ...]
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from axisopt.machine import load_machine, solve_machine  # noqa: E402
from axisopt.machine.templates import SHIPPED  # noqa: E402


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--only", nargs="*", choices=list(SHIPPED))
    args = ap.parse_args(argv)
    print(
        f"{'machine':<15} {'nominal':>9} {'solves':>6} {'wall s':>7} {'cpu s':>6}  {'joint':>14}  "
        f"{'sequential':>14}  gained"
    )
    for kind, name in SHIPPED.items():
        if args.only and kind not in args.only:
            continue
        m = load_machine(ROOT / "problems" / "machines" / name)
        w0, c0 = time.perf_counter(), time.process_time()
        res = solve_machine(m)
        wall, cpu = time.perf_counter() - w0, time.process_time() - c0
        joint = f"{res.best.value(m.objective):,.1f}" if res.best else "infeasible"
        seq = res.sequential
        seqs = (
            "-"
            if seq is None
            else f"{seq.value(m.objective):,.1f}" + ("" if seq.feasible else " (misses)")
        )
        if res.gain is None:
            gained = "a feasible machine" if res.best and (seq is None or not seq.feasible) else "-"
        else:
            gained = "the same" if abs(res.gain) < 1e-6 else f"{abs(res.gain):,.1f}"
        print(
            f"{kind:<15} {res.nominal_combinations:>9.2e} {res.axis_solves:>6} {wall:>7.1f} "
            f"{cpu:>6.1f}  {joint:>14}  {seqs:>14}  {gained}   ({m.objective})"
        )
    return 0


if __name__ == "__main__":
    sys.exit(main())
