"""The README against what its commands print.

1. Every fenced block that starts with ``$ axisopt ...`` is run; each quoted line must appear in the output,
   in order (a line ``...`` skips output; a line ending in ``...`` matches a line it starts).
2. The Python example is run and the values the README says it prints are compared.
3. Figures quoted in the prose (deterministic ones: optima, sensitivities, diagnosis results) are compared
   with the command's output to the precision the README quotes them.

Timings and fuzz counts are not deterministic and are not checked here (bench/ prints them).
"""

from __future__ import annotations

import contextlib
import io
import os
import re
import shlex
from pathlib import Path

import pytest

from axisopt.cli import main

ROOT = Path(__file__).resolve().parents[2]
README = (ROOT / "README.md").read_text(encoding="utf-8")


def _blocks():
    """(first line number, command, quoted lines) of every ``$ axisopt`` block."""
    out = []
    for m in re.finditer(r"^```[a-z]*\n(\$ axisopt[^\n]*)\n(.*?)^```", README, flags=re.M | re.S):
        line = README[:m.start()].count("\n") + 2
        out.append((line, m.group(1)[2:], m.group(2).splitlines()))
    return out


@contextlib.contextmanager
def _in_scratch(tmp_path):
    """Run in an empty directory with ``problems`` linked in, so outputs the README names land in tmp."""
    (tmp_path / "problems").symlink_to(ROOT / "problems")
    old = os.getcwd()
    os.chdir(tmp_path)
    try:
        yield
    finally:
        os.chdir(old)


def _run(cmd: str, tmp_path) -> tuple[int, str]:
    argv = shlex.split(cmd)
    assert argv[0] == "axisopt"
    buf = io.StringIO()
    with _in_scratch(tmp_path), contextlib.redirect_stdout(buf):
        rc = main(argv[1:])
    return rc, buf.getvalue()


BLOCKS = _blocks()


def test_readme_has_command_blocks():
    assert BLOCKS, "no '$ axisopt' block found in README.md"


@pytest.mark.parametrize("line, cmd, quoted", BLOCKS, ids=[f"README:{b[0]}" for b in BLOCKS])
def test_quoted_output_matches(line, cmd, quoted, tmp_path):
    rc, out = _run(cmd, tmp_path)
    got = [ln.rstrip() for ln in out.splitlines()]
    i = 0
    for q in quoted:
        q = q.rstrip()
        if q.strip() in ("", "..."):
            continue
        prefix = q.endswith("...")
        want = q[:-3] if prefix else q
        while i < len(got) and not (got[i].startswith(want) if prefix else got[i] == want):
            i += 1
        assert i < len(got), f"README line quoted under '{cmd}' not in its output (in order): {q!r}"
        i += 1


def test_python_example_prints_what_the_readme_says(tmp_path):
    code = re.search(r"```python\n(import numpy as np\nfrom axisopt.design import load_design.*?)```", README,
                     flags=re.S).group(1)
    said = re.search(r"prints `([^`]*)`, `([^`]*)` and\s+`([^`]*)`", README)
    assert said, "the sentence after the Python example changed form"
    buf = io.StringIO()
    with _in_scratch(tmp_path), contextlib.redirect_stdout(buf):
        exec(compile(code, "README.md", "exec"), {})
    lines = buf.getvalue().splitlines()
    assert lines == [said.group(1), said.group(2), said.group(3)]


def _close(readme_value: str, printed: str) -> bool:
    """``printed`` rounded to the decimals ``readme_value`` shows."""
    decimals = len(readme_value.split(".")[1]) if "." in readme_value else 0
    return round(float(printed), decimals) == float(readme_value)


