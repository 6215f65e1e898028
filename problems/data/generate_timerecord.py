"""Regenerate the shipped time records (synthetic, seeded): ``python problems/data/generate_timerecord.py``.

table_x_run_est.csv (10 s) and table_x_run_val.csv (6 s): the axis of table_x.yaml under its PD position
loop, 1 kHz, trapezoidal moves of 2..350 mm/s in both directions.  Recorded: time, table position (1 um
scale, quantised), motor force at the table (the drive's current times its force constant) and the position
reference.  The axis: 620 kg moving (table 306 kg plus the screw and motor inertia reflected through the
10 mm lead), Coulomb 500 N, viscous 1200 N s/m, and a hidden Stribeck rise of 160 N decaying with
3 mm/s -- the friction the design model does not have.  Simulated by axisopt.identify.records.synth.

table_x_ripple_est.csv (8 s) and table_x_ripple_val.csv (5 s): the same axis without the Stribeck rise but
with a force ripple of 45 N over 25 mm of travel (a nut whose ball circuit spans 2.5 turns of the 10 mm
lead) -- a period that is no harmonic of the lead, so no effect of the library explains it: the example of
the 'unexplained' verdict.

table_x_backlash_est.csv (10 s) and table_x_backlash_val.csv (6 s): the same axis without the Stribeck rise,
its motor side (150 kg of the 620 kg, reflected) tied to the table through a transmission that resonates at
30 Hz (damping ratio 0.1) and loses 25 um of motion at each reversal; the PD loop (3 Hz) closes on the table's
scale, and the motor encoder's position is recorded too (0.1 um, as table travel): the example of the
lost-motion measurement.

The three effects only time records show (each physics written here, apart from the identification's columns,
and handed to the simulator as its ``extra_force`` or ``extra_friction``), on the same axis without the
Stribeck rise, 8 s estimation and 5 s validation runs:

* table_x_pump_est.csv / _val.csv: a coolant pump on the machine bed running at 870 rpm shakes the table with
  55 N at 14.5 Hz (a force in time, whatever the axis does; each run meets it at its own phase);
* table_x_spot_est.csv / _val.csv: a dry spot on the rails at 400 mm raises the friction by 140 N over a
  Gaussian of 6 mm standard width, both directions;
* table_x_warmup_est.csv / _val.csv: the guides' grease starts cold: the friction is 180 N above its warm level
  at the start of each run and settles with a time constant of 4 s.
"""

import math
from dataclasses import replace
from pathlib import Path

from axisopt.identify.records.synth import AxisTruth, LoopSettings, simulate_axis

HERE = Path(__file__).resolve().parent
TRUTH = AxisTruth(mass=620.0, viscous=1200.0, coulomb=500.0, stribeck=160.0, stribeck_v=0.003)
RIPPLE = AxisTruth(mass=620.0, viscous=1200.0, coulomb=500.0, ripple=45.0, ripple_period=0.025)
BACKLASH = AxisTruth(mass=620.0, viscous=1200.0, coulomb=500.0, mode_hz=30.0, mode_zeta=0.1, mode_mass=150.0,
                     backlash=25e-6)
PLAIN = AxisTruth(mass=620.0, viscous=1200.0, coulomb=500.0)


def pump_force(t, x, v):
    """55 N at 870 rpm (14.5 Hz): a force on the table the drive must supply [N]."""
    return 55.0 * math.sin(2.0 * math.pi * 14.5 * t + 0.4)


def dry_spot(t, x):
    """140 N more friction at 400 mm, Gaussian of 6 mm standard width [N]."""
    return 140.0 * math.exp(-0.5 * ((x - 0.4) / 0.006) ** 2)


def cold_grease(t, x):
    """180 N more friction at the start of a run, settling with 4 s [N]."""
    return 180.0 * math.exp(-t / 4.0)


NEW = {"pump": (replace(PLAIN, extra_force=pump_force), 41),
       "spot": (replace(PLAIN, extra_friction=dry_spot), 37),
       "warmup": (replace(PLAIN, extra_friction=cold_grease), 45)}
WITH_MOTOR = ("time", "position", "force", "reference", "motor_position")


def backlash():
    loop = LoopSettings(bandwidth_hz=3.0)
    simulate_axis(BACKLASH, loop, duration=10.0, seed=27, record_motor=True).write_csv(
        HERE / "table_x_backlash_est.csv", columns=WITH_MOTOR)
    simulate_axis(BACKLASH, loop, duration=6.0, seed=28, record_motor=True).write_csv(
        HERE / "table_x_backlash_val.csv", columns=WITH_MOTOR)


def main():
    simulate_axis(TRUTH, duration=10.0, seed=7).write_csv(HERE / "table_x_run_est.csv")
    simulate_axis(TRUTH, duration=6.0, seed=8).write_csv(HERE / "table_x_run_val.csv")
    simulate_axis(RIPPLE, duration=8.0, seed=17).write_csv(HERE / "table_x_ripple_est.csv")
    simulate_axis(RIPPLE, duration=5.0, seed=18).write_csv(HERE / "table_x_ripple_val.csv")
    backlash()
    for name, (truth, seed) in NEW.items():
        simulate_axis(truth, duration=8.0, seed=seed).write_csv(HERE / f"table_x_{name}_est.csv")
        simulate_axis(truth, duration=5.0, seed=seed + 1).write_csv(HERE / f"table_x_{name}_val.csv")
    print("wrote table_x_run_est.csv, table_x_run_val.csv, table_x_ripple_est.csv, table_x_ripple_val.csv, "
          "table_x_backlash_est.csv, table_x_backlash_val.csv and table_x_{pump,spot,warmup}_{est,val}.csv")


if __name__ == "__main__":
    main()
