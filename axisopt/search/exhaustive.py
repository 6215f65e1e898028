"""The exhaustive method: every combination, no bounds and no screening (:func:`exhaustive_search`,
the ground truth of the tests).

Each limit is checked exactly on every combination (the preload-dependent ones by their own
bisection, the motor-torque ones by their interval, :func:`.preload.convex_interval`), and the
preload problem of each combination that some preload can make feasible is solved on a grid of that
feasible interval (:func:`grid_solve`; this does not assume that the objective grows with the
preload), chunked and vectorized.  IPOPT polishes the winners as in the default method.
"""

from __future__ import annotations

import time

import numpy as np

from ..model.goals import RESULT_GOALS
from ..model.limits import OUTPUT_PRELOAD
from . import task as vocabulary
from .certificate import SearchStats
from .preload import BISECTION_STEPS, concat_exact, convex_interval, goal_arrays, new_exact, subset
from .result import Exact
from .task.constraints import ok_all
from .task.objective import ObjectiveSpec
from .task.space import Space, respond

# the goals a result carries, by whether their output moves with the nut preload
# (model.limits.OUTPUT_PRELOAD)
PRELOAD_GOALS = tuple(g for g in RESULT_GOALS if OUTPUT_PRELOAD.get(g.output, 0))
FIXED_GOALS = tuple(g for g in RESULT_GOALS if not OUTPUT_PRELOAD.get(g.output, 0))


def grid_solve(space: Space, idx, constraints, objective: ObjectiveSpec, n_grid: int = 9) -> Exact:
    """Per-combination preload optimum that does not assume the objective grows with the preload.

    Each preload-dependent limit on its own is monotone in the preload (module docstring of
    ``space``), so its threshold is found by its own bisection; the feasible preloads are the
    interval between the largest lower threshold and the smallest upper one.  The objective is then
    evaluated on an even grid of that interval, both ends included, and the best feasible point
    kept.
    """
    idx = np.asarray(idx, dtype=np.int64)
    res = new_exact(idx)
    dep = [c for c in constraints if c.direction != 0]
    indep = [c for c in constraints if c.direction == 0]
    for mounting, sel, n, b, _g, p, x in space.by_mounting(idx):
        k = len(sel)
        lo, hi = space.preload_lo[n], space.preload_hi[n]
        out_lo = respond(p, x, mounting, lo[:, None], space.request)
        out_hi = respond(p, x, mounting, hi[:, None], space.request)
        ok = ok_all(indep, out_lo, k) & space.fits[n, b]
        for key, v in goal_arrays(out_lo, k, FIXED_GOALS).items():  # the same at every preload
            res.goals[key][sel] = v
        low, up = lo.copy(), hi.copy()
        for c in dep:
            # only the combinations every limit so far allows (exact, not a bound)
            w = np.nonzero(ok)[0]
            if not len(w):
                break
            pw = subset(p, w, k)
            xc = x if c.profile else x[-1:]
            if c.convex:  # a motor-torque limit: met on an interval of preloads
                ex, a_lo, a_hi = convex_interval(c, pw, xc, mounting, lo[w], hi[w])
                ok[w] &= ex
                low[w] = np.where(ex, np.maximum(low[w], a_lo), low[w])
                up[w] = np.where(ex, np.minimum(up[w], a_hi), up[w])
                continue
            ok_lo = ok_all([c], out_lo, k)
            ok_hi = ok_all([c], out_hi, k)
            if c.upper_type:
                ok &= ok_lo
                a, z = np.where(ok_hi, hi, lo), hi.copy()  # a: feasible end, z: infeasible end
                todo = ok & ~ok_hi
            else:
                ok &= ok_hi
                a, z = np.where(ok_lo, lo, hi), lo.copy()
                todo = ok & ~ok_lo
            if todo.any():
                j = np.nonzero(todo)[0]
                pj = subset(p, j, k)
                aj, zj = a[j], z[j]
                for _ in range(BISECTION_STEPS):
                    mid = 0.5 * (aj + zj)
                    good = ok_all(
                        [c], respond(pj, xc, mounting, mid[:, None], space.request), len(j)
                    )
                    aj = np.where(good, mid, aj)
                    zj = np.where(good, zj, mid)
                a[j] = aj
            if c.upper_type:
                up = np.minimum(up, a)
            else:
                low = np.maximum(low, a)
        ok &= low <= up
        best_obj = np.full(k, -np.inf)
        best_pre = np.full(k, np.nan)
        w = np.nonzero(ok)[0]  # the grid runs on the combinations with a feasible preload interval
        if len(w):
            pw = subset(p, w, k)
            bo, bp = np.full(len(w), -np.inf), np.full(len(w), np.nan)
            for t in np.linspace(0.0, 1.0, n_grid):
                # clipped: low + 1.0 * (up - low) can round one ulp above up, past a threshold
                pre = np.clip(low[w] + t * (up[w] - low[w]), low[w], up[w])
                out = respond(pw, x, mounting, pre[:, None], space.request)
                good = ok_all(constraints, out, len(w))
                J = np.broadcast_to(objective.value(out), (len(w),))
                better = good & (J > bo)
                bo = np.where(better, J, bo)
                bp = np.where(better, pre, bp)
            best_obj[w], best_pre[w] = bo, bp
        feas = np.isfinite(best_obj)
        res.feasible[sel] = feas
        res.objective[sel] = best_obj
        res.preload[sel] = best_pre
        f = np.nonzero(feas)[0]
        # at the best preload, NaN where infeasible
        vals = {g.key: np.full(k, np.nan) for g in PRELOAD_GOALS}
        if len(f):
            out = respond(subset(p, f, k), x, mounting, best_pre[f][:, None], space.request)
            for key, v in goal_arrays(out, len(f), PRELOAD_GOALS).items():
                vals[key][f] = v
        for key, v in vals.items():
            res.goals[key][sel] = v
    return res


