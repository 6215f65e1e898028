"""The default method's block bounds (best-first over (mounting, nut, bearing) blocks, never forming
the whole product): checked against every combination evaluated one by one (exhaustive enumeration),
on ball and roller guides of random properties, with and without a drive search, and the search
against exhaustive."""

from dataclasses import replace

import numpy as np
import pytest
from search_synthetic import add_drives, make_catalog, make_double, make_problem

from axisopt import model
from axisopt.search import solve
from axisopt.search.bounds import block_bounds
from axisopt.search.exhaustive import exhaustive_search
from axisopt.search.parts import build_space
from axisopt.search.task.constraints import build_constraints
from axisopt.search.task.objective import objective_spec


def _problem(seed):
    rng = np.random.default_rng(700 + seed)
    cat = make_catalog(rng, n_screws=4, nuts_per_screw=2, n_bearings=5, n_guides=8)
    g = cat.guides.copy()
    g["type"] = np.where(np.arange(len(g)) % 2 == 0, "ball", "roller")
    # guides that differ in mass, rigidity and rating
    g["block_mass"] *= rng.uniform(0.5, 2.0, len(g))
    g["normal_rigidity"] *= rng.uniform(0.5, 2.0, len(g))
    g["dynamic_load_rating"] *= rng.uniform(0.3, 1.5, len(g))
    cat = cat.replace(guides=g)
    drive = seed % 2 == 1
    if drive:
        make_double(cat)
        cat = add_drives(cat, rng, n_motors=3, n_couplings=2)
    limits = {
        "max_cost": float(rng.uniform(3500, 6000)),
        "max_drag_torque": float(rng.uniform(0.8, 2.0)),
        "max_moving_mass": float(rng.uniform(320, 360)),
    }
    p = make_problem(
        cat,
        mode="frequency" if seed % 3 else "stiffness",
        limits=limits,
        mountings=("fixed-supported", "fixed-fixed"),
    )
    if drive:
        p = replace(
            p,
            restrictions=replace(p.restrictions, drive=True),
            margins=tuple((c, 1.0) for c in model.CHECKS),
        )
    return p


@pytest.mark.parametrize("seed", [0, 1, 2, 3, 5, 6])
def test_block_bounds_hold_for_every_combination(seed):
    p = _problem(seed)
    sp, cons = build_space(p), build_constraints(p)
    spec = objective_spec(p.objective.mode, p)
    blocks = block_bounds(sp, cons, spec)
    ex, _ = exhaustive_search(sp, cons, spec)
    feas = np.nonzero(ex.feasible)[0]
    assert len(feas), "each seed has feasible combinations"
    m, n, b, _ = sp.unravel(ex.idx[feas])
    for k, i in enumerate(feas):
        ok, bound = blocks[m[k]]
        assert ok[n[k], b[k]], "a feasible combination lies in a block the bound calls infeasible"
        assert bound[n[k], b[k]] >= ex.objective[i] * (1 - 1e-6), (
            bound[n[k], b[k]],
            ex.objective[i],
        )
    # and the pruning is real: some blocks are left out
    assert sum(int((~ok).sum()) for ok, _ in blocks) > 0


@pytest.mark.parametrize("seed", [0, 1, 2, 3, 5, 6])
def test_block_search_equals_exhaustive(seed):
    p = _problem(seed)
    d = solve(p, "default", top=3, sensitivities=False)
    e = solve(p, "exhaustive", top=3, sensitivities=False)
    assert d.best.objective == pytest.approx(e.best.objective, rel=1e-6)
    assert d.best.combination == e.best.combination
    assert [c.combination for c in d.runners_up] == [c.combination for c in e.runners_up]
    c = d.certificate
    assert c.proven and c.gap == 0.0
    assert c.pruned_by_bound + c.exact_evaluations == c.feasible
    assert c.screened + c.pruned_by_block == c.combinations
