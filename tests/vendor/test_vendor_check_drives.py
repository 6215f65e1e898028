"""tools/vendor_check_drives.py (written apart from axisopt: it runs the program, reads the catalog
rows and the problem's YAML, and samples the duty cycle in time) passes the router's rack-and-pinion
design and the laser axis's linear-motor design by the vendors' printed steps, and agrees with
axisopt's margins."""

from __future__ import annotations

import importlib.util
import os
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
spec = importlib.util.spec_from_file_location(
    "vendor_check_drives", ROOT / "tools" / "vendor_check_drives.py"
)
vcd = importlib.util.module_from_spec(spec)
spec.loader.exec_module(vcd)


@pytest.mark.parametrize(
    "name, kind",
    [
        ("router_rack_problem", "rack_pinion"),
        ("laser_lm_problem", "linear_motor"),
        # the shipped laser axis's optimum is a linear motor since issue 54 (1547.23 Hz): its moves
        # are jerk-limited (300 m/s^3), which the checker samples as S-curves
        ("laser_problem", "linear_motor"),
    ],
)
def test_the_vendor_steps_pass_and_agree(name, kind, monkeypatch):
    monkeypatch.setenv("PYTHONPATH", str(ROOT) + os.pathsep + os.environ.get("PYTHONPATH", ""))
    lines, res = vcd.check(ROOT / "problems" / f"{name}.yaml")
    assert res["best"]["drive_type"] == kind
    assert len(lines) >= 5
    compared = 0
    for check, value, limit, margin, verdict, model, agree in lines:
        assert verdict in ("PASS", "INFO"), (check, value, limit, margin)
        if agree in ("ONLY", "CONV"):  # the checker's own rule (no axisopt margin) or a convention
            continue
        # the sampled cycle against the exact integrals
        assert model == pytest.approx(margin, rel=5e-3), check
        compared += 1
    assert compared >= 4


@pytest.mark.published
def test_hiwin_appendix_a_worked_example():
    """H-LMS MM99TE07-1701 Appendix A: 5 kg, mu 0.01, X 500 mm in T 400 ms on the 1/3-1/3-1/3
    trapezoid (Vmax 1.5 X / T, a 4.5 X / T^2), dwell 350 ms: Fp 70.79 N, Fe 41.92 N (LMCA6, Kf 33.8:
    Ip 2.09 A, Ie 1.24 A)."""
    x, t = 0.5, 0.4
    axis = {
        "acceleration": f"{4.5 * x / t**2} m/s^2",
        "max_speed": f"{1.5 * x / t * 60} m/min",
        "duty_cycle": [{"move": "500 mm"}, {"dwell": "0.35 s"}],
    }
    m, ff = 5.0, 5.0 * 9.81 * 0.01
    peak, rms = vcd.peak_rms(vcd.profile(axis), lambda acc, s, q: m * acc + s * ff)
    assert peak == pytest.approx(70.79, rel=1e-3)
    assert rms == pytest.approx(41.92, rel=2e-3)
    assert peak / 33.8 == pytest.approx(2.09, abs=0.005)
    assert rms / 33.8 == pytest.approx(1.24, abs=0.005)


@pytest.mark.parametrize(
    ("dist", "v", "a", "j"), [(0.8, 80 / 60, 15.0, 300.0), (0.02, 1.0, 15, 300)]
)
def test_s_curve_covers_the_move(dist, v, a, j):
    """The checker's S-curve (written from the kinematics alone): the sampled accelerations
    integrate to the move's length, never exceed a or the jerk's reach, and end at rest."""
    axis = {
        "acceleration": f"{a} m/s^2",
        "max_speed": f"{v * 60} m/min",
        "jerk": f"{j} m/s^3",
        "duty_cycle": [{"move": f"{dist * 1e3} mm"}],
    }
    speed, travel = 0.0, 0.0
    for dt, acc, _s, _q in vcd.profile(axis):
        travel += speed * dt + 0.5 * acc * dt * dt
        speed += acc * dt
        assert abs(acc) <= a * (1 + 1e-12)
    assert speed == pytest.approx(0.0, abs=1e-9)
    assert travel == pytest.approx(dist, rel=2e-3)
