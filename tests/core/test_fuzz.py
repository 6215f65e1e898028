"""Fuzz the command line with mutated shipped inputs and check the contract of every command.

exit 0 with finite output (``--json``: no NaN/Infinity, no negative mass, stiffness, length,
frequency), exit 1 with an explanation, or exit 2 with exactly one stderr line starting ``error: ``;
never a traceback, a warning on a success, a crash or a hang.  The mutations (``fuzz_inputs.py``,
shared with ``bench/bench_fuzz.py``, the long run): a key deleted or misspelt, a value replaced by
NaN, infinity, -1, 0, 1e300, 1e-300, a 10^5-character string, a list, a mapping, a wrong unit or
type, scaled far from the shipped value; the file re-encoded (Latin-1, UTF-16), truncated, emptied,
random bytes, nested 1000 deep, a billion-laughs alias bomb; CSV cells, columns and headers of the
diagnose data and of a user catalog; odd command-line flags.

Each case runs ``axisopt.cli.main(argv)`` in a forked copy of the test process (imports and caches
warm, so a case costs milliseconds; a hang is killed after ``CASE_TIMEOUT`` s without stopping the
test), or as a real subprocess where the command starts worker processes.  hypothesis draws the
mutations (derandomized: the same cases on every run; a failure shrinks to a small one).

Known bugs: each has a ``KNOWN`` entry (the outcome it produces, matched so that the fuzz tests
tolerate it) and a minimal reproducer in ``test_known_bug`` marked ``xfail(strict=True)``: when the
bug is fixed the reproducer passes, the strict xfail fails, and the fixer deletes the entry.
"""

from __future__ import annotations

import contextlib
import io
import os
import re
import tempfile
from dataclasses import dataclass
from pathlib import Path

import fuzz_inputs as F
import pytest
import yaml
from fuzz_inputs import (
    BAD,
    DATA_CSV,
    DATA_DESIGN,
    FAST_PROBLEMS,
    FLAG_CASES,
    HARDENING_CASES,
    PROBLEMS,
    Case,
    DrawChooser,
    calibration_case,
    catalog_case,
    classify,
    compare_case,
    data_case,
    design_case,
    dump_yaml,
    problem_case,
    read_csv_rows,
    run_forked,
    run_subprocess,
    shipped,
    study_case,
    write_csv_rows,
)
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

pytestmark = pytest.mark.skipif(not hasattr(os, "fork"), reason="the in-process runner forks")

CASE_TIMEOUT = 10.0  # seconds; the slowest shipped fast problem solves in well under 1 s in-process
FUZZ = settings(
    deadline=None,
    derandomize=True,
    database=None,
    print_blob=False,
    suppress_health_check=list(HealthCheck),
)


@pytest.fixture(scope="module", autouse=True)
def warm():
    """Import the solver stack and build the shipped designs' functions once in this process, so
    that every forked case starts warm; the calibration the calibration cases mutate is saved here
    too."""
    from axisopt.cli import main

    with tempfile.TemporaryDirectory() as d, contextlib.redirect_stdout(io.StringIO()):
        cal = Path(d) / "cal.yaml"
        assert (
            main(
                [
                    "diagnose",
                    str(PROBLEMS / DATA_CSV),
                    "--design",
                    str(PROBLEMS / DATA_DESIGN),
                    "--save-calibration",
                    str(cal),
                ]
            )
            == 0
        )
        F._CAL_CACHE["cal"] = cal.read_bytes()
        F.synthetic_datasets()
        for name in ("vmc_x_design.yaml", "teaching_design.yaml", "custom_parts_design.yaml"):
            assert main(["evaluate", str(PROBLEMS / name), "--json", "-"]) == 0
        for name in FAST_PROBLEMS:
            assert main(["solve", str(PROBLEMS / name), "--no-sensitivity", "--json", "-"]) == 0


# --------------------------------------------------------------------------------------------------
# ------------
# known bugs: (id, outcome class, pattern of the outcome detail or command, reason)


@dataclass(frozen=True)
class Known:
    id: str
    cls: str
    pattern: str  # searched in "<command> :: <detail>"
    reason: str


# every bug the fuzz runs found is fixed; a new one is listed here with its reproducer below
KNOWN = ()


def known(case: Case, cls: str, detail: str) -> Known | None:
    text = f"{case.command()} :: {case.mutation} :: {detail}"
    for k in KNOWN:
        if k.cls == cls and re.search(k.pattern, text):
            return k
    return None


