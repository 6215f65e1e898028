"""Friction tables: equally good explanations are said (as for time records), with the measurement
that separates them, and an accepted effect outside its plausible regime is flagged.  Tables from
the tests' own friction law (``sim_tables``), written apart from the fitted model."""

import numpy as np
import pytest
from sim_tables import friction_rows, write_table

from axisopt.identify import diagnose, read_dataset
from axisopt.report.diagnosis import diagnosis_dict, diagnosis_text


@pytest.mark.parametrize("seed, drag", [(3, 4e6), (4, 6e6), (5, 3e6)])
def test_two_speeds_cannot_tell_viscous_from_drag_and_it_is_said(tmp_path, plant, seed, drag):
    """Two speeds each way: a slope in v and one in v|v| fit them alike, so the held-out data cannot
    decide."""
    rows = friction_rows(
        np.random.default_rng(seed),
        fc=300.0,
        fv=0.0,
        drag=drag,
        speeds=np.array([0.002, 0.007]),
        rep=3,
    )
    diag = diagnose([read_dataset(write_table(tmp_path / "t.csv", rows))], plant)
    pair = {diag.verdict} | {e[2] for e in diag.equivalent}
    assert pair == {"viscous", "quadratic_drag"}, (diag.verdict, diag.equivalent)
    eq = diagnosis_dict(diag)["equivalent"]
    assert len(eq) == 1 and (
        eq[0]["percent_apart"] < 2.0 or "both at the noise floor" in eq[0]["text"]
    )
    text = diagnosis_text(diag)
    assert "explain the data equally well" in text and "the curve bends upward with v|v|" in text


def test_drag_named_at_low_speed_is_flagged_and_not_at_high_speed(tmp_path, plant):
    slow = friction_rows(
        np.random.default_rng(2),
        fc=300.0,
        fv=0.0,
        drag=4e6,
        speeds=np.array([0.001, 0.002, 0.004, 0.007]),
        rep=3,
    )
    diag = diagnose([read_dataset(write_table(tmp_path / "slow.csv", slow))], plant)
    assert diag.verdict == "quadratic_drag"
    assert len(diag.regime) == 1 and "top speed of 7 mm/s" in diag.regime[0]
    assert "  ! quadratic_drag: " in diagnosis_text(diag)
    fast = friction_rows(np.random.default_rng(6), fc=300.0, fv=plant.viscous, drag=2000.0)
    diag = diagnose([read_dataset(write_table(tmp_path / "fast.csv", fast))], plant)
    assert diag.verdict == "quadratic_drag" and diag.regime == [] and diag.equivalent == []


def test_null_table_says_no_equivalent(tmp_path, plant):
    rows = friction_rows(np.random.default_rng(7), fc=300.0, fv=plant.viscous, speed_jitter=0.005)
    diag = diagnose([read_dataset(write_table(tmp_path / "t.csv", rows))], plant)
    assert diag.verdict == "none" and diag.equivalent == [] and diag.regime == []
