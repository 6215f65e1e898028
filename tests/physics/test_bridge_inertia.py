"""The bridge's yaw inertia from its parts (physics.gantry.bridge_yaw_inertia), against the
rigid-body sum written
here: a slender beam about its centre m L^2 / 12, point masses at +-L/2 by the parallel-axis
theorem."""

import pytest

from axisopt.physics.gantry import UPRIGHT_SHARE, bridge_yaw_inertia, bridge_yaw_inertia_estimate


def test_beam_and_uprights():
    m, L, mu = 900.0, 2.2, 300.0
    beam = (m - mu) * L**2 / 12
    ends = 2 * (mu / 2) * (L / 2) ** 2
    assert bridge_yaw_inertia(m, L, mu) == pytest.approx(beam + ends)
    assert bridge_yaw_inertia(m, L, 0.0) == pytest.approx(bridge_yaw_inertia_estimate(m, L))
    # the default: half the bridge in its uprights, twice the uniform beam's inertia (conservative
    # for racking)
    assert bridge_yaw_inertia(m, L, UPRIGHT_SHARE * m) == pytest.approx(m * L**2 / 6)
