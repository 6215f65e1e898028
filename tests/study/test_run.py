"""Running studies: local pool, Dask, resume after kill -9, failing cases recorded."""

from __future__ import annotations

import json
import os
import shutil
import signal
import subprocess
import time
from pathlib import Path

import pandas as pd
import pytest
from study_helpers import PYTHON, ROOT, kill_group, stable, study_code, write_study

from axisopt.cli import main
from axisopt.errors import InputError
from axisopt.study import load_study, results_table, run_study


@pytest.fixture(scope="module")
def reference(tmp_path_factory):
    """The small study solved in this process, uninterrupted: the rows every other run must give."""
    d = tmp_path_factory.mktemp("ref")
    from study_helpers import small_study

    st = load_study(small_study(d))
    s = run_study(st, d / "out", workers=0)
    return st, s, results_table(st, d / "out")


def test_in_process_run_records_every_case(reference):
    st, s, df = reference
    assert s.total == s.solved == len(df) == 12 and s.lost == 0
    assert list(df["index"]) == list(range(12))
    ok = df[df["status"] == "optimal"]
    bad = df[df["status"] != "optimal"]
    assert len(ok) == 6 and (bad["limits.max_cost [EUR]"] == 600.0).all()
    assert (bad["status"] == "infeasible").all() and bad["reason"].str.len().gt(0).all()
    assert ok["proven"].all() and ok["nut"].notna().all() and (ok["min_stiffness [N/um]"] > 0).all()
    assert set(ok["weakest_link"]) <= {"screw", "screw torsion", "nut", "bearings"}
    out = s.out_dir
    for f in ("results.csv", "report.md", "study.json"):
        assert os.path.exists(os.path.join(out, f))
    report = Path(out, "report.md").read_text(encoding="utf-8")
    assert (
        "results.csv" in report
        and "plots/best_vs_axis_stroke.png" in report
        and "Failed cases" in report
    )


def test_parquet_results_equal_the_table(reference):
    pytest.importorskip("pyarrow")  # the parquet copy is written only with the 'parquet' extra
    st, s, df = reference
    back = pd.read_parquet(os.path.join(s.out_dir, "results.parquet"))
    pd.testing.assert_frame_equal(stable(back), stable(df), check_dtype=False)


def test_existing_results_need_resume(reference, tmp_path):
    st, s0, _ = reference
    shutil.copytree(s0.out_dir, tmp_path / "o")
    with pytest.raises(InputError, match="--resume"):
        run_study(st, tmp_path / "o", workers=0, report=False)
    s = run_study(st, tmp_path / "o", workers=0, resume=True, report=False)
    assert s.solved == 0 and s.resumed == 12


def test_killed_study_resumes_to_the_uninterrupted_rows(reference, tmp_path):
    st, _, ref = reference
    out = tmp_path / "killed"
    cmd = [
        PYTHON,
        "-m",
        "axisopt",
        "study",
        st.source,
        "--out",
        str(out),
        "--workers",
        "1",
        "--quiet",
    ]
    proc = subprocess.Popen(
        cmd, cwd=ROOT, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True
    )
    try:
        deadline = time.monotonic() + 60
        while time.monotonic() < deadline and proc.poll() is None:
            if len(list((out / "cases").glob("*.json"))) >= 2:
                break
            time.sleep(0.02)
        assert proc.poll() is None, "the study finished before it could be killed"
        os.kill(proc.pid, signal.SIGKILL)
        proc.wait(10)
    finally:
        kill_group(proc)  # the worker processes this test started
    done = len(list((out / "cases").glob("*.json")))
    assert 2 <= done < 12
    for p in (out / "cases").glob("*.json"):
        json.loads(p.read_text())  # every file written is whole
    assert main(
        ["study", st.source, "--out", str(out), "--workers", "1", "--quiet", "--resume"]
    ) == study_code(ref)
    df = results_table(st, out)
    pd.testing.assert_frame_equal(stable(df), stable(ref))
    assert len(list((out / "cases").glob("*.json"))) == 12 and not list((out / "cases").glob(".*"))


def test_failing_cases_are_recorded_and_the_study_goes_on(tmp_path, monkeypatch):
    # preload min 5 kN with max 3 kN is only invalid in combination; 5 kN to 10 kN is infeasible
    # (drag limit)
    p = write_study(
        tmp_path,
        """\
        base: @PROBLEMS@/teaching_problem.yaml
        sweep:
          continuous.nut_preload.min: [100 N, 5 kN]
          continuous.nut_preload.max: [10 kN, 3 kN]
        """,
    )
    st = load_study(p)
    s = run_study(st, tmp_path / "o", workers=0)
    df = results_table(st, tmp_path / "o").set_index("index")
    assert list(df["status"]) == ["optimal", "optimal", "infeasible", "input_error"]
    assert (
        "below min" in df.loc[3, "reason"]
        and "nut_preload" in df.loc[3, "reason"]
        and s.failed == 2
    )
    # a solver exception is recorded with its reason; the other cases go on
    import axisopt.search as search

    real = search.solve
    calls = []

    def flaky(problem, *a, **kw):
        calls.append(problem.name)
        if len(calls) == 2:
            raise RuntimeError("IPOPT exploded")
        return real(problem, *a, **kw)

    monkeypatch.setattr(search, "solve", flaky)
    run_study(st, tmp_path / "o2", workers=0, report=False)
    df2 = results_table(st, tmp_path / "o2")
    assert list(df2["status"]) == ["optimal", "error", "infeasible", "input_error"]
    assert df2.loc[1, "reason"] == "RuntimeError: IPOPT exploded"
