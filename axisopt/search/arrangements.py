"""A problem that lists axis arrangements (``search.counterbalance`` / ``search.twin_drive``,
:mod:`axisopt.design.choices`): each arrangement is solved as its own problem with the chosen method
and the answers are combined.  The best objective wins (ties: the shared tie rule, lower cost then
mass, then the arrangement listed first); the runners-up are merged in objective order; the
certificate's counts are summed and proven only if every arrangement's solve is; infeasible only if
every arrangement is.  The limit sensitivities are the best gain over all arrangements, each
re-solved with the limit relaxed (:func:`.sensitivity.limit_sensitivities` for an arrangement with a
design, a relaxed solve for one without).  A Pareto objective merges the arrangements' fronts and
keeps the designs no design of another arrangement dominates."""

from __future__ import annotations

import time
from dataclasses import dataclass, fields, replace
from typing import Callable

import numpy as np

from ..model.limits import LIMITS
from ..problem import Problem
from .certificate import Certificate
from .result import INFEASIBLE, OPTIMAL, SolveResult
from .task.objective import rank_order

_SUMMED = (
    "combinations",
    "pruned_by_bound",
    "exact_evaluations",
    "nlps_solved",
    "nlp_failures",
    "pruned_by_block",
    "pruned_by_dominance",
)


@dataclass(frozen=True)
class Door:
    """What solving the arrangements needs of the front door, handed in by it (:func:`.front.solve`
    calls this stage; the stage calls back through these, so it imports nothing of the front
    door)."""

    solve: Callable  # front.solve: one arrangement (a problem without arrangements)
    limit_sensitivities: Callable  # sensitivity.limit_sensitivities
    relax: float  # sensitivity.RELAX: the relative relaxation of a limit for its sensitivity
    sensitivities: bool  # the method's capability (front.METHOD_TABLE)
    cut_note: Callable  # sensitivity.cut_note: what a time limit cut, in words


def _miss(res: SolveResult) -> float:
    """How far the closest design of an infeasible arrangement misses (sum of its relative
    misses)."""
    inf = res.infeasibility
    if inf is None or not inf.closest:
        return float("inf")
    return float(sum(abs(v) for v in inf.closest[0].misses.values()))


def _certificate(results) -> Certificate:
    certs = [r.certificate for r in results]
    kw = {f.name: getattr(certs[0], f.name) for f in fields(Certificate)}
    for name in _SUMMED:
        kw[name] = sum(getattr(c, name) for c in certs)
    kw["feasible"] = (
        None if any(c.feasible is None for c in certs) else sum(c.feasible for c in certs)
    )
    kw["screened"] = (
        None if any(c.screened is None for c in certs) else sum(c.screened for c in certs)
    )
    # proven only if every arrangement's answer is: its optimum or its infeasibility (not a time
    # limit's cut)
    kw["proven"] = all(c.proven for c in certs) and all(
        r.status in (OPTIMAL, INFEASIBLE) for r in results
    )
    kw["gap"] = max(c.gap for c in certs)
    kw["screening_time"] = sum(c.screening_time for c in certs)
    kw["notes"] = tuple(dict.fromkeys(n for c in certs for n in c.notes))
    return Certificate(**kw)


