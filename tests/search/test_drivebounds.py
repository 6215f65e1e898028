"""The per-drive least cost the screening and the explanation use (search.drivebounds.least_cost) is the least
over every guide and bearing combination, checked by enumeration."""

import numpy as np
import pytest
from lathe_z import lathe

from axisopt.model.cost import cost
from axisopt.search.drivebounds import hull_ends
from axisopt.search.drivebounds import least_cost as drive_least_cost
from axisopt.search.parts import build_space


@pytest.mark.slow  # over 10 s on an idle core: run by `pytest -m slow`
def test_least_cost_per_drive_is_the_least_over_guides_and_bearings(tmp_path):
    """The screening's and the explanation's per-drive cost bound (drivebounds.least_cost) is the least cost
    over the block's guides and each group's bearings, for every drive of the lathe's 4 531: every (guide,
    drive) combination evaluated."""
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
