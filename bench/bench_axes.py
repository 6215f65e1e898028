"""Wall time of the shipped long, heavy and fast axes, the twin-drive gantry and the counterweighted
vertical Z, and of an infeasible variant of each (a benchmark, not a test; target: each under 2 s).

    python bench/bench_axes.py [--repeat N]

Each case runs as a user runs it: a fresh ``python -m axisopt solve`` process on a problem file (the
variants are the shipped file with one value changed, written to a temporary directory), N times,
interleaved with ``python -c pass`` so that machine load hits all alike.  Prints per case the median
wall time, its ratio to ``python -c pass``, the median CPU time (user + system), the exit code (0: a
design, 1: infeasible and explained) and the search's own time as the solve prints it.

The variants, each infeasible for a reason an engineer would try:

* lathe Z, direct drive forced: ``max_backlash`` 1 um leaves every gearbox out (its backlash at the
  table);
* boring-mill table at 20 m/min rapids instead of 15 (the motors' speed with the gearboxes' ratios);
* laser axis with 150 kg instead of 100 (the direct drives' peak torque at 1.5 g);
* twin-drive gantry at 20 m/min instead of 15 (the 4 m screws' critical speed);
* counterweighted vertical Z with a 600 kg head on the same 250 kg counterweight (the nut's
  lift-off);
* the 600 kg Z's ram at 1200 kg on the same cylinder (the motors' RMS torque).
"""

from __future__ import annotations

import argparse
import os
import re
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PROBLEMS = ROOT / "problems"

# (case, shipped problem, None or (the line's key, its value in the variant))
CASES = (
    ("boring-mill table", "boring_mill_problem.yaml", None),
    ("laser axis", "laser_problem.yaml", None),
    ("lathe Z", "lathe_z_problem.yaml", None),
    ("boring-mill table at 20 m/min", "boring_mill_problem.yaml", ("max_speed", "20 m/min")),
    ("laser axis with 150 kg", "laser_problem.yaml", ("moving_mass", "150 kg")),
    ("lathe Z, max_backlash 1 um", "lathe_z_problem.yaml", ("max_backlash", "1 um")),
    # issue 40's arrangements: the twin-drive gantry and the counterweighted vertical Z
    ("twin-drive gantry", "gantry_twin_problem.yaml", None),
    ("vertical Z, counterweight", "vertical_counterweight_problem.yaml", None),
    ("vertical Z 600 kg, cylinder", "vertical_z600_problem.yaml", None),
    ("twin-drive gantry at 20 m/min", "gantry_twin_problem.yaml", ("max_speed", "20 m/min")),
    ("vertical Z, 600 kg head", "vertical_counterweight_problem.yaml", ("moving_mass", "600 kg")),
    (
        "vertical Z, 1200 kg ram, same cylinder",
        "vertical_z600_problem.yaml",
        ("moving_mass", "1200 kg"),
    ),
)


def variant(src: Path, change, out_dir: Path) -> Path:
    """The shipped problem with the value of one key's line changed (the line must exist once)."""
    if change is None:
        return src
    key, value = change
    text = src.read_text(encoding="utf-8")
    pattern = re.compile(rf"^(\s*{re.escape(key)}:\s*)([^#\n]*?)(\s*(#.*)?)$", re.M)
    if len(pattern.findall(text)) != 1:
        raise SystemExit(f"{src.name}: expected one line with key {key}")
    path = out_dir / f"{src.stem}_{key}.yaml"
    path.write_text(pattern.sub(lambda m: m.group(1) + value + m.group(3), text), encoding="utf-8")
    return path


def run(args) -> tuple[float, float, int, str]:
    """(wall s, CPU s of the child, exit code, the solve's own time as printed) of one fresh
    process."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    proc = subprocess.run(
        [sys.executable, *args],
        cwd=ROOT,
        capture_output=True,
        text=True,
        env={**os.environ, "PYTHONPATH": str(ROOT)},
    )
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    m = re.search(r"^method \S+: status [^,]*(?:\([^)]*\))?, ([0-9.]+) s", proc.stdout, re.M)
    return wall, cpu, proc.returncode, (m.group(1) + " s") if m else "-"


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=3, help="runs of each case (median)")
    a = ap.parse_args(argv)
    with tempfile.TemporaryDirectory() as d:
        files = [(name, variant(PROBLEMS / src, change, Path(d))) for name, src, change in CASES]
        # one untimed run each: compiled modules written, as on a user's machine
        for _, path in files:
            run(["-m", "axisopt", "solve", str(path)])
        base, rows = [], {name: [] for name, _ in files}
        for _ in range(a.repeat):
            base.append(run(["-c", "pass"])[0])
            for name, path in files:
                rows[name].append(run(["-m", "axisopt", "solve", str(path)]))
    ref = statistics.median(base)
    print(f"python -c pass: {ref:.3f} s (median of {a.repeat})")
    print(f"{'case':<40}{'wall s':>8}{'x pass':>8}{'CPU s':>8}{'exit':>6}  search (as printed)")
    for name, _ in files:
        r = rows[name]
        wall = statistics.median(x[0] for x in r)
        cpu = statistics.median(x[1] for x in r)
        print(f"{name:<40}{wall:8.2f}{wall / ref:8.1f}{cpu:8.2f}{r[-1][2]:6d}  {r[-1][3]}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
