"""The rack-and-pinion and linear-motor sub-assemblies (model.rackdrive, model.lmdrive) evaluate alike on
floats, numpy arrays and CasADi symbols, and their sizing follows the vendors' steps (restated here)."""

from __future__ import annotations

import casadi as ca
import numpy as np
import pytest

from axisopt.model.lmdrive import lm_response
from axisopt.model.rackdrive import guide_response, rack_response
from axisopt.physics.motion import Segment, cycle_phases
from axisopt.physics.rack import cycle_gram

CYCLE = cycle_gram(
    cycle_phases(
        (
            Segment("move", distance=2.0, speed=0.67, acceleration=3.0, force=750.0),
            Segment("move", distance=-2.0, speed=0.67, acceleration=3.0),
            Segment("dwell", duration=0.5),
        )
    )
)
RACK = {
    "m_axis": 600.0,
    "m_parts": 30.0,
    "m_blocks": 8.0,
    "mu": 0.004,
    "f_seal": 20.0,
    "normal": 500.0,
    "vertical": 0.0,
    "d": 0.0637,
    "perm": 20.1e3,
    "k_o": 1.25,
    "face": 0.03,
    "err": 25e-6,
    "stroke": 6.0,
    "ratio": 7.0,
    "eta": 0.97,
    "j_motor": 2e-3,
    "j_red": 1e-4,
    "t_rated": 7.16,
    "t_peak": 35.3,
    "n_max": 209.0,
    "t2b": 300.0,
    "t2n": 120.0,
    "n1max": 600.0,
    "backlash": 8.7e-4,
    "kt_red": 3e5,
    "twin": 1.0,
    "bias": 0.15,
    "rms_ratio": 0.8,
    "max_inertia_ratio": 5.0,
    "k_n": 3e8,
    "blocks": 2.0,
    "v_max": 0.67,
    "thrust": 900.0,
    "mean_thrust": 300.0,
}
LM = {
    "m_axis": 100.0,
    "m_blocks": 4.0,
    "mu": 0.004,
    "f_seal": 10.0,
    "normal": 0.0,
    "vertical": 0.0,
    "forcers": 2.0,
    "fc": 875.0,
    "fp": 2469.0,
    "kf": 60.0,
    "m_forcer": 14.5,
    "fa": 4375.0,
    "accuracy": 4e-6,
    "t_acc": 0.2,
    "bandwidth": 50.0,
    "k_n": 4e8,
    "blocks": 4.0,
    "thrust": 200.0,
    "mean_thrust": 100.0,
}
GUIDE = {
    "vertical": 0.0,
    "normal": 500.0,
    "blocks": 2.0,
    "c_block": 38e3,
    "c0_block": 52e3,
    "roller": 0.0,
    "rating_distance": 5e4,
    "fw": 1.2,
    "life_needed": 2e7,
    "static_safety": 5.0,
}


def _flatten(res):
    return {
        **{"o_" + k: v for k, v in res["outputs"].items()},
        **{"m_" + k: v for k, v in res["margins"].items()},
    }


@pytest.mark.parametrize("which", ["rack", "lm", "guide"])
def test_float_numpy_casadi_agree(which):
    base = {"rack": RACK, "lm": LM, "guide": GUIDE}[which]

    def run(p):
        if which == "rack":
            return _flatten(rack_response(p, CYCLE))
        if which == "lm":
            return _flatten(lm_response(p, CYCLE))
        return _flatten(guide_response(p, 640.0, 3000.0))

    floats = run(base)
    arrays = run({k: np.array([v, v]) for k, v in base.items()})
    keys = sorted(base)
    xs = ca.SX.sym("x", len(keys))
    sym = run({k: xs[i] for i, k in enumerate(keys)})
    names = sorted(floats)
    fun = ca.Function("f", [xs], [ca.vertcat(*[ca.SX(sym[n]) for n in names])])
    vals = np.array(fun(np.array([base[k] for k in keys]))).ravel()
    for n, v in zip(names, vals):
        assert np.isfinite(float(floats[n])), n
        assert np.asarray(arrays[n]).ravel()[0] == pytest.approx(float(floats[n]), rel=1e-12), n
        assert v == pytest.approx(float(floats[n]), rel=1e-10, abs=1e-12), n


def test_rack_sizing_restated_by_hand():
    """The rack model's peak feed force, tooth force, motor peak torque and stiffness, by the vendors' steps
    written out for the acceleration phase of this cycle (THK A-241, Apex, Yaskawa 11.2.4)."""
    p = RACK
    m = p["m_axis"] + p["m_parts"] + p["m_blocks"]
    resist = p["mu"] * (m * 9.80665 + p["normal"]) + p["f_seal"]
    f_acc = m * 3.0 + resist + 750.0  # accelerating against the process force
    res = rack_response(p, CYCLE)
    assert res["outputs"]["feed_force"] == pytest.approx(f_acc, rel=1e-12)
    tooth = f_acc / 2 + 0.15 * f_acc  # twin pinion: half the force plus the bias
    assert res["margins"]["pinion_tooth"] == pytest.approx(20.1e3 / 1.25 / tooth, rel=1e-12)
    r = p["d"] / 2
    t_motor = (p["j_motor"] + p["j_red"]) * 3.0 * p["ratio"] / r + tooth * r / (
        p["ratio"] * p["eta"]
    )
    assert res["outputs"]["motor_peak_torque"] == pytest.approx(t_motor, rel=1e-12)
    k = 1 / (1 / (2 * 20e9 * p["face"]) + 1 / (2 * p["kt_red"] / r**2))
    assert res["outputs"]["stiffness"] == pytest.approx(k, rel=1e-12)
    assert res["outputs"]["lost_motion"] == 0.0  # preloaded twin pinion
    one = rack_response({**p, "twin": 0.0}, CYCLE)
    assert one["outputs"]["lost_motion"] == pytest.approx(8.7e-4 * r, rel=1e-12)
    assert one["margins"]["pinion_tooth"] == pytest.approx(20.1e3 / 1.25 / f_acc, rel=1e-12)