def run(case: Case, timeout: float = CASE_TIMEOUT):
    """Run a case in a fresh directory: forked in-process, or a subprocess where it starts
    workers."""
    pool = case.argv[:1] == ["study"] and (
        "--scheduler" in case.argv
        or ("--workers" in case.argv and case.argv[case.argv.index("--workers") + 1 :][:1] != ["0"])
    )
    with tempfile.TemporaryDirectory(prefix="fuzz-") as d:
        # the fork's fd 1 is not its sys.stdout
        if pool or case.special or "/dev/stdout" in case.argv:
            return run_subprocess(case, Path(d), timeout=max(timeout, 30.0))
        return run_forked(case, Path(d), timeout=timeout)


def check(case: Case) -> str:
    out = run(case)
    cls, detail = classify(case, out)
    if cls in BAD and known(case, cls, detail) is None:
        err = "\n".join(out.stderr.strip().splitlines()[-12:])
        pytest.fail(
            f"{cls}: {case.command()}\n  mutation: {case.mutation}\n  {detail}\n  exit {out.rc} "
            f"after {out.seconds:.1f} s; stderr:\n{err}",
            pytrace=False,
        )
    return cls


# --------------------------------------------------------------------------------------------------
# ------------
# the fuzz tests, one per input kind


@settings(FUZZ, max_examples=40)
@given(st.data())
def test_fuzz_design(data):
    check(design_case(DrawChooser(data)))


@settings(FUZZ, max_examples=20)
@given(st.data())
def test_fuzz_problem(data):
    check(problem_case(DrawChooser(data), FAST_PROBLEMS))


@settings(FUZZ, max_examples=12)
@given(st.data())
def test_fuzz_study(data):
    check(
        study_case(
            DrawChooser(data), ("teaching_random.yaml", "vmc_stroke_mounting.yaml"), fast=True
        )
    )


@settings(FUZZ, max_examples=30)
@given(st.data())
def test_fuzz_calibration(data):
    check(calibration_case(DrawChooser(data)))


@settings(FUZZ, max_examples=30)
@given(st.data())
def test_fuzz_diagnose_data(data):
    check(data_case(DrawChooser(data)))


@settings(FUZZ, max_examples=20)
@given(st.data())
def test_fuzz_catalog(data):
    check(catalog_case(DrawChooser(data)))


@settings(FUZZ, max_examples=15)
@given(st.data())
def test_fuzz_compare(data):
    check(compare_case(DrawChooser(data)))


FAST_FLAGS = [
    c
    for c in FLAG_CASES
    if "bonmin" not in c[1]
    and "exhaustive" not in c[1]
    and not ("--workers" in c[1] and c[1][c[1].index("--workers") + 1] != "0")
    and "--scheduler" not in c[1]
]


@settings(FUZZ, max_examples=30)
@given(st.sampled_from(FAST_FLAGS))
def test_fuzz_flags(flag_case):
    desc, argv, files = flag_case
    check(Case("flags", desc, list(argv), dict(files)))


# issue 24: what each hardening case must give (every other outcome of these is a regression)
HARDENING_EXPECTED = {
    "parts --csv to a FIFO": "ok",
    "parts --json to a FIFO": "ok",
    "schema --out to a FIFO": "ok",
    "evaluate --json to a FIFO": "ok",
    "compare --csv to a FIFO": "ok",
    "parts --csv -": "ok",
    "parts --json /dev/stdout": "ok",
    "schema --out -": "ok",
    "duty-cycle move harder than axis.acceleration": "ok",
    "sweep invalid only together (product)": "negative",
    "user catalog id that is a formula, parts --csv": "ok",
    "problem file name with a newline, --save-design": "ok",
    "solve --save-design -": "ok",
}


@pytest.mark.parametrize("case", HARDENING_CASES, ids=[c.mutation for c in HARDENING_CASES])
def test_fuzz_hardening(case):
    cls = check(
        Case(case.kind, case.mutation, list(case.argv), dict(case.files), case.dirs, case.special)
    )
    assert cls == HARDENING_EXPECTED.get(case.mutation, "clean error"), cls


def test_shipped_inputs_keep_the_contract():
    """The unmutated inputs: exit 0 (or 1 for the infeasible teaching variant), finite JSON."""
    for argv, files in (
        (["evaluate", "d.yaml", "--json", "-"], {"d.yaml": shipped("vmc_x_design.yaml")}),
        (
            ["solve", "p.yaml", "--no-sensitivity", "--json", "-"],
            {"p.yaml": shipped("teaching_problem.yaml")},
        ),
        (
            ["diagnose", "c.csv", "--design", "d.yaml", "--json", "-"],
            {"c.csv": shipped(DATA_CSV), "d.yaml": shipped(DATA_DESIGN)},
        ),
        (["parts", "--json", "-"], {}),
    ):
        assert check(Case("shipped", "none", argv, files)) == "ok"


