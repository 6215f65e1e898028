"""Polish: the winners' continuous problem re-solved by IPOPT on the CasADi model (the reported
preload), cross-checked against the exact 1-D solve (:func:`polish`); and the answer of a scalar
search built from its exact solves (:func:`scalar_result`: the polished designs, or the infeasible
answer with its explanation).

The NLP of one combination (:func:`solve_preload`): the nut preload, scaled to w in [0, 1] over the
allowed range, and one epigraph variable per objective term (the minimum over the position grid).
Objective and constraints are scaled (display units, :meth:`.constraints.Constraint.scaled`) before
IPOPT sees them.  Only the preload-dependent limits enter; the others do not change with the preload
and are checked exactly before any NLP is built.  One solver per (mounting, grid, objective, limit
set) and process.  Wachter and Biegler, "On the implementation of an interior-point filter
line-search algorithm", Math. Prog. 106 (2006) 25-57.
"""

from __future__ import annotations

import time
from dataclasses import replace
from typing import TYPE_CHECKING

import casadi as ca
import numpy as np

from .. import model
from .candidates import make_candidate
from .certificate import Certificate
from .result import INFEASIBLE, OPTIMAL, SOLVER_FAILED, TIME_LIMIT, Exact, NLPResult, SolveResult
from .task.constraints import ok_all
from .task.objective import ObjectiveSpec, in_display_units, rank_order
from .task.space import Space, respond

if TYPE_CHECKING:
    from .task import Task


def polish(space: Space, ex: Exact, constraints, objective: ObjectiveSpec, top: int):
    """IPOPT on the ``top`` best combinations of ``ex``.  Returns (candidates, NLPs solved, failed
    ranks, notes): the ranks whose NLP failed (their 1-D solution is kept).  A combination whose 1-D
    solution is the top of its preload range needs no NLP: the objective does not fall with the
    preload (the exact solve rests on it), so no preload in the range does better."""
    from ..model.limits import preload_direction

    pick = rank_order(ex.objective, ex.cost, ex.total_mass, ex.idx, top)
    # an objective the preload does not move (a least cost or mass): the exact solve's preload is as
    # good as any
    flat = all(preload_direction(k) == 0 for k, _ in objective.terms)
    cands, fails, notes = [], [], []
    solved = 0
    for r, j in enumerate(pick, start=1):
        combo = int(ex.idx[j])
        mi, n, b, g = (int(v) for v in space.unravel(combo))
        mounting = space.mountings[mi]
        lo, hi = float(space.preload_lo[n]), float(space.preload_hi[n])
        pre = float(ex.preload[j])
        if pre >= hi or flat:
            cands.append(make_candidate(space, combo, pre, objective, rank=r))
            continue
        p = space.params_flat(mounting, np.array([n]), np.array([b]), np.array([g]))
        p1 = model.one_design(p)
        res = solve_preload(
            mounting, space.grid[mounting], p1, lo, hi, constraints, objective, guess=pre
        )
        solved += 1
        if not res.success:
            fails.append(r)
            notes.append(
                f"IPOPT {res.status} on combination {combo} (rank {r}); kept the 1-D solution"
            )
        elif res.objective < ex.objective[j] - 1e-6 * max(abs(ex.objective[j]), 1e-9):
            notes.append(
                f"IPOPT objective {res.objective:.6g} below the 1-D solve {ex.objective[j]:.6g} on "
                f"combination {combo} (rank {r}); kept the 1-D solution"
            )
        elif feasible_at(space, combo, res.preload, constraints):
            pre = res.preload
        # else: IPOPT's point violates a limit by its tolerance; keep the (feasible) 1-D solution
        cands.append(make_candidate(space, combo, pre, objective, rank=r))
    return cands, solved, fails, notes


def feasible_at(space: Space, combo: int, preload: float, constraints) -> bool:
    """Whether combination ``combo`` meets every constraint at ``preload`` (exact, on the full
    grid)."""
    mi, n, b, g = (int(v) for v in space.unravel(combo))
    mounting = space.mountings[mi]
    p = space.params_flat(mounting, np.array([n]), np.array([b]), np.array([g]))
    out = respond(p, space.grid[mounting], mounting, np.array([[preload]]), space.request)
    return bool(ok_all(constraints, out, 1)[0])


_IPOPT = {
    "ipopt.print_level": 0,
    "print_time": False,
    "ipopt.sb": "yes",
    "ipopt.tol": 1e-10,
    "ipopt.max_iter": 300,
    "ipopt.bound_push": 1e-9,
    "ipopt.bound_frac": 1e-9,
    "ipopt.mu_init": 1e-4,
}
_SOLVERS: dict = {}


def nlp_solver(
    mounting: str, x: np.ndarray, cons: tuple, objective: ObjectiveSpec, duty: tuple = ()
):
    key = (
        mounting,
        tuple(np.round(x, 12)),
        tuple((c.key, c.sense, c.limit <= 0) for c in cons),
        objective.terms,
        duty,
    )
    if key in _SOLVERS:
        return _SOLVERS[key]
    F = model.model_for(mounting, len(x), duty).function
    P = ca.SX.sym("params", len(model.PARAM_NAMES))
    lim = ca.SX.sym("limits", len(cons))
    plo, phi = ca.SX.sym("plo"), ca.SX.sym("phi")
    w = ca.SX.sym("w")
    t = ca.SX.sym("t", len(objective.terms))
    out = F.call({"params": P, "preload": plo + w * (phi - plo), "x": ca.DM(x)})
    g, lbg, ubg = [], [], []
    for i, (okey, _wt) in enumerate(objective.terms):
        g.append(in_display_units(okey, out[okey]) - t[i])
        lbg += [0.0] * len(x)
        ubg += [ca.inf] * len(x)
    for j, c in enumerate(cons):
        v = out[c.key]
        expr = c.scaled(v, None if c.limit <= 0 else lim[j])  # >= 0 (or <= 0)
        n = v.shape[0]
        g.append(expr)
        if c.sense == ">=":
            lbg += [0.0] * n
            ubg += [ca.inf] * n
        else:
            lbg += [-ca.inf] * n
            ubg += [0.0] * n
    f = -sum(wt * t[i] for i, (_k, wt) in enumerate(objective.terms))
    nlp = {"x": ca.vertcat(w, t), "p": ca.vertcat(P, plo, phi, lim), "f": f, "g": ca.vertcat(*g)}
    solver = ca.nlpsol(f"preload_{mounting.replace('-', '_')}", "ipopt", nlp, _IPOPT)
    _SOLVERS[key] = (solver, np.array(lbg, float), np.array(ubg, float))
    return _SOLVERS[key]


