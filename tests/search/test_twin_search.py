"""The twin-drive gantry (issue 40, axisopt.model.gantry) in the search: the default method equals
exhaustive enumeration on randomized twin-drive problems (the governing side's loads, the gantry's
translation and racking modes in the frequency minimum, the pair's cost), with motors and couplings
searched.  Fixed seeds."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest
from search_synthetic import add_drives, assert_same_answer, make_catalog, make_double, make_problem

from axisopt import model
from axisopt.design.axis import TwinDrive
from axisopt.model.goals import Objective
from axisopt.search import solve


def _twin_problem(seed: int, mode: str):
    rng = np.random.default_rng(4000 + seed)
    cat = make_catalog(rng, n_screws=4, nuts_per_screw=2, n_bearings=4, n_guides=4, carriage=True)
    make_double(cat)
    cat = add_drives(cat, rng, n_motors=3, n_couplings=2)
    span = float(rng.uniform(0.8, 2.0))
    twin = TwinDrive(
        span=span,
        cross_stroke=float(rng.uniform(0.3, 1.0)) * span,
        cross_mass=float(rng.uniform(30, 150)),
        bridge_yaw_inertia=None if seed % 2 else float(rng.uniform(5, 60)),
    )
    ob = (
        Objective(
            mode="weighted",
            weights=(("stiffness", 1.0), ("frequency", 2.0)),
            scale=(("stiffness", 100e6), ("frequency", 100.0)),
        )
        if mode == "weighted"
        else Objective(mode=mode)
    )
    limits = {
        "max_cost": float(rng.uniform(6000, 12000)),
        "max_drag_torque": float(rng.uniform(1.0, 2.5)),
    }
    p = make_problem(
        cat,
        objective=ob,
        limits=limits,
        moving_mass=float(rng.uniform(150, 350)),
        axial_load=float(rng.uniform(1500, 4000)),
        twin_drive=twin,
        table_length=0.6,
        rail_spacing=0.5 * span,
        table_width=0.6 * span,
        required_life=float(rng.uniform(2e3, 1e4)) * 3600,
    )
    return replace(p, restrictions=replace(p.restrictions, drive=True))


@pytest.mark.parametrize("seed", range(4))
@pytest.mark.parametrize("mode", ["frequency", "weighted"])
def test_default_equals_exhaustive_twin_drive(seed, mode):
    p = _twin_problem(seed, mode)
    d = solve(p, "default", top=2, sensitivities=False)
    e = solve(p, "exhaustive", top=2, sensitivities=False)
    assert (d.best is None) == (e.best is None)
    assert_same_answer(d, e)
    if d.best is not None:
        assert d.certificate.proven and d.certificate.gap == 0.0
        out = model.evaluate(d.best.design).values
        # the twin model is in the answer: the gantry mode is in the minimum, the pair is paid for
        assert np.min(out["f1"]) <= np.min(out["f_gantry"]) + 1e-9
        assert np.min(out["f_gantry"]) < 1e29


def test_twin_problems_have_optima():
    """The seeds above are drawn so that most twin-drive cases have an optimum (the comparison is
    not vacuous)."""
    found = [
        solve(_twin_problem(s, "frequency"), "default", top=1, sensitivities=False).best is not None
        for s in range(4)
    ]
    assert sum(found) >= 2, found
