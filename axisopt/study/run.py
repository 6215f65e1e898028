"""Running a study: one solve per case, in worker processes, each result saved as it completes.

Execution back-ends (all call the same :func:`run_batch` on small case definitions):

* in process (``workers=0``): a plain loop, for debugging;
* a local pool (default): ``concurrent.futures.ProcessPoolExecutor`` with the ``forkserver`` start
  method (``spawn`` where there is none), one worker per core.  Each worker builds its own CasADi
  functions and loads the catalog once (both cached per process); nothing but case definitions and
  plain result dicts crosses the process boundary;
* an existing Dask cluster (``scheduler='tcp://host:8786'``): ``dask.distributed`` is imported only
  then.

Nothing is lost: the parent writes every finished case to ``DIR/cases/<case_id>.json`` through a
temporary file and ``os.replace`` (atomic), so a run stopped by Ctrl-C, ``kill -9`` or a dead worker
continues with ``resume=True`` and recomputes only the missing cases.  A failing case (infeasible,
bad combination of inputs, solver error) is a result with its reason; the others go on.  A case
whose worker process dies twice is recorded as failed rather than retried forever.
"""

from __future__ import annotations

import json
import math
import multiprocessing as mp
import os
import socket
import threading
import time
from collections import Counter
from dataclasses import dataclass, field
from pathlib import Path

from ..errors import InputError
from .spec import Case, Study, build_problem, short_message

OK_STATUSES = ("optimal", "feasible")
RECORD_VERSION = 1
# A solve is not thread-safe (per-process CasADi solver caches): a Dask worker with several threads
# runs its cases one at a time.
_SOLVE_LOCK = threading.Lock()


# ------------------------------------------------------------------------------------ one case

def solve_case(context: dict, case: Case) -> dict:
    """Build and solve one case; never raises for a case-level failure (the reason is recorded)."""
    from ..model import evaluate
    from ..report import drive_dict
    from ..search import solve

    t0 = time.perf_counter()
    rec = {"version": RECORD_VERSION, "case_id": case.case_id, "index": case.index,
           "inputs": {k: v for k, v in case.overrides}, "status": "", "reason": "",
           "worker": f"{socket.gethostname()}:{os.getpid()}"}
    try:
        problem = build_problem(context, case)
    except InputError as exc:
        rec.update(status="input_error", reason=short_message(exc).replace("\n", " "),
                   time_s=time.perf_counter() - t0)
        return rec
    try:
        with _SOLVE_LOCK:
            res = solve(problem, context["method"], top=1, sensitivities=False)
            ev = evaluate(res.best.design) if res.best is not None and res.best.design is not None else None
    except Exception as exc:  # a solver failure is a result of this case, not the end of the study
        rec.update(status="error", reason=f"{type(exc).__name__}: {exc}".replace("\n", " "),
                   time_s=time.perf_counter() - t0)
        return rec
    rec["status"] = res.status
    rec["objective"] = {"label": res.objective_label, "unit": res.objective_unit, "value": _num(res.objective)}
    reason = res.message
    if res.infeasibility is not None and res.infeasibility.unmeetable:
        reason = (reason + "; " if reason else "") + "no combination meets " + ", ".join(
            f"{n} (limit {lim:.4g}, best {b:.4g} {u})" for n, b, lim, u in res.infeasibility.unmeetable)
    rec["reason"] = reason if res.status not in OK_STATUSES else ""
    rec["note"] = res.message if res.status in OK_STATUSES else ""
    if res.best is not None:
        best = res.best.to_dict()
        best.pop("misses", None)
        rec["best"] = best
    if ev is not None:
        k, kpos = ev.minimum("k_total")
        f, fpos = ev.minimum("f1")
        rec["profile"] = {"min_stiffness_position_mm": kpos * 1e3, "min_frequency_position_mm": fpos * 1e3,
                          "weakest_link": ev.weakest, "all_checks_pass": bool(min(ev.checks().values()) >= 1.0)}
        drv = drive_dict(ev)
        if drv is not None:  # the motor's needs and its torque margins
            rec["drive"] = {k: (_num(float(v)) if isinstance(v, (int, float)) else v) for k, v in drv.items()}
            rec["drive"].update({f"margin_{k}": _num(float(ev[f"margin_{k}"]))
                                 for k in ("motor_peak_torque", "motor_rated_torque")})
    c = res.certificate
    rec["certificate"] = {"proven": bool(c.proven), "gap": _num(c.gap), "combinations": int(c.combinations),
                          "feasible": int(c.feasible), "pruned_by_bound": int(c.pruned_by_bound),
                          "exact_evaluations": int(c.exact_evaluations), "nlps": int(c.nlps_solved),
                          "nlp_failures": int(c.nlp_failures)}
    if res.pareto is not None:
        rec["pareto"] = res.pareto.to_dict()
    rec["time_s"] = time.perf_counter() - t0
    return rec


