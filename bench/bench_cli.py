"""Wall time of common commands against ``python -c pass`` (a benchmark, not a test).

    python bench/bench_cli.py [--repeat N]

Runs each command as a user does (a fresh ``python -m axisopt`` process, output discarded), N times each,
interleaved with ``python -c pass`` so that machine load hits both alike; prints the median wall time of each,
its ratio to the reference, and which heavy libraries the command imports (``-X importtime``)."""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
COMMANDS = {
    "python -c pass": ["-c", "pass"],
    "axisopt --help": ["-m", "axisopt", "--help"],
    "axisopt solve problems/teaching_problem.yaml": ["-m", "axisopt", "solve", "problems/teaching_problem.yaml"],
    "axisopt evaluate problems/teaching_design.yaml": ["-m", "axisopt", "evaluate",
                                                       "problems/teaching_design.yaml"],
    "axisopt parts screws": ["-m", "axisopt", "parts", "screws"],
}
HEAVY = ("pint", "pandas", "pyarrow", "matplotlib", "scipy", "casadi", "dask", "plotly")


def _run(args, env) -> float:
    t = time.perf_counter()
    subprocess.run([sys.executable, *args], cwd=ROOT, env=env, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL)
    return time.perf_counter() - t


def _imports(args, env) -> str:
    err = subprocess.run([sys.executable, "-X", "importtime", *args], cwd=ROOT, env=env, capture_output=True,
                         text=True).stderr
    mods = {line.rsplit("|", 1)[-1].strip() for line in err.splitlines() if line.startswith("import time:")}
    return " ".join(h for h in HEAVY if h in mods) or "-"


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=5, help="runs of each command (5)")
    args = ap.parse_args(argv)
    env = dict(os.environ, PYTHONPATH=str(ROOT), AXISOPT_COLOR="never")
    times = {k: [] for k in COMMANDS}
    for _ in range(args.repeat):
        for name, cmd in COMMANDS.items():
            times[name].append(_run(cmd, env))
    ref = statistics.median(times["python -c pass"])
    print(f"{'command':<50}{'median s':>10}{'min s':>8}{'/ pass':>8}  heavy imports")
    for name, cmd in COMMANDS.items():
        med = statistics.median(times[name])
        print(f"{name:<50}{med:>10.3f}{min(times[name]):>8.3f}{med / ref:>8.1f}  {_imports(cmd, env)}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
