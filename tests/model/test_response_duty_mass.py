"""A duty-cycle entry's own moving mass (a workpiece loaded or unloaded) and the holding torque at a
stop, through the whole model, against THK's vertical conveyance example.

THK General Catalog, ball screw section, "Examples of Selecting a Ball Screw", vertical conveyance
system (A-736 to A-746): table m1 = 40 kg, work m2 = 10 kg, guide surface resistance f = 20 N
(without load), lead 10 mm, eta 0.9, J = 1.58e-4 kg m^2, Jm = 5e-5 kg m^2; up and down at 0.3 m/s
with 0.2 s ramps over 600 mm, then "When stationary (m2 = 0): TS = 658 N.mm, t4 = 7.6 s" (A-745: the
work removed, the guide resistance helping to hold); uniform motion Tt1 = 900 and Tt2 = 830 N.mm
(A-743); "the rated torque of the motor must be 743 N.mm or greater" (A-746).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from test_checks_life_duty_cycle import DESIGN as THK_VERTICAL

from axisopt.cli import main
from axisopt.design import design_to_yaml, load_design
from axisopt.model import axis_response, design_params, evaluate
from axisopt.physics import drive as pd
from axisopt.physics import life

G = 9.80665
CYCLE = """  duty_cycle:
    - {move: 600 mm}
    - {dwell: 3.8 s}
    - {move: -600 mm}
    - {dwell: 3.8 s}"""
# THK: up, down, then the stop with the work removed
THK_CYCLE = """  motor_inertia: 0.5 kg.cm^2
  duty_cycle:
    - {move: 600 mm}
    - {move: -600 mm}
    - {dwell: 7.6 s, moving_mass: 40 kg}"""


def _design(tmp_path: Path, cycle: str, name="d.yaml"):
    assert CYCLE in THK_VERTICAL
    path = tmp_path / name
    path.write_text(THK_VERTICAL.replace(CYCLE, cycle), encoding="utf-8")
    return path


def _thk_response(tmp_path):
    """THK's example through the model: its screw (15 mm x 800 mm), no coupling, no support-bearing
    drag (THK counts the guide resistance alone), no nut preload."""
    p = design_params(load_design(_design(tmp_path, THK_CYCLE)))
    p.update(coupling_inertia=0.0, bearing_torque=0.0, span=0.8)
    return axis_response(p, np.array([0.1]), "fixed-supported", 0.0)


@pytest.mark.published
def test_thk_stationary_torque_with_the_work_removed(tmp_path):
    out = _thk_response(tmp_path)
    torques = [float(t0) for t0, _ in out["duty_torques"]]
    assert out["load_inertia"] == pytest.approx(1.58e-4, abs=0.005e-4)
    assert torques[1] * 1e3 == pytest.approx(900, abs=3)  # A-743 Tt1 (THK's g 9.807, 510 N rounded)
    assert torques[4] * 1e3 == pytest.approx(830, abs=3)  # A-743 Tt2
    assert torques[-1] * 1e3 == pytest.approx(658, abs=0.5)  # A-745 TS (m2 = 0, f credited)
    assert out["rms_torque"] * 1e3 == pytest.approx(743, abs=1)
    # the brake holds the heaviest stop: the end of a move with the work on (no published figure;
    # THK's formula)
    assert out["holding_torque"] == pytest.approx(
        (50 * G - 20) * 0.010 / (2 * math.pi * 0.9), rel=1e-9
    )


@pytest.mark.published
def test_holding_torque_formula_thk_a745():
    # (m1 g - f) P_h / (2 pi eta) with THK's g = 9.807: 658 N.mm
    assert pd.holding_torque(40 * 9.807, 20.0, 0.010, 0.9) * 1e3 == pytest.approx(658, abs=0.5)
    # friction alone holds: no torque, never negative
    assert pd.holding_torque(10.0, 20.0, 0.010, 0.9) == 0.0


def test_dwell_without_its_own_mass_holds_the_axis_mass(tmp_path):
    p = design_params(load_design(_design(tmp_path, THK_CYCLE.replace(", moving_mass: 40 kg", ""))))
    out = axis_response(p, np.array([0.1]), "fixed-supported", 0.0)
    held = (50 * G - 20) * 0.010 / (2 * math.pi * 0.9)
    assert float(out["duty_torques"][-1][0]) == pytest.approx(held, rel=1e-9)
    assert float(out["holding_torque"]) == pytest.approx(held, rel=1e-9)


def test_a_dwells_force_is_held_and_counts_in_the_rms(tmp_path):
    base = evaluate(load_design(_design(tmp_path, THK_CYCLE, "a.yaml")), use_casadi=False).values
    held = evaluate(
        load_design(
            _design(
                tmp_path,
                THK_CYCLE.replace("moving_mass: 40 kg", "moving_mass: 40 kg, force: 1 kN"),
                "b.yaml",
            )
        ),
        use_casadi=False,
    ).values
    # the dwell holds 40 kg and 1 kN on gravity's side: more than the 50 kg stop, so the brake reads
    # it
    expected = (40 * G + 1000 - 20) * 0.010 / (2 * math.pi * 0.9)
    assert float(held["holding_torque"]) == pytest.approx(expected, rel=1e-9)
    assert float(held["rms_torque"]) > float(base["rms_torque"])


def test_life_loads_take_each_phases_mass(tmp_path):
    """Work lifted at 50 kg, brought down empty (40 kg): THK's phase loads (A-739) with each phase's
    mass."""
    cycle = CYCLE.replace("{move: -600 mm}", "{move: -600 mm, moving_mass: 40 kg}")
    ev = evaluate(load_design(_design(tmp_path, cycle)), use_casadi=False)
    g, f, a = G, 20.0, 1.5
    up, dn = 50.0, 40.0
    loads = [
        up * g + f + up * a,
        up * g + f,
        up * g + f - up * a,
        dn * g - f - dn * a,
        dn * g - f,
        dn * g - f + dn * a,
    ]
    travels = [0.03, 0.54, 0.03] * 2
    fm = life.cubic_mean(loads, travels)
    hours = float(ev.values["life"]) / 3600.0
    assert hours == pytest.approx((9800.0 / (1.5 * fm)) ** 3 * 1e6 / (600 * 60), rel=1e-9)
    full = evaluate(load_design(_design(tmp_path, CYCLE, "full.yaml")), use_casadi=False)
    assert hours > float(full.values["life"]) / 3600.0  # lighter on the way down: longer life


def test_lighter_phase_lowers_torques_and_regeneration(tmp_path):
    heavy = evaluate(load_design(_design(tmp_path, CYCLE, "h.yaml")), use_casadi=False).values
    light = evaluate(
        load_design(
            _design(
                tmp_path,
                CYCLE.replace("{move: -600 mm}", "{move: -600 mm, moving_mass: 30 kg}"),
                "l.yaml",
            )
        ),
        use_casadi=False,
    ).values
    assert float(light["rms_torque"]) < float(heavy["rms_torque"])
    assert float(light["regen_energy"]) < float(heavy["regen_energy"])  # less weight lowered
    # the lift is unchanged
    assert float(light["peak_torque"]) == pytest.approx(float(heavy["peak_torque"]))


def test_phase_mass_is_written_back(tmp_path):
    d = load_design(_design(tmp_path, THK_CYCLE))
    assert d.axis.duty_cycle[-1].moving_mass == 40.0
    again = tmp_path / "again.yaml"
    again.write_text(design_to_yaml(d, inline_parts=True), encoding="utf-8")
    assert load_design(again).axis.duty_cycle == d.axis.duty_cycle


@pytest.mark.parametrize(
    "value, words",
    [
        ("-4 kg", "must be positive"),
        ("0 kg", "must be positive"),
        ("60 kg", "heavier than axis.moving_mass"),
        (".nan kg", "cannot read"),
        ("1e300 kg", "out of range"),
        ("40 mm", "unit"),
        ("40", "unit"),
    ],
)
def test_bad_phase_mass_is_one_line_exit_2(tmp_path, capsys, value, words):
    path = _design(tmp_path, THK_CYCLE.replace("moving_mass: 40 kg", f"moving_mass: {value}"))
    assert main(["evaluate", str(path)]) == 2
    err = capsys.readouterr().err.strip()
    assert err.startswith("error: ") and "\n" not in err, err
    assert "axis.duty_cycle[2].moving_mass" in err and words in err, err


def test_guide_block_loads_take_each_phases_mass():
    """A horizontal table that returns empty: the return's weight and inertia on the blocks are the
    empty table's, so the mean block load over the cycle falls, while the static load cases keep the
    axis's mass."""
    import dataclasses

    from axisopt.physics import motion

    root = Path(__file__).resolve().parents[2]
    d = load_design(root / "problems" / "vmc_x_design.yaml")
    cycle = (
        motion.Segment("move", distance=0.6, speed=0.4, acceleration=3.0),
        motion.Segment("move", distance=-0.6, speed=0.4, acceleration=3.0),
    )
    lighter = (cycle[0], dataclasses.replace(cycle[1], moving_mass=0.2 * d.axis.moving_mass))
    full = evaluate(
        dataclasses.replace(d, axis=dataclasses.replace(d.axis, duty_cycle=cycle)), use_casadi=False
    )
    empty = evaluate(
        dataclasses.replace(d, axis=dataclasses.replace(d.axis, duty_cycle=lighter)),
        use_casadi=False,
    )
    assert float(empty.values["guide_mean_load"]) < float(full.values["guide_mean_load"])
    assert float(empty.values["guide_max_load"]) == pytest.approx(
        float(full.values["guide_max_load"])
    )
    assert float(empty.values["guide_life"]) > float(full.values["guide_life"])
