"""Lines in motor orders: a cogging force periodic in the motor angle, through a 2:1 reduction (a
period of 1.25 mm at the table, under a quarter of the 10 mm lead), simulated by the tests' own
cascade (``sim_cascade``); with the order effects left out of the candidates (as a record whose line
no library effect names), the residual signature must locate it and state it per mm, per screw turn
and per motor turn with the design's reduction; with them, motor_cogging names it (tests in
effects/test_orders.py).  A reduction of 0 in the design is a one-line error."""

import subprocess
import sys

import pytest
from identify_helpers import DESIGN, unexplained
from sim_cascade import Axis, Loop, simulate, write

from axisopt.design import load_design
from axisopt.identify import plant_from_design
from axisopt.identify.records.idim import diagnose_time_files
from axisopt.report.timediag import time_diagnosis_text


def _design(tmp_path, ratio):
    text = DESIGN.read_text().replace(
        "  end_margin: 150 mm\n", f"  end_margin: 150 mm\n  reduction_ratio: {ratio}\n"
    )
    path = tmp_path / "red.yaml"
    path.write_text(text)
    return path


@pytest.mark.slow
@pytest.mark.parametrize("order, amp", [(4, 40.0)])
def test_cogging_through_a_reduction_is_stated_in_motor_orders(tmp_path, order, amp):
    plant = plant_from_design(load_design(_design(tmp_path, 2)))
    assert plant.reduction == 2.0
    ax = Axis(cog_amp=amp, cog_order=order, travel_per_motor_turn=plant.lead / 2.0)
    loop = Loop(fs=1000.0)
    runs = [
        write(tmp_path / "e.csv", simulate(ax, loop, 8.0, 71), ()),
        write(tmp_path / "v.csv", simulate(ax, loop, 5.0, 571), ()),
    ]
    diag = diagnose_time_files(runs, plant=plant, candidates=("stribeck", "lead_ripple"))
    sig = [s for s in unexplained(diag)["signatures"] if s["kind"] == "position_periodic"]
    assert sig, unexplained(diag)["signatures"]
    period = plant.lead / 2.0 / order  # 1.25 mm
    assert sig[0]["period_mm"] == pytest.approx(period * 1e3, rel=0.02)
    text = " ".join(time_diagnosis_text(diag).split())
    assert f"order {order} of the motor turn" in text and "reduction 2:1" in text
    assert "motor cogging" in text


def test_a_reduction_of_zero_is_a_one_line_error(tmp_path):
    out = subprocess.run(
        [
            sys.executable,
            "-m",
            "axisopt",
            "diagnose",
            "problems/data/table_x_run_est.csv",
            "--design",
            str(_design(tmp_path, 0)),
        ],
        capture_output=True,
        text=True,
        cwd=DESIGN.parents[2],
    )
    assert out.returncode == 2
    err = out.stderr.strip().splitlines()
    assert len(err) == 1 and "reduction_ratio" in err[0]
