"""Limit ``max_regen_power`` (the mean power the motor returns to the drive): the default search
equals exhaustive enumeration with it, on horizontal and vertical synthetic axes with drives, and it
binds."""

from __future__ import annotations

import numpy as np
import pytest
from search_synthetic import add_drives, assert_same_answer, make_catalog, make_double, make_problem

from axisopt.model.limits import LIMITS, preload_direction
from axisopt.search import solve


def test_regen_power_is_declared_falling_with_preload():
    assert LIMITS["max_regen_power"].output == "regen_power"
    assert preload_direction("regen_power") == -1  # the nut's drag brakes the moves


@pytest.mark.parametrize("seed, vertical", [(802, False), (803, False), (800, True), (805, True)])
def test_max_regen_power_default_equals_exhaustive(seed, vertical):
    rng = np.random.default_rng(seed)
    cat = make_catalog(rng, n_screws=3, nuts_per_screw=2, n_bearings=4, n_guides=3)
    make_double(cat)
    cat = add_drives(cat, rng, n_motors=3, n_couplings=2)
    kw = (
        {"orientation": "vertical", "moving_mass": 80.0}
        if vertical
        else {"acceleration": 8.0, "max_speed": 0.5}
    )
    free = solve(make_problem(cat, **kw), "exhaustive", top=1, sensitivities=False)
    if free.best is None:
        pytest.skip("no feasible design in this synthetic catalog")
    from axisopt.model import evaluate

    regen = float(evaluate(free.best.design)["regen_power"])
    assert regen > 0.0
    # a limit the free optimum misses: the answer must change and still agree with enumeration
    p = make_problem(cat, limits={"max_regen_power": 0.8 * regen}, **kw)
    d = solve(p, "default", top=3, sensitivities=False)
    e = solve(p, "exhaustive", top=3, sensitivities=False)
    assert_same_answer(d, e, preload=False)
    if d.best is not None:
        assert d.certificate.proven
        assert float(evaluate(d.best.design)["regen_power"]) <= 0.8 * regen * (1 + 1e-6)
        assert (
            d.best.combination != free.best.combination
            or d.best.design.preload > free.best.design.preload
        )
