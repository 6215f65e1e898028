"""What a solved optimum is told with: each limit's sensitivity (the optimum re-solved with the
limit relaxed by 10 %, the note when the time limit cut them), the estimated part values the optimum
rests on, and the cheapest design near a stiffness or frequency optimum (:func:`cheaper_near`)."""

from __future__ import annotations

import time
from dataclasses import replace
from typing import TYPE_CHECKING

import numpy as np

from ..model.goals import GOALS
from ..model.limits import LIMITS
from ..problem import Problem
from .bestfirst import SOLVED
from .result import Binding, SolveResult

if TYPE_CHECKING:
    from .front import Method
    from .task import Task

RELAX = 0.10  # sensitivities: relax each limit by 10 %
# a stiffness or frequency optimum is compared with the cheapest design within the problem's
# tolerance of it (objective.tolerance, or this when the problem gives none) and said when that one
# costs at least MARKEDLY less
CHEAPER_TOLERANCE = 0.01
MARKEDLY = 0.05


def reusable(space, constraints, loose, spec, key: str):
    """The main search's Exact (``space``'s cache, :data:`SOLVED`) where the re-solve with ``loose``
    (the constraints with the limit ``key`` relaxed) gives its feasible combinations the same
    answer, else None.  That holds when ``key`` is the only change and its limit does not move a
    combination's best preload: a limit independent of the preload, or one a higher preload helps
    (minimum stiffness, frequency), relaxed: the best preload is set by the others (search.preload),
    and a combination that met the limit meets it relaxed, at the same preload and objective.  A
    limit a higher preload breaks (life, drag, thermal growth) moves it, and a convex one (motor
    torque) too: those re-solve every combination."""
    hit = space._cache.get(SOLVED)
    if hit is None or hit[1] != spec or tuple(hit[0]) != tuple(constraints):
        return None
    if len(loose) != len(constraints):
        return None
    changed = [b for a, b in zip(constraints, loose) if a != b]
    if len(changed) != 1 or changed[0].name != key or changed[0].upper_type or changed[0].convex:
        return None
    return hit[2]


def backlash_unmoved(space, limit: float, relaxed: float) -> bool:
    """Whether relaxing ``max_backlash`` from ``limit`` to ``relaxed`` [m] admits no combination
    the search did not have: every lost motion at the table (model.drive.lost_motion, a nut's play
    and a reduction's backlash through the lead, independent of the preload) over the space's nuts
    and drives lies outside (limit, relaxed] (a 1e-6 relative margin each side), and the
    reductions the limit left out of the space (parts: their lost motion at the shortest lead)
    stay out.  Then the re-solve's feasible set is the search's own: no gain."""
    from ..model.drive import lost_motion

    lo, hi = limit * (1.0 - 1e-6), relaxed * (1.0 + 1e-6)
    if space.backlash_left_least <= hi:
        return False
    for mounting in space.mountings:
        n = np.arange(len(space.nuts))
        nuts = space.params_flat(mounting, n, np.zeros_like(n), np.zeros_like(n))
        d = np.arange(space.n_drives)
        drives = space.params_flat(mounting, np.zeros_like(d), np.zeros_like(d), d)
        bl = np.unique(np.asarray(drives["reduction_backlash"], dtype=float))
        p = {
            k: np.asarray(nuts[k], dtype=float).reshape(-1, 1)
            for k in ("nut_double", "nut_axial_play", "lead")
        }
        p["reduction_backlash"] = bl.reshape(1, -1)
        v = np.asarray(lost_motion(p), dtype=float)
        if not np.isfinite(v).all() or np.any((v > lo) & (v <= hi)):
            return False
    return True


def cut_note(what: str, cut: list) -> str:
    """What the time limit cut after the search: the sensitivities (``cut``: the limits not
    re-solved) or the advice (its verifying searches)."""
    if what == "sensitivities":
        return (
            f"the time limit cut the limit sensitivities: {', '.join(cut)} not re-solved (a longer "
            "--time-limit, or --no-sensitivity)"
        )
    return (
        "the time limit cut the design-change advice: the changes it could not verify in time are "
        "not proposed (a longer --time-limit searches further)"
    )


