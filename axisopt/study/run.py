"""Running a study: one solve per case, in worker processes, each result saved as it completes.

Execution back-ends (all call the same :func:`solve_case` on small case definitions; :mod:`.pool`):

* in process (``workers=0``): a plain loop, for debugging;
* a local pool (default): one ``multiprocessing`` process per core, started by a ``forkserver`` that
  has imported the solver stack once (``spawn`` where there is none), each fed one case at a time
  through its own pipe.  Each worker builds its own CasADi functions and loads the catalog once
  (both cached per process); nothing but case definitions and plain result dicts crosses the process
  boundary;
* an existing Dask cluster (``scheduler='tcp://host:8786'``): ``dask.distributed`` is imported only
  then.

Nothing is lost: the parent writes every finished case to ``DIR/cases/<case_id>.json`` through a
temporary file and ``os.replace`` (atomic, :func:`axisopt.report.atomic_file`, like every other
output file), so a run stopped by Ctrl-C, ``kill -9`` or a dead worker continues with
``resume=True`` and recomputes only the missing cases.  A failing case (infeasible, bad combination
of inputs, solver error) is a result with its reason; the others go on.

The local pool sends one case at a time to each worker and the worker acknowledges it before
solving, so the parent knows which case each worker is running.  A worker that dies (killed, out of
memory, crashed in native code) costs only the case it was running: that case is tried again, the
other workers go on, a new worker takes the dead one's place.  A case whose worker dies twice while
solving it is recorded with status ``worker_died`` (an infrastructure failure,
:data:`INFRA_STATUSES`), which a resumed run solves again.

One run at a time writes to a study directory: ``DIR/.lock`` holds the pid, host and process start
time of the run; a second run stops with an InputError, a lock left by a run that is gone is taken
over (:mod:`.lock`).  One case's solve and its record: :mod:`.record`.
"""

from __future__ import annotations

import json
import os
import time
from dataclasses import dataclass, field
from pathlib import Path

from ..errors import InputError
from .cases import Study
from .lock import StudyLock
from .pool import run_dask, run_pool
from .record import INFRA_STATUSES, LEGACY_WORKER_DIED, run_batch, solve_case
from .store import OK_STATUSES, CaseStore, sweep_temporaries


@dataclass
class Progress:
    """Passed to the progress callback after every finished case."""

    total: int  # cases in the study
    done: int = 0  # finished, this run and earlier ones
    failed: int = 0  # finished with a status other than optimal / feasible
    resumed: int = 0  # found finished from an earlier run
    started: float = field(default_factory=time.perf_counter)

    @property
    def elapsed(self) -> float:
        return time.perf_counter() - self.started

    @property
    def eta(self) -> float | None:
        new = self.done - self.resumed
        if new <= 0:
            return None
        return self.elapsed / new * (self.total - self.done)


@dataclass
class RunSummary:
    out_dir: str
    total: int
    solved: int  # this run
    resumed: int  # already present
    failed: int  # failed cases in the whole table
    lost: int  # not run (infrastructure failure); rerun with resume
    lost_reason: str
    time: float
    backend: str
    workers: int
    files: dict = field(default_factory=dict)  # name -> path of the table, plots, report
    # recorded as worker_died by this run (their worker died twice); rerun with resume
    died: int = 0
    redone: int = 0  # recorded as worker_died by an earlier run and solved again by this one


def default_workers() -> int:
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # pragma: no cover - not Linux
        return os.cpu_count() or 1


