"""The assembled axis model: one formula on floats, numpy and CasADi; stroke behaviour by
mounting."""

import dataclasses
import math
from dataclasses import replace
from pathlib import Path

import casadi as ca
import numpy as np
import pytest

from axisopt.design import load_design
from axisopt.model import (
    CHECKS,
    PARAM_NAMES,
    PROFILE_OUTPUTS,
    SCALAR_OUTPUTS,
    axis_response,
    design_params,
    evaluate,
    positions,
)
from axisopt.physics import dynamics, screw

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def vmc():
    """The shipped VMC design on the HIWIN WBK30-DFD set the hand calculations below use (HIWIN
    Table 8.12: 1520 N/um; the shipped file has an NSK light-preload set, which outlives the WBK's
    single row)."""
    from axisopt.catalog.loading import load_catalogs

    d = load_design(ROOT / "problems" / "vmc_x_design.yaml")
    return dataclasses.replace(d, bearing=load_catalogs().bearings.loc["HIWIN-WBK30-DFD"])


@pytest.mark.parametrize("mounting", ["fixed-free", "fixed-supported", "fixed-fixed"])
def test_float_numpy_casadi_agree(vmc, mounting):
    d = dataclasses.replace(vmc, axis=dataclasses.replace(vmc.axis, mounting=mounting))
    p = design_params(d)
    x = positions(d.axis)
    ev_np = evaluate(d, use_casadi=False)
    ev_ca = evaluate(d, use_casadi=True)
    for k in PROFILE_OUTPUTS + SCALAR_OUTPUTS:
        assert np.allclose(ev_np[k], ev_ca[k], rtol=1e-10), k
    # float evaluation position by position
    for i in (0, len(x) // 2, len(x) - 1):
        one = axis_response(p, float(x[i]), mounting, d.preload)
        assert float(one["k_total"]) == pytest.approx(ev_np["k_total"][i], rel=1e-12)
        assert float(one["f1"]) == pytest.approx(ev_np["f1"][i], rel=1e-12)
    # a SX graph with the parameters symbolic, evaluated at the same numbers
    sym = ca.SX.sym("p", len(PARAM_NAMES))
    out = axis_response(
        {n: sym[i] for i, n in enumerate(PARAM_NAMES)}, ca.DM(x), mounting, d.preload
    )
    f = ca.Function("f", [sym], [out["k_total"], out["drag_torque"], out["margin_nut_life"]])
    k, drag, life = f([p[n] for n in PARAM_NAMES])
    assert np.allclose(np.asarray(k).ravel(), ev_np["k_total"], rtol=1e-10)
    assert float(drag) == pytest.approx(ev_np["drag_torque"], rel=1e-10)
    assert float(life) == pytest.approx(ev_np["margin_nut_life"], rel=1e-10)


def test_vectorised_over_designs(vmc):
    """Many designs at once: arrays of parameters broadcast against the positions."""
    p = design_params(vmc)
    x = positions(vmc.axis)[None, :]
    pre = np.array([1000.0, 2000.0, 3000.0])[:, None]
    many = axis_response(p, x, vmc.axis.mounting, pre)
    assert many["k_total"].shape == (3, len(x[0]))
    for i in range(3):
        one = axis_response(p, x[0], vmc.axis.mounting, float(pre[i, 0]))
        assert np.allclose(many["k_total"][i], one["k_total"], rtol=1e-12)


def test_fixed_fixed_minimum_is_at_mid_span(vmc):
    d = dataclasses.replace(
        vmc,
        axis=dataclasses.replace(
            vmc.axis, mounting="fixed-fixed", start_offset=0.1, end_margin=0.1
        ),
    )
    ev = evaluate(d)
    _, where = ev.minimum("k_screw")
    assert where + d.axis.start_offset == pytest.approx(d.axis.span / 2, abs=1e-9)
    # and the screw is four times stiffer there than a fixed-free screw of the same span at its end
    kmid = screw.screw_stiffness(
        d.screw["root_diameter"], d.axis.span / 2, d.axis.span, "fixed-fixed"
    )
    kend = screw.screw_stiffness(d.screw["root_diameter"], d.axis.span, d.axis.span, "fixed-free")
    assert kmid / kend == pytest.approx(4.0)


def test_fixed_free_softest_at_stroke_end(vmc):
    d = dataclasses.replace(vmc, axis=dataclasses.replace(vmc.axis, mounting="fixed-free"))
    ev = evaluate(d)
    k = np.asarray(ev["k_total"])
    assert np.all(np.diff(k) < 0)
    assert ev.minimum("k_total")[1] == pytest.approx(d.axis.stroke)


def test_preload_raises_stiffness_drag_and_lowers_life(vmc):
    lo = evaluate(dataclasses.replace(vmc, nut_preload=float(vmc.nut["preload_min"])))
    hi = evaluate(dataclasses.replace(vmc, nut_preload=float(vmc.nut["preload_max"])))
    assert hi["k_nut"] > lo["k_nut"] and hi["drag_torque"] > lo["drag_torque"]
    assert hi["margin_nut_life"] < lo["margin_nut_life"]
    assert set(lo.checks()) == set(CHECKS)


@pytest.mark.published
def test_paper_3_1_3_frequency_and_stiffness_trend():
    """Seed paper section 3.1.3, eq. (10)-(11): l0 = 0.13 m, 2 m screw, m = 450 kg, d = 25/40/50/63
    mm.

    The paper states that stiffness and frequency fall with the active length l_x and rise with d.
    Our shipped examples reproduce the study with real catalog screws; here eq. (11) itself is
    checked against the model's screw term with the paper's numbers (E = 2e11 N/m^2, d as the bar).
    """
    for d in (0.025, 0.040, 0.050, 0.063):
        lx = np.linspace(0.13, 2.0, 50)
        w = dynamics.axial_angular_frequency_eq11(d, lx, 450.0, youngs_modulus=2e11)
        k = screw.screw_stiffness(d, lx, 2.0, "fixed-free", youngs_modulus=2e11)
        assert np.allclose(w, np.sqrt(k / 450.0), rtol=1e-12)
        assert np.all(np.diff(w) < 0)
    # hand check of eq. (10), d = 40 mm, l_x = 0.13 m: pi * 0.04^2 * 2e11 / (4 * 0.13) = 1933.29
    # N/um
    assert screw.screw_stiffness(
        0.040, 0.13, 2.0, "fixed-free", youngs_modulus=2e11
    ) / 1e6 == pytest.approx(1933.29, abs=0.01)
    designs = [load_design(ROOT / "problems" / f"paper_3_1_3_d{d}.yaml") for d in (25, 40, 50, 63)]
    mins = [evaluate(d).minimum("k_total")[0] for d in designs]
    assert mins == sorted(mins)


def test_vmc_example_against_a_hand_calculation(vmc):
    """The shipped VMC design, evaluated by hand from its catalog rows (HIWIN BS-08-2-EN-1704-K):
    screw root 34.91 mm, lead 20 mm, span 0.13 + 0.8 + 0.17 m, fixed-supported, nut R40-20K4-FDC
    1150 N/um at 0.1 Ca = 5130 N run at 3000 N (HIWIN F 3.34) and then loaded by the largest axial
    force (Hertz halves, lift-off at 2.83 x preload), WBK30-DFD 1520 N/um, screw torsion G pi d^4 /
    (32 x) through the lead, the default coupling (RINGFEDER GWB AKN 60, 75e3 N.m/rad) through the
    lead, and the default mounts (issue 38): the housing 1050/40 = 26.25 x the set (IBC BSBU 35 DB
    128 on its bare set, 1050 on 1090 N/um), the bracket 4 x 0.8 x the nut's 1150 N/um (THK's 80 %
    nut-mounting allowance once more)."""
    ev = evaluate(vmc)
    x_end = 0.13 + 0.8
    lead = 0.020
    k_s = math.pi / 4 * 0.03491**2 * 206e9 / x_end  # eq. 3/10
    k_n0 = 0.8 * 1150e6 * (3000 / 5130) ** (1 / 3)  # eq. 9
    # largest axial force: 3000 N cut + 456.8 kg x 3 m/s^2 + guide friction
    f_max = float(ev["max_axial_force"])
    moving = 450 + float(vmc.nut["mass"]) + 4 * float(vmc.guide["block_mass"])
    assert f_max > 3000 + moving * 3.0
    # Hertz double nut under f_max, solved here by bisection on (1+s)^1.5 - (1-s)^1.5 = f/F_pr
    f = f_max / 3000.0
    lo, hi = 0.0, 1.0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if (1 + mid) ** 1.5 - (1 - mid) ** 1.5 < f:
            lo = mid
        else:
            hi = mid
    k_n = k_n0 * 0.5 * (math.sqrt(1 + lo) + math.sqrt(1 - lo))
    k_b = 1520e6
    k_tors = 79.3e9 * math.pi * 0.03491**4 / (32 * x_end) * (2 * math.pi / lead) ** 2
    k_cpl = 75e3 * (2 * math.pi / lead) ** 2
    k_housing = 1050 / 40 * k_b
    k_bracket = 4 * 0.8 * 1150e6
    k = 1 / (1 / k_s + 1 / k_n + 1 / k_b + 1 / k_housing + 1 / k_bracket + 1 / k_tors + 1 / k_cpl)
    assert k_s / 1e6 == pytest.approx(212.0, abs=0.05)
    assert ev["k_nut_unloaded"] == pytest.approx(k_n0, rel=1e-9)
    assert ev["k_nut"] == pytest.approx(k_n, rel=1e-9)
    assert ev.minimum("k_total")[0] == pytest.approx(k, rel=1e-9)
    # eq. 11 with the moving mass and the Rayleigh share of the screw (part beyond the nut moves
    # with it)
    screw_mass = float(vmc.screw["mass_per_length"]) * 1.1
    m_eff = moving + screw_mass * (1 - 2 * x_end / (3 * 1.1))
    f1 = math.sqrt(k / m_eff) / (2 * math.pi)
    assert ev["f_axial"][-1] == pytest.approx(f1, rel=1e-9)


def _two_path_hand(k_b, ea, x, span, mounting):
    """Screw and bearings by hand: near set + segment x, in parallel with far set + segment L - x
    (fixed-fixed)."""
    near = 1 / (1 / k_b + x / ea)
    if mounting != "fixed-fixed":
        return near
    return near + 1 / (1 / k_b + (span - x) / ea)


@pytest.mark.parametrize("mounting", ["fixed-free", "fixed-supported", "fixed-fixed"])
def test_evaluate_and_diagnose_agree_on_the_chain(vmc, mounting):
    """The same design in evaluate and in diagnose's plant gives the same compliance at every
    position (nut taken at the same stiffness), and both equal the two-path chain written out by
    hand."""
    from axisopt.identify import plant_from_design
    from axisopt.identify.tables.measure import (
        baseline_terms,
        drive_compliance,
        screw_bearing_compliance,
    )

    d = replace(
        vmc,
        axis=replace(
            vmc.axis,
            mounting=mounting,
            bearing_housing_stiffness=4000e6,
            nut_bracket_stiffness=2500e6,
        ),
    )
    ev = evaluate(d)
    plant = plant_from_design(d)
    q = baseline_terms(plant, {})
    c_diag = (
        screw_bearing_compliance(q, ev.x, plant.span)
        + drive_compliance(plant, ev.x)
        + 1 / plant.k_nut
    )
    c_eval = 1 / np.asarray(ev["k_total"]) - 1 / ev["k_nut"] + 1 / ev["k_nut_unloaded"]
    np.testing.assert_allclose(c_diag, c_eval, rtol=1e-10)
    # by hand: WBK30-DFD 1520 N/um in series with its 4000 N/um housing, at both ends for
    # fixed-fixed
    k_set = 1 / (1 / 1520e6 + 1 / 4000e6)
    ea = 206e9 * math.pi / 4 * 0.03491**2
    k_sb = _two_path_hand(k_set, ea, ev.x, d.axis.span, mounting)
    np.testing.assert_allclose(1 / np.asarray(ev["k_screw_bearings"]), 1 / k_sb, rtol=1e-12)


def test_fixed_fixed_shortcut_is_exact_only_at_mid_span(vmc):
    """The old shortcut (both sets summed, in series with the screw's two segments) equals the
    two-path chain at mid-span and overstates it elsewhere (about 20 % at x = 0.1 L for stiff-screw,
    soft-bearing axes)."""
    k_b, ea, span = 300e6, 206e9 * math.pi / 4 * 0.03491**2, 1.0
    x = np.array([0.1, 0.5])
    exact = _two_path_hand(k_b, ea, x, span, "fixed-fixed")
    shortcut = 1 / (1 / (2 * k_b) + x * (span - x) / (ea * span))
    assert shortcut[1] == pytest.approx(exact[1], rel=1e-12)
    assert shortcut[0] > 1.1 * exact[0]
    from axisopt.physics.screw import screw_bearing_stiffness

    np.testing.assert_allclose(
        screw_bearing_stiffness(0.03491, x, span, "fixed-fixed", k_b), exact, rtol=1e-12
    )


def test_single_nut_follows_hiwin_f335_and_has_play():
    """HIWIN BS-08-2-EN-1704-K F 3.35: a single nut with play is rated at the mean operating load,
    R_n = 0.8 K (F_bm / (0.28 C_dyn))^(1/3); R40-20K4-FSC: K = 870 N/um, C_dyn = 51 300 N (Table
    6.4)."""
    d = load_design(ROOT / "problems" / "vmc_x_design.yaml")
    cat = d.screw  # same screw (40x20, ball 6.35)
    from axisopt.catalog.loading import default_catalog

    nut = default_catalog().nuts.loc["HIWIN-R40-20K4-FSC"]
    assert nut["screw_id"] == cat["id"]
    single = replace(d, nut=nut, nut_preload=None)
    ev = evaluate(single)
    f_bm = float(ev["mean_axial_force"])
    assert ev["k_nut"] == pytest.approx(0.8 * 870e6 * (f_bm / (0.28 * 51300)) ** (1 / 3), rel=1e-3)
    assert ev["backlash"] == pytest.approx(float(nut["axial_play"])) and ev["backlash"] > 0
    # no preload: the preload drag rule gives nothing (seals are not modelled)
    assert ev["drag_nut"] == 0.0
