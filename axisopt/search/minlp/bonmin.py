"""Reference method: the whole problem as one MINLP for CasADi + Bonmin (a heuristic on this
nonconvex problem).

The formulation is :mod:`axisopt.search.minlp.formulation`'s: one-hot binaries choose the nut, the
bearing arrangement and the guide-and-drive entry, and the symbolic
:func:`axisopt.model.axis_response` is evaluated on the binary-weighted part parameters (exact at
integer points).  The nut preload is ``lo(z) + w (hi(z) - lo(z))`` with w in [0, 1].  The objective
is an epigraph variable below the objective at every grid position (same grid as the other methods);
every limit is a constraint scaled by :func:`axisopt.search.minlp.scaling.scaled_limit`.  A mounting
is a structural choice of the model, so each allowed mounting is one MINLP, run in turn within the
overall time limit.  Bonmin's own status is reported as is; the chosen combination is then
re-evaluated exactly and re-checked.
"""

from __future__ import annotations

import logging
import os
import sys
import time
import traceback

import casadi as ca
import numpy as np

from ... import model
from ...units import N_PER_UM
from ..candidates import make_candidate
from ..certificate import Certificate
from ..result import FEASIBLE, SOLVER_FAILED, SolveResult
from ..task.objective import STIFFNESS_OUTPUTS
from .formulation import SLOTS, integral, one_hot_params, one_hot_symbols, recover
from .scaling import scaled_limit
from .statuses import BONMIN_INFEASIBLE, BONMIN_SUCCESS
from .streams import quiet_stdout

# of each column's mean added to the one-hot mixtures (no stiffness or diameter exactly 0)
FLOOR = 1e-6
# a preload that misses a limit on exact re-evaluation is backed off by this fraction of its range
# (Bonmin's constraint tolerance)
MOVES = (-1e-6,)


def _build(space, mounting, constraints, objective):
    _, N, B, G = space.shape
    z = one_hot_symbols(space)
    w = ca.SX.sym("w")
    t = ca.SX.sym("t", len(objective.terms))
    p = one_hot_params(space, mounting, z, floor=FLOOR)
    lo = ca.dot(ca.DM(space.preload_lo), z["nut"]) + FLOOR * float(np.mean(space.preload_hi))
    hi = ca.dot(ca.DM(space.preload_hi), z["nut"]) + FLOOR * float(np.mean(space.preload_hi))
    x = space.positions(mounting)
    out = model.axis_response(
        p, ca.DM(x), mounting, lo + w * (hi - lo), space.request.but(extras=True)
    )
    g, lbg, ubg = [], [], []
    for s in SLOTS:
        g.append(ca.sum1(z[s]))
        lbg.append(1.0)
        ubg.append(1.0)
    for i, (key, _w) in enumerate(objective.terms):
        v = out[key] / N_PER_UM if key in STIFFNESS_OUTPUTS else out[key]
        g.append(v - t[i])
        lbg += [0.0] * v.shape[0]
        ubg += [ca.inf] * v.shape[0]
    for c in constraints:
        v = ca.SX(out[c.key])  # a drive check without a motor is a constant
        e, rhs = scaled_limit(c, v)
        n = v.shape[0]
        g.append(e - rhs)
        lbg += [0.0 if c.sense == ">=" else -ca.inf] * n
        ubg += [ca.inf if c.sense == ">=" else 0.0] * n
    xvar = ca.vertcat(z["nut"], z["bearing"], z["guide"], w, t)
    f = -sum(wt * t[i] for i, (_k, wt) in enumerate(objective.terms))
    discrete = [True] * (N + B + G) + [False] * (1 + len(objective.terms))
    return {"x": xvar, "f": f, "g": ca.vertcat(*g)}, np.array(lbg), np.array(ubg), discrete


# Seconds Bonmin may run past the time limit before it is stopped: its own limit is checked between
# branch-and-bound nodes, and one node's NLP can run for minutes.
DEADLINE_GRACE = 2.0


class ChildError(Exception):
    """What the Bonmin child raised that is not a solver failure (a bug), with the child's
    traceback."""


