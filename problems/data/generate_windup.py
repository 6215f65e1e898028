"""Regenerate the shipped windup example (synthetic, seeded): ``python
problems/data/generate_windup.py``.

table_x_windup_est.csv (10 s) and table_x_windup_val.csv (6 s): the table_x axis as two masses, its
motor side (150 kg of the 620 kg, reflected to the table) with a friction of its own, 180 N Coulomb
and 500 N.s/m viscous (motor and support bearings, seals: it acts before the gap), tied to the table
(320 N, 1 200 N.s/m on the guides) through a transmission of 4 N/um that loses 25 um at each
reversal; a P-PI cascade closes on the table's scale (position gain 10 1/s, velocity loop 4 Hz on
the 620 kg, integral time 60 ms), the force noise is coloured (AR(1), 0.6) and the samples are taken
with +-5 % jitter of the period; the motor encoder's position is recorded too. The physics is the
tests' two-mass simulator (tests/identify/sim_twomass.py), written apart from the identification's
columns.
"""

from __future__ import annotations

import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parents[1] / "tests" / "identify"))

from sim_twomass import Servo, TwoMass, simulate, write  # noqa: E402

AXIS = TwoMass(m1=150.0, m2=470.0, k=4e6, gap=25e-6, fc1=180.0, fv1=500.0, fc2=320.0, fv2=1200.0)
LOOP = Servo(kind="ppi", kx=10.0, bw_v=4.0, ti=0.06, rho=0.6, jitter=0.05, noise=4.0)


def main():
    write(HERE / "table_x_windup_est.csv", simulate(AXIS, LOOP, 10.0, 71))
    write(HERE / "table_x_windup_val.csv", simulate(AXIS, LOOP, 6.0, 72))


if __name__ == "__main__":
    main()
