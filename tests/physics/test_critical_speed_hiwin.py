"""The screw's dangerous speed by its vendor (issue 53): HIWIN's rule for its screws (H-BS F
3.27/3.28), typed from the catalog page, against physics.checks.critical_speed_hiwin, and the model
applying it to a HIWIN screw only."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from axisopt.design import load_design
from axisopt.model import evaluate
from axisopt.physics.checks import critical_speed, critical_speed_hiwin

ROOT = Path(__file__).resolve().parents[2]


@pytest.mark.published
@pytest.mark.parametrize(
    ("mounting", "fn"), [("fixed-fixed", 1.0), ("fixed-supported", 0.692), ("fixed-free", 0.147)]
)
def test_hiwin_f_3_27(mounting, fn):
    # H-BS F 3.27: n_k,max = 0.8 x 2.71e8 f_n d_k / l_s^2 [rpm], d_k and l_s in mm
    d_k, l_s = 21.4, 1000.0
    rpm = 0.8 * 2.71e8 * fn * d_k / l_s**2
    got = critical_speed_hiwin(d_k * 1e-3, l_s * 1e-3, mounting) * 60.0 / (2.0 * math.pi)
    assert got == pytest.approx(rpm, rel=1e-12)


def test_hiwin_fixed_free_lies_6_percent_below_thks_lambda():
    # THK A-696: lambda_2 3.4 fixed-free; HIWIN 0.8 x 2.71e8 x 0.147 = 3.19e7: 6.3 % below (7.3 %
    # below the eigenvalue form axisopt evaluates THK's rule by, 1 % above lambda_2 3.4)
    ratio = critical_speed_hiwin(0.02, 1.0, "fixed-free") / critical_speed(0.02, 1.0, "fixed-free")
    assert ratio == pytest.approx(0.8 * 2.71e8 * 0.147 / 3.4e7, rel=0.015)


def test_the_model_takes_the_screws_vendor_rule():
    """The teaching design's HIWIN 25 mm screw, fixed-free: its critical speed is HIWIN's, as
    tools/vendor_check.py computes it from the catalog row (3,674 rpm; THK's lambda gave 3,953)."""
    ev = evaluate(load_design(ROOT / "problems" / "teaching_design.yaml"))
    got = float(ev.values["critical_speed"]) * 60.0 / (2.0 * math.pi)
    assert got == pytest.approx(3674.0, abs=0.6)
