"""The execution back-ends of a study run: a local pool of worker processes (:func:`run_pool`) and
an existing Dask cluster (:func:`run_dask`).  Both pass finished case records to a ``sink``; neither
writes files.

The local pool sends one case at a time to each worker and the worker acknowledges it before
solving, so the parent knows which case each worker is running.  A worker that dies (killed, out of
memory, crashed in native code) costs only the case it was running: that case is tried again, the
other workers go on, a new worker takes the dead one's place.  A case whose worker dies twice while
solving it is recorded with status ``worker_died`` (an infrastructure failure).
"""

from __future__ import annotations

import multiprocessing as mp
import os
import threading
import time
from collections import Counter
from dataclasses import dataclass

from ..errors import InputError
from .cases import Case
from .record import run_batch
from .store import RECORD_VERSION

WORKER_DEATHS = 2  # a case whose worker dies this often while solving it is recorded as worker_died


MAX_TASKS = 10_000  # batches a Dask scheduler holds at a time (run_dask)


def _pool_worker(conn, ctx: dict, solve, parent_pid: int) -> None:
    """A local pool worker: receive a case, acknowledge it, solve it, send the record; None ends
    it."""
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


def _mp_context():
    methods = mp.get_all_start_methods()
    if "forkserver" not in methods:  # pragma: no cover - not POSIX
        return mp.get_context("spawn")
    c = mp.get_context("forkserver")
    # the fork server imports the solver stack once, so that a worker (or one replacing a dead
    # worker) starts in milliseconds instead of a second; it takes effect when the server starts
    c.set_forkserver_preload(["axisopt.study.run", "axisopt.search", "axisopt.model"])
    return c


@dataclass
class _Worker:
    proc: object
    conn: object
    case: Case | None = None  # the case sent to it and not finished
    started: bool = False  # the worker acknowledged that case: it is solving it


def run_pool(workers: int, ctx: dict, cases: list, sink, solve) -> tuple:
    """Solve ``cases`` on ``workers`` local processes, one case at a time per worker.

    A worker that dies costs only the case it acknowledged (``started``): that case goes back to the
    front of the queue, or is recorded as ``worker_died`` after :data:`WORKER_DEATHS` deaths; a case
    sent but not yet acknowledged goes back uncharged; a new worker replaces the dead one.  Workers
    that keep dying before they solve anything (broken installation, no memory) end the run with the
    cases left counted as lost.  Returns (lost, reason).
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
        sink(
            {
                "version": RECORD_VERSION,
                "case_id": c.case_id,
                "index": c.index,
                "inputs": c.inputs(),
                "status": "worker_died",
                "time_s": 0.0,
                "worker": "",
                "reason": f"the worker process died {deaths[c.case_id]} times while solving this "
                f"case (last: {last_exit}); a resumed run (--resume) solves it again",
            }
        )

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
    """End the pool's processes: idle ones are asked to stop, the others (Ctrl-C, an error)
    terminated."""
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


def run_dask(scheduler, ctx: dict, batches: list, sink, max_tasks: int | None = None):
    """Solve ``batches`` (tuples of cases) on a Dask cluster, each finished batch's records to
    ``sink``.

    At most ``max_tasks`` (default :data:`MAX_TASKS`) batches are submitted at a time (the
    scheduler's memory and bookkeeping grow with its tasks), the next one as each ends.  Returns
    (cases lost, reason, workers)."""
    try:
        from dask.distributed import Client, as_completed
    except ImportError:
        raise InputError(
            "--scheduler needs dask.distributed, an optional extra: pip install 'axisopt[dask]'"
        ) from None
    own = not hasattr(scheduler, "submit")
    if own:
        try:
            client = Client(scheduler, timeout="10s")
        except (OSError, TimeoutError, ValueError) as exc:
            raise InputError(
                f"cannot connect to the Dask scheduler at '{scheduler}' ({exc})"
            ) from None
    else:
        client = scheduler
    lost, reason = 0, ""
    try:
        nw = len(client.scheduler_info().get("workers", {}))
        ctx_f = client.scatter(ctx, broadcast=True)
        futs, todo, done = {}, iter(batches), as_completed()

        def submit() -> None:  # the next batch, if any
            b = next(todo, None)
            if b is not None:
                f = client.submit(run_batch, ctx_f, b, pure=False)
                futs[f] = b
                done.add(f)

        # the scheduler holds at most max_tasks tasks; one more as each ends
        for _ in range(max_tasks or MAX_TASKS):
            submit()
        for f in done:
            b = futs.pop(f)
            submit()
            try:
                recs = f.result()
            # worker lost after the scheduler's retries, connection lost...
            except Exception as exc:
                lost += len(b)
                reason = f"{type(exc).__name__}: {exc}"
                continue
            for r in recs:
                sink(r)
    finally:
        if own:
            client.close()
    return lost, reason, nw


__all__ = ["run_pool", "run_dask", "WORKER_DEATHS", "MAX_TASKS"]