def test_the_runner_catches_what_it_must():
    """The harness itself: a traceback, a hang and a multi-line error are recognised as such."""
    from fuzz_inputs import Outcome

    c = Case("x", "x", ["evaluate", "d.yaml", "--json", "-"])
    assert (
        classify(
            c, Outcome(1, "", "Traceback (most recent call last):\n  x\nValueError: y\n", 0.1)
        )[0]
        == "traceback"
    )
    assert classify(c, Outcome(None, "", "", 20.0))[0] == "hang"
    assert classify(c, Outcome(2, "", "error: a\nerror: b\n", 0.1))[0] == "multi-line error"
    assert classify(c, Outcome(2, "", "error: a\n", 0.1))[0] == "clean error"
    assert classify(c, Outcome(0, '{"moving_mass_kg": -1.0}', "", 0.1))[0] == "bad output"
    assert classify(c, Outcome(0, '{"x": NaN}', "", 0.1))[0] == "bad output"
    assert classify(c, Outcome(0, "{}", "x.py:3: RuntimeWarning: overflow\n", 0.1))[0] == "warning"
    assert classify(c, Outcome(1, "", "", 0.1))[0] == "silent negative"
    hang = Case("x", "sleeps", ["evaluate", "d.yaml"], {"d.yaml": shipped("teaching_design.yaml")})
    import time

    from axisopt import cli

    real = cli.main
    cli.main = lambda argv: time.sleep(60)  # inherited by the fork only while set
    try:
        with tempfile.TemporaryDirectory() as d:
            out = run_forked(hang, Path(d), timeout=1.0)
    finally:
        cli.main = real
    assert out.rc is None and 1.0 <= out.seconds < 10


# --------------------------------------------------------------------------------------------------
# ------------
# minimal reproducers of the known bugs (xfail strict: a fix makes them pass and the mark must go)


def _data_scaled(column: str, factor: float) -> bytes:
    rows = read_csv_rows(shipped(DATA_CSV))
    j = rows[0].index(column)
    for r in rows[1:]:
        r[j] = repr(float(r[j]) * factor)
    return write_csv_rows(rows)


def _calibration(baseline=None, effect=None) -> bytes:
    """The rich calibration with only one baseline value or one effect, that one set to
    ``value``."""
    tree = yaml.safe_load(F.RICH_CALIBRATION)
    if baseline:
        tree["baseline"] = {baseline[0]: dict(tree["baseline"][baseline[0]], value=baseline[1])}
        tree["effects"] = []
    else:
        e = next(x for x in tree["effects"] if x["name"] == effect[0])
        k = next(iter(e["parameters"]))
        e["parameters"][k]["value"] = effect[1]
        tree["baseline"], tree["effects"] = {}, [e]
    return dump_yaml(tree)


def _teaching_pareto_infeasible() -> bytes:
    tree = yaml.safe_load(shipped("teaching_problem.yaml"))
    tree["objective"] = {"mode": "pareto", "pareto": ["stiffness", "cost"]}
    tree["limits"]["max_cost"] = "100 EUR"
    return dump_yaml(tree)


def _evaluate_calibrated(cal: bytes, json_out: bool) -> Case:
    return Case(
        "calibration",
        "",
        ["evaluate", "d.yaml", "--calibration", "cal.yaml"] + (["--json", "-"] if json_out else []),
        {"cal.yaml": cal, "d.yaml": shipped(DATA_DESIGN)},
    )


