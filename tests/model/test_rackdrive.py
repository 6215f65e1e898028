"""The rack-and-pinion and linear-motor sub-assemblies (model.rackdrive, model.lmdrive) evaluate
alike on floats, numpy arrays and CasADi symbols, and their sizing follows the vendors' steps
(restated here)."""

from __future__ import annotations

import casadi as ca
import numpy as np
import pytest
from drive_cases import CYCLE, GUIDE, LM, RACK

from axisopt.model.lmdrive import lm_response
from axisopt.model.rackdrive import guide_response, rack_response


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
    """The rack model's peak feed force, tooth force, motor peak torque and stiffness, by the
    vendors' steps written out for the acceleration phase of this cycle (THK A-241, Apex, Yaskawa
    11.2.4)."""
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