def limit_sensitivities(
    problem: Problem,
    res: SolveResult,
    *,
    space=None,
    deadline: float | None = None,
    cut: list | None = None,
) -> list:
    """For every limit: its value at the optimum and the objective gain when it is relaxed by 10 %
    (re-solved with the default method; a discrete problem has no meaningful multipliers).

    ``deadline`` (a time.perf_counter() value): a limit whose re-solve it cuts, or that comes after
    it, is left out and its key appended to ``cut`` (a list).

    ``space``: the problem's search space, if built (the part tables do not depend on the limits, so
    a re-solve reuses it and its cached parameter arrays, unless the relaxed limit is also an axis
    value the parts' checks read, as ``min_life`` is when the axis sets no ``required_life``)."""
    from .bestfirst import bound_order_search
    from .parts import build_space
    from .polish import polish
    from .task.constraints import build_constraints
    from .task.objective import objective_spec

    best = res.best
    space = build_space(problem) if space is None else space
    spec = objective_spec(problem.objective.mode, problem)
    constraints = build_constraints(problem)
    out = []
    for key, value in problem.limits:
        lim = LIMITS[key]
        at = best.outputs.get(lim.output)
        if value == 0.0 or at is None or not np.isfinite(at):
            # e.g. max_backlash 0: relaxing it by 10 % changes nothing; an output the design lacks
            continue
        unit, factor = lim.unit, lim.factor
        if deadline is not None and time.perf_counter() >= deadline:
            if cut is not None:
                cut.append(key)
            continue
        relaxed = value * (1.0 + RELAX) if lim.sense == "<=" else value * (1.0 - RELAX)
        # the optimum meets the relaxed limit too: only designs that can reach it are searched
        # (none: no gain)
        if key == "max_backlash" and backlash_unmoved(space, value, relaxed):
            # no combination's lost motion lies between the limit and the relaxed limit: the
            # re-solve's feasible set, and so its optimum, is the search's own
            out.append(
                Binding(key, unit, value / factor, at / factor, relaxed / factor, 0.0, False)
            )
            continue
        relaxed_problem = problem.with_limit(key, relaxed)
        loose = build_constraints(relaxed_problem)
        # a limit that is also an axis value (min_life: the life the checks need) changes the part
        # parameters, and a max_backlash that left reductions out (parts._add_drives) may admit
        # them relaxed: either builds the relaxed problem's own space
        rebuild = relaxed_problem.axis != problem.axis or (
            key == "max_backlash" and space.reductions_by_backlash
        )
        sp = build_space(relaxed_problem) if rebuild else space
        known = None if rebuild else reusable(sp, constraints, loose, spec, key)
        ex, stats = bound_order_search(
            sp, loose, spec, top=1, incumbent=best.objective, deadline=deadline, known=known
        )
        if stats.timed_out:  # an unproven gain is not reported
            if cut is not None:
                cut.append(key)
            continue
        if np.isfinite(ex.objective).any():
            gain = polish(sp, ex, loose, spec, 1)[0][0].objective - best.objective
        else:
            gain = 0.0
        tol = 1e-6 * max(abs(best.objective), 1e-9)
        out.append(
            Binding(
                key, unit, value / factor, at / factor, relaxed / factor, gain, bool(gain > tol)
            )
        )
    return out


def estimated_at_optimum(problem: Problem, res: SolveResult, objective_outputs) -> tuple:
    """What of the optimum rests on estimated part values (``Certificate.estimated``): the
    objective, the limits at their bound or binding by the sensitivities, the checks at their
    limit."""
    from ..model.estimates import Resting, binding_estimates, resting_on

    binding = {b.limit for b in res.binding if b.binding}
    limits = [(k, v) for k, v in problem.limits]
    found = binding_estimates(res.best.design, limits, objective_outputs)
    seen = {r.what for r in found}
    extra = [(k, v) for k, v in limits if k in binding and k not in seen]
    # binding by relaxation though not at its bound (a discrete step): its output's estimates
    if extra:
        outs = {k: LIMITS[k].output for k, _ in extra}
        moved = resting_on(res.best.design, list(outs.values()))
        found += [Resting(k, o, tuple(moved[o])) for k, o in outs.items() if moved.get(o)]
    return tuple(r.to_dict() for r in found)


def cheaper_near(
    task: Task, res: SolveResult, m: Method, time_limit: float, t0: float
) -> dict | None:
    """The cheapest design whose objective is within the problem's tolerance
    (``objective.tolerance``, else :data:`CHEAPER_TOLERANCE`) of the optimum ``res.best``, when it
    costs at least :data:`MARKEDLY` less; else None.  The lexicographic solve's second stage: the
    least cost with the objective floored, same method."""
    from .task.constraints import limit_constraint
    from .task.objective import objective_spec

    problem, best = task.problem, res.best
    tol = problem.objective.tolerance or CHEAPER_TOLERANCE
    goal = GOALS[problem.objective.mode]
    lim = LIMITS[goal.limit]
    floor = best.objective * (1.0 - tol)
    extra = limit_constraint(
        lim.key,
        floor * lim.factor,
        f"within {tol:g} of the best",
        f"{goal.key} within {tol:g} of its best {best.objective:.6g}",
    )
    cheap = m.run(
        replace(task, objective=objective_spec("cost"), constraints=task.constraints + (extra,)),
        m.name,
        1,
        time_limit,
        t0,
    )
    c = cheap.best
    if c is None or not c.cost < best.cost * (1.0 - MARKEDLY):
        return None
    return {
        "tolerance": tol,
        "objective": c.goal(goal.key),
        "unit": goal.unit,
        "cost": c.cost,
        "best_cost": best.cost,
        "proven": bool(cheap.certificate.proven),
        "mounting": c.mounting,
        "parts": c.parts(),
        "nut_preload": c.nut_preload,
    }
