"""The torque-speed view of a design with a motor (``evaluate --plot``)."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from axisopt.cli import main
from axisopt.design import load_design
from axisopt.model import evaluate
from axisopt.report import duty_points

DESIGN = Path(__file__).resolve().parents[2] / "problems" / "vmc_x_design.yaml"


def test_duty_points_on_the_motor_plane():
    ev = evaluate(load_design(DESIGN))
    d, a = ev.design, ev.design.axis
    pts = duty_points(ev)
    lead = float(d.screw["lead"])
    # default cycle: the stroke there and back, so the mean table speed is 2 x stroke / cycle time
    mean_rpm = 2 * a.stroke / ev["duty_time"] / lead * 60 * a.reduction_ratio
    assert pts["mean_speed_rpm"] == pytest.approx(mean_rpm, rel=1e-9)
    assert max(pts["speed_rpm"]) == pytest.approx(a.max_speed / lead * 60 * a.reduction_ratio, rel=1e-9)
    # the needed peak is the largest of the plotted cycle torques and the steady thrust at the axial load
    assert ev["peak_torque"] == pytest.approx(max(max(abs(t) for t in pts["torque_Nm"]), ev["thrust_torque"]))
    assert pts["peak_torque_Nm"] == pytest.approx(float(d.motor["peak_torque"]))
    assert pts["max_speed_rpm"] == pytest.approx(float(d.motor["max_speed"]) * 60 / (2 * math.pi))


def test_evaluate_plot_with_motor_has_the_torque_speed_panel(tmp_path, capsys):
    png = tmp_path / "p.png"
    assert main(["evaluate", str(DESIGN), "--plot", str(png)]) == 0
    import matplotlib.image as mpimg

    h, w = mpimg.imread(png).shape[:2]
    assert w > 1.8 * h  # two columns: profiles and torque-speed
