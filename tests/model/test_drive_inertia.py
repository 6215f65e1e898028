"""The drive sizes the screw's inertia as the vendors do: a solid steel cylinder of the nominal
diameter (THK A-744 'inertial moment per unit length of the screw shaft' at the shaft diameter;
FANUC B-65142E sec. 4; HIWIN F 3.20 'dn Nominal diameter'; Mitsubishi MDS-B-SVJ2 sec. 11-5), over
the model's screw length (the bearing span).  Checked against the load inertia written out here from
THK eq. 45, apart from the model."""

import math
from pathlib import Path

import pytest

from axisopt.design import load_design
from axisopt.model import evaluate

ROOT = Path(__file__).resolve().parents[2]


def test_load_inertia_uses_the_nominal_diameter_over_the_span():
    d = load_design(ROOT / "problems" / "vmc_x_design.yaml")
    ev = evaluate(d, use_casadi=False)
    screw = d.screw
    moving = float(ev.values["moving_mass"])
    lead, dn = float(screw["lead"]), float(screw["nominal_diameter"])
    span = float(d.axis.span)
    j_screw = math.pi * 7850.0 * dn**4 * span / 32.0  # THK A-744, rho 7.85e-6 kg/mm^3
    j_coupling = float(d.coupling["inertia"]) if d.coupling is not None else d.axis.coupling_inertia
    # THK eq. 45, direct drive
    expected = moving * (lead / (2 * math.pi)) ** 2 + j_screw + j_coupling
    assert float(ev.values["load_inertia"]) == pytest.approx(expected, rel=1e-9)
