"""Every text output of the shipped files fits 100 columns (issue 42): each problem solved (the
default command without the sensitivities' re-solves, which print no lines of their own but the
limit table, checked on the teaching problem and the infeasible one with its advice), each design
evaluated."""

from __future__ import annotations

from pathlib import Path

import pytest

from axisopt.cli import main

ROOT = Path(__file__).resolve().parents[2] / "problems"
PROBLEMS = sorted(ROOT.glob("*_problem.yaml"))
DESIGNS = sorted(ROOT.glob("*_design.yaml"))
WIDTH = 100


def _wide(out: str) -> list:
    return [f"{len(ln)}: {ln}" for ln in out.splitlines() if len(ln) > WIDTH]


@pytest.mark.parametrize("path", PROBLEMS, ids=[p.stem for p in PROBLEMS])
def test_solve_text_fits(path, capsys):
    """... and every shipped problem but the two infeasible examples has a design (exit 0)."""
    rc = main(["solve", str(path), "--top", "3", "--no-sensitivity"])
    assert not _wide(capsys.readouterr().out)
    assert rc == (1 if path.stem.startswith("infeasible") else 0)


@pytest.mark.parametrize("name", ["teaching_problem.yaml", "infeasible_problem.yaml"])
def test_solve_with_sensitivities_and_advice_fits(name, capsys):
    main(["solve", str(ROOT / name)])
    assert not _wide(capsys.readouterr().out)


@pytest.mark.parametrize("path", DESIGNS, ids=[p.stem for p in DESIGNS])
def test_evaluate_text_fits(path, capsys):
    assert main(["evaluate", str(path)]) == 0
    assert not _wide(capsys.readouterr().out)


def test_a_gain_within_tolerance_reads_plus_zero():
    """A limit that does not bind shows '+0', not a rounding residue such as '+1.421e-14' (issue
    42)."""
    from dataclasses import replace

    from axisopt.problem import load_problem
    from axisopt.search import solve

    res = solve(load_problem(ROOT / "teaching_problem.yaml"))
    loose = next(b for b in res.binding if not b.binding)
    text = repr(replace(loose, objective_gain=1.421e-14))
    assert "changes by +0" in text and "e-14" not in text
