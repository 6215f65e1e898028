"""The drive parameters the rack-and-pinion and linear-motor model tests share
(tests/model/test_rackdrive.py, tests/model/test_lmdrive.py): a 2 m cycle against a 750 N process
force, a twin-pinion rack axis, a two-forcer linear-motor axis and a guide pair (vendor-like values
in SI)."""

from __future__ import annotations

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