# Fixed bugs stay here as regression tests; OPEN lists the ones not fixed yet (xfail strict).
REPRODUCERS = {
    "diagnose-degenerate-data": (
        "diagnose data whose forces are all ~1e-300 N: overflow warnings, 'nan %' in the text, and "
        "with --json the fit's NaN reaches write_json (ValueError traceback)",
        lambda: Case(
            "data",
            "force column scaled by 1e-300",
            ["diagnose", "c.csv", "--design", "d.yaml", "--json", "-"],
            {"c.csv": _data_scaled("force [N]", 1e-300), "d.yaml": shipped(DATA_DESIGN)},
        ),
    ),
    "calibration-zero-modulus": (
        "evaluate --calibration with baseline.screw_modulus '0 GPa' is accepted: root diameter 0, "
        "ZeroDivisionError in evaluation_table",
        lambda: _evaluate_calibrated(_calibration(baseline=("screw_modulus", "0 GPa")), False),
    ),
    "calibration-negative-modulus": (
        "evaluate --calibration with baseline.screw_modulus '-202.7 GPa': math domain error (sqrt)",
        lambda: _evaluate_calibrated(_calibration(baseline=("screw_modulus", "-202.7 GPa")), True),
    ),
    "calibration-negative-viscous": (
        "evaluate --calibration with effect viscous, viscous_coefficient '-5000 N.s/m', is "
        "applied: negative guide drag torque in the output (exit 0)",
        lambda: _evaluate_calibrated(_calibration(effect=("viscous", "-5000 N.s/m")), True),
    ),
    "drive-choice-traceback": (
        "catalog.drive: maybe (any value but yes/no/true/false) is a TypeError traceback: "
        "Section.choice hands the boolean options to difflib.get_close_matches",
        lambda: Case(
            "problem",
            "catalog.drive: maybe",
            ["solve", "p.yaml", "--no-sensitivity"],
            {
                "p.yaml": shipped("teaching_problem.yaml").replace(
                    b"\ncatalog:\n", b"\ncatalog:\n  drive: maybe\n"
                )
            },
        ),
    ),
    "empty-pareto-front": (
        "solve of an infeasible Pareto problem (text output): TypeError 'int' object is not "
        "iterable in solve_cli._cand_table (max over an empty front)",
        lambda: Case(
            "problem",
            "teaching, pareto objective, max_cost 100 EUR",
            ["solve", "p.yaml", "--no-sensitivity"],
            {"p.yaml": _teaching_pareto_infeasible()},
        ),
    ),
    "time-limit-nan": (
        "solve --time-limit nan (or inf) is accepted (NaN <= 0 is False); with --method bonmin it "
        "runs ~20 s and ends in MINLP_ERROR (exit 1) instead of a one-line error",
        lambda: Case(
            "flags",
            "--time-limit nan",
            ["solve", "p.yaml", "--no-sensitivity", "--time-limit", "nan"],
            {"p.yaml": shipped("teaching_problem.yaml")},
        ),
    ),
    "reduction-ratio-tiny": (
        "axis.reduction_ratio 1e-300 in the gantry problem: OverflowError traceback in "
        "load_inertia (ratio**2)",
        lambda: Case(
            "problem",
            "axis.reduction_ratio: 1e-300",
            ["solve", "p.yaml", "--no-sensitivity"],
            {
                "p.yaml": shipped("gantry_problem.yaml").replace(
                    b"\naxis:\n", b"\naxis:\n  reduction_ratio: 1.0e-300\n"
                )
            },
        ),
    ),
    "study-named-nan": (
        "a study named 'nan mm' is echoed as given; the classifier counted the user's name as a "
        "NaN output",
        lambda: Case(
            "study",
            "name: nan mm",
            ["study", "s.yaml", "--out", "out", "--workers", "0", "--quiet"],
            {
                "s.yaml": b"name: nan mm\nbase: p.yaml\nsweep:\n  limits.max_cost: [3500 EUR]\n",
                "p.yaml": shipped("teaching_problem.yaml"),
            },
        ),
    ),
}


OPEN = ()


@pytest.mark.parametrize(
    "bug",
    [
        pytest.param(k, marks=pytest.mark.xfail(strict=True, reason=v[0]) if k in OPEN else ())
        for k, v in REPRODUCERS.items()
    ],
)
def test_known_bug(bug):
    case = REPRODUCERS[bug][1]()
    out = run(case)
    cls, detail = classify(case, out)
    if bug in ("time-limit-nan", "reduction-ratio-tiny"):  # bad input must be exit 2, one line
        assert cls == "clean error", f"{cls}: exit {out.rc}; {detail}"
        return
    assert cls not in BAD, f"{cls}: {detail}"


def test_a_plausibility_warning_is_part_of_the_contract():
    """The one-line plausibility warning (design.plausible) beside a success or an error is no stray
    warning."""
    from fuzz_inputs import Outcome

    c = Case("problem", "acceleration scaled 1e-3", ["solve", "p.yaml"])
    warn = (
        "warning: p.yaml: line 14, key 'axis.acceleration': 0.003 m/s^2 is far below machine-tool "
        "practice (0.1-50 m/s^2): check the value and its unit\n"
    )
    assert classify(c, Outcome(0, "ok\n", warn, 0.1))[0] != "warning"
    assert classify(c, Outcome(2, "", warn + "error: p.yaml: bad\n", 0.1))[0] == "clean error"
    assert classify(c, Outcome(0, "ok\n", "warning: something else\n", 0.1))[0] == "warning"
