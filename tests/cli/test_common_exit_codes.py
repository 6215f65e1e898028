"""Exit codes of the command line (0 proven optimum, 1 proven infeasible, 2 bad input, 3 unproven,
130 interrupted), kept when stdout is a closed pipe or a full device."""

import os
import subprocess
import sys
from pathlib import Path

import pytest

from axisopt.cli import main
from axisopt.cli.solve import exit_code

ROOT = Path(__file__).resolve().parents[2]
PROBLEMS = ROOT / "problems"


@pytest.mark.parametrize(
    "status, code",
    [("optimal", 0), ("infeasible", 1), ("feasible", 3), ("time_limit", 3), ("solver_failed", 3)],
)
def test_solve_status_maps_to_its_exit_code(status, code):
    assert exit_code(status) == code


@pytest.mark.slow  # over 10 s on an idle core: run by `pytest -m slow`
def test_bonmin_point_is_unproven_exit_3(capsys):
    # Bonmin's branch and bound on this nonconvex MINLP proves nothing: never exit 0 (optimal) or 1
    # (infeasible)
    rc = main(
        [
            "solve",
            str(PROBLEMS / "teaching_problem.yaml"),
            "--method",
            "bonmin",
            "--time-limit",
            "20",
            "--no-sensitivity",
        ]
    )
    out = capsys.readouterr().out
    assert rc == 3 and "bonmin" in out


def test_interrupt_is_130(monkeypatch, capsys):
    import axisopt.cli.evaluate as ev

    def interrupted(args):
        raise KeyboardInterrupt

    monkeypatch.setattr(ev, "cmd_evaluate", interrupted)
    assert main(["evaluate", str(PROBLEMS / "teaching_design.yaml")]) == 130
    assert capsys.readouterr().err.strip() == "interrupted"


def _run(args, stdout):
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    return subprocess.run(
        [sys.executable, "-m", "axisopt", *args],
        stdout=stdout,
        stderr=subprocess.PIPE,
        env=env,
        text=True,
        timeout=120,
    )


@pytest.mark.skipif(not os.path.exists("/dev/full"), reason="no /dev/full on this system")
def test_full_device_keeps_the_code_and_says_so_in_one_line(tmp_path):
    js = tmp_path / "r.json"
    with open("/dev/full", "w") as full:
        r = _run(
            [
                "solve",
                str(PROBLEMS / "infeasible_problem.yaml"),
                "--no-sensitivity",
                "--json",
                str(js),
            ],
            full,
        )
    assert r.returncode == 1, r.stderr  # infeasible, as with a working stdout
    assert "Traceback" not in r.stderr and len(r.stderr.strip().splitlines()) == 1
    assert "No space left" in r.stderr
    assert js.exists()  # the command ran to its end: its other outputs are written


def test_closed_pipe_keeps_the_code_quietly():
    # `axisopt solve infeasible.yaml | head -0`: the reader is gone before the first line is written
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    p = subprocess.Popen(
        [
            sys.executable,
            "-m",
            "axisopt",
            "solve",
            str(PROBLEMS / "infeasible_problem.yaml"),
            "--no-sensitivity",
        ],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        env=env,
    )
    p.stdout.close()
    with p.stderr:
        err = p.stderr.read().decode()
    assert p.wait(timeout=120) == 1 and err.strip() == ""


def test_axisopt_alone_lists_the_commands(capsys):
    """`axisopt` with no command prints the commands and what each does (exit 0), not an argparse
    error."""
    assert main([]) == 0
    out = capsys.readouterr()
    assert out.err == ""
    for command in ("evaluate", "solve", "diagnose", "compare", "study", "parts", "schema", "init"):
        assert f"\n    {command} " in out.out, command
