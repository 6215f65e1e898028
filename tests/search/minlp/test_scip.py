"""SCIP global-MINLP reference (optional extra axisopt[scip]): its optimum equals exhaustive
enumeration's on the teaching problem and on seeded random catalogs; infeasibility, Pareto and CLI
exit codes."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from scip_agree import agrees_with_exhaustive
from search_synthetic import make_catalog, make_problem

from axisopt.cli import main
from axisopt.errors import InputError
from axisopt.problem import load_problem
from axisopt.search import solve

pytest.importorskip("pyscipopt")

PROBLEMS = Path(__file__).resolve().parents[3] / "problems"
# wall seconds: with the vendor rules SCIP's presolved proof is contradicted and solved again with
# presolving off (scip.RETRY_PARAMS): 9.7 s CPU, 25 s wall at load 9 on 2 cores; over 40 s wall
# under the suite's load
TEACHING_LIMIT = 120


def _teaching_yaskawa_rule(tmp_path) -> Path:
    """The teaching problem under Yaskawa's own RMS rule (RMS within the rated torque,
    rms_torque_ratio 1) for its Yaskawa motors, at 2 m/s^2 and on part of its catalog: the nuts of
    its optimum and runner-up (HIWIN R40-40K2 and R32-40K2 FDC), the three DF support sets that fit
    them (WBK20/25/30-DF), one motor and one coupling.  SCIP proves this in seconds.  On the whole
    teaching catalog it finds the default method's optimum but does not prove it within 60 s: with
    the default 0.8 (issue 26) not within 400 s (207 425 nodes), with the vendor screw inertia not
    at 3 m/s^2 within 300 s (808 340 nodes), and with the vendors' nut and support-set lives
    (HIWIN's two halves, NSK's preloaded sets) not within 60 s in any variant tried (life needs of 5
    000 to 20 000 h, mean speeds of 4 and 8 m/min)."""
    text = (PROBLEMS / "teaching_problem.yaml").read_text(encoding="utf-8")
    old_require = "require: {coupling: [RINGFEDER-GWB-AKN-30, RINGFEDER-GWB-AKN-60]}"
    assert "\naxis:\n" in text and "  acceleration: 3 m/s^2\n" in text and old_require in text
    path = tmp_path / "teaching_problem.yaml"
    text = text.replace("  acceleration: 3 m/s^2\n", "  acceleration: 2 m/s^2\n", 1)
    text = text.replace(
        old_require,
        "require: {bearing: [HIWIN-WBK30-DF, HIWIN-WBK25-DF, HIWIN-WBK20-DF], "
        "nut: [HIWIN-R40-40K2-FDC, HIWIN-R32-40K2-FDC], motor: [SGM7G-13A], "
        "coupling: [RINGFEDER-GWB-AKN-60]}",
        1,
    )
    path.write_text(
        text.replace("\naxis:\n", "\naxis:\n  rms_torque_ratio: 1\n", 1), encoding="utf-8"
    )
    return path


@pytest.mark.slow  # over 10 s on an idle core: run by `pytest -m slow`
def test_teaching_problem_equals_exhaustive(tmp_path):
    p = load_problem(_teaching_yaskawa_rule(tmp_path))
    s = solve(p, "scip", time_limit=TEACHING_LIMIT)
    agrees_with_exhaustive(s, solve(p, "exhaustive", top=1, sensitivities=False))
    assert s.status == "optimal"
    assert "nodes" in s.certificate.notes[0]


def test_infeasible_problem_is_reported_infeasible():
    cat = make_catalog(
        np.random.default_rng(7), n_screws=2, nuts_per_screw=2, n_bearings=3, n_guides=2
    )
    p = make_problem(cat, limits={"max_cost": 100.0})
    s = solve(p, "scip", time_limit=20)
    assert solve(p, "exhaustive", sensitivities=False).status == "infeasible"
    assert s.status == "infeasible" and s.best is None and s.certificate.proven


def test_pareto_is_an_input_error():
    p = load_problem(PROBLEMS / "pareto_problem.yaml")
    with pytest.raises(InputError, match="Pareto"):
        solve(p, "scip")


@pytest.mark.slow  # over 10 s on an idle core: run by `pytest -m slow`
def test_cli_exit_codes(capsys, tmp_path):
    teaching = _teaching_yaskawa_rule(tmp_path)
    assert (
        main(["solve", str(teaching), "--method", "scip", "--time-limit", str(TEACHING_LIMIT)]) == 0
    )
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


@pytest.mark.slow  # over 10 s on an idle core: run by `pytest -m slow`
def test_contradicted_proof_is_detected():
    """A proof of infeasibility, or of an optimum below a design the search finds, is contradicted
    (the check that turns SCIP's numerically wrong proofs into a failure)."""
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
    """SCIP's LP relaxation proves the high-speed problem's stage 2 infeasible (57 s, proven)
    although the default method and exhaustive enumeration solve it (99.37 N/um): the answer is the
    optimum, a time limit or a failure, never a wrong proven answer."""
    p = load_problem(PROBLEMS / "highspeed_problem.yaml")
    s = solve(p, "scip", time_limit=45)
    assert s.status in ("optimal", "time_limit", "solver_failed"), s.message
    if s.certificate.proven or s.status == "optimal":
        assert s.status == "optimal" and s.best.objective == pytest.approx(99.3745, rel=1e-4)
    if s.status == "solver_failed":
        assert not s.certificate.proven and "proof is wrong" in s.message


@pytest.mark.parametrize("method", ["scip", "bonmin"])
def test_twin_drive_is_refused(method, tmp_path, capsys):
    """A twin-drive gantry (issue 40): SCIP's relaxation of the gantry's 2-DOF eigenvalues
    contradicted enumeration on a synthetic case (proof 'contradicted by a feasible design'), so the
    MINLP references refuse it with a one-line error (exit 2) instead of answering."""
    p = load_problem(PROBLEMS / "gantry_twin_problem.yaml")
    with pytest.raises(InputError, match="twin-drive"):
        solve(p, method)
    rc = main(["solve", str(PROBLEMS / "gantry_twin_problem.yaml"), "--method", method])
    err = capsys.readouterr().err.strip()
    assert rc == 2 and len(err.splitlines()) == 1 and "twin_drive" in err
