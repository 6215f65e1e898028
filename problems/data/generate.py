"""Regenerate the shipped example measurements (synthetic, seeded): ``python problems/data/generate.py``.

table_x_stiffness.csv: static stiffness test of the design table_x.yaml (Stejskal et al. method, seed
paper sec. 5.1: 9 positions, loads 500..4000 N raised then lowered, pushing and pulling), with the
floating end of the screw actually carrying axial load (far-end stiffness 90 N/um), 1 % noise, and one
reading marked as an outlier (exclude = 1).
"""

from pathlib import Path

import numpy as np

from axisopt.design import load_design
from axisopt.identify import plant_from_design
from axisopt.identify.tables.data import write_dataset
from axisopt.identify.tables.synth import simulate

HERE = Path(__file__).resolve().parent


def main():
    design = load_design(HERE / "table_x.yaml")
    plant = plant_from_design(design)
    pos, force, direction = [], [], []
    loads = np.arange(500.0, 4001.0, 500.0)
    for p in np.linspace(0.0, 0.8, 9):
        for sign in (1.0, -1.0):
            seq = np.r_[loads, loads[::-1]]
            dirs = np.r_[np.ones(len(loads)), -np.ones(len(loads))]
            pos += [p] * len(seq)
            force += list(sign * seq)
            direction += list(sign * dirs)
    ds = simulate(
        plant,
        "stiffness",
        dict(position=pos, force=force, direction=direction),
        effects={"support_condition": {"far_end_stiffness": 90e6}},
        baseline={"screw_modulus": 203e9},
        noise=0.01,
        seed=7,
        source=str(HERE / "table_x_stiffness.csv"),
    )
    ds.columns["exclude"] = np.zeros(ds.n)
    ds.columns["displacement"][40] += 8e-6  # a bumped dial gauge, marked by the operator
    ds.columns["exclude"][40] = 1.0
    write_dataset(ds, HERE / "table_x_stiffness.csv")


if __name__ == "__main__":
    main()
