"""Diagnose of reduced tables, third stage (issue 28): quadratic drag, the 'unexplained' verdict, effects that
only help together, friction sign convention, per-file gains, unidentifiable parameters.

The friction tables are written here from a friction law of a few lines (sgn(v) levels, a Gaussian
Stribeck rise, viscous, v|v| drag, a constant), apart from the library's measurement model."""

import json
import re
from pathlib import Path

import numpy as np
import pytest

from axisopt.cli import main
from axisopt.design import load_design
from axisopt.identify import diagnose, plant_from_design, read_dataset
from axisopt.identify.fit import covariance
from axisopt.report.diagnosis import diagnosis_dict, diagnosis_text

DATA = Path(__file__).resolve().parents[2] / "problems" / "data"
DESIGN = DATA / "table_x.yaml"
SPEEDS = np.geomspace(0.002, 0.4, 14)  # [m/s]


@pytest.fixture(scope="module")
def plant():
    return plant_from_design(load_design(DESIGN))


def coulomb(plant):
    return plant.coulomb + plant.mu * plant.weight_on_guides  # the design's friction level at the table [N]


def friction_table(path, law, *, speeds=SPEEDS, both=True, noise=5.0, seed=1, rep=2, magnitudes=False):
    rng = np.random.default_rng(seed)
    v = np.repeat(np.r_[speeds, -speeds] if both else speeds, rep)
    f = law(v) + noise * rng.standard_normal(len(v))
    if magnitudes:
        f = np.abs(f)
    rows = ["velocity [mm/s],friction_force [N]"] + [f"{a * 1e3:.6g},{b:.6g}" for a, b in zip(v, f)]
    path.write_text("\n".join(rows) + "\n")
    return path


