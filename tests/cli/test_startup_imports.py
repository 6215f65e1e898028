"""What the command line imports on its common paths: the heavy libraries only where the command
needs them.

Start-up time is measured in bench/bench_cli.py; this guards the cause of a slow start so it cannot
creep back: ``parts`` lists plain catalog records (no pandas, no numpy), ``solve`` and ``evaluate``
read the catalogs into pandas-free part tables, build no unit registry and draw nothing (no pandas,
pint, matplotlib, plotly, dask, rich when stdout is not a terminal)."""

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
PROBE = (
    "pint",
    "pandas",
    "pyarrow",
    "numpy",
    "casadi",
    "matplotlib",
    "plotly",
    "dask",
    "rich",
    "scipy",
)
# command -> libraries it must not import
NOT_IMPORTED = {
    ("--help",): set(PROBE),
    ("parts",): set(PROBE),
    ("parts", "screws"): set(PROBE),
    ("parts", "nuts", "--fits", "HIWIN-G-40x20-b6p35", "--json", "-"): set(PROBE),
    ("solve", "problems/teaching_problem.yaml"): {
        "pint",
        "pandas",
        "pyarrow",
        "matplotlib",
        "plotly",
        "dask",
        "rich",
        "scipy",
    },
    ("evaluate", "problems/teaching_design.yaml"): {
        "pint",
        "pandas",
        "pyarrow",
        "matplotlib",
        "plotly",
        "dask",
        "rich",
        "scipy",
    },
}
_SCRIPT = """
import contextlib, io, json, sys
from axisopt.cli import main
with contextlib.redirect_stdout(io.StringIO()):
    try:
        code = main(sys.argv[1:])
    except SystemExit as exc:  # --help
        code = exc.code
print(json.dumps([code, sorted({m.split('.')[0] for m in sys.modules})]))
"""


@pytest.mark.parametrize("argv", list(NOT_IMPORTED), ids=" ".join)
def test_command_imports_only_what_it_needs(argv):
    env = dict(os.environ, PYTHONPATH=str(ROOT), AXISOPT_COLOR="never")
    p = subprocess.run(
        [sys.executable, "-c", _SCRIPT, *argv],
        cwd=ROOT,
        env=env,
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert p.returncode == 0, p.stderr
    code, modules = json.loads(p.stdout.splitlines()[-1])
    assert code == 0
    assert "axisopt" in modules  # the probe did run the command
    heavy = sorted(NOT_IMPORTED[argv] & set(modules))
    assert not heavy, f"{' '.join(argv)} imports {heavy}"
