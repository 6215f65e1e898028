"""tools/vendor_check_drives.py (written apart from axisopt: it runs the program, reads the catalog rows and
the problem's YAML, and samples the duty cycle in time) passes the router's rack-and-pinion design and the
laser axis's linear-motor design by the vendors' printed steps, and agrees with axisopt's margins."""

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
    "name, kind", [("router_rack_problem", "rack_pinion"), ("laser_lm_problem", "linear_motor")]
)
def test_the_vendor_steps_pass_and_agree(name, kind, monkeypatch):
    monkeypatch.setenv("PYTHONPATH", str(ROOT) + os.pathsep + os.environ.get("PYTHONPATH", ""))
    lines, res = vcd.check(ROOT / "problems" / f"{name}.yaml")
    assert res["best"]["drive_type"] == kind
    assert len(lines) >= 5
    for check, value, limit, margin, verdict, model, _agree in lines:
        assert verdict == "PASS", (check, value, limit, margin)
        assert model == pytest.approx(margin, rel=5e-3), (
            check
        )  # the sampled cycle against the exact integrals
