"""model.request: what the caller asks the axis model for, not switches in the parameter dict."""

from __future__ import annotations

import dataclasses
from pathlib import Path

import numpy as np
import pytest

from axisopt import model
from axisopt.design import load_design
from axisopt.model import FULL, MECHANICS, SCREEN, Request, axis_response, design_params, positions
from axisopt.model.accuracy import BUDGET_OUTPUTS
from axisopt.model.outputs import DRIVE_OUTPUTS
from axisopt.problem import load_problem
from axisopt.search.parts import build_space, reads_budget

ROOT = Path(__file__).resolve().parents[2]


def test_presets_and_but():
    assert FULL == Request()
    assert SCREEN == FULL.but(extras=False)
    assert MECHANICS == SCREEN.but(drive=False)
    assert SCREEN.but(chain=False).chain is False and SCREEN.chain is True  # the preset unchanged
    with pytest.raises(dataclasses.FrozenInstanceError):
        FULL.chain = False
    with pytest.raises(TypeError):
        FULL.but(stiffness=False)  # no such sub-assembly


def test_budget_false_leaves_out_the_budget_and_nothing_else_changes():
    d = load_design(ROOT / "problems" / "vmc_x_design.yaml")
    p, x = design_params(d), positions(d.axis)
    full = axis_response(p, x, d.axis.mounting, d.preload)
    bare = axis_response(p, x, d.axis.mounting, d.preload, FULL.but(budget=False))
    assert set(full) - set(bare) == set(BUDGET_OUTPUTS)
    same = [
        np.array_equal(np.asarray(full[k]), np.asarray(bare[k]))
        for k in bare
        if k != "duty_torques"
    ]
    assert all(same)
    no_drive = axis_response(p, x, d.axis.mounting, d.preload, MECHANICS)
    assert not set(no_drive) & (set(DRIVE_OUTPUTS) - model.CHAIN_OUTPUTS - {"cost", "backlash"})


@pytest.mark.parametrize("name", ["teaching_problem.yaml", "precision_problem.yaml"])
def test_search_parameter_dicts_carry_no_switch(name):
    """The search's parameter dicts hold the model's parameters and the duty cycle only; the budget
    switch is the space's request (set from the problem's limits)."""
    prob = load_problem(ROOT / "problems" / name)
    sp = build_space(prob)
    assert sp.request == SCREEN.but(budget=reads_budget(prob))
    m = sp.mountings[0]
    n = np.zeros(1, dtype=np.int64)
    for ps in (sp.params_structured(m), sp.params_drives(m, n), sp.params_flat(m, n, n, n)):
        assert set(ps) <= set(model.PARAM_NAMES) | {"duty"}
