"""Wall time of common commands against ``python -c pass`` (a benchmark, not a test).

    python bench/bench_cli.py [--repeat N]

Runs each command as a user does (a fresh ``python -m axisopt`` process, output discarded), N times
each, interleaved with ``python -c pass`` and ``python -c "import numpy"`` so that machine load hits
all alike; prints the median wall time of each (after one untimed run that writes the compiled
modules, as a user's machine keeps them), its ratios to both references, the median CPU time (user +
system, less affected by other processes on a loaded machine) and which heavy libraries the command
imports (``-X importtime``).

Targets (issue 29): ``solve problems/teaching_problem.yaml`` < 0.6 s and ``parts screws`` < 0.4 s
wall on an idle machine."""

from __future__ import annotations

import argparse
import os
import resource
import statistics
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
COMMANDS = {
    "python -c pass": ["-c", "pass"],
    'python -c "import numpy"': ["-c", "import numpy"],
    "axisopt --help": ["-m", "axisopt", "--help"],
    "axisopt solve problems/teaching_problem.yaml": [
        "-m",
        "axisopt",
        "solve",
        "problems/teaching_problem.yaml",
    ],
    "axisopt evaluate problems/teaching_design.yaml": [
        "-m",
        "axisopt",
        "evaluate",
        "problems/teaching_design.yaml",
    ],
    "axisopt parts screws": ["-m", "axisopt", "parts", "screws"],
}
HEAVY = ("numpy", "pint", "pandas", "pyarrow", "matplotlib", "scipy", "casadi", "dask", "plotly")


def _cpu() -> float:
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def _run(args, env) -> tuple[float, float]:
    """(wall, CPU) seconds of one run."""
    c, t = _cpu(), time.perf_counter()
    subprocess.run(
        [sys.executable, *args],
        cwd=ROOT,
        env=env,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
    )
    return time.perf_counter() - t, _cpu() - c


def _imports(args, env) -> str:
    err = subprocess.run(
        [sys.executable, "-X", "importtime", *args],
        cwd=ROOT,
        env=env,
        capture_output=True,
        text=True,
    ).stderr
    mods = {
        line.rsplit("|", 1)[-1].strip()
        for line in err.splitlines()
        if line.startswith("import time:")
    }
    return " ".join(h for h in HEAVY if h in mods) or "-"


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=5, help="runs of each command (5)")
    args = ap.parse_args(argv)
    env = dict(os.environ, PYTHONPATH=str(ROOT), AXISOPT_COLOR="never")
    # as on a user's machine: Python keeps the compiled modules (some sandboxes set
    # PYTHONDONTWRITEBYTECODE, and then every run compiles axisopt's modules again, about 0.09 s);
    # one untimed run of each writes them
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    for cmd in COMMANDS.values():
        _run(cmd, env)
    times = {k: [] for k in COMMANDS}
    cpu = {k: [] for k in COMMANDS}
    for _ in range(args.repeat):
        for name, cmd in COMMANDS.items():
            wall, used = _run(cmd, env)
            times[name].append(wall)
            cpu[name].append(used)
    ref = statistics.median(times["python -c pass"])
    ref_np = statistics.median(times['python -c "import numpy"'])
    print(
        f"{'command':<48}{'median s':>9}{'min s':>7}{'CPU s':>7}{'/ pass':>8}{'/ numpy':>8}  heavy "
        "imports"
    )
    for name, cmd in COMMANDS.items():
        med = statistics.median(times[name])
        print(
            f"{name:<48}{med:>9.3f}{min(times[name]):>7.3f}{statistics.median(cpu[name]):>7.3f}"
            f"{med / ref:>8.1f}"
            f"{med / ref_np:>8.2f}  {_imports(cmd, env)}"
        )
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
