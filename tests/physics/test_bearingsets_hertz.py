"""The Hertz split of a support set's row groups (physics.bearingsets.hertz_set_halves, issue 53:
NSK rates its sets' groups by it) against IBC TI-I-5010.2/E Table 2.2's unloading points, which
follow from the same law, and against the linear split it refines."""

from __future__ import annotations

import numpy as np
import pytest

from axisopt.physics.bearingsets import hertz_set_halves, set_halves, set_preload_ratio

FV = 1000.0  # IBC's Fv: the preload of two of the bearings as a DB pair [N]


@pytest.mark.published
@pytest.mark.parametrize(("n_load", "n_other", "x"), [(1, 1, 2.83), (2, 1, 5.66), (3, 1, 8.49)])
def test_the_other_group_unloads_at_ibc_table_2_2(n_load, n_other, x):
    """IBC Table 2.2: the opposite group unloads at Fae = X Fv (X 2.83, 5.66, 8.49 for 1, 2, 3
    against 1), the set's own preload being set_preload_ratio x Fv (1, 1.36, 1.57 Fv)."""
    pre = set_preload_ratio(n_load, n_other) * FV
    before = hertz_set_halves(pre, 0.995 * x * FV, float(n_load), float(n_other))
    after = hertz_set_halves(pre, 1.005 * x * FV, float(n_load), float(n_other))
    assert float(before[1]) > 0.0
    assert float(after[1]) == pytest.approx(0.0, abs=1e-6 * FV)
    assert float(after[0]) == pytest.approx(1.005 * x * FV, rel=1e-9)


@pytest.mark.parametrize("load", [-9000.0, -2500.0, 0.0, 700.0, 3000.0, 5000.0, 12000.0])
def test_groups_balance_the_load_and_stay_below_the_linear_split(load):
    pre = set_preload_ratio(3, 1) * FV
    plus, minus = (float(v) for v in hertz_set_halves(pre, load, 3.0, 1.0))
    assert plus - minus == pytest.approx(load, abs=1e-6 * FV)
    assert min(plus, minus) >= 0.0
    lin = set_halves(pre, load, 3.0, 1.0)
    pressed = plus if load >= 0 else minus
    assert pressed <= float(lin[0] if load >= 0 else lin[1]) + 1e-9


def test_the_deflections_match():
    """Each bearing deflects as (Q / K)^(2/3): the pressed group's contacts close by what the
    other's open."""
    pre = set_preload_ratio(3, 1) * FV
    plus, minus = (float(v) for v in hertz_set_halves(pre, np.float64(2000.0), 3.0, 1.0))
    d = lambda q, n: (q / n) ** (2 / 3)  # noqa: E731
    assert d(plus, 3) - d(pre, 3) == pytest.approx(d(pre, 1) - d(minus, 1), rel=1e-9)