def run_batch(context: dict, cases) -> list:
    """Solve several cases (one task of a pool or Dask cluster)."""
    return [solve_case(context, c) for c in cases]


def _num(v):
    return float(v) if v is not None and math.isfinite(v) else None


def _init_worker(parent_pid: int):
    import signal

    signal.signal(signal.SIGINT, signal.SIG_IGN)  # the parent handles Ctrl-C and stops the pool
    threading.Thread(target=_watch_parent, args=(parent_pid,), daemon=True).start()


def _watch_parent(pid: int, interval: float = 1.0) -> None:
    """End this worker when the study process is gone (killed with -9): no orphans left solving."""
    while True:
        time.sleep(interval)
        try:
            os.kill(pid, 0)
        except ProcessLookupError:
            os._exit(1)
        except PermissionError:  # pragma: no cover - pid reused by another user's process
            os._exit(1)


# ---------------------------------------------------------------------------------------- store

class CaseStore:
    """``DIR/cases/<case_id>.json``, one file per finished case, each written atomically."""

    def __init__(self, out_dir):
        self.dir = Path(out_dir) / "cases"

    def prepare(self) -> None:
        from ..report import make_output_dir

        make_output_dir(self.dir)
        for tmp in self.dir.glob(".*.tmp"):  # left by a run killed while writing
            tmp.unlink(missing_ok=True)

    def existing(self) -> set:
        if not self.dir.is_dir():
            return set()
        return {p.stem for p in self.dir.glob("*.json")}

    def write(self, rec: dict) -> None:
        final = self.dir / f"{rec['case_id']}.json"
        tmp = self.dir / f".{rec['case_id']}.{os.getpid()}.tmp"
        with open(tmp, "w", encoding="utf-8") as fh:
            json.dump(rec, fh, indent=1, allow_nan=False, default=_json_default)
        # os.replace is atomic: a reader (or a resumed run) sees the whole file or none.  No fsync: that
        # only guards against power loss, after which an unreadable file is treated as missing.
        os.replace(tmp, final)

    def read(self, case_id: str) -> dict | None:
        try:
            with open(self.dir / f"{case_id}.json", encoding="utf-8") as fh:
                return json.load(fh)
        except (OSError, ValueError):
            return None


def _json_default(o):
    import numpy as np

    if isinstance(o, np.generic):
        return o.item()
    raise TypeError(f"not JSON serialisable: {type(o).__name__}")


# ---------------------------------------------------------------------------------------- runner

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


def default_workers() -> int:
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # pragma: no cover - not Linux
        return os.cpu_count() or 1


