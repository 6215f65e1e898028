"""Hardening of study runs: dead workers, full disks, unwritable or wrong-kind outputs, two runs on
one directory, and kills at any moment -- each ends in the rows of an uninterrupted run or a
one-line error."""

from __future__ import annotations

import errno
import json
import os
import shutil
import signal
import subprocess
import time
from pathlib import Path

import pandas as pd
import pytest
from cli_helpers import one_line_error
from crash_helpers import CRASH_CONFIG, copy_study, crashing_solve, fill_disk_on, worker_pid
from study_helpers import PROBLEMS, PYTHON, ROOT, kill_group, stable
from study_helpers import study_code as _study_code

from axisopt.cli import main
from axisopt.errors import InputError
from axisopt.report import atomic_file
from axisopt.study import load_study, results_table, run_study
from axisopt.study.run import StudyLock

LINUX_PROC = pytest.mark.skipif(not Path("/proc/self/fd").is_dir(), reason="needs Linux /proc")


@pytest.fixture(scope="module")
def reference(tmp_path_factory):
    """The first 16 cases of teaching_random solved in this process, uninterrupted, with their
    outputs."""
    d = tmp_path_factory.mktemp("ref")
    st = load_study(copy_study(d))
    run_study(st, d / "out", workers=0)
    return st, d / "out", results_table(st, d / "out")


def _finished_copy(reference, tmp_path) -> tuple:
    """A finished study directory (copy of the reference) and its study file: a resumed run solves
    nothing and only writes the outputs."""
    _, ref_out, _ = reference
    src = copy_study(tmp_path)
    out = tmp_path / "out"
    shutil.copytree(ref_out, out)
    return src, out


def _resume(src, out, *more) -> int:
    return main(
        ["study", str(src), "--out", str(out), "--resume", "--workers", "0", "--quiet", *more]
    )


def _temporaries(d: Path) -> list:
    return sorted(p.name for p in Path(d).rglob(".*.tmp"))


# ---------------------------------------------------------------------------------- atomic writer


def test_atomic_file_keeps_the_old_file_when_writing_fails(tmp_path):
    p = tmp_path / "results.csv"
    p.write_text("old,whole\n1,2\n", encoding="utf-8")
    with pytest.raises(
        InputError, match=r"results.csv: cannot write table \(No space left on device\)"
    ):
        with atomic_file(p, what="table") as fh:
            fh.write("new,half")
            raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))
    with pytest.raises(RuntimeError):  # any failure, not only OSError
        with atomic_file(p, "wb") as fh:
            fh.write(b"new")
            raise RuntimeError("stopped")
    assert p.read_text(encoding="utf-8") == "old,whole\n1,2\n" and _temporaries(tmp_path) == []
    with atomic_file(p) as fh:
        fh.write("new\n")
    assert p.read_text(encoding="utf-8") == "new\n" and _temporaries(tmp_path) == []


def test_run_killed_while_writing_results_leaves_the_old_file(reference, tmp_path):
    _, out = _finished_copy(reference, tmp_path)
    csv = out / "results.csv"
    old = csv.read_bytes()
    code = (
        "import sys, time\nfrom axisopt.report import atomic_file\n"
        "with atomic_file(sys.argv[1]) as fh:\n"
        "    fh.write('case_id,index\\n' * 5000); fh.flush()\n"
        "    print('half written', flush=True); time.sleep(60)\n"
    )
    proc = subprocess.Popen(
        [PYTHON, "-c", code, str(csv)], cwd=ROOT, stdout=subprocess.PIPE, text=True
    )
    try:
        assert proc.stdout.readline().strip() == "half written"
        proc.kill()
        proc.wait(10)
    finally:
        proc.stdout.close()
    assert csv.read_bytes() == old  # the old table, whole
    assert len(_temporaries(out)) == 1  # the half-written new one, never under the real name
    run_study(reference[0], out, workers=0, resume=True, report=False)  # the next run sweeps it
    assert _temporaries(out) == [] and csv.read_bytes() == old


# ------------------------------------------------------------------------- full disk, permissions


@LINUX_PROC
@pytest.mark.parametrize(
    "name, code",
    [
        ("results.csv", errno.ENOSPC),
        ("results.parquet", errno.ENOSPC),
        ("report.md", errno.EACCES),
        ("study.json", errno.ENOSPC),
        ("tradeoff_cost_stiffness.png", errno.ENOSPC),
        ("case", errno.ENOSPC),
    ],
)
def test_full_disk_or_no_permission_is_aone_line_error(
    reference, tmp_path, monkeypatch, capsys, name, code
):
    if name.endswith(".parquet"):
        pytest.importorskip("pyarrow")  # written only with the 'parquet' extra
    src, out = _finished_copy(reference, tmp_path)
    victim = None
    if name == "case":  # a case solved by this run cannot be saved
        victim = sorted((out / "cases").glob("*.json"))[5]
        victim.unlink()
        name = victim.name
    old = (out / "results.csv").read_bytes()
    fill_disk_on(monkeypatch, name, code=code)
    assert _resume(src, out) == 2
    line = one_line_error(capsys)
    assert name in line and os.strerror(code) in line
    assert (out / "results.csv").read_bytes() == old  # never a truncated table
    assert _temporaries(out) == [] and not (out / ".lock").exists()
    if victim is not None:  # with space again, a resumed run solves the case it could not save
        monkeypatch.undo()
        s = run_study(reference[0], out, workers=0, resume=True, report=False)
        assert s.solved == 1
        pd.testing.assert_frame_equal(
            stable(results_table(reference[0], out)), stable(reference[2])
        )


