"""The exhaustive method's per-combination solve (core.grid_solve) evaluates its preload grid up to
the upper end of the feasible interval found by bisection.  That end must be evaluated exactly: the
grid point ``low + 1.0 * (up - low)`` can round one ulp above ``up``, past the drag threshold, and
the combination then lost its best preload (the next grid point, 1/8 of the range lower): the
reference method reported a worse objective than the default method for the same combination, and so
other runners-up.  Reference: the default method's exact 1-D solve (the objective grows with
the preload: the optimum is the upper end)."""

import numpy as np
from search_synthetic import make_catalog, make_double, make_problem

from axisopt.search.exhaustive import grid_solve
from axisopt.search.parts import build_space
from axisopt.search.preload import exact_solve
from axisopt.search.task.constraints import build_constraints
from axisopt.search.task.objective import objective_spec


def test_grid_keeps_the_upper_end_of_the_feasible_preloads():
    cat = make_catalog(
        np.random.default_rng(4), n_screws=40, nuts_per_screw=3, n_bearings=1, n_guides=1
    )
    make_double(cat)
    checked = 0
    # drag limits whose thresholds (one per nut) include ones where the rounding showed
    for drag in (2.1, 2.169230769230769, 2.792307692307692, 2.9307692307692306, 3.0):
        p = make_problem(
            cat,
            mountings=("fixed-supported",),
            axial_load=800.0,
            limits={"max_cost": 1e5, "max_drag_torque": drag},
        )
        sp, cons, spec = build_space(p), build_constraints(p), objective_spec("stiffness")
        idx = np.arange(sp.size)
        ex, gr = exact_solve(sp, idx, cons, spec), grid_solve(sp, idx, cons, spec)
        assert np.array_equal(ex.feasible, gr.feasible)
        f = np.nonzero(ex.feasible & (ex.preload < sp.preload_hi[sp.unravel(idx)[1]]))[0]
        checked += len(f)
        np.testing.assert_allclose(gr.preload[f], ex.preload[f], rtol=1e-12)
        np.testing.assert_allclose(gr.objective[f], ex.objective[f], rtol=1e-12)
    assert checked >= 100, checked
