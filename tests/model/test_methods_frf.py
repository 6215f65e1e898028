"""Stiffness by every seed method (``evaluate --methods``) and the table's dynamic compliance
(``--frf``)."""

import dataclasses
import json
import math
from pathlib import Path

import numpy as np
import pytest
import yaml

from axisopt.design import load_design
from axisopt.model import design_params, evaluate
from axisopt.model.loads import bearing_set_stiffness
from axisopt.model.methods import bearing_c_type, stiffness_methods
from axisopt.report.methods import methods_dict, methods_table

ROOT = Path(__file__).resolve().parents[2]


def _design_files():
    out = []
    for f in sorted(
        list((ROOT / "problems").glob("*.yaml")) + list((ROOT / "problems" / "data").glob("*.yaml"))
    ):
        doc = yaml.safe_load(f.read_text(encoding="utf-8"))
        if isinstance(doc, dict) and "parts" in doc:
            out.append(f)
    return out


DESIGNS = _design_files()


@pytest.fixture(scope="module")
def evals():
    return {f.name: evaluate(load_design(f)) for f in DESIGNS}


def test_designs_found():
    assert len(DESIGNS) >= 5


@pytest.mark.parametrize("name", [f.name for f in DESIGNS])
def test_methods_rows(evals, name):
    ev = evals[name]
    rows = stiffness_methods(ev)
    assert {r.component for r in rows} == {"nut", "bearings", "screw"}
    used = {r.component: r for r in rows if r.used}
    assert set(used) == {"nut", "bearings", "screw"}
    assert sum(r.used for r in rows) == 3
    assert used["nut"].value_N_per_m == pytest.approx(ev["k_nut_unloaded"], rel=1e-12)
    assert used["screw"].value_N_per_m == pytest.approx(float(np.min(ev["k_screw"])), rel=1e-12)
    p = design_params(ev.design)
    c_a = used["bearings"].value_N_per_m
    assert c_a == pytest.approx(float(ev.design.bearing["axial_rigidity"]), rel=1e-12)
    # the model: bearing sets x (one set in series with its housing)
    assert p["bearing_sets"] * float(bearing_set_stiffness(p)) == pytest.approx(
        ev["k_bearing"], rel=1e-9
    )
    for r in rows:
        if r.value_N_per_m is None:
            assert r.missing and all(isinstance(m, str) and m for m in r.missing), r
        else:
            assert r.missing == () and math.isfinite(r.value_N_per_m) and r.value_N_per_m > 0, r
    # no shipped part has a ball count: Hertz, Palmgren, Kraemer report it missing, never invent it
    by = {(r.component, r.method): r for r in rows}
    assert "n_balls" in by[("nut", "Hertz eq. 12-18")].missing
    assert {"ball_diameter", "n_balls"} <= set(by[("bearings", "Palmgren eq. 21-23")].missing)
    assert {"ball_diameter", "n_balls"} <= set(by[("bearings", "Kraemer eq. 25-26")].missing)
    table = methods_table(rows)
    assert "missing: n_balls" in table and "*" in table
    js = methods_dict(rows)
    json.dumps(js, allow_nan=False)
    assert [m["value_N_per_um"] is None for m in js["methods"]] == [
        r.value_N_per_m is None for r in rows
    ]


def test_methods_compute_when_columns_exist(evals):
    """A nut with n_balls and a 7012C spindle bearing set with ball data: every method gives a
    value."""
    ev = evals["vmc_x_design.yaml"]
    d = ev.design
    nut = d.nut.copy()
    nut["n_balls"] = 40.0
    brg = d.bearing.copy()
    brg["series"] = "7012C spindle bearing"
    brg["contact_angle"] = math.radians(15.0)
    brg["ball_diameter"] = 11.1e-3
    brg["n_balls"] = 19.0
    d2 = dataclasses.replace(d, nut=nut, bearing=brg)
    rows = stiffness_methods(evaluate(d2))
    assert all(r.value_N_per_m is not None and r.value_N_per_m > 0 for r in rows), [
        r for r in rows if not r.missing
    ]
    assert bearing_c_type("7012C", math.radians(15.0)) == 5.43
    assert bearing_c_type("71912AC") == 5.83
    assert bearing_c_type("7205B angular contact ball bearing set") is None
    assert bearing_c_type("7012C", math.radians(25.0)) is None
