"""Time-record estimators (:mod:`axisopt.identify.estimators`): without a reference column IV uses
delayed regressors as instruments."""

from pathlib import Path

import pytest

from axisopt.design import load_design
from axisopt.identify import plant_from_design
from axisopt.identify.idim import diagnose_time_files
from axisopt.identify.timesynth import AxisTruth, simulate_axis

DESIGN = Path(__file__).resolve().parents[2] / "problems" / "data" / "table_x.yaml"


LEAD = 0.01


@pytest.fixture(scope="module")
def plant():
    p = plant_from_design(load_design(DESIGN))
    assert p.lead == LEAD and p.stroke == pytest.approx(0.8)
    return p


def records(tmp_path, truth, loop=None, seed=0, est_s=12.0, val_s=8.0, **csv):
    est, val = tmp_path / f"est{seed}.csv", tmp_path / f"val{seed}.csv"
    simulate_axis(truth, loop, duration=est_s, seed=seed).write_csv(est, **csv)
    simulate_axis(truth, loop, duration=val_s, seed=seed + 500).write_csv(val, **csv)
    return [est, val]


def close(est, term, true, rel):
    assert est.value(term) == pytest.approx(true, rel=rel), (term, est.value(term), true)


def test_without_reference_iv_uses_delayed_regressors(tmp_path, plant):
    truth = AxisTruth(mass=400.0, viscous=900.0, coulomb=250.0)
    paths = records(tmp_path, truth, seed=51, columns=("time", "position", "force"))
    diag = diagnose_time_files(paths, plant=plant)
    assert diag.controller is None and "delayed-regressor" in diag.baseline_iv.note
    close(diag.baseline_iv, "M", 400.0, 0.10)
    close(diag.baseline_iv, "Fc", 250.0, 0.10)
