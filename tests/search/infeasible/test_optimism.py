"""The infeasibility scores (search.infeasible.optimism) equal an evaluation of every
combination."""

from __future__ import annotations

import numpy as np
from search_synthetic import (
    add_drives,
    make_catalog,
    make_double,
    make_problem,
)

from axisopt.search.parts import build_space
from axisopt.search.task.constraints import build_constraints


def _drive_problem(seed, axis_coupling):
    """A synthetic drive problem whose two couplings are both stiffer than the axis's stand-in
    value."""
    from dataclasses import replace

    rng = np.random.default_rng(300 + seed)
    cat = make_catalog(rng, n_screws=8, nuts_per_screw=2, n_bearings=6, n_guides=4)
    make_double(cat)
    cat = add_drives(cat, rng, n_motors=3, n_couplings=2)
    cp = cat.couplings.copy()
    cp["torsional_stiffness"], cp["rated_torque"] = [3e5, 1.5e5], 500.0
    cat = cat.replace(couplings=cp)
    p = make_problem(
        cat,
        limits={"max_cost": float(rng.uniform(3500, 6000))},
        moving_mass=200.0,
        axial_load=3000.0,
    )
    return replace(
        p,
        restrictions=replace(p.restrictions, drive=True),
        axis=replace(p.axis, coupling_stiffness=axis_coupling),
    )


def test_infeasibility_scores_equal_per_combination_evaluation():
    """The structured infeasibility explanation (mechanics once, coupling-stiffness groups, drive
    pairs on the drive sub-assembly) gives every combination the same sum of relative misses as
    evaluating that combination alone with all its parts (the flat layout the model is evaluated on
    everywhere else)."""
    from axisopt.search.infeasible.explain import miss_scores
    from axisopt.search.infeasible.optimism import RULE_WEIGHT, weight
    from axisopt.search.task.constraints import as_vector
    from axisopt.search.task.space import respond

    p = _drive_problem(2, axis_coupling=2e3).with_limit("min_stiffness", 400e6)
    sp, cons = build_space(p), build_constraints(p)
    assert sp.n_drives > 1 and len(sp.coupling_stiffnesses()) == 2
    new = np.full(sp.size, np.nan)
    for idx, score in miss_scores(sp, cons):
        new[idx] = score
    ref = np.zeros(sp.size)
    for mounting, sel, n, b, _g, prm, x in sp.by_mounting(np.arange(sp.size)):
        k = len(sel)
        lo = respond(prm, x, mounting, sp.preload_lo[n][:, None], sp.request)
        hi = respond(prm, x, mounting, sp.preload_hi[n][:, None], sp.request)
        # a compatibility rule outweighs every limit
        ref[sel] += np.where(sp.fits[n, b], 0.0, RULE_WEIGHT)
        for c in cons:
            v_lo, v_hi = as_vector(c.value(lo), k), as_vector(c.value(hi), k)
            if c.convex:
                v = np.maximum(v_lo, v_hi) if c.sense == ">=" else np.minimum(v_lo, v_hi)
            else:
                v = v_hi if c.lower_type else v_lo
            ref[sel] += weight(c) * c.violation(v)
    np.testing.assert_allclose(new, ref, rtol=1e-9, atol=1e-12)


def test_drive_bounds_split_into_nut_chunks_are_unchanged(monkeypatch):
    """The drive limits' interval bounds are taken a few nuts at a time (at most HULL_BLOCK (nut,
    bearing group, drive) elements: fuzz case 1909 held GB of temporaries with 18,808 drives x 47
    nuts); one nut at a time gives the very values of all the nuts at once."""
    from axisopt.search.infeasible import optimism
    from axisopt.search.task.space import DRIVE_KEYS

    p = _drive_problem(0, 1e9)
    space = build_space(p)
    drive = [c for c in build_constraints(p) if c.key in DRIVE_KEYS]
    assert drive and space.shape[1] > 1
    mounting = space.mountings[0]
    whole = optimism.drive_bounds_of(space, mounting, drive)
    monkeypatch.setattr(optimism, "HULL_BLOCK", 1)
    split = optimism.drive_bounds_of(space, mounting, drive)
    assert whole.keys() == split.keys()
    for name, v in whole.items():
        np.testing.assert_array_equal(split[name], v)


def test_the_explanation_stops_inside_the_drive_bounds_at_its_deadline(monkeypatch):
    """The drive limits' bounds of every block were one step without a clock (a generated 1490 t
    axis spent 147 s there past --time-limit 100): a deadline that passes inside them stops the
    explanation there, said to be cut by time; before the deadline the same explanation is
    complete."""
    import time
    from dataclasses import replace

    from axisopt.search.infeasible import explain, optimism
    from axisopt.search.task.objective import objective_spec

    p = _drive_problem(0, 1e9)
    p = replace(p, axis=replace(p.axis, moving_mass=1.5e6))  # no motor moves it
    space, cons, spec = build_space(p), build_constraints(p), objective_spec("stiffness")
    full = explain.explain_infeasible(space, cons, spec, deadline=time.perf_counter() + 600)
    assert not full.cut
    assert optimism.drive_bounds_of(space, space.mountings[0], [], time.perf_counter() - 1) is None

    def late(space, mounting, drive, deadline=None):  # the clock runs out inside the bounds
        return optimism.drive_bounds_of(space, mounting, drive, time.perf_counter() - 1)

    monkeypatch.setattr(explain, "drive_bounds_of", late)
    cut = explain.explain_infeasible(space, cons, spec, deadline=time.perf_counter() + 600)
    assert cut.cut and cut.cut_by == "time" and cut.unmeetable
