"""search.advice: a design change offered before any limit is relaxed, verified by a search.  The test solves the
changed problem again from its own YAML text (the change written as a user would write it), so a change that
only the advice believes in fails here.  The advice is a what-if re-solve like the sensitivities: a study's batch
solves (sensitivities=False) leave it out."""

import re
from pathlib import Path

import pytest

from axisopt.problem import load_problem
from axisopt.search import solve

ROOT = Path(__file__).resolve().parents[2]


def _variant(tmp_path, name, **values):
    text = (ROOT / "problems" / name).read_text(encoding="utf-8")
    for key, value in values.items():
        text, n = re.subn(rf"^(\s*{key}:\s*)[^#\n]*", lambda m, v=value: m.group(1) + v, text, flags=re.M)
        assert n == 1, key
    path = tmp_path / f"{key}.yaml"
    path.write_text(text, encoding="utf-8")
    return path


def test_lower_rapid_speed_is_offered_and_holds(tmp_path):
    """The lathe Z with at most 1 um of lost motion (no gearbox: direct drive) misses the critical speed at
    40 m/min; the advice lowers the rapid speed, and the problem with that speed solves."""
    res = solve(load_problem(_variant(tmp_path, "lathe_z_problem.yaml", max_backlash="1 um")), "default")
    assert res.best is None
    changes = res.infeasibility.design_changes
    assert [c.key for c in changes] == ["axis.max_speed"]
    c = changes[0]
    assert c.unit == "m/min" and c.value == pytest.approx(40.0) and 30.0 < c.to < 40.0
    fixed = _variant(tmp_path, "lathe_z_problem.yaml", max_backlash="1 um", max_speed=f"{c.to:g} m/min")
    again = solve(load_problem(fixed), "default", sensitivities=False)
    assert again.best is not None and again.certificate.proven


def test_no_change_offered_where_speed_and_torque_do_not_bind(tmp_path):
    """The teaching problem at 65 m/min misses the support set's life and the nut's lift-off: no speed or
    torque check, so no axis change is offered (the limits to relax still are)."""
    res = solve(load_problem(_variant(tmp_path, "teaching_problem.yaml", max_speed="65 m/min")), "default")
    assert res.best is None and res.infeasibility.design_changes == [] and res.infeasibility.relax


def test_batch_solves_leave_the_advice_out(tmp_path):
    """sensitivities=False (a study's cases): no verifying search, no design change."""
    res = solve(load_problem(_variant(tmp_path, "lathe_z_problem.yaml", max_backlash="1 um")), "default",
                sensitivities=False)
    assert res.best is None and res.infeasibility.design_changes == []
