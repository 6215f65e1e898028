"""diagnose on a correct fixed-fixed axis, with data written from the two-path physics by hand (not from the
code under test): nothing may be named."""

from __future__ import annotations

import math
from dataclasses import replace
from pathlib import Path

import numpy as np

from axisopt.design import load_design
from axisopt.identify import diagnose, plant_from_design
from axisopt.identify.data import Dataset

ROOT = Path(__file__).resolve().parents[2]


def test_correct_fixed_fixed_axis_names_nothing():
    d = load_design(ROOT / "problems" / "vmc_x_design.yaml")
    d = replace(d, axis=replace(d.axis, mounting="fixed-fixed"))
    plant = plant_from_design(d)
    # by hand: WBK30-DFD 1520 N/um at both ends (housings rigid), root 34.91 mm, E 206 GPa, span 1.1 m; screw
    # torsion G pi d^4/(32 x) and the GWB AKN 60 coupling (75e3 N.m/rad) through the 20 mm lead; nut at its preload
    # (R40-20K4-FDC 0.8 x 1150 N/um x (3000/5130)^(1/3)), linear at these small loads
    ea = 206e9 * math.pi / 4 * 0.03491**2
    k_b, span, r2 = 1520e6, 1.1, (0.020 / (2 * math.pi)) ** 2
    k_n = 0.8 * 1150e6 * (3000 / 5130) ** (1 / 3)
    rng = np.random.default_rng(3)
    pos, force, direction = [], [], []
    for p in np.linspace(0.0, 0.8, 9):
        for sign in (1.0, -1.0):
            loads = np.array([200.0, 400.0, 600.0, 800.0])
            seq = np.r_[loads, loads[::-1]]
            pos += [p] * len(seq)
            force += list(sign * seq)
            direction += list(sign * np.r_[np.ones(4), -np.ones(4)])
    pos, force = np.array(pos), np.array(force)
    x = 0.13 + pos
    k_sb = 1 / (1 / k_b + x / ea) + 1 / (1 / k_b + (span - x) / ea)
    c_tors = r2 * 32 * x / (79.3e9 * math.pi * 0.03491**4)
    c = 1 / k_sb + c_tors + r2 / 75e3 + 1 / k_n
    disp = force * c * (1 + 0.005 * rng.standard_normal(len(force)))
    cols = {"position": pos, "force": force, "direction": np.array(direction), "displacement": disp}
    ds = Dataset("stiffness", "hand_two_path.csv", cols, np.arange(2, len(pos) + 2))
    diag = diagnose([ds], plant)
    assert diag.verdict == "none", [e.name for e in diag.effects]
