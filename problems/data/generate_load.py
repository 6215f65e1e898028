"""Regenerate the shipped friction tables with load- and temperature-dependent friction (synthetic, seeded):
``python problems/data/generate_load.py``.  The friction law is written here, apart from the identification's
measurement model; the design is ``table_x.yaml`` (Coulomb level 292 N at the table with its own weight).

table_x_axial_friction.csv: constant-speed friction readings of the table_x axis, 2-300 mm/s both ways, at
five process forces on the nut (-3 to +3 kN, pushing and pulling), two readings each, logged with the jitter
of a real test (speeds +-0.5 %, positions +-1 mm); the nut loses 6 % of the axial force it carries
(k_a = 1/eta - 1 = 0.06, a ball screw of efficiency 0.943), noise 3 N.

table_x_warm_friction.csv: the same axis at four temperatures of a warm-up (20-42 degC); the viscous friction,
1 200 N.s/m at 20 degC, halves every 20 K (the grease's viscosity, beta = ln 2 / 20 K = 0.0347 /K).

table_x_two_speeds.csv: a slow friction test at two speeds only (2 and 7 mm/s both ways, three readings each)
of the axis with a drag growing with v|v| (4e6 N.s^2/m^2, 196 N at 7 mm/s): two speeds fit a slope in v as
well as one in v|v|, the example of two explanations the data do not tell apart.
"""

import math
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
FC = 292.0  # [N] the design's friction level at the table (nut, bearings, guides with the table's weight)
FV = 137.0  # [N.s/m] the design's viscous friction (guides)
SPEEDS = np.geomspace(0.002, 0.3, 10)  # [m/s]


def rows(rng, *, axial=(None,), temps=(None,), ka=0.0, fv20=FV, beta=0.0, speeds=SPEEDS, drag=0.0, rep=2):
    out = []
    for fa in axial:
        for tc in temps:
            for x in (0.2, 0.5):
                for v in np.r_[speeds, -speeds]:
                    for _ in range(rep):
                        dT = (tc - 20.0) if tc is not None else 0.0
                        f = math.copysign(FC + ka * abs(fa or 0.0), v) + fv20 * math.exp(-beta * dT) * v + drag * v * abs(v)
                        f += 3.0 * rng.standard_normal()
                        row = [v * (1 + 0.005 * rng.uniform(-1, 1)) * 1e3, f]
                        row += [fa] if fa is not None else []
                        row += [tc] if tc is not None else []
                        out.append(row + [(x + 0.001 * rng.uniform(-1, 1)) * 1e3])
    return out


def write(path, head, data):
    path.write_text(head + "\n" + "\n".join(",".join(f"{v:.6g}" for v in r) for r in data) + "\n")


def main():
    write(HERE / "table_x_axial_friction.csv", "velocity [mm/s],friction_force [N],axial_load [N],position [mm]",
          rows(np.random.default_rng(56), axial=(-3000.0, -1500.0, 0.0, 1500.0, 3000.0), ka=0.06))
    write(HERE / "table_x_warm_friction.csv", "velocity [mm/s],friction_force [N],temperature [degC],position [mm]",
          rows(np.random.default_rng(57), temps=(20.0, 27.0, 34.0, 42.0), fv20=1200.0, beta=math.log(2) / 20.0))
    write(HERE / "table_x_two_speeds.csv", "velocity [mm/s],friction_force [N],position [mm]",
          rows(np.random.default_rng(58), speeds=np.array([0.002, 0.007]), drag=4.0e6, rep=3))


if __name__ == "__main__":
    main()
