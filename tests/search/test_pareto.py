"""The default search equals exhaustive enumeration; certificates, interior preloads, infeasibility,
Pareto, problem YAML and CLI.  Fixed seeds; no timing assertions."""

from __future__ import annotations

import numpy as np
from search_synthetic import (
    make_catalog,
    make_problem,
)

from axisopt.model.goals import Objective
from axisopt.search import solve
from axisopt.search.exhaustive import exhaustive_search
from axisopt.search.pareto import nondominated
from axisopt.search.parts import build_space
from axisopt.search.task.constraints import build_constraints
from axisopt.search.task.objective import objective_spec


def test_nondominated_matches_pairwise():
    rng = np.random.default_rng(2)
    P = np.round(rng.normal(size=(700, 4)), 1)  # rounding makes ties and duplicates
    ge = (P[:, None, :] >= P[None, :, :]).all(-1)
    gt = (P[:, None, :] > P[None, :, :]).any(-1)
    naive = np.nonzero(~(ge & gt).any(0))[0]
    np.testing.assert_array_equal(nondominated(P, block=64), naive)


def test_pareto_default_equals_exhaustive():
    cat = make_catalog(np.random.default_rng(4))
    ob = Objective(mode="pareto", pareto=("stiffness", "frequency", "cost", "total_mass"))
    p = make_problem(cat, objective=ob, limits={"max_drag_torque": 1.0})
    d, e = solve(p, "default"), solve(p, "exhaustive")
    assert d.status == e.status == "optimal"
    assert sorted(c.combination for c in d.pareto.points) == sorted(
        c.combination for c in e.pareto.points
    )
    # brute force over the exact per-combination values
    sp = build_space(p)
    ex, _ = exhaustive_search(sp, build_constraints(p), objective_spec("stiffness"))
    ok = np.nonzero(ex.feasible)[0]
    P = np.column_stack(
        [ex.min_stiffness[ok], ex.min_frequency[ok], -ex.cost[ok], -ex.total_mass[ok]]
    )
    ge = (P[:, None, :] >= P[None, :, :]).all(-1)
    gt = (P[:, None, :] > P[None, :, :]).any(-1)
    assert sorted(ex.idx[ok][~(ge & gt).any(0)].tolist()) == sorted(
        c.combination for c in d.pareto.points
    )


def test_top_limits_the_printed_pareto_front(capsys):
    from axisopt.cli.solve import format_pareto

    p = make_problem(
        make_catalog(
            np.random.default_rng(4), n_screws=3, nuts_per_screw=2, n_bearings=3, n_guides=3
        ),
        objective=Objective(mode="pareto", pareto=("stiffness", "cost")),
    )
    front = solve(p, "default").pareto
    assert len(front.points) >= 3
    rows = [ln for ln in format_pareto(front, 2).splitlines() if ln[:5].strip().isdigit()]
    assert [int(r.split()[0]) for r in rows] == [1, 2]
    assert len([ln for ln in format_pareto(front).splitlines() if ln[:5].strip().isdigit()]) == len(
        front.points
    )
