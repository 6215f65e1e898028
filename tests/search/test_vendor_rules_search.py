"""default == exhaustive with each part by its own vendor's rule (model.motorrule on motors with
different vendors' ratios or none, an unbalanced vertical axis, a drive torque limit, reductions'
emergency-stop torques listed or not, the nut lift-off by load case or with the cut while
accelerating) on randomized catalogs."""

from dataclasses import replace

import numpy as np
import pytest
from search_synthetic import (
    add_drives,
    add_reductions,
    assert_same_answer,
    make_catalog,
    make_double,
    make_problem,
)

from axisopt import model
from axisopt.search import solve


@pytest.mark.parametrize("seed", range(6))
def test_default_equals_exhaustive_vendor_rules(seed):
    from axisopt.physics.motion import Segment

    rng = np.random.default_rng(900 + seed)
    cat = make_catalog(rng, n_screws=4, nuts_per_screw=2, n_bearings=4, n_guides=3)
    make_double(cat)
    cat = add_reductions(
        add_drives(cat, rng, n_motors=4, n_couplings=2, rules=True), rng, n=3, rules=True
    )
    vertical = seed % 2 == 1
    mass = float(rng.uniform(60, 150) if vertical else rng.uniform(150, 400))
    duty = (
        ()
        if seed < 2
        else (
            Segment("move", distance=0.5, speed=0.3, acceleration=4.0, jerk=60.0),
            Segment("move", distance=-0.3, speed=0.02, acceleration=1.0, force=2500.0),
            Segment("dwell", duration=1.0),
            Segment("move", distance=-0.2, speed=0.3, acceleration=4.0),
        )
    )
    limits = {
        "max_cost": float(rng.uniform(3500, 6000)),
        "max_drag_torque": float(rng.uniform(1.0, 2.0)),
    }
    extra = {}
    if seed in (1, 4):
        extra["torque_limit"] = float(rng.uniform(8.0, 25.0))
    if seed in (0, 3):
        extra["cut_while_accelerating"] = True
    # no duty cycle: the heat balance of the default cycle, bounded by max_thermal_growth
    if seed in (0, 1):
        extra["rise_without_cycle"] = "balance"
        limits["max_thermal_growth"] = float(rng.uniform(20e-6, 80e-6))
    if seed == 5:
        extra["buckling_nut_end"] = "supported"
    if seed in (2, 4):  # Schneeberger's slenderness guidance as a limit
        limits["max_slenderness"] = float(rng.uniform(25.0, 45.0))
    p = make_problem(
        cat,
        limits=limits,
        moving_mass=mass,
        axial_load=1500.0 if vertical else 3000.0,
        orientation="vertical" if vertical else "horizontal",
        duty_cycle=duty,
        backlash=float(rng.uniform(5e-6, 40e-6)),
        **extra,
    )
    p = replace(
        p,
        restrictions=replace(p.restrictions, drive=True),
        margins=tuple((c, 1.0) for c in model.CHECKS),
    )
    d = solve(p, "default", top=2, sensitivities=False)
    e = solve(p, "exhaustive", top=2, sensitivities=False)
    assert (d.best is None) == (e.best is None)
    if d.best is not None:
        assert_same_answer(d, e)
        ev = model.evaluate(d.best.design)
        for c in model.CHECKS:
            assert model.passes(ev.values[f"margin_{c}"]), c


@pytest.mark.parametrize("seed", range(3))
def test_default_equals_exhaustive_screw_and_set_makers(seed):
    """The screw's critical speed by its vendor (HIWIN's F 3.27 or THK's lambda) and the set's
    load split by its maker (NSK's printed split or HIWIN's pair law), on catalogs mixing them, with
    fixed-free mountings where HIWIN's rule differs most."""
    rng = np.random.default_rng(950 + seed)
    cat = make_catalog(rng, n_screws=4, nuts_per_screw=2, n_bearings=4, n_guides=3)
    make_double(cat)
    cat.screws["vendor"] = ["HIWIN" if i % 2 == 0 else "THK" for i in range(len(cat.screws))]
    cat.bearings["vendor"] = ["NSK" if i % 2 == 0 else "HIWIN" for i in range(len(cat.bearings))]
    p = make_problem(
        cat,
        mountings=("fixed-free", "fixed-supported", "fixed-fixed"),
        limits={"max_cost": float(rng.uniform(3000, 5000)), "min_life": 15000 * 3600.0},
        moving_mass=float(rng.uniform(150, 400)),
        axial_load=3000.0,
    )
    d = solve(p, "default", top=2, sensitivities=False)
    e = solve(p, "exhaustive", top=2, sensitivities=False)
    assert (d.best is None) == (e.best is None)
    if d.best is not None:
        assert_same_answer(d, e)