def _sensitivities(
    problem: Problem, subs, results, win: int, method: str, deadline: float, cut: list, door: Door
) -> list:
    """The winner's limits, each with the best gain over every arrangement relaxed by
    sensitivity.RELAX (a limit the ``deadline`` cuts in any arrangement is left out, its key in
    ``cut``)."""
    RELAX, limit_sensitivities, solve = door.relax, door.limit_sensitivities, door.solve

    best = results[win].best.objective
    per = [
        limit_sensitivities(sub, r, deadline=deadline, cut=cut) if r.best is not None else None
        for sub, r in zip(subs, results)
    ]
    out = []
    for b in per[win]:
        if b.limit in cut:
            continue
        reach = best + (b.objective_gain or 0.0)
        for i, (sub, r) in enumerate(zip(subs, results)):
            if i == win:
                continue
            if r.best is not None:
                g = next((x.objective_gain or 0.0 for x in per[i] if x.limit == b.limit), 0.0)
                reach = max(reach, r.best.objective + g)
                continue
            lim, value = LIMITS[b.limit], sub.limit_map[b.limit]
            relaxed = value * (1.0 + RELAX) if lim.sense == "<=" else value * (1.0 - RELAX)
            left = deadline - time.perf_counter()
            rr = solve(
                sub.with_limit(b.limit, relaxed),
                method,
                top=1,
                sensitivities=False,
                time_limit=max(left, 1e-3),
                explain=False,  # only whether it has a design, and its optimum, are read
            )
            if rr.status not in (OPTIMAL, INFEASIBLE):
                cut.append(b.limit)
                break
            if rr.best is not None:
                reach = max(reach, rr.best.objective)
        if b.limit in cut:
            continue
        gain = reach - best
        out.append(
            replace(b, objective_gain=gain, binding=bool(gain > 1e-6 * max(abs(best), 1e-9)))
        )
    return out


def _pareto(
    problem: Problem, method: str, subs, labels, t0: float, door: Door, time_limit: float = 100.0
) -> SolveResult:
    """A Pareto objective over the arrangements: each arrangement's front, merged and filtered to
    the designs no design of any arrangement dominates (each point names its arrangement)."""
    solve = door.solve
    from .pareto import FIELD, SENSE, nondominated

    deadline = t0 + time_limit
    results = [
        solve(
            sub, method, sensitivities=False, time_limit=max(deadline - time.perf_counter(), 1e-3)
        )
        for sub in subs
    ]
    n = len(results)
    cert = _certificate(results)
    fronts = [r.pareto for r in results]
    pts = [
        replace(c, arrangement=labels[i])
        for i, f in enumerate(fronts)
        if f is not None
        for c in f.points
    ]
    keys = problem.objective.pareto
    first = next((f for f in fronts if f is not None), None)
    if not pts or first is None:
        r = results[0]
        return replace(
            r,
            message=f"{n} arrangements tried ({'; '.join(labels)}), none feasible",
            certificate=cert,
            time=time.perf_counter() - t0,
            arrangements=n,
        )
    P = np.array(
        [[getattr(c, FIELD[k]) * (1.0 if SENSE[k] == "max" else -1.0) for k in keys] for c in pts]
    )
    keep = nondominated(P)
    lead = np.array([P[j, 0] for j in keep])
    keep = [int(keep[j]) for j in np.argsort(-lead, kind="stable")]
    points = [replace(pts[j], rank=r + 1) for r, j in enumerate(keep)]
    clouds = [
        np.asarray(f.cloud, dtype=float) for f in fronts if f is not None and f.cloud is not None
    ]
    front = replace(
        first,
        points=points,
        feasible=sum(f.feasible for f in fronts if f is not None),
        cloud=np.vstack(clouds) if clouds else None,
    )
    counts = {lab: sum(p.arrangement == lab for p in points) for lab in labels}
    msg = f"{n} arrangements tried; front points by arrangement: " + "; ".join(
        f"{k} {v}" for k, v in counts.items()
    )
    notes = tuple(n for n in cert.notes if not n.startswith("front size"))
    cert = replace(
        cert,
        notes=notes
        + (
            f"front size {len(points)} (the arrangements' fronts merged: "
            + ", ".join(str(len(f.points)) for f in fronts if f is not None)
            + ")",
        ),
    )
    return replace(
        results[0],
        status=OPTIMAL
        if all(r.status in (OPTIMAL, INFEASIBLE) for r in results)
        else next(r.status for r in results if r.status not in (OPTIMAL, INFEASIBLE)),
        best=points[0],
        runners_up=[],
        pareto=front,
        certificate=cert,
        message=msg,
        time=time.perf_counter() - t0,
        arrangements=n,
    )


