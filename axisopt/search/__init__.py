"""Sizing search over the catalogs: ``solve(problem, method=...) -> SolveResult``.

Methods: ``'default'`` (screening + bound order + IPOPT, proves the optimum), ``'exhaustive'`` (every
combination; the ground truth), ``'bonmin'`` (CasADi Bonmin MINLP with one-hot part selection; a
heuristic reference) and ``'scip'`` (the same MINLP solved globally by SCIP; optional extra
``axisopt[scip]``).  All use the same model position grid (``model.positions``) for the
minimum over the stroke, the same limits and the same tie rule, so their objectives compare.

``solve`` is a pure function of the problem (no printing, no global state besides per-process solver
caches), so a trade study may call it in worker processes.
"""

from __future__ import annotations

import time
from dataclasses import replace

import numpy as np

from ..model.limits import LIMITS
from ..problem import Problem
from .core import bound_order_search, certificate, exhaustive_search, polish
from .result import Binding, Candidate, Certificate, Infeasibility, ParetoFront, Relaxation, SolveResult
from .space import Constraint, build_constraints, build_space, objective_spec

METHODS = ("default", "exhaustive", "bonmin", "scip")
RELAX = 0.10  # sensitivities: relax each limit by 10 %


def solve(problem: Problem, method: str = "default", *, top: int = 5, time_limit: float = 100.0,
          sensitivities: bool = True) -> SolveResult:
    """Solve a sizing problem.

    problem       : :class:`axisopt.problem.Problem`
    method        : 'default' | 'exhaustive' | 'bonmin' | 'scip'
    top           : number of designs returned (best + runners-up)
    time_limit    : Bonmin / SCIP wall-clock limit [s]
    sensitivities : re-solve with each limit relaxed by 10 % to report what it costs (default method)
    """
    if method not in METHODS:
        raise ValueError(f"unknown method '{method}'; use one of {', '.join(METHODS)}")
    t0 = time.perf_counter()
    ob = problem.objective
    if ob.mode == "pareto":
        if method == "scip":
            from ..errors import InputError

            raise InputError("--method scip solves one scalar objective; a Pareto front needs --method default "
                             "or exhaustive")
        from .pareto import solve_pareto

        return solve_pareto(problem, method=method, t0=t0)
    space = build_space(problem)
    constraints = build_constraints(problem)
    if ob.mode == "lexicographic":
        primary, secondary = ob.order
        first = _solve_scalar(problem, space, constraints, objective_spec(primary), method, 1, time_limit, t0)
        if first.best is None:
            return first
        j1 = first.best.objective
        floor = j1 * (1.0 - max(ob.tolerance, 1e-9))
        key = "min_stiffness" if primary == "stiffness" else "min_frequency"
        lim = LIMITS[key]
        extra = Constraint(f"lexicographic {primary}", lim.output, ">=", floor * lim.factor, lim.preload,
                           f"{primary} within {ob.tolerance:g} of its best {j1:.6g}", lim.unit, lim.factor)
        res = _solve_scalar(problem, space, constraints + (extra,), objective_spec(secondary), method, top,
                            time_limit, t0)
        res.objective_label = f"{ob.label}: primary best {j1:.6g} {first.objective_unit}; " + res.objective_label
        res.certificate.notes = res.certificate.notes + (
            f"stage 1 ({primary}): {first.certificate.exact_evaluations} exact evaluations, "
            f"{first.certificate.nlps_solved} NLPs, gap {first.certificate.gap:g}",)
        res.certificate.nlps_solved += first.certificate.nlps_solved
        res.certificate.proven = res.certificate.proven and first.certificate.proven
        if first.status != "optimal" and res.status == "optimal":  # stage 2 proven on an unproven stage 1
            res.status = first.status
            res.message = "; ".join(m for m in (f"stage 1 ({primary}): {first.message or first.status}",
                                                res.message) if m)
        if res.best is not None and res.best.design is not None:  # both stages' objectives
            terms = [k for st in (primary, secondary) for k, _ in objective_spec(st).terms]
            res.certificate.estimated = estimated_at_optimum(problem, res, terms)
        res.time = time.perf_counter() - t0
        return res
    spec = objective_spec(ob.mode, problem)
    res = _solve_scalar(problem, space, constraints, spec, method, top, time_limit, t0)
    if sensitivities and res.best is not None and method not in ("bonmin", "scip"):
        res.binding = limit_sensitivities(problem, res, space=space)
        res.time = time.perf_counter() - t0
    if res.best is not None and res.best.design is not None:
        res.certificate.estimated = estimated_at_optimum(problem, res, [k for k, _ in spec.terms])
    return res


