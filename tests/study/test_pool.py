"""Running studies: local pool, Dask, resume after kill -9, failing cases recorded."""

from __future__ import annotations

import pandas as pd
import pytest
from study_helpers import stable

from axisopt.cli import main
from axisopt.study import load_study, results_table, run_study


@pytest.fixture(scope="module")
def reference(tmp_path_factory):
    """The small study solved in this process, uninterrupted: the rows every other run must give."""
    d = tmp_path_factory.mktemp("ref")
    from study_helpers import small_study

    st = load_study(small_study(d))
    s = run_study(st, d / "out", workers=0)
    return st, s, results_table(st, d / "out")


def test_local_pool_gives_the_same_rows(reference, tmp_path):
    st, _, ref = reference
    s = run_study(st, tmp_path / "pool", workers=2, report=False)
    assert s.backend == "local pool" and s.solved == 12
    df = results_table(st, tmp_path / "pool")
    pd.testing.assert_frame_equal(stable(df), stable(ref))
    assert df["worker"].nunique() >= 1


def test_dask_local_cluster_gives_the_same_rows(reference, tmp_path):
    distributed = pytest.importorskip("distributed")
    st, _, ref = reference
    # ":0": the scheduler's HTTP server on a free port, not on 8787 that another cluster may hold (a
    # test on another pytest-xdist worker, another run on the machine; Dask then warns, an error
    # here)
    with distributed.LocalCluster(
        n_workers=1, threads_per_worker=2, processes=False, dashboard_address=":0"
    ) as cluster:
        s = run_study(st, tmp_path / "dask", scheduler=cluster.scheduler_address, report=False)
    assert s.backend == "dask" and s.solved == 12 and s.lost == 0
    pd.testing.assert_frame_equal(stable(results_table(st, tmp_path / "dask")), stable(ref))


def test_scheduler_errors_are_one_line(tmp_path, capsys):
    # without the 'dask' extra the message says to install it (next test)
    pytest.importorskip("distributed")
    from study_helpers import small_study

    p = small_study(tmp_path)
    rc = main(
        [
            "study",
            str(p),
            "--out",
            str(tmp_path / "o"),
            "--scheduler",
            "inproc://no-such-scheduler/0/0",
            "--quiet",
        ]
    )
    assert rc == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "Dask scheduler" in err