def solve_preload(
    mounting: str,
    x,
    params: dict,
    plo: float,
    phi: float,
    constraints,
    objective: ObjectiveSpec,
    guess: float | None = None,
) -> NLPResult:
    """IPOPT on one combination; ``constraints`` may include preload-independent ones (ignored)."""
    cons = tuple(c for c in constraints if c.direction != 0)
    duty = params.get("duty", ())
    solver, lbg, ubg = nlp_solver(mounting, np.asarray(x, float), cons, objective, duty)
    pv = np.array([float(params[n]) for n in model.PARAM_NAMES])
    span = phi - plo
    w0 = 1.0 if guess is None or span <= 0 else float(np.clip((guess - plo) / span, 0.0, 1.0))
    f = model.model_for(mounting, len(x), duty)(
        dict(zip(model.PARAM_NAMES, pv)), plo + w0 * max(span, 0.0), x
    )
    t0 = [float(np.min(in_display_units(k, f[k]))) * (1 - 1e-6) for k, _ in objective.terms]
    arg = {
        "x0": np.array([w0] + t0),
        "lbx": np.array([0.0] + [-np.inf] * len(t0)),
        "ubx": np.array([1.0 if span > 0 else 0.0] + [np.inf] * len(t0)),
        "p": np.concatenate([pv, [plo, phi], [c.limit for c in cons]]),
        "lbg": lbg,
        "ubg": ubg,
    }
    sol = solver(**arg)
    st = solver.stats()
    xs = np.asarray(sol["x"]).ravel()
    pre = plo + float(np.clip(xs[0], 0.0, 1.0)) * max(span, 0.0)
    return NLPResult(bool(st["success"]), str(st["return_status"]), pre, -float(sol["f"]))


def scalar_result(
    task: Task, method: str, ex, stats, top: int, t0: float, *, deadline: float | None = None
) -> SolveResult:
    """The SolveResult of a search that ends in the exact solves ``ex`` with statistics ``stats``:
    infeasible (with the explanation, cut at ``deadline``, and what to relax), or the ``top`` best
    polished by IPOPT."""
    problem, space, constraints, spec = task.problem, task.space, task.constraints, task.objective
    stats.pruned_by_dominance = space.pruned_by_dominance
    if not np.isfinite(ex.objective).any():
        return _no_design(task, method, stats, t0, deadline)
    cands, nlps, failed_ranks, notes = polish(space, ex, constraints, spec, top)
    cert = Certificate.of(stats, nlps, len(failed_ranks), notes)
    status = OPTIMAL if cert.proven else TIME_LIMIT
    if 1 in failed_ranks:  # IPOPT failed on the best design (its 1-D solution is kept)
        status = SOLVER_FAILED
    return SolveResult(
        status,
        method,
        problem.name,
        spec.label,
        spec.unit,
        cands[0],
        cands[1:],
        cert,
        time.perf_counter() - t0,
        message="; ".join(notes),
        solver_status="ipopt",
    )


def _no_design(task: Task, method: str, stats, t0: float, deadline: float | None) -> SolveResult:
    """:func:`scalar_result` when the search found no design: the time limit's answer (not proven
    infeasible), or the infeasible answer with its explanation (unless the task asks without
    one)."""
    problem, space, constraints, spec = task.problem, task.space, task.constraints, task.objective
    status, cert, why = INFEASIBLE, Certificate.of(stats), None
    if stats.timed_out:
        status, cert = TIME_LIMIT, replace(cert, proven=False)
        message = (
            "the time limit came before any design was found: not proven infeasible (a longer "
            "--time-limit searches on)"
        )
    elif not task.explain:
        message = "no catalog combination meets every limit (not explained: asked without)"
    else:
        from .infeasible.explain import cut_note, explain_infeasible
        from .infeasible.relax import missing_values, rank_relaxations

        why = explain_infeasible(
            space, constraints, spec, every_combination=method == "exhaustive", deadline=deadline
        )
        why.relax, why.not_relaxable, why.relax_blocked_by = rank_relaxations(constraints, why)
        why.missing = missing_values(constraints, why, space)
        message = "no catalog combination meets every limit"
        if why.cut:
            message += "; " + cut_note(why)
        if space.reductions_by_backlash:
            lim = problem.limit_map.get("max_backlash", 0.0)
            message += (
                f"; {space.reductions_by_backlash} reductions (gearboxes, belts) were left out: "
                f"each one's backlash at the table exceeds limits.max_backlash ({lim * 1e6:g} um) "
                "even on the shortest lead; admit some lost motion to let the search choose one"
            )
    return SolveResult(
        status,
        method,
        problem.name,
        spec.label,
        spec.unit,
        None,
        [],
        cert,
        time.perf_counter() - t0,
        message=message,
        infeasibility=why,
    )