def batch_size(n_cases: int, workers: int) -> int:
    """Several cases per task cut the per-task overhead; keep >= ~6 tasks per worker for balance."""
    return max(1, min(8, n_cases // max(1, 6 * workers)))


def run_study(
    study: Study,
    out_dir,
    *,
    workers: int | None = None,
    scheduler=None,
    resume: bool = False,
    progress=None,
    batch: int | None = None,
    report: bool = True,
) -> RunSummary:
    """Run every case of ``study`` not yet in ``out_dir`` and write the table, plots and report.

    workers   : local worker processes (default: all cores); 0 solves in this process
    scheduler : address of a Dask scheduler (or a ``dask.distributed.Client``); overrides workers
    resume    : continue a run in ``out_dir``; without it an ``out_dir`` holding results is an
                error.  Cases recorded as infrastructure failures (``worker_died``) are solved
                again.
    progress  : callable(Progress) after each finished case

    Holds ``out_dir/.lock`` while it runs (InputError if another run holds it).  Files that cannot
    be written (disk full, no permission, a directory where a file belongs) are InputErrors naming
    the file.
    """
    from ..fileio import make_output_dir

    out = make_output_dir(out_dir)
    with StudyLock(out):
        return _run_locked(study, out, workers, scheduler, resume, progress, batch, report)


def _run_locked(
    study, out: Path, workers, scheduler, resume, progress, batch, report
) -> RunSummary:
    store = CaseStore(out)
    have = store.existing()
    ids = {c.case_id for c in study.cases}
    if have and not resume:
        raise InputError(
            f"already holds {len(have)} case results; pass --resume to continue that study, "
            f"--overwrite to solve it again, or choose another --out",
            source=str(out),
        )
    store.prepare()
    sweep_temporaries(out)
    if (out / "plots").is_dir():
        sweep_temporaries(out / "plots")
    _write_definition(study, out)
    kept = {}
    for i in have & ids:
        rec = store.read(i)
        if rec is not None:
            kept[i] = (
                "worker_died" if rec.get("reason") == LEGACY_WORKER_DIED else rec.get("status")
            )
    # the machinery failed, not the case
    redo = {i for i, st in kept.items() if st in INFRA_STATUSES}
    done_ids = set(kept) - redo
    todo = [c for c in study.cases if c.case_id not in done_ids]
    prog = Progress(total=len(study.cases), done=len(done_ids), resumed=len(done_ids))
    prog.failed = sum(1 for i in done_ids if kept[i] not in OK_STATUSES)
    died = 0

    def sink(rec: dict) -> None:
        nonlocal died
        store.write(rec)
        prog.done += 1
        if rec["status"] not in OK_STATUSES:
            prog.failed += 1
        died += rec["status"] in INFRA_STATUSES
        if progress is not None:
            progress(prog)

    if progress is not None:
        progress(prog)
    ctx = study.context()
    lost, lost_reason = 0, ""
    if scheduler is not None:
        backend, nw = "dask", 0
        bs = batch or batch_size(len(todo), 4)
        lost, lost_reason, nw = run_dask(scheduler, ctx, _batches(todo, bs), sink)
    else:
        nw = default_workers() if workers is None else int(workers)
        if nw < 0:
            raise InputError(f"--workers must be 0 or more, got {nw}")
        if nw == 0 or not todo:
            backend = "in-process"
            for c in todo:
                sink(solve_case(ctx, c))
        else:
            backend = "local pool"
            # solve_case is looked up now (not imported by the workers) so that a test can replace
            # it
            lost, lost_reason = run_pool(min(nw, len(todo)), ctx, todo, sink, solve_case)
    summary = RunSummary(
        out_dir=str(out),
        total=len(study.cases),
        solved=prog.done - prog.resumed,
        resumed=prog.resumed,
        failed=prog.failed,
        lost=lost,
        lost_reason=lost_reason,
        time=prog.elapsed,
        backend=backend,
        workers=nw,
        died=died,
        redone=len(redo),
    )
    if report:
        from .outputs import write_outputs

        summary.files = write_outputs(study, out, summary)
    return summary


def _batches(cases, size: int) -> list:
    return [tuple(cases[i : i + size]) for i in range(0, len(cases), size)]


def _write_definition(study: Study, out: Path) -> None:
    from ..fileio import write_text_atomic

    d = {
        "name": study.name,
        "source": study.source,
        "base_source": study.base_source,
        "method": study.method,
        "combine": study.combine,
        "keys": list(study.keys),
        "fingerprint": study.fingerprint(),
        "cases": [
            {"case_id": c.case_id, "index": c.index, "inputs": c.inputs()} for c in study.cases
        ],
    }
    write_text_atomic(
        out / "study.json", json.dumps(d, indent=1, default=str) + "\n", what="study definition"
    )


__all__ = [
    "run_study",
    "solve_case",
    "run_batch",
    "CaseStore",
    "StudyLock",
    "Progress",
    "RunSummary",
    "OK_STATUSES",
    "INFRA_STATUSES",
]
