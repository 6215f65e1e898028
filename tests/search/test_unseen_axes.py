"""Axes written outside the project (issue 52): each answers with its status and exit code, no traceback.

The files are in tests/search/unseen/: the fixed-fixed screw with ``end_margin: 0 mm`` (the nut reaches the far
bearing: the screw's stiffness there divided by zero in the positioning budget), the coupling filter that leaves
no coupling for any motor's peak torque (a valid infeasible problem, not an input error), and the slowest
problems of bench/axis_generator.py (their times are measured in bench/bench_generalize.py, not here)."""

import json
from pathlib import Path

import numpy as np
import pytest

from axisopt.cli import main
from axisopt.physics import screw as ps

HERE = Path(__file__).resolve().parent / "unseen"


def _solve(tmp_path, name, *extra, advice=False):
    out = tmp_path / "r.json"
    rc = main(["solve", str(HERE / name), "--json", str(out), *(() if advice else ("--no-sensitivity",)), *extra])
    return rc, json.loads(out.read_text())


def test_fixed_fixed_screw_is_rigid_at_its_bearing():
    """x (L - x) = 0 at the far bearing: a finite stiffness far above the mid-span one, on floats and arrays."""
    d_r, span = 0.02, 0.8
    k_end = ps.screw_stiffness(d_r, span, span, "fixed-fixed")
    k_mid = ps.screw_stiffness(d_r, span / 2, span, "fixed-fixed")
    assert np.isfinite(k_end) and k_end > 1e6 * k_mid
    ks = ps.screw_stiffness(d_r, np.array([0.1, span]), span, "fixed-fixed")
    assert np.all(np.isfinite(ks))
    # away from the bearing the formula is THK's A E L / (a b) unchanged
    ea = ps.E_STEEL * np.pi * d_r**2 / 4
    assert ps.screw_stiffness(d_r, 0.2, span, "fixed-fixed") == pytest.approx(ea * span / (0.2 * 0.6))


def test_end_margin_zero_infeasible_answers(tmp_path, capsys):
    rc, r = _solve(tmp_path, "fixed_fixed_end_margin0.yaml")
    assert rc == 1 and r["status"] == "infeasible"
    text = capsys.readouterr().out
    assert "closest designs" in text and "Traceback" not in text


def test_end_margin_zero_feasible_design(tmp_path):
    """A lighter axis with the nut reaching the bearing has a design, its stiffness finite."""
    rc, r = _solve(tmp_path, "fixed_fixed_end_margin0_feasible.yaml")
    assert rc == 0 and r["status"] == "optimal"
    assert np.isfinite(r["best"]["objective"]) and r["best"]["objective"] > 0


def test_coupling_filter_below_peak_torque_is_infeasible_not_input_error(tmp_path, capsys):
    rc, r = _solve(tmp_path, "coupling_filter_too_small.yaml", advice=True)
    assert rc == 1 and r["status"] == "infeasible"
    text = capsys.readouterr().out
    assert "coupling rated torque / motor peak torque" in text
    assert "to catalog.require.coupling" in text
