"""Benchmark: a 20-minute warm-up record at 1 kHz (1 200 000 samples, viscous friction halving every
20 K as the axis warms from 20 to 40 degC) and a 30 s validation run that starts warm, simulated by
the tests' own cascade (tests/identify/sim_cascade.py, physics written apart from the fitted
model).  Budget: 60 s of CPU on 2 cores for reading and diagnosing (the record is fitted in windows,
:func:`axisopt.identify.records.signal.windowed`).
Prints the CPU time, the verdict and beta.  ``python bench/bench_long_record.py [minutes]``; not run
as a test (simulating the record takes a few minutes)."""

import argparse
import sys
import tempfile
import time
from pathlib import Path

from axisopt.design import load_design
from axisopt.identify import plant_from_design
from axisopt.identify.records.idim import diagnose_time_files

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests" / "identify"))
from sim_cascade import Axis, Loop, simulate, write  # noqa: E402

BUDGET = 60.0  # [s] CPU


def main(minutes: float = 20.0) -> None:
    plant = plant_from_design(load_design(ROOT / "problems" / "data" / "table_x.yaml"))
    dur = 60.0 * minutes
    ax = Axis(beta=0.035, temp=(20.0, 20.0, dur / 4))
    with tempfile.TemporaryDirectory() as d:
        est, val = Path(d) / "est.csv", Path(d) / "val.csv"
        write(est, simulate(ax, Loop(fs=1000.0, rho=0.5), dur, 61), ("temperature",))
        warm = Axis(**{**ax.__dict__, "temp_start": 12.0})
        write(val, simulate(warm, Loop(fs=1000.0, rho=0.5), 30.0, 561), ("temperature",))
        c0, t0 = time.process_time(), time.perf_counter()
        diag = diagnose_time_files([est, val], plant=plant)
        cpu, wall = time.process_time() - c0, time.perf_counter() - t0
    print(
        f"{dur:.0f} s record at 1 kHz: {cpu:.1f} s CPU ({wall:.1f} s wall), budget {BUDGET:g} s "
        f"CPU ({cpu / BUDGET:.2f}x)"
    )
    print(
        f"verdict {diag.verdict}; beta {diag.final.shape.get('beta', float('nan')):.4g} /K (true "
        f"0.035); {diag.estimation.record.run_note()}"
    )


if __name__ == "__main__":
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("minutes", nargs="?", type=float, default=20.0)
    main(ap.parse_args().minutes)
