"""SCIP global-MINLP reference (optional extra axisopt[scip]): its optimum equals exhaustive enumeration's on
the teaching problem and on seeded random catalogs; infeasibility, Pareto and CLI exit codes."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from search_synthetic import add_drives, add_reductions, make_catalog, make_double, make_problem

from axisopt.cli import main
from axisopt.errors import InputError
from axisopt.problem import Objective, load_problem
from axisopt.search import solve

pytest.importorskip("pyscipopt")

PROBLEMS = Path(__file__).resolve().parents[2] / "problems"
REL = 1e-4


def _agrees(s, e):
    """SCIP's answer against the exhaustive one: the same optimum (or worse only when stopped)."""
    assert e.status in ("optimal", "infeasible")
    if e.best is None:
        assert s.status == "infeasible" and s.best is None
        return
    assert s.status in ("optimal", "time_limit"), s.message
    if s.best is None:  # stopped without a design it could confirm: nothing claimed
        assert s.status == "time_limit" and not s.certificate.proven
        return
    if s.status == "optimal":
        assert s.best.objective == pytest.approx(e.best.objective, rel=REL)
        assert s.certificate.proven and s.certificate.gap <= 1e-4
    assert s.best.objective <= e.best.objective * (1 + 1e-6)
    # the reported design is the model's evaluation of the chosen parts and preload
    assert s.best.design is not None and s.best.design.nut_preload == pytest.approx(s.best.nut_preload)
    assert s.certificate.feasible is None and s.certificate.combinations == e.certificate.combinations


def _teaching_yaskawa_rule(tmp_path) -> Path:
    """The teaching problem under Yaskawa's own RMS rule (RMS within the rated torque, rms_torque_ratio 1) for its
    Yaskawa motors, at 2 m/s^2 and on part of its catalog: the nuts of its optimum and runner-up (HIWIN R40-40K2
    and R32-40K2 FDC), the three DF support sets that fit them (WBK20/25/30-DF), one motor and one coupling.
    SCIP proves this in seconds.  On the whole teaching catalog it finds the default method's optimum but does
    not prove it within 60 s: with the default 0.8 (issue 26) not within 400 s (207 425 nodes), with the vendor
    screw inertia not at 3 m/s^2 within 300 s (808 340 nodes), and with the vendors' nut and support-set lives
    (HIWIN's two halves, NSK's preloaded sets) not within 60 s in any variant tried (life needs of 5 000 to
    20 000 h, mean speeds of 4 and 8 m/min)."""
    text = (PROBLEMS / "teaching_problem.yaml").read_text(encoding="utf-8")
    old_require = "require: {coupling: [RINGFEDER-GWB-AKN-30, RINGFEDER-GWB-AKN-60]}"
    assert "\naxis:\n" in text and "  acceleration: 3 m/s^2\n" in text and old_require in text
    path = tmp_path / "teaching_problem.yaml"
    text = text.replace("  acceleration: 3 m/s^2\n", "  acceleration: 2 m/s^2\n", 1)
    text = text.replace(old_require, "require: {bearing: [HIWIN-WBK30-DF, HIWIN-WBK25-DF, HIWIN-WBK20-DF], "
                        "nut: [HIWIN-R40-40K2-FDC, HIWIN-R32-40K2-FDC], motor: [SGM7G-13A], "
                        "coupling: [RINGFEDER-GWB-AKN-60]}", 1)
    path.write_text(text.replace("\naxis:\n", "\naxis:\n  rms_torque_ratio: 1\n", 1), encoding="utf-8")
    return path


def test_teaching_problem_equals_exhaustive(tmp_path):
    p = load_problem(_teaching_yaskawa_rule(tmp_path))
    s = solve(p, "scip", time_limit=40)
    _agrees(s, solve(p, "exhaustive", top=1, sensitivities=False))
    assert s.status == "optimal"
    assert "nodes" in s.certificate.notes[0]


