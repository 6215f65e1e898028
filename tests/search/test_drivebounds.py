"""The per-drive least cost the screening and the explanation use (search.drivebounds.least_cost) is
the least over every guide and bearing combination, checked by enumeration."""

import numpy as np
import pytest
from lathe_z import lathe

from axisopt.model.cost import cost
from axisopt.search.drivebounds import hull_ends
from axisopt.search.drivebounds import least_cost as drive_least_cost
from axisopt.search.parts import build_space


@pytest.mark.slow  # over 10 s on an idle core: run by `pytest -m slow`
def test_least_cost_per_drive_is_the_least_over_guides_and_bearings(tmp_path):
    """The screening's and the explanation's per-drive cost bound (drivebounds.least_cost) is the
    least cost over the block's guides and each group's bearings, for every drive of the lathe's
    4 531: every (guide, drive) combination evaluated."""
    sp = build_space(lathe(tmp_path, "500 EUR"))
    B = sp.shape[2]
    for mounting in sp.mountings:
        nuts = np.array([0, sp.shape[1] // 2, sp.shape[1] - 1])
        _, group = hull_ends(sp, mounting, nuts, False)
        got = drive_least_cost(sp, mounting, nuts, group)
        for k in range(len(nuts)):
            every = np.asarray(cost(sp.params_drives(mounting, nuts[k : k + 1])), dtype=float)
            every = np.broadcast_to(every, (1, B) + every.shape[2:]).min(axis=2)[
                0
            ]  # (bearings, drives)
            for g in range(group.max() + 1):
                np.testing.assert_allclose(got[k, g], every[group == g].min(axis=0), rtol=1e-12)


def test_hull_rows_kept_on_the_space_bound_as_a_fresh_evaluation(tmp_path):
    """The per-nut rows drive_hull keeps on the space for the searches after the first (limit
    sensitivities, the cheaper design) are the fresh interval bounds rounded outward to float32: an
    upper end never below, a lower end never above, within float32's rounding; asked again (in
    another order, with another nut among them) they come from the store and are the same."""
    from axisopt.search.drivebounds import _drive_hull, _whole_hull, drive_hull
    from axisopt.search.task.constraints import build_constraints
    from axisopt.search.task.space import DRIVE_KEYS

    problem = lathe(tmp_path, "20000 EUR")
    sp = build_space(problem)
    assert not _whole_hull(sp)  # the store is used on this space
    cons = [c for c in build_constraints(problem) if c.key in DRIVE_KEYS]
    assert any(c.sense == ">=" for c in cons) and any(c.sense == "<=" for c in cons)
    mounting = sp.mountings[-1]
    nuts = np.array([3, sp.shape[1] // 2])
    fresh, group = _drive_hull(sp, mounting, nuts, cons)
    kept, g1 = drive_hull(sp, mounting, nuts, cons)
    np.testing.assert_array_equal(group, g1)
    for c in cons:
        f, k = fresh[c.name], kept[c.name]
        fin = np.isfinite(f)
        np.testing.assert_array_equal(fin, np.isfinite(k))
        assert (k[fin] >= f[fin]).all() if c.sense == ">=" else (k[fin] <= f[fin]).all()
        np.testing.assert_allclose(k[fin], f[fin], rtol=2e-7, atol=1e-30)
    again, _ = drive_hull(sp, mounting, np.array([1, 3, sp.shape[1] // 2]), cons)
    for c in cons:
        np.testing.assert_array_equal(again[c.name][1:], kept[c.name])
    fresh1, _ = _drive_hull(sp, mounting, np.array([1]), cons)
    for c in cons:
        np.testing.assert_allclose(again[c.name][0], fresh1[c.name][0], rtol=2e-7)
