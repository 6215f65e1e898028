"""SCIP against exhaustive enumeration on random catalogs (the mechanics, a drive with a frequency
objective, a counterweighted vertical axis, reductions): a file of its own so that pytest-xdist runs
it beside the other SCIP tests."""

from __future__ import annotations

import numpy as np
import pytest
from scip_agree import agrees_with_exhaustive
from search_synthetic import add_drives, add_reductions, make_catalog, make_double, make_problem

from axisopt.model.goals import Objective
from axisopt.search import solve

pytest.importorskip("pyscipopt")


# Seed 3 failed from issue 26 to issue 38 (SCIP stopped at preload 1578 N, 45.51 N/um, where
# exhaustive enumeration found 1872 N, 47.04 N/um, on the same parts: SCIP's global search cut the
# optimum off).  With the vendors' load factor and the estimated mounts the problem's optimum moved
# and SCIP proves it: kept as a case.
@pytest.mark.parametrize("seed", [3, 4])
def test_random_catalogs_equal_exhaustive(seed):
    rng = np.random.default_rng(seed)
    cat = make_catalog(rng, n_screws=3, nuts_per_screw=2, n_bearings=4, n_guides=3)
    limits = {
        "max_cost": float(rng.uniform(2500, 5000)),
        "max_drag_torque": float(rng.uniform(0.4, 1.5)),
        "min_life": float(rng.uniform(5e3, 3e4)) * 3600,
    }
    ob = (
        Objective(
            mode="weighted",
            weights=(("stiffness", 1.0), ("frequency", 2.0)),
            scale=(("stiffness", 100e6), ("frequency", 100.0)),
        )
        if seed == 4
        else Objective(mode="stiffness")
    )
    p = make_problem(cat, objective=ob, limits=limits)
    agrees_with_exhaustive(
        solve(p, "scip", time_limit=20), solve(p, "exhaustive", top=1, sensitivities=False)
    )


@pytest.mark.slow  # over 10 s on an idle core: run by `pytest -m slow`
def test_random_catalog_with_drive_and_frequency_equals_exhaustive():
    rng = np.random.default_rng(105)
    cat = make_catalog(rng, n_screws=3, nuts_per_screw=2, n_bearings=3, n_guides=2)
    make_double(cat)
    cat = add_drives(cat, rng, n_motors=3, n_couplings=2)
    p = make_problem(
        cat,
        mode="frequency",
        limits={"max_cost": 5000.0, "max_drag_torque": 1.5},
        moving_mass=200.0,
    )
    agrees_with_exhaustive(
        solve(p, "scip", time_limit=20), solve(p, "exhaustive", top=1, sensitivities=False)
    )


@pytest.mark.slow  # over 10 s on an idle core: run by `pytest -m slow`
def test_random_catalog_with_counterweight_equals_exhaustive():
    """A counterweighted vertical axis with a drive: the one-hot MINLP sees the balance force in the
    loads and the counterweight's inertia and weight in the motor torques as the default method
    does."""
    from dataclasses import replace

    from axisopt.design import Counterbalance

    rng = np.random.default_rng(105)
    cat = make_catalog(rng, n_screws=3, nuts_per_screw=2, n_bearings=3, n_guides=2)
    make_double(cat)
    cat = add_drives(cat, rng, n_motors=3, n_couplings=2)
    p = make_problem(
        cat,
        mode="stiffness",
        limits={"max_cost": 5000.0, "max_drag_torque": 1.5},
        moving_mass=200.0,
        orientation="vertical",
        axial_load=1500.0,
        counterbalance=Counterbalance("counterweight", mass=150.0, efficiency=0.9, chain_mass=5.0),
    )
    p = replace(p, restrictions=replace(p.restrictions, drive=True))
    e = solve(p, "exhaustive", top=1, sensitivities=False)
    assert e.best is not None
    agrees_with_exhaustive(solve(p, "scip", time_limit=20), e)


@pytest.mark.slow  # over 10 s on an idle core: run by `pytest -m slow`
def test_random_catalog_with_reductions_equals_exhaustive():
    """(motor, coupling, reduction or none) drives: the one-hot MINLP over the guide-and-drive
    entries sees the reduction's parameters (ratio, efficiency, input inertia, T2B/T2N, n1Max, Ct21,
    backlash, price) as the default method does."""
    from dataclasses import replace

    rng = np.random.default_rng(106)
    cat = make_catalog(rng, n_screws=3, nuts_per_screw=2, n_bearings=3, n_guides=2)
    make_double(cat)
    cat = add_reductions(add_drives(cat, rng, n_motors=2, n_couplings=2), rng, n=2)
    p = make_problem(
        cat,
        mode="stiffness",
        limits={"max_cost": 5000.0, "max_drag_torque": 1.5},
        moving_mass=200.0,
        backlash=40e-6,
    )
    p = replace(p, restrictions=replace(p.restrictions, drive=True))
    from axisopt.search.parts import build_space

    assert any(r is not None for _, _, r in build_space(p).drives)
    agrees_with_exhaustive(
        solve(p, "scip", time_limit=30), solve(p, "exhaustive", top=1, sensitivities=False)
    )
