"""CPU time of the issue-54 axes (not a test): the 6 m twin-drive router, the 1.5 g laser axis, the
belt lathe Z and the 2 t boring table, each solved as `axisopt solve` does (sensitivities, the
cheaper design, the default offer of other drive types), and an infeasible variant of each; each in
its own process, its CPU time (user + system, the process and its children) and wall time, with the
answer's first status line.

    python bench/bench_drive_axes.py [--only NAME ...]

The infeasible variants: the shipped ones for the router and the laser, the lathe at a 500 EUR
budget and the boring table at 45 m/min rapids (written to a temporary directory).
"""

from __future__ import annotations

import argparse
import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PROBLEMS = ROOT / "problems"
# the wall-clock time limit of each solve [s]: far above the CPU time, so that a loaded machine (the
# shared cores) does not cut the sensitivities or the advice and the CPU time counts all the work
TIME_LIMIT = 3000


def _variant(src: Path, old: str, new: str, out: Path) -> Path:
    text = src.read_text(encoding="utf-8")
    if old not in text:
        raise SystemExit(f"{src.name}: '{old}' not found; update bench/bench_drive_axes.py")
    out.write_text(text.replace(old, new, 1), encoding="utf-8")
    return out


def cases(tmp: Path) -> list:
    lathe = PROBLEMS / "lathe_z_belt_problem.yaml"
    boring = PROBLEMS / "boring_table_problem.yaml"
    return [
        ("router", PROBLEMS / "router_rack_problem.yaml"),
        ("router infeasible", PROBLEMS / "infeasible_router_rack_problem.yaml"),
        ("laser", PROBLEMS / "laser_lm_problem.yaml"),
        ("laser infeasible", PROBLEMS / "infeasible_laser_lm_problem.yaml"),
        ("lathe Z belt", lathe),
        (
            "lathe Z 500 EUR",
            _variant(lathe, "limits:\n", "limits:\n  max_cost: 500 EUR\n", tmp / "lathe.yaml"),
        ),
        ("boring table", boring),
        (
            "boring 45 m/min",
            _variant(boring, "max_speed: 20 m/min", "max_speed: 45 m/min", tmp / "boring.yaml"),
        ),
    ]


def run(path: Path) -> tuple:
    """(CPU s, wall s, first status line) of `axisopt solve path` in its own process."""
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    proc = subprocess.run(
        [sys.executable, "-m", "axisopt", "solve", str(path), "--time-limit", str(TIME_LIMIT)],
        capture_output=True,
        text=True,
        env=env,
        cwd=str(ROOT),
    )
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    lines = [ln for ln in proc.stdout.splitlines() if "status" in ln]
    return cpu, wall, (lines[0] if lines else proc.stderr.strip()[:80]).strip()


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--only", nargs="+", metavar="NAME", help="cases whose name holds one of these")
    args = ap.parse_args(argv)
    with tempfile.TemporaryDirectory() as d:
        todo = cases(Path(d))
        if args.only:
            todo = [(n, p) for n, p in todo if any(o in n for o in args.only)]
        print(f"{'axis':20s} {'CPU s':>7s} {'wall s':>7s}  answer")
        for name, path in todo:
            cpu, wall, status = run(path)
            print(f"{name:20s} {cpu:7.2f} {wall:7.2f}  {status[:90]}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
