"""The default method's driver: best-first over blocks of combinations, never forming the whole
product (:func:`bound_order_search`).  Its stages: block bounds (:mod:`.bounds`), screening
(:mod:`.screen`), the exact preload solve (:mod:`.preload`); the winners are polished after it
(:mod:`.polish`).
"""

from __future__ import annotations

import time

import numpy as np

from . import task as vocabulary
from .bounds import block_bounds
from .certificate import SearchStats
from .preload import concat_exact, exact_solve, solve_known
from .screen import group_end, screen_blocks
from .task.objective import ObjectiveSpec, objective_floor
from .task.space import Space


def bound_order_search(
    space: Space,
    constraints,
    objective: ObjectiveSpec,
    top: int = 1,
    *,
    max_evaluations: int | None = None,
    incumbent: float = -np.inf,
    first_feasible: bool = False,
    deadline: float | None = None,
    known=None,
):
    """Default method core: best-first over blocks of combinations, never forming the whole product.

    1. :func:`block_bounds`: every (mounting, nut, bearing) block -- all its guides and drives --
       gets a feasibility test and an objective bound from one evaluation with the optimistic guide.
    2. The blocks are taken in decreasing bound.  A group of blocks is screened
       (:func:`screen_nuts`, exact per combination up to the float32 slack) and its survivors join a
       pool; the pool's best bounds are solved exactly (:func:`exact_solve`) before the next group
       whenever they beat the next block's bound.  The incumbent is the ``top``-th best exact
       objective.
    3. It stops when neither the next block nor the pool can reach the incumbent: the gap is then 0.
       Blocks never screened are the certificate's ``pruned_by_block``; survivors never solved its
       ``pruned_by_bound``.
    ``incumbent``: an objective some design is known to reach (top 1): what cannot tie with it is
    pruned from the start, and the Exact returned may then be empty.  ``deadline`` (a
    time.perf_counter() value): stop there with what is solved so far (``stats.timed_out``; the gap
    is the bound of what is left against the best found), and every :data:`.task.PROGRESS` seconds a
    progress record goes to the "axisopt" logger (a terminal shows it).
    ``first_feasible``: stop at the first exact solve that
    finds a feasible design (a feasibility test, no optimum: search.advice).
    ``known``: an Exact of this space whose feasible rows are what :func:`exact_solve` gives under
    these constraints too (the main search's, for a limit relaxed that does not move the
    best preload: search.sensitivity); those rows are taken from it instead of solved again.
    Returns (Exact of evaluated combinations, :class:`.certificate.SearchStats`)."""
    t0 = time.perf_counter()
    GD = space.shape[3]
    blocks = block_bounds(space, constraints, objective)
    bm, bn, bb, bv = [], [], [], []
    n_block_ok = 0
    for mi, (ok, bound) in enumerate(blocks):
        n, b = np.nonzero(ok)
        n_block_ok += len(n)
        bm.append(np.full(len(n), mi))
        bn.append(n)
        bb.append(b)
        bv.append(bound[n, b])
    bm, bn, bb, bv = (np.concatenate(x) if x else np.zeros(0) for x in (bm, bn, bb, bv))
    order = np.argsort(-bv, kind="stable")
    bm, bn, bb, bv = bm[order].astype(int), bn[order].astype(int), bb[order].astype(int), bv[order]
    t_screen = time.perf_counter() - t0
    per_group = space.nuts_per_block
    pos, batch, n_eval, screened_blocks, feasible = 0, 64, 0, 0, 0
    group = 1  # distinct nuts per screened group: grows as long as no incumbent prunes
    pool_idx, pool_bnd = np.zeros(0, np.int64), np.zeros(0)
    parts, thr = [], (incumbent if top == 1 else -np.inf)
    timed_out, shown = False, time.perf_counter()
    while True:
        now = time.perf_counter()
        if deadline is not None and now > deadline:
            timed_out = True
            break
        if now - shown > vocabulary.PROGRESS:
            shown = now
            found = sum(int(np.isfinite(p.objective).sum()) for p in parts)
            vocabulary.LOG.info(
                f"  searching: {pos:,} of {len(bv):,} blocks screened, {n_eval:,} combinations "
                f"solved, {found:,} feasible, {now - t0:.0f} s"
            )
        floor = objective_floor(thr)
        nxt = bv[pos] if pos < len(bv) else -np.inf
        best_pool = pool_bnd.max() if len(pool_bnd) else -np.inf
        if max(nxt, best_pool) < floor or (pos >= len(bv) and not len(pool_bnd)):
            break
        if max_evaluations is not None and n_eval >= max_evaluations:
            break
        if len(pool_bnd) and best_pool >= nxt:  # exact solves of the pool's best bounds
            cand = np.nonzero(pool_bnd >= max(nxt, floor))[0]
            take = cand[np.argsort(-pool_bnd[cand], kind="stable")[:batch]]
            batch = min(batch * 2, 131072)
            ex = solve_known(space, pool_idx[take], constraints, objective, known)
            n_eval += len(take)
            parts.append(ex)
            keep = np.ones(len(pool_bnd), dtype=bool)
            keep[take] = False
            pool_idx, pool_bnd = pool_idx[keep], pool_bnd[keep]
            allobj = np.concatenate([p.objective for p in parts])
            fin = allobj[np.isfinite(allobj)]
            if first_feasible and len(fin):
                break
            if len(fin) >= top:
                thr = np.partition(fin, len(fin) - top)[len(fin) - top]
            continue
        # screen the next group of blocks: up to per_group distinct nuts, in bound order
        t1 = time.perf_counter()
        end = group_end(bm, bn, pos, lambda i, f=floor: bv[i] >= f, min(group, per_group))
        grp = slice(pos, end)
        group = min(group * 2, per_group)
        screened_blocks += end - pos
        pos = end
        new_idx, new_bnd = [], []
        for i, bnd in screen_blocks(space, bm[grp], bn[grp], bb[grp], constraints, objective):
            new_idx.append(i)
            new_bnd.append(bnd)
        add_i = np.concatenate(new_idx) if new_idx else np.zeros(0, np.int64)
        add_b = np.concatenate(new_bnd) if new_bnd else np.zeros(0)
        feasible += len(add_i)
        pool_idx, pool_bnd = np.concatenate([pool_idx, add_i]), np.concatenate([pool_bnd, add_b])
        t_screen += time.perf_counter() - t1
    ex = concat_exact(parts) if parts else exact_solve(space, [], constraints, objective)
    rest = max(bv[pos] if pos < len(bv) else -np.inf, pool_bnd.max() if len(pool_bnd) else -np.inf)
    best = ex.objective.max() if len(ex.objective) else -np.inf
    if rest == -np.inf or rest < objective_floor(thr) or rest < objective_floor(best):
        gap = 0.0
    else:
        gap = float((rest - best) / max(abs(best), 1e-30)) if np.isfinite(best) else float("inf")
    screened = screened_blocks * GD
    stats = SearchStats(
        combinations=space.size,
        feasible=int(feasible),
        pruned_by_bound=int(feasible - n_eval),
        exact_evaluations=int(n_eval),
        gap=gap,
        proven=gap == 0.0,
        screening_time=t_screen,
        screening_rate=space.size / max(t_screen, 1e-9),
        pruned_by_block=int(space.size - screened),
        screened=int(screened),
        timed_out=timed_out,
    )
    return ex, stats


# the key of the default search's solved combinations in its space's cache: (constraints, objective,
# Exact), set by :func:`run` (the limit sensitivities' re-solves take them:
# search.sensitivity.reusable)
SOLVED = ("solved by the default search",)


def run(task, method: str, top: int, time_limit: float, t0: float):
    """The default method's runner (``search.front.METHOD_TABLE``): :func:`bound_order_search` over
    ``task``, stopped at ``t0 + time_limit``, then its result (:func:`.polish.scalar_result`)."""
    from .polish import scalar_result

    ex, stats = bound_order_search(
        task.space, task.constraints, task.objective, top=top, deadline=t0 + time_limit
    )
    task.space._cache[SOLVED] = (task.constraints, task.objective, ex)
    return scalar_result(task, method, ex, stats, top, t0, deadline=t0 + time_limit)
