"""Machine studies: sweeps over a machine file, one joint solve per case, run by the axis study's
runner.  The records are the same whatever ran them (one process, two local workers, a Dask cluster
of one or two workers fed one batch at a time), a resumed run solves only the missing cases, the
table reads the records only."""

import json

import pytest
from machinegen import random_machine

from axisopt.cli import main
from axisopt.machine import load_machine, solve_machine
from axisopt.study.cases import Case
from axisopt.study.machine import build_machine, load_machine_study, run_machine_study

SWEEP = """sweep:
  axes.A.problem.axis.moving_mass: [200 kg, 300 kg, 400 kg]
  machine.limits.min_tool_stiffness: [5 N/um, 20 N/um]
"""


def _study(tmp_path, seed=4):
    (tmp_path / "m.yaml").write_text(random_machine(seed))
    p = tmp_path / "s.yaml"
    p.write_text("name: s\nbase: m.yaml\n" + SWEEP)
    return load_machine_study(p)


def _records(out) -> dict:
    recs = {}
    for f in sorted((out / "cases").glob("*.json")):
        r = json.loads(f.read_text())
        for k in ("worker", "time_s"):
            r.pop(k)
        recs[f.stem] = r
    return recs


@pytest.fixture(scope="module")
def reference(tmp_path_factory):
    d = tmp_path_factory.mktemp("ms")
    st = _study(d)
    s = run_machine_study(st, d / "one", workers=0)
    assert s.solved == 6 and s.backend == "in-process"
    return st, d, _records(d / "one"), (d / "one" / "machines.csv").read_text()


def test_a_case_is_the_machine_solve_of_its_values(reference):
    st, d, recs, _ = reference
    assert len(recs) == 6
    case = st.cases[5]  # 400 kg, 20 N/um
    assert dict(case.overrides) == {
        "axes.A.problem.axis.moving_mass": "400 kg",
        "machine.limits.min_tool_stiffness": "20 N/um",
    }
    m = build_machine(st.context(), case)
    assert m.by_name["A"].problem.axis.moving_mass == 400.0 and m.min_tool_stiffness == (20e6,) * 3
    res = solve_machine(m)
    rec = recs[case.case_id]
    assert rec["status"] == res.status
    if res.best is not None:
        assert rec["objective"]["value"] == pytest.approx(
            res.best.value(m.objective) * (1e-6 if m.objective == "tool_stiffness" else 1.0),
            rel=1e-12,
        )
        assert [a["name"] for a in rec["best"]["axes"]] == [a.name for a in m.axes]


def test_two_local_workers_give_the_same_records_and_table(reference):
    st, d, recs, table = reference
    s = run_machine_study(st, d / "two", workers=2)
    assert s.backend == "local pool" and s.solved == 6
    assert _records(d / "two") == recs
    assert (d / "two" / "machines.csv").read_text() == table


@pytest.mark.parametrize("workers", [1, 2])
def test_dask_gives_the_same_records_fed_a_few_tasks_at_a_time(reference, workers, monkeypatch):
    distributed = pytest.importorskip("distributed")
    from axisopt.study import pool

    st, d, recs, table = reference
    monkeypatch.setattr(pool, "MAX_TASKS", 2)  # the scheduler holds two batches at a time
    held = []
    with distributed.LocalCluster(
        n_workers=workers, threads_per_worker=1, processes=False, dashboard_address=":0"
    ) as cluster:
        with distributed.Client(cluster) as client:

            def count(_progress):
                held.append(sum(1 for t in cluster.scheduler.tasks if "run_batch" in str(t)))

            s = run_machine_study(
                st, d / f"dask{workers}", scheduler=client, batch=1, progress=count
            )
    assert s.backend == "dask" and s.solved == 6 and s.lost == 0
    assert 0 < max(held) <= 3  # two in flight and the one just finished
    assert _records(d / f"dask{workers}") == recs
    assert (d / f"dask{workers}" / "machines.csv").read_text() == table


def test_resume_solves_only_the_missing_cases(reference):
    import shutil

    st, d, recs, table = reference
    shutil.copytree(d / "one", d / "resumed")
    gone = sorted((d / "resumed" / "cases").glob("*.json"))[1::3]
    for f in gone:
        f.unlink()
    with pytest.raises(Exception, match="--resume"):
        run_machine_study(st, d / "resumed", workers=0)
    s = run_machine_study(st, d / "resumed", workers=0, resume=True)
    assert s.solved == len(gone) and s.resumed == 6 - len(gone)
    assert _records(d / "resumed") == recs
    assert (d / "resumed" / "machines.csv").read_text() == table


def test_cli_and_bad_sweep_values(reference, tmp_path, capsys):
    st, d, _, table = reference
    assert main(
        ["machine", "study", st.source, "--out", str(tmp_path / "cli"), "--workers", "0", "--quiet"]
    ) in (0, 1)
    assert (tmp_path / "cli" / "machines.csv").read_text() == table
    capsys.readouterr()
    bad = tmp_path / "bad.yaml"
    bad.write_text(
        f"base: {d / 'm.yaml'}\nsweep:\n  axes.A.problem.axis.moving_mass: [200 kg, 3 m]\n"
    )
    assert main(["machine", "study", str(bad), "--out", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "axes.A.problem.axis.moving_mass" in err and "3 m" in err
    bad.write_text(f"base: {d / 'm.yaml'}\nsweep:\n  axes.Q.direction: [x]\n")
    assert main(["machine", "study", str(bad), "--out", str(tmp_path / "o")]) == 2
    assert len(capsys.readouterr().err.strip().splitlines()) == 1


def test_the_shipped_machine_study_loads_on_the_shipped_machine():
    st = load_machine_study("problems/machines/vmc_masses_study.yaml")
    assert len(st.cases) == 2
    m = build_machine(st.context(), Case("c", 0, st.cases[1].overrides))
    assert m.by_name["Z"].problem.axis.moving_mass == 400.0
    assert (
        load_machine("problems/machines/vmc_machine.yaml").by_name["Z"].problem.axis.moving_mass
        == 300.0
    )


def test_a_machine_study_never_writes_over_its_machine_file(tmp_path):
    # the base machine named as the table the study writes, in the output directory: refused before
    # any solve
    from axisopt.errors import InputError

    (tmp_path / "machines.csv").write_text(random_machine(4))
    before = (tmp_path / "machines.csv").read_text()
    p = tmp_path / "s.yaml"
    p.write_text("name: s\nbase: machines.csv\n" + SWEEP)
    with pytest.raises(
        InputError, match="would overwrite the input .*machines.csv with the study's machines.csv"
    ):
        run_machine_study(load_machine_study(p), tmp_path, workers=0)
    assert (tmp_path / "machines.csv").read_text() == before
    assert not (tmp_path / "cases").exists()