# Seed 3 failed from issue 26 to issue 38 (SCIP stopped at preload 1578 N, 45.51 N/um, where exhaustive
# enumeration found 1872 N, 47.04 N/um, on the same parts: SCIP's global search cut the optimum off).  With the
# vendors' load factor and the estimated mounts the problem's optimum moved and SCIP proves it: kept as a case.
@pytest.mark.parametrize("seed", [3, 4])
def test_random_catalogs_equal_exhaustive(seed):
    rng = np.random.default_rng(seed)
    cat = make_catalog(rng, n_screws=3, nuts_per_screw=2, n_bearings=4, n_guides=3)
    limits = {"max_cost": float(rng.uniform(2500, 5000)), "max_drag_torque": float(rng.uniform(0.4, 1.5)),
              "min_life": float(rng.uniform(5e3, 3e4)) * 3600}
    ob = Objective(mode="weighted", weights=(("stiffness", 1.0), ("frequency", 2.0)),
                   scale=(("stiffness", 100e6), ("frequency", 100.0))) if seed == 4 else Objective(mode="stiffness")
    p = make_problem(cat, objective=ob, limits=limits)
    _agrees(solve(p, "scip", time_limit=20), solve(p, "exhaustive", top=1, sensitivities=False))


def test_random_catalog_with_drive_and_frequency_equals_exhaustive():
    rng = np.random.default_rng(105)
    cat = make_catalog(rng, n_screws=3, nuts_per_screw=2, n_bearings=3, n_guides=2)
    make_double(cat)
    cat = add_drives(cat, rng, n_motors=3, n_couplings=2)
    p = make_problem(cat, mode="frequency", limits={"max_cost": 5000.0, "max_drag_torque": 1.5},
                     moving_mass=200.0)
    _agrees(solve(p, "scip", time_limit=20), solve(p, "exhaustive", top=1, sensitivities=False))


def test_random_catalog_with_counterweight_equals_exhaustive():
    """A counterweighted vertical axis with a drive: the one-hot MINLP sees the balance force in the loads and the
    counterweight's inertia and weight in the motor torques as the default method does."""
    from dataclasses import replace

    from axisopt.design import Counterbalance

    rng = np.random.default_rng(105)
    cat = make_catalog(rng, n_screws=3, nuts_per_screw=2, n_bearings=3, n_guides=2)
    make_double(cat)
    cat = add_drives(cat, rng, n_motors=3, n_couplings=2)
    p = make_problem(cat, mode="stiffness", limits={"max_cost": 5000.0, "max_drag_torque": 1.5},
                     moving_mass=200.0, orientation="vertical", axial_load=1500.0,
                     counterbalance=Counterbalance("counterweight", mass=150.0, efficiency=0.9, chain_mass=5.0))
    p = replace(p, restrictions=replace(p.restrictions, drive=True))
    e = solve(p, "exhaustive", top=1, sensitivities=False)
    assert e.best is not None
    _agrees(solve(p, "scip", time_limit=20), e)


def test_random_catalog_with_reductions_equals_exhaustive():
    """(motor, coupling, reduction or none) drives: the one-hot MINLP over the guide-and-drive entries sees the
    reduction's parameters (ratio, efficiency, input inertia, T2B/T2N, n1Max, Ct21, backlash, price) as the
    default method does."""
    from dataclasses import replace

    rng = np.random.default_rng(106)
    cat = make_catalog(rng, n_screws=3, nuts_per_screw=2, n_bearings=3, n_guides=2)
    make_double(cat)
    cat = add_reductions(add_drives(cat, rng, n_motors=2, n_couplings=2), rng, n=2)
    p = make_problem(cat, mode="stiffness", limits={"max_cost": 5000.0, "max_drag_torque": 1.5},
                     moving_mass=200.0, backlash=40e-6)
    p = replace(p, restrictions=replace(p.restrictions, drive=True))
    from axisopt.search.parts import build_space

    assert any(r is not None for _, _, r in build_space(p).drives)
    _agrees(solve(p, "scip", time_limit=30), solve(p, "exhaustive", top=1, sensitivities=False))


