"""The k-ary threshold search of the default method's exact 1-D solve (space.kary_threshold) against
thresholds known in closed form: it returns a preload where the limit holds, within the bisection's
resolution of the true threshold, from either side and for any number of points per round."""

import numpy as np
import pytest

from axisopt.search.preload import kary_threshold


@pytest.mark.parametrize("points", [2, 3, 16, 64])
def test_threshold_of_a_monotone_limit(points):
    rng = np.random.default_rng(points)
    lo, hi = rng.uniform(0, 1e3, 50), rng.uniform(2e3, 1e4, 50)
    t = lo + rng.uniform(0, 1, 50) * (hi - lo)  # the largest preload meeting a 'drag below a limit'
    a = kary_threshold(lambda pre: pre <= t[:, None], lo, hi, points)
    assert np.all(a <= t)
    np.testing.assert_allclose(a, t, rtol=1e-14)


def test_threshold_from_above_and_of_an_interval():
    """A limit met on an interval [l, u] of preloads, searched from a feasible point toward each
    end."""
    lo, hi = np.zeros(20), np.full(20, 100.0)
    l, u = np.linspace(5, 40, 20), np.linspace(60, 95, 20)
    start = 0.5 * (l + u)

    def good(pre):
        return (pre >= l[:, None]) & (pre <= u[:, None])

    np.testing.assert_allclose(kary_threshold(good, start, hi), u, rtol=1e-14)
    np.testing.assert_allclose(kary_threshold(good, start, lo), l, rtol=1e-14)
    assert np.all(good(kary_threshold(good, start, lo)[:, None]))


def test_exact_solve_drops_early_what_the_refined_threshold_would_reject():
    """exact_solve drops the combinations that miss a limit a higher preload helps already at the
    coarse bracket's upper end (COARSE_BITS): every combination's feasibility, objective and
    (feasible) preload are those of the solve that refines every threshold to the bisection's 2^-52
    before checking."""
    import sys
    import time
    import warnings
    from pathlib import Path

    from axisopt.errors import ImplausibleInput
    from axisopt.problem import load_problem
    from axisopt.search import bestfirst, front, preload
    from axisopt.search.bestfirst import SOLVED

    root = Path(__file__).resolve().parents[2]
    sys.path.insert(0, str(root / "bench"))
    from axis_generator import make

    for src in ("teaching", 0):
        if src == "teaching":
            problem = load_problem(root / "problems" / "teaching_problem.yaml")
        else:
            f = Path(__file__).resolve().parent / "_gen_preload.yaml"
            f.write_text(make(0, src).text)
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", ImplausibleInput)
                problem = load_problem(f)
            f.unlink()
        task = front.build_task(problem)
        bestfirst.run(task, "default", 5, 1e4, time.perf_counter())
        idx = task.space._cache[SOLVED][2].idx
        coarse = preload.exact_solve(task.space, idx, task.constraints, task.objective)
        old = preload.COARSE_BITS
        try:
            preload.COARSE_BITS = preload.BISECTION_STEPS  # no early drop
            full = preload.exact_solve(task.space, idx, task.constraints, task.objective)
        finally:
            preload.COARSE_BITS = old
        assert len(idx) and full.feasible.any() and not full.feasible.all()
        np.testing.assert_array_equal(coarse.feasible, full.feasible)
        np.testing.assert_array_equal(coarse.objective, full.objective)
        f_ = full.feasible
        np.testing.assert_array_equal(coarse.preload[f_], full.preload[f_])
