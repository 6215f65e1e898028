"""Every design of the shipped Pareto front (problems/pareto_problem.yaml) by the part vendors'
procedures (issue 53: every shipped optimum passes the independent check): the front saved with
``solve --save-design DIR``, tools/vendor_check.py on each design, and docs/validation.md's
sentence on it (the number of designs, the lowest vendor margin and its check) compared with what
the checker prints.  Slow: one checker run per design."""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]


@pytest.mark.slow
def test_every_pareto_design_passes_the_vendor_check(tmp_path):
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    out = tmp_path / "front"
    subprocess.run(
        [
            sys.executable,
            "-m",
            "axisopt",
            "solve",
            "problems/pareto_problem.yaml",
            "--no-sensitivity",
            "--save-design",
            str(out),
        ],
        cwd=ROOT,
        env=env,
        check=True,
        capture_output=True,
        text=True,
    )
    designs = sorted(out.glob("*.yaml"))
    lowest = None
    for path in designs:
        js = path.with_suffix(".json")
        subprocess.run(
            [sys.executable, str(ROOT / "tools" / "vendor_check.py"), str(path), "--json", str(js)],
            cwd=ROOT,
            env=env,
            check=True,
            capture_output=True,
            text=True,
        )
        rows = json.loads(js.read_text(encoding="utf-8"))
        assert all(r["passes"] for r in rows), (
            path.name,
            [r["check"] for r in rows if not r["passes"]],
        )
        for r in rows:
            if r["margin"] is not None and (lowest is None or r["margin"] < lowest[0]):
                lowest = (r["margin"], r["check"])
    text = (ROOT / "docs" / "validation.md").read_text(encoding="utf-8")
    m = re.search(
        r"Pareto front \(problems/pareto_problem\.yaml, (\d+) designs\).*?lowest\s+vendor\s+"
        r"margin\s+([\d.]+)\s+\(([^)]+)\)",
        text,
        re.S,
    )
    assert m, "docs/validation.md: no sentence on the Pareto front's check"
    assert int(m.group(1)) == len(designs)
    assert float(m.group(2)) == pytest.approx(lowest[0], abs=0.0051)
    assert m.group(3) == lowest[1]