@LINUX_PROC
def test_full_disk_for_json_output_keeps_the_old_file(tmp_path, monkeypatch, capsys):
    target = tmp_path / "out.json"
    target.write_text('{"old": true}\n', encoding="utf-8")
    fill_disk_on(monkeypatch, "out.json", budget=10)
    assert main(["evaluate", str(PROBLEMS / "teaching_design.yaml"), "--json", str(target)]) == 2
    line = one_line_error(capsys)
    assert str(target) in line and "No space left on device" in line
    assert target.read_text(encoding="utf-8") == '{"old": true}\n' and _temporaries(tmp_path) == []


@pytest.mark.skipif(os.name != "posix" or os.geteuid() == 0, reason="root writes through chmod")
def test_unwritable_study_directory_is_aone_line_error(reference, tmp_path, capsys):
    src, out = _finished_copy(reference, tmp_path)
    os.chmod(out, 0o555)
    try:
        assert _resume(src, out) == 2
    finally:
        os.chmod(out, 0o755)
    line = one_line_error(capsys)
    assert str(out) in line and "Permission denied" in line


@pytest.mark.parametrize(
    "name, make", [("results.csv", "dir"), ("plots", "file"), ("report.md", "dir")]
)
def test_output_of_the_wrong_kind_is_aone_line_error(reference, tmp_path, capsys, name, make):
    src, out = _finished_copy(reference, tmp_path)
    p = out / name
    shutil.rmtree(p) if p.is_dir() else p.unlink()
    if make == "dir":
        (p / "x").mkdir(parents=True)
    else:
        p.write_text("not a directory\n", encoding="utf-8")
    old = (out / "results.csv").read_bytes() if name != "results.csv" else None
    assert _resume(src, out) == 2
    line = one_line_error(capsys)
    assert str(p) in line and "in the way" in line
    if old is not None:
        assert (out / "results.csv").read_bytes() == old


# --------------------------------------------------------------------------------------- lock


def test_second_run_on_the_same_directory_is_refused(reference, tmp_path, capsys):
    src, out = _finished_copy(reference, tmp_path)
    with StudyLock(out):  # a run in progress (this process)
        assert _resume(src, out) == 2
        line = one_line_error(capsys)
        assert str(out) in line and f"pid {os.getpid()}" in line and "another study run" in line
        assert (out / ".lock").exists()
        with pytest.raises(InputError, match="another study run"):
            StudyLock(out).acquire()
    assert not (out / ".lock").exists()
    with StudyLock(out):
        assert json.loads((out / ".lock").read_text(encoding="utf-8"))["pid"] == os.getpid()


# ------------------------------------------------------------------------------ dead pool workers


def _first_cases(ref, st):
    """The reference rows of a study cut to fewer cases (the same cases: the same ids)."""
    ids = [c.case_id for c in st.cases]
    assert set(ids) <= set(ref["case_id"])
    return ref[ref["case_id"].isin(ids)].reset_index(drop=True)


def test_only_the_case_a_dead_worker_was_running_is_charged(
    reference, tmp_path, monkeypatch, capsys
):
    """Of 8 cases on 2 workers, case 3 kills its worker on the first try, case 5 on every try: 3
    deaths while other cases wait or run on the other worker.  Only case 5 is given up
    (worker_died), the run exits 1 with a one-line note, and --resume solves it again and says
    so."""
    src = copy_study(tmp_path, n=8)
    st = load_study(src)
    ref = _first_cases(reference[2], st)
    out = tmp_path / "out"
    (tmp_path / CRASH_CONFIG).write_text(json.dumps({"once": [3], "always": [5]}), encoding="utf-8")
    import axisopt.study.run as run

    monkeypatch.setattr(run, "solve_case", crashing_solve)  # sent to the workers by reference
    assert main(["study", str(src), "--out", str(out), "--workers", "2", "--quiet"]) == 1
    cap = capsys.readouterr()
    note = cap.err.strip().splitlines()
    assert (
        len(note) == 1
        and note[0].startswith("note: 1 case not solved")
        and "worker_died" in note[0]
    )
    assert "--resume" in note[0]
    assert (tmp_path / "crashed-3").exists()
    df = results_table(st, out)
    died = df[df["status"] == "worker_died"]
    assert list(died["index"]) == [5] and "died 2 times" in died["reason"].iloc[0]
    pd.testing.assert_frame_equal(
        stable(df[df["index"] != 5]), stable(ref[ref["index"] != 5]), check_dtype=False
    )
    assert "worker_died" in (out / "report.md").read_text(encoding="utf-8")
    monkeypatch.undo()
    assert _resume(src, out) == _study_code(ref)
    cap = capsys.readouterr()
    assert cap.out.startswith("resume: 1 case recorded as worker_died") and cap.err == ""
    pd.testing.assert_frame_equal(stable(results_table(st, out)), stable(ref))


