"""Running a study: one solve per case, in worker processes, each result saved as it completes.

Execution back-ends (all call the same :func:`solve_case` on small case definitions):

* in process (``workers=0``): a plain loop, for debugging;
* a local pool (default): one ``multiprocessing`` process per core, started by a ``forkserver`` that
  has imported the solver stack once (``spawn`` where there is none), each fed one case at a time
  through its own pipe.  Each worker builds its own CasADi functions and loads the catalog once (both
  cached per process); nothing but case definitions and plain result dicts crosses the process
  boundary;
* an existing Dask cluster (``scheduler='tcp://host:8786'``): ``dask.distributed`` is imported only
  then.

Nothing is lost: the parent writes every finished case to ``DIR/cases/<case_id>.json`` through a
temporary file and ``os.replace`` (atomic, :func:`axisopt.report.atomic_file`, like every other output
file), so a run stopped by Ctrl-C, ``kill -9`` or a dead worker continues with ``resume=True`` and
recomputes only the missing cases.  A failing case (infeasible, bad combination of inputs, solver error)
is a result with its reason; the others go on.

The local pool sends one case at a time to each worker and the worker acknowledges it before solving,
so the parent knows which case each worker is running.  A worker that dies (killed, out of memory,
crashed in native code) costs only the case it was running: that case is tried again, the other
workers go on, a new worker takes the dead one's place.  A case whose worker dies twice while solving
it is recorded with status ``worker_died`` (an infrastructure failure, :data:`INFRA_STATUSES`), which a
resumed run solves again.

One run at a time writes to a study directory: ``DIR/.lock`` holds the pid, host and process start time
of the run; a second run stops with an InputError, a lock left by a run that is gone is taken over.
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
from .store import OK_STATUSES, RECORD_VERSION, CaseStore, _sweep_temporaries

# failures of the machinery, not of the case: not a result, solved again by a resumed run
INFRA_STATUSES = ("worker_died",)
# how versions before worker_died recorded a case whose worker died twice (status "error")
_LEGACY_WORKER_DIED = "worker process died twice while solving this case"
WORKER_DEATHS = 2  # a case whose worker dies this often while solving it is recorded as worker_died
# A solve is not thread-safe (per-process CasADi solver caches): a Dask worker with several threads
# runs its cases one at a time.
_SOLVE_LOCK = threading.Lock()


# ------------------------------------------------------------------------------------ one case

def solve_case(context: dict, case: Case) -> dict:
    """Build and solve one case; never raises for a case-level failure (the reason is recorded)."""
    from ..model import evaluate
    from ..report import drive_dict
    from ..report.evaluation import check_rows
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
            # on numpy: the CasADi Function of a case's duty cycle would be built for this one evaluation
            ev = evaluate(res.best.design, use_casadi=False) if res.best is not None and res.best.design is not None \
                else None
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
        rec["checks"] = {r["check"]: {k: r[k] for k in ("available", "needed", "unit", "margin", "pass")}
                         for r in check_rows(ev)}
    c = res.certificate
    rec["certificate"] = {"proven": bool(c.proven), "gap": _num(c.gap), "combinations": int(c.combinations),
                          "feasible": None if c.feasible is None else int(c.feasible),
                          "pruned_by_bound": int(c.pruned_by_bound),
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


def _pool_worker(conn, ctx: dict, solve, parent_pid: int) -> None:
    """A local pool worker: receive a case, acknowledge it, solve it, send the record; None ends it."""
    _init_worker(parent_pid)
    while True:
        try:
            case = conn.recv()
        except (EOFError, OSError):  # the parent is gone or closed the pipe
            return
        if case is None:
            return
        conn.send(("start", case.case_id))
        conn.send(("done", solve(ctx, case)))


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
    died: int = 0  # recorded as worker_died by this run (their worker died twice); rerun with resume
    redone: int = 0  # recorded as worker_died by an earlier run and solved again by this one


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
    resume    : continue a run in ``out_dir``; without it an ``out_dir`` holding results is an error.
                Cases recorded as infrastructure failures (``worker_died``) are solved again.
    progress  : callable(Progress) after each finished case

    Holds ``out_dir/.lock`` while it runs (InputError if another run holds it).  Files that cannot be
    written (disk full, no permission, a directory where a file belongs) are InputErrors naming the file.
    """
    from ..fileio import make_output_dir

    out = make_output_dir(out_dir)
    with StudyLock(out):
        return _run_locked(study, out, workers, scheduler, resume, progress, batch, report)


