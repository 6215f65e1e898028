"""The same defaults in Python and on the command line (issue 57:
``axisopt.diagnose(max_effects=2)`` against ``--max-effects 3``), and the options the user missed:
``--time-limit`` on study and compare, ``--overwrite`` on study."""

from __future__ import annotations

import inspect
from pathlib import Path

import pytest
from cli_helpers import one_line_error

import axisopt
from axisopt.cli import build_parser, main

ROOT = Path(__file__).resolve().parents[2]

# (Python function, its parameter, command, option)
PAIRS = [
    (axisopt.solve, "method", "solve", "method"),
    (axisopt.solve, "top", "solve", "top"),
    (axisopt.solve, "time_limit", "solve", "time_limit"),
    (axisopt.compare, "time_limit", "compare", "time_limit"),
    (axisopt.compare, "method", "solve", "method"),
    (axisopt.diagnose, "max_effects", "diagnose", "max_effects"),
    (axisopt.api.study, "time_limit", "study", "time_limit"),
]


def _defaults(command: str) -> dict:
    sub = next(
        a for a in build_parser()._actions if getattr(a, "choices", None) and command in a.choices
    )
    return {a.dest: a.default for a in sub.choices[command]._actions}


@pytest.mark.parametrize("fn, param, command, dest", PAIRS)
def test_python_and_command_line_defaults_agree(fn, param, command, dest):
    assert inspect.signature(fn).parameters[param].default == _defaults(command)[dest]


def test_the_identify_pipelines_take_the_same_default():
    from axisopt.identify.records.idim import diagnose_time_files
    from axisopt.identify.tables.diagnose import MAX_EFFECTS, diagnose

    assert inspect.signature(diagnose).parameters["max_effects"].default == MAX_EFFECTS
    assert inspect.signature(diagnose_time_files).parameters["max_effects"].default == MAX_EFFECTS
    assert _defaults("diagnose")["max_effects"] == MAX_EFFECTS


def _spy(monkeypatch):
    """The solve the study and compare commands call, recording the time limit they pass."""
    import axisopt.search as search

    seen = []
    real = search.solve

    def spy(*a, **k):
        seen.append(k.get("time_limit"))
        return real(*a, **k)

    monkeypatch.setattr(search, "solve", spy)
    return seen


def test_compare_time_limit_reaches_the_solve(monkeypatch, capsys):
    seen = _spy(monkeypatch)
    assert (
        main(["compare", str(ROOT / "problems" / "teaching_problem.yaml"), "--time-limit", "42"])
        == 0
    )
    assert seen == [42.0]
    assert (
        main(["compare", str(ROOT / "problems" / "teaching_problem.yaml"), "--time-limit", "0"])
        == 2
    )
    assert "--time-limit must be positive" in one_line_error(capsys)


def test_study_time_limit_and_overwrite(monkeypatch, tmp_path, capsys):
    from axisopt.study import load_study

    f = tmp_path / "s.yaml"
    f.write_text(
        "name: tiny\nbase: "
        + str(ROOT / "problems" / "teaching_problem.yaml")
        + "\nsweep:\n  axis.stroke: [400 mm, 450 mm]\n",
        encoding="utf-8",
    )
    assert len(load_study(f).cases) == 2
    seen = _spy(monkeypatch)
    out = str(tmp_path / "out")
    argv = ["study", str(f), "--out", out, "--workers", "0", "--quiet"]
    assert main(argv + ["--time-limit", "37"]) == 0
    assert seen == [37.0, 37.0]
    assert main(argv) == 2  # results there: --resume or --overwrite
    assert "--overwrite to solve it again" in one_line_error(capsys)
    seen.clear()
    assert main(argv + ["--overwrite"]) == 0
    assert seen == [100.0, 100.0]  # solved again, at the default limit
    assert main(argv + ["--overwrite", "--resume"]) == 2
    assert "give one of them" in one_line_error(capsys)