# (command, regex on the README prose, regex on the output): each group pair is one figure
FIGURES = [
    ("axisopt solve problems/teaching_problem.yaml",
     r"raising max drag torque to ([\d.]+) N\.m buys \+([\d.]+) N/um\" on the teaching problem",
     r"raising max drag torque to ([\d.]+) N\.m buys \+([\d.]+) N/um"),
    ("axisopt diagnose problems/data/table_x_stiffness.csv --design problems/data/table_x.yaml",
     r"`support_condition` wins \(dBIC (-[\d.]+), held-out gain (\d+) %\)",
     r"support_condition\s+(-[\d.]+)\s+held-out gain (\d+) %"),
    ("axisopt diagnose problems/data/table_x_stiffness.csv --design problems/data/table_x.yaml",
     r"carrying ([\d.]+) ± ([\d.]+) N/um",
     r"far_end_stiffness = ([\d.]+) ± ([\d.]+) N/um"),
    ("axisopt diagnose problems/data/table_x_stiffness.csv --design problems/data/table_x.yaml "
     "--save-calibration cal.yaml",
     r"modulus comes back to ([\d.]+) ±",
     r"screw modulus ([\d.]+) GPa applied"),
    ("axisopt diagnose problems/data/table_x_stiffness.csv --design problems/data/table_x.yaml",
     r"Held-out RMSE falls from ([\d.]+) um to\s+([\d.]+) um",
     r"held-out RMSE \S+: ([\d.]+) -> ([\d.]+) um(?s:.*)"),
    ("axisopt diagnose problems/data/xjtu/xjtu_up_friction.csv --design problems/data/xjtu/xjtu_rig.yaml",
     r"friction falls ([\d.]+) ± ([\d.]+) % of its initial value per 35 h",
     r"preload_loss_rate = ([\d.]+) ± ([\d.]+) percent"),
    ("axisopt diagnose problems/data/xjtu/xjtu_up_friction.csv --design problems/data/xjtu/xjtu_rig.yaml",
     r"held-out RMSE ([\d.]+) -> ([\d.]+) N.m over held-out cycles \(gain (\d+) %\)",
     r"(?s:.*)held-out RMSE \S+: [\d.]+ -> [\d.]+ N \(gain \d+ %\); ([\d.]+) -> ([\d.]+) N.m at the screw"),
    ("axisopt diagnose problems/data/table_x_run_est.csv problems/data/table_x_run_val.csv "
     "--design problems/data/table_x.yaml",
     r"The IV fit gives Fs - Fc = ([\d.]+) ± ([\d.]+) N and vs = ([\d.]+) mm/s",
     r"final fit(?s:.*)Fs\s+([\d.]+) ± ([\d.]+) N(?s:.*)vs\s+([\d.]+) mm/s"),
    ("axisopt diagnose problems/data/table_x_run_est.csv problems/data/table_x_run_val.csv "
     "--design problems/data/table_x.yaml",
     r"`stribeck` wins: dBIC (-[\d.]+), validation gain (\d+) %",
     r"stribeck\s+dBIC\s+(-[\d.]+)\s+gain\s+([\d.]+) %"),
    ("axisopt diagnose problems/data/xjtu/xjtu_down_friction.csv --design problems/data/xjtu/xjtu_rig.yaml",
     r"The 'down' screw gives ([\d.]+) % per cycle \(gain (\d+) %\)",
     r"preload_loss_rate = ([\d.]+) ±(?s:.*)held-out RMSE \S+: [\d.]+ -> [\d.]+ N \(gain (\d+) %\)"),
]


@pytest.mark.parametrize("cmd, in_readme, in_output", FIGURES, ids=[f"figure{i}" for i in range(len(FIGURES))])
def test_quoted_figures_match(cmd, in_readme, in_output, tmp_path):
    r = re.search(in_readme, " ".join(README.split()) if "\\s" not in in_readme else README)
    assert r, f"README no longer quotes /{in_readme}/"
    _, out = _run(cmd, tmp_path)
    o = re.search(in_output, out)
    assert o, f"'{cmd}' no longer prints /{in_output}/"
    for a, b in zip(r.groups(), o.groups()):
        assert _close(a, b), f"README says {a}, '{cmd}' prints {b}"


def test_noise_floor_quoted(tmp_path):
    r = re.search(r"at the ([\d.]+) um noise floor", " ".join(README.split()))
    _, out = _run("axisopt diagnose problems/data/table_x_stiffness.csv --design problems/data/table_x.yaml",
                  tmp_path)
    o = re.search(r"noise floor ([\d.]+) um", out)
    assert r and o and _close(r.group(1), o.group(1))


def test_test_files_have_unique_basenames():
    """pytest's default import mode keys test modules by basename: two tests/*/test_x.py break collection
    (it did once, in CI only, where no __pycache__ hid it)."""
    root = Path(__file__).resolve().parents[1]
    names = [p.name for p in root.rglob("*.py") if p.name != "__init__.py"]
    assert len(names) == len(set(names)), sorted({n for n in names if names.count(n) > 1})
