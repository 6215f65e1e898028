"""The driven rotating-nut unit (THK DIR/BLR): its catalog rows, the estimates that stand in for
what THK does not print, and what turning the nut instead of the screw changes in the model
(model.checks.unit_checks, model.params.rotating_nut_params).  Published values name their
source."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from axisopt.catalog.loading import default_catalog
from axisopt.design import Axis, Design
from axisopt.model import PARAM_NAMES, axis_response
from axisopt.model.function import design_params, evaluate
from axisopt.model.params import positions, rotating_nut_params
from axisopt.physics.screw import screw_rotary_inertia

RPM = 60.0 / (2.0 * math.pi)
NA = 1e9


def _design(
    nut="THK-DIR4010-6", screw="THK-DIR-40x10", mounting="fixed-fixed", **axis_kw
) -> Design:
    cat = default_catalog()
    kw = {
        "stroke": 2.0,
        "moving_mass": 300.0,
        "mounting": mounting,
        "start_offset": 0.1,
        "end_margin": 0.1,
        "max_speed": 15 / 60,
        "acceleration": 2.0,
        "axial_load": 3000.0,
    }
    kw.update(axis_kw)
    return Design(
        axis=Axis(**kw),
        screw=cat.part("screws", screw),
        nut=cat.part("nuts", nut),
        bearing=cat.part("bearings", "THK-BK30"),
        guide=cat.part("guides", "HIWIN-HG25-ZA"),
        motor=cat.part("motors", "SGM7G-13A"),
    )


@pytest.mark.published
def test_thk_dir_and_blr_rows_in_si():
    # THK General Catalog B-720/B-721: DIR4010-6 Ca 29.8 kN, C0a 69.3 kN, K 750 N/um, support
    # bearing Ca 21.5 kN / C0a 36.8 kN, nut inertia 20.6 kg.cm^2, nut mass 3.55 kg; B-722/B-723:
    # BLR4040-3.6 Ca 38.7 / C0a 99.2 kN, support bearing 59.3 / 74.1 kN, nut inertia 27.9 kg.cm^2
    nuts = default_catalog().nuts
    d = nuts.loc["THK-DIR4010-6"]
    assert d["rotating"] == 1 and d["type"] == "double"
    assert d["dynamic_load_rating"] == pytest.approx(29.8e3) and d[
        "static_load_rating"
    ] == pytest.approx(69.3e3)
    assert d["stiffness"] == pytest.approx(750e6) and d["stiffness_preload"] == pytest.approx(
        0.1 * 29.8e3
    )
    assert d["unit_bearing_dynamic_load"] == pytest.approx(21.5e3)
    assert d["unit_bearing_static_load"] == pytest.approx(36.8e3)
    assert d["unit_inertia"] == pytest.approx(20.6e-4) and d["mass"] == pytest.approx(3.55)
    b = nuts.loc["THK-BLR4040-3.6"]
    assert b["rotating"] == 1 and b["type"] == "single"
    assert (b["dynamic_load_rating"], b["static_load_rating"]) == (
        pytest.approx(38.7e3),
        pytest.approx(99.2e3),
    )
    assert (b["unit_bearing_dynamic_load"], b["unit_bearing_static_load"]) == (
        pytest.approx(59.3e3),
        pytest.approx(74.1e3),
    )
    assert b["unit_inertia"] == pytest.approx(27.9e-4)
    # a nut on a turning screw: no flag
    assert math.isnan(nuts.loc["THK-BNFN4010-5"]["rotating"])


@pytest.mark.published
def test_unit_speed_without_a_vendor_figure_is_thk_dn_rule():
    # THK A-697: DN <= 70 000 for precision ball screws, D the ball centre diameter dp; DIR4010-6 dp
    # = 41.75 mm (B-720), so the nut turns at most 70 000 / 41.75 = 1 677 rpm relative to the screw
    d = _design()
    p = design_params(d)
    assert p["nut_rotating"] == 1.0
    assert p["unit_max_speed"] * RPM == pytest.approx(70_000 / 41.75, abs=0.5)
    ev = evaluate(d)
    assert ev["available_unit_speed"] * RPM == pytest.approx(70_000 / 41.75, abs=0.5)
    # 15 m/min on a 10 mm lead: 1 500 rpm
    assert ev["margin_unit_speed"] == pytest.approx((70_000 / 41.75) / 1500.0, rel=1e-3)


def test_estimates_of_the_unit_are_named():
    from axisopt.model.estimates import design_estimates

    cols = {e.column for e in design_estimates(_design())}
    assert {"unit_max_speed", "unit_bearing_rigidity", "unit_starting_torque"} <= cols
    plain = {e.column for e in design_estimates(_design("THK-BNFN4010-5", "THK-BNFN-40x10"))}
    assert not any(c.startswith("unit_") for c in plain)


def test_turning_the_nut_instead_of_the_screw():
    rot, plain = _design(), _design("THK-DIR4010-6", "THK-DIR-40x10")
    plain = dataclasses.replace(plain, nut=dict(plain.nut, rotating=0.0))
    er, ep = evaluate(rot), evaluate(plain)
    # no whirl of a standing screw; the end bearings do not turn (life and speed n/a), their static
    # check stays
    assert er["margin_critical_speed"] == NA and ep["margin_critical_speed"] < NA
    assert er["margin_bearing_life"] == NA and er["margin_bearing_speed"] == NA
    assert er["margin_bearing_static"] == pytest.approx(ep["margin_bearing_static"])
    assert ep["margin_unit_speed"] == NA and ep["margin_rotating_mount"] == NA
    # the unit's rotating parts instead of the screw in the drive inertia (THK B-721 "nut inertia")
    j_screw = screw_rotary_inertia(rot.screw["nominal_diameter"], rot.axis.span)
    assert er["load_inertia"] - ep["load_inertia"] == pytest.approx(20.6e-4 - j_screw, rel=1e-9)
    # the unit bearing in series in the chain: 1/k grows by 1/k_unit (11.2 N/um per kN of Ca: 240.8
    # N/um)
    k_unit = rotating_nut_params(design_params(rot), rot.nut)["unit_bearing_stiffness"]
    assert k_unit == pytest.approx(11.2e6 * 21.5, rel=1e-9)
    i = int(np.argmin(ep["k_total"]))
    assert 1 / er["k_total"][i] - 1 / ep["k_total"][i] == pytest.approx(1 / k_unit, rel=1e-6)
    # drag: the unit's bearing instead of the two end sets
    assert er["drag_bearings"] == pytest.approx(3.72e-3 * 0.05 * 21.5e3 * 2.5 * 0.040, rel=1e-9)
    assert er["margin_rotating_mount"] == 1.0


def test_one_formula_on_floats_numpy_and_casadi_for_a_mix_of_rows():
    designs = [
        _design(),
        _design("THK-BNFN4010-5", "THK-BNFN-40x10"),
        _design("THK-BLR4040-3.6", "THK-BLW-40x40"),
    ]
    ps = [design_params(d) for d in designs]
    x = positions(designs[0].axis)
    pre = np.array([d.preload for d in designs])
    many = {n: np.array([float(p[n]) for p in ps])[:, None] for n in PARAM_NAMES}
    many["duty"] = ps[0]["duty"]
    out = axis_response(many, x[None, :], "fixed-fixed", pre[:, None])
    keys = (
        "k_total",
        "drag_torque",
        "load_inertia",
        "margin_critical_speed",
        "margin_unit_speed",
        "margin_unit_bearing_life",
        "margin_unit_bearing_static",
        "margin_bearing_life",
        "screw_sag",
        "friction_power",
        "f_axial_torsional",
        "margin_rotating_mount",
    )
    for i, d in enumerate(designs):
        one = axis_response(ps[i], x, "fixed-fixed", float(pre[i]))
        sym = evaluate(d, use_casadi=True)
        for k in keys:
            row = np.asarray(out[k])[i] if np.ndim(out[k]) else out[k]
            assert np.allclose(row, one[k], rtol=1e-9), k
            assert np.allclose(np.ravel(sym[k]), np.ravel(one[k]), rtol=1e-9), k


def test_sag_only_on_a_horizontal_axis():
    h = evaluate(_design())
    v = evaluate(_design(orientation="vertical"))
    assert h["screw_sag"] > 0 and v["screw_sag"] == 0.0


def test_a_reductions_output_torque_turns_the_unit_not_the_screw():
    """A gearbox driving a rotating-nut unit accelerates the unit's turning parts (THK B-721 "nut
    inertia"), not the standing screw: its output torque (T2B, T2N checks) takes the same inertia as
    the motor torque does."""
    from axisopt.model.drive import output_torques

    p = design_params(_design())
    plain = dict(p, nut_rotating=0.0)
    drag, a = 0.5, 2.0
    rot_t = output_torques(p, 300.0, drag, p["duty"])[0]
    plain_t = output_torques(plain, 300.0, drag, p["duty"])[0]
    j_screw = screw_rotary_inertia(p["nominal_diameter"], p["span"])
    lead = p["lead"]
    accel = [i for i, ph in enumerate(p["duty"]) if ph.a0 == a and ph.direction > 0][0]
    assert rot_t[accel][0] - plain_t[accel][0] == pytest.approx(
        (20.6e-4 - j_screw) * 2 * math.pi / lead * a, rel=1e-9
    )
