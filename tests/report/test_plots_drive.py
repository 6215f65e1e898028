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
    assert max(pts["speed_rpm"]) == pytest.approx(
        a.max_speed / lead * 60 * a.reduction_ratio, rel=1e-9
    )
    # the needed peak is the largest of the plotted cycle torques and the steady thrust at the axial
    # load
    assert ev["peak_torque"] == pytest.approx(
        max(max(abs(t) for t in pts["torque_Nm"]), ev["thrust_torque"])
    )
    assert pts["peak_torque_Nm"] == pytest.approx(float(d.motor["peak_torque"]))
    assert pts["max_speed_rpm"] == pytest.approx(float(d.motor["max_speed"]) * 60 / (2 * math.pi))


def test_evaluate_plot_with_motor_has_the_torque_speed_panel(tmp_path, capsys):
    png = tmp_path / "p.png"
    assert main(["evaluate", str(DESIGN), "--plot", str(png)]) == 0
    assert png.stat().st_size > 0
    from axisopt.report.plots import plot_profiles

    ev = evaluate(load_design(DESIGN))
    fig = plot_profiles([ev])
    assert len(fig.axes) == 3  # profiles (2) and the torque-speed panel
    ax = fig.axes[2]
    assert (
        ax.get_xlabel() == "motor speed [rpm]" and ax.get_ylabel() == "motor torque magnitude [N.m]"
    )
    pts = duty_points(ev)
    lines = ax.get_lines()
    # the steady thrust at feed (the peak the text reports when it is the largest) is drawn, at
    # standstill
    thrust = [ln for ln in lines if ln.get_marker() == "^"]
    assert len(thrust) == 1 and thrust[0].get_ydata()[0] == pytest.approx(
        float(ev["thrust_torque"])
    )
    assert ax.get_ylim()[1] >= float(ev["peak_torque"])  # the whole needed peak is inside the panel
    # the rated torque runs to the rated speed and does not drop to zero there like a speed limit
    rated = [ln for ln in lines if ln.get_linewidth() == 2.5]
    assert len(rated) == 1 and list(rated[0].get_ydata()) == [pts["rated_torque_Nm"]] * 2
    assert rated[0].get_xdata()[-1] == pytest.approx(pts["rated_speed_rpm"])
    # the speed limit is the max speed; the peak zone the check reads, from the flat peak to max
    # speed
    vmax = [ln for ln in lines if ln.get_linestyle() == "-."]
    assert len(vmax) == 1 and vmax[0].get_xdata()[0] == pytest.approx(pts["max_speed_rpm"])
    zone = [ln for ln in lines if ln.get_linestyle() == "--"]
    assert len(zone) == 1 and list(zone[0].get_ydata()) == pytest.approx(pts["zone_torque_Nm"])
    # the legend sits below the panel: it cannot hide a limit line or a point
    leg = ax.get_legend()
    fig.canvas.draw()
    box = leg.get_window_extent().transformed(ax.transAxes.inverted())
    assert box.y1 <= 0.0
    texts = " | ".join(t.get_text() for t in leg.get_texts())
    assert (
        f"thrust at feed {float(ev['thrust_torque']):.1f}" in texts and "corner estimated" in texts
    )


def test_compare_plot_draws_each_motor_once_and_names_a_design_without_one(tmp_path):
    from axisopt.report.plots import plot_profiles

    root = DESIGN.parent
    evs = [evaluate(load_design(p)) for p in (DESIGN, DESIGN, root / "teaching_design.yaml")]
    fig = plot_profiles(evs, labels=["A", "B", "C"])
    ax = fig.axes[2]
    texts = [t.get_text() for t in ax.get_legend().get_texts()]
    motor = str(evs[0].design.motor["id"])
    assert sum(t.startswith(f"{motor}:") for t in texts) == 1  # one motor, its limits drawn once
    assert len([ln for ln in ax.get_lines() if ln.get_linestyle() == "--"]) == 1
    assert "C: no drive (the design has no motor)" in texts  # not silently left out
    # the design that fails checks says which, in the profiles' legend
    names = [t.get_text() for t in fig.axes[1].get_legend().get_texts()]
    failed = [r["check"] for r in evs[2].check_rows() if not r["pass"]]
    assert failed and any(n.startswith("C - FAILS ") and all(c in n for c in failed) for n in names)
    # A and B draw the same curves: one line, both named
    assert any(n.startswith("A, B: the same curves") for n in names)


def test_regeneration_of_the_default_cycle_is_yaskawas_two_stops(capsys):
    # the default cycle (trapezoidal rapid over the stroke and back) stops twice from the
    # rapid speed: Yaskawa Sigma-7 12.8.6 gives each stop E_S - E_L = J n^2 / 182 - (pi / 60) n T_L
    # t_D (182.38 unrounded)
    ev = evaluate(load_design(DESIGN))
    a = ev.design.axis
    assert a.jerk is None and not a.duty_cycle and a.orientation == "horizontal"
    n = ev["motor_speed"] * 60 / (2 * math.pi)
    t_d = a.max_speed / a.acceleration
    stop = ev["total_inertia"] * n**2 / 182.38 - (math.pi / 60) * n * ev["friction_torque"] * t_d
    assert ev["regen_energy"] == pytest.approx(2 * stop, rel=1e-4)
    assert ev["regen_power"] == pytest.approx(ev["regen_energy"] / ev["duty_time"], rel=1e-12)
    assert main(["evaluate", str(DESIGN), "--json", "-"]) == 0
    import json

    drive = json.loads(capsys.readouterr().out)["drive"]
    assert drive["regen_energy_J"] == pytest.approx(float(ev["regen_energy"]))
    assert main(["evaluate", str(DESIGN)]) == 0
    assert f"regeneration {float(ev['regen_energy']):,.0f} J per cycle" in capsys.readouterr().out