LOG = logging.getLogger("axisopt.search")
PROGRESS_EVERY = 10.0  # [s] progress lines on a terminal's stderr


def _solve_with_deadline(work, deadline: float, label: str):
    """Run ``work()`` (build and solve one MINLP) in a forked child and stop it at ``deadline``
    seconds.

    Building the symbolic problem and its derivatives can itself take minutes on a large catalog, so
    the whole of it runs in the child.  Returns ("ok", (x, stats)), ("error", message) or
    ("timeout", None).  Where fork is not available the work runs in this process (Bonmin's own time
    limit only)."""
    import multiprocessing as mp

    try:
        ctx = mp.get_context("fork")
    except ValueError:
        return work()
    recv, send = ctx.Pipe(duplex=False)

    def child():
        recv.close()
        sent = False
        try:
            send.send(work())
            sent = True
        # CasADi's errors building the problem, no memory for it
        except (RuntimeError, MemoryError) as exc:
            send.send(("error", f"{type(exc).__name__}: {exc}"))
            sent = True
        finally:
            # anything else is a bug, not a solver failure: the parent raises it (ChildError)
            if not sent:
                send.send(("raised", traceback.format_exc()))
            send.close()
            os._exit(0)

    proc = ctx.Process(target=child, daemon=True)
    proc.start()
    send.close()
    start = time.perf_counter()
    tty = sys.stderr.isatty()
    try:
        while True:
            left = deadline - (time.perf_counter() - start)
            if left <= 0:
                return "timeout", None
            if recv.poll(min(left, PROGRESS_EVERY)):
                try:
                    status, value = recv.recv()
                except EOFError:
                    return "error", "the Bonmin process ended without a result"
                if status == "raised":  # what the work raised in the child, as it would have here
                    raise ChildError(value)
                return status, value
            if tty:  # the CLI shows the "axisopt" logger's records on a terminal (only cli prints)
                LOG.info(
                    "bonmin %s: running, %.0f s of at most %.0f s",
                    label,
                    time.perf_counter() - start,
                    deadline,
                )
    finally:
        recv.close()
        if proc.is_alive():
            proc.kill()
        proc.join()


def _mounting_solve(space, mounting, constraints, objective, time_limit: float):
    """Build the MINLP of one mounting and solve it with Bonmin (runs in the deadline child)."""
    _, N, B, G = space.shape
    nlp, lbg, ubg, discrete = _build(space, mounting, constraints, objective)
    opts = {
        "discrete": discrete,
        "print_time": False,
        "bonmin.time_limit": float(time_limit),
        "bonmin.bb_log_level": 0,
        "bonmin.nlp_log_level": 0,
        "bonmin.fp_log_level": 0,
        "bonmin.lp_log_level": 0,
        "bonmin.milp_log_level": 0,
        "bonmin.oa_log_level": 0,
        "bonmin.print_level": 0,
        "bonmin.sb": "yes",
    }
    solver = ca.nlpsol(f"bonmin_{mounting.replace('-', '_')}", "bonmin", nlp, opts)
    nt = len(objective.terms)
    x0 = np.concatenate(
        [np.full(N, 1.0 / N), np.full(B, 1.0 / B), np.full(G, 1.0 / G), [1.0], np.zeros(nt)]
    )
    lbx = np.concatenate([np.zeros(N + B + G + 1), np.full(nt, -np.inf)])
    ubx = np.concatenate([np.ones(N + B + G + 1), np.full(nt, np.inf)])
    return _solve_here(solver, dict(x0=x0, lbx=lbx, ubx=ubx, lbg=lbg, ubg=ubg))


def _solve_here(solver, args: dict):
    try:
        with quiet_stdout():
            sol = solver(**args)
    except RuntimeError as exc:
        last = [ln for ln in str(exc).splitlines() if ln.strip()][-1]
        return "error", last.split(": ", 1)[-1].strip()
    st = solver.stats()
    return "ok", (
        np.asarray(sol["x"]).ravel(),
        {
            "return_status": str(st.get("return_status", "unknown")),
            "success": bool(st.get("success", False)),
        },
    )


