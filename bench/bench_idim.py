"""Benchmark: identify a 25 000-sample time record (1 kHz, 25 s) with LS and IV and diagnose it
against a 12 000-sample validation run (budget 5 s).  Prints the times, the IV/LS time ratio and the
ratio to the budget.
``python bench/bench_idim.py [samples]``; not run as a test."""

import argparse
import tempfile
import time
from pathlib import Path

from axisopt.design import load_design
from axisopt.identify import plant_from_design
from axisopt.identify.records.estimators import instrumental_variables, least_squares
from axisopt.identify.records.idim import diagnose_time_files
from axisopt.identify.records.regression import BASE
from axisopt.identify.records.synth import AxisTruth, simulate_axis

BUDGET = 5.0
DESIGN = Path(__file__).resolve().parents[1] / "problems" / "data" / "table_x.yaml"


def main(samples: int = 25_000) -> None:
    plant = plant_from_design(load_design(DESIGN))
    truth = AxisTruth(mass=650.0, viscous=1500.0, coulomb=450.0, stribeck=120.0, stribeck_v=0.004)
    with tempfile.TemporaryDirectory() as d:
        est, val = Path(d) / "est.csv", Path(d) / "val.csv"
        simulate_axis(truth, duration=samples / 1000.0, seed=1).write_csv(est)
        simulate_axis(truth, duration=12.0, seed=2).write_csv(val)
        t0 = time.perf_counter()
        diag = diagnose_time_files([est, val], plant=plant)
        total = time.perf_counter() - t0
    rows = diag.estimation
    reps = 20
    t0 = time.perf_counter()
    for _ in range(reps):
        ls = least_squares(rows, BASE)
    t_ls = (time.perf_counter() - t0) / reps
    t0 = time.perf_counter()
    iv = instrumental_variables(rows, BASE, ctrl=diag.controller, start=ls)
    t_iv = time.perf_counter() - t0
    print(
        f"{rows.record.n} samples -> {rows.n} regression rows (cut-off {rows.proc.fc:.1f} Hz, "
        f"decimation {rows.proc.nd}); verdict {diag.verdict or 'nothing'}"
    )
    print(
        f"LS {t_ls * 1e3:.1f} ms  IV {t_iv * 1e3:.0f} ms ({iv.iterations} iterations)  IV/LS "
        f"{t_iv / t_ls:.0f}"
    )
    print(
        f"read + identify + diagnose {total:.2f} s  budget {BUDGET:.1f} s  ratio "
        f"{total / BUDGET:.2f}"
    )


def cli(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument(
        "samples",
        nargs="?",
        type=int,
        default=25_000,
        help="samples of the estimation record (25 000)",
    )
    main(ap.parse_args(argv).samples)
    return 0


if __name__ == "__main__":
    raise SystemExit(cli())
