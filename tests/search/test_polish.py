"""The default search equals exhaustive enumeration; certificates, interior preloads, infeasibility,
Pareto, problem YAML and CLI.  Fixed seeds; no timing assertions."""

from __future__ import annotations

import numpy as np
import pytest
from search_synthetic import (
    make_catalog,
    make_double,
    make_problem,
)

from axisopt import model
from axisopt.search.parts import build_space
from axisopt.search.preload import exact_solve
from axisopt.search.task.constraints import build_constraints
from axisopt.search.task.objective import objective_spec


def test_ipopt_agrees_with_exact_1d_solve():
    from axisopt.search import polish as nlp

    cat = make_catalog(np.random.default_rng(3))
    make_double(cat)
    p = make_problem(cat, axial_load=800.0, limits={"max_drag_torque": 0.6})
    sp, cons, spec = build_space(p), build_constraints(p), objective_spec("stiffness")
    ex = exact_solve(sp, np.arange(sp.size), cons, spec)
    rng = np.random.default_rng(0)
    for j in rng.choice(np.nonzero(ex.feasible)[0], size=4, replace=False):
        m, n, b, g = (int(v) for v in sp.unravel(ex.idx[j]))
        prm = sp.params_flat(sp.mountings[m], np.array([n]), np.array([b]), np.array([g]))
        prm = model.one_design(prm)
        r = nlp.solve_preload(
            sp.mountings[m],
            sp.positions(sp.mountings[m]),
            prm,
            sp.preload_lo[n],
            sp.preload_hi[n],
            cons,
            spec,
            guess=0.5 * (sp.preload_lo[n] + sp.preload_hi[n]),
        )
        assert r.success, r.status
        assert r.objective == pytest.approx(ex.objective[j], rel=1e-6)
        assert r.preload == pytest.approx(ex.preload[j], rel=1e-5)
