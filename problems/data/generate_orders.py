"""Regenerate the shipped runs with a line in motor orders (synthetic, seeded):
``python problems/data/generate_orders.py``.

table_x_cogging_est.csv (8 s) and table_x_cogging_val.csv (5 s): the axis of table_x_belt.yaml (the
axis of table_x.yaml through a 1.5:1 toothed belt, 32 teeth on the motor pulley) as in
generate_timerecord.py without the Stribeck rise (620 kg moving, Coulomb 500 N, viscous 1200 N s/m,
PD loop, 1 kHz), with a cogging force of 30 N at the table at order 8 of the motor turn: a period of
10 mm / (1.5 x 8) = 0.833 mm in the table's travel.  Simulated by axisopt.identify.records.synth.
"""

from pathlib import Path

from axisopt.identify.records.synth import AxisTruth, simulate_axis

HERE = Path(__file__).resolve().parent
LEAD, RATIO, ORDER = 0.010, 1.5, 8
AXIS = AxisTruth(
    mass=620.0,
    viscous=1200.0,
    coulomb=500.0,
    stribeck=0.0,
    stribeck_v=0.003,
    ripple=30.0,
    ripple_period=LEAD / (RATIO * ORDER),
    ripple_phase=0.4,
)


def main():
    simulate_axis(AXIS, duration=8.0, seed=81).write_csv(HERE / "table_x_cogging_est.csv")
    simulate_axis(AXIS, duration=5.0, seed=82).write_csv(HERE / "table_x_cogging_val.csv")
    print("wrote table_x_cogging_est.csv and table_x_cogging_val.csv")  # noqa: T201


if __name__ == "__main__":
    main()