def solve_arrangements(
    problem: Problem, method: str, *, top: int, time_limit: float, sensitivities: bool, door: Door
) -> SolveResult:
    """Solve every arrangement of ``problem`` with ``method`` and combine (see the module)."""
    solve = door.solve

    t0 = time.perf_counter()
    labels = [lab for lab, _ in problem.arrangements]
    subs = [replace(problem, axis=ax, arrangements=()) for _, ax in problem.arrangements]
    if problem.objective.mode == "pareto":
        return _pareto(problem, method, subs, labels, t0, door, time_limit)
    # one time limit for the whole command: each arrangement gets what the ones before it left
    deadline = t0 + time_limit

    # an infeasible arrangement is explained only when none has a design (its explanation is then
    # the answer's): searched again then, with the explanation
    def run(sub, explain):
        left = max(deadline - time.perf_counter(), 1e-3)
        return solve(sub, method, top=top, time_limit=left, sensitivities=False, explain=explain)

    results = [run(sub, False) for sub in subs]
    found = [i for i, r in enumerate(results) if r.best is not None]
    if not found:
        results = [run(sub, True) if r.status == INFEASIBLE else r for sub, r in zip(subs, results)]
    n = len(results)
    cert = _certificate(results)
    tried = f"{n} arrangements tried ({'; '.join(labels)})"
    if not found:
        close = min(range(n), key=lambda i: _miss(results[i]))
        r = results[close]
        msg = f"{tried}, none feasible; closest: {labels[close]}: {r.message}"
        return replace(
            r,
            message=msg,
            certificate=cert,
            time=time.perf_counter() - t0,
            arrangement=labels[close],
            arrangements=n,
        )
    # every design found, ranked by the shared tie rule (the arrangement listed first wins an exact
    # tie)
    cands = [(i, c) for i in found for c in [results[i].best] + list(results[i].runners_up)]
    obj = np.array([c.objective for _, c in cands])
    cost = np.array([c.cost for _, c in cands])
    mass = np.array([c.total_mass for _, c in cands])
    order = rank_order(
        obj, cost, mass, np.arange(len(cands)), min(top, len(cands)) if top > 0 else 1
    )
    win = cands[order[0]][0]
    ranked = [replace(cands[k][1], rank=r + 1) for r, k in enumerate(order)]
    res = results[win]
    status = res.status
    # optimal only if every arrangement is proven: solved to its optimum or proven infeasible (an
    # arrangement the time limit cut before any design may hold a better one)
    unproven = [r.status for r in results if r.status not in (OPTIMAL, INFEASIBLE)]
    if unproven and status == OPTIMAL:
        status = unproven[0]
    notes = [f"{labels[i]}: infeasible" for i in range(n) if results[i].status == INFEASIBLE]
    notes += [
        f"{labels[i]}: {results[i].status} (not proven)"
        for i in range(n)
        if results[i].status not in (OPTIMAL, INFEASIBLE) and i != win
    ]
    out = replace(
        res,
        status=status,
        best=ranked[0],
        runners_up=ranked[1:],
        certificate=cert,
        message="; ".join(x for x in [res.message] + notes if x),
        arrangement=labels[win],
        arrangements=n,
    )
    if sensitivities and door.sensitivities and problem.objective.mode != "lexicographic":
        cut_note = door.cut_note
        cut: list = []
        out.binding = _sensitivities(problem, subs, results, win, method, deadline, cut, door)
        if cut:
            out.message = "; ".join(
                x for x in (out.message, cut_note("sensitivities", sorted(set(cut)))) if x
            )
    out.certificate.estimated = results[win].certificate.estimated
    out.time = time.perf_counter() - t0
    return out


__all__ = ["Door", "solve_arrangements"]
