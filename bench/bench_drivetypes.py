"""Scaling benchmark of the drive-type search (not a test): the router problem's axis with synthetic
rack-and-pinion sets, reductions, motors and guides at about 10^7, 10^8 and 10^9 rack combinations
(and the shipped linear motors), solved by the default method (bounded best-first,
:mod:`axisopt.search.drivebest`); prints combinations, solve time, and the best design.
``--exhaustive-check`` compares the smallest size with the exhaustive method (every combination
evaluated).

    python bench/bench_drivetypes.py [--sizes 1e7 1e8 1e9] [--exhaustive-check]
"""

from __future__ import annotations

import argparse
import sys
import time
from dataclasses import replace
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from axisopt.drivecatalog import DriveTables  # noqa: E402
from axisopt.problem import load_problem  # noqa: E402
from axisopt.search.drivetype import solve_drive_types  # noqa: E402

# racks x reductions x motors x twin (2) x guides
SHAPES = {1e7: (40, 40, 40, 2, 80), 1e8: (80, 80, 80, 2, 100), 1e9: (160, 150, 160, 2, 130)}


def part_tables(problem, shape, rng):
    n_rack, n_red, n_mot, _, n_guide = shape
    racks = []
    for i in range(n_rack):
        d = rng.uniform(0.03, 0.12)
        racks.append(
            {
                "id": f"R{i}",
                "kind": "helical",
                "quality": 6.0,
                "module": d / 20,
                "teeth": 20.0,
                "helix_angle": 0.34,
                "pitch_diameter": d,
                "face_width": rng.uniform(0.015, 0.06),
                "permissible_force": rng.uniform(1e3, 3e4),
                "pitch_error": rng.uniform(1e-5, 6e-5),
                "pinion_price": rng.uniform(50, 500),
                "rack_price_per_length": rng.uniform(80, 600),
                "rack_mass_per_length": 4.0,
                "estimated": [],
            }
        )
    cat = problem.catalog

    def grow(name, n):
        t = cat.rows(name)
        idx = rng.integers(0, len(t), n)
        out = {c: np.asarray(t[c])[idx] for c in t.columns}
        for c in out:
            if out[c].dtype.kind == "f":
                out[c] = out[c] * rng.uniform(0.8, 1.25, n)
        out["id"] = np.array([f"{name[:3]}{i}" for i in range(n)])
        return out

    return tuple(racks), grow("reductions", n_red), grow("motors", n_mot), grow("guides", n_guide)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("--sizes", nargs="*", type=float, default=[1e7, 1e8, 1e9])
    ap.add_argument("--exhaustive-check", action="store_true")
    args = ap.parse_args(argv)
    base = load_problem(ROOT / "problems" / "router_rack_problem.yaml")
    import axisopt.search.drivetype as dt

    print(f"{'size':>6s} {'combinations':>14s} {'time s':>8s}  best")
    for size in args.sizes:
        rng = np.random.default_rng(int(size) % 1000)
        racks, red, mot, gd = part_tables(base, SHAPES[size], rng)
        prob = replace(
            base,
            drives=replace(
                base.drives, tables=DriveTables(racks, base.drives.tables.linear_motors)
            ),
        )
        orig = dt.part_tables
        dt.part_tables = lambda _p, t=(red, mot, gd): tuple(_Table(x) for x in t)  # synthetic parts
        try:
            t0 = time.perf_counter()
            res = solve_drive_types(prob, "default", top=1)
            t = time.perf_counter() - t0
            n = sum(x.combinations for x in res.types)
            best = (
                ""
                if res.best is None
                else f"{res.best.objective:.6g} {res.objective_unit} {res.best.parts}"
            )
            print(f"{size:6.0e} {n:14,d} {t:8.2f}  {best}")
            if args.exhaustive_check and size == min(args.sizes):
                ex = solve_drive_types(prob, "exhaustive", top=1)
                same = (ex.best is None) == (res.best is None) and (
                    ex.best is None or ex.best.parts == res.best.parts
                )
                print(f"       exhaustive agrees: {same}")
        finally:
            dt.part_tables = orig
    return 0


class _Table:
    """A dict of arrays with the PartTable access the drive-type spaces use."""

    def __init__(self, cols):
        self.cols = cols
        self.columns = list(cols)

    def __getitem__(self, c):
        return self.cols[c]


if __name__ == "__main__":
    sys.exit(main())
