"""Study records and outcomes (issue 24, item 6): a case file read back is validated (a bad one is
solved again, never trusted); a combination invalid only together is a failed case, not a rejected
study; a bad --report path is refused before the study runs; the exit code is 1 when any case has no
design."""

from __future__ import annotations

import json
import shutil

import pandas as pd
import pytest
from study_helpers import PROBLEMS, small_study, stable, study_code, write_study

from axisopt.cli import main
from axisopt.study import load_study, results_table, run_study


@pytest.fixture(scope="module")
def reference(tmp_path_factory):
    d = tmp_path_factory.mktemp("ref")
    src = small_study(d)
    st = load_study(src)
    run_study(st, d / "out", workers=0)
    return st, d / "out", results_table(st, d / "out")


def _copy(reference, tmp_path):
    st, ref_out, ref = reference
    out = tmp_path / "out"
    shutil.copytree(ref_out, out)
    return st, out, ref


BAD_RECORDS = {
    "empty list": lambda rec: [],
    "empty mapping": lambda rec: {},
    "missing status": lambda rec: {k: v for k, v in rec.items() if k != "status"},
    "missing inputs": lambda rec: {k: v for k, v in rec.items() if k != "inputs"},
    "unknown status": lambda rec: {**rec, "status": "bogus"},
    "objective not a mapping": lambda rec: {**rec, "status": "optimal", "objective": [1, 2]},
    "index a string": lambda rec: {**rec, "index": "3"},
    "wrong version": lambda rec: {**rec, "version": 99},
    "not JSON": None,
}


@pytest.mark.parametrize("what", sorted(BAD_RECORDS))
def test_bad_case_record_is_solved_again_on_resume(reference, tmp_path, capsys, what):
    st, out, ref = _copy(reference, tmp_path)
    p = sorted((out / "cases").glob("*.json"))[3]
    rec = json.loads(p.read_text(encoding="utf-8"))
    make = BAD_RECORDS[what]
    p.write_text("{not json" if make is None else json.dumps(make(rec)), encoding="utf-8")
    rc = main(["study", st.source, "--out", str(out), "--resume", "--workers", "0", "--quiet"])
    assert rc == study_code(ref)
    assert "Traceback" not in capsys.readouterr().err
    again = json.loads(p.read_text(encoding="utf-8"))  # solved again and written whole
    assert again["case_id"] == rec["case_id"] and again["status"] == rec["status"]
    pd.testing.assert_frame_equal(stable(results_table(st, out)), stable(ref))


def test_record_naming_another_case_is_not_trusted(reference, tmp_path):
    """A case file whose case_id names another case: neither row is duplicated or lost."""
    st, out, ref = _copy(reference, tmp_path)
    a, b = sorted((out / "cases").glob("*.json"))[:2]
    b.write_text(a.read_text(encoding="utf-8"), encoding="utf-8")  # b's file now holds a's record
    s = run_study(st, out, workers=0, resume=True)
    assert s.solved == 1
    df = results_table(st, out)
    assert len(df) == len(ref) and df["case_id"].is_unique
    pd.testing.assert_frame_equal(stable(df), stable(ref))


def test_exit_code_is_one_when_a_case_has_no_design(reference, tmp_path, capsys):
    st, out, ref = _copy(reference, tmp_path)
    assert (ref["status"] == "infeasible").any()  # the small study has a budget too tight
    assert (
        main(["study", st.source, "--out", str(out), "--resume", "--workers", "0", "--quiet"]) == 1
    )
    assert "failed" in capsys.readouterr().out


def test_all_cases_solved_exits_zero(tmp_path, capsys):
    src = write_study(
        tmp_path,
        """\
        name: ok
        base: @PROBLEMS@/teaching_problem.yaml
        sweep:
          axis.stroke: [300 mm, 400 mm]
        """,
    )
    assert main(["study", str(src), "--out", str(tmp_path / "o"), "--workers", "0", "--quiet"]) == 0


def test_combination_invalid_only_together_is_a_failed_case(tmp_path, capsys):
    """nut_preload min 5 kN is valid alone, max 1 kN is valid alone; together (min > max) they are
    not."""
    base = (PROBLEMS / "teaching_problem.yaml").read_text(encoding="utf-8")
    if "continuous:" not in base:
        base += "continuous:\n  nut_preload: {min: 200 N, max: 20 kN}\n"
    (tmp_path / "base.yaml").write_text(base, encoding="utf-8")
    src = write_study(
        tmp_path,
        """\
        name: together
        base: base.yaml
        combine: product
        sweep:
          continuous.nut_preload.min: [100 N, 5 kN]
          continuous.nut_preload.max: [1 kN, 20 kN]
        """,
    )
    out = tmp_path / "o"
    assert main(["study", str(src), "--out", str(out), "--workers", "0", "--quiet"]) == 1
    df = pd.read_csv(out / "results.csv")
    assert len(df) == 4
    bad = df[df["status"] == "input_error"]
    assert len(bad) == 1 and "below min" in bad["reason"].iloc[0]


def test_a_value_invalid_on_its_own_still_rejects_the_study(tmp_path, capsys):
    src = write_study(
        tmp_path,
        """\
        name: bad
        base: @PROBLEMS@/teaching_problem.yaml
        sweep:
          axis.stroke: [300 mm, -5 mm]
        """,
    )
    assert main(["study", str(src), "--out", str(tmp_path / "o"), "--workers", "0", "--quiet"]) == 2
    err = capsys.readouterr().err.strip()
    assert err.startswith("error: ") and "axis.stroke" in err and "\n" not in err
    assert not (tmp_path / "o" / "cases").exists()


def test_bad_report_directory_is_refused_before_the_study_runs(tmp_path, capsys):
    pytest.importorskip("plotly")
    src = small_study(tmp_path)
    out = tmp_path / "o"
    rc = main(
        [
            "study",
            str(src),
            "--out",
            str(out),
            "--workers",
            "0",
            "--quiet",
            "--report",
            str(tmp_path / "no" / "such" / "dir" / "r.html"),
        ]
    )
    assert rc == 2
    err = capsys.readouterr().err.strip()
    assert "does not exist" in err and "\n" not in err
    assert not (out / "cases").exists()  # nothing was solved


def test_empty_scheduler_is_one_line_and_no_bar_off_a_terminal(tmp_path, capsys):
    src = small_study(tmp_path)
    assert main(["study", str(src), "--out", str(tmp_path / "o"), "--scheduler", ""]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith("error: ") and "\r" not in err
