"""Helpers of the identify tests: the shipped table_x axis, measured tables written from a law or a
simulated data set, and time records simulated by :mod:`axisopt.identify.records.synth` (an
estimation run and a validation run, seeds ``seed`` and ``seed + 500``).  The module-scoped
``plant`` fixture is in conftest.py."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from axisopt.identify.records.synth import AxisTruth, simulate_axis
from axisopt.report.timediag import time_diagnosis_dict

DATA = Path(__file__).resolve().parents[2] / "problems" / "data"
DESIGN = DATA / "table_x.yaml"
LEAD = 0.01  # the lead of table_x.yaml [m]
SPEEDS = np.geomspace(0.002, 0.4, 14)  # [m/s]


def assert_timesynth_axis(plant):
    """The plant, after checking that it is the axis the time records assume (lead 10 mm, stroke 0.8
    m)."""
    assert plant.lead == LEAD and plant.stroke == pytest.approx(0.8)
    return plant


# -----------------------------------------------------------------------------------------------
# measured tables
def write(tmp_path, text, name="d.csv"):
    p = tmp_path / name
    p.write_text(text)
    return p


def dataset_csv(ds, path, torque_lead=None, efficiency=None):
    """A simulated data set written as a measured table in vendor units; with ``torque_lead`` (and
    ``efficiency``) its friction force as screw drag torque."""
    cols = dict(ds.columns)
    head, data = [], []
    units = {
        "position": ("mm", 1e3),
        "force": ("N", 1.0),
        "displacement": ("um", 1e6),
        "direction": ("", 1.0),
        "velocity": ("mm/s", 1e3),
        "normal_load": ("N", 1.0),
        "friction_force": ("N", 1.0),
        "frequency": ("Hz", 1.0),
    }
    if torque_lead is not None:  # the same friction measured as screw torque: T = F l / (2 pi eta)
        cols["drag_torque"] = cols.pop("friction_force") * torque_lead / (2 * math.pi * efficiency)
        units["drag_torque"] = ("N.m", 1.0)
    for k, v in cols.items():
        u, f = units[k]
        head.append(f"{k} [{u}]" if u else k)
        data.append(np.asarray(v) * f)
    rows = [",".join(head)] + [",".join(f"{x:.9g}" for x in r) for r in zip(*data)]
    path.write_text("\n".join(rows) + "\n", encoding="utf-8")
    return path


def coulomb(plant):
    # the design's friction level at the table [N]
    return plant.coulomb + plant.mu * plant.weight_on_guides


def friction_table(
    path, law, *, speeds=SPEEDS, both=True, noise=5.0, seed=1, rep=2, magnitudes=False
):
    """A friction table from ``law(v)`` [N] at ``speeds`` [m/s] (both directions unless
    ``both=False``), ``rep`` readings each, Gaussian noise of ``noise`` [N]."""
    rng = np.random.default_rng(seed)
    v = np.repeat(np.r_[speeds, -speeds] if both else speeds, rep)
    f = law(v) + noise * rng.standard_normal(len(v))
    if magnitudes:
        f = np.abs(f)
    rows = ["velocity [mm/s],friction_force [N]"] + [f"{a * 1e3:.6g},{b:.6g}" for a, b in zip(v, f)]
    path.write_text("\n".join(rows) + "\n")
    return path


# --------------------------------------------------------------------------------------------------
# time records
def baseline_truth(rng, **kw):
    """A random baseline axis (mass, viscous, Coulomb, offset of random sign) drawn from ``rng``,
    plus ``kw``."""
    sign = rng.choice([-1.0, 1.0])
    return AxisTruth(
        mass=rng.uniform(300, 900),
        viscous=rng.uniform(600, 2500),
        coulomb=rng.uniform(200, 600),
        offset=sign * rng.uniform(20, 60),
        **kw,
    )


def truth_for(seed, **kw):
    return baseline_truth(np.random.default_rng(seed), **kw)


def records(tmp_path, truth, seed=0, *, loop=None, est_s=12.0, val_s=8.0, **csv):
    """An estimation record (``est_s`` [s], seed ``seed``) and a validation record (``val_s`` [s],
    seed ``seed + 500``) of ``truth`` under ``loop`` (timesynth's default loop when None); ``csv``
    goes to ``Record.write_csv``."""
    est, val = tmp_path / f"est{seed}.csv", tmp_path / f"val{seed}.csv"
    simulate_axis(truth, loop, duration=est_s, seed=seed).write_csv(est, **csv)
    simulate_axis(truth, loop, duration=val_s, seed=seed + 500).write_csv(val, **csv)
    return [est, val]


def close(est, term, true, rel):
    assert est.value(term) == pytest.approx(true, rel=rel), (term, est.value(term), true)


def unexplained(diag):
    return time_diagnosis_dict(diag)["unexplained"]