def estimated_at_optimum(problem: Problem, res: SolveResult, objective_outputs) -> tuple:
    """What of the optimum rests on estimated part values (``Certificate.estimated``): the objective, the
    limits at their bound or binding by the sensitivities, the checks at their limit."""
    from ..model.estimates import binding_estimates

    binding = {b.limit for b in res.binding if b.binding}
    limits = [(k, v) for k, v in problem.limits]
    found = binding_estimates(res.best.design, limits, objective_outputs)
    seen = {r.what for r in found}
    extra = [(k, v) for k, v in limits if k in binding and k not in seen]
    if extra:  # binding by relaxation though not at its bound (a discrete step): its output's estimates
        from ..model.estimates import Resting, resting_on

        outs = {k: LIMITS[k].output for k, _ in extra}
        moved = resting_on(res.best.design, list(outs.values()))
        found += [Resting(k, o, tuple(moved[o])) for k, o in outs.items() if moved.get(o)]
    return tuple(r.to_dict() for r in found)


def _solve_scalar(problem, space, constraints, spec, method, top, time_limit, t0) -> SolveResult:
    if method == "bonmin":
        from .minlp import solve_bonmin

        return solve_bonmin(problem, space, constraints, spec, time_limit=time_limit, top=top, t0=t0)
    if method == "scip":
        from .minlp import solve_scip

        return solve_scip(problem, space, constraints, spec, time_limit=time_limit, top=top, t0=t0)
    if method == "exhaustive":
        ex, info = exhaustive_search(space, constraints, spec)
    else:
        ex, info = bound_order_search(space, constraints, spec, top=top)
    info["pruned_by_dominance"] = space.pruned_by_dominance
    if not np.isfinite(ex.objective).any():
        from .explain import explain_infeasible
        from .relax import rank_relaxations

        cert = certificate(info, 0, 0, ())
        why = explain_infeasible(space, constraints, spec, every_combination=method == "exhaustive")
        why.relax, why.not_relaxable, why.relax_blocked_by = rank_relaxations(constraints, why)
        return SolveResult("infeasible", method, problem.name, spec.label, spec.unit, None, [], cert,
                           time.perf_counter() - t0, message="no catalog combination meets every limit",
                           infeasibility=why)
    cands, nlps, failed_ranks, notes = polish(space, ex, constraints, spec, top)
    cert = certificate(info, nlps, len(failed_ranks), notes)
    status = "optimal" if cert.proven else "time_limit"
    if 1 in failed_ranks:  # IPOPT failed on the best design (its 1-D solution is kept)
        status = "solver_failed"
    return SolveResult(status, method, problem.name, spec.label, spec.unit, cands[0], cands[1:], cert,
                       time.perf_counter() - t0, message="; ".join(notes), solver_status="ipopt")


def limit_sensitivities(problem: Problem, res: SolveResult, *, space=None) -> list:
    """For every limit: its value at the optimum and the objective gain when it is relaxed by 10 %
    (re-solved with the default method; a discrete problem has no meaningful multipliers).

    ``space``: the problem's search space, if built (the part tables do not depend on the limits, so every
    re-solve reuses it and its cached parameter arrays)."""
    best = res.best
    space = build_space(problem) if space is None else space
    spec = objective_spec(problem.objective.mode, problem)
    out = []
    for key, value in problem.limits:
        lim = LIMITS[key]
        at = best.outputs.get(lim.output)
        if value == 0.0 or at is None or not np.isfinite(at):
            continue  # e.g. max_backlash 0: relaxing it by 10 % changes nothing; an output the design lacks
        unit, factor = lim.unit, lim.factor
        relaxed = value * (1.0 + RELAX) if lim.sense == "<=" else value * (1.0 - RELAX)
        # the optimum meets the relaxed limit too: only designs that can reach it are searched (none: no gain)
        loose = build_constraints(problem.with_limit(key, relaxed))
        ex, _info = bound_order_search(space, loose, spec, top=1, incumbent=best.objective)
        if np.isfinite(ex.objective).any():
            gain = polish(space, ex, loose, spec, 1)[0][0].objective - best.objective
        else:
            gain = 0.0
        tol = 1e-6 * max(abs(best.objective), 1e-9)
        out.append(Binding(key, unit, value / factor, at / factor, relaxed / factor, gain,
                           bool(gain > tol)))
    return out


__all__ = ["solve", "METHODS", "SolveResult", "Candidate", "Certificate", "Binding", "Infeasibility",
           "ParetoFront", "Relaxation", "replace"]
