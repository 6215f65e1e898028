"""A reduction part (planetary gearbox on the motor flange) in the axis model: catalog values in SI,
THK eq. 43-46 with the reduction ratio A, the vendor checks on the output side (Beckhoff AG2400 T2B,
T2N, n1Max), the torsional stiffness in series with the coupling's, the backlash as lost motion at
the table, and float = numpy = CasADi."""

from __future__ import annotations

import math
from dataclasses import replace
from pathlib import Path

import casadi as ca
import numpy as np
import pytest

from axisopt.catalog.loading import default_catalog
from axisopt.design import load_design
from axisopt.model import evaluate
from axisopt.model.chain import drive_torsional_stiffness
from axisopt.model.drive import lost_motion, output_torques
from axisopt.physics.motion import Segment, cycle_phases

ROOT = Path(__file__).resolve().parents[2]
ARCMIN = math.pi / 10800.0
MM, KG_CM2 = 1e-3, 1e-4


@pytest.mark.published
def test_beckhoff_tp050_row_in_si():
    # Beckhoff AG2400 TP050 MF "Mechanical data"
    # (infosys.beckhoff.com/content/1033/ag2400_ba/8995561355.html), i = 5: Ct21 187 Nm/arcmin, eta
    # 97 %, J1 (K = 38 mm) 12.1 kgcm^2, T2N 337, T2B 840 Nm, n1Max 5000 min^-1, jt <= 3
    r = default_catalog().part("reductions", "BK-TP050-MF-5")
    assert r["torsional_stiffness"] == pytest.approx(642_859, abs=0.5)  # 187 x 10800 / pi
    assert r["efficiency"] == pytest.approx(0.97)
    assert r["inertia"] == pytest.approx(12.1 * KG_CM2)
    assert (r["rated_torque"], r["accel_torque"]) == (337.0, 840.0)
    assert r["max_input_speed"] == pytest.approx(5000 * 2 * math.pi / 60)
    assert r["backlash"] == pytest.approx(3 * ARCMIN)
    # TP010 MF i = 5 (…/8995369483.html): Ct21 33 Nm/arcmin -> 113 446 N m/rad; TP300 MF i = 5: 1000
    # -> 3 437 747
    tp010 = default_catalog().part("reductions", "BK-TP010-MF-5")
    assert tp010["torsional_stiffness"] == pytest.approx(113_446, abs=0.5)
    assert default_catalog().part("reductions", "BK-TP300-MF-5")[
        "torsional_stiffness"
    ] == pytest.approx(3_437_747, abs=0.5)


def _thk_example_1(a=1.0):
    """THK A-722..A-735 (example 1, horizontal transfer): m 80 kg, lead 40 mm, screw 20 mm x 1200
    mm, friction T1 = 120 N mm (A-733), t1 0.15 s to 1 m/s; as model parameters (no coupling
    inertia, no gravity)."""
    return {
        "lead": 40 * MM,
        "nominal_diameter": 20 * MM,
        "span": 1.2,
        "coupling_inertia": 0.0,
        "gravity_axial": 0.0,
        "table_mass": 80.0,
        "axial_load": 0.0,
        "mean_axial_load": 0.0,
    }


@pytest.mark.published
def test_output_torque_is_thk_eq_45_at_the_screw():
    # THK A-733: load inertia J = 3.39e-3 kg m^2 (table 80 kg through the 40 mm lead plus the
    # screw), friction torque T1 = 120 N mm; the torque at the screw (the reduction's output) in the
    # acceleration is J w' + T1, w' = 2 pi / P_h x a, without the rotor's J_m w' (THK's Tmax 4730 N
    # mm includes Jm = 1e-3 kg m^2 x w')
    p = _thk_example_1()
    phases = cycle_phases((Segment("move", distance=1.0, speed=1.0, acceleration=1.0 / 0.15),))
    torques, thrust, _ = output_torques(p, 80.0, 0.120, phases)
    w_dot = 2 * math.pi / 0.040 / 0.15
    assert torques[0][0] == pytest.approx(3.39e-3 * w_dot + 0.120, rel=5e-3)
    # A-734 less the rotor's
    assert torques[0][0] * 1e3 == pytest.approx(4730 - 1e-3 * w_dot * 1e3, rel=5e-3)
    assert thrust == pytest.approx(0.120)


def test_motor_torque_through_the_reduction_is_thk_eq_43_45_with_a():
    # THK eq. 43 and 45 with the reduction ratio A = 1/i: the motor's acceleration torque is the
    # output's inertia torque / i plus (J_rotor + J_reduction) w'_motor, its friction the drag / (i
    # eta)
    d = load_design(ROOT / "problems" / "vmc_x_design.yaml")
    red = default_catalog().part("reductions", "BK-TP050-MF-5")
    base = evaluate(replace(d, reduction=red), use_casadi=False).values
    i, eta = float(red["ratio"]), float(red["efficiency"])
    lead = float(d.screw["lead"])
    # at the motor, the load side of the gear
    j_out = float(base["load_inertia"]) - float(red["inertia"])
    assert float(base["load_inertia"]) == pytest.approx(
        evaluate(d, use_casadi=False).values["load_inertia"] / i**2 + float(red["inertia"]),
        rel=1e-9,
    )
    assert float(base["friction_torque"]) == pytest.approx(
        evaluate(d, use_casadi=False).values["friction_torque"] / (i * eta), rel=1e-9
    )
    assert j_out > 0 and lead > 0
    # motor speed 6000 rpm at 24 m/min on the 20 mm lead x 5 (THK eq. 46: N = V / (P_h A))
    assert float(base["motor_speed"]) * 60 / (2 * math.pi) == pytest.approx(24 / 0.020 * 5)