def test_infeasible_problem_is_reported_infeasible():
    cat = make_catalog(np.random.default_rng(7), n_screws=2, nuts_per_screw=2, n_bearings=3, n_guides=2)
    p = make_problem(cat, limits={"max_cost": 100.0})
    s = solve(p, "scip", time_limit=20)
    assert solve(p, "exhaustive", sensitivities=False).status == "infeasible"
    assert s.status == "infeasible" and s.best is None and s.certificate.proven


def test_pareto_is_an_input_error():
    p = load_problem(PROBLEMS / "pareto_problem.yaml")
    with pytest.raises(InputError, match="Pareto"):
        solve(p, "scip")


def test_cli_exit_codes(capsys, tmp_path):
    teaching = _teaching_yaskawa_rule(tmp_path)
    assert main(["solve", str(teaching), "--method", "scip", "--time-limit", "40"]) == 0
    out = capsys.readouterr().out
    assert "method scip: status optimal" in out
    assert main(["solve", str(teaching), "--method", "scip", "--time-limit", "0.01"]) == 3
    assert main(["solve", str(PROBLEMS / "pareto_problem.yaml"), "--method", "scip"]) == 2
    assert "Pareto" in capsys.readouterr().err


def test_missing_pyscipopt_names_the_extra(monkeypatch):
    import sys

    monkeypatch.setitem(sys.modules, "pyscipopt", None)  # import fails as if not installed
    p = load_problem(PROBLEMS / "teaching_problem.yaml")
    with pytest.raises(InputError, match=r"pip install 'axisopt\[scip\]'"):
        solve(p, "scip")


def test_contradicted_proof_is_detected():
    """A proof of infeasibility, or of an optimum below a design the search finds, is contradicted (the check
    that turns SCIP's numerically wrong proofs into a failure)."""
    from axisopt.search.minlp.scip import _contradiction
    from axisopt.search.parts import build_space
    from axisopt.search.task.constraints import build_constraints
    from axisopt.search.task.objective import objective_spec

    p = load_problem(PROBLEMS / "teaching_problem.yaml")
    space, cons, spec = build_space(p), build_constraints(p), objective_spec("stiffness")
    e = solve(p, "exhaustive", top=1, sensitivities=False)
    assert "no design meets the limits" in _contradiction(space, cons, spec, None)
    assert _contradiction(space, cons, spec, e.best) == ""
    from dataclasses import replace

    worse = replace(e.best, objective=0.9 * e.best.objective)
    assert "SCIP's proof is wrong" in _contradiction(space, cons, spec, worse)


@pytest.mark.slow
def test_highspeed_problem_never_a_wrong_proof():
    """SCIP's LP relaxation proves the high-speed problem's stage 2 infeasible (57 s, proven) although the default
    method and exhaustive enumeration solve it (99.37 N/um): the answer is the optimum, a time limit or a failure,
    never a wrong proven answer."""
    p = load_problem(PROBLEMS / "highspeed_problem.yaml")
    s = solve(p, "scip", time_limit=45)
    assert s.status in ("optimal", "time_limit", "solver_failed"), s.message
    if s.certificate.proven or s.status == "optimal":
        assert s.status == "optimal" and s.best.objective == pytest.approx(99.3745, rel=1e-4)
    if s.status == "solver_failed":
        assert not s.certificate.proven and "proof is wrong" in s.message



@pytest.mark.parametrize("method", ["scip", "bonmin"])
def test_twin_drive_is_refused(method, tmp_path, capsys):
    """A twin-drive gantry (issue 40): SCIP's relaxation of the gantry's 2-DOF eigenvalues contradicted
    enumeration on a synthetic case (proof 'contradicted by a feasible design'), so the MINLP references refuse
    it with a one-line error (exit 2) instead of answering."""
    p = load_problem(PROBLEMS / "gantry_twin_problem.yaml")
    with pytest.raises(InputError, match="twin-drive"):
        solve(p, method)
    rc = main(["solve", str(PROBLEMS / "gantry_twin_problem.yaml"), "--method", method])
    err = capsys.readouterr().err.strip()
    assert rc == 2 and len(err.splitlines()) == 1 and "twin_drive" in err
