"""The state-space model (model.statespace) is the model: its eigenfrequencies are the model's modes
at every nut position, its frequency response is ``--frf``'s curve; python-control round trip; the
servo rule's published examples (model.servo, physics.servo)."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from axisopt.design import load_design
from axisopt.model import design_params, evaluate
from axisopt.model.frf import chain_at, frf, frf_positions
from axisopt.model.statespace import second_order, state_space
from axisopt.physics import dynamics as pdy

PROBLEMS = Path(__file__).resolve().parents[2] / "problems"
DESIGNS = ("vmc_x_design.yaml", "teaching_design.yaml", "custom_parts_design.yaml")


@pytest.fixture(scope="module", params=DESIGNS)
def ev(request):
    return evaluate(load_design(PROBLEMS / request.param))


def test_open_loop_eigenfrequencies_are_the_model_modes_at_every_position(ev):
    for i in range(len(ev.x)):
        free = state_space(ev, i)
        f = free.natural_frequencies()
        assert f == pytest.approx(
            [ev.at("f_axial_torsional", i), ev.at("f_axial_torsional_2", i)], rel=1e-9
        )
        # the undamped A has the same frequencies as its eigenvalues (and the rigid-body pair at 0)
        lam = np.sort(np.abs(state_space(ev, i, damping_scale=0.0).poles())) / (2 * math.pi)
        assert lam[:2] == pytest.approx([0, 0], abs=1e-3)
        assert lam[2::2] == pytest.approx(f, rel=1e-7)
        held = state_space(ev, i, motor_held=True)
        m = held.mass.diagonal()
        r = held.lead / (2 * math.pi)
        k_c = held.stiffness[0, 0] - ev.at("k_drive", i) * r**2
        want = pdy.axial_torsional_frequencies(m[0], k_c, ev.at("k_drive", i), m[1], held.lead)
        assert held.natural_frequencies() == pytest.approx(want, rel=1e-9)
        # the headline axial mode f_axial (motor held) leaves out the screw's rotary inertia on
        # the coupling: the held model's first mode is at or below it and equal to it without that
        # inertia
        assert held.natural_frequencies()[0] <= ev.at("f_axial", i) * (1 + 1e-12)
        spring = chain_at(ev, design_params(ev.design), i)
        spring["screw_inertia"] = 1e-12 * spring["screw_inertia"]
        mass, stiff, _ = second_order(spring)
        lam = np.linalg.eigvals(np.linalg.solve(mass[1:, 1:], stiff[1:, 1:])).real
        assert math.sqrt(min(lam)) / (2 * math.pi) == pytest.approx(ev.at("f_axial", i), rel=1e-6)


@pytest.mark.parametrize("held", [False, True])
def test_frequency_response_equals_frf_curve(ev, held):
    r = frf(ev, motor_held=held)
    for q, i in zip(r["positions"], frf_positions(ev)):
        ss = state_space(ev, i, motor_held=held)
        h = ss.frequency_response(r["frequency_Hz"], "process_force", "table_position")
        np.testing.assert_allclose(h, q["compliance_m_per_N"], rtol=1e-9)
        assert tuple(ss.natural_frequencies()) == pytest.approx(q["modes_Hz"], rel=1e-9)


def test_python_control_round_trip(ev):
    control = pytest.importorskip("control")
    ss = state_space(ev, 0)
    sys = ss.to_control()
    assert isinstance(sys, control.StateSpace)
    np.testing.assert_array_equal(sys.A, ss.A)
    np.testing.assert_array_equal(sys.B, ss.B)
    assert list(sys.input_labels) == list(ss.inputs) and list(sys.output_labels) == list(ss.outputs)
    f = np.array([20.0, 84.0, 300.0])
    h = np.asarray(sys(2j * math.pi * f))[
        ss.outputs.index("table_position"), ss.inputs.index("process_force")
    ]
    np.testing.assert_allclose(h, ss.frequency_response(f), rtol=1e-9)
    held = state_space(ev, 0, motor_held=True).to_control()
    assert held.nstates == 4