def test_reduction_checks_and_stiffness_in_series():
    d = load_design(ROOT / "problems" / "vmc_x_design.yaml")
    red = default_catalog().part("reductions", "BK-TP050-MF-5")
    v0 = evaluate(d, use_casadi=False).values
    v = evaluate(replace(d, reduction=red), use_casadi=False).values
    # the vendor's limits over the output torques of the cycle and the motor speed
    assert v["margin_reduction_accel_torque"] == pytest.approx(840.0 / v["output_peak_torque"])
    assert v["margin_reduction_rated_torque"] == pytest.approx(337.0 / v["output_rms_torque"])
    assert v["margin_reduction_speed"] == pytest.approx(5000.0 / 6000.0)
    assert v0["margin_reduction_speed"] >= 1e9  # no reduction: not applicable
    # the output torques are the screw side's: the same whatever the gear's ratio (the coupling and
    # load are); a design without a reduction reports none
    v7 = evaluate(
        replace(d, reduction=default_catalog().part("reductions", "BK-TP050-MF-7")),
        use_casadi=False,
    ).values
    assert v["output_peak_torque"] == pytest.approx(v7["output_peak_torque"])
    assert v["output_peak_torque"] > 0.0 and v0["output_peak_torque"] == 0.0
    # torsional stiffness: coupling and gear in series (k_coupling is the axial equivalent through
    # the lead)
    k_c = float(d.coupling["torsional_stiffness"])
    k_t = 1.0 / (1.0 / k_c + 1.0 / 642_858.6461)
    lead = float(d.screw["lead"])
    assert v["k_coupling"] == pytest.approx(k_t * (2 * math.pi / lead) ** 2, rel=1e-6)
    assert v0["k_coupling"] == pytest.approx(k_c * (2 * math.pi / lead) ** 2, rel=1e-9)
    # lost motion: 3 arcmin through the 20 mm lead = 2.78 um; the cost takes the (illustrative)
    # price
    assert v["backlash"] == pytest.approx(3 * ARCMIN * lead / (2 * math.pi))
    assert v["cost"] - v0["cost"] == pytest.approx(float(red["price"]))


def test_casadi_and_numpy_evaluations_agree_with_a_reduction():
    d = load_design(ROOT / "problems" / "vmc_x_design.yaml")
    d = replace(d, reduction=default_catalog().part("reductions", "BK-NPT035-MF-4"))
    a, b = evaluate(d, use_casadi=True).values, evaluate(d, use_casadi=False).values
    for k in (
        "margin_reduction_accel_torque",
        "margin_reduction_rated_torque",
        "margin_reduction_speed",
        "output_peak_torque",
        "output_rms_torque",
        "backlash",
        "k_coupling",
        "cost",
        "peak_torque",
    ):
        assert np.allclose(a[k], b[k], rtol=1e-10), k


def _sym_or(values, backend):
    if backend == "float":
        return {k: float(v[1]) for k, v in values.items()}, None
    if backend == "numpy":
        return {k: np.asarray(v, dtype=float) for k, v in values.items()}, None
    syms = {k: ca.SX.sym(k) for k in values}
    return syms, syms


@pytest.mark.parametrize("backend", ["float", "numpy", "casadi"])
def test_new_model_terms_on_float_numpy_casadi(backend):
    """lost_motion, drive_torsional_stiffness and output_torques agree on floats, numpy arrays and
    CasADi."""
    vals = {
        "nut_double": (1.0, 0.0, 1.0),
        "nut_axial_play": (0.0, 10e-6, 0.0),
        "reduction_backlash": (3 * ARCMIN, 8 * ARCMIN, 0.0),
        "lead": (0.01, 0.02, 0.04),
        "coupling_stiffness": (5e4, 1e5, 2e5),
        "reduction_compliance": (1 / 6e5, 1 / 8e4, 0.0),
        "nominal_diameter": (0.032, 0.04, 0.05),
        "span": (0.8, 1.0, 1.2),
        "coupling_inertia": (1e-4, 2e-4, 3e-4),
        "gravity_axial": (0.0, 1.0, 0.0),
        "table_mass": (200.0, 300.0, 400.0),
        "axial_load": (1000.0, 2000.0, 3000.0),
        "mean_axial_load": (300.0, 600.0, 900.0),
    }
    phases = cycle_phases(
        (
            Segment("move", distance=0.4, speed=0.4, acceleration=3.0),
            Segment("dwell", duration=0.5, force=500.0),
            Segment("move", distance=-0.4, speed=0.4, acceleration=3.0),
        )
    )

    def compute(p):
        t, thrust, mean = output_torques(p, p["table_mass"] + 10.0, 0.5 + 0.0 * p["lead"], phases)
        return [
            lost_motion(p),
            drive_torsional_stiffness(p),
            thrust,
            mean,
            *(x for pair in t for x in pair),
        ]

    ref = [np.asarray(compute({k: v[i] for k, v in vals.items()}), dtype=float) for i in range(3)]
    p, syms = _sym_or(vals, backend)
    out = compute(p)
    if backend == "casadi":
        f = ca.Function("f", list(syms.values()), [ca.vertcat(*out)])
        got = np.asarray(f(*[v[1] for v in vals.values()])).ravel()
        assert np.allclose(got, ref[1], rtol=1e-12)
    elif backend == "numpy":
        got = np.array([np.broadcast_to(np.asarray(x, dtype=float), (3,)) for x in out])
        assert np.allclose(got, np.stack(ref, axis=1), rtol=1e-12)
    else:
        assert np.allclose(np.asarray(out, dtype=float), ref[1], rtol=1e-12)
