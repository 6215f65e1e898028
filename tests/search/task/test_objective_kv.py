"""Objective ``kv`` and limit ``min_kv`` (model.servo): the default search equals exhaustive
enumeration on randomized problems, and Kv rises with the nut preload (the search's 1-D solve rests
on it)."""

from __future__ import annotations

import numpy as np
import pytest
from search_synthetic import add_drives, assert_same_answer, make_catalog, make_double, make_problem

from axisopt.model.goals import Objective
from axisopt.model.limits import LIMITS, preload_direction
from axisopt.search import solve


@pytest.mark.parametrize("seed", range(4))
def test_kv_objective_default_equals_exhaustive(seed):
    rng = np.random.default_rng(700 + seed)
    cat = make_catalog(rng, n_screws=4, nuts_per_screw=3, n_bearings=6, n_guides=4)
    limits = {
        "max_cost": float(rng.uniform(2500, 5000)),
        "max_drag_torque": float(rng.uniform(0.4, 1.5)),
    }
    if seed % 2:
        limits["min_life"] = float(rng.uniform(5e3, 3e4)) * 3600
    p = make_problem(
        cat, objective=Objective(mode="kv"), limits=limits, backlash=5e-5 if seed % 2 else None
    )
    d = solve(p, "default", top=3, sensitivities=False)
    e = solve(p, "exhaustive", top=3, sensitivities=False)
    assert_same_answer(d, e, preload=False)
    if d.best is not None:
        assert d.certificate.proven
        assert [c.combination for c in d.runners_up] == [c.combination for c in e.runners_up]
        assert d.best.outputs["kv"] == pytest.approx(d.best.objective, rel=1e-9)


@pytest.mark.parametrize("seed", [0, 3])
def test_min_kv_limit_default_equals_exhaustive_with_drive(seed):
    rng = np.random.default_rng(800 + seed)
    cat = make_catalog(rng, n_screws=3, nuts_per_screw=2, n_bearings=4, n_guides=3)
    make_double(cat)
    cat = add_drives(cat, rng, n_motors=3, n_couplings=2)
    free = solve(make_problem(cat, mode="kv"), "exhaustive", top=1, sensitivities=False)
    if free.best is None:
        pytest.skip("no feasible design in this synthetic catalog")
    # a min_kv that the best meets and some others miss
    p = make_problem(cat, mode="stiffness", limits={"min_kv": 0.9 * free.best.objective})
    d = solve(p, "default", top=3, sensitivities=False)
    e = solve(p, "exhaustive", top=3, sensitivities=False)
    assert_same_answer(d, e, preload=False)
    assert d.best.outputs["kv"] >= 0.9 * free.best.objective * (1 - 1e-9)


def test_kv_is_declared_rising_with_preload():
    assert LIMITS["min_kv"].output == "kv" and preload_direction("kv") == 1


def test_kv_rises_with_preload_on_the_model():
    from pathlib import Path

    from axisopt.design import load_design
    from axisopt.model import SCREEN, axis_response, design_params, positions

    d = load_design(Path(__file__).resolve().parents[3] / "problems" / "vmc_x_design.yaml")
    p = design_params(d)
    x = positions(d.axis)
    pre = np.linspace(float(d.nut["preload_min"]), float(d.nut["preload_max"]), 25)
    kv = [np.min(axis_response(p, x, d.axis.mounting, q, SCREEN)["kv"]) for q in pre]
    assert np.all(np.diff(kv) >= -1e-12 * max(kv))