def exhaustive_search(
    space: Space,
    constraints,
    objective: ObjectiveSpec,
    chunk: int = 20000,
    *,
    deadline: float | None = None,
):
    """Every combination of ``space``, ``chunk`` at a time (:func:`grid_solve`).  ``deadline`` (a
    time.perf_counter() value): stop there with the chunks solved so far (``stats.timed_out``, not
    proven, gap
    unknown: no bound covers the rest); every :data:`.task.PROGRESS` seconds a progress record goes
    to the "axisopt" logger (a terminal shows it).  Returns (Exact of the evaluated combinations,
    SearchStats)."""
    t0 = shown = time.perf_counter()
    parts, done, timed_out = [], 0, False
    for s in range(0, space.size, chunk):
        now = time.perf_counter()
        if deadline is not None and now > deadline:
            timed_out = True
            break
        if now - shown > vocabulary.PROGRESS:
            shown = now
            vocabulary.LOG.info(
                f"  exhaustive: {done:,} of {space.size:,} combinations solved, {now - t0:.0f} s"
            )
        parts.append(
            grid_solve(space, np.arange(s, min(space.size, s + chunk)), constraints, objective)
        )
        done = min(space.size, s + chunk)
    ex = concat_exact(parts) if parts else grid_solve(space, [], constraints, objective)
    stats = SearchStats(
        combinations=space.size,
        feasible=int(ex.feasible.sum()),
        pruned_by_bound=0,
        exact_evaluations=done,
        gap=float("nan") if timed_out else 0.0,
        proven=not timed_out,
        screening_time=0.0,
        screening_rate=done / max(time.perf_counter() - t0, 1e-9),
        timed_out=timed_out,
    )
    return ex, stats


def run(task, method: str, top: int, time_limit: float, t0: float):
    """The exhaustive method's runner (``search.front.METHOD_TABLE``): :func:`exhaustive_search`
    over ``task``, stopped at ``t0 + time_limit``, then its result
    (:func:`.polish.scalar_result`)."""
    from .polish import scalar_result

    ex, stats = exhaustive_search(
        task.space, task.constraints, task.objective, deadline=t0 + time_limit
    )
    return scalar_result(task, method, ex, stats, top, t0, deadline=t0 + time_limit)