def solve_bonmin(
    problem,
    space,
    constraints,
    objective,
    *,
    time_limit: float = 100.0,
    top: int = 1,
    t0: float | None = None,
) -> SolveResult:
    """Solve each mounting's MINLP with Bonmin and return the best design (re-evaluated;
    never proven: status 'feasible' at best).  One design only (``top`` is accepted for the common
    signature)."""
    t0 = time.perf_counter() if t0 is None else t0
    _, N, B, G = space.shape
    best = None
    statuses, notes = [], []
    n_solves = 0
    if N == 0 or B == 0 or G == 0:
        statuses.append("empty search space")
    for mi, mounting in enumerate(space.mountings):
        if N == 0 or B == 0 or G == 0:
            break
        remaining = time_limit - (time.perf_counter() - t0)
        if remaining <= 0.5:
            statuses.append(f"{mounting}: not run (time limit)")
            continue
        n_solves += 1
        kind, got = _solve_with_deadline(
            lambda m=mounting, r=remaining: _mounting_solve(space, m, constraints, objective, r),
            remaining + DEADLINE_GRACE,
            mounting,
        )
        if kind == "timeout":
            statuses.append(
                f"{mounting}: stopped at the time limit ({time_limit:g} s) without a result"
            )
            continue
        if kind == "error":  # Bonmin aborts on NaN derivatives etc.: report it, do not hide it
            statuses.append(f"{mounting}: ERROR ({got})")
            continue
        xs, st = got
        status = str(st.get("return_status", "unknown"))
        statuses.append(f"{mounting}: {status}")
        # whatever the status, Bonmin may carry an integer feasible point (e.g. on the time limit):
        # checked here
        zs = dict(zip(SLOTS, (xs[:N], xs[N : N + B], xs[N + B : N + B + G])))
        if not integral(zs):
            notes.append(f"{mounting}: no integer solution returned")
            continue
        w = float(np.clip(xs[N + B + G], 0, 1))
        got = recover(space, mi, zs, lambda lo, hi, w=w: lo + w * (hi - lo), constraints, MOVES)
        combo, pre = got.combination, got.preload
        if pre is None:  # beyond Bonmin's constraint tolerance
            notes.append(
                f"{mounting}: Bonmin's point violates a limit on exact re-evaluation "
                f"(combination {combo}, preload {got.proposed:.1f} N)"
            )
            continue
        cand = make_candidate(space, combo, pre, objective, rank=1)
        if best is None or cand.objective > best.objective:
            best = cand
    all_success = all(s.split(": ", 1)[-1] == BONMIN_SUCCESS for s in statuses) and bool(statuses)
    if best is None:
        # Bonmin's INFEASIBLE on a nonconvex problem is not a proof (it says so on feasible problems
        # too)
        status = SOLVER_FAILED
        if statuses and all(s.endswith(BONMIN_INFEASIBLE) for s in statuses):
            notes.append(
                "Bonmin reports INFEASIBLE; not a proof on this nonconvex problem "
                "(the default method proves feasibility or infeasibility)"
            )
    else:
        status = FEASIBLE  # Bonmin's B-BB on a nonconvex problem proves nothing
    failed = sum(1 for s in statuses if not s.endswith((BONMIN_SUCCESS, "(time limit)")))
    cert = Certificate(
        combinations=space.size,
        feasible=None,
        pruned_by_bound=0,
        exact_evaluations=0,
        nlps_solved=n_solves,
        nlp_failures=failed,
        gap=float("nan"),
        proven=False,
        notes=tuple(["Bonmin B-BB on a nonconvex MINLP: a heuristic, no optimality proof"] + notes),
    )
    msg = "; ".join(statuses + notes)
    if all_success:
        msg = "Bonmin reported SUCCESS for every mounting (local, not a global proof); " + msg
    return SolveResult(
        status,
        "bonmin",
        problem.name,
        objective.label,
        objective.unit,
        best,
        [],
        cert,
        time.perf_counter() - t0,
        message=msg,
        solver_status="; ".join(statuses),
    )


__all__ = ["solve_bonmin"]