def _run_locked(study, out: Path, workers, scheduler, resume, progress, batch, report) -> RunSummary:
    store = CaseStore(out)
    have = store.existing()
    ids = {c.case_id for c in study.cases}
    if have and not resume:
        raise InputError(f"already holds {len(have)} case results; pass --resume to continue that study or "
                         f"choose another --out", source=str(out))
    store.prepare()
    _sweep_temporaries(out)
    if (out / "plots").is_dir():
        _sweep_temporaries(out / "plots")
    _write_definition(study, out)
    kept = {}
    for i in have & ids:
        rec = store.read(i)
        if rec is not None:
            kept[i] = "worker_died" if rec.get("reason") == _LEGACY_WORKER_DIED else rec.get("status")
    redo = {i for i, st in kept.items() if st in INFRA_STATUSES}  # the machinery failed, not the case
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
        lost, lost_reason, nw = _run_dask(scheduler, ctx, _batches(todo, bs), sink)
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
            # solve_case is looked up now (not imported by the workers) so that a test can replace it
            lost, lost_reason = _run_pool(min(nw, len(todo)), ctx, todo, sink, solve_case)
    summary = RunSummary(out_dir=str(out), total=len(study.cases), solved=prog.done - prog.resumed,
                         resumed=prog.resumed, failed=prog.failed, lost=lost, lost_reason=lost_reason,
                         time=prog.elapsed, backend=backend, workers=nw, died=died, redone=len(redo))
    if report:
        from .table import write_outputs

        summary.files = write_outputs(study, out, summary)
    return summary


def _batches(cases, size: int) -> list:
    return [tuple(cases[i:i + size]) for i in range(0, len(cases), size)]


def _write_definition(study: Study, out: Path) -> None:
    from ..fileio import write_text_atomic

    d = {"name": study.name, "source": study.source, "base_source": study.base_source, "method": study.method,
         "combine": study.combine, "keys": list(study.keys), "fingerprint": study.fingerprint(),
         "cases": [{"case_id": c.case_id, "index": c.index, "inputs": c.inputs()} for c in study.cases]}
    write_text_atomic(out / "study.json", json.dumps(d, indent=1, default=str) + "\n", what="study definition")


# ------------------------------------------------------------------------------------------- lock

