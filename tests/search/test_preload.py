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
    """A limit met on an interval [l, u] of preloads, searched from a feasible point toward each end."""
    lo, hi = np.zeros(20), np.full(20, 100.0)
    l, u = np.linspace(5, 40, 20), np.linspace(60, 95, 20)
    start = 0.5 * (l + u)

    def good(pre):
        return (pre >= l[:, None]) & (pre <= u[:, None])

    np.testing.assert_allclose(kary_threshold(good, start, hi), u, rtol=1e-14)
    np.testing.assert_allclose(kary_threshold(good, start, lo), l, rtol=1e-14)
    assert np.all(good(kary_threshold(good, start, lo)[:, None]))