@pytest.mark.parametrize(
    "status, reason",
    [
        (
            "worker_died",
            "the worker process died 2 times while solving this case (last: killed by SIGKILL)",
        ),
        # as versions before worker_died wrote it
        ("error", "worker process died twice while solving this case"),
    ],
)
def test_resume_solves_again_the_cases_lost_to_dead_workers(
    reference, tmp_path, capsys, status, reason
):
    st, _, ref = reference
    src, out = _finished_copy(reference, tmp_path)
    for p in sorted((out / "cases").glob("*.json"))[2:4]:
        rec = json.loads(p.read_text(encoding="utf-8"))
        keep = {k: rec[k] for k in ("version", "case_id", "index", "inputs")}
        p.write_text(
            json.dumps({**keep, "status": status, "reason": reason, "time_s": 0.0, "worker": ""}),
            encoding="utf-8",
        )
    s = run_study(st, out, workers=0, resume=True, report=False)
    assert s.solved == 2 and s.redone == 2 and s.resumed == 14
    pd.testing.assert_frame_equal(stable(results_table(st, out)), stable(ref))


def _wait_for(cond, proc, what, timeout=60.0):
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        assert proc.poll() is None, f"the study ended before {what}"
        v = cond()
        if v:
            return v
        time.sleep(0.005)
    raise AssertionError(f"timed out waiting for {what}")


@pytest.mark.slow  # over 10 s on an idle core: run by `pytest -m slow`
def test_two_dead_workers_and_a_killed_run_resume_to_the_uninterrupted_rows(
    reference, tmp_path, capsys
):
    st, _, ref = reference
    src = copy_study(tmp_path)
    out = tmp_path / "out"
    cmd = [
        PYTHON,
        "-m",
        "axisopt",
        "study",
        str(src),
        "--out",
        str(out),
        "--workers",
        "2",
        "--quiet",
    ]
    proc = subprocess.Popen(
        cmd, cwd=ROOT, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True
    )

    def finished():
        return len(list((out / "cases").glob("*.json")))

    killed = []
    try:
        for n in (1, 3):  # kill -9 a worker after 1 finished case, another one after 3
            pid = _wait_for(
                lambda n=n: finished() >= n and worker_pid(out, killed), proc, f"{n} cases"
            )
            os.kill(pid, signal.SIGKILL)
            killed.append(pid)
        # meanwhile a second run on the same directory is refused
        assert _resume(src, out) == 2 and "another study run" in one_line_error(capsys)
        _wait_for(lambda: finished() >= 5, proc, "5 cases")
        os.kill(proc.pid, signal.SIGKILL)  # and the run itself
        proc.wait(10)
    finally:
        kill_group(proc)  # the worker processes this test started
    recs = [json.loads(p.read_text(encoding="utf-8")) for p in (out / "cases").glob("*.json")]
    assert 5 <= len(recs) < 16
    # two deaths charge at most one case twice: the waiting cases were never charged
    assert sum(r["status"] == "worker_died" for r in recs) <= 1
    assert main(
        ["study", str(src), "--out", str(out), "--workers", "2", "--quiet", "--resume"]
    ) == _study_code(ref)
    pd.testing.assert_frame_equal(stable(results_table(st, out)), stable(ref))
    assert not (out / ".lock").exists() and _temporaries(out) == []


@pytest.mark.slow  # over 10 s on an idle core: run by `pytest -m slow`
def test_dask_worker_killed_mid_study_gives_the_uninterrupted_rows(reference, tmp_path):
    distributed = pytest.importorskip("distributed")
    st = load_study(copy_study(tmp_path, n=8))
    ref = _first_cases(reference[2], st)
    out = tmp_path / "out"
    # ":0": the scheduler's HTTP server on a free port, not on 8787 that another cluster may hold (a
    # test on another pytest-xdist worker, another run on the machine; Dask then warns, an error
    # here)
    with (
        distributed.LocalCluster(
            n_workers=2,
            threads_per_worker=1,
            processes=True,
            dashboard_address=":0",
            silence_logs=50,
        ) as cluster,
        distributed.Client(cluster) as client,
    ):
        victim = sorted(client.run(os.getpid).values())[0]
        killed = []

        def kill_one(p):  # kill -9 a worker process after 2 finished cases
            if p.done >= 2 and not killed:
                os.kill(victim, signal.SIGKILL)
                killed.append(victim)

        s = run_study(st, out, scheduler=client, progress=kill_one, report=False)
        assert killed and s.died == 0
        if s.lost:  # the scheduler gave up on some cases: a resumed run solves them
            s = run_study(st, out, scheduler=client, resume=True, report=False)
        assert s.lost == 0
    pd.testing.assert_frame_equal(stable(results_table(st, out)), stable(ref))
