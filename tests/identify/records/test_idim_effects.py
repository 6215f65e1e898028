"""Time-record effects at the edge of the library (:mod:`axisopt.identify.records.idim`): a ripple
at the lead and a quadratic drag named (not an extra mode, an asymmetry or a position friction),
baseline plausibility and identifiability flags, the external-force column in the dynamics.

The records come from :mod:`axisopt.identify.records.synth`, the closed-loop simulator written apart
from the identification (its ripple is ``sin(2 pi x / period + phase)`` on the simulated table, its
drag ``c v|v|``); nothing here builds data with the columns of the time-record effects
(:mod:`axisopt.identify.effects`)."""

import math

import numpy as np
import pytest
from identify_helpers import LEAD, records, truth_for, unexplained

from axisopt.identify.records.estimators import Estimate
from axisopt.identify.records.idim import baseline_flags, diagnose_time_files
from axisopt.identify.records.synth import AxisTruth, simulate_axis
from axisopt.report.timediag import time_diagnosis_text


# ------------------------------------------------------------------------------ the effects the
# library lacked
@pytest.mark.parametrize("seed", [1, 2, 3, 4])
def test_lead_ripple_is_named_not_an_extra_mode(tmp_path, plant, seed):
    """A 40 N force ripple with the lead's period (sin(2 pi x / lead)) was named extra_mode in 3 of
    4 seeds."""
    truth = truth_for(seed, ripple=40.0, ripple_period=LEAD, ripple_phase=0.7 * seed)
    diag = diagnose_time_files(records(tmp_path, truth, seed), plant=plant)
    assert diag.verdict and diag.verdict[0] == "lead_ripple", diag.verdict
    assert "extra_mode" not in diag.verdict
    fin = diag.final
    assert fin.shape["period"] == pytest.approx(LEAD)
    assert math.hypot(fin.value("rs"), fin.value("rc")) == pytest.approx(40.0, rel=0.10)
    assert math.hypot(fin.value("ks"), fin.value("kc")) < 6.0  # a force, not a friction ripple
    assert diag.accepted[0].gain >= 30.0
    assert not unexplained(diag)["remaining"]


def test_friction_ripple_at_half_the_lead(tmp_path, plant):
    """A friction ripple (follows sgn v) at the second harmonic of the lead: the same effect, its
    friction columns, period lead/2."""
    truth = truth_for(5, ripple=50.0, ripple_period=LEAD / 2, ripple_friction=True)
    diag = diagnose_time_files(records(tmp_path, truth, 5), plant=plant)
    assert diag.verdict[:1] == ["lead_ripple"], diag.verdict
    fin = diag.final
    assert fin.shape["period"] == pytest.approx(LEAD / 2)
    assert math.hypot(fin.value("ks"), fin.value("kc")) == pytest.approx(50.0, rel=0.10)


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_quadratic_drag_is_named_not_asymmetry_or_position(tmp_path, plant, seed):
    """A symmetric c v|v| drag was named direction_asymmetry or position_friction, or nothing while
    the force error stayed at 6-9 %."""
    c = 3000.0 * (1 + 0.3 * seed)
    diag = diagnose_time_files(
        records(tmp_path, truth_for(seed, quadratic_drag=c), seed), plant=plant
    )
    assert diag.verdict[:1] == ["quadratic_drag"], diag.verdict
    assert not {"direction_asymmetry", "position_friction"} & set(diag.verdict)
    assert diag.final.value("Cq") == pytest.approx(c, rel=0.10)
    assert not unexplained(diag)["remaining"]


# -----------------------------------------------------------------------------------------------
# plausibility
def test_sign_flipped_effort_is_flagged_not_reported_as_a_fit(tmp_path, plant):
    """A force column recorded with the wrong sign gives a negative mass and Coulomb friction:
    flagged with an explanation, never printed as a plain fit."""
    rec = simulate_axis(truth_for(6), duration=8.0, seed=6)
    rec.force = -rec.force
    path = tmp_path / "flipped.csv"
    rec.write_csv(path)
    diag = diagnose_time_files([path], plant=plant)
    flags = " ".join(diag.flags["baseline"])
    assert "M = " in flags and "not positive" in flags and "Fc = " in flags
    assert "! M = " in time_diagnosis_text(diag)


def test_degenerate_term_is_unidentifiable_not_zero_uncertainty():
    est = Estimate(
        "LS",
        ("M", "Fv", "Fc", "offset"),
        np.array([500.0, 1000.0, 300.0, 1.0]),
        np.array([1.0, 0.0, 400.0, 0.5]),
        {},
        1.0,
        100,
    )
    flags = baseline_flags(est, "force")
    assert any(f.startswith("Fv is not identifiable") and "zero" in f for f in flags)
    assert any(f.startswith("Fc = 300 ± 400 N is not identifiable") for f in flags)


# --------------------------------------------------------------------------------------------------
# - inputs
def test_external_force_column_is_used_in_the_dynamics(tmp_path, plant):
    """A process force of up to 300 N on the table: with the column the baseline is recovered and
    nothing is named; without it the fit is far worse."""
    truth = AxisTruth(mass=500.0, viscous=1200.0, coulomb=300.0, offset=20.0, process_force=300.0)
    cols = ("time", "position", "force", "reference", "external_force")
    paths = records(tmp_path, truth, 7, columns=cols)
    diag = diagnose_time_files(paths, plant=plant)
    for term, true in (("M", 500.0), ("Fv", 1200.0), ("Fc", 300.0)):
        assert diag.final.value(term) == pytest.approx(true, rel=0.05), term
    assert diag.verdict == []
    bare = tmp_path / "bare.csv"
    simulate_axis(truth, duration=12.0, seed=7).write_csv(bare)
    without = diagnose_time_files([bare], plant=plant, candidates=["stribeck"])
    with_col = diagnose_time_files(paths[:1], plant=plant, candidates=["stribeck"])
    from axisopt.identify.records.estimators import rel_error

    assert rel_error(without.estimation, without.baseline_ls) > 3 * rel_error(
        with_col.estimation, with_col.baseline_ls
    )


def test_external_force_on_a_torque_record(tmp_path, plant):
    truth = AxisTruth(mass=500.0, viscous=1200.0, coulomb=300.0, process_force=300.0)
    path = tmp_path / "torque.csv"
    rec = simulate_axis(truth, duration=12.0, seed=8)
    rec.write_csv(
        path,
        columns=("time", "position", "force", "reference", "external_force"),
        effort="torque",
        lead=LEAD,
        efficiency=plant.efficiency,
        position_unit="rad",
    )
    diag = diagnose_time_files([path], plant=plant)
    g = 2 * math.pi / LEAD
    assert diag.final.value("M") * g * g * plant.efficiency == pytest.approx(500.0, rel=0.05)
    assert diag.final.value("Fc") * g * plant.efficiency == pytest.approx(300.0, rel=0.05)