# ------------------------------------------------------------------------------------------------ inputs
def test_friction_magnitudes_with_signed_speed_are_refused(tmp_path, plant, capsys):
    """Magnitudes with a negative speed fitted a 39.6 N 'Coulomb' level: now a one-line error with the
    convention, exit 2."""
    fc = coulomb(plant)
    p = friction_table(tmp_path / "mag.csv", lambda v: np.sign(v) * fc + plant.viscous * v, magnitudes=True)
    assert main(["diagnose", str(p), "--design", str(DESIGN)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1
    assert re.search(r"line \d+, column 2 \(friction_force\).*negative at negative velocity", err), err


def test_vertical_axis_positive_both_ways_is_accepted(tmp_path, plant):
    """A weight larger than the friction makes the force positive in both directions, but unequal: read."""
    fc = coulomb(plant)
    p = friction_table(tmp_path / "vertical.csv", lambda v: np.sign(v) * fc + plant.viscous * v + 3 * fc)
    assert read_dataset(p).n == 2 * 2 * len(SPEEDS)


# ------------------------------------------------------------------------------------ drag and unexplained
def test_quadratic_drag_is_named_with_its_coefficient(tmp_path, plant):
    fc = coulomb(plant)
    p = friction_table(tmp_path / "drag.csv", lambda v: np.sign(v) * fc + plant.viscous * v + 2000.0 * v * np.abs(v))
    diag = diagnose([read_dataset(p)], plant)
    assert diag.verdict == "quadratic_drag"
    assert diag.final.value("drag_coefficient") == pytest.approx(2000.0, rel=0.10)
    assert not diagnosis_dict(diag)["unexplained"][0]["remaining"]


def test_drag_outside_the_library_is_unexplained_and_grows_with_v_abs_v(tmp_path, plant):
    fc = coulomb(plant)
    p = friction_table(tmp_path / "drag.csv", lambda v: np.sign(v) * fc + plant.viscous * v + 2000.0 * v * np.abs(v))
    diag = diagnose([read_dataset(p)], plant, candidates=["viscous", "stribeck", "direction_asymmetry"])
    un = diagnosis_dict(diag)["unexplained"][0]
    assert un["remaining"] and un["rms_over_noise"] > 2
    sig = un["signatures"][0]
    assert sig["factor"] == "velocity" and "grows with v|v|" in sig["signature"]
    assert "quadratic drag" in sig["causes"]
    assert "unexplained (drag.csv)" in diagnosis_text(diag)


@pytest.mark.parametrize("seed", [1, 2])
def test_null_friction_table_names_nothing_and_leaves_nothing(tmp_path, plant, seed):
    fc = coulomb(plant)
    p = friction_table(tmp_path / "null.csv", lambda v: np.sign(v) * 1.1 * fc + plant.viscous * v, seed=seed)
    diag = diagnose([read_dataset(p)], plant)
    assert diag.verdict == "none"
    d = diagnosis_dict(diag)
    assert not d["unexplained"][0]["remaining"]
    text = diagnosis_text(diag)
    assert "verdict: none -- " in text and "dBIC" in text  # the reason, not a bare 'none'


def test_effects_that_only_help_together_are_found_as_a_pair(tmp_path, plant):
    """A lead-screw rig's friction curve: a direction difference, a Stribeck rise and a viscous slope three
    times the catalog's.  After the asymmetry, neither Stribeck nor viscous predicts held-out speed bands
    alone (Stribeck's held-out gain is negative); together they do."""
    fc = coulomb(plant)

    def law(v):
        return np.sign(v) * (fc + 0.8 * fc * np.exp(-(v / 0.004) ** 2)) + 3 * plant.viscous * v + 0.3 * fc

    diag = diagnose([read_dataset(friction_table(tmp_path / "rig.csv", law))], plant, max_effects=3)
    assert diag.verdict == "direction_asymmetry, stribeck, viscous"
    assert [a.together for a in diag.accepted] == ["", "viscous", "stribeck"]
    r2 = diag.rounds[1]
    assert all(c.reason for c in r2)  # each alone fails, with its reason
    assert any("held-out gain" in c.reason for c in r2 if c.effect.name in ("stribeck", "viscous"))
    fin = diag.final
    assert fin.value("stribeck_rise") == pytest.approx(0.8 * fc, rel=0.05)
    assert fin.value("viscous_coefficient") == pytest.approx(3 * plant.viscous, rel=0.10)
    assert fin.value("direction_difference") == pytest.approx(0.6 * fc, rel=0.05)
    assert diag.gain > 90
    assert "accepted, neither passes alone" in diagnosis_text(diag)


# --------------------------------------------------------------------------------- per-file gains, identifiability
def test_each_file_gets_its_own_gain(tmp_path, plant, capsys):
    """The gain quoted for one record repeated the pooled gain; each file now has its own."""
    fc = coulomb(plant)

    def law(v):
        return np.sign(v) * fc + plant.viscous * v + 2000.0 * v * np.abs(v)

    fast = friction_table(tmp_path / "fast.csv", law)
    slow = friction_table(tmp_path / "slow.csv", law, speeds=np.geomspace(0.002, 0.03, 10), seed=3)
    assert main(["diagnose", str(fast), str(slow), "--design", str(DESIGN), "--json", "-"]) == 0
    d = json.loads(capsys.readouterr().out)
    assert d["verdict"] == "quadratic_drag"
    g = {Path(h["file"]).name: h["gain_percent"] for h in d["holdout_rmse_units"]}
    assert g["fast.csv"] > 50 and g["fast.csv"] - g["slow.csv"] > 10, g
    assert max(abs(v - d["gain_percent"]) for v in g.values()) > 5, (g, d["gain_percent"])


def test_a_dependent_column_is_not_identifiable_not_zero_uncertainty():
    J = np.array([[1.0, 0.0, 2.0], [2.0, 0.0, 1.0], [3.0, 0.0, 0.5], [1.0, 0.0, 1.0]])
    cov = covariance(J, rss=1.0, n=4, scale=np.ones(3))
    sd = np.sqrt(np.diag(cov))
    assert np.isfinite(sd[0]) and np.isfinite(sd[2]) and sd[0] > 0
    assert np.isinf(sd[1])


def test_single_speed_friction_reports_viscous_as_not_identifiable():
    """The shipped XJTU series is measured at one speed: a viscous slope cannot be told from the Coulomb level,
    and is printed as not identifiable rather than with a zero uncertainty."""
    plant = plant_from_design(load_design(DATA / "xjtu" / "xjtu_rig.yaml"))
    diag = diagnose([read_dataset(DATA / "xjtu" / "xjtu_up_friction.csv")], plant)
    assert diag.verdict == "preload_loss"
    d = diagnosis_dict(diag)
    visc = [p for rnd in d["candidates"] for c in rnd if c["effect"] == "viscous" for p in c["parameters"]]
    assert visc and all(p["sigma"] is None and "not identifiable" in p["text"] for p in visc)
