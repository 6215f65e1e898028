"""Time-record estimators (:mod:`axisopt.identify.records.estimators`): without a reference column
IV uses delayed regressors as instruments."""

import pytest
from identify_helpers import assert_timesynth_axis, close, records

from axisopt.identify.records.idim import diagnose_time_files
from axisopt.identify.records.synth import AxisTruth


@pytest.fixture(scope="module")
def plant(plant):
    return assert_timesynth_axis(plant)


def test_without_reference_iv_uses_delayed_regressors(tmp_path, plant):
    truth = AxisTruth(mass=400.0, viscous=900.0, coulomb=250.0)
    paths = records(tmp_path, truth, seed=51, columns=("time", "position", "force"))
    diag = diagnose_time_files(paths, plant=plant)
    assert diag.controller is None and "delayed-regressor" in diag.baseline_iv.note
    close(diag.baseline_iv, "M", 400.0, 0.10)
    close(diag.baseline_iv, "Fc", 250.0, 0.10)
