"""The least-squares fit (:mod:`axisopt.identify.fit`): a dependent column is not identifiable."""

import numpy as np

from axisopt.identify.fit import covariance


def test_a_dependent_column_is_not_identifiable_not_zero_uncertainty():
    J = np.array([[1.0, 0.0, 2.0], [2.0, 0.0, 1.0], [3.0, 0.0, 0.5], [1.0, 0.0, 1.0]])
    cov = covariance(J, rss=1.0, n=4, scale=np.ones(3))
    sd = np.sqrt(np.diag(cov))
    assert np.isfinite(sd[0]) and np.isfinite(sd[2]) and sd[0] > 0
    assert np.isinf(sd[1])
