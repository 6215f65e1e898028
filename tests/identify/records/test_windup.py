"""Backlash windup without the motor side's friction bias
(:mod:`axisopt.identify.records.lostmotion`) and the position loop's structure
(:mod:`axisopt.identify.records.controller`), hidden in records of tests/identify/sim_twomass.py:
a motor-side mass with its own Coulomb and viscous friction tied through a spring with a dead zone
to the table, a PD loop or a P-PI cascade, AR(1) force noise and sampling jitter -- physics written
apart from the identification's columns."""

from __future__ import annotations

import json

import numpy as np
import pytest
from identify_helpers import DESIGN
from sim_twomass import Servo, TwoMass, simulate, write

from axisopt.cli import main
from axisopt.identify.records.controller import fit_controller
from axisopt.identify.records.idim import diagnose_time_files
from axisopt.identify.records.record import read_time_record
from axisopt.identify.records.regression import make_rows, processing_for
from axisopt.report.timediag import time_diagnosis_text


def runs(tmp_path, ax, sv, seed, external=False):
    return [
        write(tmp_path / f"est{seed}.csv", simulate(ax, sv, 12.0, seed), external),
        write(tmp_path / f"val{seed}.csv", simulate(ax, sv, 8.0, seed + 500), external),
    ]


# (seed, gap, k, Fc1, Fv1, loop, AR rho, jitter, beside): motor-side friction from none to as
# strong as the table's own; white and coloured noise; jitter up to 10 % of the period; alone and
# beside a table-side Stribeck rise or a process force on the table
CASES = [
    (11, 30e-6, 4e6, 150.0, 400.0, "pd", 0.0, 0.0, ""),
    (12, 50e-6, 3e6, 300.0, 900.0, "pd", 0.7, 0.05, ""),
    (13, 20e-6, 6e6, 200.0, 800.0, "ppi", 0.5, 0.0, ""),
    (14, 40e-6, 4e6, 350.0, 300.0, "ppi", 0.8, 0.1, "stribeck"),
    (15, 30e-6, 5e6, 250.0, 600.0, "pd", 0.6, 0.05, "process_force"),
]


@pytest.mark.parametrize("seed, gap, k, fc1, fv1, loop, rho, jitter, beside", CASES)
def test_windup_stiffness_without_the_motor_friction_bias(
    tmp_path, plant, seed, gap, k, fc1, fv1, loop, rho, jitter, beside
):
    ax = TwoMass(
        gap=gap,
        k=k,
        fc1=fc1,
        fv1=fv1,
        stribeck=250.0 if beside == "stribeck" else 0.0,
        load_amp=600.0 if beside == "process_force" else 0.0,
    )
    sv = Servo(kind=loop, rho=rho, jitter=jitter)
    paths = runs(tmp_path, ax, sv, seed, external=beside == "process_force")
    diag = diagnose_time_files(paths, plant=plant)
    text = time_diagnosis_text(diag)
    assert "backlash" in diag.verdict, text
    lm = diag.lost
    assert lm.width == pytest.approx(gap, rel=0.1)
    assert lm.stiffness == pytest.approx(k, rel=0.1)  # was (Fc1 + Fc2) / Fc2 high
    assert lm.motor_coulomb == pytest.approx(fc1, rel=0.1)
    assert lm.motor_mass == pytest.approx(ax.m1, rel=0.1)
    assert "motor side's own friction" in " ".join(text.split())


@pytest.mark.parametrize("seed, fc1, loop, rho", [(21, 200.0, "pd", 0.7), (22, 0.0, "ppi", 0.0)])
def test_windup_without_a_gap_names_no_backlash(tmp_path, plant, seed, fc1, loop, rho):
    """A compliant transmission with motor-side friction and no gap (a decoy: the friction shares
    the gap's sign in steady motion), coloured noise or none: no backlash."""
    ax = TwoMass(gap=0.0, fc1=fc1, fv1=500.0)
    diag = diagnose_time_files(runs(tmp_path, ax, Servo(kind=loop, rho=rho), seed), plant=plant)
    assert "backlash" not in diag.verdict
    assert diag.lost is not None and not diag.lost.accepted


def _rows(path):
    rec = read_time_record(path, lead=0.01, gain=None, efficiency=0.9)
    return make_rows(rec, processing_for(rec, 0.8, 0.01))


