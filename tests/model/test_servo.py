"""The state-space model (model.statespace) is the model: its eigenfrequencies are the model's modes
at every nut position, its frequency response is ``--frf``'s curve; python-control round trip; the
servo rule's published examples (model.servo, physics.servo)."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from axisopt.design import load_design
from axisopt.model import evaluate
from axisopt.model.frf import frf_positions
from axisopt.model.servo import closed_loop, servo_response
from axisopt.model.statespace import state_space
from axisopt.physics.servo import following_error

PROBLEMS = Path(__file__).resolve().parents[2] / "problems"
DESIGNS = ("vmc_x_design.yaml", "teaching_design.yaml", "custom_parts_design.yaml")


@pytest.fixture(scope="module", params=DESIGNS)
def ev(request):
    return evaluate(load_design(PROBLEMS / request.param))


def test_tuned_servo_is_stable_on_the_model(ev):
    r = servo_response(ev)
    g = r.gains
    assert g.kv == pytest.approx(float(np.min(ev["f_axial"])))
    assert all(r.stable) and min(r.min_damping) > 0
    # the closed position loop is roughly first order at Kv: its -3 dB near Kv / 2 pi
    for bw in r.position_bandwidth_Hz:
        assert 0.8 * g.kv / (2 * math.pi) < bw < 2.0 * g.kv / (2 * math.pi)
    # at constant speed the motor lags v / Kv; the table as much again as the guides' viscous damper
    # deflects the chain (c_g v / k_total): ramp x_ref = v t, z(t) = z1 t + z0 with A z1 = -b v, A
    # z0 = z1
    i = frf_positions(ev)[1]
    A, B, C, D = closed_loop(state_space(ev, i), g)
    v = 0.1
    z1 = -np.linalg.solve(A, B[:, 0] * v)
    z0 = np.linalg.solve(A, z1)
    assert C[0] @ z1 == pytest.approx(v, rel=1e-9)
    assert -C[2] @ z0 == pytest.approx(following_error(v, g.kv), rel=1e-6)
    c_g = float(ev.design.guide["damping"]) * ev.design.axis.guide_blocks
    assert -C[0] @ z0 == pytest.approx(
        following_error(v, g.kv) + c_g * v / ev.at("k_total", i), rel=1e-3
    )