class StudyLock:
    """``DIR/.lock``: one run at a time writes to a study directory.

    The file is created with ``O_CREAT | O_EXCL`` and holds one JSON line: pid, host and start time of
    the holding process.  A lock whose process is gone (same host; a pid now used by another process
    does not count) is taken over; taking it is serialised with ``flock`` on the directory, so two runs
    cannot both take over the same stale lock.  A lock from another host is never taken over: delete it
    by hand when that run is gone.
    """

    def __init__(self, out_dir):
        self.dir = Path(out_dir)
        self.path = self.dir / ".lock"
        self.mine = None

    def __enter__(self):
        self.acquire()
        return self

    def __exit__(self, *exc) -> None:
        self.release()

    def acquire(self) -> None:
        me = {"pid": os.getpid(), "host": socket.gethostname(), "start": _process_start(os.getpid()),
              "since": time.strftime("%Y-%m-%d %H:%M:%S")}
        text = json.dumps(me) + "\n"
        try:
            with _directory_flock(self.dir):
                try:
                    self._create(text)
                except FileExistsError:
                    holder = self._holder()
                    if _holder_alive(holder):
                        raise self._busy(holder) from None
                    os.unlink(self.path)  # stale: its run is gone
                    self._create(text)
        except OSError as exc:
            raise InputError(f"cannot take the study lock ({exc.strerror or exc})", source=str(self.path)) \
                from None
        self.mine = me

    def _create(self, text: str) -> None:
        fd = os.open(self.path, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o644)
        try:
            os.write(fd, text.encode())
        except OSError:  # disk full: no lock without its holder
            os.close(fd)
            os.unlink(self.path)
            raise
        os.close(fd)

    def _holder(self) -> dict:
        try:
            d = json.loads(self.path.read_text(encoding="utf-8"))
        except ValueError:
            return {}  # written only in part: its writer died between create and write
        return d if isinstance(d, dict) else {}

    def _busy(self, h: dict) -> InputError:
        return InputError(f"another study run (pid {h.get('pid')} on {h.get('host')}, since {h.get('since')}) is "
                          f"writing to this directory; wait for it to end, or delete {self.path} if that run "
                          f"is gone", source=str(self.dir))

    def release(self) -> None:
        if self.mine is None:
            return
        try:
            if self._holder().get("pid") == self.mine["pid"]:
                os.unlink(self.path)
        except OSError:
            pass  # left behind: the next run finds its process gone and takes it over
        self.mine = None


class _directory_flock:
    """Exclusive ``flock`` on a directory while a lock file in it is checked and taken (no-op without
    fcntl)."""

    def __init__(self, d: Path):
        self.d = d
        self.fd = None

    def __enter__(self):
        try:
            import fcntl
        except ImportError:  # pragma: no cover - not POSIX
            return self
        self.fd = os.open(self.d, os.O_RDONLY)
        try:
            fcntl.flock(self.fd, fcntl.LOCK_EX)
        except OSError:  # a file system without flock: the lock file alone still keeps runs apart
            pass
        return self

    def __exit__(self, *exc) -> None:
        if self.fd is not None:
            os.close(self.fd)  # releases the flock


def _process_start(pid: int):
    """Start time of a process in clock ticks since boot (Linux ``/proc``), else None."""
    try:
        with open(f"/proc/{pid}/stat", encoding="ascii", errors="replace") as fh:
            return int(fh.read().rsplit(")", 1)[1].split()[19])
    except (OSError, ValueError, IndexError):
        return None