@pytest.mark.parametrize(
    "seed, kx, bw_v, ti, rho, jitter",
    [
        (31, 8.0, 4.0, 0.05, 0.0, 0.0),
        (32, 15.0, 5.0, 0.2, 0.7, 0.05),
        (33, 5.0, 3.0, 0.1, 0.5, 0.1),
    ],
)
def test_a_p_pi_cascade_is_named_with_its_gains(tmp_path, seed, kx, bw_v, ti, rho, jitter):
    ax = TwoMass(gap=10e-6, fc1=100.0, fv1=200.0)
    sv = Servo(kind="ppi", kx=kx, bw_v=bw_v, ti=ti, rho=rho, jitter=jitter)
    c = fit_controller(_rows(write(tmp_path / "c.csv", simulate(ax, sv, 10.0, seed))))
    assert c.structure == "p_pi_cascade" and c.source == "fitted"
    kx_fit, kv_fit, ti_fit = c.cascade
    kv = (ax.m1 + ax.m2) * 2 * np.pi * bw_v
    assert kv_fit == pytest.approx(kv, rel=0.1)
    # Kx and 1/Ti enter the loop's law alike (controller's docstring): compared as a pair
    assert sorted([kx_fit, 1 / ti_fit]) == pytest.approx(sorted([kx, 1 / ti]), rel=0.1)


@pytest.mark.parametrize("seed, bw, rho, load", [(41, 3.0, 0.0, 0.0), (42, 4.0, 0.8, 600.0)])
def test_a_pd_loop_is_named_pd(tmp_path, seed, bw, rho, load):
    """A PD loop, also with coloured noise and a process force the integral could take for its
    own (a decoy): PD, with its gains."""
    ax = TwoMass(gap=0.0, load_amp=load)
    sv = Servo(kind="pd", bw=bw, rho=rho)
    c = fit_controller(_rows(write(tmp_path / "c.csv", simulate(ax, sv, 10.0, seed))))
    w = 2 * np.pi * bw
    M = ax.m1 + ax.m2
    assert c.structure == "pd" and c.cascade is None
    assert c.kp == pytest.approx(M * w * w, rel=0.1) and c.kd == pytest.approx(1.6 * w * M, rel=0.1)


def test_the_design_states_the_structure(tmp_path, plant):
    """A stated structure is fitted as stated; one the record contradicts carries a note; the
    instrumental variables converge on a P-PI record (they assumed PD: a negative derivative gain,
    no convergence)."""
    ax = TwoMass(gap=0.0, fc1=0.0, fv1=0.0)
    path = write(tmp_path / "c.csv", simulate(ax, Servo(kind="ppi"), 10.0, 51))
    rows = _rows(path)
    assert fit_controller(rows, "p_pi_cascade").source == "design"
    pd = fit_controller(rows, "pd")
    assert pd.structure == "pd" and "P-PI cascade?" in pd.note
    diag = diagnose_time_files([path], plant=plant.with_(controller="p_pi_cascade"))
    assert diag.controller.structure == "p_pi_cascade" and diag.controller.source == "design"
    assert diag.baseline_iv.converged, diag.baseline_iv.note
    assert diag.baseline_iv.value("M") == pytest.approx(ax.m1 + ax.m2, rel=0.1)
    text = " ".join(time_diagnosis_text(diag).split())
    assert "P-PI cascade (position P, velocity PI), stated by the design" in text


def test_cli_json_carries_the_controller_and_the_motor_friction(tmp_path, capsys):
    ax = TwoMass(gap=30e-6, fc1=200.0, fv1=500.0)
    paths = runs(tmp_path, ax, Servo(kind="ppi", rho=0.5), 61)
    assert main(["diagnose", *map(str, paths), "--design", str(DESIGN), "--json", "-"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["controller"]["structure"] == "p_pi_cascade"
    assert out["controller"]["integral_heldout_gain_percent"] > 50.0  # judged on the validation run
    lm = out["lost_motion"]
    assert lm["accepted"] and lm["motor_coulomb_N"] == pytest.approx(200.0, rel=0.1)


@pytest.mark.parametrize("value", ["pid", "PD", "7"])
def test_an_unknown_controller_is_one_line_exit_2(tmp_path, capsys, value):
    text = DESIGN.read_text(encoding="utf-8").replace("axis:\n", f"axis:\n  controller: {value}\n")
    design = tmp_path / "d.yaml"
    design.write_text(text, encoding="utf-8")
    rec = write(tmp_path / "c.csv", simulate(TwoMass(), Servo(), 2.0, 1))
    assert main(["diagnose", str(rec), "--design", str(design)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "controller" in err and "d.yaml" in err


def test_the_stated_controller_survives_the_design_writer(tmp_path):
    """A design's axis.controller is read, kept off the defaults-used list (a structure left out is
    fitted, not assumed) and written back."""
    from axisopt.design import load_design
    from axisopt.design.writer import design_to_dict

    text = DESIGN.read_text(encoding="utf-8").replace(
        "axis:\n", "axis:\n  controller: p_pi_cascade\n"
    )
    path = tmp_path / "d.yaml"
    path.write_text(text, encoding="utf-8")
    d = load_design(path)
    assert d.axis.controller == "p_pi_cascade"
    assert design_to_dict(d)["axis"]["controller"] == "p_pi_cascade"
    plain = load_design(DESIGN)
    assert plain.axis.controller is None and "controller" not in plain.assumed
    assert "controller" not in design_to_dict(plain)["axis"]
