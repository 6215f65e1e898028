"""Regenerate the shipped time records (synthetic, seeded): ``python problems/data/generate_timerecord.py``.

table_x_run_est.csv (10 s) and table_x_run_val.csv (6 s): the axis of table_x.yaml under its PD position
loop, 1 kHz, trapezoidal moves of 2..350 mm/s in both directions.  Recorded: time, table position (1 um
scale, quantised), motor force at the table (the drive's current times its force constant) and the position
reference.  The axis: 620 kg moving (table 306 kg plus the screw and motor inertia reflected through the
10 mm lead), Coulomb 500 N, viscous 1200 N s/m, and a hidden Stribeck rise of 160 N decaying with
3 mm/s -- the friction the design model does not have.  Simulated by axisopt.identify.timesynth.

table_x_ripple_est.csv (8 s) and table_x_ripple_val.csv (5 s): the same axis without the Stribeck rise but
with a force ripple of 45 N over 25 mm of travel (a nut whose ball circuit spans 2.5 turns of the 10 mm
lead) -- a period that is no harmonic of the lead, so no effect of the library explains it: the example of
the 'unexplained' verdict.

table_x_backlash_est.csv (10 s) and table_x_backlash_val.csv (6 s): the same axis without the Stribeck rise,
its motor side (150 kg of the 620 kg, reflected) tied to the table through a transmission that resonates at
30 Hz (damping ratio 0.1) and loses 25 um of motion at each reversal; the PD loop (3 Hz) closes on the table's
scale, and the motor encoder's position is recorded too (0.1 um, as table travel): the example of the
lost-motion measurement.
"""

from pathlib import Path

from axisopt.identify.timesynth import AxisTruth, LoopSettings, simulate_axis

HERE = Path(__file__).resolve().parent
TRUTH = AxisTruth(mass=620.0, viscous=1200.0, coulomb=500.0, stribeck=160.0, stribeck_v=0.003)
RIPPLE = AxisTruth(mass=620.0, viscous=1200.0, coulomb=500.0, ripple=45.0, ripple_period=0.025)
BACKLASH = AxisTruth(mass=620.0, viscous=1200.0, coulomb=500.0, mode_hz=30.0, mode_zeta=0.1, mode_mass=150.0,
                     backlash=25e-6)
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
    print("wrote table_x_run_est.csv, table_x_run_val.csv, table_x_ripple_est.csv, table_x_ripple_val.csv, "
          "table_x_backlash_est.csv, table_x_backlash_val.csv")


if __name__ == "__main__":
    main()
