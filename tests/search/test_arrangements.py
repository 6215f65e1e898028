"""A problem listing axis arrangements (search.counterbalance / search.twin_drive,
axisopt.search.arrangements): the default method equals exhaustive enumeration, and the combined
answer is the best of the arrangements solved one by one (the tie rule: lower cost, then mass);
infeasible only when every arrangement is.  Fixed seeds, drawn so that the winner is sometimes not
the first option and sometimes 'none'."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest
from search_synthetic import add_drives, assert_same_answer, make_catalog, make_double, make_problem

from axisopt import model
from axisopt.design import Counterbalance
from axisopt.design.axis import TwinDrive
from axisopt.search import solve


def _vertical(seed: int):
    """A vertical axis with a motor searched and four counterbalance options (none among them) in a
    drawn order; seeds from 4 on an overbalancing cylinder or none (the cylinder wins the first
    seeds; seed 5 has no optimum)."""
    rng = np.random.default_rng(900 + seed)
    cat = make_catalog(rng, n_screws=4, nuts_per_screw=2, n_bearings=4, n_guides=3)
    make_double(cat)
    cat = add_drives(cat, rng, n_motors=4, n_couplings=2)
    mass = float(rng.uniform(100, 250))
    opts = [
        None,
        Counterbalance(
            "counterweight",
            mass=float(rng.uniform(0.3, 0.95)) * mass,
            chain_mass=float(rng.uniform(0, 10)),
        ),
        Counterbalance("cylinder", force=float(rng.uniform(0.5, 1.2)) * mass * 9.80665),
        Counterbalance("counterweight", mass=float(rng.uniform(0.3, 0.95)) * mass),
    ]
    # an overbalancing cylinder (2.2 to 4.5 times the weight: it loads the nut the other way)
    if seed >= 4:
        opts = [
            Counterbalance("cylinder", force=float(rng.uniform(2.2, 4.5)) * mass * 9.80665),
            None,
        ]
    opts = [opts[i] for i in rng.permutation(len(opts))]
    limits = {
        "max_cost": float(rng.uniform(3500, 6000)),
        "max_drag_torque": float(rng.uniform(1.0, 2.0)),
    }
    p = make_problem(
        cat,
        mode="frequency" if seed % 2 and seed < 4 else "stiffness",
        limits=limits,
        moving_mass=mass,
        axial_load=1500.0,
        orientation="vertical",
        required_life=float(rng.uniform(3e3, 1e4)) * 3600,
    )
    p = replace(
        p,
        restrictions=replace(p.restrictions, drive=True),
        margins=tuple((c, 1.0) for c in model.CHECKS),
    )
    return replace(
        p,
        arrangements=tuple(
            (f"option {i}", replace(p.axis, counterbalance=cb)) for i, cb in enumerate(opts)
        ),
    )


def _gantry(seed: int):
    """A horizontal axis: one drive or a twin-drive gantry."""
    rng = np.random.default_rng(4100 + seed)
    cat = make_catalog(rng, n_screws=4, nuts_per_screw=2, n_bearings=4, n_guides=4, carriage=True)
    make_double(cat)
    span = float(rng.uniform(0.8, 2.0))
    twin = TwinDrive(
        span=span,
        cross_stroke=float(rng.uniform(0.3, 1.0)) * span,
        cross_mass=float(rng.uniform(30, 150)),
    )
    p = make_problem(
        cat,
        mode="frequency",
        limits={"max_cost": float(rng.uniform(3000, 12000))},
        moving_mass=float(rng.uniform(150, 350)),
        axial_load=float(rng.uniform(1500, 4000)),
        table_length=0.6,
        rail_spacing=0.5 * span,
        table_width=0.6 * span,
    )
    opts = [None, twin] if seed % 2 else [twin, None]
    return replace(
        p,
        arrangements=tuple(
            (f"option {i}", replace(p.axis, twin_drive=tw)) for i, tw in enumerate(opts)
        ),
    )


def _check(p):
    d = solve(p, "default", top=3, sensitivities=False)
    e = solve(p, "exhaustive", top=3, sensitivities=False)
    assert_same_answer(d, e)
    assert d.arrangements == len(p.arrangements)
    # the best of the arrangements solved one by one (each with no options)
    one = [
        solve(replace(p, axis=ax, arrangements=()), "exhaustive", top=1, sensitivities=False)
        for _, ax in p.arrangements
    ]
    found = [r.best.objective for r in one if r.best is not None]
    if not found:
        assert d.best is None and d.status == "infeasible"
        return None
    assert d.best.objective == pytest.approx(max(found), rel=1e-6)
    win = [lab for lab, _ in p.arrangements].index(d.arrangement)
    assert one[win].best is not None and one[win].best.objective == pytest.approx(
        d.best.objective, rel=1e-6
    )
    ax = dict(p.arrangements)[d.arrangement]
    assert (
        d.best.design.axis.counterbalance == ax.counterbalance
        and d.best.design.axis.twin_drive == ax.twin_drive
    )
    assert d.certificate.proven == all(r.certificate.proven for r in one)
    assert d.certificate.combinations == sum(r.certificate.combinations for r in one)
    objs = [d.best.objective] + [c.objective for c in d.runners_up]
    assert objs == sorted(objs, reverse=True)
    return win, ax


def _won(make, seeds):
    """(index of the winning option, its axis) of each seed with an optimum."""
    return [w for w in (_check(make(s)) for s in seeds) if w is not None]


@pytest.mark.slow  # over 10 s on an idle core: run by `pytest -m slow`
def test_counterbalance_choice_default_equals_exhaustive():
    won = _won(_vertical, range(7))

    assert len(won) >= 3  # the seeds are drawn so that most cases have an optimum
    assert any(w != 0 for w, _ax in won)  # a winner other than the first option
    assert any(ax.counterbalance is None for _w, ax in won)  # and 'none' winning
    assert any(ax.counterbalance is not None for _w, ax in won)


@pytest.mark.slow  # over 10 s on an idle core: run by `pytest -m slow`
def test_twin_drive_choice_default_equals_exhaustive():
    won = _won(_gantry, range(4))

    assert len(won) >= 2
    assert any(w != 0 for w, _ax in won)


def _brute_front(p):
    """Every feasible design of every arrangement (exhaustive enumeration, exact per combination),
    filtered to the non-dominated ones by pairwise comparison: {(arrangement, combination)}."""
    from axisopt.search.exhaustive import exhaustive_search
    from axisopt.search.parts import build_space
    from axisopt.search.task.constraints import build_constraints
    from axisopt.search.task.objective import objective_spec

    rows, keys = [], []
    for label, ax in p.arrangements:
        sub = replace(p, axis=ax, arrangements=())
        ex, _ = exhaustive_search(
            build_space(sub), build_constraints(sub), objective_spec("stiffness")
        )
        ok = np.nonzero(ex.feasible)[0]
        rows.append(np.column_stack([ex.min_stiffness[ok], -ex.cost[ok]]))
        keys += [(label, int(i)) for i in ex.idx[ok]]
    P = np.vstack(rows)
    ge = (P[:, None, :] >= P[None, :, :]).all(-1)
    gt = (P[:, None, :] > P[None, :, :]).any(-1)
    return {k for k, dominated in zip(keys, (ge & gt).any(0)) if not dominated}


# the vertical axis's two cases take over 10 s each on an idle core: marked slow (`pytest -m slow`)
@pytest.mark.parametrize(
    "make,seed",
    [
        pytest.param(_vertical, 0, marks=pytest.mark.slow),
        pytest.param(_vertical, 2, marks=pytest.mark.slow),
        (_gantry, 0),
        (_gantry, 1),
    ],
)
def test_pareto_over_arrangements_is_the_front_of_all_their_designs(make, seed):
    """A Pareto objective with arrangements: the merged front equals the non-dominated set of every
    feasible design of every arrangement (brute force), each point naming its arrangement; default
    == exhaustive."""
    from axisopt.model.goals import Objective

    p = replace(make(seed), objective=Objective(mode="pareto", pareto=("stiffness", "cost")))
    d, e = solve(p, "default"), solve(p, "exhaustive")
    got = {(c.arrangement, c.combination) for c in d.pareto.points}
    assert got == {(c.arrangement, c.combination) for c in e.pareto.points}
    assert got == _brute_front(p)
    assert d.arrangements == len(p.arrangements) and d.pareto.feasible == e.pareto.feasible
    firsts = [c.min_stiffness for c in d.pareto.points]
    assert firsts == sorted(firsts, reverse=True)
    if make is _gantry:  # both arrangements on the front: one drive cheap, two stiff
        assert len({c.arrangement for c in d.pareto.points}) == 2