def _holder_alive(h: dict) -> bool:
    """Whether the run recorded in a lock file may still be running."""
    if not h or not isinstance(h.get("pid"), int):
        return False  # garbled: its writer died while writing it
    if h.get("host") != socket.gethostname():
        return True  # cannot tell: another host's run is never taken over
    try:
        os.kill(h["pid"], 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        pass  # a process of another user has that pid
    start = _process_start(h["pid"])
    return not (start is not None and h.get("start") is not None and start != h["start"])


# ------------------------------------------------------------------------------------------- pool

def _mp_context():
    methods = mp.get_all_start_methods()
    if "forkserver" not in methods:  # pragma: no cover - not POSIX
        return mp.get_context("spawn")
    c = mp.get_context("forkserver")
    # the fork server imports the solver stack once, so that a worker (or one replacing a dead worker)
    # starts in milliseconds instead of a second; it takes effect when the server starts
    c.set_forkserver_preload(["axisopt.study.run", "axisopt.search", "axisopt.model", "axisopt.report"])
    return c


@dataclass
class _Worker:
    proc: object
    conn: object
    case: Case | None = None  # the case sent to it and not finished
    started: bool = False  # the worker acknowledged that case: it is solving it


def _run_pool(workers: int, ctx: dict, cases: list, sink, solve) -> tuple:
    """Solve ``cases`` on ``workers`` local processes, one case at a time per worker.

    A worker that dies costs only the case it acknowledged (``started``): that case goes back to the
    front of the queue, or is recorded as ``worker_died`` after :data:`WORKER_DEATHS` deaths; a case sent
    but not yet acknowledged goes back uncharged; a new worker replaces the dead one.  Workers that keep
    dying before they solve anything (broken installation, no memory) end the run with the cases left
    counted as lost.  Returns (lost, reason).
    """
    from collections import deque
    from multiprocessing.connection import wait

    mpc = _mp_context()
    queue = deque(cases)
    deaths: Counter = Counter()
    pool: list = []
    barren, last_exit = 0, ""  # deaths in a row that cost no case: no case was running

    def spawn() -> None:
        here, there = mpc.Pipe()
        proc = mpc.Process(target=_pool_worker, args=(there, ctx, solve, os.getpid()), daemon=True)
        proc.start()
        there.close()
        pool.append(_Worker(proc, here))

    def receive(w: _Worker) -> bool:
        """Take the worker's messages; False when its pipe is closed (the worker is gone)."""
        nonlocal barren
        try:
            while w.conn.poll():
                kind, val = w.conn.recv()
                if kind == "start":
                    w.started = True
                else:
                    w.case, w.started, barren = None, False, 0
                    sink(val)
        except (EOFError, OSError):
            return False
        return True

    def bury(w: _Worker) -> None:
        nonlocal barren, last_exit
        receive(w)  # a record sent just before it died still counts
        pool.remove(w)
        w.conn.close()
        w.proc.join(5)
        last_exit = _exit_text(w.proc.exitcode)
        c = w.case
        if c is None or not w.started:
            barren += 1
            if c is not None:
                queue.appendleft(c)  # sent, never started: not this case's fault
            return
        deaths[c.case_id] += 1
        if deaths[c.case_id] < WORKER_DEATHS:
            queue.appendleft(c)  # alone on a fresh worker next
            return
        sink({"version": RECORD_VERSION, "case_id": c.case_id, "index": c.index, "inputs": c.inputs(),
              "status": "worker_died", "time_s": 0.0, "worker": "",
              "reason": f"the worker process died {deaths[c.case_id]} times while solving this case (last: "
                        f"{last_exit}); a resumed run (--resume) solves it again"})

    finished = False
    try:
        while queue or any(w.case is not None for w in pool):
            if barren > 2 * workers + 2:
                lost = len(queue) + sum(w.case is not None for w in pool)
                return lost, f"worker processes keep dying before they solve a case ({last_exit})"
            busy = sum(w.case is not None for w in pool)
            while len(pool) < min(workers, busy + len(queue)):
                spawn()
            for w in pool:
                if w.case is None and queue:
                    w.case, w.started = queue.popleft(), False
                    try:
                        w.conn.send(w.case)
                    except OSError:
                        pass  # it died: its sentinel is ready
            ready = set(wait([w.conn for w in pool] + [w.proc.sentinel for w in pool]))
            for w in list(pool):
                if w.conn in ready or w.proc.sentinel in ready:
                    if not receive(w) or not w.proc.is_alive():
                        bury(w)
        finished = True
        return 0, ""
    finally:
        _stop_workers(pool, gently=finished)


def _exit_text(code) -> str:
    if code is None:
        return "did not exit"
    if code < 0:
        import signal

        try:
            return f"killed by {signal.Signals(-code).name}"
        except ValueError:
            return f"killed by signal {-code}"
    return f"exit code {code}"


def _stop_workers(pool: list, gently: bool) -> None:
    """End the pool's processes: idle ones are asked to stop, the others (Ctrl-C, an error) terminated."""
    for w in pool:
        if gently and w.case is None:
            try:
                w.conn.send(None)
                continue
            except OSError:
                pass
        if w.proc.is_alive():
            w.proc.terminate()
    for w in pool:
        w.proc.join(5)
        if w.proc.is_alive():  # pragma: no cover - stuck in native code
            w.proc.kill()
            w.proc.join(5)
        w.conn.close()


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


__all__ = ["run_study", "solve_case", "run_batch", "CaseStore", "StudyLock", "Progress", "RunSummary", "OK_STATUSES",
           "INFRA_STATUSES"]
