"""Benchmark: diagnose a 10 000-row static stiffness test (budget 5 s).  Prints the time and its
ratio to the budget.  ``python bench/bench_diagnose.py [rows]``; not run as a test."""

import argparse
import time
from pathlib import Path

import numpy as np

from axisopt.design import load_design
from axisopt.identify import diagnose, plant_from_design
from axisopt.identify.tables.synth import simulate

BUDGET = 5.0
DESIGN = Path(__file__).resolve().parents[1] / "problems" / "data" / "table_x.yaml"


def main(rows: int = 10_000) -> None:
    plant = plant_from_design(load_design(DESIGN))
    rng = np.random.default_rng(0)
    pos = rng.choice(np.linspace(0.0, 0.8, 9), rows)
    force = rng.choice([-4000.0, -3000.0, -2000.0, -1000.0, 1000.0, 2000.0, 3000.0, 4000.0], rows)
    direction = rng.choice([-1.0, 1.0], rows)
    t = np.arange(rows) * 2.0
    temp = 293.15 + 2.0 * (1.0 - np.exp(-t / t[-1] * 3.0))
    cycle = np.floor(np.arange(rows) / (rows / 10))
    cols = dict(
        position=pos, force=force, direction=direction, time=t, temperature=temp, cycle=cycle
    )
    ds = simulate(
        plant,
        "stiffness",
        cols,
        effects={"backlash": {"backlash": 6e-6}},
        baseline={"screw_modulus": 200e9},
        noise=0.015,
        seed=1,
    )
    t0 = time.perf_counter()
    diag = diagnose([ds], plant)
    dt = time.perf_counter() - t0
    print(
        f"diagnose {rows} rows, {len(diag.rounds[0])} candidates, verdict {diag.verdict}, "
        f"gain {diag.gain:.0f} %"
    )
    print(f"time {dt:.2f} s  budget {BUDGET:.1f} s  ratio {dt / BUDGET:.2f}")


def cli(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument(
        "rows", nargs="?", type=int, default=10_000, help="rows of the synthetic test (10 000)"
    )
    main(ap.parse_args(argv).rows)
    return 0


if __name__ == "__main__":
    raise SystemExit(cli())
