"""Yaskawa Σ-7 capacity-selection examples for a horizontal ball screw, reproduced through the
model's drive sub-assembly (:func:`axisopt.model.drive.drive`) and the duty-cycle phases
(:mod:`axisopt.physics.motion`).

Source: Yaskawa Σ-7-Series Rotary Servomotor Product Manual, chapter 2 "Capacity Selection" (stored
copies at manualshive.com, manual 3259625 / 907516, pages 37-40; manual pp. 2-2 to 2-5):

* §2.1.1 speed control: 250 kg, screw 20 mm x 1.0 m, lead 10 mm, density 7.87e3, gear 1/2 with gear
  and coupling inertia 0.40e-4 kg m^2, 40 feeds/min of 0.275 m at 15 m/min in at most 1.2 s, mu 0.2,
  eta 0.9.  Printed: TL 0.43 N m, JL 2.29e-4 kg m^2 (JL1 1.58e-4, JB 0.31e-4, JG 0.40e-4), ta = td
  0.1 s, tc 1.0 s, TP 1.23 N m, TS 0.37 N m, Trms 0.483 N m.
* §2.1.2 position control: 80 kg, screw 16 mm x 0.8 m, lead 5 mm, coupling 0.3 kg x 30 mm, 40
  feeds/min of 0.25 m at 15 m/min, settling 0.1 s.  Printed: TL 0.139 N m, JL1 0.507e-4, JB
  0.405e-4, JC 0.338e-4, JL 1.25e-4 kg m^2, ta 0.1 s, tc 0.9 s; provisionally selected SGM7J-01A
  (allowable load inertia 35 x rotor).
"""

from math import pi

import pytest

from axisopt.catalog.loading import default_catalog
from axisopt.model.drive import drive
from axisopt.physics import drive as pdrive
from axisopt.physics import motion

G_YASKAWA = 9.8  # the manual's g


def _params(mass_lead_screw, coupling_inertia, ratio, reduction_inertia, rotor, **motor):
    lead, d, length = mass_lead_screw
    p = {
        "reduction_ratio": ratio,
        "reduction_efficiency": 1.0,
        "reduction_inertia": reduction_inertia,
        "nominal_diameter": d,
        "root_diameter": d,
        "span": length,
        "lead": lead,
        "coupling_inertia": coupling_inertia,
        "rotor_inertia": rotor,
        "gravity_axial": 0.0,
        "axial_load": 0.0,
        "mean_axial_load": 0.0,
        "has_motor": 1.0,
        "has_coupling": 0.0,
        "max_inertia_ratio": 35.0,
        "brake_safety": 2.0,
        "motor_brake_torque": 0.0,
        "coupling_rated_torque": 1.0,
        "coupling_max_speed": 1.0,
        # no reduction part (issue 39): its checks do not apply
        "has_reduction": 0.0,
        "reduction_rated_torque": 1.0,
        "reduction_accel_torque": 1.0,
        "reduction_max_speed": 1.0,
    }
    # Yaskawa's selection rule: RMS torque within the rated torque (no margin, sec. 2.4.1)
    p.update(
        {
            "motor_rated_torque": 1.0,
            "motor_peak_torque": 1.0,
            "motor_max_speed": 1.0,
            "rms_torque_ratio": 1.0,
            "motor_peak_corner_speed": 1.0,
            "motor_peak_at_max_speed": 1.0,
        }
    )
    p.update(motor)
    return p


def _cycle(distance, speed, t_acc, cycle_time):
    seg = motion.Segment("move", distance=distance, speed=speed, acceleration=speed / t_acc)
    phases = motion.cycle_phases([seg])
    dwell = cycle_time - motion.cycle_time(phases)
    return motion.cycle_phases([seg, motion.Segment("dwell", duration=dwell)])


def test_speed_control_example_torques_and_rms():
    mass, lead, ratio = 250.0, 0.01, 2.0
    phases = _cycle(0.275, 15.0 / 60.0, 0.1, 60.0 / 40.0)
    # the move splits as printed: ta = td = 0.1 s, tc = 1.0 s, dwell 0.3 s
    assert [round(ph.duration, 6) for ph in phases] == [0.1, 1.0, 0.1, 0.3]
    # friction mu m g at the table, referred to the screw through eta 0.9 (the model's drag torque)
    drag = pdrive.force_torque(0.2 * mass * G_YASKAWA, lead, 0.9)
    # JM: the 200 W SGM7J-02A (the page naming the pick was not retrieved; its rotor gives TP and TS
    # as printed)
    p = _params((lead, 0.02, 1.0), 0.0, ratio, 0.40e-4, 0.263e-4)
    p["duty"] = phases
    out = drive(p, mass, drag)
    assert out["friction_torque"] == pytest.approx(0.43, abs=0.005)
    # 7850 kg/m^3 against the 7870 printed
    assert out["load_inertia"] == pytest.approx(2.29e-4, abs=0.005e-4)
    assert out["motor_speed"] * 60 / (2 * pi) == pytest.approx(3000.0)
    torques = out["duty_torques"]
    assert torques[0][0] == pytest.approx(1.23, abs=0.01)  # TP
    assert -torques[2][0] == pytest.approx(0.37, abs=0.01)  # TS (decelerating, friction helps)
    # printed from the rounded TP, TL, TS
    assert out["rms_torque"] == pytest.approx(0.483, rel=0.01)


def test_position_control_example_selects_sgm7j_01a():
    mass, lead = 80.0, 0.005
    phases = _cycle(0.25, 15.0 / 60.0, 0.1, 60.0 / 40.0)
    assert [round(ph.duration, 6) for ph in phases[:3]] == [0.1, 0.9, 0.1]
    drag = pdrive.force_torque(0.2 * mass * G_YASKAWA, lead, 0.9)
    j_coupling = 0.3 * 0.03**2 / 8.0  # JC = mC dC^2 / 8
    motors = default_catalog().motors
    sgm7j = motors[motors["series"] == "Sigma-7 SGM7J"].sort_values("rated_torque")
    passing = []
    for mid, m in sgm7j.iterrows():
        p = _params(
            (lead, 0.016, 0.8),
            j_coupling,
            1.0,
            0.0,
            float(m["rotor_inertia"]),
            motor_rated_torque=float(m["rated_torque"]),
            motor_peak_torque=float(m["peak_torque"]),
            motor_max_speed=float(m["max_speed"]),
            # the intermittent zone the model estimates where the vendor prints no corner values
            motor_peak_corner_speed=min(float(m["rated_speed"]), 0.5 * float(m["max_speed"])),
            motor_peak_at_max_speed=float(m["rated_torque"]),
        )
        p["duty"] = phases
        out = drive(p, mass, drag)
        assert out["friction_torque"] == pytest.approx(0.139, abs=0.0005)
        assert out["load_inertia"] == pytest.approx(1.25e-4, abs=0.005e-4)
        margins = [
            out[f"margin_{c}"]
            for c in ("motor_peak_torque", "motor_rated_torque", "motor_speed", "inertia_ratio")
        ]
        if min(margins) >= 1.0:
            passing.append(mid)
    # the smallest motor meeting peak, RMS, speed and Yaskawa's 35x load-inertia limit is Yaskawa's
    # pick
    assert passing[0] == "SGM7J-01A"