def batch_size(n_cases: int, workers: int) -> int:
    """Several cases per task cut the per-task overhead; keep >= ~6 tasks per worker for balance."""
    return max(1, min(8, n_cases // max(1, 6 * workers)))


def run_study(study: Study, out_dir, *, workers: int | None = None, scheduler=None, resume: bool = False,
              progress=None, batch: int | None = None, report: bool = True) -> RunSummary:
    """Run every case of ``study`` not yet in ``out_dir`` and write the table, plots and report.

    workers   : local worker processes (default: all cores); 0 solves in this process
    scheduler : address of a Dask scheduler (or a ``dask.distributed.Client``); overrides workers
    resume    : continue a run in ``out_dir``; without it an ``out_dir`` holding results is an error
    progress  : callable(Progress) after each finished case
    """
    out = Path(out_dir)
    store = CaseStore(out)
    have = store.existing()
    ids = {c.case_id for c in study.cases}
    if have and not resume:
        raise InputError(f"already holds {len(have)} case results; pass --resume to continue that study or "
                         f"choose another --out", source=str(out))
    store.prepare()
    _write_definition(study, out)
    done_ids = {i for i in have & ids if store.read(i) is not None}
    todo = [c for c in study.cases if c.case_id not in done_ids]
    prog = Progress(total=len(study.cases), done=len(done_ids), resumed=len(done_ids))
    if done_ids:
        prog.failed = sum(1 for i in done_ids if store.read(i).get("status") not in OK_STATUSES)

    def sink(rec: dict) -> None:
        store.write(rec)
        prog.done += 1
        if rec["status"] not in OK_STATUSES:
            prog.failed += 1
        if progress is not None:
            progress(prog)

    if progress is not None:
        progress(prog)
    ctx = study.context()
    lost, lost_reason = 0, ""
    if scheduler is not None:
        backend, nw = "dask", 0
        bs = batch or batch_size(len(todo), 4)
        lost, lost_reason, nw = _run_dask(scheduler, ctx, _batches(todo, bs), sink)
    else:
        nw = default_workers() if workers is None else int(workers)
        if nw < 0:
            raise InputError(f"--workers must be 0 or more, got {nw}")
        bs = batch or batch_size(len(todo), max(nw, 1))
        if nw == 0 or not todo:
            backend = "in-process"
            for c in todo:
                sink(solve_case(ctx, c))
        else:
            backend = "local pool"
            _run_pool(min(nw, len(todo)), ctx, _batches(todo, bs), sink)
    summary = RunSummary(out_dir=str(out), total=len(study.cases), solved=prog.done - prog.resumed,
                         resumed=prog.resumed, failed=prog.failed, lost=lost, lost_reason=lost_reason,
                         time=prog.elapsed, backend=backend, workers=nw)
    if report:
        from .table import write_outputs

        summary.files = write_outputs(study, out, summary)
    return summary


def _batches(cases, size: int) -> list:
    return [tuple(cases[i:i + size]) for i in range(0, len(cases), size)]


def _write_definition(study: Study, out: Path) -> None:
    d = {"name": study.name, "source": study.source, "base_source": study.base_source, "method": study.method,
         "combine": study.combine, "keys": list(study.keys), "fingerprint": study.fingerprint(),
         "cases": [{"case_id": c.case_id, "index": c.index, "inputs": c.inputs()} for c in study.cases]}
    tmp = out / ".study.json.tmp"
    tmp.write_text(json.dumps(d, indent=1, default=str) + "\n", encoding="utf-8")
    os.replace(tmp, out / "study.json")


def _mp_context():
    methods = mp.get_all_start_methods()
    return mp.get_context("forkserver" if "forkserver" in methods else "spawn")


def _run_pool(workers: int, ctx: dict, batches: list, sink) -> None:
    from concurrent.futures import ProcessPoolExecutor, as_completed
    from concurrent.futures.process import BrokenProcessPool

    crashes: Counter = Counter()
    pending = list(batches)
    while pending:
        ex = ProcessPoolExecutor(workers, mp_context=_mp_context(), initializer=_init_worker,
                                 initargs=(os.getpid(),))
        futs = {ex.submit(run_batch, ctx, b): b for b in pending}
        pending = []
        try:
            for f in as_completed(futs):
                recs = f.result()
                futs.pop(f)
                for r in recs:
                    sink(r)
        except BrokenProcessPool:
            # a worker died (killed, out of memory, crashed in native code): keep what finished, retry
            # the rest one case per task; a case in flight at two deaths is recorded as failed
            for f, b in futs.items():
                if f.done() and f.exception() is None:
                    for r in f.result():
                        sink(r)
                    continue
                for c in b:
                    crashes[c.case_id] += 1
                    if crashes[c.case_id] >= 2:
                        sink({"version": RECORD_VERSION, "case_id": c.case_id, "index": c.index,
                              "inputs": c.inputs(), "status": "error", "time_s": 0.0, "worker": "",
                              "reason": "worker process died twice while solving this case"})
                    else:
                        pending.append((c,))
            pending.sort(key=lambda b: b[0].index)
        except BaseException:
            _stop(ex)
            raise
        finally:
            ex.shutdown(wait=True, cancel_futures=True)


def _stop(ex) -> None:
    """Stop a pool now (Ctrl-C): end the worker processes we started, then cancel queued tasks."""
    procs = list((getattr(ex, "_processes", None) or {}).values())  # shutdown() forgets them
    for p in procs:
        if p.is_alive():
            p.terminate()
    ex.shutdown(wait=False, cancel_futures=True)
    for p in procs:
        p.join(5)


def _run_dask(scheduler, ctx: dict, batches: list, sink):
    try:
        from dask.distributed import Client, as_completed
    except ImportError:
        raise InputError("--scheduler needs dask.distributed, an optional extra: pip install 'axisopt[dask]'") \
            from None
    own = not hasattr(scheduler, "submit")
    if own:
        try:
            client = Client(scheduler, timeout="10s")
        except (OSError, TimeoutError, ValueError) as exc:
            raise InputError(f"cannot connect to the Dask scheduler at '{scheduler}' ({exc})") from None
    else:
        client = scheduler
    lost, reason = 0, ""
    try:
        nw = len(client.scheduler_info().get("workers", {}))
        ctx_f = client.scatter(ctx, broadcast=True)
        futs = {}
        for b in batches:
            futs[client.submit(run_batch, ctx_f, b, pure=False)] = b
        for f in as_completed(list(futs)):
            b = futs[f]
            try:
                recs = f.result()
            except Exception as exc:  # worker lost after the scheduler's retries, connection lost...
                lost += len(b)
                reason = f"{type(exc).__name__}: {exc}"
                continue
            for r in recs:
                sink(r)
    finally:
        if own:
            client.close()
    return lost, reason, nw


__all__ = ["run_study", "solve_case", "run_batch", "CaseStore", "Progress", "RunSummary", "OK_STATUSES"]
