"""The front door of a solve: :func:`solve` validates the method, builds the :class:`Task` (problem,
search space, constraints, objective) and dispatches by the objective's mode -- scalar,
lexicographic (two scalar solves, the first's optimum a floor of the second) or Pareto
(:mod:`.pareto`) -- to the method's runner (:data:`METHOD_TABLE`: the default and exhaustive runners
sit in their stage modules, :func:`.bestfirst.run` and :func:`.exhaustive.run`, and end in
:func:`.polish.scalar_result`); the limit sensitivities, the cheaper design near the optimum
(:mod:`.sensitivity`) and what of the optimum rests on estimated part values are added here.  The
MINLP methods are imported when a solve first reaches them.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, replace
from types import MappingProxyType
from typing import TYPE_CHECKING, Callable

from ..errors import InputError
from ..model.goals import GOALS
from ..model.limits import LIMITS
from ..problem import Problem
from . import bestfirst, exhaustive
from .result import OPTIMAL, SolveResult
from .sensitivity import RELAX, cheaper_near, cut_note, estimated_at_optimum, limit_sensitivities
from .task import Task

if TYPE_CHECKING:
    from .task.objective import ObjectiveSpec


def build_task(problem: Problem, objective: ObjectiveSpec | None = None) -> Task:
    """The task of ``problem``: its search space, constraints and objective (``objective``: another
    one)."""
    from .parts import build_space

    space = build_space(problem)  # each stage module is imported when a solve first reaches it
    from .task.objective import objective_spec

    objective = objective_spec(problem.objective.mode, problem) if objective is None else objective
    from .task.constraints import build_constraints

    return Task(problem, space, build_constraints(problem), objective)


def _run_bonmin(task: Task, method: str, top: int, time_limit: float, t0: float) -> SolveResult:
    from .minlp import solve_bonmin

    return solve_bonmin(
        task.problem,
        task.space,
        task.constraints,
        task.objective,
        time_limit=time_limit,
        top=top,
        t0=t0,
    )


def _run_scip(task: Task, method: str, top: int, time_limit: float, t0: float) -> SolveResult:
    from .minlp import solve_scip

    return solve_scip(
        task.problem,
        task.space,
        task.constraints,
        task.objective,
        time_limit=time_limit,
        top=top,
        t0=t0,
    )


@dataclass(frozen=True)
class Method:
    """A search method and what it can do (the one place its capabilities are said)."""

    name: str
    run: Callable  # (task, method name, top, time_limit, t0) -> SolveResult, a scalar objective
    proves: bool  # proves the optimum over the catalog (gap 0) when it ends 'optimal'
    pareto: bool  # computes exact Pareto fronts
    sensitivities: bool  # the limit sensitivities are re-solved with it
    runners_up: bool  # returns the ``top`` best designs (else the best only)
    doc: str


METHOD_TABLE = (
    Method(
        "default",
        bestfirst.run,
        True,
        True,
        True,
        True,
        "block bounds, screening, exact preload solve in bound order, IPOPT polish; proves the "
        "optimum",
    ),
    Method(
        "exhaustive",
        exhaustive.run,
        True,
        True,
        True,
        True,
        "every combination, preload on a grid of its feasible interval; the ground truth",
    ),
    Method(
        "bonmin",
        _run_bonmin,
        False,
        False,
        False,
        False,
        "CasADi Bonmin MINLP with one-hot part selection; a heuristic reference",
    ),
    Method(
        "scip",
        _run_scip,
        True,
        False,
        False,
        False,
        "the same MINLP solved globally by SCIP (optional extra axisopt[scip])",
    ),
)
METHODS_BY_NAME = MappingProxyType({m.name: m for m in METHOD_TABLE})
METHODS = tuple(METHODS_BY_NAME)


def solve(
    problem: Problem,
    method: str = "default",
    *,
    top: int = 5,
    time_limit: float = 100.0,
    sensitivities: bool = True,
    explain: bool = True,
) -> SolveResult:
    """Solve a sizing problem.

    problem       : :class:`axisopt.problem.Problem`
    method        : a :data:`METHOD_TABLE` name: 'default' | 'exhaustive' | 'bonmin' | 'scip'
    top           : number of designs returned (best + runners-up; a method without runners-up notes
                    it)
    time_limit    : wall-clock limit [s] of every method: the default method then returns the best
                    design found with its gap (status 'time_limit'), or an infeasible answer's
                    explanation so far
    sensitivities : re-solve with each limit relaxed by 10 % to report what it costs (methods that
                    allow it); and, when nothing fits (default method), the design change a search
                    verifies (:mod:`.advice`); a batch study leaves both out
    explain       : an infeasible answer of the default or exhaustive method carries its explanation
                    (the closest designs, what to relax); False: the status alone (a what-if that
                    reads only whether a design exists and its optimum)

    What the search left out of the design (the drive, and why) is on the answer's ``left_out``.
    """
    if getattr(problem, "drives", None) is not None:
        raise InputError(
            "a problem with search.drive_types is solved over its drive types "
            "(search.drivetype.solve_drive_types; axisopt solve and axisopt.solve do)",
            source=problem.source,
            where="search.drive_types",
        )
    res = _solve(
        problem,
        method,
        top=top,
        time_limit=time_limit,
        sensitivities=sensitivities,
        explain=explain,
    )
    ob = problem.objective
    if ob.mode != "pareto" and res.pareto is None:
        from .task.objective import objective_spec

        if (
            not objective_spec(ob.order[1] if ob.mode == "lexicographic" else ob.mode, problem).sign
            > 0
        ):
            _shown_sign(res)
    why = problem.restrictions.drive_left_out
    if why and not res.left_out:
        res.left_out = (
            f"the drive (motor, coupling, reduction) is not sized: {why}; the axis's motor_inertia "
            "and coupling values stand in and no motor check is made",
        )
    return res


def _shown_sign(res: SolveResult) -> None:
    """A least cost or mass is searched as its negative, maximised: the designs' objectives and the
    limits' gains turned back into the value itself (a gain then reads as the change of cost
    or mass: negative, cheaper or lighter)."""
    for c in [res.best] + list(res.runners_up):
        if c is not None:
            c.objective = -c.objective
    res.binding = [
        replace(b, objective_gain=None if b.objective_gain is None else -b.objective_gain)
        for b in res.binding
    ]  # SolveResult wraps the list in a Bindings


def _solve(
    problem: Problem,
    method: str = "default",
    *,
    top: int = 5,
    time_limit: float = 100.0,
    sensitivities: bool = True,
    explain: bool = True,
) -> SolveResult:
    """:func:`solve` without the left-out statement."""
    if method not in METHODS_BY_NAME:
        raise ValueError(f"unknown method '{method}'; use one of {', '.join(METHODS)}")
    m = METHODS_BY_NAME[method]
    # search.counterbalance / search.twin_drive: each arrangement solved, the best kept
    if problem.arrangements:
        from .arrangements import Door, solve_arrangements

        door = Door(solve, limit_sensitivities, RELAX, m.sensitivities, cut_note)
        return solve_arrangements(
            problem, method, top=top, time_limit=time_limit, sensitivities=sensitivities, door=door
        )
    t0 = time.perf_counter()
    ob = problem.objective
    if problem.axis.twin_drive is not None and not m.pareto:
        # the MINLP references are built on the same model, but SCIP's LP relaxation of the gantry's
        # 2-DOF eigenvalues contradicted enumeration on a synthetic twin-drive problem: refused, not
        # trusted
        raise InputError(
            f"--method {method} does not take a twin-drive gantry (axis.twin_drive) yet; use "
            "--method default or exhaustive",
            source=problem.source,
        )
    if ob.mode == "pareto":
        if not m.pareto:
            raise InputError(
                f"--method {method} solves one scalar objective; a Pareto front needs "
                f"--method {' or '.join(x.name for x in METHOD_TABLE if x.pareto)}",
                source=problem.source,
            )
        from .pareto import solve_pareto

        return solve_pareto(problem, method=method, t0=t0, time_limit=time_limit)
    if ob.mode == "lexicographic":
        from .task.objective import objective_spec

        res = _solve_lexicographic(
            build_task(problem, objective_spec(ob.order[1])), m, top, time_limit, t0
        )
    else:
        task = replace(build_task(problem), explain=explain)
        res = m.run(task, method, top, time_limit, t0)
        # the whole command's: the what-ifs below stop there too, and say so
        deadline = t0 + time_limit
        if sensitivities and res.best is not None and m.sensitivities:
            cut: list = []
            res.binding = limit_sensitivities(
                problem, res, space=task.space, deadline=deadline, cut=cut
            )
            if cut:
                res.message = "; ".join(
                    x for x in (res.message, cut_note("sensitivities", cut)) if x
                )
        if sensitivities and res.infeasibility is not None and method == "default":
            # the infeasible answer's what-if: an axis change the search verifies, before any limit
            # is relaxed
            from .infeasible.advice import design_changes

            cut = []
            res.infeasibility.design_changes = design_changes(
                problem,
                task.constraints,
                res.infeasibility,
                space=task.space,
                deadline=deadline,
                cut=cut,
            )
            if cut:
                res.message = "; ".join(x for x in (res.message, cut_note("advice", cut)) if x)
            res.time = time.perf_counter() - t0
        if res.best is not None and res.best.design is not None:
            res.certificate.estimated = estimated_at_optimum(
                problem, res, [k for k, _ in task.objective.terms]
            )
        if (
            sensitivities
            and method == "default"
            and res.best is not None
            and ob.mode in ("stiffness", "frequency")
        ):
            res.cheaper = cheaper_near(task, res, m, time_limit, t0)
            res.time = time.perf_counter() - t0
    if top > 1 and not m.runners_up:
        res.certificate.notes = res.certificate.notes + (
            f"--method {method} returns the best design only (top {top} asked: no runners-up)",
        )
    return res


def _solve_lexicographic(
    task: Task, m: Method, top: int, time_limit: float, t0: float
) -> SolveResult:
    """The primary objective's optimum, then the secondary's over the designs within the tolerance
    of it."""
    from .task.constraints import limit_constraint
    from .task.objective import objective_spec

    problem, ob = task.problem, task.problem.objective
    primary, secondary = ob.order
    first = m.run(replace(task, objective=objective_spec(primary)), m.name, 1, time_limit, t0)
    if first.best is None:
        return first
    j1 = first.best.objective  # the search's value: a least cost or mass is its negative
    sign = objective_spec(primary).sign
    # a floor (maximised goal) or a ceiling (least)
    bound = sign * (j1 - max(ob.tolerance, 1e-9) * abs(j1))
    lim = LIMITS[GOALS[primary].limit]
    extra = limit_constraint(
        lim.key,
        bound * lim.factor,
        f"lexicographic {primary}",
        f"{primary} within {ob.tolerance:g} of its best {sign * j1:.6g}",
    )
    res = m.run(replace(task, constraints=task.constraints + (extra,)), m.name, top, time_limit, t0)
    res.objective_label = (
        f"{ob.label}: primary best {sign * j1:.6g} {first.objective_unit}; " + res.objective_label
    )
    res.certificate.notes = res.certificate.notes + (
        f"stage 1 ({primary}): {first.certificate.exact_evaluations} exact evaluations, "
        f"{first.certificate.nlps_solved} NLPs, gap {first.certificate.gap:g}",
    )
    res.certificate.nlps_solved += first.certificate.nlps_solved
    res.certificate.proven = res.certificate.proven and first.certificate.proven
    if first.status != OPTIMAL and res.status == OPTIMAL:  # stage 2 proven on an unproven stage 1
        res.status = first.status
        res.message = "; ".join(
            x for x in (f"stage 1 ({primary}): {first.message or first.status}", res.message) if x
        )
    if res.best is not None and res.best.design is not None:  # both stages' objectives
        terms = [k for st in (primary, secondary) for k, _ in objective_spec(st).terms]
        res.certificate.estimated = estimated_at_optimum(problem, res, terms)
    res.time = time.perf_counter() - t0
    return res
