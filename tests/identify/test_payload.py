"""Runs that differ in payload: a ``payload [kg]`` column is a known mass (its inertial force leaves
the effort), so an estimation run and a validation run with 350 kg more share one model.  Records
come from the tests' own cascade simulator (``sim_cascade``: a P-PI loop, coloured force noise),
written apart from the fitted model; the simulated axis carries its own mass plus the payload.  A
payload that changes within a run and a design whose reduction is 0 are one-line errors (exit 2)."""

import numpy as np
import pytest
from identify_helpers import DESIGN
from sim_cascade import Axis, Loop, simulate, write

from axisopt.errors import InputError
from axisopt.identify.records.idim import diagnose_time_files, heldout_rmse
from axisopt.identify.records.record import read_time_record
from axisopt.identify.records.regression import BASE

OWN = 600.0  # the axis's own moving mass in the simulator [kg]


def _run(path, payload, seed, rho, fs=500.0, duration=8.0):
    rec = simulate(Axis(mass=OWN + payload), Loop(fs=fs, rho=rho), duration, seed)
    rec["payload"] = np.full(len(rec["time"]), payload)
    return write(path, rec, ("payload",))


@pytest.mark.parametrize(
    "seed, rho, est_load, val_load", [(11, 0.0, 0.0, 350.0), (12, 0.7, 120.0, 470.0)]
)
def test_a_validation_run_with_another_payload_is_predicted(
    tmp_path, plant, seed, rho, est_load, val_load
):
    files = [
        _run(tmp_path / "e.csv", est_load, seed, rho),
        _run(tmp_path / "v.csv", val_load, seed + 500, rho, duration=5.0),
    ]
    diag = diagnose_time_files(files, plant=plant)
    assert diag.verdict == []  # no effect stands in for the known mass
    assert diag.final.value("M") == pytest.approx(
        OWN, rel=0.10
    )  # the axis's own mass, not with the payload
    assert not diag.unexplained.remaining  # the heavier run claims no structure


def test_without_the_payload_column_the_heavier_run_misfits(tmp_path, plant):
    """The finding the column answers: the same runs without it, and the held-out error grows."""
    e, v = (
        _run(tmp_path / "e.csv", 0.0, 13, 0.0),
        _run(tmp_path / "v.csv", 350.0, 513, 0.0, duration=5.0),
    )
    with_col = diagnose_time_files([e, v], plant=plant)
    for p in (e, v):
        lines = p.read_text().splitlines()
        p.write_text("\n".join(",".join(ln.split(",")[:-1]) for ln in lines) + "\n")
    without = diagnose_time_files([e, v], plant=plant)
    ho_with = heldout_rmse(with_col.estimation, with_col.validation, BASE, {})
    ho_without = heldout_rmse(without.estimation, without.validation, BASE, {})
    assert ho_with < 0.5 * ho_without, (ho_with, ho_without)


def test_a_payload_that_changes_within_a_run_is_a_one_line_error(tmp_path, plant, capsys):
    from axisopt.cli import main

    p = _run(tmp_path / "e.csv", 100.0, 14, 0.0, duration=2.0)
    lines = p.read_text().splitlines()
    lines[500] = ",".join(lines[500].split(",")[:-1] + ["450"])
    p.write_text("\n".join(lines) + "\n")
    with pytest.raises(
        InputError, match="conflicting payloads in one run: 100 at the start, 450 here"
    ):
        read_time_record(p, lead=plant.lead)
    assert main(["diagnose", str(p), "--design", str(DESIGN)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "line 501, column 5 (payload)" in err[0]


def test_a_reduction_of_zero_is_a_one_line_error(tmp_path, capsys):
    from axisopt.cli import main

    bad = tmp_path / "r0.yaml"
    bad.write_text(DESIGN.read_text().replace("axis:\n", "axis:\n  reduction_ratio: 0\n", 1))
    assert main(["diagnose", str(DESIGN.parent / "table_x_run_est.csv"), "--design", str(bad)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "axis.reduction_ratio" in err[0] and "got 0" in err[0]


def test_a_long_record_is_read_in_windows_that_start_at_rest(tmp_path, plant):
    """The windows of a long record (thresholds lowered here): each starts where the axis rests, the
    times stay the record's, and the filters see each window on its own."""
    from axisopt.identify.records.regression import make_rows, processing_for
    from axisopt.identify.records.signal import windowed

    rec = read_time_record(
        _run(tmp_path / "e.csv", 0.0, 15, 0.0, fs=500.0, duration=24.0), lead=plant.lead
    )
    w = windowed(rec, long_samples=6000, count=3, size=2500)
    assert [b - a for a, b in w.segments] == [2500] * 3 and w.n == 7500
    starts = [a for a, _ in w.segments]
    assert np.all(
        np.diff(w.t)[np.array(starts[1:]) - 1] > 1.0
    )  # gaps in time between windows: times kept
    for a in starts:  # at rest: still over the first 50 ms
        assert abs(w.q[a + 25] - w.q[a]) <= 1e-4 * float(np.ptp(rec.q))
    rows = make_rows(w, processing_for(w, plant.stroke, plant.lead))
    assert all(any(a < k < b for a, b in w.segments) for k in rows.keep)
    assert "3 windows of 5 s fitted" in w.run_note()
    assert windowed(rec) is rec  # a record under the threshold is itself
